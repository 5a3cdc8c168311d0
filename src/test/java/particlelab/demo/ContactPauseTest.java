package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.lecture.BounceDemo;
import particlelab.physics.Gravity;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;
import particlelab.world.ContactLog;
import particlelab.world.World;

/**
 * Pause at the next contact (the Enter key), in plain JUnit: Bounce's physics runs without
 * jME ({@code new BounceDemo()}, {@code advancePhysics}). Its balls fall from rest, so the
 * step of its first impact has a closed form, and the clock must stop exactly there however
 * many steps a frame holds.
 */
class ContactPauseTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    /** Enough frames of 1/60 s for the first impact (step 54) and the second. */
    private static final int MAX_FRAMES = 600;
    /** Frames run after the pause, to see it hold. */
    private static final int FRAMES_WHILE_PAUSED = 120;
    /**
     * World and clock times are sums of float steps in double: exact to about 1e-16 relative
     * over a few hundred steps, so 1e-12 s is round-off with a wide margin, far below h.
     */
    private static final double TIME_TOLERANCE = 1e-12;

    /**
     * Frames of one step (the window at 60 Hz), of 15 steps (a clamped 0.25 s frame: the
     * contact's step 54 lies inside the frame of steps 46 to 60) and of 2.5 steps.
     */
    @ParameterizedTest
    @ValueSource(floats = {1f / 60f, 0.25f, 2.5f / 60f})
    void theClockStopsOnTheStepOfTheFirstContactAndStaysStopped(float frameSeconds) {
        BounceDemo bounce = new BounceDemo();
        World world = bounce.getWorld();
        int contactStep = firstContactStep();

        press(bounce, "Enter");
        runUntilPaused(bounce, frameSeconds);

        // World time is the end of the step that contained the contact: n·h.
        assertEquals(contactStep * (double) H, world.getTimeSeconds(), TIME_TOLERANCE);
        assertEquals(contactStep, world.getStepCount());
        assertEquals(world.getTimeSeconds(), bounce.getClock().getSimulatedSeconds(),
                TIME_TOLERANCE);
        ContactLog.Entry contact = world.getLog().get(0);
        // Both lanes' balls fall from the same height: their first contacts share the step.
        assertEquals(2, world.getLog().size(), "the pause came on the first contacts");
        assertTrue(contact.getTimeSeconds() > (contactStep - 1) * (double) H
                && contact.getTimeSeconds() <= world.getTimeSeconds(),
                "contact at " + contact.getTimeSeconds() + " s, inside step " + contactStep);
        // The views show the ball as the resolution left it: on its way up.
        float rebound = bounce.getParticles().get(0).getParticle().velocity.y;
        assertTrue(rebound > 0f, "V_y = " + rebound);

        for (int frame = 0; frame < FRAMES_WHILE_PAUSED; ++frame) {
            bounce.getRun().advancePhysics(frameSeconds);
        }
        assertEquals(contactStep, world.getStepCount(), "stepped while paused at the contact");
        assertEquals(contactStep * (double) H, bounce.getClock().getSimulatedSeconds(),
                TIME_TOLERANCE);
        assertEquals(rebound, bounce.getParticles().get(0).getParticle().velocity.y, 0f);
    }

    /**
     * After Home the HUD shows another step: it must not still describe the contact; End
     * back to the contact's step shows it again.
     */
    @Test
    void theContactLineIsShownOnlyAtTheContactsStep() {
        BounceDemo bounce = new BounceDemo();
        press(bounce, "Enter");
        runUntilPaused(bounce, H);
        assertTrue(hud(bounce).contains("PAUSED at contact: "), hud(bounce));
        assertTrue(bounce.getReplayControls().stepBack());
        assertFalse(hud(bounce).contains("at contact"), hud(bounce));
        bounce.getReplayControls().stepForward();
        assertFalse(bounce.getRun().isReplaying());
        assertTrue(hud(bounce).contains("PAUSED at contact: "), hud(bounce));
    }

    @Test
    void theHudNamesTheBodiesTheTimeAndTheApproachSpeed() {
        BounceDemo bounce = new BounceDemo();
        press(bounce, "Enter");
        assertTrue(hud(bounce).contains("t = 0.00 s   pausing at the next contact (Enter"
                + " cancels)   time x1\n"), hud(bounce));
        runUntilPaused(bounce, H);

        ContactLog.Entry contact = bounce.getWorld().getLog().get(0);
        // The time line, in place of the usual pause text: t is the end of step n = 54 (0.90
        // s). Semi-implicit Euler from rest gives V_n = −g·h·n, and the swept contact keeps
        // the step's V, so the approach speed is g·h·n (8.82 m/s), to the 2 decimals shown;
        // the contact's own time is inside the step.
        StringBuilder expected = new StringBuilder("t = ");
        TextFormat.appendFixed(expected, firstContactStep() * H, 2)
                .append(" s   PAUSED at contact: swept test - ground, approach ");
        TextFormat.appendFixed(expected, Gravity.STANDARD_G * H * firstContactStep(), 2)
                .append(" m/s at t = ");
        TextFormat.appendFixed(expected, contact.getTimeSeconds(), 4)
                .append(" s (+1 more in this step) (Enter: next contact, Space resumes)"
                        + "   time x1\n");
        assertTrue(hud(bounce).contains(expected), expected + " in\n" + hud(bounce));
    }

    @Test
    void spaceResumesAndEnterRunsOnToTheNextContact() {
        BounceDemo bounce = new BounceDemo();
        World world = bounce.getWorld();
        press(bounce, "Enter");
        runUntilPaused(bounce, H);
        long firstStop = world.getStepCount();

        press(bounce, "Space");
        bounce.getRun().advancePhysics(H);
        assertEquals(firstStop + 1, world.getStepCount(), "Space resumes");
        assertFalse(hud(bounce).contains("at contact"), hud(bounce));

        press(bounce, "Space");
        press(bounce, "Enter");
        assertFalse(bounce.getClock().isPaused(), "Enter runs a paused clock to the contact");
        runUntilPaused(bounce, H);
        // The next impact, after a whole hop (e = 0.9: about 1.6 s), and on its step.
        long secondStop = world.getStepCount();
        assertTrue(secondStop > firstStop + 60, firstStop + " then " + secondStop);
        ContactLog.Entry second = world.getLog().latest();
        assertTrue(second.getTimeSeconds() > (secondStop - 1) * (double) H
                && second.getTimeSeconds() <= world.getTimeSeconds(),
                "contact at " + second.getTimeSeconds() + " s, step " + secondStop);
        assertTrue(world.getLog().size() >= 3, "log " + world.getLog().size());
    }

    /**
     * Once Box2D's threshold (1 m/s, the default) has stopped the swept lane's ball, at the
     * impact its HUD gives as "at rest at", the ball lies on the ground and meets it again
     * every step, closing at g·h from rest, at the step's start. A pause there (15.83 s in
     * the audit) is such a resting contact, not the moment the ball stopped: it says so.
     */
    @Test
    void aPauseOnABallLyingOnTheGroundSaysItIsAResting() {
        BounceDemo bounce = new BounceDemo();
        // 950 frames: 15.83 s, after both lanes came to rest (the swept one at 15.49 s)
        for (int frame = 0; frame < 950; ++frame) {
            bounce.getRun().advancePhysics(H);
        }
        assertTrue(hud(bounce).contains("swept 0.042 m, 0.000 J, at rest at 15.494 s"),
                hud(bounce));
        press(bounce, "Enter");
        runUntilPaused(bounce, H);
        // One step of gravity from rest: V = −g·h, shown to 2 decimals (0.16 m/s).
        StringBuilder expected = new StringBuilder(" - ground, resting: approach ");
        TextFormat.appendFixed(expected, Gravity.STANDARD_G * H, 2)
                .append(" m/s (this step's h·a alone) at t = ");
        assertTrue(hud(bounce).contains(expected), expected + " in\n" + hud(bounce));
    }

    @Test
    void enterWhileArmedCancelsAndNothingPausesWithoutIt() {
        BounceDemo bounce = new BounceDemo();
        press(bounce, "Enter");
        press(bounce, "Enter");
        for (int frame = 0; frame < firstContactStep() + 30; ++frame) {
            bounce.getRun().advancePhysics(H);
        }
        assertFalse(bounce.getClock().isPaused());
        assertEquals(firstContactStep() + 30, bounce.getWorld().getStepCount());
        assertFalse(hud(bounce).contains("at contact"), hud(bounce));
        assertFalse(hud(bounce).contains("next contact"), hud(bounce));
    }

    /**
     * The first step whose end puts the ball's lowest point below the ground: from rest at
     * height y0 (the lowest point), semi-implicit Euler gives {@code y_n = y0 − g·h²·n(n+1)/2}.
     * For the demo's 4 m and g = 9.8 that is n = 54 (4.04 m fallen; step 53 leaves 0.10 m),
     * centimetres from the boundary, far beyond float round-off.
     */
    private static int firstContactStep() {
        double perStep = Gravity.STANDARD_G * H * H / 2.0;
        int n = 0;
        while (BounceDemo.DROP_HEIGHT - perStep * n * (n + 1) >= 0.0) {
            ++n;
        }
        return n;
    }

    private static void runUntilPaused(DemoState demo, float frameSeconds) {
        for (int frame = 0; frame < MAX_FRAMES && !demo.getClock().isPaused(); ++frame) {
            demo.getRun().advancePhysics(frameSeconds);
        }
        assertTrue(demo.getClock().isPaused(), "no contact paused the clock");
    }

    private static String hud(DemoState demo) {
        return demo.getWindow().formatHud(new StringBuilder()).toString();
    }

    private static void press(DemoState demo, String label) {
        for (KeyBinding binding : demo.getKeys().getBindings()) {
            for (int i = 0; i < binding.countKeys(); ++i) {
                if (binding.getKeyLabel(i).equals(label)) {
                    binding.press(i);
                    return;
                }
            }
        }
        throw new AssertionError("no key " + label);
    }
}

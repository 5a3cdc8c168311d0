package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;

/** The HUD lines every demo shows, written from a real clock and bindings; no jME app. */
class HudWriterTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;

    private final SimulationClock clock = new SimulationClock();
    /** One ball launched at (10, 10) m/s from the ground, stopping when it comes down. */
    private final DemoState demo = new DemoState("ball (test)") {
        @Override
        protected void createScene() {
            addParticle("ball", ColorRGBA.White, new Vector3f(0f, 0f, 0f),
                    new Vector3f(10f, 10f, 0f), 1f, new ParticleIntegrator(new Gravity()))
                    .stopAtGround();
        }
    };
    private final DemoParticle ball = demo.getParticles().get(0);
    private final HudWriter writer = new HudWriter(clock, List.of(ball));

    HudWriterTest() {
        writer.setTimeKeys(key(KeyInput.KEY_SPACE, "Space"), key(KeyInput.KEY_N, "N"),
                key(KeyInput.KEY_R, "R"),
                new KeyBinding(new int[] {KeyInput.KEY_EQUALS, KeyInput.KEY_ADD},
                        new String[] {"+", "keypad +"}, "faster", null, k -> { }),
                new KeyBinding(new int[] {KeyInput.KEY_MINUS, KeyInput.KEY_SUBTRACT},
                        new String[] {"-", "keypad -"}, "slower", null, k -> { }),
                key(KeyInput.KEY_X, "X"));
    }

    @Test
    void atRealTimeTheTimeLineIsShortAndNamesNoKeys() {
        run(60, H);

        String hud = write(false);

        assertTrue(hud.startsWith("t = 1.00 s   time x1\n"), hud);
        assertFalse(hud.contains("back to x1"), hud);
    }

    @Test
    void x64AtSixtyFramesPerSecondShowsTheMeasuredRateTheDropAndTheWayBack() {
        // 0.25 s a frame at most: x15 at 60 fps (SimulationClockTest checks the clock).
        clock.setTimeScale(SimulationClock.MAX_TIME_SCALE);
        run(60, H);

        String hud = write(false);

        assertTrue(hud.contains("time x64 asked, x15.0 measured: DROPPING TIME (a frame"
                + " simulates at most 0.250 s; frames take 16.7 ms, so at most x15.0)\n"), hud);
        assertTrue(hud.contains("\n   + / keypad +  x2,   - / keypad -  /2   (x1/64 to x64),"
                + "   X  back to x1\n"), hud);
    }

    @Test
    void atFiveFramesASecondTheDropNoticesFiguresAgreeWithEachOther() {
        // Frames of 0.191 s: the cap of 0.25 s a frame gives x1.31. A rounded "5 fps" beside
        // x1.31 did not multiply out (0.25 × 5 = 1.25); the frame time does (250 / 191).
        clock.setTimeScale(SimulationClock.MAX_TIME_SCALE);
        run(30, 0.191f);

        String hud = write(false);

        assertTrue(hud.contains("frames take 191.0 ms, so at most x1.31)"), hud);
    }

    @Test
    void aSlowerScaleWithinTheLimitsIsMeasuredWithoutADropNotice() {
        clock.setTimeScale(0.25f);
        run(60, H);

        String hud = write(false);

        // A quarter step per frame: whole steps only, so the window of 0.5 s holds 7 or 8 of
        // them; the rate shown is within h/0.5 s of 0.25.
        assertTrue(hud.contains("time x1/4 asked, x0.2"), hud);
        assertFalse(hud.contains("DROPPING"), hud);
        assertTrue(hud.contains("X  back to x1"), hud);
    }

    @Test
    void pauseAndTheEndOfTheSceneAreSaidWithTheirKeys() {
        run(10, H);
        clock.setPaused(true);
        assertTrue(write(false).contains("t = 0.17 s   PAUSED: Space resumes, N takes one step"
                + "   time x1\n"), write(false));
        clock.setPaused(false);
        assertTrue(write(true).contains("t = 0.17 s   stopped: every particle has landed"
                + " (R launches again)   time x1\n"), write(true));
    }

    @Test
    void aNoticeStaysUpForItsTimeThenGoes() {
        writer.showNotice("no demo 7: there are 6; Tab cycles");
        writer.age(HudWriter.NOTICE_SECONDS - 0.5f);
        assertTrue(write(false).contains("\nno demo 7: there are 6; Tab cycles\n"), write(false));
        writer.age(0.5f);
        assertNull(writer.getNotice());
        assertFalse(write(false).contains("no demo"), write(false));
    }

    @Test
    void aLandedParticleShowsWhereAndAfterHowLong() {
        // The demo's world lands it: the ground stop is one of its rules.
        for (int i = 0; i < 200 && !ball.hasLanded(); ++i) {
            demo.getWorld().step(H);
        }
        assertTrue(ball.hasLanded());
        assertEquals(0f, ball.getParticle().position.y);
        assertEquals(ball.getLandingX(), ball.getParticle().position.x);

        String hud = write(true);

        StringBuilder expected = new StringBuilder("landed at x = ");
        particlelab.view.TextFormat.appendFixed(expected, ball.getLandingX(), 2)
                .append(" m after ");
        particlelab.view.TextFormat.appendFixed(expected, ball.getLandingSeconds(), 2)
                .append(" s\n");
        assertTrue(hud.contains(expected), hud);
        // The stepped samples lie on the parabola launched with vy − g·h/2, which lands at
        // 2·vy/g − h = 2.024 s; the chord between two samples is off that parabola by at most
        // g·h²/8 in y, 3.4e-5 s at the landing speed of 10 m/s, so 1e-4 s is safe.
        double h = H;
        assertEquals(2.0 * 10.0 / Gravity.STANDARD_G - h, ball.getLandingSeconds(), 1e-4);
    }

    @Test
    void scalesArePrintedAsTheKeysMakeThem() {
        assertEquals("x64", HudWriter.appendScale(new StringBuilder(), 64f).toString());
        assertEquals("x1", HudWriter.appendScale(new StringBuilder(), 1f).toString());
        assertEquals("x1/2", HudWriter.appendScale(new StringBuilder(), 0.5f).toString());
        assertEquals("x1/64", HudWriter.appendScale(new StringBuilder(), 1f / 64f).toString());
        assertEquals("x1.50", HudWriter.appendScale(new StringBuilder(), 1.5f).toString());
        assertEquals("x0.300", HudWriter.appendScale(new StringBuilder(), 0.3f).toString());
    }

    private void run(int frames, float tpf) {
        for (int i = 0; i < frames; ++i) {
            clock.advance(tpf, seconds -> { });
        }
    }

    private String write(boolean sceneOver) {
        return writer.write(new StringBuilder(), sceneOver).toString();
    }

    private static KeyBinding key(int code, String label) {
        return new KeyBinding(code, label, label, () -> { });
    }
}

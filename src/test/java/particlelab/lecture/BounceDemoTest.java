package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.Callable;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.physics.Gravity;
import particlelab.view.TextFormat;
import particlelab.world.Detection;
import particlelab.world.HopCycle;

/**
 * What the Bounce demo's HUD says against the closed forms. Plain JUnit: the demo's physics
 * and HUD text run without jME. Its height graph (a view) and its sound line (written by a
 * frame) are checked in {@link LectureFramesHeadlessTest}.
 */
class BounceDemoTest {

    private static final float H = 1f / 60f;
    private static final double G = Gravity.STANDARD_G;
    private final BounceDemo bounce = declared(new BounceDemo());

    @Test
    void apexesFollowEToThe2nTimesH0WithinTheStepBound() throws Exception {
        float[] apexes = measure(() -> {
            bounce.configure(0.8f, 0, false, Detection.SWEPT);
            for (int frame = 0; frame < 600; ++frame) {
                bounce.getRun().advancePhysics(H);
            }
            BounceRecorder recorder = bounce.getRecorder(Detection.SWEPT);
            float[] result = new float[recorder.countApexes()];
            for (int i = 0; i < result.length; ++i) {
                result[i] = recorder.getApex(i);
            }
            return result;
        });
        double h0 = BounceDemo.DROP_HEIGHT;
        double e = 0.8;
        assertTrue(apexes.length >= 6, "apexes: " + apexes.length);
        for (int k = 1; k <= 6; ++k) {
            // The world's bound (BounceTest): after k impacts the stepped ball is off by at
            // most about one step of travel per impact at the rebound speed, (k+1)·v'·h.
            double rebound = e * Math.pow(e, k - 1) * Math.sqrt(2.0 * G * h0);
            assertEquals(h0 * Math.pow(e, 2 * k), apexes[k - 1], (k + 1) * rebound * H,
                    "apex " + k);
        }
    }

    @Test
    void withEOneTheSweptTestKeepsItsApexesAndTheHudComparesBoth() throws Exception {
        Object[] result = measure(() -> {
            bounce.configure(1f, 0, false, Detection.SWEPT);
            for (int frame = 0; frame < 600; ++frame) {
                bounce.getRun().advancePhysics(H);
            }
            BounceRecorder swept = bounce.getRecorder(Detection.SWEPT);
            return new Object[] {swept.getApex(swept.countApexes() - 1),
                bounce.getRecorder(Detection.OVERLAP).countApexes(),
                bounce.getWindow().formatHud(new StringBuilder()).toString()};
        });
        // Swept: every impact is found on the step's segment, so the apex stays within one
        // step's travel at the impact speed (8.9 m/s · h = 0.15 m) of h0.
        double v = Math.sqrt(2.0 * G * BounceDemo.DROP_HEIGHT);
        assertEquals(BounceDemo.DROP_HEIGHT, (Float) result[0], v * H);
        assertTrue((Integer) result[1] >= 3);
        String hud = (String) result[2];
        assertTrue(hud.contains("time to rest: T = t0 (1+e)/(1-e) = never (e = 1)"), hud);
        assertTrue(hud.contains("e = 1, apex - h0 after "), hud);
        assertTrue(hud.contains("never at rest (e = 1)"), hud);
    }

    @Test
    void withCyclonesThresholdAndNoFixTheHudShowsTheFixedPointTheBallHopsAt() throws Exception {
        String[] huds = measure(() -> {
            String[] result = new String[3];
            bounce.configure(0.8f, 1, false, Detection.SWEPT);
            for (int frame = 0; frame < 3600; ++frame) {
                bounce.getRun().advancePhysics(H);
            }
            result[0] = bounce.getWindow().formatHud(new StringBuilder()).toString();
            result[1] = String.valueOf(bounce.getRecorder(Detection.SWEPT).isResting());
            bounce.configure(0.8f, 2, false, Detection.SWEPT);
            for (int frame = 0; frame < 3600; ++frame) {
                bounce.getRun().advancePhysics(H);
            }
            result[2] = bounce.getWindow().formatHud(new StringBuilder()).toString();
            return result;
        });
        // The 4 m drop with e = 0.8 settles on hops of K = 4 steps (HopCycleTest checks the
        // stepped impacts against it): w* = 4·g·h/1.8 = 0.363 m/s, above Cyclone's 0.25 m/s.
        StringBuilder expected = new StringBuilder("never at rest: hops of K = 4 steps, fixed"
                + " point w* = K g h/(1+e) = ");
        TextFormat.appendFixed(expected, HopCycle.fixedPointSpeed(4, 0.8f, (float) G, H), 3)
                .append(" m/s > threshold 0.25 m/s\n");
        assertEquals("false", huds[1], "still hopping after 60 s");
        assertTrue(huds[0].contains("swept lane " + expected), huds[0]);
        assertTrue(huds[0].contains("   swept "), huds[0]);
        assertTrue(huds[0].contains("0.363 m/s"), huds[0]);
        // Box2D's 1 m/s is above w*: both balls rest and the line is gone.
        assertTrue(huds[2].contains("at rest at "), huds[2]);
        assertFalse(huds[2].contains("never at rest"), huds[2]);
        assertFalse(huds[2].contains("still bouncing"), huds[2]);
    }

    /**
     * With e = 1 the swept ball bounces for ever; after more apexes than the recorder's ring
     * holds, the table still shows the latest four (numbered to the count), not rows 61 to 64
     * for ever. One bounce from 4 m takes 2·t0 = 1.81 s: 9000 steps (150 s) give about 83.
     */
    @Test
    void theApexTableKeepsShowingTheLatestApexesPastTheRing() throws Exception {
        Object[] result = measure(() -> {
            bounce.configure(1f, 0, false, Detection.SWEPT);
            for (int frame = 0; frame < 9000; ++frame) {
                bounce.getRun().advancePhysics(H);
            }
            BounceRecorder swept = bounce.getRecorder(Detection.SWEPT);
            int count = swept.countApexes();
            return new Object[] {count, swept.getApex(count - 1),
                bounce.getWindow().formatHud(new StringBuilder()).toString()};
        });
        int count = (Integer) result[0];
        assertTrue(count > BounceRecorder.MAX_APEXES + 4, "apexes " + count);
        StringBuilder latest = new StringBuilder("  ").append(count).append(": ");
        TextFormat.appendFixed(latest, (Float) result[1], 3);
        String hud = (String) result[2];
        assertTrue(hud.contains(latest), latest + " in " + hud);
        assertTrue(hud.contains("  " + (count - 3) + ": "), hud);
    }

    /**
     * With e = 0.9 and no threshold the demo's 4 m drop ends on a cycle of 64 hops, not on
     * one K (HopCycleTest re-measures it in a world of its own): the HUD names the cycle from
     * the latest impacts, and never a fixed point the ball is not on.
     */
    @Test
    void withEPointNineTheHudNamesTheCycleOfHopsTheBallIsOn() throws Exception {
        String hud = measure(() -> {
            bounce.configure(0.9f, 0, false, Detection.SWEPT);
            for (int frame = 0; frame < 12_000; ++frame) {
                bounce.getRun().advancePhysics(H);
            }
            return bounce.getWindow().formatHud(new StringBuilder()).toString();
        });
        assertTrue(hud.contains("swept lane never at rest: a cycle of 64 hops, K = 4 to 9"
                + " steps, impacts 0.300 to 0.815 m/s, all > threshold 0.00 m/s\n"), hud);
        assertFalse(hud.contains("fixed point"), hud);
    }

    /** Run one block of a test and hand back what it measured. */
    private static <T> T measure(Callable<T> block) throws Exception {
        return block.call();
    }

    /**
     * Declare a demo's scene, as a window's start does before anything else: its setters
     * act on the particles the scene created.
     */
    private static <D extends DemoState> D declared(D demo) {
        demo.getRun();
        return demo;
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.aiming.CheatFrontier;
import particlelab.aiming.Hitscan;
import particlelab.physics.Gravity;
import particlelab.view.TextFormat;

/** The cheat demo's frontier lane, in plain JUnit: its four ways, HUD and choice. */
class FastBulletsFrontierTest {

    private static final float H = 1f / 60f;
    private static final float G = Gravity.STANDARD_G;

    /**
     * At each speed the demo's four ways are the closed forms' (the straight lines by the drop
     * D, the corrected aim by D³/d², the ray at t = 0), and the stepped way's miss is the
     * demo's own projectile's crossing: the round-off bound of {@code HitscanTest} (2·N ulps
     * of the drop and of d).
     */
    @Test
    void theFrontierIsTheClosedFormsAndTheSteppedWayIsTheDemosProjectile() {
        FastBulletsDemo demo = new FastBulletsDemo();
        for (int index = 0; index < FastBulletsDemo.SPEEDS.length; ++index) {
            demo.setSpeedIndex(index);
            float v = demo.getSpeed();
            CheatFrontier frontier = demo.getFrontier();
            double drop = Hitscan.formulaDrop(G, FastBulletsDemo.DISTANCE, v);
            double slope = drop / FastBulletsDemo.DISTANCE;
            assertEquals(-drop, frontier.getMiss(CheatFrontier.Way.STRAIGHT), 1e-12 * drop);
            assertEquals(-drop * slope * slope, frontier.getMiss(CheatFrontier.Way.CORRECTED),
                    1e-9 * drop);
            assertEquals(0.0, frontier.getHitSeconds(CheatFrontier.Way.RAY));
            int frames = 0;
            while (!demo.isReached() && frames < 600) {
                demo.getRun().advancePhysics(H);
                ++frames;
            }
            assertTrue(demo.isReached(), "v = " + v);
            double steps = FastBulletsDemo.DISTANCE / (v * (double) H);
            double roundOff = 2.0 * Math.ceil(steps) * (Math.ulp((float) drop)
                    + Math.ulp(FastBulletsDemo.DISTANCE));
            assertEquals(-demo.getSteppedDrop(), frontier.getMiss(CheatFrontier.Way.STEPPED),
                    roundOff, "v = " + v);
            assertEquals(demo.getArrivalSeconds(),
                    frontier.getHitSeconds(CheatFrontier.Way.STEPPED), roundOff / v + 1e-6);
        }
    }

    /**
     * The HUD's frontier lines carry each way's miss as the frontier computes it, and say the
     * cost is not timed without an application (it is timed once when the demo starts in
     * one). The shot parameter marks the way shown.
     */
    @Test
    void theHudListsTheFourWaysAndMarksTheOneShown() {
        FastBulletsDemo demo = new FastBulletsDemo();
        demo.getRun().advancePhysics(H);
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        String[] names = {"ray ", "line ", "raised ", "stepped "};
        CheatFrontier.Way[] ways = CheatFrontier.Way.values();
        for (int w = 0; w < ways.length; ++w) {
            StringBuilder expected = new StringBuilder(names[w]);
            TextFormat.appendFixed(expected, demo.getFrontier().getMiss(ways[w]), 3);
            assertTrue(hud.contains(expected), expected + " in\n" + hud);
        }
        assertTrue(hud.contains("Ways (L: all)"), hud);
        assertTrue(hud.contains("not timed"), hud);
        demo.getParameters().set("shot", 3);
        assertEquals(3, demo.getShown());
        hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("[raised] "), hud);
        assertTrue(hud.contains("Ways (L: raised)"), hud);
    }
}

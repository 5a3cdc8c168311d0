package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;

/** The cheat's frontier: each way's miss and hit time against the closed forms. */
class CheatFrontierTest {

    private static final float G = Gravity.STANDARD_G;
    private static final float H = 1f / 60f;
    private static final float D = 50f;
    private static final float R = 0.5f;
    /** The cheat demo's speeds, slowest to fastest (m/s). */
    private static final float[] SPEEDS = {35f, 50f, 100f, 300f, 900f};

    /**
     * The instant ray finds the centre at t = 0; a real bullet on its level aim falls the
     * closed-form drop {@code ½·g·(d/v)²}. At 35 m/s that is 10.0 m: a miss.
     */
    @Test
    void theRayHitsAtTimeZeroAndMissesByTheDrop() {
        for (float v : SPEEDS) {
            CheatFrontier frontier = new CheatFrontier(G, D, R, v, H);
            assertEquals(0.0, frontier.getHitSeconds(CheatFrontier.Way.RAY));
            assertEquals(0, frontier.getSteps(CheatFrontier.Way.RAY));
            // The ray's segment meets the plane at its own height, 0, exactly.
            assertEquals(0.0, frontier.shoot(CheatFrontier.Way.RAY));
            double drop = 0.5 * G * (D / (double) v) * (D / (double) v);
            // Same double operations up to their order: a few ulps of the drop.
            assertEquals(-drop, frontier.getMiss(CheatFrontier.Way.RAY), 1e-12 * drop);
        }
        assertFalse(new CheatFrontier(G, D, R, 35f, H).hits(CheatFrontier.Way.RAY));
    }

    /**
     * The straight-line bullet takes the travel time: it arrives at {@code d/v}, on the
     * centre, and a real bullet then is {@code ½·g·t²} lower, t its own measured arrival
     * (independent of the drop formula). Tolerances: the bullet's x is a float sum of N steps
     * {@code v·h}, each rounding by at most half an ulp of d (2^-19 m near 50 m), so its
     * arrival time is off by at most {@code N·ulp(d)/v}; the drop at that time by
     * {@code g·t·δt}. Its y stays 0: no drop, no slope.
     */
    @Test
    void theStraightLineArrivesAtDOverVAndMissesByTheClosedFormDrop() {
        for (float v : SPEEDS) {
            CheatFrontier frontier = new CheatFrontier(G, D, R, v, H);
            double t = D / (double) v;
            int n = frontier.getSteps(CheatFrontier.Way.STRAIGHT);
            // ceil(t/h) steps, or one more where t/h is a whole number and rounding falls short
            assertTrue(n >= t / H && n <= Math.ceil(t / H) + 1.0, n + " steps at v = " + v);
            double timeTolerance = n * Math.ulp(D) / v;
            double arrival = frontier.getHitSeconds(CheatFrontier.Way.STRAIGHT);
            assertEquals(t, arrival, timeTolerance, "d/v at v = " + v);
            assertEquals(0.0, frontier.shoot(CheatFrontier.Way.STRAIGHT));
            double realBullet = -0.5 * G * arrival * arrival;
            assertEquals(realBullet, frontier.getMiss(CheatFrontier.Way.STRAIGHT),
                    G * t * timeTolerance + 1e-12, "miss at v = " + v);
        }
    }

    /**
     * The drop-corrected aim, {@code tan θ = D/d}: its own straight line meets the plane D
     * above the centre, and a real bullet fired along it misses by {@code −D·tan²θ = −D³/d²}
     * (class Javadoc), second order in the slope: under 1 % of D wherever {@code D < d/10}.
     * The closed form and the parabola's double arithmetic agree to 1e-9 of D (cancellation
     * of two numbers near D leaves about 1e-16·D/tan²θ, at most 1e-11·D here). The line's
     * crossing height is a float sum: N steps each rounding y by half an ulp of D.
     */
    @Test
    void theDropCorrectedAimMissesByTheSecondOrderTerm() {
        for (float v : SPEEDS) {
            CheatFrontier frontier = new CheatFrontier(G, D, R, v, H);
            double drop = frontier.getDrop();
            double slope = drop / D;
            double miss = frontier.getMiss(CheatFrontier.Way.CORRECTED);
            assertEquals(-drop * slope * slope, miss, 1e-9 * drop, "v = " + v);
            // The bound D·tan²θ, with the cancellation's round-off (above) as its slack.
            assertTrue(Math.abs(miss) <= drop * slope * slope + 1e-11 * drop, "v = " + v);
            if (slope < 0.1) {
                assertTrue(Math.abs(miss) < 0.01 * drop, "v = " + v);
            }
            int n = frontier.getSteps(CheatFrontier.Way.CORRECTED);
            double lineY = frontier.shoot(CheatFrontier.Way.CORRECTED);
            assertEquals(drop, lineY, n * Math.ulp((float) drop) + 1e-6, "v = " + v);
        }
        // 35 m/s: D = 10 m, tan θ = 0.2, the corrected aim misses by D³/d² = 0.4 m, inside r
        // (to 1e-6 m: g is the float 9.8f, 2e-8 off 9.8, and the miss goes as g³).
        CheatFrontier slow = new CheatFrontier(G, D, R, 35f, H);
        assertEquals(-0.4, slow.getMiss(CheatFrontier.Way.CORRECTED), 1e-6);
        assertTrue(slow.hits(CheatFrontier.Way.CORRECTED));
    }

    /**
     * The stepped projectile's miss is the shared integrator's own crossing: the existing
     * {@link Hitscan#steppedDrop} (tested in {@code HitscanTest}, whose round-off bound this
     * uses), and its hit time {@code d/v} to the same bound.
     */
    @Test
    void theSteppedProjectilesMissIsTheSteppedDrop() {
        for (float v : SPEEDS) {
            CheatFrontier frontier = new CheatFrontier(G, D, R, v, H);
            double stepped = Hitscan.steppedDrop(G, D, v, H);
            double steps = D / (v * (double) H);
            double roundOff = 2.0 * Math.ceil(steps)
                    * (Math.ulp((float) stepped) + Math.ulp(D));
            assertEquals(-stepped, frontier.getMiss(CheatFrontier.Way.STEPPED), roundOff);
            assertEquals(D / (double) v, frontier.getHitSeconds(CheatFrontier.Way.STEPPED),
                    roundOff / v + 1e-6);
            // It falls more than the straight line's real bullet: by the half step ½·g·h·t.
            assertTrue(frontier.getMiss(CheatFrontier.Way.STEPPED)
                    < frontier.getMiss(CheatFrontier.Way.STRAIGHT));
        }
    }

    /**
     * A frontier reset in place for another speed and step gives, way by way, what a new one
     * for that speed and step gives: the same operations on the same inputs, so equal
     * exactly (no tolerance).
     */
    @Test
    void aFrontierResetInPlaceEqualsANewOne() {
        CheatFrontier reused = new CheatFrontier(G, D, R, SPEEDS[0], H);
        float[] steps = {H, 1.1f * H, 0.9f * H, 0.25f};
        for (float v : SPEEDS) {
            for (float h : steps) {
                reused.reset(v, h);
                CheatFrontier fresh = new CheatFrontier(G, D, R, v, h);
                assertEquals(v, reused.getSpeed());
                assertEquals(h, reused.getStepSeconds());
                assertEquals(fresh.getDrop(), reused.getDrop());
                for (CheatFrontier.Way way : CheatFrontier.Way.values()) {
                    assertEquals(fresh.getMiss(way), reused.getMiss(way), way + " miss");
                    assertEquals(fresh.getHitSeconds(way), reused.getHitSeconds(way),
                            way + " hit time");
                    assertEquals(fresh.getSteps(way), reused.getSteps(way), way + " steps");
                    assertEquals(fresh.hits(way), reused.hits(way), way + " hit");
                }
            }
        }
    }

    /** A bad reset is refused naming the value, and leaves the frontier as it was. */
    @Test
    void aBadResetIsRefusedAndChangesNothing() {
        CheatFrontier frontier = new CheatFrontier(G, D, R, 50f, H);
        double miss = frontier.getMiss(CheatFrontier.Way.STEPPED);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> frontier.reset(100f, Float.NaN));
        assertTrue(e.getMessage().contains("step h"), e.getMessage());
        assertEquals(50f, frontier.getSpeed());
        assertEquals(H, frontier.getStepSeconds());
        assertEquals(miss, frontier.getMiss(CheatFrontier.Way.STEPPED));
    }

    @Test
    void badInputIsRefusedNamingTheValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new CheatFrontier(G, D, R, Float.NaN, H));
        assertTrue(e.getMessage().contains("speed v"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new CheatFrontier(G, D, R, 35f, 0f));
        CheatFrontier frontier = new CheatFrontier(G, D, R, 35f, H);
        e = assertThrows(IllegalArgumentException.class, () -> frontier.shoot(null));
        assertTrue(e.getMessage().contains("way"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> frontier.getMiss(null));
    }
}

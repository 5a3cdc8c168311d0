package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SafetyParabolaTest {

    private static final double G = 9.8;
    private static final double SPEED = 30.0;

    /** Straight up s²/(2g) = 45.918 m; the level range s²/g = 91.837 m. */
    @Test
    void envelopeMeetsTheApexStraightUpAndTheMaximumRange() {
        assertEquals(SPEED * SPEED / (2.0 * G), LaunchAngles.envelopeHeight(SPEED, 0.0, G),
                1e-12);
        assertEquals(0.0, LaunchAngles.envelopeHeight(SPEED, SPEED * SPEED / G, G), 1e-12);
    }

    /**
     * Just below the envelope both angles exist and nearly coincide; just above there is none.
     * The margin 1e-6 m is far above the double round-off of the discriminant at these sizes
     * (about 1e-13 relative). Below it by δ the discriminant ratio of
     * LaunchAngles is {@code 1 − q = 2g·δ/s²}, so {@code tan θ = u·(1 ± sqrt(2g·δ)/s)}: a
     * relative split of 1.5e-4, at most {@code 1.5e-4·sin θ·cos θ ≤ 7.5e-5} rad in angle,
     * well inside 1e-3 rad.
     */
    @Test
    void targetsBelowTheEnvelopeAreReachableAndAboveAreNot() {
        for (double x : new double[] {5.0, 30.0, 60.0, 90.0, 120.0}) {
            double top = LaunchAngles.envelopeHeight(SPEED, x, G);
            LaunchAngles below = LaunchAngles.solve(SPEED, x, top - 1e-6, G);
            assertTrue(below.isReachable(), "x=" + x);
            // On the envelope the two roots merge: one angle, atan(s²/(g·x)).
            double merged = Math.atan(SPEED * SPEED / (G * x));
            assertEquals(merged, below.getLowRadians(), 1e-3, "x=" + x);
            assertEquals(merged, below.getHighRadians(), 1e-3, "x=" + x);
            assertFalse(LaunchAngles.solve(SPEED, x, top + 1e-6, G).isReachable(), "x=" + x);
        }
    }
}

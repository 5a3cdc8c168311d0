package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class LaunchAnglesTest {

    private static final double G = 9.8;
    /**
     * The angles come from a square root and an arctangent of values near s² ≈ 1e3; the
     * heights checked are a few metres: 1e-9 m leaves room for a few hundred ulps.
     */
    private static final double HEIGHT_TOLERANCE = 1e-9;

    @Test
    void bothAnglesHitTheTargetOnTheExactParabola() {
        double speed = 30.0;
        double x = 50.0;
        double y = 5.0;
        LaunchAngles angles = LaunchAngles.solve(speed, x, y, G);
        assertTrue(angles.isReachable());
        assertEquals("reachable", angles.getExplanation());
        assertTrue(angles.getLowRadians() < angles.getHighRadians());
        assertEquals(y, heightAt(speed, angles.getLowRadians(), x), HEIGHT_TOLERANCE);
        assertEquals(y, heightAt(speed, angles.getHighRadians(), x), HEIGHT_TOLERANCE);
    }

    @Test
    void levelTargetAnglesAreComplementary() {
        // y = 0: tan θ1 · tan θ2 = 1, so θ1 + θ2 = 90°.
        LaunchAngles angles = LaunchAngles.solve(25.0, 40.0, 0.0, G);
        assertEquals(Math.PI / 2.0, angles.getLowRadians() + angles.getHighRadians(), 1e-12);
        assertEquals(0.0, heightAt(25.0, angles.getLowRadians(), 40.0), HEIGHT_TOLERANCE);
    }

    @Test
    void maximumRangeHasOneAngleOf45Degrees() {
        // s = 10, g = 10: the level range peaks at s²/g = 10 m, where the discriminant is 0
        // exactly (all values are small integers).
        LaunchAngles angles = LaunchAngles.solve(10.0, 10.0, 0.0, 10.0);
        assertEquals(Math.PI / 4.0, angles.getLowRadians(), 1e-15);
        assertEquals(Math.PI / 4.0, angles.getHighRadians(), 1e-15);
    }

    @Test
    void beyondTheRangeIsOutOfReachWithAReason() {
        // s = 20 reaches at most s²/g = 40.8 m on level ground.
        LaunchAngles angles = LaunchAngles.solve(20.0, 50.0, 0.0, G);
        assertFalse(angles.isReachable());
        assertTrue(Double.isNaN(angles.getLowRadians()));
        assertTrue(Double.isNaN(angles.getHighRadians()));
        assertTrue(angles.getExplanation().contains("out of reach at launch speed 20.0 m/s"),
                angles.getExplanation());
        // Too high even straight up: s²/(2g) = 20.4 m.
        assertFalse(LaunchAngles.solve(20.0, 1.0, 25.0, G).isReachable());
    }

    /** The height of the drag-free parabola at horizontal distance x. */
    private static double heightAt(double speed, double radians, double x) {
        double time = x / (speed * Math.cos(radians));
        return speed * Math.sin(radians) * time - G * time * time / 2.0;
    }

    /**
     * A huge launch speed once overflowed s⁴ and gave a −90° "solution". The angles tend to
     * their true limits: the lob straight up, the flat shot along the line of sight atan(y/x).
     */
    @Test
    void aHugeSpeedGivesTheLimitingAnglesNotMinusNinetyDegrees() {
        for (double height : new double[] {0.0, 30.0, -30.0}) {
            LaunchAngles angles = LaunchAngles.solve(1e100, 100.0, height, G);
            assertTrue(angles.isReachable());
            // u = s²/(g·x) ≈ 1e197: tan θ_high = 2u is far beyond 1e16, so θ_high rounds to
            // π/2; tan θ_low = k + (1 + k²)/(2u) equals k = y/x to round-off.
            assertEquals(Math.PI / 2.0, angles.getHighRadians(), 1e-15);
            assertEquals(Math.atan(height / 100.0), angles.getLowRadians(), 1e-15);
        }
        // s = 1e200: s² overflows the double range, u itself is infinite, the limits hold.
        LaunchAngles beyond = LaunchAngles.solve(1e200, 100.0, 30.0, G);
        assertEquals(Math.atan(0.3), beyond.getLowRadians(), 1e-15);
        assertEquals(Math.PI / 2.0, beyond.getHighRadians(), 0.0);
    }

    @Test
    void proportionsBeyondTheDoubleRangeAreRefused() {
        IllegalArgumentException thrown = org.junit.jupiter.api.Assertions.assertThrows(
                IllegalArgumentException.class,
                () -> LaunchAngles.solve(10.0, Double.MIN_VALUE, 1e300, G));
        assertTrue(thrown.getMessage().contains("out of the double range"), thrown.getMessage());
    }
}

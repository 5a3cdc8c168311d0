package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

class LevelAimTest {

    private static final double G = 9.8;
    private static final float VX = 20f;
    private static final float H = 1f / 60f;
    /** Long enough for every shot here (they fly 0.5 to 15 s). */
    private static final float MAX_FLIGHT_SECONDS = 60f;
    /** A few double operations: a few units in the last place of values near 25. */
    private static final double ROUND_OFF = 1e-12;

    private final ShotSimulator simulator =
            new ShotSimulator(new ParticleIntegrator(new Gravity()), 1f, H, MAX_FLIGHT_SECONDS);
    private final Landing landing = new Landing();

    @Test
    void lectureFormulaGivesGSOverTwoVxAndFlightTimeSOverVx() {
        assertEquals(24.5, LevelAim.lectureVy(G, 100.0, 20.0), ROUND_OFF);
        assertEquals(5.0, LevelAim.flightTime(100.0, 20.0), ROUND_OFF);
        assertEquals(9.8 * 30.0 / (2.0 * 7.0), LevelAim.lectureVy(G, 30.0, 7.0), ROUND_OFF);
    }

    @Test
    void discreteCorrectionMatchesNumericsReference() {
        // docs/numerics.md: vx = 20, S = 100, h = 1/60 gives 24.58166666666667.
        assertEquals(24.58166666666667, LevelAim.discreteVy(G, 100.0, 20.0, 1.0 / 60.0),
                ROUND_OFF);
        // Whole N = S/(vx·h): the lecture's correction g·(S/vx + h)/2.
        assertEquals(G * (50.0 / 10.0 + 0.1) / 2.0, LevelAim.discreteVy(G, 50.0, 10.0, 0.1),
                ROUND_OFF);
    }

    /**
     * The discrete vy, stepped by the shared integrator in float, lands at S for whole and
     * non-whole step counts N = S/(vx·h). In exact arithmetic the interpolated crossing is S
     * (checked in double to 1e-12 when deriving the formula); here the float position
     * accumulates one rounding of at most ulp(S)/2 per step in x and a similar one in y, so the
     * landing may drift by up to about N·ulp(S). Measured: 1.3e-4 m at S = 100 (N = 300),
     * against a bound of 2.3e-3 m.
     */
    @ParameterizedTest
    @ValueSource(doubles = {100.0, 97.3, 123.456, 55.5, 10.01})
    void discreteVyLandsAtSWhenStepped(double distance) {
        double vy = LevelAim.discreteVy(G, distance, VX, H);
        assertTrue(simulator.fire(VX, (float) vy, landing));
        double steps = distance / (VX * (double) H);
        double tolerance = steps * Math.ulp((float) distance);
        assertEquals(distance, landing.getX(), tolerance);
    }

    /**
     * The lecture's vy lands vx·h short: the stepped samples lie exactly on the parabola
     * launched with vy − g·h/2, whose crossing is vx·h short of S. The crossing is read off the
     * chord between two samples, which sags below the parabola by at most g·h²/8 in height;
     * at the landing slope |dy/dx| = (vy − g·h/2)/vx that moves the landing by at most
     * g·h²·vx/(8·(vy − g·h/2)), about 5e-4 m here, always shorter. Float round-off adds up to
     * N·ulp(S) as above. S = 100 is the docs/numerics.md hazard (y_299 = 0 exactly): the
     * interpolated crossing does not care.
     */
    @ParameterizedTest
    @ValueSource(doubles = {100.0, 97.3, 55.5, 300.1})
    void lectureVyLandsVxHShort(double distance) {
        double vy = LevelAim.lectureVy(G, distance, VX);
        assertTrue(simulator.fire(VX, (float) vy, landing));
        double shortfall = VX * (double) H;
        double chordSag = G * H * H * VX / (8.0 * (vy - G * H / 2.0));
        double roundOff = distance / shortfall * Math.ulp((float) distance);
        double miss = landing.getX() - distance;
        assertTrue(miss <= -shortfall + roundOff && miss >= -shortfall - chordSag - roundOff,
                "miss " + miss + " should be -vx·h = " + -shortfall + " less up to " + chordSag);
    }

    @Test
    void badInputNamesTheParameter() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> LevelAim.lectureVy(G, -1.0, 20.0));
        assertTrue(e.getMessage().contains("distance S (m)"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> LevelAim.discreteVy(G, 100.0, 20.0, 0.0));
        assertTrue(e.getMessage().contains("step h (s)"), e.getMessage());
    }

    /** Closed forms that overflow the double range once returned Infinity. */
    @Test
    void resultsBeyondTheDoubleRangeAreRefused() {
        IllegalArgumentException vy = assertThrows(IllegalArgumentException.class,
                () -> LevelAim.lectureVy(1e300, 1e300, 1.0));
        assertTrue(vy.getMessage().contains("out of the double range"), vy.getMessage());
        assertThrows(IllegalArgumentException.class, () -> LevelAim.flightTime(1e300, 1e-300));
        assertThrows(IllegalArgumentException.class,
                () -> LevelAim.discreteVy(1e300, 1e300, 1.0, 1.0 / 60.0));
        // g·S overflows, g·S/(2·vx) does not: computed in the other order.
        assertEquals(2.5e300, LevelAim.lectureVy(1e300, 100.0, 20.0), 1e286);
        assertEquals(5e299, LevelAim.lectureVy(1e300, 1e300, 1e300), 1e285);
    }
}

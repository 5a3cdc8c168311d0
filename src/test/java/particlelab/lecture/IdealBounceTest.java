package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The ideal bouncing ball against its geometric series, in plain JUnit. */
class IdealBounceTest {

    private static final double G = 9.81;
    /** Double arithmetic over a few dozen flights: round-off near 1e-15 relative. */
    private static final double TOLERANCE = 1e-9;

    @Test
    void eachFlightPeaksAtETo2nTimesH0AndEndsOnTheGround() {
        double h0 = 4.0;
        double e = 0.8;
        IdealBounce ball = new IdealBounce(h0, e, G);
        double t0 = Math.sqrt(2.0 * h0 / G);
        assertEquals(t0, ball.getFallSeconds(), TOLERANCE);
        assertEquals(h0, ball.height(0.0), TOLERANCE);
        assertEquals(0.0, ball.height(t0), TOLERANCE);
        double start = t0;
        for (int n = 1; n <= 8; ++n) {
            double flight = 2.0 * Math.pow(e, n) * t0;
            assertEquals(Math.pow(e, 2 * n) * h0, ball.height(start + 0.5 * flight), TOLERANCE,
                    "apex " + n);
            assertEquals(0.0, ball.speed(start + 0.5 * flight), TOLERANCE, "still at apex " + n);
            // Just after the impact (its instant belongs to either flight): the rebound,
            // less the speed gravity took in that microsecond.
            assertEquals(Math.pow(e, n) * G * t0, ball.speed(start + 1e-6), G * 1e-6 + TOLERANCE,
                    "rebound " + n);
            start += flight;
        }
        assertEquals(t0 * (1.0 + e) / (1.0 - e), ball.getRestSeconds(), TOLERANCE);
        assertEquals(0.0, ball.height(ball.getRestSeconds() + 1.0), 0.0, "at rest after T");
    }

    @Test
    void withEOneTheBallKeepsItsHeightAndWithEZeroItStops() {
        IdealBounce elastic = new IdealBounce(1.0, 1.0, G);
        double t0 = elastic.getFallSeconds();
        assertEquals(1.0, elastic.height(t0 + 11 * 2.0 * t0 + t0), TOLERANCE);
        assertEquals(Double.POSITIVE_INFINITY, elastic.getRestSeconds(), 0.0);
        IdealBounce dead = new IdealBounce(1.0, 0.0, G);
        assertEquals(0.0, dead.height(2.0 * t0), 0.0);
        assertEquals(t0, dead.getRestSeconds(), TOLERANCE);
    }

    @Test
    void badValuesAreRefusedByName() {
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> new IdealBounce(4.0, 1.5, G));
        assertEquals("h0 (m) and g (m/s^2) must be finite and > 0, e from 0 to 1, but were"
                + " 4.0, 9.81, 1.5", bad.getMessage());
    }
}

package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.collision.Plane;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/** The one place a flight's ground crossing is found and interpolated. */
class FlightTest {

    private static final float H = 1f / 60f;

    /** A particle with no force moves on a straight line: its segments are easy to check. */
    private final Flight drift = new Flight(new ParticleIntegrator());

    @Test
    void aStepCrossesTheGroundOnlyFromAtOrAboveToStrictlyBelow() {
        // From 3 m to -1 m in one step: the line meets y = 0 three quarters of the way,
        // exact in binary, and x is interpolated on the same segment.
        Particle p = particle(0f, 3f, 8f, -4f);
        double fraction = drift.step(p, 1f);
        assertEquals(0.75, fraction, 0.0);
        assertEquals(6.0, drift.crossingX(fraction), 0.0);
        // A sample exactly on the ground is still "above": the crossing is in the next step
        // (testing y <= 0 would stop the lecture's own shot a whole step early).
        assertEquals(Flight.NO_LANDING, drift.step(particle(0f, 1f, 0f, -1f), 1f), 0.0);
        // From the ground itself, going down: at the start of the step.
        assertEquals(0.0, drift.step(particle(0f, 0f, 0f, -0.5f), 1f), 0.0);
        // Going up: no landing.
        assertEquals(Flight.NO_LANDING, drift.step(particle(0f, -1f, 0f, 2f), 1f), 0.0);
    }

    @Test
    void theLecturesShotLandsVxTimesHShort() {
        // HelloAiming: S = 100 m, vx = 20 m/s, vy = g·S/(2·vx) = 24.5 m/s; stepped with
        // semi-implicit Euler it lands vx·h = 0.333 m short, at T − h = 5 − 1/60 s.
        Flight shot = new Flight(new ParticleIntegrator(new Gravity()));
        Landing landing = new Landing();
        assertTrue(shot.fly(particle(0f, 0f, 20f, 24.5f), H, 1000, landing));
        // The crossing lies on a chord of the stepped parabola: within g·h²/8 of it, and the
        // float steps add ~1e-5 m; 1e-3 m is safe and far below vx·h.
        assertEquals(100.0 - 20.0 * H, landing.getX(), 1e-3);
        assertEquals(5.0 - H, landing.getTimeSeconds(), 1e-4);
        assertEquals(299, landing.getSteps());
    }

    @Test
    void aShotStillInTheAirAfterTheLastStepHasNotLanded() {
        Flight shot = new Flight(new ParticleIntegrator(new Gravity()));
        Landing landing = new Landing();
        assertFalse(shot.fly(particle(0f, 0f, 20f, 24.5f), H, 10, landing));
        assertFalse(landing.hasLanded());
        assertEquals(10, landing.getSteps());
    }

    /**
     * A step swept against a target of the caller's (a hitscan's disc or sphere) is the
     * integrator's step and that sweep on its segment, and the crossing is interpolated on the
     * same segment: the hitscan's shots go through this one helper, bit for bit what it did
     * with its own loop.
     */
    @Test
    void aStepSweptAgainstATargetIsTheStepAndTheSweepOnItsSegment() {
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Flight flight = new Flight(gravity);
        Particle flown = particle(0.25f, 1.5f, 300f, 0.7f);
        Particle byHand = particle(0.25f, 1.5f, 300f, 0.7f);
        // A plane x = 4 facing back along x, swept with radius 0 as the disc's face is.
        Plane face = new Plane(new Vector3f(-1f, 0f, 0f), -4f);
        Vector3f normal = new Vector3f();
        Flight.Sweep sweep = (from, to) -> face.sweep(from, to, 0f, normal);
        for (int step = 0; step < 3; ++step) {
            Vector3f before = byHand.position.clone();
            gravity.step(byHand, H);
            double expected = face.sweep(before, byHand.position, 0f, new Vector3f());
            double fraction = flight.step(flown, H, sweep);
            assertEquals(expected, fraction, 0.0, "step " + step);
            assertEquals(byHand.position, flown.position);
            assertEquals(byHand.velocity, flown.velocity);
            if (fraction != Flight.NO_LANDING) {
                // the same double sums as before the helper: no tolerance
                assertEquals(before.x + fraction * ((double) byHand.position.x - before.x),
                        flight.crossingX(fraction), 0.0);
                assertEquals(before.y + fraction * ((double) byHand.position.y - before.y),
                        flight.crossingY(fraction), 0.0);
                return;
            }
        }
        throw new AssertionError("300 m/s reaches x = 4 m within the first steps of 1/60 s");
    }

    @Test
    void climbStopsAtTheFirstStateThatNoLongerRises() {
        // Gravity from vy = 10 m/s, h = 1/60 s: vy_n = 10 − n·g·h first reaches <= 0 at
        // n = ceil(10/(9.8/60)) = 62 (61.2 in exact arithmetic: not near a whole step, so
        // float round-off cannot move it).
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Flight flight = new Flight(gravity);
        Particle climbed = particle(0f, 0f, 5f, 10f);
        assertEquals(62, flight.climb(climbed, H, 1_000));
        // The same steps, done directly: bit for bit.
        Particle reference = particle(0f, 0f, 5f, 10f);
        for (int n = 0; n < 62; ++n) {
            gravity.step(reference, H);
        }
        assertEquals(reference.position, climbed.position);
        assertEquals(reference.velocity, climbed.velocity);
        assertTrue(climbed.velocity.y <= 0f);
        // The cap stops it early; a particle not rising takes no step.
        assertEquals(10, flight.climb(particle(0f, 0f, 5f, 10f), H, 10));
        assertEquals(0, flight.climb(particle(0f, 3f, 5f, 0f), H, 1_000));
    }

    private static Particle particle(float x, float y, float vx, float vy) {
        return new Particle(new Vector3f(x, y, 0f), new Vector3f(vx, vy, 0f), 1f);
    }
}

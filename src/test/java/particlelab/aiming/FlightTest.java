package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
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

    private static Particle particle(float x, float y, float vx, float vy) {
        return new Particle(new Vector3f(x, y, 0f), new Vector3f(vx, vy, 0f), 1f);
    }
}

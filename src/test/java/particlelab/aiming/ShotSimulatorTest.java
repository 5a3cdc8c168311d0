package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

class ShotSimulatorTest {

    private static final float H = 1f / 60f;

    @Test
    void aHeavierStartParticleDoesNotChangeLaterShots() {
        // With linear drag the landing depends on the mass, so a leaked mass would show.
        ShotSimulator simulator = new ShotSimulator(
                new ParticleIntegrator(new Gravity(), new LinearDrag(0.5f)), 1f, H, 60f);
        Landing first = new Landing();
        assertTrue(simulator.fire(20f, 20f, first));
        Landing heavy = new Landing();
        assertTrue(simulator.fire(new Particle(new Vector3f(), new Vector3f(20f, 20f, 0f), 5f),
                heavy));
        assertTrue(heavy.getX() > first.getX(), "the heavy bullet slows less");
        Landing again = new Landing();
        assertTrue(simulator.fire(20f, 20f, again));
        assertEquals(first.getX(), again.getX(), 0.0);
    }

    @Test
    void crossingIsInterpolatedInsideTheLastStep() {
        ShotSimulator simulator = new ShotSimulator(new ParticleIntegrator(new Gravity()), 1f,
                H, 60f);
        Landing landing = new Landing();
        assertTrue(simulator.fire(20f, 10f, landing));
        // The landing lies within the last step: between (steps − 1)·h and steps·h.
        double time = landing.getTimeSeconds();
        assertTrue(time > (landing.getSteps() - 1) * H && time <= landing.getSteps() * H);
        // x moves at a constant 20 m/s, so the interpolated x and t agree (float x: 1e-4).
        assertEquals(20.0 * time, landing.getX(), 1e-4);
    }

    @Test
    void aShotThatNeverComesDownReportsNoLanding() {
        // No force: the bullet rises for ever.
        ShotSimulator simulator = new ShotSimulator(new ParticleIntegrator(), 1f, H, 1f);
        Landing landing = new Landing();
        assertFalse(simulator.fire(20f, 1f, landing));
        assertFalse(landing.hasLanded());
        assertTrue(Double.isNaN(landing.getX()));
        assertEquals(60, landing.getSteps());
    }
}

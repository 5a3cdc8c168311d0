package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;

/**
 * The per-step and per-frame code allocates nothing: measured in bytes with the thread's
 * allocation counter (see {@link Allocations}), over {@value #STEPS} steps or frames.
 */
class PhysicsAllocationTest {

    private static final int STEPS = 100_000;
    private static final float H = 1f / 60f;
    /** Does nothing with its steps: it captures nothing, so it is one shared instance. */
    private static final SimulationClock.Stepper IGNORE_STEPS = stepSeconds -> {
    };
    private static final Vector3f START_POSITION = new Vector3f(0f, 10f, 0f);
    private static final Vector3f START_VELOCITY = new Vector3f(20f, 15f, -3f);

    /** Where the deliberately allocating code leaves its garbage, so none is optimised away. */
    private Vector3f sink = new Vector3f();

    @Test
    void integratorStepWithEveryForceAllocatesNothing() {
        Particle particle = new Particle(START_POSITION, START_VELOCITY, 2f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new LinearDrag(0.3f), new QuadraticDrag(0.05f), new Thrust(4f));

        Allocations.assertAllocatesNothing(STEPS + " steps, gravity + both drags + thrust",
                () -> {
                    particle.setState(START_POSITION, START_VELOCITY);
                    for (int i = 0; i < STEPS; ++i) {
                        integrator.step(particle, H);
                    }
                });
        assertTrue(particle.isFinite(), particle.toString());
    }

    @Test
    void clockAdvanceAllocatesNothingInAnyMode() {
        SimulationClock clock = new SimulationClock();

        Allocations.assertAllocatesNothing(STEPS + " frames through the clock", () -> {
            for (int i = 0; i < STEPS; ++i) {
                // Uneven frames, a hitch now and then, both modes, pause and single steps.
                float tpf = i % 1000 == 0 ? 0.7f : (i % 3 == 0 ? 1f / 90f : 1f / 45f);
                if (i % 5000 == 0) {
                    clock.toggleMode();
                }
                if (i % 7000 == 0) {
                    clock.setPaused(!clock.isPaused());
                    clock.requestSingleStep();
                }
                clock.advance(tpf, IGNORE_STEPS);
            }
        });
        assertTrue(clock.getSimulatedSeconds() > 0.0);
    }

    @Test
    void clockDrivingTheIntegratorAllocatesNothing() {
        Particle particle = new Particle(START_POSITION, START_VELOCITY, 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new LinearDrag(0.2f), new Thrust(2f));
        SimulationClock clock = new SimulationClock();
        // Made once, before measuring: calling it allocates nothing.
        SimulationClock.Stepper stepper = stepSeconds -> integrator.step(particle, stepSeconds);

        Allocations.assertAllocatesNothing(STEPS + " frames stepping a particle", () -> {
            particle.setState(START_POSITION, START_VELOCITY);
            for (int i = 0; i < STEPS; ++i) {
                clock.advance(i % 2 == 0 ? 0.01f : 0.02f, stepper);
            }
        });
        assertTrue(particle.isFinite(), particle.toString());
    }

    @Test
    void allocationCounterSeesTheAllocatingAntiPattern() {
        // The style guide's anti-pattern, v = v.add(a.mult(h)): two vectors per step. This
        // proves the measurement can fail; escaping garbage cannot be optimised away.
        Vector3f acceleration = new Vector3f(0f, -9.8f, 0f);

        long bytes = Allocations.warmBytesAllocatedBy(() -> {
            for (int i = 0; i < STEPS; ++i) {
                sink = sink.add(acceleration.mult(H));
            }
        });

        // At least one object of 16+ bytes (header and three floats) per step.
        assertTrue(bytes >= 16L * STEPS, bytes + " bytes");
    }
}

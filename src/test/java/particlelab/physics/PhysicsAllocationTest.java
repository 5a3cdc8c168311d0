package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Arrays;
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

    /**
     * Every path of every force mix, with the stability bookkeeping the demos do each step:
     * per particle, an array of objects, the batch, and a scene with a spring (through the
     * interface).
     */
    @Test
    void everyPathOfEveryMixAllocatesNothing() {
        Force[][] mixes = {
            {new Gravity()},
            {new Gravity(), new LinearDrag(0.5f)},
            {new Gravity(), new QuadraticDrag(0.05f)},
            {new Gravity(), new LinearDrag(0.3f), new Thrust(4f)},
            {new Gravity(), new Spring(new Vector3f(0f, 10f, 0f), 1f, 20f, 0.3f)},
        };
        int count = 100;
        for (Force[] forces : mixes) {
            ParticleIntegrator integrator = new ParticleIntegrator(forces);
            Particle particle = new Particle(START_POSITION, START_VELOCITY, 2f);
            Particle[] particles = new Particle[count];
            for (int i = 0; i < count; ++i) {
                particles[i] = new Particle(START_POSITION, START_VELOCITY, 2f);
            }
            float[] positions = new float[3 * count];
            float[] velocities = new float[3 * count];
            int[] below = new int[count];
            float[] velocityYBefore = new float[count];
            String mix = integrator.describe();
            Allocations.assertAllocatesNothing(STEPS + " steps and regimes, " + mix, () -> {
                particle.setState(START_POSITION, START_VELOCITY);
                for (int i = 0; i < STEPS; ++i) {
                    if (integrator.regime(particle, H) == StepRegime.GROWS) {
                        sink.x += integrator.dragRate(particle);
                    }
                    sink.y += integrator.maxStableStep(particle) + integrator.dampingRate(particle);
                    integrator.step(particle, H);
                }
            });
            Allocations.assertAllocatesNothing("array and batch steps, " + mix, () -> {
                for (int i = 0; i < count; ++i) {
                    particles[i].setState(START_POSITION, START_VELOCITY);
                }
                Arrays.fill(positions, 0f);
                Arrays.fill(velocities, 1f);
                for (int i = 0; i < STEPS / count; ++i) {
                    integrator.step(particles, H);
                    integrator.batch().stepPacked(positions, velocities, count, 2f, H);
                    integrator.batch().stepPackedFindingFloor(positions, velocities, count, count,
                            2f, H, 0.5f, below, velocityYBefore);
                }
            });
            assertTrue(particle.isFinite() && particles[0].isFinite(), mix);
        }
    }

    @Test
    void refoldingAfterASetterAllocatesNothing() {
        LinearDrag drag = new LinearDrag(0.5f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), drag);
        Particle particle = new Particle(START_POSITION, START_VELOCITY, 1f);
        Allocations.assertAllocatesNothing(STEPS + " steps, b changed before each", () -> {
            particle.setState(START_POSITION, START_VELOCITY);
            for (int i = 0; i < STEPS; ++i) {
                drag.setCoefficient(i % 2 == 0 ? 0.5f : 0.6f);
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

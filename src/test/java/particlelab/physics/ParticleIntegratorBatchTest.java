package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** The packed batch form {@link ParticleBatch#stepPacked}. */
class ParticleIntegratorBatchTest {

    private static final int COUNT = 37;
    private static final float H = 1f / 60f;

    @Test
    void gravityAndLinearDragBatchFollowsTheOneParticleStep() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), new LinearDrag(0.9f));
        Particle[] particles = launch(2f);
        float[] positions = new float[3 * COUNT];
        float[] velocities = new float[3 * COUNT];
        pack(particles, positions, velocities);
        for (int n = 0; n < 240; ++n) {
            integrator.step(particles, H);
            integrator.batch().stepPacked(positions, velocities, COUNT, 2f, H);
        }
        // The batch rearranges a = g − (b/m)·V into V·(1 − h·b/m) + h·g: a few ulp per step.
        // Drag damps old differences (factor 0.9925 per step), so they stay near 1e-6 relative;
        // positions near 100 m accumulate ~240 steps of them: 1e-4 m covers both.
        for (int i = 0; i < COUNT; ++i) {
            assertEquals(particles[i].velocity.x, velocities[i], 1e-4f);
            assertEquals(particles[i].velocity.y, velocities[COUNT + i], 1e-4f);
            assertEquals(particles[i].velocity.z, velocities[2 * COUNT + i], 1e-4f);
            assertEquals(particles[i].position.x, positions[i], 1e-4f);
            assertEquals(particles[i].position.y, positions[COUNT + i], 1e-4f);
            assertEquals(particles[i].position.z, positions[2 * COUNT + i], 1e-4f);
        }
    }

    @Test
    void otherForcesGoThroughTheOneParticleStepBitForBit() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new QuadraticDrag(0.02f), new Thrust(3f), new LinearDrag(0.1f));
        Particle[] particles = launch(1.5f);
        float[] positions = new float[3 * COUNT];
        float[] velocities = new float[3 * COUNT];
        pack(particles, positions, velocities);
        for (int n = 0; n < 100; ++n) {
            integrator.step(particles, H);
            integrator.batch().stepPacked(positions, velocities, COUNT, 1.5f, H);
        }
        for (int i = 0; i < COUNT; ++i) {
            // the same code on the same floats: identical
            assertEquals(particles[i].position.y, positions[COUNT + i], 0f);
            assertEquals(particles[i].velocity.x, velocities[i], 0f);
        }
    }

    /**
     * With a stride, the first count particles of a larger layout step to the same bits as
     * the same particles packed alone, and the slots beyond them are not touched: in each of
     * the batch's three forms (by axes, by speed, one by one).
     */
    @Test
    void aStrideStepsTheFirstParticlesAloneToTheSameBits() {
        ParticleIntegrator[] integrators = {
            new ParticleIntegrator(new Gravity(), new LinearDrag(0.9f)),
            new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.02f), new Thrust(3f)),
            new ParticleIntegrator(new Gravity(), new Spring(new Vector3f(0f, 1f, 0f), 0.5f, 4f)),
        };
        int stride = COUNT + 11;
        for (ParticleIntegrator integrator : integrators) {
            float[] positions = new float[3 * COUNT];
            float[] velocities = new float[3 * COUNT];
            pack(launch(2f), positions, velocities);
            float[] widePositions = new float[3 * stride];
            float[] wideVelocities = new float[3 * stride];
            java.util.Arrays.fill(widePositions, -7f);
            java.util.Arrays.fill(wideVelocities, 5f);
            for (int axis = 0; axis < 3; ++axis) {
                System.arraycopy(positions, axis * COUNT, widePositions, axis * stride, COUNT);
                System.arraycopy(velocities, axis * COUNT, wideVelocities, axis * stride, COUNT);
            }
            for (int n = 0; n < 120; ++n) {
                integrator.batch().stepPacked(positions, velocities, COUNT, 2f, H);
                integrator.batch().stepPacked(widePositions, wideVelocities, stride, COUNT, 2f, H);
            }
            for (int axis = 0; axis < 3; ++axis) {
                for (int i = 0; i < stride; ++i) {
                    float p = widePositions[axis * stride + i];
                    float v = wideVelocities[axis * stride + i];
                    if (i < COUNT) {
                        // the same code on the same floats: identical
                        assertEquals(positions[axis * COUNT + i], p, 0f, integrator.describe());
                        assertEquals(velocities[axis * COUNT + i], v, 0f, integrator.describe());
                    } else {
                        assertEquals(-7f, p, 0f, "slot " + i + " beyond count moved");
                        assertEquals(5f, v, 0f, "slot " + i + " beyond count moved");
                    }
                }
            }
        }
    }

    @Test
    void aStrideBelowTheCountOrArraysTooShortForItAreRefused() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        IllegalArgumentException below = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(new float[30], new float[30], 9, 10, 1f, H));
        assertTrue(below.getMessage().contains("stride between the axes must be >= the"
                + " particle count 10, but was 9"), below.getMessage());
        float[] positions = new float[3 * 20];
        float[] velocities = new float[3 * 20];
        velocities[20 + 3] = Float.NaN;
        NonFiniteStepException nan = assertThrows(NonFiniteStepException.class,
                () -> integrator.batch().stepPacked(positions, velocities, 20, 10, 1f, H));
        assertTrue(nan.getMessage().contains("packed particle 3 of 10 non-finite"),
                nan.getMessage());
        IllegalArgumentException shortArrays = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(new float[30], new float[60], 20, 10, 1f, H));
        assertTrue(shortArrays.getMessage().contains("positions must hold 3*stride = 60"),
                shortArrays.getMessage());
    }

    @Test
    void batchFarBeyondTheLimitStopsInsteadOfSpreadingNaN() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), new LinearDrag(10f));
        float[] positions = new float[3 * 4];
        float[] velocities = {1f, 2f, 3f, 4f, 1f, 1f, 1f, 1f, 0f, 0f, 0f, 0f};
        // h = 5 s with b/m = 10/s: the velocity factor is 1 − 50 = −49 per step; float
        // overflows after about 23 steps
        NonFiniteStepException failure = assertThrows(NonFiniteStepException.class, () -> {
            for (int n = 0; n < 100; ++n) {
                integrator.batch().stepPacked(positions, velocities, 4, 1f, 5f);
            }
        });
        assertTrue(failure.getMessage().contains("-49"), failure.getMessage());
    }

    /**
     * Finite input that overflows the float range, and NaN input, are refused on both paths,
     * as {@link ParticleIntegrator#step(Particle, float)} refuses them: the exception names
     * the first non-finite particle, and every particle has been stepped.
     */
    @Test
    void batchRefusesOverflowAndNonFiniteInputOnBothPaths() {
        ParticleIntegrator folded = new ParticleIntegrator(new Gravity(), new LinearDrag(0.1f));
        ParticleIntegrator general = new ParticleIntegrator(new Gravity(),
                new QuadraticDrag(0.001f));
        ParticleIntegrator strongGravity =
                new ParticleIntegrator(new Gravity(new Vector3f(0f, -3e38f, 0f)));
        for (ParticleIntegrator integrator : new ParticleIntegrator[] {folded, general}) {
            // P near the top of the float range plus h·V overflows: particle 2's x
            assertRefused(integrator, 2, 0, Float.MAX_VALUE, 1e37f);
            // the same at the bottom of the range, P moved down by h·V
            assertRefused(integrator, 1, 3, -Float.MAX_VALUE, -3e38f);
            // NaN in the input is not passed through
            assertRefused(integrator, 3, 5, 0f, Float.NaN);
        }
        // h·g finite, but V + h·g and then P overflow after a few steps
        float[] positions = new float[3 * 2];
        float[] velocities = new float[3 * 2];
        NonFiniteStepException failure = assertThrows(NonFiniteStepException.class, () -> {
            for (int n = 0; n < 100; ++n) {
                strongGravity.batch().stepPacked(positions, velocities, 2, 1f, 1f);
            }
        });
        assertTrue(failure.getMessage().contains("packed particle 0 of 2"),
                failure.getMessage());
    }

    @Test
    void batchRefusesAMassWhoseInverseIsNotAFiniteFloat() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        float[] three = new float[3];
        IllegalArgumentException tiny = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(three, three, 1, 1e-39f, H));
        // The message names the least mass allowed. Its digits are those of the compiler's
        // Float.toString (the constant is folded into the text); JDK 19 and later print the
        // same float with fewer digits (1.1754944E-38, not 1.17549435E-38), so read the
        // number back and compare it as a float.
        String message = tiny.getMessage();
        Matcher least = Pattern.compile("at least (\\S+) ").matcher(message);
        assertTrue(least.find(), message);
        assertEquals(Particle.MIN_MASS_KG, Float.parseFloat(least.group(1)), message);
        integrator.batch().stepPacked(three, three, 1, Particle.MIN_MASS_KG, H);
        assertTrue(Float.isFinite(three[1]));
    }

    /**
     * Step 6 particles whose one component (at index {@code particle + axis·6}) is set to
     * position and velocity; expect a refusal naming that particle, and all others stepped.
     */
    private static void assertRefused(ParticleIntegrator integrator, int particle, int axisIndex,
            float position, float velocity) {
        int count = 6;
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        int axis = axisIndex % 3;
        positions[axis * count + particle] = position;
        velocities[axis * count + particle] = velocity;
        // one more finite particle after the bad one, to see that it was stepped too
        velocities[count + 5] = 1f;
        NonFiniteStepException failure = assertThrows(NonFiniteStepException.class,
                () -> integrator.batch().stepPacked(positions, velocities, count, 1f, H));
        assertTrue(failure.getMessage().contains("packed particle " + particle + " of 6"),
                failure.getMessage());
        assertTrue(failure.getMessage().contains("every particle was stepped"),
                failure.getMessage());
        // particle 5 rose by h·(1 + h·g_y) (plus drag, under 1%): it was stepped
        assertEquals(H * (1f - 9.8f * H), positions[count + 5], 0.01f * H);
    }

    @Test
    void zeroStepOrNoParticlesChangeNothing() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        float[] positions = {1f, 2f, 3f};
        float[] velocities = {4f, 5f, 6f};
        integrator.batch().stepPacked(positions, velocities, 1, 1f, 0f);
        integrator.batch().stepPacked(positions, velocities, 0, 1f, H);
        assertEquals(2f, positions[1], 0f);
        assertEquals(5f, velocities[1], 0f);
    }

    @Test
    void badBatchArgumentsAreRejectedNamingTheValue() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        float[] six = new float[6];
        IllegalArgumentException shortArray = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(six, new float[9], 3, 1f, H));
        assertTrue(shortArray.getMessage().contains("held 6"), shortArray.getMessage());
        IllegalArgumentException negative = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(six, six, -1, 1f, H));
        assertTrue(negative.getMessage().contains("-1"), negative.getMessage());
        IllegalArgumentException mass = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(six, six, 2, 0f, H));
        assertTrue(mass.getMessage().contains("mass"), mass.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPacked(six, six, 2, 1f, Float.NaN));
    }

    private static Particle[] launch(float massKg) {
        Particle[] particles = new Particle[COUNT];
        for (int i = 0; i < COUNT; ++i) {
            particles[i] = new Particle(new Vector3f(i, 0f, -i),
                    new Vector3f(20f + i % 5, 30f - i % 3, i % 4), massKg);
        }
        return particles;
    }

    private static void pack(Particle[] particles, float[] positions, float[] velocities) {
        for (int i = 0; i < COUNT; ++i) {
            positions[i] = particles[i].position.x;
            positions[COUNT + i] = particles[i].position.y;
            positions[2 * COUNT + i] = particles[i].position.z;
            velocities[i] = particles[i].velocity.x;
            velocities[COUNT + i] = particles[i].velocity.y;
            velocities[2 * COUNT + i] = particles[i].velocity.z;
        }
    }
}

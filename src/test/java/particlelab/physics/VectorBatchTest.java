package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Random;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;

/**
 * The two forms of the batch step with gravity and linear drag: the scalar passes and the
 * Vector API ({@link VectorBatch}). They must give the same floats and refuse the same
 * particles. The build starts the test JVM with the Vector API, so both forms run here.
 */
class VectorBatchTest {

    private static final float H = 1f / 60f;

    /**
     * Particle counts around the vector lengths (4, 8 or 16 floats) and the scalar passes'
     * block of 1024: tails of every length, one block and a bit, several blocks.
     */
    private static final int[] COUNTS = {1, 3, 7, 8, 15, 16, 17, 31, 33, 1023, 1024, 1025, 2500};

    @Test
    void theTestJvmHasTheVectorApi() {
        assertTrue(ParticleBatch.isVectorApiAvailable(), "the tests need a JVM started"
                + " with --add-modules=jdk.incubator.vector (build.gradle adds it)");
        assertTrue(new ParticleIntegrator(new Gravity()).batch().isVectorBatch(),
                "where the JVM has the Vector API, the batch uses it by default");
    }

    @Test
    void bothFormsGiveTheSameFloatsForGravityAndLinearDrag() {
        Random random = new Random(12);
        for (int count : COUNTS) {
            for (float drag : new float[] {0f, 0.7f}) {
                ParticleIntegrator vector = integrator(drag, true);
                ParticleIntegrator scalar = integrator(drag, false);
                float[] positions = new float[3 * count];
                float[] velocities = new float[3 * count];
                for (int i = 0; i < 3 * count; ++i) {
                    positions[i] = 200f * (random.nextFloat() - 0.5f);
                    velocities[i] = 60f * (random.nextFloat() - 0.5f);
                }
                float[] scalarPositions = positions.clone();
                float[] scalarVelocities = velocities.clone();
                for (int n = 0; n < 120; ++n) {
                    vector.batch().stepPacked(positions, velocities, count, 1.5f, H);
                    scalar.batch().stepPacked(scalarPositions, scalarVelocities, count, 1.5f, H);
                }
                // the same operations on the same floats, each rounded once: identical bits
                // (assertArrayEquals compares floats by their bits, -0 and 0 apart)
                assertArrayEquals(scalarVelocities, velocities, 0f, "V, N=" + count);
                assertArrayEquals(scalarPositions, positions, 0f, "P, N=" + count);
            }
        }
    }

    @Test
    void bothFormsFollowTheOneParticleStepBitForBit() {
        int count = 19;
        ParticleIntegrator byParticle = integrator(0.4f, false);
        ParticleIntegrator vector = integrator(0.4f, true);
        Particle particle = new Particle(new Vector3f(), new Vector3f(), 2f);
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        for (int i = 0; i < count; ++i) {
            velocities[i] = 10f + i;
            velocities[count + i] = 25f - i;
            velocities[2 * count + i] = 0.5f * i;
        }
        float[] expected = positions.clone();
        float[] expectedVelocities = velocities.clone();
        for (int n = 0; n < 60; ++n) {
            vector.batch().stepPacked(positions, velocities, count, 2f, H);
            for (int i = 0; i < count; ++i) {
                particle.position.set(expected[i], expected[count + i], expected[2 * count + i]);
                particle.velocity.set(expectedVelocities[i], expectedVelocities[count + i],
                        expectedVelocities[2 * count + i]);
                byParticle.step(particle, H);
                expected[i] = particle.position.x;
                expected[count + i] = particle.position.y;
                expected[2 * count + i] = particle.position.z;
                expectedVelocities[i] = particle.velocity.x;
                expectedVelocities[count + i] = particle.velocity.y;
                expectedVelocities[2 * count + i] = particle.velocity.z;
            }
        }
        // step(Particle, h) folds the forces the same way: identical bits
        assertArrayEquals(expected, positions, 0f);
        assertArrayEquals(expectedVelocities, velocities, 0f);
    }

    /**
     * A NaN or an overflow is refused by both forms, wherever it sits: in the first or the
     * last vector of an axis, in the scalar tail, on any axis. Both name the same particle.
     */
    @Test
    void bothFormsRefuseTheSameNonFiniteParticle() {
        int count = 37; // two vectors of 16 and a tail of 5 per axis with AVX-512
        int[] bad = {0, 15, 16, 31, 32, 36};
        for (boolean useVector : new boolean[] {true, false}) {
            for (int axis = 0; axis < 3; ++axis) {
                for (int particle : bad) {
                    for (float[] state : new float[][] {{0f, Float.NaN},
                            {Float.MAX_VALUE, 1e37f}, {Float.POSITIVE_INFINITY, 0f}}) {
                        float[] positions = new float[3 * count];
                        float[] velocities = new float[3 * count];
                        positions[axis * count + particle] = state[0];
                        velocities[axis * count + particle] = state[1];
                        ParticleIntegrator integrator = integrator(0.2f, useVector);
                        NonFiniteStepException failure = assertThrows(
                                NonFiniteStepException.class,
                                () -> integrator.batch().stepPacked(positions, velocities,
                                        count, 1f, H));
                        String where = "packed particle " + particle + " of " + count;
                        assertTrue(failure.getMessage().contains(where),
                                (useVector ? "vector: " : "scalar: ") + failure.getMessage());
                        // every particle was stepped: the last one fell by h·(h·g)
                        int last = count + count - 1;
                        if (axis != 1 || particle != count - 1) {
                            assertEquals(-9.8f * H * H, positions[last], 1e-3f * H * H);
                        }
                    }
                }
            }
        }
    }

    /** Finite positions whose sum overflows are not a failure: the search finds none. */
    @Test
    void aSumThatOverflowsOverFinitePositionsIsNoFailure() {
        int count = 40;
        for (boolean useVector : new boolean[] {true, false}) {
            float[] positions = new float[3 * count];
            float[] velocities = new float[3 * count];
            java.util.Arrays.fill(positions, 0, count, 0.9f * Float.MAX_VALUE);
            integrator(0f, useVector).batch().stepPacked(positions, velocities, count, 1f, H);
            assertEquals(0.9f * Float.MAX_VALUE, positions[count - 1], 0f);
        }
    }

    @Test
    void bothFormsAllocateNothing() {
        for (boolean useVector : new boolean[] {true, false}) {
            ParticleIntegrator integrator = integrator(0.5f, useVector);
            float[] positions = new float[3 * 1000];
            float[] velocities = new float[3 * 1000];
            // warm until compiled: before C2, the Vector API's vectors are objects
            Allocations.assertAllocatesNothing((useVector ? "vector" : "scalar")
                    + " form, 1000 steps of 1000 particles", () -> {
                        for (int n = 0; n < 1000; ++n) {
                            integrator.batch().stepPacked(positions, velocities, 1000, 1f, H);
                        }
                    });
        }
    }

    private static ParticleIntegrator integrator(float linearDrag, boolean useVector) {
        ParticleIntegrator integrator = linearDrag == 0f ? new ParticleIntegrator(new Gravity())
                : new ParticleIntegrator(new Gravity(), new LinearDrag(linearDrag));
        integrator.batch().setVectorBatch(useVector);
        return integrator;
    }
}

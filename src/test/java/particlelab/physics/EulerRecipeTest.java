package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every per-particle step is the lecture's recipe, as code: for each mix of forces
 * ({@link FastPathsMatchTheRecipeTest#mixes}: every subset of the built-ins, each twice, and
 * with a spring), the step equals {@code V' = V + h·a}, then {@code P' = P + h·V'}, computed
 * here in that order from the a the integrator reports, bit for bit. And the order shows: a
 * copy of the recipe with its two lines swapped lands a level shot {@code vx·h} long.
 */
class EulerRecipeTest {

    private static final float H = 1f / 60f;

    @ParameterizedTest
    @MethodSource("particlelab.physics.FastPathsMatchTheRecipeTest#mixes")
    void everyPerParticleStepIsVPlusHaThenPPlusHvBitForBit(FastPathsMatchTheRecipeTest.Mix mix) {
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        Random random = new Random(17);
        Vector3f a = new Vector3f();
        for (int shot = 0; shot < 300; ++shot) {
            float mass = 0.1f + 5f * random.nextFloat();
            float h = shot % 2 == 0 ? H : 0.01f * random.nextFloat();
            Particle particle = new Particle(randomVector(random, 50f),
                    randomVector(random, shot % 3 == 0 ? 1f : 60f), mass);
            Particle[] asArray = {copy(particle)};
            // consecutive steps of one particle, so the state drifts as in a demo
            for (int n = 0; n < 20; ++n) {
                integrator.acceleration(particle, a);
                Vector3f v = particle.velocity;
                Vector3f p = particle.position;
                float vx = v.x + h * a.x;
                float vy = v.y + h * a.y;
                float vz = v.z + h * a.z;
                float px = p.x + h * vx;
                float py = p.y + h * vy;
                float pz = p.z + h * vz;
                integrator.step(particle, h);
                integrator.step(asArray, h);
                String where = mix + ", shot " + shot + ", step " + n;
                assertBits(new Vector3f(vx, vy, vz), particle.velocity, where);
                assertBits(new Vector3f(px, py, pz), particle.position, where);
                assertBits(particle.velocity, asArray[0].velocity, where + " (array form)");
                assertBits(particle.position, asArray[0].position, where + " (array form)");
            }
        }
    }

    /**
     * The step reads each particle's own 1/m (nothing remembered for one mass): particles of
     * many masses in one array, one of them copied and one given a new mass between steps,
     * are each stepped with their own, bit for bit.
     */
    @ParameterizedTest
    @MethodSource("particlelab.physics.FastPathsMatchTheRecipeTest#mixes")
    void particlesOfManyMassesInOneArrayAreEachSteppedWithTheirOwnMass(
            FastPathsMatchTheRecipeTest.Mix mix) {
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        Random random = new Random(23);
        Particle[] particles = new Particle[12];
        for (int i = 0; i < particles.length; ++i) {
            particles[i] = new Particle(randomVector(random, 50f),
                    randomVector(random, i % 3 == 0 ? 1f : 60f), 0.1f + 5f * random.nextFloat());
        }
        particles[5] = copy(particles[4]);
        Vector3f[] expectedV = new Vector3f[particles.length];
        Vector3f[] expectedP = new Vector3f[particles.length];
        Vector3f a = new Vector3f();
        for (int n = 0; n < 20; ++n) {
            particles[7].setMass(n % 2 == 0 ? 0.25f : 4f);
            for (int i = 0; i < particles.length; ++i) {
                integrator.acceleration(particles[i], a);
                Vector3f v = particles[i].velocity;
                Vector3f p = particles[i].position;
                expectedV[i] = new Vector3f(v.x + H * a.x, v.y + H * a.y, v.z + H * a.z);
                expectedP[i] = new Vector3f(p.x + H * expectedV[i].x, p.y + H * expectedV[i].y,
                        p.z + H * expectedV[i].z);
            }
            integrator.step(particles, H);
            for (int i = 0; i < particles.length; ++i) {
                String where = mix + ", step " + n + ", particle " + i;
                assertBits(expectedV[i], particles[i].velocity, where);
                assertBits(expectedP[i], particles[i].position, where);
            }
        }
    }

    @Test
    void whereTheFoldOverflowsTheStepIsTheRecipeWithEveryForceAsked() {
        // b/m beyond the float range at rest: σ·V is ∞·0; asked force by force, a is g
        Gravity gravity = new Gravity();
        ParticleIntegrator integrator = new ParticleIntegrator(gravity, new LinearDrag(1e30f));
        Particle particle = new Particle(new Vector3f(1f, 2f, 3f), new Vector3f(), 1e-20f);
        Vector3f a = integrator.acceleration(particle, new Vector3f());
        Vector3f g = gravity.copyAcceleration(new Vector3f());
        assertBits(g, a, "a at rest");
        integrator.step(particle, H);
        // V' = 0 + h·g, P' = P + h·V'
        Vector3f v = new Vector3f(H * g.x, H * g.y, H * g.z);
        assertBits(v, particle.velocity, "V'");
        assertBits(new Vector3f(1f + H * v.x, 2f + H * v.y, 3f + H * v.z), particle.position,
                "P'");
    }

    @Test
    void aCopyWithTheTwoLinesSwappedLandsALevelShotVxHLong() {
        // vx·h = 8 m/s · 1/8 s = 1 m exactly, so every x below is an exact float
        float h = 0.125f;
        float vx = 8f;
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle recipe = new Particle(new Vector3f(0f, 20f, 0f), new Vector3f(vx, 0f, 0f), 1f);
        Particle swapped = copy(recipe);
        Vector3f a = new Vector3f();
        int recipeSteps = stepsToGround(recipe, () -> integrator.step(recipe, h));
        int swappedSteps = stepsToGround(swapped, () -> {
            // forward Euler: P ← P + h·V with the OLD V, then V ← V + h·a
            integrator.acceleration(swapped, a);
            swapped.position.scaleAdd(h, swapped.velocity, swapped.position);
            swapped.velocity.scaleAdd(h, a, swapped.velocity);
        });
        // y_n = y0 − g·h²·n(n+1)/2 for the recipe, n(n−1)/2 swapped: one step later, exactly
        // (in reals; both cross y = 0 well away from a rounding's reach: 20 m, g·h² ≈ 0.15 m)
        assertEquals(recipeSteps + 1, swappedSteps);
        assertEquals(recipe.position.x + vx * h, swapped.position.x, 0f,
                "the swapped copy lands vx·h = 1 m long");
        assertTrue(recipe.position.x > 0f);
    }

    /** Step until y &le; 0; return the number of steps. */
    private static int stepsToGround(Particle particle, Runnable step) {
        int steps = 0;
        while (particle.position.y > 0f) {
            step.run();
            ++steps;
        }
        return steps;
    }

    private static Particle copy(Particle particle) {
        Particle copy = new Particle();
        copy.copyFrom(particle);
        return copy;
    }

    private static Vector3f randomVector(Random random, float scale) {
        return new Vector3f(scale * (2f * random.nextFloat() - 1f),
                scale * (2f * random.nextFloat() - 1f), scale * (2f * random.nextFloat() - 1f));
    }

    private static void assertBits(Vector3f expected, Vector3f actual, String where) {
        for (int axis = 0; axis < 3; ++axis) {
            assertEquals(Float.floatToIntBits(expected.get(axis)),
                    Float.floatToIntBits(actual.get(axis)),
                    () -> where + ": expected " + expected + " but was " + actual);
        }
    }
}

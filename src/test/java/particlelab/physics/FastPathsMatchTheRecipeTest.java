package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.lang.ref.WeakReference;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The fast forms of {@link ParticleIntegrator}'s step against the lecture's recipe, for every
 * mix of built-in forces: each subset of gravity, linear drag, quadratic drag and thrust,
 * alone, with each force twice (the fold sums them), and with a {@link Spring} (asked through
 * the interface, its acceleration added to the folded g). {@link ParticleIntegratorFoldingTest}
 * checks the four mixes of the demos in depth; this class covers the rest:
 * <ul>
 * <li>{@link FoldedForces}: the per-particle step within the stated rounding bound of the
 * recipe (bit for bit where only gravity acts);</li>
 * <li>{@link PackedStep} in both forms and the array step: bit for bit the per-particle
 * step;</li>
 * <li>{@link StepLimits}: the remembered regime is the public limits' answer.</li>
 * </ul>
 * The recipe is reached by hiding every force behind a plain {@link Force}
 * ({@link ParticleIntegratorFoldingTest#hide}), which the integrator cannot fold.
 */
class FastPathsMatchTheRecipeTest {

    private static final double U = ParticleIntegratorFoldingTest.U;
    /**
     * Roundings in one velocity update with another force, each of a term no larger than the
     * scale S of {@link #assertWithinRoundings}: the 24 of the folded forces
     * ({@link ParticleIntegratorFoldingTest#ROUNDINGS}), plus the other force's share, at most
     * 4 per path (the folded path rounds {@code F·(1/m)}, {@code + g_other} and
     * {@code g + a_other}; the recipe sums F and g with one more term each and rounds
     * {@code F·(1/m)}): 32.
     */
    private static final double ROUNDINGS_WITH_OTHERS = ParticleIntegratorFoldingTest.ROUNDINGS
            + 8.0;
    private static final float H = 1f / 60f;

    /** A mix of forces: which built-ins, how often each, and whether a spring joins them. */
    static final class Mix {
        final int builtIns;
        final boolean twice;
        final boolean spring;

        Mix(int builtIns, boolean twice, boolean spring) {
            this.builtIns = builtIns;
            this.twice = twice;
            this.spring = spring;
        }

        /** Fresh forces of this mix, in a fixed order. */
        Force[] forces() {
            List<Force> forces = new ArrayList<>();
            for (int copy = 0; copy < (twice ? 2 : 1); ++copy) {
                if (has(GRAVITY)) {
                    forces.add(new Gravity(new Vector3f(0.4f * copy, -9.8f + copy, 0.1f)));
                }
                if (has(LINEAR)) {
                    forces.add(new LinearDrag(0.6f + 0.3f * copy));
                }
                if (has(QUADRATIC)) {
                    forces.add(new QuadraticDrag(0.04f + 0.02f * copy));
                }
                if (has(THRUST)) {
                    forces.add(new Thrust(3f + copy));
                }
            }
            if (spring) {
                forces.add(new Spring(new Vector3f(0f, 10f, 0f), 2f, 30f, 0.5f));
            }
            return forces.toArray(new Force[0]);
        }

        boolean has(int builtIn) {
            return (builtIns & builtIn) != 0;
        }

        /** True if only gravity acts (or nothing): the fold is then the recipe's floats. */
        boolean onlyGravity() {
            return !spring && (builtIns & ~GRAVITY) == 0;
        }

        @Override
        public String toString() {
            String text = (has(GRAVITY) ? "g" : "") + (has(LINEAR) ? "b" : "")
                    + (has(QUADRATIC) ? "c" : "") + (has(THRUST) ? "k" : "");
            return (text.isEmpty() ? "none" : text) + (twice ? " twice" : "")
                    + (spring ? " + spring" : "");
        }
    }

    private static final int GRAVITY = 1;
    private static final int LINEAR = 2;
    private static final int QUADRATIC = 4;
    private static final int THRUST = 8;

    /** Every subset of the four built-ins, alone, twice and with a spring: 47 mixes. */
    static Stream<Mix> mixes() {
        List<Mix> mixes = new ArrayList<>();
        for (int builtIns = 0; builtIns < 16; ++builtIns) {
            mixes.add(new Mix(builtIns, false, false));
            mixes.add(new Mix(builtIns, false, true));
            if (builtIns != 0) {
                mixes.add(new Mix(builtIns, true, false));
            }
        }
        return mixes.stream();
    }

    @ParameterizedTest
    @MethodSource("mixes")
    void perParticleStepIsTheRecipeWithinItsRoundingBound(Mix mix) {
        Force[] forces = mix.forces();
        ParticleIntegrator fast = new ParticleIntegrator(forces);
        ParticleIntegrator recipe = new ParticleIntegrator(
                ParticleIntegratorFoldingTest.hide(forces));
        ParticleIntegrator others = new ParticleIntegrator(FoldedForces.others(forces));
        ParticleIntegrator gravity = new ParticleIntegrator(gravities(forces));
        Random random = new Random(31);
        Vector3f otherAcceleration = new Vector3f();
        Vector3f g = new Vector3f();
        for (int n = 0; n < 5000; ++n) {
            float mass = 0.1f + 5f * random.nextFloat();
            float h = n % 2 == 0 ? H : 0.2f * random.nextFloat();
            Vector3f position = randomVector(random, 50f);
            Vector3f velocity = randomVector(random, n % 3 == 0 ? 1f : 80f);
            Particle one = new Particle(position, velocity, mass);
            Particle two = new Particle(position, velocity, mass);
            others.acceleration(one, otherAcceleration);
            gravity.acceleration(one, g);
            fast.step(one, h);
            recipe.step(two, h);
            if (mix.onlyGravity()) {
                // σ = 0: the folded a is g − 0·V = g, the force-by-force sum g + 0·(1/m)
                assertBitwiseEqual(two.velocity, one.velocity);
                assertBitwiseEqual(two.position, one.position);
            } else {
                assertWithinRoundings(forces, mix.spring ? ROUNDINGS_WITH_OTHERS
                        : ParticleIntegratorFoldingTest.ROUNDINGS, velocity, mass, h, g,
                        otherAcceleration, one, two);
            }
        }
    }

    @ParameterizedTest
    @MethodSource("mixes")
    void batchInBothFormsAndTheArrayStepAreThePerParticleStepBitForBit(Mix mix) {
        for (boolean vector : new boolean[] {false, true}) {
            ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
            // only gravity and linear drag have two forms; the others ignore the choice
            integrator.batch().setVectorBatch(vector && ParticleBatch.isVectorApiAvailable());
            // 1100 particles: one block of 1024 and a partial one, tails of every vector width
            ParticleIntegratorFoldingTest.assertBatchMatchesObjects(integrator, 1.3f, 1100, 60);
        }
    }

    @ParameterizedTest
    @MethodSource("mixes")
    void rememberedRegimeAndRatesAreTheLimitsAnswer(Mix mix) {
        Force[] forces = mix.forces();
        ParticleIntegrator integrator = new ParticleIntegrator(forces);
        ParticleIntegrator recipe = new ParticleIntegrator(
                ParticleIntegratorFoldingTest.hide(forces));
        Random random = new Random(9);
        Particle particle = new Particle();
        for (int n = 0; n < 6000; ++n) {
            particle.setMass(n % 3 == 0 ? 1f : 0.2f + 4f * random.nextFloat());
            float h = n % 2 == 0 ? 0.5f : 8f * random.nextFloat();
            // 0.1 to 1000 m/s, and some at rest
            float speed = n % 17 == 0 ? 0f
                    : (float) Math.pow(10.0, 4.0 * random.nextDouble() - 1.0);
            particle.position.set(randomVector(random, 20f));
            particle.velocity.set(randomVector(random, 1f)).normalizeLocal().multLocal(speed);
            // λ: added in double either way, but through the interface each force's rate is
            // first rounded to float: half an ulp of a term no larger than λ for each of at
            // most 5 forces with a rate here, plus the sums' own rounding to float: 3 ulp
            float lambda = recipe.dampingRate(particle);
            assertEquals(lambda, integrator.dampingRate(particle), 3f * Math.ulp(lambda));
            float sigmaH = h * integrator.dragRate(particle);
            float lambdaH = h * integrator.dampingRate(particle);
            if (isNear(sigmaH) || isNear(lambdaH)) {
                // closer than 1e-3 to a limit a rounding of either side could tip it
                continue;
            }
            StepRegime expected = StepRegime.of(h, integrator.dragRate(particle),
                    integrator.maxStableStep(particle), integrator.maxMonotoneStep(particle));
            assertEquals(expected, integrator.regime(particle, h),
                    () -> mix + " h=" + h + ", " + particle);
        }
    }

    /**
     * A force that outlives its integrator (a scene's drag kept by a demo that builds its
     * integrators again) must not keep the integrator alive: it holds its folds weakly.
     */
    @Test
    void aForceDoesNotKeepADroppedIntegratorAlive() {
        LinearDrag drag = new LinearDrag(0.5f);
        WeakReference<ParticleIntegrator> dropped =
                new WeakReference<>(new ParticleIntegrator(new Gravity(), drag));
        // bounded: a collector that ignores System.gc() fails the test rather than hang it
        for (int attempt = 0; attempt < 50 && dropped.get() != null; ++attempt) {
            System.gc();
            byte[][] pressure = new byte[64][];
            for (int i = 0; i < pressure.length; ++i) {
                pressure[i] = new byte[16 * 1024];
            }
        }
        assertNull(dropped.get(), "the integrator is still reachable through its force");
        // and the force still reaches the integrators that live
        ParticleIntegrator kept = new ParticleIntegrator(drag);
        drag.setCoefficient(2f);
        assertEquals(2f, kept.dampingRate(new Particle()), 0f);
    }

    /**
     * No integrator or force keeps mutable state in a static field: a change of one scene's
     * force reaches only the integrators that hold it (before this, every setter bumped a
     * counter shared by the whole JVM).
     */
    @Test
    void noMutableStateIsSharedBetweenIntegrators() {
        Class<?>[] classes = {ParticleIntegrator.class, FoldedForces.class, PackedStep.class,
            StepLimits.class, FoldedForce.class, Gravity.class, LinearDrag.class,
            QuadraticDrag.class, Thrust.class, Spring.class, SlideFormDrag.class};
        for (Class<?> type : classes) {
            for (Field field : type.getDeclaredFields()) {
                int modifiers = field.getModifiers();
                // a static constant of a primitive type cannot change, nor be changed through
                assertTrue(!Modifier.isStatic(modifiers) || Modifier.isFinal(modifiers)
                        && field.getType().isPrimitive(),
                        type.getSimpleName() + "." + field.getName() + " is shared state");
            }
        }
    }

    /**
     * Compare one fast step with the recipe's from the same state, component by component:
     * the velocities differ by at most {@code roundings}·U·S with the scale
     * {@code S = |V_i|·(1 + h·σ⁺) + h·(|g_i| + |a_other_i|) + |V'_i|}, σ⁺ the drag rate with
     * every term positive; the positions by h times that plus one rounding of each P'.
     */
    private static void assertWithinRoundings(Force[] forces, double roundings,
            Vector3f velocity, float mass, float h, Vector3f g, Vector3f otherAcceleration,
            Particle fast, Particle recipe) {
        double rate = ParticleIntegratorFoldingTest.positiveDragRate(forces, velocity.length(),
                mass);
        for (int axis = 0; axis < 3; ++axis) {
            double next = recipe.velocity.get(axis);
            double scale = Math.abs(velocity.get(axis)) * (1.0 + h * rate)
                    + h * (Math.abs(g.get(axis)) + Math.abs(otherAcceleration.get(axis)))
                    + Math.abs(next);
            double velocityBound = roundings * U * scale;
            assertEquals(next, fast.velocity.get(axis), velocityBound,
                    () -> "V at V=" + velocity + ", h=" + h);
            double p = recipe.position.get(axis);
            // h·V' and P + h·V' round once in each path
            double positionBound = h * velocityBound * (1.0 + 2.0 * U)
                    + 2.0 * U * (Math.abs(p) + h * Math.abs(next));
            assertEquals(p, fast.position.get(axis), positionBound,
                    () -> "P at V=" + velocity + ", h=" + h);
        }
    }

    /** The gravities among the forces. */
    private static Force[] gravities(Force[] forces) {
        List<Force> gravities = new ArrayList<>();
        for (Force force : forces) {
            if (force instanceof Gravity) {
                gravities.add(force);
            }
        }
        return gravities.toArray(new Force[0]);
    }

    /** True if h·rate is within 1e-3 (relatively) of the limits 1 or 2. */
    private static boolean isNear(float stepTimesRate) {
        return Math.abs(stepTimesRate - 1f) < 1e-3f || Math.abs(stepTimesRate - 2f) < 2e-3f;
    }

    private static Vector3f randomVector(Random random, float scale) {
        return new Vector3f(scale * (2f * random.nextFloat() - 1f),
                scale * (2f * random.nextFloat() - 1f), scale * (2f * random.nextFloat() - 1f));
    }

    private static void assertBitwiseEqual(Vector3f expected, Vector3f actual) {
        for (int axis = 0; axis < 3; ++axis) {
            assertEquals(Float.floatToIntBits(expected.get(axis)),
                    Float.floatToIntBits(actual.get(axis)),
                    "expected " + expected + " but was " + actual);
        }
    }
}

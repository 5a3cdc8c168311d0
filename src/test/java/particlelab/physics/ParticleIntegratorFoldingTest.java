package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The folded forces of {@link ParticleIntegrator}: against the general path (every force asked
 * through the {@link Force} interface), the batch form against the per-particle step, refolding
 * after a setter, and the finiteness guards on every path, for every mix of built-in forces.
 *
 * <p>The general path is reached by hiding each built-in force behind a plain {@link Force}
 * ({@link ThroughInterface}): the integrator then cannot fold it and evaluates the lecture's
 * recipe {@code a = g + F/m} force by force.
 */
class ParticleIntegratorFoldingTest {

    /** The unit round-off of float, 2^-24: one rounding errs by at most this, relatively. */
    static final double U = Math.ulp(1f) / 2.0;
    /**
     * Roundings per path in one velocity update, each erring by at most U of a term no larger
     * than the scale S of {@link #assertFoldedAgrees}: the folded path rounds 1/m, c·|V| (and
     * the square root), b + c·|V|, k/|V|, the difference, ·(1/m), σ·V, g − σ·V, h·a and
     * V + h·a (at most 10; until the fold ran only in the acceleration, issue 30, it rounded
     * 16 times: 1 − h·σ, V·r, h·g ...); the general path 1/m, c·|V|, the product by V,
     * ·(1/m), + g, h·a and V + h·a (at most 8 with the square root). Both errors add: 18,
     * and the bound keeps the 24 it was proven with.
     */
    static final double ROUNDINGS = 24.0;
    private static final float H = 1f / 60f;
    private static final int COUNT = 41;

    /** The force mixes the demos use, each with the coefficients of a typical scene. */
    enum Mix {
        GRAVITY, LINEAR, QUADRATIC, THRUST_LINEAR;

        /** Fresh forces of this mix. */
        Force[] forces() {
            switch (this) {
                case GRAVITY:
                    return new Force[] {new Gravity()};
                case LINEAR:
                    return new Force[] {new Gravity(), new LinearDrag(0.9f)};
                case QUADRATIC:
                    return new Force[] {new Gravity(), new QuadraticDrag(0.05f)};
                default:
                    return new Force[] {new Gravity(), new LinearDrag(0.3f), new Thrust(4f)};
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void foldedStepAgreesWithTheForceByForceRecipeToAFewUlp(Mix mix) {
        Force[] forces = mix.forces();
        ParticleIntegrator folded = new ParticleIntegrator(forces);
        ParticleIntegrator general = new ParticleIntegrator(hide(forces));
        Random random = new Random(12);
        for (int n = 0; n < 20_000; ++n) {
            float mass = 0.1f + 5f * random.nextFloat();
            float h = n % 2 == 0 ? H : 0.2f * random.nextFloat();
            Vector3f position = randomVector(random, 1000f);
            Vector3f velocity = randomVector(random, n % 3 == 0 ? 1f : 80f);
            Particle one = new Particle(position, velocity, mass);
            Particle two = new Particle(position, velocity, mass);
            folded.step(one, h);
            general.step(two, h);
            assertFoldedAgrees(forces, position, velocity, mass, h, one, two);
        }
    }

    @Test
    void gravityAloneFoldsBitForBit() {
        // σ = 0, so the folded a is g − 0·V = g, as the force-by-force sum
        ParticleIntegrator folded = new ParticleIntegrator(new Gravity());
        ParticleIntegrator general = new ParticleIntegrator(hide(new Gravity()));
        Particle one = new Particle(new Vector3f(1f, 2f, 3f), new Vector3f(20f, 30f, -1f), 2f);
        Particle two = new Particle(one.position, one.velocity, 2f);
        for (int n = 0; n < 1000; ++n) {
            folded.step(one, H);
            general.step(two, H);
        }
        assertBitwiseEqual(two.position, one.position);
        assertBitwiseEqual(two.velocity, one.velocity);
    }

    @Test
    void generalPathIsTheLecturesRecipe() {
        // a = g + F/m from acceleration(), V ← V + h·a, P ← P + h·V: the same floats
        ParticleIntegrator general = new ParticleIntegrator(hide(new Gravity(),
                new QuadraticDrag(0.05f), new LinearDrag(0.2f), new Thrust(3f)));
        Particle particle = new Particle(new Vector3f(0f, 5f, 0f), new Vector3f(9f, 12f, 2f), 1.5f);
        Vector3f a = new Vector3f();
        for (int n = 0; n < 500; ++n) {
            general.acceleration(particle, a);
            Vector3f velocity = particle.velocity.clone();
            velocity.set(velocity.x + H * a.x, velocity.y + H * a.y, velocity.z + H * a.z);
            Vector3f position = particle.position.clone();
            position.set(position.x + H * velocity.x, position.y + H * velocity.y,
                    position.z + H * velocity.z);
            general.step(particle, H);
            assertBitwiseEqual(velocity, particle.velocity);
            assertBitwiseEqual(position, particle.position);
        }
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void foldedTrajectoryFollowsTheRecipe(Mix mix) {
        Force[] forces = mix.forces();
        ParticleIntegrator folded = new ParticleIntegrator(forces);
        ParticleIntegrator general = new ParticleIntegrator(hide(forces));
        Particle one = new Particle(new Vector3f(), new Vector3f(20f, 30f, 5f), 1.2f);
        Particle two = new Particle(one.position, one.velocity, 1.2f);
        for (int n = 0; n < 600; ++n) {
            folded.step(one, H);
            general.step(two, H);
        }
        // 600 steps of differences of a few ulp each; the step is stable (σh < 0.1 here) so
        // old differences do not grow: at most 600·(24·U) relative, about 9e-4, of speeds and
        // distances up to about 100: 1e-3 m and m/s.
        assertVectorNear(two.position, one.position, 1e-3f);
        assertVectorNear(two.velocity, one.velocity, 1e-3f);
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void batchIsBitForBitThePerParticleStep(Mix mix) {
        assertBatchMatchesObjects(new ParticleIntegrator(mix.forces()), 1.7f);
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void batchOfSeveralBlocksIsBitForBitAndNamesTheFirstBadParticle(Mix mix) {
        // 2500 particles: the batch works in blocks of 1024, the last one partial
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        assertBatchMatchesObjects(integrator, 0.8f, 2500, 20);
        for (int bad : new int[] {0, 1023, 1024, 2100, 2499}) {
            for (int axis = 0; axis < 3; ++axis) {
                float[] positions = new float[3 * 2500];
                float[] velocities = new float[3 * 2500];
                Arrays.fill(velocities, 3f);
                velocities[axis * 2500 + bad] = axis == 1 ? Float.POSITIVE_INFINITY : Float.NaN;
                NonFiniteStepException thrown = assertThrows(NonFiniteStepException.class,
                        () -> integrator.batch().stepPacked(positions, velocities, 2500, 1f, H));
                assertTrue(thrown.getMessage().contains("packed particle " + bad + " of 2500"),
                        thrown.getMessage());
                // every particle was stepped: the last one moved
                assertEquals(Float.floatToIntBits(positions[2 * 2500 + 2499]),
                        Float.floatToIntBits(bad == 2499 && axis == 2 ? Float.NaN
                                : H * velocities[2 * 2500 + 2499]));
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void batchWhosePositionsSumBeyondTheFloatRangeIsStillStepped(Mix mix) {
        // every position is finite, their sum (the cheap check) overflows: no refusal
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        int count = 40;
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        Arrays.fill(positions, 3e38f);
        Arrays.fill(velocities, 1f);
        integrator.batch().stepPacked(positions, velocities, count, 1f, H);
        for (float position : positions) {
            assertEquals(3e38f, position, 0f);
        }
    }

    @Test
    void batchWithASpringOrAStudentForceIsBitForBitThePerParticleStep() {
        assertBatchMatchesObjects(new ParticleIntegrator(new Gravity(), new LinearDrag(0.4f),
                new Spring(new Vector3f(0f, 10f, 0f), 2f, 30f, 0.5f)), 1.3f);
        assertBatchMatchesObjects(new ParticleIntegrator(hide(new Gravity(),
                new QuadraticDrag(0.02f))), 0.8f);
    }

    @Test
    void aSetterOnAFoldedForceIsSeenByTheNextStep() {
        Gravity gravity = new Gravity();
        LinearDrag linear = new LinearDrag(0.9f);
        QuadraticDrag quadratic = new QuadraticDrag(0.02f);
        Thrust thrust = new Thrust(1f);
        ParticleIntegrator integrator = new ParticleIntegrator(gravity, linear, quadratic, thrust);
        Particle particle = new Particle(new Vector3f(), new Vector3f(20f, 30f, 5f), 2f);
        float[] positions = new float[3];
        float[] velocities = {20f, 30f, 5f};
        for (int n = 0; n < 10; ++n) {
            integrator.step(particle, H);
            integrator.batch().stepPacked(positions, velocities, 1, 2f, H);
        }
        linear.setCoefficient(0.1f);
        quadratic.setCoefficient(0.3f);
        thrust.setMagnitude(6f);
        gravity.setAcceleration(new Vector3f(1f, -3.7f, 0f));
        // a fresh integrator with the new coefficients, from the same state
        ParticleIntegrator fresh = new ParticleIntegrator(new Gravity(new Vector3f(1f, -3.7f, 0f)),
                new LinearDrag(0.1f), new QuadraticDrag(0.3f), new Thrust(6f));
        Particle expected = new Particle(particle.position, particle.velocity, 2f);
        assertEquals(fresh.dampingRate(expected), integrator.dampingRate(particle), 0f);
        assertEquals(fresh.dragRate(expected), integrator.dragRate(particle), 0f);
        for (int n = 0; n < 10; ++n) {
            integrator.step(particle, H);
            fresh.step(expected, H);
            integrator.batch().stepPacked(positions, velocities, 1, 2f, H);
        }
        assertBitwiseEqual(expected.velocity, particle.velocity);
        assertBitwiseEqual(expected.position, particle.position);
        assertBitwiseEqual(expected.velocity, new Vector3f(velocities[0], velocities[1],
                velocities[2]));
        // setting a coefficient back to its value is a change too: still the same numbers
        linear.setCoefficient(0.1f);
        integrator.step(particle, H);
        fresh.step(expected, H);
        assertBitwiseEqual(expected.velocity, particle.velocity);
    }

    /**
     * A setter marks stale the folds of the integrators that hold its force, and no other: a
     * change of another integrator's force leaves it as it was, a change of a force two
     * integrators share reaches both, and a change after another one was already seen is
     * seen too.
     */
    @Test
    void aSetterReachesEveryIntegratorHoldingTheForceAndNoOther() {
        LinearDrag shared = new LinearDrag(0.9f);
        LinearDrag alone = new LinearDrag(0.9f);
        ParticleIntegrator first = new ParticleIntegrator(new Gravity(), shared);
        ParticleIntegrator second = new ParticleIntegrator(new Gravity(), shared);
        ParticleIntegrator other = new ParticleIntegrator(new Gravity(), alone);
        Particle a = new Particle(new Vector3f(), new Vector3f(20f, 30f, 5f), 2f);
        Particle b = new Particle(a.position, a.velocity, 2f);
        Particle c = new Particle(a.position, a.velocity, 2f);
        first.step(a, H);
        second.step(b, H);
        other.step(c, H);
        // another integrator's force changed: other steps with b = 0.4 now, first still 0.9
        alone.setCoefficient(0.4f);
        ParticleIntegrator stillNine = new ParticleIntegrator(new Gravity(), new LinearDrag(0.9f));
        ParticleIntegrator nowFour = new ParticleIntegrator(new Gravity(), new LinearDrag(0.4f));
        Particle expectNine = new Particle(a.position, a.velocity, 2f);
        Particle expectFour = new Particle(c.position, c.velocity, 2f);
        first.step(a, H);
        stillNine.step(expectNine, H);
        other.step(c, H);
        nowFour.step(expectFour, H);
        assertBitwiseEqual(expectNine.velocity, a.velocity);
        assertBitwiseEqual(expectFour.velocity, c.velocity);
        // the shared force changed after first had seen the other change: both see it
        shared.setCoefficient(0.1f);
        ParticleIntegrator nowOne = new ParticleIntegrator(new Gravity(), new LinearDrag(0.1f));
        Particle expectA = new Particle(a.position, a.velocity, 2f);
        Particle expectB = new Particle(b.position, b.velocity, 2f);
        first.step(a, H);
        second.step(b, H);
        nowOne.step(expectA, H);
        nowOne.step(expectB, H);
        assertBitwiseEqual(expectA.velocity, a.velocity);
        assertBitwiseEqual(expectB.velocity, b.velocity);
        assertEquals(0.1f / 2f, first.dampingRate(a), 0f);
        assertEquals(0.1f / 2f, second.dampingRate(b), 0f);
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void foldedRatesAreTheForcesOwn(Mix mix) {
        Force[] forces = mix.forces();
        ParticleIntegrator folded = new ParticleIntegrator(forces);
        ParticleIntegrator general = new ParticleIntegrator(hide(forces));
        Random random = new Random(5);
        for (int n = 0; n < 2000; ++n) {
            Particle particle = new Particle(randomVector(random, 100f),
                    randomVector(random, 60f), 0.2f + random.nextFloat());
            float h = 0.5f * random.nextFloat();
            // λ: the forces' own rates added in double, either way: equal to a float rounding
            float lambda = general.dampingRate(particle);
            assertEquals(lambda, folded.dampingRate(particle), Math.ulp(lambda));
            assertEquals(0f, folded.stiffness(particle), 0f);
            // σ: in double from the coefficients, against the general path's difference of
            // float accelerations a(V) − a(0), each rounded a few times by U of their terms
            // (at most |g| + σ⁺·|V|), then divided by |V|
            float sigma = general.dragRate(particle);
            float speed = particle.velocity.length();
            double slack = 8.0 * U * (Gravity.STANDARD_G / speed
                    + positiveDragRate(forces, speed, particle.getMass()));
            assertEquals(sigma, folded.dragRate(particle), slack);
            StepRegime expected = general.regime(particle, h);
            StepRegime actual = folded.regime(particle, h);
            if (expected != actual) {
                // only at a boundary, where a rounding of σ or λ tips it
                assertTrue(Math.abs(h * sigma - Math.round(h * sigma)) < 1e-4
                        || Math.abs(h * lambda - Math.round(h * lambda)) < 1e-4,
                        expected + " vs " + actual + " at " + particle + ", h=" + h);
            }
        }
    }

    @Test
    void rememberedRegimeFollowsTheStepTheMassRestAndSetters() {
        // gravity and linear drag: the integrator remembers the regime per step and mass
        LinearDrag drag = new LinearDrag(1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), drag);
        ParticleIntegrator general = new ParticleIntegrator(hide(new Gravity(), drag));
        Particle moving = new Particle(new Vector3f(), new Vector3f(3f, 0f, 0f), 1f);
        Particle resting = new Particle(new Vector3f(), new Vector3f(), 1f);
        Particle heavy = new Particle(new Vector3f(), new Vector3f(3f, 0f, 0f), 10f);
        Particle[] order = {moving, resting, heavy, moving, resting};
        // h·b/m = 0.5, 1.5 (overshoots at rest, reverses moving), 2.5 (unstable, grows)
        float[] steps = {0.5f, 1.5f, 2.5f, 1.5f, 0.5f, 2.5f};
        for (float b : new float[] {1f, 0.7f}) {
            drag.setCoefficient(b);
            for (float h : steps) {
                for (Particle particle : order) {
                    assertEquals(general.regime(particle, h), integrator.regime(particle, h),
                            "b=" + b + ", h=" + h + ", " + particle);
                }
            }
        }
        drag.setCoefficient(1f);
        assertEquals(StepRegime.REVERSES, integrator.regime(moving, 1.5f));
        assertEquals(StepRegime.OVERSHOOTS, integrator.regime(resting, 1.5f));
        assertEquals(StepRegime.GROWS, integrator.regime(moving, 2.5f));
        assertEquals(StepRegime.UNSTABLE, integrator.regime(resting, 2.5f));
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void rememberedRegimeIsTheLimitsAnswerAtEverySpeedStepAndSetter(Mix mix) {
        // regime() answers most particles from a remembered speed bound; the public limits
        // (σ from dragRate, 2/λ, 1/λ) must give the same regime wherever h·σ and h·λ are
        // clear of 1 and 2 (closer than 1e-3, roundings of either side could tip it)
        Force[] forces = mix.forces();
        ParticleIntegrator integrator = new ParticleIntegrator(forces);
        Random random = new Random(7);
        Particle particle = new Particle();
        int unstable = 0;
        for (int n = 0; n < 40_000; ++n) {
            if (n % 1000 == 0) {
                // a setter mid-run: the remembered bound must follow it
                setCoefficients(forces, 0.05f + 3f * random.nextFloat());
            }
            float mass = n % 3 == 0 ? 1f : 0.2f + 4f * random.nextFloat();
            float h = n % 2 == 0 ? 0.5f : 8f * random.nextFloat();
            // 0.1 to 1000 m/s, and some at rest
            float speed = n % 17 == 0 ? 0f
                    : (float) Math.pow(10.0, 4.0 * random.nextDouble() - 1.0);
            particle.setMass(mass);
            particle.velocity.set(randomVector(random, 1f)).normalizeLocal().multLocal(speed);
            float sigmaH = h * integrator.dragRate(particle);
            float lambdaH = h * integrator.dampingRate(particle);
            if (isNear(sigmaH) || isNear(lambdaH)) {
                continue;
            }
            StepRegime expected = StepRegime.of(h, integrator.dragRate(particle),
                    integrator.maxStableStep(particle), integrator.maxMonotoneStep(particle));
            unstable += expected == StepRegime.STABLE ? 0 : 1;
            assertEquals(expected, integrator.regime(particle, h),
                    () -> mix + " h=" + h + ", " + particle + ", h*sigma=" + sigmaH
                            + ", h*lambda=" + lambdaH);
        }
        // gravity alone is stable at any step; with drag both sides of the bound were visited
        assertTrue(mix == Mix.GRAVITY ? unstable == 0 : unstable > 1000 && unstable < 39_000,
                "unstable cases: " + unstable);
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void everyPathRefusesNaNInputAndKeepsTheState(Mix mix) {
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        Particle particle = new Particle(new Vector3f(1f, 2f, 3f), new Vector3f(4f, 5f, 6f), 1f);
        particle.velocity.y = Float.NaN;
        assertThrows(NonFiniteStepException.class, () -> integrator.step(particle, H));
        assertEquals(1f, particle.position.x, 0f);
        assertTrue(Float.isNaN(particle.velocity.y));
        Particle[] two = {new Particle(), particle};
        assertThrows(NonFiniteStepException.class, () -> integrator.step(two, H));
        float[] positions = new float[3 * 4];
        float[] velocities = new float[3 * 4];
        velocities[4 + 2] = Float.NaN;
        NonFiniteStepException batch = assertThrows(NonFiniteStepException.class,
                () -> integrator.batch().stepPacked(positions, velocities, 4, 1f, H));
        assertTrue(batch.getMessage().contains("packed particle 2 of 4"), batch.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void everyPathRefusesOverflowAndKeepsTheState(Mix mix) {
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        Vector3f top = new Vector3f(Float.MAX_VALUE, 0f, 0f);
        // |V| = 3e38 with h = 1/60: the move h·V = 5e36 takes P past the largest float
        Particle particle = new Particle(top, new Vector3f(3e38f, 0f, 0f), 1f);
        if (mix == Mix.QUADRATIC) {
            // c·|V|² overflows already: the step would make V itself non-finite
            particle.velocity.set(1e30f, 0f, 0f);
        }
        Vector3f before = particle.velocity.clone();
        assertThrows(NonFiniteStepException.class, () -> integrator.step(particle, H));
        assertBitwiseEqual(before, particle.velocity);
        assertBitwiseEqual(top, particle.position);
        float[] positions = new float[3 * 3];
        float[] velocities = new float[3 * 3];
        positions[1] = Float.MAX_VALUE;
        velocities[1] = before.x;
        NonFiniteStepException batch = assertThrows(NonFiniteStepException.class,
                () -> integrator.batch().stepPacked(positions, velocities, 3, 1f, H));
        assertTrue(batch.getMessage().contains("packed particle 1 of 3"), batch.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void aSpeedBeyondTheFloatRangeOfItsSquareIsStillStepped(Mix mix) {
        // |V| = 1e20 m/s: |V|² overflows, so |V| computes as ∞; without quadratic drag the
        // step itself stays finite and must be taken, the rates must not be NaN
        ParticleIntegrator integrator = new ParticleIntegrator(mix.forces());
        Particle particle = new Particle(new Vector3f(), new Vector3f(1e20f, 0f, 0f), 1f);
        assertFalse(Float.isNaN(integrator.dampingRate(particle)));
        assertFalse(Float.isNaN(integrator.dragRate(particle)));
        assertTrue(integrator.regime(particle, H) != null);
        if (mix == Mix.QUADRATIC) {
            assertThrows(NonFiniteStepException.class, () -> integrator.step(particle, H));
            return;
        }
        ParticleIntegrator general = new ParticleIntegrator(hide(mix.forces()));
        Particle reference = new Particle(particle.position, particle.velocity, 1f);
        integrator.step(particle, H);
        general.step(reference, H);
        // a few roundings apart, as foldedStepAgreesWithTheForceByForceRecipeToAFewUlp
        assertEquals(reference.velocity.x, particle.velocity.x, 1e-6f * 1e20f);
        assertEquals(reference.velocity.y, particle.velocity.y, 1e-6f);
        float[] positions = new float[3];
        float[] velocities = {1e20f, 0f, 0f};
        integrator.batch().stepPacked(positions, velocities, 1, 1f, H);
        assertBitwiseEqual(particle.velocity, new Vector3f(velocities[0], velocities[1],
                velocities[2]));
    }

    @ParameterizedTest
    @EnumSource(Mix.class)
    void theSmallestMassStaysFiniteWhereTheRecipeDoes(Mix mix) {
        // b/m = 1e3/1.2e-38 is beyond the float range: the folded factor 1 − h·b/m is
        // infinite, and ∞·0 would give NaN for a particle at rest. The recipe gives a = g:
        // every path must take that step, not refuse it.
        Force[] forces = mix.forces();
        for (Force force : forces) {
            if (force instanceof LinearDrag) {
                ((LinearDrag) force).setCoefficient(1e3f);
            }
        }
        ParticleIntegrator integrator = new ParticleIntegrator(forces);
        ParticleIntegrator general = new ParticleIntegrator(hide(forces));
        float mass = Particle.MIN_MASS_KG;
        Particle resting = new Particle(new Vector3f(0f, 1f, 0f), new Vector3f(), mass);
        Particle reference = new Particle(resting.position, resting.velocity, mass);
        integrator.step(resting, H);
        general.step(reference, H);
        assertBitwiseEqual(reference.velocity, resting.velocity);
        assertBitwiseEqual(reference.position, resting.position);
        float[] positions = {0f, 1f, 0f};
        float[] velocities = new float[3];
        integrator.batch().stepPacked(positions, velocities, 1, mass, H);
        assertBitwiseEqual(reference.velocity, new Vector3f(velocities[0], velocities[1],
                velocities[2]));
        // moving, the same drag overflows the step: refused on both paths
        Particle moving = new Particle(new Vector3f(), new Vector3f(1f, 1f, 1f), mass);
        if (mix == Mix.LINEAR || mix == Mix.THRUST_LINEAR || mix == Mix.QUADRATIC) {
            assertThrows(NonFiniteStepException.class, () -> {
                for (int n = 0; n < 3; ++n) {
                    integrator.step(moving, H);
                }
            });
            assertTrue(moving.isFinite(), moving.toString());
        }
    }

    /**
     * Compare one folded step with the general step from the same state, component by
     * component: the velocities differ by at most {@link #ROUNDINGS}·U·S, with the scale
     * {@code S = |V_i|·(1 + h·σ⁺) + h·|g_i| + |V'_i|} and σ⁺ the drag rate with every term
     * taken positive (thrust's −k/|V| can cancel drag, but not its rounding); the positions by
     * h times that plus one rounding of each P'.
     */
    private static void assertFoldedAgrees(Force[] forces, Vector3f position, Vector3f velocity,
            float mass, float h, Particle folded, Particle general) {
        double rate = positiveDragRate(forces, velocity.length(), mass);
        Vector3f g = new Vector3f();
        for (Force force : forces) {
            if (force instanceof Gravity) {
                ((Gravity) force).copyAcceleration(g);
            }
        }
        for (int axis = 0; axis < 3; ++axis) {
            double v = velocity.get(axis);
            double next = general.velocity.get(axis);
            double scale = Math.abs(v) * (1.0 + h * rate) + h * Math.abs(g.get(axis))
                    + Math.abs(next);
            double velocityBound = ROUNDINGS * U * scale;
            assertEquals(next, folded.velocity.get(axis), velocityBound,
                    () -> "V" + " at P=" + position + ", V=" + velocity + ", h=" + h);
            double p = general.position.get(axis);
            // h·V' and P + h·V' round once in each path
            double positionBound = h * velocityBound * (1.0 + 2.0 * U)
                    + 2.0 * U * (Math.abs(p) + h * Math.abs(next));
            assertEquals(p, folded.position.get(axis), positionBound,
                    () -> "P" + " at P=" + position + ", V=" + velocity + ", h=" + h);
        }
    }

    /** σ⁺: the drag rate with every term taken positive (in 1/s). */
    static double positiveDragRate(Force[] forces, double speed, float mass) {
        double rate = 0.0;
        for (Force force : forces) {
            if (force instanceof LinearDrag) {
                rate += ((LinearDrag) force).getCoefficient();
            } else if (force instanceof QuadraticDrag) {
                rate += ((QuadraticDrag) force).getCoefficient() * speed;
            } else if (force instanceof Thrust && speed >= Thrust.MIN_SPEED) {
                rate += ((Thrust) force).getMagnitude() / speed;
            }
        }
        return rate / mass;
    }

    /** Step objects and the packed copy side by side for 300 steps: the same floats. */
    private static void assertBatchMatchesObjects(ParticleIntegrator integrator, float mass) {
        assertBatchMatchesObjects(integrator, mass, COUNT, 300);
    }

    /** Step objects and the packed copy side by side: the same floats. */
    static void assertBatchMatchesObjects(ParticleIntegrator integrator, float mass,
            int count, int steps) {
        Particle[] particles = new Particle[count];
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        for (int i = 0; i < count; ++i) {
            // include a particle at rest: thrust gives it no heading
            Vector3f velocity = i == 0 ? new Vector3f()
                    : new Vector3f(20f + i % 5, 30f - i % 3, i % 4 - 2f);
            particles[i] = new Particle(new Vector3f(i, 0f, -i), velocity, mass);
            for (int axis = 0; axis < 3; ++axis) {
                positions[axis * count + i] = particles[i].position.get(axis);
                velocities[axis * count + i] = velocity.get(axis);
            }
        }
        for (int n = 0; n < steps; ++n) {
            if (n % 2 == 0) {
                integrator.step(particles, H);
            } else {
                for (Particle particle : particles) {
                    integrator.step(particle, H);
                }
            }
            integrator.batch().stepPacked(positions, velocities, count, mass, H);
        }
        for (int i = 0; i < count; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                assertEquals(Float.floatToIntBits(particles[i].position.get(axis)),
                        Float.floatToIntBits(positions[axis * count + i]), "P of " + i);
                assertEquals(Float.floatToIntBits(particles[i].velocity.get(axis)),
                        Float.floatToIntBits(velocities[axis * count + i]), "V of " + i);
            }
        }
    }

    /** Set every drag coefficient and thrust of the forces to the value given. */
    private static void setCoefficients(Force[] forces, float value) {
        for (Force force : forces) {
            if (force instanceof LinearDrag) {
                ((LinearDrag) force).setCoefficient(value);
            } else if (force instanceof QuadraticDrag) {
                ((QuadraticDrag) force).setCoefficient(0.1f * value);
            } else if (force instanceof Thrust) {
                ((Thrust) force).setMagnitude(4f * value);
            }
        }
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

    private static void assertVectorNear(Vector3f expected, Vector3f actual, float tolerance) {
        for (int axis = 0; axis < 3; ++axis) {
            assertEquals(expected.get(axis), actual.get(axis), tolerance,
                    "expected " + expected + " but was " + actual);
        }
    }

    /** Each force behind a plain {@link Force}, so that the integrator cannot fold it. */
    static Force[] hide(Force... forces) {
        Force[] hidden = new Force[forces.length];
        for (int i = 0; i < forces.length; ++i) {
            hidden[i] = new ThroughInterface(forces[i]);
        }
        return hidden;
    }

    /** A force the integrator knows only through the interface, as a student's own. */
    private static final class ThroughInterface implements Force {

        private final Force force;

        ThroughInterface(Force force) {
            this.force = force;
        }

        @Override
        public void addForce(Particle particle, Vector3f netForce) {
            force.addForce(particle, netForce);
        }

        @Override
        public void addFieldAcceleration(Particle particle, Vector3f fieldAcceleration) {
            force.addFieldAcceleration(particle, fieldAcceleration);
        }

        @Override
        public float dampingRate(Particle particle) {
            return force.dampingRate(particle);
        }

        @Override
        public float stiffness(Particle particle) {
            return force.stiffness(particle);
        }

        @Override
        public String describe() {
            return force.describe();
        }
    }
}

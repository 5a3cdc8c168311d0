package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static particlelab.VectorAssert.assertVectorEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * {@link ParticleIntegrator} in the hard cases: stiff drag, steps near and beyond the stability
 * limits, thrust from rest, NaN stopped at the source, and a very long run.
 *
 * <p>Linear drag {@code b} on mass {@code m} makes one Euler step multiply the velocity by
 * {@code r = 1 − b·h/m}: monotone decay for {@code b·h/m < 1}, decay with alternating sign for
 * {@code 1 < b·h/m < 2}, growth beyond 2 (docs/numerics.md, "Stability"). Gravity adds a
 * constant to each step and does not change {@code r}. A spring adds the stiffness
 * {@code ω² = k/m}: the damped oscillator's limit {@code 4/(λ + sqrt(λ² + 4ω²))}.
 */
class ParticleIntegratorStabilityTest {

    private static final float G = Gravity.STANDARD_G;
    /** Float machine epsilon, 2^-23: each operation rounds within EPS/2 relative. */
    private static final float EPS = Math.ulp(1f);
    /** Mass (kg) and linear drag (kg/s) of the stiff cases: m/b = 0.1 s. */
    private static final float MASS = 1f;
    private static final float STIFF_B = 10f;

    @Test
    void stiffLinearDragAtHalfTheMonotoneLimitDecaysWithoutChangingSign() {
        float[] speeds = stiffDragVelocities(0.5f, 20);

        for (int n = 1; n < speeds.length; ++n) {
            assertTrue(speeds[n] > 0f, "sign kept at step " + n);
            // r = 0.5: b·h/m is 0.5 only to float round-off, so allow a few EPS per step.
            assertEquals(0.5f * speeds[n - 1], speeds[n], 4 * EPS * speeds[n - 1], "step " + n);
        }
    }

    @Test
    void stiffLinearDragBetweenTheLimitsAlternatesSignButDecays() {
        float[] speeds = stiffDragVelocities(1.5f, 20);

        for (int n = 1; n < speeds.length; ++n) {
            assertTrue(Math.signum(speeds[n]) == -Math.signum(speeds[n - 1]),
                    "sign flips at step " + n + ": " + speeds[n - 1] + " → " + speeds[n]);
            // r = −0.5: b·h/m is 1.5 only to float round-off, so allow a few EPS per step.
            assertEquals(-0.5f * speeds[n - 1], speeds[n], 4 * EPS * Math.abs(speeds[n - 1]));
        }
    }

    @Test
    void stiffLinearDragBeyondTheStableLimitGrowsWithAlternatingSign() {
        float[] speeds = stiffDragVelocities(2.5f, 20);

        for (int n = 1; n < speeds.length; ++n) {
            assertTrue(Math.abs(speeds[n]) > Math.abs(speeds[n - 1]), "grows at step " + n);
            assertEquals(-1.5f * speeds[n - 1], speeds[n], 4 * EPS * Math.abs(speeds[n]));
        }
        // 1.5^20 ≈ 3325: the "drag" has made the particle 3000 times faster.
        assertEquals(Math.pow(1.5, 20), Math.abs(speeds[20]), 1e-3 * Math.pow(1.5, 20));
    }

    @Test
    void linearDragLimitsAreTwoMOverBAndMOverB() {
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.UNIT_X, 2f);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(), new LinearDrag(8f));

        assertEquals(2f * 2f / 8f, integrator.maxStableStep(particle), 0f);
        assertEquals(2f / 8f, integrator.maxMonotoneStep(particle), 0f);
        assertEquals(4f, integrator.dampingRate(particle), 0f);
    }

    @Test
    void nothingThatDampsMeansNoStepLimit() {
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.UNIT_X, 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), new Thrust(5f));

        assertEquals(Float.POSITIVE_INFINITY, integrator.maxStableStep(particle));
        assertEquals(Float.POSITIVE_INFINITY, integrator.maxMonotoneStep(particle));
    }

    @Test
    void linearDragSettlesJustBelowTheStableLimitAndBlowsUpJustAbove() {
        // With gravity: the velocity tends to the terminal value (0, −m·g/b, 0) when stable.
        float b = 4f;
        Particle probe = new Particle(Vector3f.ZERO, Vector3f.ZERO, MASS);
        float limit = new ParticleIntegrator(new LinearDrag(b)).maxStableStep(probe);
        float terminal = MASS * G / b;

        // |r| = 0.98: after 2000 steps the start is forgotten (0.98^2000 ≈ 3e-18).
        float below = runLinearDragWithGravity(b, 0.99f * limit, 2000);
        assertEquals(-terminal, below, terminal * 1e-4f);
        // |r| = 1.02: the deviation from terminal velocity grows 1.02^2000 ≈ 1.6e17 times.
        float above = runLinearDragWithGravity(b, 1.01f * limit, 2000);
        assertTrue(Math.abs(above + terminal) > 1e10f, "diverged: " + above);
    }

    @Test
    void quadraticDragNeverReversesVelocityBelowLimit() {
        // One step multiplies V by 1 − c·h·|V|/m; below c·h·|V0|/m = 1 the speed only falls,
        // which makes the factor closer to 1 on every later step.
        float c = 1f;
        float h = 0.009f;
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(100f, 0f, 0f), MASS);
        ParticleIntegrator integrator = new ParticleIntegrator(new QuadraticDrag(c));
        assertEquals(0.9f, c * h * particle.velocity.x / MASS, 1e-6f);

        float previous = particle.velocity.x;
        for (int n = 1; n <= 1000; ++n) {
            integrator.step(particle, h);
            assertTrue(particle.velocity.x > 0f && particle.velocity.x < previous,
                    "speed falls without reversing at step " + n + ": " + particle.velocity.x);
            previous = particle.velocity.x;
        }
    }

    @Test
    void quadraticDragAtHighSpeedReversesTheVelocityBeyondTheLimit() {
        // c·h·v/m = 1.5 > 1: the documented reversal, V1 = (1 − 1.5)·V0.
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(100f, 0f, 0f), MASS);

        new ParticleIntegrator(new QuadraticDrag(1f)).step(particle, 0.015f);

        assertVectorEquals(new Vector3f(-50f, 0f, 0f), particle.velocity, 100f * 4 * EPS);
    }

    @Test
    void quadraticDragBeyondTwiceTheLimitDivergesAndTheStepThrows() {
        // c·h·v/m = 3: V1 = −2·V0, then the factor worsens every step (−5, +11, ...), and the
        // speed overflows within a handful of steps: the step must throw, not return NaN.
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(100f, 0f, 0f), MASS);
        ParticleIntegrator integrator = new ParticleIntegrator(new QuadraticDrag(1f));

        assertThrows(IllegalStateException.class, () -> {
            for (int n = 0; n < 100; ++n) {
                integrator.step(particle, 0.03f);
            }
        });
        assertTrue(particle.isFinite(), particle.toString());
    }

    @Test
    void quadraticDragWithGravityIsStableUpToTerminalSpeedOverG() {
        // Near terminal speed v_t a small change of speed decays at 2c·v_t/m = 2g/v_t, so the
        // Euler step settles for h < v_t/g and not beyond (docs/numerics.md), the limit the
        // integrator reports there.
        float m = 1f;
        float c = 0.1f;
        float terminal = (float) Math.sqrt(m * G / c);
        Particle atTerminal = new Particle(Vector3f.ZERO, new Vector3f(0f, -terminal, 0f), m);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(c));
        float limit = integrator.maxStableStep(atTerminal);
        // Both sides carry a few float roundings: 1e-5 relative.
        assertEquals(terminal / G, limit, limit * 1e-5f);
        assertEquals(terminal / (2 * G), integrator.maxMonotoneStep(atTerminal), limit * 1e-5f);

        // Start 10 % off terminal speed: below the limit the error dies out ...
        float[] below = fallWithQuadraticDrag(integrator, m, 0.9f * limit, 0.9f * terminal);
        assertEquals(terminal, -below[0], terminal * 1e-5f);
        assertEquals(terminal, -below[1], terminal * 1e-5f);
        // ... just above it the speed keeps swinging about v_t (or runs away): no settling.
        float[] above = fallWithQuadraticDrag(integrator, m, 1.1f * limit, 0.9f * terminal);
        assertTrue(Math.abs(above[0] - above[1]) > 0.1f * terminal,
                "still swinging: " + above[0] + ", " + above[1]);
    }

    @Test
    void dampedOscillatorLimitReducesToTwoOverLambdaAndTwoOverOmega() {
        assertEquals(2.0 / 5.0, ParticleIntegrator.stableStepLimit(5.0, 0.0), 1e-15);
        assertEquals(2.0 / 3.0, ParticleIntegrator.stableStepLimit(0.0, 9.0), 1e-15);
        assertEquals(Double.POSITIVE_INFINITY, ParticleIntegrator.stableStepLimit(0.0, 0.0));
        // λ = 2, ω² = 4: 4/(2 + sqrt(20)), where ω²h² + 2λh = 4 exactly.
        double h = ParticleIntegrator.stableStepLimit(2.0, 4.0);
        assertEquals(4.0 / (2.0 + Math.sqrt(20.0)), h, 1e-15);
        assertEquals(4.0, 4.0 * h * h + 2.0 * 2.0 * h, 1e-14);
        // No overflow in between: λ² and 4ω² would overflow a float (and λ² a double here).
        assertEquals(2.0 / 1e200, ParticleIntegrator.stableStepLimit(1e200, 1.0), 1e-214);
        assertThrows(IllegalArgumentException.class,
                () -> ParticleIntegrator.stableStepLimit(-1.0, 0.0));
    }

    @Test
    void springAndDampingTogetherGiveTheOscillatorLimitTheIntegratorReports() {
        Particle particle = new Particle(new Vector3f(3f, 0f, 0f), Vector3f.ZERO, 2f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new Spring(Vector3f.ZERO, 1f, 8f, 2f), new LinearDrag(2f));

        assertEquals(4f, integrator.stiffness(particle), 0f);
        assertEquals(2f, integrator.dampingRate(particle), 0f);
        assertEquals((float) (4.0 / (2.0 + Math.sqrt(20.0))), integrator.maxStableStep(particle),
                0f);
    }

    @Test
    void dampedSpringLimitMatchesAMeasuredBisection() {
        // (λ, ω²) from drag-dominated to spring-dominated. Bisection in float on the shared
        // integrator; a trial is stable if the swing did not grow in 2000 steps. Near the
        // limit the factor per step is 1 ± O(Δh/h), so 2000 steps resolve about 1e-3 of h.
        double[][] cases = {{0.5, 100.0}, {2.0, 4.0}, {4.0, 1.0}, {1.0, 0.01}};
        for (double[] c : cases) {
            double theory = ParticleIntegrator.stableStepLimit(c[0], c[1]);
            double stable = 0.5 * theory;
            double unstable = 2.0 * theory;
            assertTrue(springDecays(c[0], c[1], (float) stable), "decays at " + stable);
            assertTrue(!springDecays(c[0], c[1], (float) unstable), "grows at " + unstable);
            for (int i = 0; i < 30; ++i) {
                double mid = 0.5 * (stable + unstable);
                if (springDecays(c[0], c[1], (float) mid)) {
                    stable = mid;
                } else {
                    unstable = mid;
                }
            }
            assertEquals(theory, stable, 2e-3 * theory, "lambda = " + c[0] + ", omega^2 = " + c[1]);
            // Just below decays, just above grows.
            assertTrue(springDecays(c[0], c[1], (float) (0.99 * theory)));
            assertTrue(!springDecays(c[0], c[1], (float) (1.01 * theory)));
        }
    }

    @Test
    void undampedSpringStaysBoundedBelowTwoOverOmegaAndGrowsAbove() {
        // λ = 0: the step is marginally stable below 2/ω (the modified energy is kept, see
        // SpringTest), so "stable" here means bounded. E = ω²x² + v² − ωh·(ωx)·v lies between
        // (1 ∓ ωh/2) times the squared swing, so from v = 0 the swing stays within
        // 1/sqrt(1 − ωh/2) = 10 times its start at ωh = 1.98 (1 % added for float round-off).
        float omegaSquared = 16f;
        float limit = new ParticleIntegrator(new Spring(Vector3f.ZERO, 1f, omegaSquared))
                .maxStableStep(new Particle());
        assertEquals(0.5f, limit, 0f);
        assertTrue(springSwing(0.0, omegaSquared, 0.99f * limit, 5000) < 10.1 * 0.04);
        // Beyond, one eigenvalue is −1.33 (1.33^20 ≈ 290): 20 steps grow it over 100 times.
        assertTrue(springSwing(0.0, omegaSquared, 1.01f * limit, 20) > 100 * 0.04);
    }

    @Test
    void dragRateIsWhatTheDragDoesToTheVelocityItself() {
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(3f, 4f, 0f), 2f);

        assertEquals(1.5f, new ParticleIntegrator(new LinearDrag(3f)).dragRate(particle),
                1.5f * 4 * EPS);
        // c·|V|/m = 0.4·5/2, half of quadratic drag's damping rate.
        assertEquals(1f, new ParticleIntegrator(new QuadraticDrag(0.4f)).dragRate(particle),
                4 * EPS);
        // Thrust speeds the particle up: −k/(m·|V|). Gravity and a spring add nothing.
        assertEquals(-0.6f, new ParticleIntegrator(new Gravity(), new Thrust(6f),
                new Spring(Vector3f.UNIT_Y, 0f, 5f)).dragRate(particle), 0.6f * 4 * EPS);
        assertEquals(0f, new ParticleIntegrator(new LinearDrag(3f)).dragRate(new Particle()),
                0f);
    }

    @Test
    void regimeSeparatesReversingFromGrowing() {
        // Quadratic drag alone at 10 m/s, c = 1, m = 1: σ = 10 /s, λ = 20 /s.
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(10f, 0f, 0f), 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new QuadraticDrag(1f));

        assertEquals(StepRegime.STABLE, integrator.regime(particle, 0.04f));
        assertEquals(StepRegime.OVERSHOOTS, integrator.regime(particle, 0.07f));
        // σh = 1.5: the velocity reverses but shrinks; one step of small changes grows.
        assertEquals(StepRegime.UNSTABLE, integrator.regime(particle, 0.15f));
        assertEquals(StepRegime.GROWS, integrator.regime(particle, 0.25f));
        // Linear drag, σ = λ: reversing and growing come with the λ limits.
        assertEquals(StepRegime.REVERSES, StepRegime.of(0.15f, 10f, Float.POSITIVE_INFINITY,
                0.1f));
        assertEquals(StepRegime.GROWS, StepRegime.of(0.25f, 10f, 0.2f, 0.1f));

        // What the steps really do: at σh = 1.5, V1 = −0.5·V0, and the speed keeps falling.
        integrator.step(particle, 0.15f);
        assertEquals(-5f, particle.velocity.x, 5f * 4 * EPS);
        for (int n = 0; n < 20; ++n) {
            float before = particle.velocity.length();
            integrator.step(particle, 0.15f);
            assertTrue(particle.velocity.length() < before, "shrinks at step " + n);
        }
    }

    @Test
    void thrustFromRestStaysAtRestAndFinite() {
        Particle particle = new Particle();
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Thrust(100f), new LinearDrag(1f));

        for (int n = 0; n < 100; ++n) {
            integrator.step(particle, 1f / 60f);
        }

        // No heading, so no push: not NaN from 0/0, and not a push in an invented direction.
        assertVectorEquals(Vector3f.ZERO, particle.velocity, 0f);
        assertVectorEquals(Vector3f.ZERO, particle.position, 0f);
    }

    @Test
    void thrustFromRestUnderGravityStartsPushingOnceItHasAVelocity() {
        float h = 0.1f;
        float thrust = 3f;
        float m = 2f;
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.ZERO, m);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(), new Thrust(thrust));

        // Step 1: at rest, no heading: gravity alone.
        integrator.step(particle, h);
        assertVectorEquals(new Vector3f(0f, -G * h, 0f), particle.velocity, G * h * EPS);
        // Step 2: the motor now points down, along V, and adds k/m to gravity.
        integrator.step(particle, h);
        float expected = -G * h - h * (G + thrust / m);
        assertVectorEquals(new Vector3f(0f, expected, 0f), particle.velocity,
                Math.abs(expected) * 4 * EPS);
    }

    @Test
    void stepThatWouldOverflowThrowsAndKeepsTheLastFiniteState() {
        // b·h/m = 2.5: |V| grows 1.5 times a step and overflows float after about
        // ln(3.4e38)/ln(1.5) ≈ 219 steps.
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(1f, 1f, 0f), MASS);
        ParticleIntegrator integrator = new ParticleIntegrator(new LinearDrag(STIFF_B));
        float h = 2.5f * MASS / STIFF_B;

        int completed = 0;
        IllegalStateException thrown = null;
        while (thrown == null && completed < 1000) {
            try {
                integrator.step(particle, h);
                assertTrue(particle.isFinite(), "finite after step " + completed);
                ++completed;
            } catch (IllegalStateException e) {
                thrown = e;
            }
        }

        assertTrue(thrown != null, "no exception after " + completed + " steps");
        assertTrue(completed > 150 && completed < 300, "threw after " + completed + " steps");
        assertTrue(particle.isFinite(), "the particle keeps its last finite state: " + particle);
        assertTrue(Math.abs(particle.velocity.x) > 1e36f, particle.toString());
        String message = thrown.getMessage();
        assertTrue(message.contains("non-finite") && message.contains("is 0.2 s"), message);
    }

    @Test
    void representativeSceneRunsAMillionStepsWithoutNaN() {
        // Gravity + linear drag + thrust at 60 Hz for 4.6 hours of simulated time. The motor
        // ends up pointing straight down: terminal velocity (0, −(m·g + k)/b, 0), where
        // sideways motion decays (its rate b/m − k/(m·|V|) is positive there). The float step
        // stalls within ulp(V)/(2·b·h/m) = 60 ulps (1.9e-6 each at 25.6 m/s) of the fixed
        // point, 4.5e-6 relative: hence 1e-5.
        float m = 1f;
        float b = 0.5f;
        float thrust = 3f;
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(10f, 10f, 0f), m);
        ParticleIntegrator integrator = new ParticleIntegrator(
                new Gravity(), new LinearDrag(b), new Thrust(thrust));

        for (int n = 0; n < 1_000_000; ++n) {
            integrator.step(particle, 1f / 60f);
        }

        assertTrue(particle.isFinite(), particle.toString());
        float terminal = (m * G + thrust) / b;
        assertVectorEquals(new Vector3f(0f, -terminal, 0f), particle.velocity, terminal * 1e-5f);
    }

    /**
     * Step a damped spring (λ = c/m, ω² = k/m, m = 1) 2000 times from 0.01 m off its rest
     * length and tell whether the swing, measured as {@code sqrt(ω²x² + v²)}, has shrunk. A
     * step that overflows counts as growing.
     */
    private static boolean springDecays(double lambda, double omegaSquared, float h) {
        float start = 0.01f * (float) Math.sqrt(omegaSquared);
        try {
            return springSwing(lambda, omegaSquared, h, 2000) < start;
        } catch (IllegalStateException overflow) {
            return false;
        }
    }

    /** The swing sqrt(ω²x² + v²) after the given steps of the spring in springDecays. */
    private static double springSwing(double lambda, double omegaSquared, float h, int steps) {
        // Rest length 10 m: the particle never reaches the anchor, so the force stays linear.
        float rest = 10f;
        Particle particle = new Particle(new Vector3f(rest + 0.01f, 0f, 0f), Vector3f.ZERO, 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(
                new Spring(Vector3f.ZERO, rest, (float) omegaSquared, (float) lambda));
        for (int n = 0; n < steps; ++n) {
            integrator.step(particle, h);
        }
        double x = particle.position.x - rest;
        double v = particle.velocity.x;
        return Math.sqrt(omegaSquared * x * x + v * v);
    }

    /** Velocities x_0..x_steps of a particle under stiff linear drag at b·h/m = ratio. */
    private static float[] stiffDragVelocities(float ratio, int steps) {
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.UNIT_X, MASS);
        ParticleIntegrator integrator = new ParticleIntegrator(new LinearDrag(STIFF_B));
        assertEquals(MASS / STIFF_B, integrator.maxMonotoneStep(particle), 0f);
        assertEquals(2 * MASS / STIFF_B, integrator.maxStableStep(particle), 0f);
        float h = ratio * MASS / STIFF_B;
        float[] velocities = new float[steps + 1];
        velocities[0] = particle.velocity.x;
        for (int n = 1; n <= steps; ++n) {
            integrator.step(particle, h);
            velocities[n] = particle.velocity.x;
            assertEquals(0f, particle.velocity.y, 0f);
            assertEquals(0f, particle.velocity.z, 0f);
        }
        return velocities;
    }

    /** The vertical velocity after falling from rest with linear drag b and gravity. */
    private static float runLinearDragWithGravity(float b, float h, int steps) {
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.ZERO, MASS);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), new LinearDrag(b));
        for (int n = 0; n < steps; ++n) {
            integrator.step(particle, h);
        }
        return particle.velocity.y;
    }

    /** The vertical velocities after 1999 and 2000 steps of a fall from speed v0 (m/s). */
    private static float[] fallWithQuadraticDrag(ParticleIntegrator integrator, float m,
            float h, float v0) {
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(0f, -v0, 0f), m);
        float[] lastTwo = new float[2];
        for (int n = 1; n <= 2000; ++n) {
            integrator.step(particle, h);
            lastTwo[n % 2] = particle.velocity.y;
        }
        return lastTwo;
    }
}

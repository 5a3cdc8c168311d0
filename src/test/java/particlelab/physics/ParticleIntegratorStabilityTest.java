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
 * {@code 1 < b·h/m < 2}, growth beyond 2 (NUMERICS.md, "Stability"). Gravity adds a constant
 * to each step and does not change {@code r}.
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
        // Euler step settles for h < v_t/g and not beyond (NUMERICS.md), the limit the
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

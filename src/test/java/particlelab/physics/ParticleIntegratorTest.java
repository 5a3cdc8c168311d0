package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static particlelab.VectorAssert.assertVectorEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link ParticleIntegrator}: the lecture's Euler step against its exact discrete solutions
 * and against the continuous solutions it converges to (see docs/numerics.md).
 *
 * <p>Tolerances. Each float operation rounds with a relative error of at most EPS/2, where
 * {@link #EPS} = 2^-23 ≈ 1.2e-7. After n steps the rounding in a quantity of size up to M is at
 * most about n·EPS·M (a factor 2 to spare for the few operations per step), so "to round-off"
 * below means within that; the discretisation errors checked against are far larger.
 */
class ParticleIntegratorTest {

    /** Float machine epsilon, 2^-23. */
    private static final double EPS = Math.ulp(1f);
    private static final float G = Gravity.STANDARD_G;
    private static final float STEP_60HZ = 1f / 60f;

    @Test
    void uniformMotionWithNoForceIsExact() {
        // Dyadic step and velocity: every product and sum below is exact in float.
        float h = 1f / 64f;
        Vector3f velocity = new Vector3f(2f, -0.5f, 0.25f);
        Particle particle = new Particle(new Vector3f(1f, 2f, 3f), velocity, 1f);
        ParticleIntegrator integrator = new ParticleIntegrator();

        for (int i = 0; i < 640; ++i) {
            integrator.step(particle, h);
        }

        // 640 steps of 1/64 s are 10 s.
        assertVectorEquals(new Vector3f(21f, -3f, 5.5f), particle.position, 0f);
        assertVectorEquals(velocity, particle.velocity, 0f);
    }

    @Test
    void uniformMotionKeepsTheVelocityBitForBitAtAnyStep() {
        Vector3f velocity = new Vector3f(0.1f, -7.3f, 1e3f);
        Particle particle = new Particle(Vector3f.ZERO, velocity, 3f);
        ParticleIntegrator integrator = new ParticleIntegrator();
        int steps = 600;

        for (int i = 0; i < steps; ++i) {
            integrator.step(particle, STEP_60HZ);
        }

        assertVectorEquals(velocity, particle.velocity, 0f);
        // Position n·h·V to round-off: n·EPS·|P|.
        Vector3f expected = velocity.mult(steps * STEP_60HZ);
        assertVectorEquals(expected, particle.position, (float) (steps * EPS * 1e4));
    }

    @Test
    void stepUsesTheNewVelocityForThePosition() {
        // Semi-implicit Euler from rest: V1 = −g·h, then P1 = h·V1 = −g·h². Forward Euler would
        // leave P1 = 0; the exact solution is −g·h²/2.
        float h = 0.1f;
        Particle particle = new Particle();
        new ParticleIntegrator(new Gravity()).step(particle, h);

        float expectedY = -G * h * h;
        // Two roundings of the product: within 2 EPS relative.
        assertEquals(expectedY, particle.position.y, Math.abs(expectedY) * 2 * EPS);
        assertEquals(-G * h, particle.velocity.y, G * h * EPS);
    }

    @Test
    void gravityFollowsTheExactDiscreteSolutionAtEveryStep() {
        // y_n = n·h·vy − g·h²·n(n+1)/2, x_n = n·h·vx (docs/numerics.md), with the float values of
        // h and g so that only the integrator's own round-off remains.
        float vx = 10f;
        float vy = 10f;
        int steps = 120;
        double h = STEP_60HZ;
        double g = G;
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(vx, vy, 0f), 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());

        for (int n = 1; n <= steps; ++n) {
            integrator.step(particle, STEP_60HZ);

            double t = n * h;
            double y = n * h * vy - g * h * h * n * (n + 1) / 2.0;
            double x = n * h * vx;
            // Round-off after n steps: the position sums n rounded terms (size up to |P|) and
            // takes h·V with V carrying n rounded additions (size up to |V| ≤ vy + g·t):
            // n·EPS·(|P| + t·|V|) covers both.
            double magnitude = Math.abs(y) + Math.abs(x) + t * (vx + vy + g * t);
            double tolerance = n * EPS * magnitude;
            assertEquals(x, particle.position.x, tolerance, "x at step " + n);
            assertEquals(y, particle.position.y, tolerance, "y at step " + n);
            assertEquals(vy - n * h * g, particle.velocity.y, n * EPS * (vy + g * t),
                    "vy at step " + n);
        }
    }

    @Test
    void gravityErrorIsExactlyMinusGHTOverTwoAndHalvesWithTheStep() {
        // The samples lie on the parabola launched with vy − g·h/2, so the error at time t is
        // −g·h·t/2: first order, exactly halved when h halves (docs/numerics.md).
        float vy = 10f;
        double t = 2.0;
        double errorCoarse = gravityErrorAt(t, vy, 1f / 50f);
        double errorFine = gravityErrorAt(t, vy, 1f / 100f);

        // Round-off: 200 steps·EPS·(|y| + t·|V|) < 200·1.2e-7·(6 + 2·20) ≈ 1.1e-3 m, against
        // errors of 0.196 m and 0.098 m.
        double roundOff = 200 * EPS * (6 + 2 * 20);
        assertEquals(-G * (1f / 50f) * t / 2, errorCoarse, roundOff);
        assertEquals(-G * (1f / 100f) * t / 2, errorFine, roundOff);
        // Ratio 2 exactly in exact arithmetic; round-off moves it by at most
        // 2·(roundOff/0.196 + roundOff/0.098) ≈ 0.034.
        assertEquals(2.0, errorCoarse / errorFine, 0.04);
    }

    @Test
    void linearDragFollowsTheExactDiscreteSolution() {
        // No gravity, k = b/m, r = 1 − k·h: V_n = V0·rⁿ and
        // x_n = h·Σ_{i=1..n} V0·rⁱ = V0·r·(1 − rⁿ)/k.
        float b = 1.5f;
        float m = 1.5f;
        float vx = 10f;
        float h = 0.01f;
        int steps = 200;
        double k = (double) b / m;
        double r = 1 - k * h;
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(vx, 0f, 0f), m);
        ParticleIntegrator integrator = new ParticleIntegrator(new LinearDrag(b));

        for (int n = 0; n < steps; ++n) {
            integrator.step(particle, h);
        }

        // Round-off n·EPS·|V0| in V (every step rounds) and n·EPS·(|x| + t·|V0|) in x.
        assertEquals(vx * Math.pow(r, steps), particle.velocity.x, steps * EPS * vx);
        double x = vx * r * (1 - Math.pow(r, steps)) / k;
        assertEquals(x, particle.position.x, steps * EPS * (x + steps * h * vx));
    }

    @Test
    void linearDragConvergesToTheContinuousSolutionAtFirstOrder() {
        // Continuous: x(t) = vx·(1 − e^{−kt})/k. A first-order method's error halves when h
        // halves, up to O(h) corrections: the ratio is 2.006 at h = 0.04 → 0.02 and 2.003 at
        // 0.02 → 0.01 (k = 1/s, t = 2 s, errors 0.29, 0.146, 0.073 m). Round-off after at
        // most 200 steps: n·EPS·(|x| + t·|V|) ≤ 200·1.2e-7·(10 + 20) ≈ 7e-4 m, which moves a
        // ratio by at most 2·(7e-4/0.146 + 7e-4/0.073) ≈ 0.03.
        double e1 = linearDragErrorAt(2.0, 0.04f);
        double e2 = linearDragErrorAt(2.0, 0.02f);
        double e3 = linearDragErrorAt(2.0, 0.01f);

        assertTrue(e1 < 0 && e2 < 0 && e3 < 0, "the Euler path falls short: " + e1);
        assertEquals(2.0, e1 / e2, 0.05);
        assertEquals(2.0, e2 / e3, 0.05);
    }

    @Test
    void thrustWithLinearDragReachesTerminalSpeedThrustOverDrag() {
        // Terminal speed k/b where thrust balances drag (docs/numerics.md); it is also the exact
        // fixed point of the Euler step. Time constant m/b = 2 s; after 40 s the remaining
        // transient is e^{-20} ≈ 2e-9 relative. In float the step stops moving V once h·|a|
        // is under half a unit in the last place of V, that is within ulp(V)/(2·b·h/m) = 60
        // ulps (2.4e-7 each at 2.8 m/s) of the fixed point: 1.4e-5 m/s, 4e-6 relative.
        float thrust = 2f;
        float b = 0.5f;
        Vector3f heading = new Vector3f(1f, 1f, 0f).normalizeLocal();
        Particle particle = new Particle(Vector3f.ZERO, heading.mult(0.1f), 1f);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Thrust(thrust), new LinearDrag(b));

        for (int i = 0; i < 40 * 60; ++i) {
            integrator.step(particle, STEP_60HZ);
        }

        float terminal = thrust / b;
        assertVectorEquals(heading.mult(terminal), particle.velocity, terminal * 1e-5f,
                "velocity: terminal speed along the launch heading");
    }

    @Test
    void quadraticDragFallingReachesTerminalSpeedSqrtMgOverC() {
        // v_t = sqrt(m·g/c), the exact fixed point of the Euler step. Speed approaches it as
        // tanh(g·t/v_t): after 10 s the transient is e^{-2gt/v_t} ≈ 3e-14. The float step
        // stalls within ulp(v)/(2·h·2c·v_t/m) ≈ 10 ulps of v_t (see the thrust test above),
        // 1e-6 relative: 1e-5 is ample. h = 1/60 is far below the limit v_t/g = 0.64 s.
        float m = 2f;
        float c = 0.5f;
        Particle particle = new Particle(new Vector3f(0f, 1000f, 0f), Vector3f.ZERO, m);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(c));

        for (int i = 0; i < 10 * 60; ++i) {
            integrator.step(particle, STEP_60HZ);
        }

        float terminal = (float) Math.sqrt(m * G / c);
        assertVectorEquals(new Vector3f(0f, -terminal, 0f), particle.velocity, terminal * 1e-5f);
    }

    @Test
    void accelerationIsFieldPlusForceOverMass() {
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(3f, -4f, 12f), 2f);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(), new LinearDrag(0.5f), new Thrust(26f));

        Vector3f acceleration = integrator.acceleration(particle, new Vector3f());

        // g + (−0.5·V + 2·V)/2 = g + 0.75·V
        Vector3f expected = new Vector3f(0f, -G, 0f).addLocal(2.25f, -3f, 9f);
        assertVectorEquals(expected, acceleration, 1e-5f);
        assertVectorEquals(new Vector3f(3f, -4f, 12f), particle.velocity, 0f);
    }

    @Test
    void zeroStepChangesNothing() {
        Particle particle = new Particle(Vector3f.UNIT_X, Vector3f.UNIT_Y, 1f);

        new ParticleIntegrator(new Gravity(), new LinearDrag(1f)).step(particle, 0f);

        assertVectorEquals(Vector3f.UNIT_X, particle.position, 0f);
        assertVectorEquals(Vector3f.UNIT_Y, particle.velocity, 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {-1e-3f, Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsStepThatIsNegativeOrNotFinite(float bad) {
        Particle particle = new Particle();
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());

        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> integrator.step(particle, bad));

        String message = thrown.getMessage();
        assertTrue(message.contains("step h") && message.contains(String.valueOf(bad))
                && message.contains(">= 0"), message);
    }

    @Test
    void rejectsNullForcesAndCopiesTheArray() {
        assertThrows(IllegalArgumentException.class, () -> new ParticleIntegrator((Force[]) null));
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new ParticleIntegrator(new Gravity(), null));
        assertTrue(thrown.getMessage().contains("forces[1]"), thrown.getMessage());

        Force gravity = new Gravity();
        Force[] forces = {gravity};
        ParticleIntegrator integrator = new ParticleIntegrator(forces);
        forces[0] = new LinearDrag(1f);
        assertEquals(1, integrator.countForces());
        assertSame(gravity, integrator.getForce(0));
    }

    @Test
    void stepsEveryParticleOfAnArray() {
        Particle[] particles = {new Particle(), new Particle(), new Particle()};
        particles[1].setMass(50f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());

        integrator.step(particles, 0.5f);

        for (Particle particle : particles) {
            assertVectorEquals(new Vector3f(0f, -G * 0.5f, 0f), particle.velocity, 0f);
        }
    }

    @Test
    void describeListsEveryForceOrSaysThereIsNone() {
        assertEquals("no force", new ParticleIntegrator().describe());
        assertEquals("g = (0.0, -9.8, 0.0) m/s², F = -0.9·V",
                new ParticleIntegrator(new Gravity(), new LinearDrag(0.9f)).describe());
    }

    /** Position error y_n − y(t) of a launch straight up at vy under gravity, at time t. */
    private static double gravityErrorAt(double t, float vy, float h) {
        int steps = (int) Math.round(t / h);
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(0f, vy, 0f), 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        for (int i = 0; i < steps; ++i) {
            integrator.step(particle, h);
        }
        double time = steps * (double) h;
        double exact = vy * time - G * time * time / 2;
        return particle.position.y - exact;
    }

    /** Position error x_n − x(t) under linear drag, k = 1/s, vx = 10 m/s, at time t. */
    private static double linearDragErrorAt(double t, float h) {
        float vx = 10f;
        double k = 1.0;
        int steps = (int) Math.round(t / h);
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(vx, 0f, 0f), 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new LinearDrag((float) k));
        for (int i = 0; i < steps; ++i) {
            integrator.step(particle, h);
        }
        double time = steps * (double) h;
        double exact = vx * (1 - Math.exp(-k * time)) / k;
        return particle.position.x - exact;
    }

    /** The named exception, so callers can catch "the step blew up" and nothing else. */
    @Test
    void aNonFiniteStepThrowsNonFiniteStepExceptionAndKeepsTheState() {
        ParticleIntegrator integrator = new ParticleIntegrator(new LinearDrag(10f));
        Particle particle = new Particle(new Vector3f(1f, 2f, 3f),
                new Vector3f(3e38f, 0f, 0f), 1f);
        // h·b/m = 50: V ← (1 − 50)·V overflows at once
        NonFiniteStepException thrown = assertThrows(NonFiniteStepException.class,
                () -> integrator.step(particle, 5f));
        assertTrue(thrown.getMessage().contains("largest stable step"), thrown.getMessage());
        assertVectorEquals(new Vector3f(1f, 2f, 3f), particle.position, 0f);
        assertVectorEquals(new Vector3f(3e38f, 0f, 0f), particle.velocity, 0f);
        particle.velocity.x = Float.NaN;
        NonFiniteStepException nan = assertThrows(NonFiniteStepException.class,
                () -> integrator.step(particle, 1f / 60f));
        assertTrue(nan.getMessage().contains("already non-finite"), nan.getMessage());
    }
}

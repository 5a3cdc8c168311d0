package particlelab.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.lang.management.ManagementFactory;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.accuracy.ClosedForms;
import particlelab.accuracy.OrderFit;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;


class SteppersTest {

    private static final double G = 9.8;
    /** The canonical launch: from the origin at (20, 30) m/s. */
    private static final MotionState LAUNCH = new MotionState(0.0, 0.0, 20.0, 30.0);
    private static final double DURATION_SECONDS = 4.0;
    /** Step sizes 1/15 … 1/480 s: inside every method's asymptotic range for k = 0.5/s. */
    private static final double[] STEPS = {1.0 / 15, 1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240,
        1.0 / 480};

    @ParameterizedTest
    @EnumSource(value = Scheme.class, names = {"FORWARD_EULER", "SEMI_IMPLICIT_EULER",
        "VELOCITY_VERLET", "MIDPOINT", "RUNGE_KUTTA_4"})
    void measuredOrderOnLinearDragIsWithinAFifteenthOfTheory(Scheme scheme) {
        ForceModel forces = ForceModel.perUnitMass(G, 0.5, 0.0, 0.0);
        MotionState exact = ClosedForms.gravityLinearDrag(forces, LAUNCH, DURATION_SECONDS,
                new MotionState());
        double[] errors = new double[STEPS.length];
        for (int i = 0; i < STEPS.length; ++i) {
            errors[i] = runFor(scheme.create(forces), STEPS[i]).positionDistance(exact);
        }
        // The floor excludes round-off only: RK4's smallest error here is about 1e-8 m, the
        // float run's round-off about 1e-5 m against first-order errors above 1e-3 m.
        double measured = OrderFit.slope(STEPS, errors, 1e-10);
        double theory = scheme.theoreticalOrder(forces);
        // The acceptance band: pre-asymptotic terms move a slope fitted over a factor
        // of 32 in h by a few hundredths, well inside 0.15.
        assertEquals(theory, measured, 0.15, scheme + " errors " + Arrays.toString(errors));
    }

    @Test
    void everyMethodAboveFirstOrderIsExactForGravityAlone() {
        ForceModel forces = ForceModel.perUnitMass(G, 0.0, 0.0, 0.0);
        MotionState exact = ClosedForms.gravityLinearDrag(forces, LAUNCH, DURATION_SECONDS,
                new MotionState());
        for (Scheme scheme : new Scheme[] {Scheme.VELOCITY_VERLET, Scheme.MIDPOINT,
            Scheme.RUNGE_KUTTA_4, Scheme.EXACT}) {
            assertEquals(Double.POSITIVE_INFINITY, scheme.theoreticalOrder(forces));
            double error = runFor(scheme.create(forces), 1.0 / 15).positionDistance(exact);
            // Constant acceleration: each of these updates is the exact parabola, so only
            // round-off of ~60 steps on values near 100 m remains (~1e-14 m each).
            assertTrue(error < 1e-11, scheme + " error " + error);
        }
    }

    @Test
    void exactStepMatchesTheClosedFormToRoundOff() {
        for (double k : new double[] {0.0, 1e-4, 0.1, 0.5, 2.0, 50.0}) {
            ForceModel forces = ForceModel.perUnitMass(G, k, 0.0, 0.0);
            MotionState closed = new MotionState();
            MotionState stepped = new MotionState().set(LAUNCH);
            Stepper exact = Scheme.EXACT.create(forces);
            double h = 1.0 / 60;
            for (int n = 1; n <= 240; ++n) {
                exact.step(stepped, h);
                ClosedForms.gravityLinearDrag(forces, LAUNCH, n * h, closed);
                // 1e-12 relative to the size of the numbers: 240 steps add ~240 roundings of
                // 1.1e-16 each, about 3e-14 of |P| + |V|, far inside the bound.
                double scale = 1.0 + Math.abs(closed.position[0]) + Math.abs(closed.position[1]);
                assertEquals(closed.position[0], stepped.position[0], 1e-12 * scale, "x, k=" + k);
                assertEquals(closed.position[1], stepped.position[1], 1e-12 * scale, "y, k=" + k);
                assertEquals(closed.velocity[0], stepped.velocity[0], 1e-12 * scale, "vx, k=" + k);
                assertEquals(closed.velocity[1], stepped.velocity[1], 1e-12 * scale, "vy, k=" + k);
            }
        }
    }

    @Test
    void closedFormIsTheTextbookSolution() {
        // V(t) = V* + (V0 − V*)·e^{−kt}, P(t) = V*·t + (V0 − V*)·(1 − e^{−kt})/k, V* = g/k;
        // well conditioned at k = 0.5, t = 3 (|V*| = 19.6 m/s), so agreement to 1e-12
        double k = 0.5;
        double t = 3.0;
        ForceModel forces = ForceModel.perUnitMass(G, k, 0.0, 0.0);
        MotionState at = ClosedForms.gravityLinearDrag(forces, LAUNCH, t, new MotionState());
        double terminalY = -G / k;
        double decay = Math.exp(-k * t);
        assertEquals(terminalY + (30.0 - terminalY) * decay, at.velocity[1], 1e-12);
        assertEquals(terminalY * t + (30.0 - terminalY) * (1 - decay) / k, at.position[1], 1e-12);
        assertEquals(20.0 * decay, at.velocity[0], 1e-12);
        assertEquals(20.0 * (1 - decay) / k, at.position[0], 1e-12);
    }

    @Test
    void exactStepOfAnyLengthIsTheClosedForm() {
        ForceModel forces = ForceModel.perUnitMass(G, 2.0, 0.0, 0.0);
        MotionState closed = ClosedForms.gravityLinearDrag(forces, LAUNCH, 10.0, new MotionState());
        MotionState stepped = new MotionState().set(LAUNCH);
        // h = 10 s is 5 times the Euler limit m/b... any h is exact
        Scheme.EXACT.create(forces).step(stepped, 10.0);
        assertEquals(closed.position[1], stepped.position[1], 1e-12 * Math.abs(closed.position[1]));
        assertEquals(closed.velocity[1], stepped.velocity[1], 1e-12 * Math.abs(closed.velocity[1]));
    }

    @Test
    void phiFunctionsAreContinuousAcrossTheSeriesSwitch() {
        // At z = 1e-2 the series and the closed form must agree: the closed form loses about
        // 2·eps/z = 2e-14 there, the truncated series less than 1e-20.
        double below = Math.nextDown(1e-2);
        assertEquals(ExactDragStep.phi2(1e-2), ExactDragStep.phi2(below), 1e-13);
        assertEquals(0.5, ExactDragStep.phi2(0.0), 0.0);
        assertEquals(1.0, ExactDragStep.phi1(0.0), 0.0);
        // φ2(1) = e^{-1} exactly
        assertEquals(Math.exp(-1.0), ExactDragStep.phi2(1.0), 1e-15);
    }

    @Test
    void forwardAndSemiImplicitEulerFollowTheirDiscreteSolutions() {
        // docs/numerics.md: SIE gives y_n = n·h·vy − g·h²·n(n+1)/2; forward Euler uses the old
        // V, so y_n = n·h·vy − g·h²·n(n−1)/2. Both land vx·h from the true point, on opposite
        // sides.
        ForceModel forces = ForceModel.perUnitMass(G, 0.0, 0.0, 0.0);
        double h = 1.0 / 64; // a power of two: the double run below is exact up to round-off
        int n = 200;
        MotionState euler = new MotionState().set(LAUNCH);
        Scheme.FORWARD_EULER.create(forces).advance(euler, h, n);
        assertEquals(n * h * 30.0 - G * h * h * n * (n - 1) / 2, euler.position[1], 1e-12);
        MotionState semi = new MotionState().set(LAUNCH);
        Scheme.SEMI_IMPLICIT_EULER.create(forces).advance(semi, h, n);
        // float run (the shared integrator): y ≈ 33 m after 200 steps, float round-off of
        // ~200 steps at ulp(33) = 3.8e-6 stays below 1e-3 m
        assertEquals(n * h * 30.0 - G * h * h * n * (n + 1) / 2, semi.position[1], 1e-3);
    }

    @Test
    void sharedStepperIsTheSharedIntegrator() {
        ForceModel forces = ForceModel.perUnitMass(G, 0.5, 0.01, 3.0);
        Particle particle = new Particle(new Vector3f(0f, 0f, 0f), new Vector3f(20f, 30f, 0f), 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(forces.toForces());
        MotionState state = new MotionState().set(LAUNCH);
        Stepper shared = Scheme.SEMI_IMPLICIT_EULER.create(forces);
        for (int n = 0; n < 100; ++n) {
            integrator.step(particle, 1f / 60f);
            shared.step(state, 1.0 / 60);
        }
        // the same float operations in the same order: bit for bit
        assertEquals(particle.position.x, state.position[0], 0.0);
        assertEquals(particle.position.y, state.position[1], 0.0);
        assertEquals(particle.velocity.y, state.velocity[1], 0.0);
    }

    @Test
    void forceModelMatchesThePhysicsForces() {
        ForceModel forces = ForceModel.perUnitMass(G, 0.5, 0.01, 3.0);
        double[] velocity = {20.0, 30.0, -5.0};
        double[] acceleration = new double[3];
        forces.acceleration(velocity, acceleration);
        Particle particle = new Particle(new Vector3f(), new Vector3f(20f, 30f, -5f), 1f);
        Vector3f floatAcceleration = new ParticleIntegrator(forces.toForces())
                .acceleration(particle, new Vector3f());
        // float against double: |a| ≈ 25 m/s², float keeps ~7 digits, so 1e-5 m/s²
        assertEquals(acceleration[0], floatAcceleration.x, 1e-5);
        assertEquals(acceleration[1], floatAcceleration.y, 1e-5);
        assertEquals(acceleration[2], floatAcceleration.z, 1e-5);
    }

    @Test
    void referenceMatchesThePublishedQuadraticDragState() {
        // docs/numerics.md, quadratic c/m = 0.01 from (20, 30): the state at t = 1
        ForceModel forces = ForceModel.perUnitMass(G, 0.0, 0.01, 0.0);
        MotionState at = ClosedForms.reference(forces, LAUNCH, 1.0, new MotionState());
        // RK4 at h = 1/30720 s: truncation ~1e-18, round-off of 30720 steps ~1e-13
        assertEquals(17.26060623497018, at.position[0], 1e-11);
        assertEquals(21.40920548727494, at.position[1], 1e-11);
        assertEquals(15.18231176296057, at.velocity[0], 1e-11);
        assertEquals(14.09912560377118, at.velocity[1], 1e-11);
    }

    @Test
    void landingTimeMatchesThePublishedFlightTimes() {
        // docs/numerics.md reference table, linear drag from (20, 30): flight time and range
        double[][] table = {{0.1, 5.602104945629903, 85.78223197995789},
            {0.5, 4.53774969651613, 35.86286050472426}, {2.0, 3.558334680938495, 9.99188535048632}};
        for (double[] row : table) {
            ForceModel forces = ForceModel.perUnitMass(G, row[0], 0.0, 0.0);
            double t = ClosedForms.landingTime(forces, LAUNCH);
            // both to full double precision: 1e-12 leaves room for a few ulp of each
            assertEquals(row[1], t, 1e-12);
            MotionState at = ClosedForms.gravityLinearDrag(forces, LAUNCH, t, new MotionState());
            assertEquals(row[2], at.position[0], 1e-11);
        }
    }

    @ParameterizedTest
    @EnumSource(Scheme.class)
    void stepperAllocatesNothingPerStep(Scheme scheme) {
        ForceModel forces = ForceModel.perUnitMass(G, 0.5, 0.0, 0.0);
        Stepper stepper = scheme.create(forces);
        MotionState state = new MotionState().set(LAUNCH);
        stepper.advance(state, 1.0 / 60, 20_000); // let the JIT settle
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long before = threads.getCurrentThreadAllocatedBytes();
        for (int n = 0; n < 10_000; ++n) {
            stepper.step(state, 1.0 / 60);
        }
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;
        // even one 16-byte object per step would be 160 kB; allow the meter's own few bytes
        assertTrue(allocated < 1024, scheme + " allocated " + allocated + " bytes");
    }

    @Test
    void exactStepRefusesScenesWithoutAClosedForm() {
        ForceModel quadratic = ForceModel.perUnitMass(G, 0.0, 0.01, 0.0);
        IllegalArgumentException failure = assertThrows(IllegalArgumentException.class,
                () -> Scheme.EXACT.create(quadratic));
        assertTrue(failure.getMessage().contains("c/m = 0.01"), failure.getMessage());
    }

    @Test
    void forceModelRejectsNegativeDragNamingIt() {
        IllegalArgumentException failure = assertThrows(IllegalArgumentException.class,
                () -> ForceModel.perUnitMass(G, -1.0, 0.0, 0.0));
        assertTrue(failure.getMessage().contains("linear drag b"), failure.getMessage());
        assertTrue(failure.getMessage().contains("-1.0"), failure.getMessage());
    }

    private static MotionState runFor(Stepper stepper, double h) {
        MotionState state = new MotionState().set(LAUNCH);
        stepper.advance(state, h, (int) Math.round(DURATION_SECONDS / h));
        return state;
    }
}

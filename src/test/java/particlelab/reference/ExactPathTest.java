package particlelab.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.accuracy.ClosedForms;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;


/**
 * The exact path a demo draws as a particle's ghost: the closed form where one exists, RK4
 * otherwise, with its apex and landing found inside the step.
 */
class ExactPathTest {

    private static final float H = 1f / 60f;
    private static final Vector3f ORIGIN = new Vector3f();
    private static final Vector3f LAUNCH = new Vector3f(20f, 30f, 0f);

    @Test
    void gravityAndLinearDragFollowTheClosedFormAtEveryStep() {
        float b = 0.1f;
        ExactPath path = new ExactPath(new ParticleIntegrator(new Gravity(), new LinearDrag(b)));
        assertTrue(path.hasClosedForm());
        path.start(ORIGIN, LAUNCH, 1f, false);
        ForceModel model = ForceModel.perUnitMass(Gravity.STANDARD_G, b, 0.0, 0.0);
        MotionState launch = new MotionState(0.0, 0.0, 20.0, 30.0);
        MotionState expected = new MotionState();
        for (int n = 1; n <= 300; ++n) {
            path.advance(H);
            ClosedForms.gravityLinearDrag(model, launch, path.getTimeSeconds(), expected);
            // The same formula from the launch every time: only double round-off of a few
            // operations on values below 100 differs, far below 1e-12 m.
            assertEquals(expected.position[0], path.getPosition(0), 1e-12);
            assertEquals(expected.position[1], path.getPosition(1), 1e-12);
            assertEquals(expected.velocity[1], path.getVelocity(1), 1e-12);
        }
        // Gravity is the float 9.8f, so the time steps are h = 1/60f summed in double.
        assertEquals(300 * (double) H, path.getTimeSeconds(), 1e-12);
    }

    @Test
    void apexAndLandingOfLinearDragAreTheClosedFormsToRoundOff() {
        float b = 0.1f;
        ExactPath path = new ExactPath(new ParticleIntegrator(new Gravity(), new LinearDrag(b)));
        path.start(ORIGIN, LAUNCH, 1f, true);
        while (!path.hasLanded()) {
            path.advance(H);
        }
        double g = Gravity.STANDARD_G;
        double k = b;
        // V.y(t) = e^{-kt}·vy0 − g·(1 − e^{-kt})/k is 0 at t = ln(1 + k·vy0/g)/k.
        double apexSeconds = Math.log1p(k * 30.0 / g) / k;
        ForceModel model = ForceModel.perUnitMass(g, k, 0.0, 0.0);
        MotionState launch = new MotionState(0.0, 0.0, 20.0, 30.0);
        MotionState at = ClosedForms.gravityLinearDrag(model, launch, apexSeconds,
                new MotionState());
        // Bisection to 1e-18 of a step leaves the rounding of the closed form: 1e-12 s.
        assertEquals(apexSeconds, path.getApexSeconds(), 1e-12);
        assertEquals(at.position[1], path.getApexHeight(), 1e-10);
        double flight = ClosedForms.landingTime(model, launch);
        assertEquals(flight, path.getLandingSeconds(), 1e-10);
        ClosedForms.gravityLinearDrag(model, launch, flight, at);
        assertEquals(at.position[0], path.getLandingX(), 1e-9);
        // The project's reference values for k = 0.1 exactly; b = 0.1f differs by 1.5e-9.
        assertEquals(5.602104945629903, path.getLandingSeconds(), 1e-6);
        assertEquals(85.78223197995789, path.getLandingX(), 1e-5);
        assertEquals(0.0, path.getPosition(1));
        double landedX = path.getPosition(0);
        path.advance(H);
        assertEquals(landedX, path.getPosition(0), "a landed path stays");
    }

    @Test
    void quadraticDragFollowsTheReferenceValuesThroughRk4() {
        // c/m = 0.01 /m: NUMERICS reference state at t = 1 and landing.
        ExactPath path = new ExactPath(
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.01f)));
        assertFalse(path.hasClosedForm());
        path.start(ORIGIN, LAUNCH, 1f, true);
        for (int n = 0; n < 60; ++n) {
            path.advance(H);
        }
        // The stages' accelerations come in float (relative 6e-8 of |a| ≈ 15 m/s²), so the
        // position may be off by about 6e-8·15·t²/2 ≈ 5e-7 m at t = 1; c = 0.01f adds 2e-10
        // relative. RK4's own error at 960 substeps per second is below 1e-12.
        assertEquals(17.26060623497018, path.getPosition(0), 2e-6);
        assertEquals(21.40920548727494, path.getPosition(1), 2e-6);
        assertEquals(15.18231176296057, path.getVelocity(0), 2e-6);
        assertEquals(14.09912560377118, path.getVelocity(1), 2e-6);
        while (!path.hasLanded()) {
            path.advance(H);
        }
        // Over the 4.9 s flight the float accelerations add up to about 6e-8·15·4.9²/2, 1e-5.
        assertEquals(4.941484669495773, path.getLandingSeconds(), 2e-5);
        assertEquals(62.26446045043191, path.getLandingX(), 2e-4);
    }

    @Test
    void aLongStepFindsTheSameApexAndLandingAsShortOnes() {
        ExactPath fine = new ExactPath(
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.01f)));
        ExactPath coarse = new ExactPath(
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.01f)));
        fine.start(ORIGIN, LAUNCH, 1f, true);
        coarse.start(ORIGIN, LAUNCH, 1f, true);
        while (!fine.hasLanded()) {
            fine.advance(H);
        }
        while (!coarse.hasLanded()) {
            coarse.advance(0.2);
        }
        // Both are RK4 at 960 substeps per second; only how the substeps fall differs.
        assertEquals(fine.getApexSeconds(), coarse.getApexSeconds(), 1e-6);
        assertEquals(fine.getApexHeight(), coarse.getApexHeight(), 1e-6);
        assertEquals(fine.getLandingSeconds(), coarse.getLandingSeconds(), 1e-6);
        assertEquals(fine.getLandingX(), coarse.getLandingX(), 1e-5);
    }

    @Test
    void changingTheDragLiveStartsTheClosedFormAgainFromTheState() {
        LinearDrag drag = new LinearDrag(0f);
        ExactPath path = new ExactPath(new ParticleIntegrator(new Gravity(), drag));
        path.start(ORIGIN, LAUNCH, 1f, false);
        path.advance(0.5);
        MotionState middle = new MotionState(path.getPosition(0), path.getPosition(1),
                path.getVelocity(0), path.getVelocity(1));
        drag.setCoefficient(0.5f);
        path.advance(0.5);
        MotionState expected = ClosedForms.gravityLinearDrag(
                ForceModel.perUnitMass(Gravity.STANDARD_G, 0.5, 0.0, 0.0), middle, 0.5,
                new MotionState());
        assertEquals(expected.position[0], path.getPosition(0), 1e-12);
        assertEquals(expected.position[1], path.getPosition(1), 1e-12);
    }

    @Test
    void advancingAllocatesNothing() {
        ExactPath exact = new ExactPath(new ParticleIntegrator(new Gravity(), new LinearDrag(1f)));
        ExactPath rk4 = new ExactPath(
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.01f)));
        Allocations.assertAllocatesNothing("1000 advances with landings", () -> {
            exact.start(ORIGIN, LAUNCH, 1f, true);
            rk4.start(ORIGIN, LAUNCH, 1f, true);
            for (int n = 0; n < 1000; ++n) {
                exact.advance(H);
                rk4.advance(H);
            }
        });
    }
}

package particlelab.rigid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;

/**
 * The accumulated (unwrapped) spin angle against the orientation methods' known turn per step
 * for constant ω, at the rotation demo's largest |ω|h = 12 rad/s · 1/15 s = 0.8 (Up Up Right
 * Right), where the wrapped angle error ranks the methods the wrong way round.
 *
 * <p>The turn per step, with {@code θ = |ω|h} and u the unit spin axis:
 * <ul>
 * <li>exact: θ.</li>
 * <li>polar: on the plane across u, {@code I + h·[ω]×} is {@code [[1, −θ], [θ, 1]]}, which is
 * {@code √(1 + θ²)} times the rotation by {@code atan θ}; along u it is 1. Its polar factor is
 * the rotation by {@code atan θ} about u, and for a rotation R
 * {@code polar((I + h[ω]×)·R) = polar(I + h[ω]×)·R}: each step turns {@code atan θ}.</li>
 * <li>quaternion: {@code q ← (1, (h/2)·ω)·q / |…|}, and {@code (1, (θ/2)·u)} normalised is
 * {@code (cos φ, sin φ·u)} with {@code tan φ = θ/2}, the rotation by {@code 2φ}: each step
 * turns {@code 2·atan(θ/2)}.</li>
 * <li>plain Euler: its nearest rotation is the polar box's, so it turns {@code atan θ}.</li>
 * </ul>
 * Float round-off: each step rounds R's entries at {@code EPS/2} relative, which moves the
 * turn read from consecutive matrices by a few EPS; the increments telescope, so after n steps
 * the accumulated angle is off by at most about {@code n·EPS} per step's own error. The
 * tolerance {@code 10·n·EPS} (7e-5 rad after 60 steps) is ten times that.
 */
class SpinAngleTest {

    private static final double EPS = Math.ulp(1f);
    /** The demo's spin axis (tilted off every body axis) at its fastest, 12 rad/s. */
    private static final Vector3f OMEGA = new Vector3f(0.2f, 0.4f, 0.9f).normalizeLocal()
            .multLocal(12f);
    /** The demo's longest step, 1/15 s: |ω|h = 0.8. */
    private static final float H = 1f / 15f;
    private static final int STEPS = 60;

    /** θ = |ω|h of the float ω and h actually stepped. */
    private static double theta() {
        return OMEGA.length() * (double) H;
    }

    /**
     * Step R from the identity with one method, tracking the spin angle.
     *
     * @return {accumulated angle, wrapped angle error, largest wrapped error seen} (rad)
     */
    private static double[] spin(Orientation method, int steps) {
        RotationIntegrator integrator = new RotationIntegrator(method, Angular.EXPLICIT, true);
        RotationCheck check = new RotationCheck();
        SpinAngle angle = new SpinAngle();
        Matrix3f r = new Matrix3f();
        Matrix3f exact = new Matrix3f();
        angle.start(r, OMEGA);
        double largest = 0.0;
        double error = 0.0;
        for (int n = 1; n <= steps; ++n) {
            integrator.stepOrientation(r, OMEGA, H);
            angle.add(r);
            check.exactRotation(new Matrix3f(), OMEGA, n * (double) H, exact);
            error = check.angleError(r, exact);
            largest = Math.max(largest, error);
        }
        return new double[] {angle.getAccumulatedRadians(), error, largest};
    }

    @Test
    void eachMethodAccumulatesItsClosedFormTurnPerStepUnwrapped() {
        double theta = theta();
        assertEquals(0.8, theta, 1e-6, "the demo's largest |ω|h");
        double tolerance = 10.0 * STEPS * EPS;
        assertEquals(STEPS * theta, spin(Orientation.EXACT, STEPS)[0], tolerance);
        assertEquals(STEPS * Math.atan(theta), spin(Orientation.POLAR, STEPS)[0], tolerance);
        assertEquals(STEPS * 2.0 * Math.atan(theta / 2.0),
                spin(Orientation.QUATERNION, STEPS)[0], tolerance);
        // 48 rad: far past one turn, so nothing wrapped.
        assertTrue(spin(Orientation.EXACT, STEPS)[0] > 7.0 * Math.PI);
    }

    /**
     * Plain Euler grows by 1.64 in det per step here (no restart in this test: 20 steps reach
     * det 2e4, entries about 140, well inside float); its nearest rotation turns as polar's.
     */
    @Test
    void plainEulerTurnsAsItsNearestRotationThePolarBox() {
        int steps = 20;
        assertEquals(steps * Math.atan(theta()), spin(Orientation.EULER, steps)[0],
                10.0 * steps * EPS * Math.pow(1.0 + theta() * theta(), steps / 2.0));
    }

    /**
     * The audit's case: after 60 steps at |ω|h = 0.8 the quaternion lags 60·(θ − 2·atan(θ/2))
     * = 2.34 rad (134°) and polar 60·(θ − atan θ) = 7.52 rad (431°). The wrapped distance
     * reads polar's as 431° − 360° = 71°, so it ranks the quaternion worse; the accumulated
     * lag ranks them right. The wrapped distance never exceeds 180°.
     */
    @Test
    void accumulatedLagRanksTheQuaternionAheadOfPolarWhereTheWrappedAngleDoesNot() {
        double theta = theta();
        double[] polar = spin(Orientation.POLAR, STEPS);
        double[] quaternion = spin(Orientation.QUATERNION, STEPS);
        SpinAngle lag = new SpinAngle();
        double exact = STEPS * theta;
        double polarLag = exact - polar[0];
        double quaternionLag = exact - quaternion[0];
        assertEquals(STEPS * (theta - Math.atan(theta)), polarLag, 10.0 * STEPS * EPS);
        assertEquals(STEPS * (theta - 2.0 * Math.atan(theta / 2.0)), quaternionLag,
                10.0 * STEPS * EPS);
        assertTrue(quaternionLag < polarLag, quaternionLag + " vs " + polarLag);
        assertTrue(polarLag > 2.0 * Math.PI, "polar has lagged more than a turn");
        // The wrapped distances are the lags folded into 0..π: polar 7.52 − 2π = 1.24 rad.
        assertEquals(polarLag - 2.0 * Math.PI, polar[1], 1e-4);
        assertEquals(quaternionLag, quaternion[1], 1e-4);
        assertTrue(quaternion[1] > polar[1], "the wrapped distance ranks them the wrong way");
        assertTrue(polar[2] <= Math.PI && quaternion[2] <= Math.PI, "wrapped at most 180°");
        lag.start(new Matrix3f(), OMEGA);
        assertEquals(exact, lag.lagRadians(exact), 0.0, "nothing accumulated yet");
    }

    @Test
    void zeroSpinAccumulatesNothingAndBadInputIsRefused() {
        SpinAngle angle = new SpinAngle();
        angle.start(new Matrix3f(), new Vector3f());
        Matrix3f turned = new Matrix3f();
        turned.fromAngleNormalAxis(0.5f, Vector3f.UNIT_Z);
        assertEquals(0.0, angle.add(turned), 0.0);
        assertEquals(0.0, angle.getAccumulatedRadians(), 0.0);
        IllegalArgumentException nan = assertThrows(IllegalArgumentException.class,
                () -> angle.start(new Matrix3f(), new Vector3f(Float.NaN, 0f, 0f)));
        assertTrue(nan.getMessage().contains("omega"), nan.getMessage());
        Matrix3f mirror = new Matrix3f();
        mirror.set(0, 0, -1f);
        IllegalArgumentException flipped = assertThrows(IllegalArgumentException.class,
                () -> angle.add(mirror));
        assertTrue(flipped.getMessage().contains("det > 0"), flipped.getMessage());
    }

    @Test
    void addingAStepAllocatesNothing() {
        SpinAngle angle = new SpinAngle();
        RotationIntegrator integrator =
                new RotationIntegrator(Orientation.POLAR, Angular.EXPLICIT, true);
        Matrix3f r = new Matrix3f();
        angle.start(r, OMEGA);
        Allocations.assertAllocatesNothing("1000 steps tracked", () -> {
            for (int i = 0; i < 1000; ++i) {
                integrator.stepOrientation(r, OMEGA, H);
                angle.add(r);
            }
        });
        assertTrue(angle.getAccumulatedRadians() > 0.0);
    }
}

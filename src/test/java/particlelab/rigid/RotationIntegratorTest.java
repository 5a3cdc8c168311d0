package particlelab.rigid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.Allocations;
import particlelab.physics.NonFiniteStepException;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;

/**
 * The orientation methods against their known discrete solutions for constant ω, and their
 * orders. Float round-off: every step rounds each entry of R once (relative {@code EPS/2},
 * {@code EPS = 2⁻²³}), so after n steps R is off its double-precision value by at most about
 * {@code n·EPS} in each entry; the tolerances below are small multiples of that.
 */
class RotationIntegratorTest {

    private static final double EPS = Math.ulp(1f);
    /** One turn per second about the diagonal, the case: |ω| = 2π rad/s. */
    private static final Vector3f DIAGONAL = new Vector3f(1f, 1f, 1f).normalizeLocal()
            .multLocal((float) (2.0 * Math.PI));

    private final RotationCheck check = new RotationCheck();

    /** Step R from the identity n times with constant ω. */
    private static Matrix3f spin(Orientation method, Vector3f omega, float h, int steps) {
        RotationIntegrator integrator = new RotationIntegrator(method, Angular.EXPLICIT, true);
        Matrix3f r = new Matrix3f();
        for (int i = 0; i < steps; ++i) {
            integrator.stepOrientation(r, omega, h);
        }
        return r;
    }

    /** The angle error after n steps of h against the exact rotation. */
    private double angleError(Orientation method, Vector3f omega, float h, int steps) {
        Matrix3f r = spin(method, omega, h, steps);
        Matrix3f exact = check.exactRotation(new Matrix3f(), omega, steps * (double) h,
                new Matrix3f());
        return check.angleError(r, exact);
    }

    @Test
    void plainMatrixEulerGrowsTheDeterminantByOnePlusOmegaHSquaredEachStep() {
        float h = 1f / 60f;
        double growth = 1.0 + Math.pow(DIAGONAL.length() * (double) h, 2);
        RotationIntegrator euler = new RotationIntegrator();
        Matrix3f r = new Matrix3f();
        for (int n = 1; n <= 60; ++n) {
            euler.stepOrientation(r, DIAGONAL, h);
            // det is a sum of products of three entries, each off by about n·EPS relative.
            assertEquals(Math.pow(growth, n), check.determinant(r),
                    3.0 * n * EPS * Math.pow(growth, n), "det after " + n + " steps");
        }
        // 1 s at 1 rev/s and 60 Hz: det 1.924 (to the printed digits)
        assertEquals(1.924, check.determinant(r), 5e-4);
        assertTrue(check.orthogonalityError(r) > 1.0, "visibly not a rotation");
    }

    @Test
    void polarReorthonormalisationLagsOmegaHMinusAtanOmegaHPerStep() {
        for (float h : new float[] {1f / 15f, 1f / 60f}) {
            double wh = DIAGONAL.length() * (double) h;
            for (int n : new int[] {1, 10, 60}) {
                double expected = n * (wh - Math.atan(wh));
                // round-off of about n·EPS in each entry, hence in the angle
                assertEquals(expected, angleError(Orientation.POLAR, DIAGONAL, h, n),
                        4.0 * n * EPS, "h = " + h + ", " + n + " steps");
            }
        }
        // Plain Euler turns the same: its nearest rotation is the polar step's.
        assertEquals(angleError(Orientation.POLAR, DIAGONAL, 1f / 60f, 60),
                angleError(Orientation.EULER, DIAGONAL, 1f / 60f, 60), 4.0 * 60 * EPS);
    }

    @Test
    void normalisedQuaternionLagsOmegaHMinusTwoAtanHalfOmegaHPerStep() {
        for (float h : new float[] {1f / 15f, 1f / 60f}) {
            double wh = DIAGONAL.length() * (double) h;
            for (int n : new int[] {1, 10, 60}) {
                double expected = n * (wh - 2.0 * Math.atan(0.5 * wh));
                assertEquals(expected, angleError(Orientation.QUATERNION, DIAGONAL, h, n),
                        4.0 * n * EPS, "h = " + h + ", " + n + " steps");
            }
        }
    }

    @Test
    void exactStepStaysOrthonormalAndOnTheExactAngleToRoundOff() {
        for (float h : new float[] {1f / 15f, 1f / 60f, 1f / 960f}) {
            int n = Math.round(2f / h);
            Matrix3f r = spin(Orientation.EXACT, DIAGONAL, h, n);
            // n roundings of each entry: at most n·EPS per entry, random in sign
            assertEquals(0.0, check.orthogonalityError(r), n * EPS, "h = " + h);
            assertEquals(1.0, check.determinant(r), n * EPS, "h = " + h);
            assertEquals(0.0, angleError(Orientation.EXACT, DIAGONAL, h, n), n * EPS,
                    "h = " + h);
        }
    }

    @Test
    void gramSchmidtIsFirstOrderOffAxisPolarAndQuaternionSecondOrder() {
        // Errors after 1 s at 1 rev/s about the diagonal (measured while writing this:
        // Gram–Schmidt 0.195, 0.0966, 0.0479; polar 0.0228, 0.00573, 0.00143; quaternion
        // 0.00573, 0.00143, 0.000358 at h = 1/60, 1/120, 1/240). Halving h must halve the
        // first and quarter the others, within 5 % (the next term of each error is a
        // factor ωh ≈ 0.1 smaller; round-off is below 1e-4 of the smallest error).
        int[] rates = {60, 120, 240};
        for (int i = 0; i + 1 < rates.length; ++i) {
            float coarse = 1f / rates[i];
            float fine = 1f / rates[i + 1];
            double gramSchmidt = angleError(Orientation.GRAM_SCHMIDT, DIAGONAL, coarse,
                    rates[i]) / angleError(Orientation.GRAM_SCHMIDT, DIAGONAL, fine,
                    rates[i + 1]);
            double polar = angleError(Orientation.POLAR, DIAGONAL, coarse, rates[i])
                    / angleError(Orientation.POLAR, DIAGONAL, fine, rates[i + 1]);
            double quaternion = angleError(Orientation.QUATERNION, DIAGONAL, coarse, rates[i])
                    / angleError(Orientation.QUATERNION, DIAGONAL, fine, rates[i + 1]);
            assertEquals(2.0, gramSchmidt, 0.1, "Gram-Schmidt ratio at 1/" + rates[i]);
            assertEquals(4.0, polar, 0.2, "polar ratio at 1/" + rates[i]);
            assertEquals(4.0, quaternion, 0.2, "quaternion ratio at 1/" + rates[i]);
        }
    }

    @Test
    void gramSchmidtAboutABodyAxisTurnsAsThePolarCureDoes() {
        // About a column's own axis the Euler step only scales the other two columns, which
        // Gram–Schmidt then normalises: the same atan(ωh) per step, second order.
        Vector3f aboutY = new Vector3f(0f, (float) (2.0 * Math.PI), 0f);
        assertEquals(angleError(Orientation.POLAR, aboutY, 1f / 60f, 60),
                angleError(Orientation.GRAM_SCHMIDT, aboutY, 1f / 60f, 60), 4.0 * 60 * EPS);
    }

    @Test
    void constantTorqueAboutAPrincipalAxisFollowsTheDiscreteParabolaOfTheAngle() {
        // θ(t) = θ0 + ω0·t + ½·α·t², α = τ/C. The semi-implicit order (ω first, then R with
        // the new ω) turns θ_n = n·h·ω0 + α·h²·n(n+1)/2 = θ(t) + ½·α·h·t: the particle step's
        // offset under gravity, first order in h. The exact orientation step adds no error.
        float h = 1f / 60f;
        float omega0 = 0.5f;
        float torque = 3f;
        Inertia box = Inertia.box(2f, 1f, 0.5f, 0.25f);
        double alpha = torque / (double) box.getMoment(2);
        RigidBody body = new RigidBody(2f, box);
        body.setAngularVelocity(new Vector3f(0f, 0f, omega0));
        body.setTorque(new Vector3f(0f, 0f, torque));
        RotationIntegrator integrator =
                new RotationIntegrator(Orientation.EXACT, Angular.EXPLICIT, true);
        Matrix3f expected = new Matrix3f();
        Vector3f angle = new Vector3f();
        int steps = 60;
        for (int n = 1; n <= steps; ++n) {
            integrator.step(body, h);
            double t = n * (double) h;
            double continuous = omega0 * t + 0.5 * alpha * t * t;
            double discrete = continuous + 0.5 * alpha * h * t;
            angle.set(0f, 0f, (float) discrete);
            check.exactRotation(new Matrix3f(), angle, 1.0, expected);
            // ω: n float additions, each rounding within EPS·|ω|; θ sums them, and R's
            // entries round once a step: n·EPS·(|ω|·t + 1) bounds both, with room.
            double roundOff = 4.0 * n * EPS * (Math.abs(body.angularVelocity.z) * t + 1.0);
            assertEquals(omega0 + alpha * t, body.angularVelocity.z, roundOff);
            assertEquals(0.0, check.angleError(body.orientation, expected), roundOff,
                    "step " + n);
        }
        // ...and that offset is really there: 1 s off the continuous angle by ½·α·h·t.
        angle.set(0f, 0f, (float) (omega0 + 0.5 * alpha));
        check.exactRotation(new Matrix3f(), angle, 1.0, expected);
        assertEquals(0.5 * alpha * h, check.angleError(body.orientation, expected), 1e-4);
    }

    @ParameterizedTest
    @EnumSource(Orientation.class)
    void stepAllocatesNothing(Orientation method) {
        RigidBody body = new RigidBody(1f, Inertia.of(1f, 2f, 3f));
        body.setAngularVelocity(new Vector3f(0.1f, 2f, 0.1f));
        body.setTorque(new Vector3f(0f, 0f, 0.01f));
        RotationIntegrator explicit = new RotationIntegrator(method, Angular.EXPLICIT, true);
        RotationIntegrator midpoint =
                new RotationIntegrator(method, Angular.IMPLICIT_MIDPOINT, true);
        Matrix3f drift = new Matrix3f();
        Allocations.assertAllocatesNothing("1000 " + method + " steps", () -> {
            for (int i = 0; i < 1000; ++i) {
                explicit.step(body, 1e-4f);
                midpoint.step(body, 1e-4f);
                explicit.stepOrientation(drift, body.angularVelocity, 1e-4f);
            }
        });
    }

    @Test
    void badStepsAndMethodsAreRefused() {
        RotationIntegrator integrator = new RotationIntegrator();
        RigidBody body = new RigidBody(1f, Inertia.of(1f, 1f, 1f));
        assertThrows(IllegalArgumentException.class, () -> integrator.step(body, -1f));
        assertThrows(IllegalArgumentException.class, () -> integrator.step(body, Float.NaN));
        assertThrows(IllegalArgumentException.class,
                () -> integrator.step(body, Float.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> integrator.stepOrientation(
                new Matrix3f(), new Vector3f(Float.NaN, 0f, 0f), 0.1f));
        assertThrows(IllegalArgumentException.class,
                () -> new RotationIntegrator(null, Angular.EXPLICIT, true));
        assertThrows(IllegalArgumentException.class,
                () -> new RotationIntegrator(Orientation.EXACT, null, true));
    }

    @Test
    void anOrientationThatWouldOverflowThrowsAndKeepsTheMatrix() {
        Matrix3f r = new Matrix3f();
        r.multLocal(1e38f);
        Matrix3f before = r.clone();
        RotationIntegrator euler = new RotationIntegrator();
        // R + h·[ω]×·R with entries 1e38 and h·|ω| = 1e4 overflows the float range.
        assertThrows(NonFiniteStepException.class,
                () -> euler.stepOrientation(r, new Vector3f(1e4f, 0f, 0f), 1f));
        assertEquals(before, r);
    }
}

package particlelab.rigid;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.util.Arrays;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Validate;

/**
 * The rotation counterpart of the shared particle integrator: one step turns a
 * {@link RigidBody}'s angular velocity and orientation, in the same semi-implicit order as the
 * particle step (velocity first, then position with the new velocity):
 *
 * <pre>
 *   angular velocity, Euler's equations in the body frame (ω_b = Rᵀ·ω, τ_b = Rᵀ·τ):
 *       I·ω̇_b = τ_b − ω_b × (I·ω_b)               (the second term: gyroscopic, switchable)
 *       ω ← ω + R·Δω_b                            (Δω_b by the {@link Angular} method)
 *   then the orientation, with the NEW ω:
 *       Ṙ = [ω]×·R                                (by the {@link Orientation} method)
 * </pre>
 *
 * Only the change {@code Δω_b} is carried back through R, so a body whose ω does not change
 * (a sphere, or no gyroscopic term and no torque) keeps ω exactly even while the plain matrix
 * step lets R drift; an asymmetric body under that step sees the drift in {@code Rᵀ·ω} too,
 * which is one more reason for a cure.
 *
 * <p>The sensitive arithmetic is done in double and rounded into the body's float state once per
 * step. Nothing is written unless the whole result is finite. Each integrator owns scratch
 * arrays, so it is not thread-safe and {@link #step} allocates nothing.
 */
public final class RotationIntegrator {

    /** How the orientation R follows {@code Ṙ = [ω]×·R} over one step. */
    public enum Orientation {
        /**
         * The lecture's Euler step on the matrix, {@code R ← R + h·[ω]×·R}, with no cure: for
         * constant ω, det R grows by {@code 1 + (|ω|h)²} every step and the columns across ω
         * stretch by the square root of that; the body grows and shears.
         */
        EULER,
        /**
         * The Euler step, then Gram–Schmidt on the columns (x kept in direction, y made
         * orthogonal to it, z = x × y): a rotation again, but the cure favours the x axis, so
         * off that axis it is only first order in h.
         */
        GRAM_SCHMIDT,
        /**
         * The Euler step, then the nearest rotation (the polar factor, by Newton's iteration
         * to round-off): for constant ω it turns by {@code atan(|ω|h)} per step, lagging
         * {@code |ω|h − atan(|ω|h) ≈ (|ω|h)³/3}: second order.
         */
        POLAR,
        /**
         * The quaternion step {@code q ← q + (h/2)·(0, ω)·q}, then normalised: turns by
         * {@code 2·atan(|ω|h/2)} per step, lagging {@code ≈ (|ω|h)³/12}: second order. The
         * body's state stays the matrix: q is read from R (Shepperd's method) and written
         * back each step, which changes nothing but round-off while R is a rotation.
         */
        QUATERNION,
        /**
         * The exact step for the step's ω, {@code R ← exp(h·[ω]×)·R} (Rodrigues' formula):
         * turns by exactly {@code |ω|h} and stays a rotation, to round-off.
         */
        EXACT
    }

    /** How ω follows Euler's equations over one step. */
    public enum Angular {
        /** Explicit (forward) Euler: {@code ω_b ← ω_b + h·I⁻¹·(τ_b − ω_b × I·ω_b)}. */
        EXPLICIT,
        /**
         * Implicit midpoint: {@code I·(ω_b' − ω_b) = h·(τ_b − m × I·m)},
         * {@code m = (ω_b + ω_b')/2}, solved by Newton's iteration to round-off. Torque-free, it
         * keeps the energy {@code ½·ωᵀIω} and {@code |L|} exactly (both are quadratic
         * invariants, which the implicit midpoint rule preserves).
         */
        IMPLICIT_MIDPOINT
    }

    /** Newton's iteration stops once a correction is below this, relative to |ω|. */
    private static final double NEWTON_TOLERANCE = 1e-15;
    /** The most Newton iterations per step. */
    private static final int NEWTON_MAX_ITERATIONS = 50;

    private final Orientation orientation;
    private final Angular angular;
    private final boolean gyroscopic;
    /** Scratch: R (row-major). */
    private final double[] rotation = new double[9];
    /** Scratch: R after the step (row-major). */
    private final double[] next = new double[9];
    /** Scratch: a step matrix, or the polar iteration's work (row-major). */
    private final double[] work = new double[9];
    /** Scratch: ω_b, then the new ω_b (rad/s). */
    private final double[] bodyOmega = new double[3];

    /**
     * Create the integrator the lecture starts with: plain matrix Euler, explicit Euler for
     * ω, the gyroscopic term on.
     */
    public RotationIntegrator() {
        this(Orientation.EULER, Angular.EXPLICIT, true);
    }

    /**
     * Create an integrator.
     *
     * @param orientation how R is stepped (not null)
     * @param angular how ω is stepped (not null)
     * @param gyroscopic true for Euler's equations in full, false to leave out
     *     {@code ω × I·ω} (as Cyclone does: then a torque-free body keeps ω, and an asymmetric
     *     one never shows the intermediate-axis flip)
     */
    public RotationIntegrator(Orientation orientation, Angular angular, boolean gyroscopic) {
        if (orientation == null) {
            throw new IllegalArgumentException("orientation method must be one of "
                    + Arrays.toString(Orientation.values()) + ", but was null");
        }
        if (angular == null) {
            throw new IllegalArgumentException("angular method must be one of "
                    + Arrays.toString(Angular.values()) + ", but was null");
        }
        this.orientation = orientation;
        this.angular = angular;
        this.gyroscopic = gyroscopic;
    }

    /**
     * Return the orientation method.
     *
     * @return the method (not null)
     */
    public Orientation getOrientation() {
        return orientation;
    }

    /**
     * Return the angular-velocity method.
     *
     * @return the method (not null)
     */
    public Angular getAngular() {
        return angular;
    }

    /**
     * Tell whether the gyroscopic term {@code ω × I·ω} is in Euler's equations.
     *
     * @return true if it is
     */
    public boolean isGyroscopic() {
        return gyroscopic;
    }

    /**
     * Advance a body's rotation by one step: ω from the torque, then R with the new ω. The
     * centre is not moved (see {@link RigidBody#step}).
     *
     * @param body the body (not null; its ω and R are modified unless the step fails)
     * @param stepSeconds h (in seconds, finite, &ge;0; 0 does nothing)
     * @throws NonFiniteStepException if the step would leave ω or R non-finite (or singular,
     *     for the polar cure); the body keeps its last state
     */
    public void step(RigidBody body, float stepSeconds) {
        checkStep(stepSeconds);
        if (stepSeconds == 0f) {
            return;
        }
        Mat3.load(body.orientation, rotation);
        double h = stepSeconds;
        Vector3f w = body.angularVelocity;
        Vector3f t = body.torque;
        double[] r = rotation;
        // ω_b = Rᵀ·ω, τ_b = Rᵀ·τ
        double wx = r[0] * w.x + r[3] * w.y + r[6] * w.z;
        double wy = r[1] * w.x + r[4] * w.y + r[7] * w.z;
        double wz = r[2] * w.x + r[5] * w.y + r[8] * w.z;
        double tx = r[0] * t.x + r[3] * t.y + r[6] * t.z;
        double ty = r[1] * t.x + r[4] * t.y + r[7] * t.z;
        double tz = r[2] * t.x + r[5] * t.y + r[8] * t.z;
        Inertia inertia = body.getInertia();
        double a = inertia.getMoment(0);
        double b = inertia.getMoment(1);
        double c = inertia.getMoment(2);
        if (angular == Angular.EXPLICIT || !gyroscopic) {
            // −ω × I·ω = ((B − C)·ωy·ωz, (C − A)·ωz·ωx, (A − B)·ωx·ωy); without it both
            // methods are ω_b + h·I⁻¹·τ_b.
            double g = gyroscopic ? 1.0 : 0.0;
            bodyOmega[0] = wx + h * (tx + g * (b - c) * wy * wz) / a;
            bodyOmega[1] = wy + h * (ty + g * (c - a) * wz * wx) / b;
            bodyOmega[2] = wz + h * (tz + g * (a - b) * wx * wy) / c;
        } else {
            solveMidpoint(wx, wy, wz, tx, ty, tz, a, b, c, h);
        }
        double dx = bodyOmega[0] - wx;
        double dy = bodyOmega[1] - wy;
        double dz = bodyOmega[2] - wz;
        // ω ← ω + R·Δω_b
        double ox = w.x + r[0] * dx + r[1] * dy + r[2] * dz;
        double oy = w.y + r[3] * dx + r[4] * dy + r[5] * dz;
        double oz = w.z + r[6] * dx + r[7] * dy + r[8] * dz;
        float nx = (float) ox;
        float ny = (float) oy;
        float nz = (float) oz;
        if (!(Float.isFinite(nx) && Float.isFinite(ny) && Float.isFinite(nz))) {
            throw nonFinite(body, stepSeconds, "angular velocity");
        }
        // Turn with the new ω as it will be stored.
        if (!stepOrientation(r, nx, ny, nz, h, next)) {
            throw nonFinite(body, stepSeconds, "orientation");
        }
        w.set(nx, ny, nz);
        Mat3.store(next, body.orientation);
    }

    /**
     * Step an orientation alone, with a given ω: what the drift demo does with four
     * matrices side by side. Allocates nothing.
     *
     * @param matrix R (not null, modified unless the step fails)
     * @param omega ω in the world frame (in rad/s, finite, not null, not modified)
     * @param stepSeconds h (in seconds, finite, &ge;0)
     * @throws NonFiniteStepException if the result would not be finite
     */
    public void stepOrientation(Matrix3f matrix, Vector3f omega, float stepSeconds) {
        checkStep(stepSeconds);
        if (matrix == null) {
            throw new IllegalArgumentException("orientation must be a matrix, but was null");
        }
        Validate.finite(omega, "angular velocity (rad/s)");
        Mat3.load(matrix, rotation);
        if (!stepOrientation(rotation, omega.x, omega.y, omega.z, stepSeconds, next)) {
            throw new NonFiniteStepException("the " + orientation + " orientation step h="
                    + stepSeconds + " s would leave R non-finite: R=" + matrix + ", omega="
                    + omega);
        }
        Mat3.store(next, matrix);
    }

    @Override
    public String toString() {
        return "RotationIntegrator[" + orientation + ", " + angular + ", gyroscopic "
                + (gyroscopic ? "on" : "off") + "]";
    }

    /**
     * One orientation step in double.
     *
     * @param r R (row-major, not modified)
     * @param out R after the step (row-major, modified)
     * @return false if the result is not finite (or not usable by the cure)
     */
    private boolean stepOrientation(double[] r, double wx, double wy, double wz, double h,
            double[] out) {
        switch (orientation) {
            case EXACT:
                Mat3.rotation(wx, wy, wz, h, work);
                Mat3.multiply(work, r, out);
                return Mat3.fitsFloat(out);
            case QUATERNION:
                return quaternionStep(r, wx, wy, wz, h, out);
            default:
                break;
        }
        // R ← R + h·[ω]×·R, column by column: c ← c + h·ω × c
        for (int column = 0; column < 3; ++column) {
            double x = r[column];
            double y = r[3 + column];
            double z = r[6 + column];
            out[column] = x + h * (wy * z - wz * y);
            out[3 + column] = y + h * (wz * x - wx * z);
            out[6 + column] = z + h * (wx * y - wy * x);
        }
        if (!Mat3.fitsFloat(out)) {
            return false;
        }
        switch (orientation) {
            case GRAM_SCHMIDT:
                return Mat3.gramSchmidt(out) && Mat3.fitsFloat(out);
            case POLAR:
                return Mat3.nearestRotation(out, work) && Mat3.fitsFloat(out);
            default:
                return true;
        }
    }

    /** q from R, {@code q ← q + (h/2)·(0, ω)·q}, normalised, back to R. */
    private static boolean quaternionStep(double[] r, double wx, double wy, double wz,
            double h, double[] out) {
        // q from R by Shepperd's method: the largest of w, x, y, z first, for accuracy.
        double trace = r[0] + r[4] + r[8];
        double qw;
        double qx;
        double qy;
        double qz;
        if (trace >= r[0] && trace >= r[4] && trace >= r[8]) {
            double s = 2.0 * Math.sqrt(1.0 + trace);
            qw = 0.25 * s;
            qx = (r[7] - r[5]) / s;
            qy = (r[2] - r[6]) / s;
            qz = (r[3] - r[1]) / s;
        } else if (r[0] >= r[4] && r[0] >= r[8]) {
            double s = 2.0 * Math.sqrt(Math.max(0.0, 1.0 + r[0] - r[4] - r[8]));
            qw = (r[7] - r[5]) / s;
            qx = 0.25 * s;
            qy = (r[1] + r[3]) / s;
            qz = (r[2] + r[6]) / s;
        } else if (r[4] >= r[8]) {
            double s = 2.0 * Math.sqrt(Math.max(0.0, 1.0 + r[4] - r[0] - r[8]));
            qw = (r[2] - r[6]) / s;
            qx = (r[1] + r[3]) / s;
            qy = 0.25 * s;
            qz = (r[5] + r[7]) / s;
        } else {
            double s = 2.0 * Math.sqrt(Math.max(0.0, 1.0 + r[8] - r[0] - r[4]));
            qw = (r[3] - r[1]) / s;
            qx = (r[2] + r[6]) / s;
            qy = (r[5] + r[7]) / s;
            qz = 0.25 * s;
        }
        // (0, ω)·(w, v) = (−ω·v, w·ω + ω × v)
        double half = 0.5 * h;
        double nw = qw - half * (wx * qx + wy * qy + wz * qz);
        double nx = qx + half * (qw * wx + wy * qz - wz * qy);
        double ny = qy + half * (qw * wy + wz * qx - wx * qz);
        double nz = qz + half * (qw * wz + wx * qy - wy * qx);
        double norm = Math.sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
        if (!(norm > 0.0) || !Double.isFinite(norm)) {
            return false;
        }
        nw /= norm;
        nx /= norm;
        ny /= norm;
        nz /= norm;
        out[0] = 1.0 - 2.0 * (ny * ny + nz * nz);
        out[1] = 2.0 * (nx * ny - nw * nz);
        out[2] = 2.0 * (nx * nz + nw * ny);
        out[3] = 2.0 * (nx * ny + nw * nz);
        out[4] = 1.0 - 2.0 * (nx * nx + nz * nz);
        out[5] = 2.0 * (ny * nz - nw * nx);
        out[6] = 2.0 * (nx * nz - nw * ny);
        out[7] = 2.0 * (ny * nz + nw * nx);
        out[8] = 1.0 - 2.0 * (nx * nx + ny * ny);
        return Mat3.fitsFloat(out);
    }

    /**
     * Solve the implicit midpoint equation for the new ω_b into {@link #bodyOmega} by Newton's
     * iteration on {@code F(x) = I·(x − ω) − h·τ + h·m × I·m}, {@code m = (ω + x)/2}, whose
     * Jacobian is {@code I + (h/2)·([m]×·I − [I·m]×)}, starting from the explicit step.
     */
    private void solveMidpoint(double wx, double wy, double wz, double tx, double ty,
            double tz, double a, double b, double c, double h) {
        double x = wx + h * (tx + (b - c) * wy * wz) / a;
        double y = wy + h * (ty + (c - a) * wz * wx) / b;
        double z = wz + h * (tz + (a - b) * wx * wy) / c;
        double scale = Math.sqrt(wx * wx + wy * wy + wz * wz) + Math.abs(x) + Math.abs(y)
                + Math.abs(z);
        for (int i = 0; i < NEWTON_MAX_ITERATIONS; ++i) {
            double mx = 0.5 * (wx + x);
            double my = 0.5 * (wy + y);
            double mz = 0.5 * (wz + z);
            double lx = a * mx;
            double ly = b * my;
            double lz = c * mz;
            // F = I·(x − ω) − h·τ + h·(m × L), L = I·m
            double fx = a * (x - wx) - h * tx + h * (my * lz - mz * ly);
            double fy = b * (y - wy) - h * ty + h * (mz * lx - mx * lz);
            double fz = c * (z - wz) - h * tz + h * (mx * ly - my * lx);
            // J = I + (h/2)·([m]×·I − [L]×)
            double k = 0.5 * h;
            double j00 = a;
            double j01 = k * (-mz * b + lz);
            double j02 = k * (my * c - ly);
            double j10 = k * (mz * a - lz);
            double j11 = b;
            double j12 = k * (-mx * c + lx);
            double j20 = k * (-my * a + ly);
            double j21 = k * (mx * b - lx);
            double j22 = c;
            double det = j00 * (j11 * j22 - j12 * j21) - j01 * (j10 * j22 - j12 * j20)
                    + j02 * (j10 * j21 - j11 * j20);
            // δ = J⁻¹·F by Cramer's rule
            double ddx = (fx * (j11 * j22 - j12 * j21) - j01 * (fy * j22 - j12 * fz)
                    + j02 * (fy * j21 - j11 * fz)) / det;
            double ddy = (j00 * (fy * j22 - j12 * fz) - fx * (j10 * j22 - j12 * j20)
                    + j02 * (j10 * fz - fy * j20)) / det;
            double ddz = (j00 * (j11 * fz - fy * j21) - j01 * (j10 * fz - fy * j20)
                    + fx * (j10 * j21 - j11 * j20)) / det;
            x -= ddx;
            y -= ddy;
            z -= ddz;
            double correction = Math.abs(ddx) + Math.abs(ddy) + Math.abs(ddz);
            if (!(correction > NEWTON_TOLERANCE * scale)) {
                // Converged, or NaN: the caller's finiteness check catches the latter.
                break;
            }
        }
        bodyOmega[0] = x;
        bodyOmega[1] = y;
        bodyOmega[2] = z;
    }

    private NonFiniteStepException nonFinite(RigidBody body, float stepSeconds, String what) {
        return new NonFiniteStepException("the rotation step h=" + stepSeconds + " s ("
                + orientation + ", " + angular + ") would leave the " + what + " non-finite: "
                + body);
    }

    private static void checkStep(float stepSeconds) {
        if (!(stepSeconds >= 0f) || stepSeconds == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "step h (s) must be finite and >= 0, but was " + stepSeconds);
        }
    }
}

package particlelab.rigid;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;

/**
 * The angle a stepped orientation has turned about a fixed spin axis, accumulated step by step
 * so that it never wraps, and its lag behind the exact angle {@code |ω|·t}.
 *
 * <p>{@link RotationCheck#angleError} measures the distance between two orientations, which
 * wraps: a box that lags by 200° reads 160°, one that lags by 360° reads 0°. This tracker
 * instead adds, after each step, the angle of the relative rotation {@code D = Rₙ₊₁·Rₙᵀ}
 * between the nearest rotations to consecutive orientations, taken about the spin axis u:
 * <pre>
 *   Δθ = atan2(s·u, c),   s = the axial vector of (D − Dᵀ)/2 = sin θ·a,   c = (tr D − 1)/2
 * </pre>
 * For a step that turns by θ about u itself this is θ exactly, so each step's increment is
 * right as long as one step turns by less than half a turn ({@code |ω|·h < π}); for a step
 * whose axis is tilted off u (Gram–Schmidt) it is the turn about u. The accumulated angle is
 * then the sum, and the lag {@code |ω|·t − θ} grows without bound for a method that lags.
 *
 * <p>For the plain Euler matrix the nearest rotation is used, as for the angle error. Computed
 * in double; each tracker owns scratch arrays, so it is not thread-safe and allocates nothing.
 */
public final class SpinAngle {

    /** The nearest rotation to the last orientation seen (row-major). */
    private final double[] previous = new double[9];
    /** The nearest rotation to the orientation being added (row-major). */
    private final double[] current = new double[9];
    /** Scratch for the polar iteration. */
    private final double[] work = new double[9];
    /** The unit spin axis u (all 0 when ω is 0: then nothing accumulates). */
    private double axisX;
    private double axisY;
    private double axisZ;
    /** The angle accumulated since {@link #start} (in radians). */
    private double accumulatedRadians;

    /** The doubles of {@link #copyState}: the last rotation, the axis, the angle. */
    public static final int STATE_DOUBLES = 9 + 3 + 1;

    /**
     * Create a tracker about the z axis, starting from the identity.
     */
    public SpinAngle() {
        previous[0] = 1.0;
        previous[4] = 1.0;
        previous[8] = 1.0;
        axisZ = 1.0;
    }

    /**
     * Start accumulating from an orientation, about the axis of ω.
     *
     * @param orientation R at the start (not null, det &gt; 0, not modified)
     * @param omega ω, whose direction is the spin axis (in rad/s, finite, not null, not
     *     modified; zero: no axis, and the accumulated angle stays 0)
     * @throws IllegalArgumentException if R is not finite with det &gt; 0, or ω not finite
     */
    public void start(Matrix3f orientation, Vector3f omega) {
        if (omega == null || !Vector3f.isValidVector(omega)) {
            throw new IllegalArgumentException("omega (rad/s) must be finite, but was " + omega);
        }
        nearest(orientation, previous);
        double length = Math.sqrt((double) omega.x * omega.x + (double) omega.y * omega.y
                + (double) omega.z * omega.z);
        double inverse = length > 0.0 ? 1.0 / length : 0.0;
        axisX = omega.x * inverse;
        axisY = omega.y * inverse;
        axisZ = omega.z * inverse;
        accumulatedRadians = 0.0;
    }

    /**
     * Copy the tracker's state (the last rotation seen, the axis, the angle) into an array,
     * for a demo's record of its steps. Allocates nothing.
     *
     * @param storeResult storage ({@link #STATE_DOUBLES} from offset, not null, modified)
     * @param offset where to start
     */
    public void copyState(double[] storeResult, int offset) {
        System.arraycopy(previous, 0, storeResult, offset, 9);
        storeResult[offset + 9] = axisX;
        storeResult[offset + 10] = axisY;
        storeResult[offset + 11] = axisZ;
        storeResult[offset + 12] = accumulatedRadians;
    }

    /**
     * Put back a state {@link #copyState} copied.
     *
     * @param state the state ({@link #STATE_DOUBLES} from offset, not null, not modified)
     * @param offset where it starts
     */
    public void setState(double[] state, int offset) {
        System.arraycopy(state, offset, previous, 0, 9);
        axisX = state[offset + 9];
        axisY = state[offset + 10];
        axisZ = state[offset + 11];
        accumulatedRadians = state[offset + 12];
    }

    /**
     * Add the turn from the last orientation seen to this one (call after each step).
     *
     * @param orientation R after the step (not null, det &gt; 0, not modified)
     * @return the angle this step added (in radians, −π to π)
     * @throws IllegalArgumentException if R is not finite with det &gt; 0
     */
    public double add(Matrix3f orientation) {
        nearest(orientation, current);
        double[] p = previous;
        double[] q = current;
        // D = Q·Pᵀ: D_ij = row i of Q · row j of P.
        double d01 = q[0] * p[3] + q[1] * p[4] + q[2] * p[5];
        double d02 = q[0] * p[6] + q[1] * p[7] + q[2] * p[8];
        double d10 = q[3] * p[0] + q[4] * p[1] + q[5] * p[2];
        double d12 = q[3] * p[6] + q[4] * p[7] + q[5] * p[8];
        double d20 = q[6] * p[0] + q[7] * p[1] + q[8] * p[2];
        double d21 = q[6] * p[3] + q[7] * p[4] + q[8] * p[5];
        double trace = q[0] * p[0] + q[1] * p[1] + q[2] * p[2]
                + q[3] * p[3] + q[4] * p[4] + q[5] * p[5]
                + q[6] * p[6] + q[7] * p[7] + q[8] * p[8];
        // (D − Dᵀ)/2 = sin θ·[a]×, so its axial vector is sin θ·a.
        double sinAlong = 0.5 * ((d21 - d12) * axisX + (d02 - d20) * axisY
                + (d10 - d01) * axisZ);
        double cos = 0.5 * (trace - 1.0);
        double increment = axisX == 0.0 && axisY == 0.0 && axisZ == 0.0 ? 0.0
                : Math.atan2(sinAlong, cos);
        accumulatedRadians += increment;
        System.arraycopy(current, 0, previous, 0, 9);
        return increment;
    }

    /**
     * Return the angle turned about the spin axis since {@link #start}, unwrapped.
     *
     * @return the angle (in radians; grows past 2π)
     */
    public double getAccumulatedRadians() {
        return accumulatedRadians;
    }

    /**
     * Calculate how far the accumulated angle lags an exact one, unwrapped.
     *
     * @param exactRadians the exact angle turned, {@code |ω|·t} for a steady spin (in radians)
     * @return {@code exactRadians − accumulated} (in radians; positive when behind)
     */
    public double lagRadians(double exactRadians) {
        return exactRadians - accumulatedRadians;
    }

    private void nearest(Matrix3f orientation, double[] storeResult) {
        if (orientation == null) {
            throw new IllegalArgumentException("orientation must be a matrix, but was null");
        }
        Mat3.load(orientation, storeResult);
        if (!Mat3.nearestRotation(storeResult, work)) {
            throw new IllegalArgumentException("R must be finite with det > 0, but was "
                    + orientation);
        }
    }
}

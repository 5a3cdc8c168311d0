package particlelab.rigid;

import com.jme3.math.Matrix3f;

/**
 * 3×3 matrix arithmetic in double on row-major arrays of nine ({@code m[3·row + column]}),
 * for the steps whose float round-off would hide what they teach. Every method works on arrays
 * the caller owns, so nothing allocates.
 */
final class Mat3 {

    /** Newton's polar iteration stops once a sweep changes no entry by more than this. */
    private static final double POLAR_TOLERANCE = 1e-15;
    /** The most sweeps of the polar iteration (from det 2 it needs about eight). */
    private static final int POLAR_MAX_SWEEPS = 60;

    private Mat3() {
    }

    /** Copy a jME matrix into a row-major array. */
    static void load(Matrix3f source, double[] target) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                target[3 * row + column] = source.get(row, column);
            }
        }
    }

    /** Round a row-major array into a jME matrix. */
    static void store(double[] source, Matrix3f target) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                target.set(row, column, (float) source[3 * row + column]);
            }
        }
    }

    /** The product {@code a·b} into out (out must be neither a nor b). */
    static void multiply(double[] a, double[] b, double[] out) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                out[3 * row + column] = a[3 * row] * b[column]
                        + a[3 * row + 1] * b[3 + column]
                        + a[3 * row + 2] * b[6 + column];
            }
        }
    }

    /** The determinant. */
    static double determinant(double[] m) {
        return m[0] * (m[4] * m[8] - m[5] * m[7])
                - m[1] * (m[3] * m[8] - m[5] * m[6])
                + m[2] * (m[3] * m[7] - m[4] * m[6]);
    }

    /** Test whether all nine entries are finite and stay finite when rounded to float. */
    static boolean fitsFloat(double[] m) {
        for (int i = 0; i < 9; ++i) {
            // Written so that NaN fails.
            if (!(Math.abs(m[i]) <= Float.MAX_VALUE)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Write the rotation {@code exp(θ·[u]×)} by the angle {@code θ = |w|·t} about {@code w}
     * (Rodrigues): {@code I + sin θ·[u]× + (1 − cos θ)·[u]×²}, written with
     * {@code [w]×} and the stable factors {@code sin θ/θ} and {@code (1 − cos θ)/θ²}.
     *
     * @param wx w's x (in rad/s)
     * @param wy w's y (in rad/s)
     * @param wz w's z (in rad/s)
     * @param seconds t (in seconds)
     * @param out the rotation (row-major, modified)
     */
    static void rotation(double wx, double wy, double wz, double seconds, double[] out) {
        double ax = wx * seconds;
        double ay = wy * seconds;
        double az = wz * seconds;
        double theta = Math.sqrt(ax * ax + ay * ay + az * az);
        double sine;
        double versine;
        if (theta < 1e-4) {
            // Taylor series; the next terms are below 1e-17 here.
            double square = theta * theta;
            sine = 1.0 - square / 6.0;
            versine = 0.5 - square / 24.0;
        } else {
            double half = Math.sin(0.5 * theta) / (0.5 * theta);
            sine = Math.sin(theta) / theta;
            versine = 0.5 * half * half;
        }
        // exp(A) = I + sine·A + versine·A², A = [a]×, A² = a·aᵀ − θ²·I
        double theta2 = theta * theta;
        out[0] = 1.0 + versine * (ax * ax - theta2);
        out[1] = -sine * az + versine * ax * ay;
        out[2] = sine * ay + versine * ax * az;
        out[3] = sine * az + versine * ay * ax;
        out[4] = 1.0 + versine * (ay * ay - theta2);
        out[5] = -sine * ax + versine * ay * az;
        out[6] = -sine * ay + versine * az * ax;
        out[7] = sine * ax + versine * az * ay;
        out[8] = 1.0 + versine * (az * az - theta2);
    }

    /**
     * Replace m by its nearest rotation, the orthogonal factor Q of the polar decomposition
     * {@code m = Q·S} (closest in the Frobenius norm), by Newton's iteration
     * {@code X ← ½·(X + X⁻ᵀ)}, which converges quadratically for every matrix of positive
     * determinant, to round-off.
     *
     * @param m the matrix (row-major, det &gt; 0; modified)
     * @param scratch nine doubles of scratch (modified)
     * @return false if m was singular or not finite (then m is unchanged)
     */
    static boolean nearestRotation(double[] m, double[] scratch) {
        for (int sweep = 0; sweep < POLAR_MAX_SWEEPS; ++sweep) {
            double det = determinant(m);
            if (!(det > 0.0) || !Double.isFinite(det)) {
                return false;
            }
            // X⁻ᵀ = cofactor(X) / det X
            double inverse = 1.0 / det;
            scratch[0] = (m[4] * m[8] - m[5] * m[7]) * inverse;
            scratch[1] = (m[5] * m[6] - m[3] * m[8]) * inverse;
            scratch[2] = (m[3] * m[7] - m[4] * m[6]) * inverse;
            scratch[3] = (m[2] * m[7] - m[1] * m[8]) * inverse;
            scratch[4] = (m[0] * m[8] - m[2] * m[6]) * inverse;
            scratch[5] = (m[1] * m[6] - m[0] * m[7]) * inverse;
            scratch[6] = (m[1] * m[5] - m[2] * m[4]) * inverse;
            scratch[7] = (m[2] * m[3] - m[0] * m[5]) * inverse;
            scratch[8] = (m[0] * m[4] - m[1] * m[3]) * inverse;
            double change = 0.0;
            for (int i = 0; i < 9; ++i) {
                double next = 0.5 * (m[i] + scratch[i]);
                change = Math.max(change, Math.abs(next - m[i]));
                m[i] = next;
            }
            if (change <= POLAR_TOLERANCE) {
                return true;
            }
        }
        return true;
    }

    /**
     * Make m's columns orthonormal by Gram–Schmidt in column order: the first column keeps its
     * direction, the second loses its part along the first, the third is their cross product
     * (so the result is a rotation, det +1).
     *
     * @param m the matrix (row-major, columns independent; modified)
     * @return false if the first two columns were (nearly) parallel (then m is unusable)
     */
    static boolean gramSchmidt(double[] m) {
        double x0 = m[0];
        double y0 = m[3];
        double z0 = m[6];
        double n0 = Math.sqrt(x0 * x0 + y0 * y0 + z0 * z0);
        if (!(n0 > 0.0)) {
            return false;
        }
        x0 /= n0;
        y0 /= n0;
        z0 /= n0;
        double x1 = m[1];
        double y1 = m[4];
        double z1 = m[7];
        double along = x0 * x1 + y0 * y1 + z0 * z1;
        x1 -= along * x0;
        y1 -= along * y0;
        z1 -= along * z0;
        double n1 = Math.sqrt(x1 * x1 + y1 * y1 + z1 * z1);
        if (!(n1 > 0.0)) {
            return false;
        }
        x1 /= n1;
        y1 /= n1;
        z1 /= n1;
        m[0] = x0;
        m[3] = y0;
        m[6] = z0;
        m[1] = x1;
        m[4] = y1;
        m[7] = z1;
        m[2] = y0 * z1 - z0 * y1;
        m[5] = z0 * x1 - x0 * z1;
        m[8] = x0 * y1 - y0 * x1;
        return true;
    }
}

package particlelab.rigid;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;

/**
 * Measures how far an orientation matrix has drifted: from being a rotation at all
 * ({@code det R}, {@code ‖RᵀR − I‖}) and from the exact rotation (the angle between them),
 * for the HUD, the command line and the tests. Computed in double; each checker owns scratch
 * arrays, so it is not thread-safe and allocates nothing.
 */
public final class RotationCheck {

    /** √8: {@code ‖P − Q‖_F = √8·sin(θ/2)} for rotations P, Q an angle θ apart. */
    private static final double ROOT_EIGHT = Math.sqrt(8.0);

    private final double[] matrix = new double[9];
    private final double[] other = new double[9];
    private final double[] work = new double[9];
    private final double[] product = new double[9];

    /**
     * Calculate det R in double.
     *
     * @param r the matrix (not null, not modified)
     * @return the determinant (1 for a rotation)
     */
    public double determinant(Matrix3f r) {
        Mat3.load(r, matrix);
        return Mat3.determinant(matrix);
    }

    /**
     * Calculate the orthogonality error, the Frobenius norm {@code ‖RᵀR − I‖}.
     *
     * @param r the matrix (not null, not modified)
     * @return the error (&ge;0; 0 for a rotation)
     */
    public double orthogonalityError(Matrix3f r) {
        Mat3.load(r, matrix);
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                // (RᵀR)_ij = column i · column j
                double dot = matrix[i] * matrix[j] + matrix[3 + i] * matrix[3 + j]
                        + matrix[6 + i] * matrix[6 + j];
                double entry = dot - (i == j ? 1.0 : 0.0);
                sum += entry * entry;
            }
        }
        return Math.sqrt(sum);
    }

    /**
     * Copy the nearest rotation to R (the polar factor, closest in the Frobenius norm) into
     * storeResult.
     *
     * @param r the matrix (not null, det &gt; 0, not modified)
     * @param storeResult storage for the rotation (not null, modified; may be r)
     * @return storeResult
     */
    public Matrix3f nearestRotation(Matrix3f r, Matrix3f storeResult) {
        Mat3.load(r, matrix);
        if (!Mat3.nearestRotation(matrix, work)) {
            throw new IllegalArgumentException("R must be finite with det > 0, but was " + r);
        }
        Mat3.store(matrix, storeResult);
        return storeResult;
    }

    /**
     * Calculate the angle between the nearest rotation to R and a rotation Q: the angle of
     * the rotation that takes one to the other.
     *
     * @param r the stepped matrix (not null, det &gt; 0, not modified)
     * @param exact Q, a rotation (not null, not modified)
     * @return the angle (in radians, 0 to π)
     */
    public double angleError(Matrix3f r, Matrix3f exact) {
        Mat3.load(r, matrix);
        if (!Mat3.nearestRotation(matrix, work)) {
            throw new IllegalArgumentException("R must be finite with det > 0, but was " + r);
        }
        Mat3.load(exact, other);
        return angleBetween(matrix, other);
    }

    /**
     * Write the exact rotation of a body that spins at constant ω from R0 for t seconds,
     * {@code exp(t·[ω]×)·R0}, in double, rounded once into storeResult.
     *
     * @param start R0 (not null, not modified)
     * @param omega ω in the world frame (in rad/s, not null, not modified)
     * @param seconds t (in seconds, finite)
     * @param storeResult storage for the rotation (not null, modified; may be start)
     * @return storeResult
     */
    public Matrix3f exactRotation(Matrix3f start, Vector3f omega, double seconds,
            Matrix3f storeResult) {
        Mat3.load(start, matrix);
        Mat3.rotation(omega.x, omega.y, omega.z, seconds, work);
        Mat3.multiply(work, matrix, product);
        Mat3.store(product, storeResult);
        return storeResult;
    }

    /**
     * The angle between two rotations, from {@code ‖P − Q‖_F = √8·sin(θ/2)}: accurate for small
     * angles, where the usual {@code acos((tr(PᵀQ) − 1)/2)} loses half the digits.
     */
    private static double angleBetween(double[] p, double[] q) {
        double sum = 0.0;
        for (int i = 0; i < 9; ++i) {
            double d = p[i] - q[i];
            sum += d * d;
        }
        double half = Math.sqrt(sum) / ROOT_EIGHT;
        return 2.0 * Math.asin(Math.min(1.0, half));
    }
}

package particlelab.view;

import com.jme3.math.Matrix3f;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;

/**
 * The orientation a view draws between two physics steps, at {@code α = leftover / h}: the
 * rotation by a slerp of the two states' rotations, {@code q(α) = slerp(q_prev, q, α)} (the
 * shorter way round, at a uniform angular rate), so the drawn box turns smoothly in slow
 * motion instead of jumping once a step.
 *
 * <p>The lecture's matrices need not be rotations: the plain matrix Euler step lets R grow and
 * shear, and the views show that drift. So each matrix is split into its rotation Q (its
 * columns made orthonormal, Gram–Schmidt from the first) and what is left,
 * {@code S = Qᵀ·R} (the identity for a true rotation); the drawn matrix is
 * {@code Q(α)·((1 − α)·S_prev + α·S)}. At α = 0 that is R_prev and at α = 1 it is R, exactly
 * (both are returned as they are), and a drifting matrix is drawn drifting.
 *
 * <p>Allocates nothing: every intermediate is a scratch field.
 */
public final class OrientationBlend {

    private final Quaternion previousRotation = new Quaternion();
    private final Quaternion currentRotation = new Quaternion();
    private final Quaternion drawnRotation = new Quaternion();
    private final Matrix3f previousPure = new Matrix3f();
    private final Matrix3f currentPure = new Matrix3f();
    private final Matrix3f previousRest = new Matrix3f();
    private final Matrix3f currentRest = new Matrix3f();
    private final Matrix3f transposed = new Matrix3f();
    private final Vector3f column0 = new Vector3f();
    private final Vector3f column1 = new Vector3f();
    private final Vector3f column2 = new Vector3f();

    /**
     * Blend two orientations.
     *
     * @param previous R_prev, the state before the last step (not null, not modified)
     * @param current R, the state after it (not null, not modified)
     * @param alpha the blend (0: R_prev, 1 or more: R; clamped to 0 to 1)
     * @param storeResult storage for the drawn matrix (not null, not an argument, modified)
     * @return storeResult
     */
    public Matrix3f blend(Matrix3f previous, Matrix3f current, float alpha,
            Matrix3f storeResult) {
        if (!(alpha > 0f)) {
            return storeResult.set(previous);
        }
        if (alpha >= 1f) {
            return storeResult.set(current);
        }
        rotationOf(previous, previousPure);
        rotationOf(current, currentPure);
        previousRotation.fromRotationMatrix(previousPure).normalizeLocal();
        currentRotation.fromRotationMatrix(currentPure).normalizeLocal();
        drawnRotation.slerp(previousRotation, currentRotation, alpha);
        drawnRotation.normalizeLocal();
        // The rest, S = Qᵀ·R, of each state, blended linearly.
        transposed.set(previousPure).transposeLocal().mult(previous, previousRest);
        transposed.set(currentPure).transposeLocal().mult(current, currentRest);
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                float rest = (1f - alpha) * previousRest.get(row, column)
                        + alpha * currentRest.get(row, column);
                previousRest.set(row, column, rest);
            }
        }
        drawnRotation.toRotationMatrix(transposed);
        return transposed.mult(previousRest, storeResult);
    }

    /**
     * The rotation of a matrix: its columns made orthonormal (the first normalised, the
     * second made perpendicular to it, the third their cross product).
     */
    private void rotationOf(Matrix3f matrix, Matrix3f storeResult) {
        matrix.getColumn(0, column0).normalizeLocal();
        matrix.getColumn(1, column1);
        column1.scaleAdd(-column0.dot(column1), column0, column1).normalizeLocal();
        column0.cross(column1, column2);
        storeResult.setColumn(0, column0);
        storeResult.setColumn(1, column1);
        storeResult.setColumn(2, column2);
    }
}

package particlelab.solutions;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import particlelab.coursework.RotationExercise;

/** Exercise 7, solved: {@code R += h·ω̃·R}, then Gram–Schmidt on the columns. */
public final class Rotation implements RotationExercise {

    private final Matrix3f product = new Matrix3f();
    private final Vector3f first = new Vector3f();
    private final Vector3f second = new Vector3f();
    private final Vector3f third = new Vector3f();

    @Override
    public void step(Matrix3f rotation, Vector3f omega, float stepSeconds) {
        // ω̃·R: column j of the product is ω × (column j of R).
        for (int j = 0; j < 3; ++j) {
            float x = rotation.get(0, j);
            float y = rotation.get(1, j);
            float z = rotation.get(2, j);
            product.set(0, j, omega.y * z - omega.z * y);
            product.set(1, j, omega.z * x - omega.x * z);
            product.set(2, j, omega.x * y - omega.y * x);
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                rotation.set(i, j, rotation.get(i, j) + stepSeconds * product.get(i, j));
            }
        }
    }

    @Override
    public void orthonormalize(Matrix3f rotation) {
        rotation.getColumn(0, first).normalizeLocal();
        rotation.getColumn(1, second);
        second.scaleAdd(-first.dot(second), first, second).normalizeLocal();
        first.cross(second, third);
        rotation.setColumn(0, first);
        rotation.setColumn(1, second);
        rotation.setColumn(2, third);
    }
}

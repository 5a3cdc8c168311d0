package particlelab.solutions;

import com.jme3.math.Vector3f;
import particlelab.coursework.QuadraticDragExercise;

/** Exercise 2, solved: {@code F = −c·|V|·V}, magnitude c·|V|², against the motion. */
public final class QuadraticDrag implements QuadraticDragExercise {

    @Override
    public void addForce(Vector3f velocity, float coefficient, Vector3f netForce) {
        netForce.scaleAdd(-coefficient * velocity.length(), velocity, netForce);
    }
}

package particlelab.coursework;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;

/** Exercise 7, the "Rotation" slide: the matrix Euler step and a cure for its drift. */
public interface RotationExercise {

    /**
     * One Euler step of the orientation: {@code R += h·ω̃·R}, ω̃ the cross-product matrix of ω.
     *
     * @param rotation R (modified)
     * @param omega the angular velocity ω (in rad/s, world frame, not modified)
     * @param stepSeconds h (in seconds, &gt;0)
     */
    void step(Matrix3f rotation, Vector3f omega, float stepSeconds);

    /**
     * Makes a nearly orthonormal matrix a rotation again (Gram–Schmidt or polar).
     *
     * @param rotation the matrix (modified)
     */
    void orthonormalize(Matrix3f rotation);
}

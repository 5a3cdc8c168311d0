package particlelab.exercises;

import com.jme3.math.Vector3f;
import particlelab.coursework.ImpulseExercise;

/**
 * Exercise 5. Slide: "Collision resolution".
 *
 * <p>Two spheres touch. Along the unit normal n between their centres, apply the impulse
 * {@code j = −(1+e)·(v1−v2)·n / (1/m1 + 1/m2)}: {@code v1 += (j/m1)·n}, {@code v2 −= (j/m2)·n}.
 * Only when they approach ({@code (v1−v2)·n < 0} with n pointing from 2 to 1); separating
 * spheres are left alone.
 *
 * <p>Hint: afterwards the momentum is unchanged and the spheres separate at e times the speed
 * at which they approached.
 */
public final class Impulse implements ImpulseExercise {

    @Override
    public void resolve(Vector3f p1, Vector3f v1, float m1, Vector3f p2, Vector3f v2, float m2,
            float restitution) {
        throw new UnsupportedOperationException("not written yet");
    }
}

package particlelab.exercises;

import com.jme3.math.Vector3f;
import particlelab.coursework.SweptPlaneExercise;

/**
 * Exercise 6. Slide: "Tunnelling".
 *
 * <p>The overlap test looks only where the sphere is at the end of the step, so a fast sphere
 * jumps over a thin wall. Write the swept test: with {@code dist = n·p − d} the centre's
 * distance to the plane and {@code n·v < 0}, the sphere touches at
 * {@code t = (r − dist)/(n·v)}. Return t when it lies within the step (0 to h), 0 when the
 * sphere already touches at the start ({@code |dist| < r}), and −1 otherwise.
 *
 * <p>Hint: the test never looks at the end position.
 */
public final class SweptPlane implements SweptPlaneExercise {

    @Override
    public float hitTime(Vector3f position, Vector3f velocity, float radius, Vector3f normal,
            float planeOffset, float stepSeconds) {
        throw new UnsupportedOperationException("not written yet");
    }
}

package particlelab.exercises;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import particlelab.coursework.RotationExercise;

/**
 * Exercise 7. Slide: "Rotation".
 *
 * <p>{@code step}: the orientation's Euler step {@code R += h·ω̃·R}, ω̃ the matrix with
 * {@code ω̃·u = ω × u}. So column j of {@code ω̃·R} is ω crossed with column j of R.
 *
 * <p>{@code orthonormalize}: the step makes R grow (its determinant by {@code 1 + (|ω|h)²} per
 * step). Cure it: Gram–Schmidt on the columns (normalise the first, take the second's part
 * across the first and normalise it, the third is their cross product) or the polar
 * decomposition.
 *
 * <p>Hint: compute the product into a scratch matrix first; R must not change while you read it.
 */
public final class Rotation implements RotationExercise {

    @Override
    public void step(Matrix3f rotation, Vector3f omega, float stepSeconds) {
        throw new UnsupportedOperationException("not written yet");
    }

    @Override
    public void orthonormalize(Matrix3f rotation) {
        throw new UnsupportedOperationException("not written yet");
    }
}

package particlelab.exercises;

import com.jme3.math.Vector3f;
import particlelab.coursework.QuadraticDragExercise;

/**
 * Exercise 2. Slide: "Quadratic drag".
 *
 * <p>Add the quadratic drag force {@code F = −c·|V|·V} to {@code netForce}: its magnitude is
 * {@code c·|V|²} and it points against the motion.
 *
 * <p>The slide writes {@code −c·|V|²·V}. Work out its magnitude: {@code c·|V|³}, so doubling
 * the speed would multiply the drag by eight, and c would need other units. That is not the
 * drag of air.
 *
 * <p>Hint: one {@code scaleAdd} with the factor {@code −c·|V|}; at rest the force is zero
 * (don't divide by |V|).
 */
public final class QuadraticDrag implements QuadraticDragExercise {

    @Override
    public void addForce(Vector3f velocity, float coefficient, Vector3f netForce) {
        throw new UnsupportedOperationException("not written yet");
    }
}

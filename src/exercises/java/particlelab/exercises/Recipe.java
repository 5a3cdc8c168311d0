package particlelab.exercises;

import com.jme3.math.Vector3f;
import particlelab.coursework.RecipeExercise;

/**
 * Exercise 1. Slide: "Simulation recipe".
 *
 * <p>Write one step of the lecture's recipe for one particle: the acceleration
 * {@code a = g + F/m} from gravity, linear drag {@code F = −b·V} and a thrust of T newtons along
 * the velocity (none while the particle is at rest), then {@code V += h·a}, then
 * {@code P += h·V} with the new V.
 *
 * <p>Hint: the order is the lesson. Update V before P. Use {@code scaleAdd} and
 * {@code multLocal} on a scratch field, so the step allocates nothing.
 */
public final class Recipe implements RecipeExercise {

    @Override
    public void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
            float dragNsPerM, float thrustN, float stepSeconds) {
        throw new UnsupportedOperationException("not written yet");
    }
}

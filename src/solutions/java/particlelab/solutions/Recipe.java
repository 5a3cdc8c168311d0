package particlelab.solutions;

import com.jme3.math.Vector3f;
import particlelab.coursework.RecipeExercise;

/** Exercise 1, solved: the recipe, velocity first, then position with the new velocity. */
public final class Recipe implements RecipeExercise {

    private final Vector3f acceleration = new Vector3f();
    private final Vector3f push = new Vector3f();

    @Override
    public void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
            float dragNsPerM, float thrustN, float stepSeconds) {
        // F = −b·V + T·V/|V| (the unit vector along V; at rest V stays zero: no push),
        // then a = g + F/m.
        acceleration.set(velocity).multLocal(-dragNsPerM);
        acceleration.addLocal(push.set(velocity).normalizeLocal().multLocal(thrustN));
        acceleration.divideLocal(massKg).addLocal(gravity);
        velocity.scaleAdd(stepSeconds, acceleration, velocity);   // V += h·a
        position.scaleAdd(stepSeconds, velocity, position);       // P += h·V (the new V)
    }
}

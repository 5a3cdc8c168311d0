package particlelab.coursework;

import com.jme3.math.Vector3f;

/**
 * Exercise 1, the "Simulation recipe" slide: one step of the lecture's semi-implicit Euler step
 * with gravity, linear drag and thrust along the velocity.
 */
public interface RecipeExercise {

    /**
     * Steps one particle by {@code h}: {@code a = g + (−b·V + T·V/|V|)/m}, {@code V += h·a},
     * then {@code P += h·V} with the new V. Thrust acts only while {@code |V| > 0}.
     *
     * @param position the position (in metres, modified)
     * @param velocity the velocity (in m/s, modified)
     * @param massKg the mass (in kg, &gt;0)
     * @param gravity the gravitational acceleration (in m/s², not modified)
     * @param dragNsPerM the linear drag coefficient b (in N·s/m, ≥0)
     * @param thrustN the thrust along the velocity (in N)
     * @param stepSeconds the step h (in seconds, &gt;0)
     */
    void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
            float dragNsPerM, float thrustN, float stepSeconds);
}

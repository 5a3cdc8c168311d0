package particlelab.coursework;

import com.jme3.math.Vector3f;

/** Exercise 2, the "Quadratic drag" slide: the force {@code F = −c·|V|·V}. */
public interface QuadraticDragExercise {

    /**
     * Adds the quadratic drag force to a net force in place.
     *
     * @param velocity the particle's velocity (in m/s, not modified)
     * @param coefficient the drag coefficient c (in N·s²/m², ≥0)
     * @param netForce the net force to add to (in N, modified)
     */
    void addForce(Vector3f velocity, float coefficient, Vector3f netForce);
}

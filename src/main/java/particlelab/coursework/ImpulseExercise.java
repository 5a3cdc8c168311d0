package particlelab.coursework;

import com.jme3.math.Vector3f;

/** Exercise 5, the "Collision resolution" slide: the impulse between two spheres. */
public interface ImpulseExercise {

    /**
     * Applies the impulse with restitution along the line of centres when the spheres approach
     * each other; leaves separating spheres alone.
     *
     * @param p1 the first centre (in metres, not modified)
     * @param v1 the first velocity (in m/s, modified)
     * @param m1 the first mass (in kg, &gt;0)
     * @param p2 the second centre (in metres, not modified)
     * @param v2 the second velocity (in m/s, modified)
     * @param m2 the second mass (in kg, &gt;0)
     * @param restitution e (between 0 and 1)
     */
    void resolve(Vector3f p1, Vector3f v1, float m1, Vector3f p2, Vector3f v2, float m2,
            float restitution);
}

package particlelab.coursework;

import com.jme3.math.Vector3f;

/** Exercise 6, the "Tunnelling" slide: the swept sphere-plane test. */
public interface SweptPlaneExercise {

    /**
     * When, within one step, a sphere moving at constant velocity first touches the plane
     * {@code n·x = d} from its front side.
     *
     * @param position the centre at the start of the step (in metres, not modified)
     * @param velocity the velocity (in m/s, not modified)
     * @param radius the sphere's radius (in metres, &gt;0)
     * @param normal the plane's unit normal n, pointing to its front (not modified)
     * @param planeOffset d (in metres)
     * @param stepSeconds the step h (in seconds, &gt;0)
     * @return the time of first touch (in seconds, between 0 and h), or −1 for no touch
     */
    float hitTime(Vector3f position, Vector3f velocity, float radius, Vector3f normal,
            float planeOffset, float stepSeconds);
}

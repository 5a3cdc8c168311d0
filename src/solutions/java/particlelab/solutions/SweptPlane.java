package particlelab.solutions;

import com.jme3.math.Vector3f;
import particlelab.coursework.SweptPlaneExercise;

/** Exercise 6, solved: {@code t = (r − (n·p − d))/(n·v)} for a sphere moving toward the plane. */
public final class SweptPlane implements SweptPlaneExercise {

    @Override
    public float hitTime(Vector3f position, Vector3f velocity, float radius, Vector3f normal,
            float planeOffset, float stepSeconds) {
        float distance = normal.dot(position) - planeOffset;   // of the centre, signed
        float approach = normal.dot(velocity);
        if (distance < radius) {
            // Already touching at the start (or behind the face): touching now if in front.
            return distance > -radius ? 0f : -1f;
        }
        if (approach >= 0f) {
            return -1f;
        }
        float t = (radius - distance) / approach;
        return t <= stepSeconds ? t : -1f;
    }
}

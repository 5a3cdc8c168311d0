package particlelab.solutions;

import com.jme3.math.Vector3f;
import particlelab.coursework.ImpulseExercise;

/** Exercise 5, solved: {@code j = −(1+e)·(v1−v2)·n / (1/m1 + 1/m2)} along the centres. */
public final class Impulse implements ImpulseExercise {

    private final Vector3f normal = new Vector3f();

    @Override
    public void resolve(Vector3f p1, Vector3f v1, float m1, Vector3f p2, Vector3f v2, float m2,
            float restitution) {
        normal.set(p1).subtractLocal(p2).normalizeLocal();     // n from 2 to 1
        float closing = v1.dot(normal) - v2.dot(normal);       // (v1 − v2)·n
        if (closing >= 0f) {
            return;                                            // separating: no impulse
        }
        float j = -(1f + restitution) * closing / (1f / m1 + 1f / m2);
        v1.scaleAdd(j / m1, normal, v1);
        v2.scaleAdd(-j / m2, normal, v2);
    }
}

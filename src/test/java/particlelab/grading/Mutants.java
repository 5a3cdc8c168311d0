package particlelab.grading;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import particlelab.coursework.AimingExercise;
import particlelab.coursework.ImpulseExercise;
import particlelab.coursework.QuadraticDragExercise;
import particlelab.coursework.RecipeExercise;
import particlelab.coursework.RotationExercise;
import particlelab.coursework.SweptPlaneExercise;
import particlelab.solutions.Rotation;

/** The mistakes students make, each written once, for the grader's checks to catch. */
final class Mutants {

    private Mutants() {
    }

    /** Forward Euler: P moves with the old V, then V changes. */
    static final class PositionFirst implements RecipeExercise {
        private final Vector3f acceleration = new Vector3f();

        @Override
        public void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
                float dragNsPerM, float thrustN, float stepSeconds) {
            acceleration.set(velocity).multLocal(-dragNsPerM);
            float speed = velocity.length();
            if (speed > 0f) {
                acceleration.scaleAdd(thrustN / speed, velocity, acceleration);
            }
            acceleration.divideLocal(massKg).addLocal(gravity);
            position.scaleAdd(stepSeconds, velocity, position);
            velocity.scaleAdd(stepSeconds, acceleration, velocity);
        }
    }

    /** The slide's {@code −c·|V|²·V}. */
    static final class SlideDrag implements QuadraticDragExercise {
        @Override
        public void addForce(Vector3f velocity, float coefficient, Vector3f netForce) {
            netForce.scaleAdd(-coefficient * velocity.lengthSquared(), velocity, netForce);
        }
    }

    /** The continuous aim fired under a coarse step. */
    static final class ContinuousAim implements AimingExercise {
        @Override
        public float continuousVy(float vx, float rangeM, float gravity) {
            return gravity * rangeM / (2f * vx);
        }

        @Override
        public float discreteVy(float vx, float rangeM, float gravity, float stepSeconds) {
            return continuousVy(vx, rangeM, gravity);
        }
    }

    /** The impulse without its {@code (1+e)}: the spheres stick. */
    static final class NoRestitution implements ImpulseExercise {
        private final Vector3f normal = new Vector3f();

        @Override
        public void resolve(Vector3f p1, Vector3f v1, float m1, Vector3f p2, Vector3f v2,
                float m2, float restitution) {
            normal.set(p1).subtractLocal(p2).normalizeLocal();
            float closing = v1.dot(normal) - v2.dot(normal);
            if (closing >= 0f) {
                return;
            }
            float j = -closing / (1f / m1 + 1f / m2);
            v1.scaleAdd(j / m1, normal, v1);
            v2.scaleAdd(-j / m2, normal, v2);
        }
    }

    /** The overlap test: a touch only if the sphere overlaps the face at the step's end. */
    static final class OverlapOnly implements SweptPlaneExercise {
        @Override
        public float hitTime(Vector3f position, Vector3f velocity, float radius,
                Vector3f normal, float planeOffset, float stepSeconds) {
            float distance = normal.dot(position) - planeOffset;
            float approach = normal.dot(velocity);
            float end = distance + stepSeconds * approach;
            if (Math.abs(end) >= radius) {
                return -1f;
            }
            return distance < radius ? 0f : (radius - distance) / approach;
        }
    }

    /** {@code R += h·ω̃}, the R forgotten; its cure is right. */
    static final class NoR implements RotationExercise {
        private final Rotation cure = new Rotation();

        @Override
        public void step(Matrix3f rotation, Vector3f omega, float stepSeconds) {
            rotation.set(0, 1, rotation.get(0, 1) - stepSeconds * omega.z);
            rotation.set(0, 2, rotation.get(0, 2) + stepSeconds * omega.y);
            rotation.set(1, 0, rotation.get(1, 0) + stepSeconds * omega.z);
            rotation.set(1, 2, rotation.get(1, 2) - stepSeconds * omega.x);
            rotation.set(2, 0, rotation.get(2, 0) - stepSeconds * omega.y);
            rotation.set(2, 1, rotation.get(2, 1) + stepSeconds * omega.x);
        }

        @Override
        public void orthonormalize(Matrix3f rotation) {
            cure.orthonormalize(rotation);
        }
    }
}

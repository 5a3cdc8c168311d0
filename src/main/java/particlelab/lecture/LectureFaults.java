package particlelab.lecture;

import com.jme3.math.Vector3f;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.Thrust;
import particlelab.physics.Validate;

/**
 * The lecture code's own faults, each as the force the faulty listing computes, kept apart
 * from the shared integrator's recipe ({@code physics/EulerRecipe}), which stays as the
 * lecture writes it. A demo puts a fault's force beside its correct one and moves the
 * coefficient from one to the other ({@code --set fault=...}); a fault force at magnitude 0
 * adds nothing, so with every fault off a scene steps bit for bit as it did without them.
 *
 * <p>The slide's drag {@code −c·|V|²·V} is the third such force, {@link
 * particlelab.physics.SlideFormDrag}, which the drag demo already had for {@code law=slide}.
 * The fourth fault is not a force but the order of the step's two updates: {@link
 * PositionBeforeVelocity}, a stepper of its own, which moves a twin sphere beside the
 * lecture's.
 */
public final class LectureFaults {

    private LectureFaults() {
    }

    /**
     * The HelloGravityDragAndThrust listing's thrust: {@code F = k·V_other/|V_other|}, a push
     * along <em>another</em> sphere's velocity instead of the sphere's own. The other sphere's
     * velocity is read as the world has it when this sphere's forces are asked: a sphere
     * added before this one has already taken the step (the world steps its bodies in order).
     * Below {@link Thrust#MIN_SPEED} (the other sphere at rest, landed) it pushes nothing, as
     * the correct thrust does.
     */
    public static final class ThrustAlongAnother implements Force {

        private final Particle other;
        private float magnitude;

        /**
         * Create the faulty thrust.
         *
         * @param other the sphere whose velocity it pushes along (not null, read each step)
         */
        public ThrustAlongAnother(Particle other) {
            this.other = Validate.notNull(other, "other");
        }

        /**
         * Alter the push.
         *
         * @param newMagnitude k (in newtons, finite, &ge;0; 0: this fault is off)
         */
        public void setMagnitude(float newMagnitude) {
            magnitude = Validate.nonNegative(newMagnitude, "faulty thrust k (N)");
        }

        /** @return k (in newtons, &ge;0) */
        public float getMagnitude() {
            return magnitude;
        }

        @Override
        public void addForce(Particle particle, Vector3f netForce) {
            Validate.notNull(particle, "particle");
            Validate.notNull(netForce, "netForce");
            float speed = other.velocity.length();
            if (magnitude == 0f || speed < Thrust.MIN_SPEED) {
                return;
            }
            // the fault: F = k·V_other/|V_other|
            netForce.scaleAdd(magnitude / speed, other.velocity, netForce);
        }

        @Override
        public String describe() {
            return "F = " + magnitude + "·V_other/|V_other| (fault: another sphere's velocity)";
        }
    }

    /**
     * The thrust with its direction left unnormalised: {@code velocity.mult(k)} where the
     * listing needs {@code velocity.normalize().mult(k)}, so {@code F = k·V} (magnitude
     * {@code k·|V|}, not k). Along V with a coefficient k, it is linear drag with the sign
     * turned: with linear drag b beside it the velocity obeys {@code a = g + ((k − b)/m)·V},
     * which grows without bound once {@code k > b}. Not folded: asked through {@link Force}.
     */
    public static final class UnnormalisedThrust implements Force {

        private float magnitude;

        /**
         * Alter the push.
         *
         * @param newMagnitude k (in N per m/s as this code uses it, finite, &ge;0; 0: off)
         */
        public void setMagnitude(float newMagnitude) {
            magnitude = Validate.nonNegative(newMagnitude, "unnormalised thrust k");
        }

        /** @return k (in N per m/s as this code uses it, &ge;0) */
        public float getMagnitude() {
            return magnitude;
        }

        @Override
        public void addForce(Particle particle, Vector3f netForce) {
            Validate.notNull(particle, "particle");
            Validate.notNull(netForce, "netForce");
            if (magnitude == 0f) {
                return;
            }
            // the fault: F = k·V, the direction V never divided by |V|
            netForce.scaleAdd(magnitude, particle.velocity, netForce);
        }

        @Override
        public String describe() {
            return "F = " + magnitude + "·V (fault: direction not normalised)";
        }
    }

    /**
     * "P updated before V", another book's order: {@code P ← P + h·V} with the <em>old</em>
     * V, then {@code V ← V + h·a}. This is forward (explicit) Euler, in float in this order
     * (the report's {@code reference/ForwardEuler} is the same scheme in double); the
     * lecture's recipe ({@code physics/EulerRecipe}, semi-implicit Euler) updates V first and
     * moves P with the new V, and stays as it is. Under gravity alone the faulty samples lie
     * on the parabola launched with {@code Vy + g·h/2} (the lecture's on {@code Vy − g·h/2}),
     * so a shot lands about {@code Vx·h} long where the lecture's lands {@code Vx·h} short.
     *
     * <p>In a demo the world moves the twin with a forceless integrator, whose step is
     * exactly {@link #movePosition} ({@code V + h·0 = V}, then {@code P + h·V}), and the demo
     * calls {@link #updateVelocity} after the world's step. Allocates nothing.
     */
    public static final class PositionBeforeVelocity {

        private final Gravity gravity;
        /** Scratch: a = g at the step's start (m/s²). */
        private final Vector3f acceleration = new Vector3f();

        /**
         * Create the faulty stepper.
         *
         * @param gravity the field it falls in (not null, read at each step)
         */
        public PositionBeforeVelocity(Gravity gravity) {
            this.gravity = Validate.notNull(gravity, "gravity");
        }

        /**
         * Take the whole faulty step: {@link #movePosition}, then {@link #updateVelocity}.
         *
         * @param particle the particle (not null, modified)
         * @param stepSeconds h (in seconds, &gt;0)
         */
        public void step(Particle particle, float stepSeconds) {
            movePosition(particle, stepSeconds);
            updateVelocity(particle, stepSeconds);
        }

        /**
         * The fault's first half: {@code P ← P + h·V}, V still the step's old one.
         *
         * @param particle the particle (not null, its position modified)
         * @param stepSeconds h (in seconds, &gt;0)
         */
        public void movePosition(Particle particle, float stepSeconds) {
            particle.position.scaleAdd(stepSeconds, particle.velocity, particle.position);
        }

        /**
         * The fault's second half: {@code V ← V + h·g}, after P has moved.
         *
         * @param particle the particle (not null, its velocity modified)
         * @param stepSeconds h (in seconds, &gt;0)
         */
        public void updateVelocity(Particle particle, float stepSeconds) {
            acceleration.zero();
            gravity.addFieldAcceleration(particle, acceleration);
            particle.velocity.scaleAdd(stepSeconds, acceleration, particle.velocity);
        }
    }
}

package particlelab.reference;

import com.jme3.math.Vector3f;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Thrust;
import particlelab.physics.Validate;

/**
 * The forces of one scene in double precision, for the reference steppers: the laws of
 * {@link Gravity}, {@link LinearDrag}, {@link QuadraticDrag} and {@link Thrust} acting on one
 * mass m, summed as the lecture's recipe sums them:
 *
 * <pre>
 *   a(V) = g + (−b·V − c·|V|·V + T·V/|V|)/m      (thrust is 0 while |V| &lt; Thrust.MIN_SPEED)
 * </pre>
 *
 * Every one of these forces depends on the velocity only, never on the position; the steppers
 * rely on that. {@link #toForces()} builds the same scene from the physics classes, so the
 * shared (float) integrator can run it beside the double-precision steppers. Immutable.
 */
public final class ForceModel {

    private final double gravityX;
    private final double gravityY;
    private final double gravityZ;
    private final double massKg;
    private final double linearDrag;
    private final double quadraticDrag;
    private final double thrustNewtons;

    /**
     * Create a force model.
     *
     * @param gravity g (in m/s², 3 finite components, not null, copied)
     * @param massKg m (in kilograms, finite, &gt;0)
     * @param linearDrag b of {@code F = −b·V} (in kg/s, finite, &ge;0)
     * @param quadraticDrag c of {@code F = −c·|V|·V} (in kg/m, finite, &ge;0)
     * @param thrustNewtons T of {@code F = T·V/|V|} (in newtons, finite, &ge;0)
     */
    public ForceModel(double[] gravity, double massKg, double linearDrag, double quadraticDrag,
            double thrustNewtons) {
        if (gravity == null || gravity.length != 3) {
            throw new IllegalArgumentException("gravity g (m/s^2) must have 3 components, but was "
                    + (gravity == null ? "null" : gravity.length + " long"));
        }
        this.gravityX = Validate.finite(gravity[0], "gravity g.x (m/s^2)");
        this.gravityY = Validate.finite(gravity[1], "gravity g.y (m/s^2)");
        this.gravityZ = Validate.finite(gravity[2], "gravity g.z (m/s^2)");
        this.massKg = Validate.positive(massKg, "mass (kg)");
        this.linearDrag = Validate.nonNegative(linearDrag, "linear drag b (kg/s)");
        this.quadraticDrag = Validate.nonNegative(quadraticDrag, "quadratic drag c (kg/m)");
        this.thrustNewtons = Validate.nonNegative(thrustNewtons, "thrust T (N)");
    }

    /**
     * Create the lecture's scene: gravity {@code (0, −gDown, 0)} on a mass of 1 kg, with the
     * given damping rates per unit mass.
     *
     * @param gDown the pull of gravity (in m/s², finite, &ge;0), 9.8 in the lecture
     * @param linearRate k = b/m (in 1/s, finite, &ge;0)
     * @param quadraticRate c/m (in 1/m, finite, &ge;0)
     * @param thrustAcceleration T/m (in m/s², finite, &ge;0)
     * @return a new model with m = 1 kg
     */
    public static ForceModel perUnitMass(double gDown, double linearRate, double quadraticRate,
            double thrustAcceleration) {
        return new ForceModel(new double[] {0.0, -gDown, 0.0}, 1.0, linearRate, quadraticRate,
                thrustAcceleration);
    }

    /**
     * Calculate the acceleration {@code a(V)} at a velocity. Allocates nothing.
     *
     * @param velocity V (in m/s, 3 components, not null, not modified)
     * @param storeResult storage for a (in m/s², 3 components, not null, modified; may be
     *     velocity itself)
     */
    public void acceleration(double[] velocity, double[] storeResult) {
        double vx = velocity[0];
        double vy = velocity[1];
        double vz = velocity[2];
        // F/V: the forces here are all along V, so sum their factors first
        double forcePerVelocity = -linearDrag;
        if (quadraticDrag != 0.0 || thrustNewtons != 0.0) {
            double speed = Math.sqrt(vx * vx + vy * vy + vz * vz);
            forcePerVelocity -= quadraticDrag * speed;
            if (thrustNewtons != 0.0 && speed >= Thrust.MIN_SPEED) {
                forcePerVelocity += thrustNewtons / speed;
            }
        }
        double scale = forcePerVelocity / massKg;
        storeResult[0] = gravityX + scale * vx;
        storeResult[1] = gravityY + scale * vy;
        storeResult[2] = gravityZ + scale * vz;
    }

    /**
     * Build the same scene from the physics force classes, for the shared float integrator.
     *
     * @return new forces: gravity, then those of linear drag, quadratic drag and thrust whose
     *     coefficient is not zero (coefficients rounded to float)
     */
    public Force[] toForces() {
        int count = 1 + (linearDrag != 0.0 ? 1 : 0) + (quadraticDrag != 0.0 ? 1 : 0)
                + (thrustNewtons != 0.0 ? 1 : 0);
        Force[] forces = new Force[count];
        int next = 0;
        forces[next++] = new Gravity(
                new Vector3f((float) gravityX, (float) gravityY, (float) gravityZ));
        if (linearDrag != 0.0) {
            forces[next++] = new LinearDrag((float) linearDrag);
        }
        if (quadraticDrag != 0.0) {
            forces[next++] = new QuadraticDrag((float) quadraticDrag);
        }
        if (thrustNewtons != 0.0) {
            forces[next] = new Thrust((float) thrustNewtons);
        }
        return forces;
    }

    /**
     * Return one component of g.
     *
     * @param axis 0 for x, 1 for y, 2 for z
     * @return g along that axis (in m/s²)
     */
    public double gravity(int axis) {
        switch (axis) {
            case 0:
                return gravityX;
            case 1:
                return gravityY;
            case 2:
                return gravityZ;
            default:
                throw new IllegalArgumentException("axis must be 0, 1 or 2, but was " + axis);
        }
    }

    /**
     * Return the mass.
     *
     * @return m (in kilograms, &gt;0)
     */
    public double getMassKg() {
        return massKg;
    }

    /**
     * Return the linear drag coefficient.
     *
     * @return b (in kg/s, &ge;0)
     */
    public double getLinearDrag() {
        return linearDrag;
    }

    /**
     * Return the quadratic drag coefficient.
     *
     * @return c (in kg/m, &ge;0)
     */
    public double getQuadraticDrag() {
        return quadraticDrag;
    }

    /**
     * Return the thrust.
     *
     * @return T (in newtons, &ge;0)
     */
    public double getThrustNewtons() {
        return thrustNewtons;
    }

    /**
     * Return the linear damping rate {@code k = b/m}, which sets every stepper's stability limit.
     *
     * @return k (in 1/s, &ge;0)
     */
    public double linearRate() {
        return linearDrag / massKg;
    }

    /**
     * Test whether the scene is gravity plus linear drag only, the case with a closed form and
     * an exact step.
     *
     * @return true if there is no quadratic drag and no thrust
     */
    public boolean hasClosedForm() {
        return quadraticDrag == 0.0 && thrustNewtons == 0.0;
    }

    /**
     * Test whether any force depends on the velocity. Without one, a is constant and every
     * method of order 2 or more is exact.
     *
     * @return true if there is drag or thrust
     */
    public boolean dependsOnVelocity() {
        return linearDrag != 0.0 || quadraticDrag != 0.0 || thrustNewtons != 0.0;
    }

    /**
     * Describe the forces, for a report.
     *
     * @return e.g. {@code "g = 9.8 m/s², b/m = 0.5 /s"}
     */
    public String describe() {
        StringBuilder text = new StringBuilder();
        text.append("g = ").append(Math.sqrt(gravityX * gravityX + gravityY * gravityY
                + gravityZ * gravityZ)).append(" m/s²");
        if (linearDrag != 0.0) {
            text.append(", b/m = ").append(linearDrag / massKg).append(" /s");
        }
        if (quadraticDrag != 0.0) {
            text.append(", c/m = ").append(quadraticDrag / massKg).append(" /m");
        }
        if (thrustNewtons != 0.0) {
            text.append(", T/m = ").append(thrustNewtons / massKg).append(" m/s²");
        }
        return text.toString();
    }
}

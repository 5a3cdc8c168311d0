package particlelab.rigid;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;

/**
 * A uniform solid body, translation and rotation kept apart as the lecture asks:
 * <ul>
 * <li>a {@link Particle} for its centre of mass (P, V, m), moved by the shared
 * {@code ParticleIntegrator}: translation is exactly the particle code;</li>
 * <li>an orientation R, the lecture's rotation matrix: its columns are the body's x, y, z axes
 * in the world, so a point at body coordinates b is at {@code P + R·b};</li>
 * <li>an angular velocity ω (world frame, rad/s), a torque τ (world frame, N·m) and the
 * body-frame principal {@link Inertia}, turned by a {@link RotationIntegrator}.</li>
 * </ul>
 *
 * <p>The vectors and the matrix are {@code public final} and live, like the particle's: change
 * them in place.
 *
 * <p>How a world can hold rigid bodies (not done yet): a world body keeps a nullable rigid
 * part built with {@link #RigidBody(Particle, Inertia)} on the body's own particle, and the
 * world's integration phase, after the particle step of that body, calls
 * {@link RotationIntegrator#step} on the rigid part: the same order as
 * {@link #step(ParticleIntegrator, RotationIntegrator, float)}. The contact phases are not
 * changed; an impulse at a contact point would also change ω through the inertia.
 *
 * <p>For a view: jME's spatial rotation is a quaternion and would hide the drift of the plain
 * matrix step, so a view that shows it must move the mesh's vertices by
 * {@link #bodyToWorld} (or by R itself).
 */
public final class RigidBody {

    /** Orientation R (live; starts as the identity: body axes along the world axes). */
    public final Matrix3f orientation = new Matrix3f();
    /** Angular velocity ω in the world frame (in rad/s; live). */
    public final Vector3f angularVelocity = new Vector3f();
    /** Torque τ about the centre of mass in the world frame (in N·m; live; held each step). */
    public final Vector3f torque = new Vector3f();

    private final Particle particle;
    private final Particle savedParticle = new Particle();
    private Inertia inertia;

    /**
     * Create a body at rest at the origin, with the identity orientation.
     *
     * @param massKg m (in kg, finite, &gt;0)
     * @param inertia the principal moments in the body frame (not null)
     */
    public RigidBody(float massKg, Inertia inertia) {
        particle = new Particle(Vector3f.ZERO, Vector3f.ZERO, massKg);
        setInertia(inertia);
    }

    /**
     * Create a rigid body around an existing particle (its centre, shared, not copied), with
     * the identity orientation, at rest.
     *
     * @param centre the particle for the centre of mass (not null; live, shared)
     * @param inertia the principal moments in the body frame (not null)
     */
    public RigidBody(Particle centre, Inertia inertia) {
        if (centre == null) {
            throw new IllegalArgumentException("centre must be a particle, but was null");
        }
        particle = centre;
        setInertia(inertia);
    }

    /**
     * Access the centre of mass as a particle.
     *
     * @return the live particle (not null)
     */
    public Particle getParticle() {
        return particle;
    }

    /**
     * Return the principal moments.
     *
     * @return the inertia (not null, immutable)
     */
    public Inertia getInertia() {
        return inertia;
    }

    /**
     * Replace the principal moments.
     *
     * @param newInertia the body-frame inertia (not null)
     */
    public void setInertia(Inertia newInertia) {
        if (newInertia == null) {
            throw new IllegalArgumentException("inertia must be an Inertia, but was null");
        }
        inertia = newInertia;
    }

    /**
     * Copy a new angular velocity into the body.
     *
     * @param omega ω in the world frame (in rad/s, finite, not null, not modified)
     */
    public void setAngularVelocity(Vector3f omega) {
        angularVelocity.set(Validate.finite(omega, "angular velocity (rad/s)"));
    }

    /**
     * Copy a new torque into the body.
     *
     * @param newTorque τ in the world frame (in N·m, finite, not null, not modified)
     */
    public void setTorque(Vector3f newTorque) {
        torque.set(Validate.finite(newTorque, "torque (N*m)"));
    }

    /**
     * Copy a new orientation into the body.
     *
     * @param rotation R (finite, not null, not modified; any matrix is kept as given, so a
     *     demo can start from a drifted one)
     */
    public void setOrientation(Matrix3f rotation) {
        if (rotation == null) {
            throw new IllegalArgumentException("orientation must be a matrix, but was null");
        }
        for (int i = 0; i < 9; ++i) {
            if (!Float.isFinite(rotation.get(i / 3, i % 3))) {
                throw new IllegalArgumentException(
                        "orientation must have finite entries, but was " + rotation);
            }
        }
        orientation.set(rotation);
    }

    /**
     * Copy ω in the body frame, {@code Rᵀ·ω}, into storeResult (exact while R is a rotation;
     * with the plain matrix Euler step R drifts and so does this frame change).
     *
     * @param storeResult storage for the result (in rad/s, not null, modified)
     * @return storeResult
     */
    public Vector3f bodyAngularVelocity(Vector3f storeResult) {
        Matrix3f r = orientation;
        Vector3f w = angularVelocity;
        double x = (double) r.get(0, 0) * w.x + (double) r.get(1, 0) * w.y
                + (double) r.get(2, 0) * w.z;
        double y = (double) r.get(0, 1) * w.x + (double) r.get(1, 1) * w.y
                + (double) r.get(2, 1) * w.z;
        double z = (double) r.get(0, 2) * w.x + (double) r.get(1, 2) * w.y
                + (double) r.get(2, 2) * w.z;
        return storeResult.set((float) x, (float) y, (float) z);
    }

    /**
     * Copy where a point fixed in the body is in the world, {@code P + R·b}: a corner's trail,
     * or a drifting mesh. Allocates nothing.
     *
     * @param bodyPoint b, the point in body coordinates (in metres, not null, not modified)
     * @param storeResult storage for the world point (in metres, not null, modified; may be
     *     bodyPoint)
     * @return storeResult
     */
    public Vector3f bodyToWorld(Vector3f bodyPoint, Vector3f storeResult) {
        Matrix3f r = orientation;
        float x = bodyPoint.x;
        float y = bodyPoint.y;
        float z = bodyPoint.z;
        Vector3f p = particle.position;
        return storeResult.set(
                p.x + r.get(0, 0) * x + r.get(0, 1) * y + r.get(0, 2) * z,
                p.y + r.get(1, 0) * x + r.get(1, 1) * y + r.get(1, 2) * z,
                p.z + r.get(2, 0) * x + r.get(2, 1) * y + r.get(2, 2) * z);
    }

    /**
     * Calculate the rotational kinetic energy {@code ½·ωᵀ·I·ω} (body frame). Allocates nothing.
     *
     * @param scratch storage for ω in the body frame (not null, modified)
     * @return the energy (in joules, &ge;0)
     */
    public double rotationalEnergy(Vector3f scratch) {
        return inertia.kineticEnergy(bodyAngularVelocity(scratch));
    }

    /**
     * Calculate {@code |L| = |I·ω|} (body frame). Allocates nothing.
     *
     * @param scratch storage for ω in the body frame (not null, modified)
     * @return |L| (in kg·m²/s, &ge;0)
     */
    public double angularMomentum(Vector3f scratch) {
        return inertia.angularMomentum(bodyAngularVelocity(scratch));
    }

    /**
     * Advance the body by one step, translation and rotation separately: the centre by the
     * particle integrator (its forces), then ω and R by the rotation integrator. If either
     * step would go non-finite it throws and the whole body keeps its last state.
     *
     * @param translation the particle integrator for the centre (not null)
     * @param rotation the rotation integrator (not null)
     * @param stepSeconds h (in seconds, finite, &ge;0)
     * @throws particlelab.physics.NonFiniteStepException (or the particle integrator's
     *     IllegalStateException) if the step would go non-finite
     */
    public void step(ParticleIntegrator translation, RotationIntegrator rotation,
            float stepSeconds) {
        savedParticle.copyFrom(particle);
        translation.step(particle, stepSeconds);
        try {
            rotation.step(this, stepSeconds);
        } catch (IllegalStateException failed) {
            particle.copyFrom(savedParticle);
            throw failed;
        }
    }

    @Override
    public String toString() {
        return "RigidBody[" + particle + ", R=" + orientation + ", omega=" + angularVelocity
                + ", tau=" + torque + ", " + inertia + "]";
    }
}

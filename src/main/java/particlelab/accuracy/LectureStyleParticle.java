package particlelab.accuracy;

import com.jme3.math.Vector3f;
import particlelab.physics.Thrust;

/**
 * The lecture slides' own code style, kept as a benchmark reference only: every step builds
 * new vectors with jME's allocating {@code mult}/{@code add}/{@code divide} and replaces the
 * particle's position and velocity with them.
 *
 * <pre>
 *   force = velocity.mult(−b);  acceleration = gravity.add(force.divide(m));
 *   velocity = velocity.add(acceleration.mult(tpf));  position = position.add(velocity.mult(tpf));
 * </pre>
 *
 * The project's own code does the same step in place ({@code scaleAdd}); this class shows what
 * that saves. Its fields are deliberately not final, since the style replaces them.
 */
public final class LectureStyleParticle {

    /** Position P (in metres; replaced by a new vector every step). */
    public Vector3f position;
    /** Velocity V (in m/s; replaced by a new vector every step). */
    public Vector3f velocity;
    private final float massKg;

    /**
     * Create a particle.
     *
     * @param position P (in metres, not null, copied)
     * @param velocity V (in m/s, not null, copied)
     * @param massKg m (in kilograms, &gt;0)
     */
    public LectureStyleParticle(Vector3f position, Vector3f velocity, float massKg) {
        this.position = position.clone();
        this.velocity = velocity.clone();
        this.massKg = massKg;
    }

    /**
     * Take one semi-implicit Euler step under gravity and linear drag, the slides' way.
     *
     * @param gravity g (in m/s², not null, not modified)
     * @param linearDrag b (in kg/s)
     * @param tpf the step (in seconds)
     */
    public void step(Vector3f gravity, float linearDrag, float tpf) {
        Vector3f force = velocity.mult(-linearDrag);
        Vector3f acceleration = gravity.add(force.divide(massKg));
        velocity = velocity.add(acceleration.mult(tpf));
        position = position.add(velocity.mult(tpf));
    }

    /**
     * Take one semi-implicit Euler step under gravity and a mix's forces, the slides' way:
     * each force a new vector, summed with {@code add}. For {@link ForceMix#LINEAR} this is
     * the same arithmetic as {@link #step(Vector3f, float, float)}.
     *
     * <pre>
     *   force = velocity.mult(−b) + velocity.mult(−c·|V|) + velocity.normalize().mult(k)
     * </pre>
     *
     * @param gravity g (in m/s², not null, not modified)
     * @param mix the forces besides gravity (not null)
     * @param tpf the step (in seconds)
     */
    public void step(Vector3f gravity, ForceMix mix, float tpf) {
        Vector3f force = mix.linearDrag() != 0f ? velocity.mult(-mix.linearDrag())
                : new Vector3f();
        if (mix.quadraticDrag() != 0f) {
            force = force.add(velocity.mult(-mix.quadraticDrag() * velocity.length()));
        }
        if (mix.thrustNewtons() != 0f && velocity.length() >= Thrust.MIN_SPEED) {
            force = force.add(velocity.normalize().mult(mix.thrustNewtons()));
        }
        Vector3f acceleration = gravity.add(force.divide(massKg));
        velocity = velocity.add(acceleration.mult(tpf));
        position = position.add(velocity.mult(tpf));
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The one Euler step every demo uses: the lecture's "simulation recipe".
 *
 * <pre>
 *   forces from the state at the start of the step:  a = g + F(P, V)/m
 *   velocity first:                                  V ← V + h·a
 *   then position, with the NEW velocity:            P ← P + h·V
 * </pre>
 *
 * This is the <b>semi-implicit (symplectic) Euler</b> method, first order in h. Forward
 * (explicit) Euler would move P with the old V instead; the order matters (a level shot lands
 * {@code vx·h} short here, {@code vx·h} long with forward Euler).
 *
 * <p>An integrator holds the forces of one scene (or of one particle in a side-by-side scene)
 * and a few scratch vectors, so it is not thread-safe and {@link #step} allocates nothing.
 */
public final class ParticleIntegrator {

    private final Force[] forces;
    /** Scratch: g, the sum of field accelerations (m/s²). */
    private final Vector3f fieldAcceleration = new Vector3f();
    /** Scratch: F, the sum of pushing forces (N). */
    private final Vector3f netForce = new Vector3f();
    /** Scratch: a = g + F/m (m/s²). */
    private final Vector3f acceleration = new Vector3f();
    /** Scratch: the velocity after the step (m/s), committed only if finite. */
    private final Vector3f nextVelocity = new Vector3f();
    /** Scratch: the position after the step (m), committed only if finite. */
    private final Vector3f nextPosition = new Vector3f();

    /**
     * Create an integrator for a scene's forces.
     *
     * @param forces the forces the scene models, only those (none means uniform motion; not
     *     null, no null elements; the array is copied, the forces are shared)
     */
    public ParticleIntegrator(Force... forces) {
        if (forces == null) {
            throw new IllegalArgumentException("forces must be an array, but was null");
        }
        for (int i = 0; i < forces.length; ++i) {
            if (forces[i] == null) {
                throw new IllegalArgumentException(
                        "forces[" + i + "] must be a force, but was null");
            }
        }
        this.forces = forces.clone();
    }

    /**
     * Advance one particle by one Euler step.
     *
     * @param particle the particle to move (not null, modified unless the step fails)
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0; 0 does nothing)
     * @throws IllegalStateException if the step would leave the particle with a NaN or
     *     infinite component (the step was far beyond the stability limit): stop rather than
     *     spread NaN. The particle then keeps its last finite state.
     */
    public void step(Particle particle, float stepSeconds) {
        checkStep(stepSeconds);
        if (stepSeconds == 0f) {
            return;
        }
        acceleration(particle, acceleration);
        // V ← V + h·a, then P ← P + h·V with the new V
        nextVelocity.set(particle.velocity).scaleAdd(stepSeconds, acceleration, nextVelocity);
        nextPosition.set(particle.position).scaleAdd(stepSeconds, nextVelocity, nextPosition);
        if (!Validate.isFinite(nextVelocity) || !Validate.isFinite(nextPosition)) {
            throw new IllegalStateException("the Euler step h=" + stepSeconds
                    + " s would leave the particle non-finite: " + particle
                    + " would get P=" + nextPosition + ", V=" + nextVelocity
                    + "; the largest stable step here is " + maxStableStep(particle) + " s");
        }
        particle.velocity.set(nextVelocity);
        particle.position.set(nextPosition);
    }

    /**
     * Advance each of several particles by one Euler step, all under this integrator's forces.
     *
     * @param particles the particles to move (not null, elements not null and modified)
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0)
     */
    public void step(Particle[] particles, float stepSeconds) {
        for (int i = 0; i < particles.length; ++i) {
            step(particles[i], stepSeconds);
        }
    }

    /**
     * Calculate the particle's acceleration {@code a = g + F/m} at its current state.
     *
     * @param particle the particle (not null, not modified)
     * @param storeResult storage for the result (in m/s², not null, modified)
     * @return storeResult
     */
    public Vector3f acceleration(Particle particle, Vector3f storeResult) {
        fieldAcceleration.zero();
        netForce.zero();
        for (int i = 0; i < forces.length; ++i) {
            forces[i].addFieldAcceleration(particle, fieldAcceleration);
            forces[i].addForce(particle, netForce);
        }
        // a = g + F/m
        return storeResult.set(fieldAcceleration)
                .scaleAdd(1f / particle.getMass(), netForce, storeResult);
    }

    /**
     * Return the total damping rate λ of the forces at the particle's state (see
     * {@link Force#dampingRate}).
     *
     * @param particle the particle (not null, not modified)
     * @return λ (in 1/s, &ge;0)
     */
    public float dampingRate(Particle particle) {
        float rate = 0f;
        for (int i = 0; i < forces.length; ++i) {
            rate += forces[i].dampingRate(particle);
        }
        return rate;
    }

    /**
     * Return the largest step for which the Euler step is stable at the particle's current
     * state, small changes of the velocity dying out rather than growing: {@code 2/λ} (linear
     * drag: {@code 2m/b}; quadratic drag: {@code m/(c·|V|)}, which at the terminal speed
     * {@code v_t} is {@code v_t/g}).
     *
     * @param particle the particle (not null, not modified)
     * @return the limit (in seconds, &gt;0; infinite when nothing damps)
     */
    public float maxStableStep(Particle particle) {
        return 2f / dampingRate(particle);
    }

    /**
     * Return the largest step for which the Euler step does not overshoot at the particle's
     * current state: {@code 1/λ} (linear drag: {@code m/b}, beyond which the velocity flips
     * sign every step; quadratic drag: {@code m/(2c·|V|)}, beyond which the speed swings about
     * its terminal value; drag alone reverses the velocity only beyond {@code m/(c·|V|)}).
     *
     * @param particle the particle (not null, not modified)
     * @return the limit (in seconds, &gt;0; infinite when nothing damps)
     */
    public float maxMonotoneStep(Particle particle) {
        return 1f / dampingRate(particle);
    }

    /**
     * Count the forces.
     *
     * @return the number of forces (&ge;0)
     */
    public int countForces() {
        return forces.length;
    }

    /**
     * Access a force.
     *
     * @param index which force (&ge;0, &lt;{@link #countForces()})
     * @return the live force
     */
    public Force getForce(int index) {
        return forces[index];
    }

    /**
     * Describe the forces, one equation each, for a HUD or a report.
     *
     * @return e.g. {@code "g = (0.0, -9.8, 0.0) m/s², F = -0.9·V"}, or "no force"
     */
    public String describe() {
        if (forces.length == 0) {
            return "no force";
        }
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < forces.length; ++i) {
            if (i > 0) {
                text.append(", ");
            }
            text.append(forces[i].describe());
        }
        return text.toString();
    }

    private static void checkStep(float stepSeconds) {
        if (!(stepSeconds >= 0f) || stepSeconds == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "step h (s) must be finite and >= 0, but was " + stepSeconds);
        }
    }
}

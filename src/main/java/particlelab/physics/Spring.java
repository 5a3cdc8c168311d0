package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * A spring from a fixed anchor A to the particle, with rest length L, spring constant k and
 * optional damping c along the spring (Hooke's law plus a dashpot):
 * <pre>
 *   d = P − A,  u = d/|d|
 *   F = −k·(|d| − L)·u − c·(V·u)·u
 * </pre>
 * Stretched ({@code |d| > L}) it pulls the particle toward A, compressed it pushes it away;
 * the damping slows only the motion along the spring.
 *
 * <p>Stability: the spring's stiffness is {@code ω² = k/m} (ω its angular frequency, in rad/s)
 * and its damping rate {@code λ = c/m}. The Euler step is stable while
 * {@code h < 4/(λ + sqrt(λ² + 4ω²))} ({@link ParticleIntegrator#stableStepLimit}): {@code 2/ω}
 * without damping, where the step keeps a modified energy exactly and the swing neither grows
 * nor decays. Forward Euler would gain energy at every step, whatever h.
 *
 * <p>At the anchor ({@code |d|} below {@link #MIN_LENGTH}) there is no direction to push along,
 * so the spring exerts no force there, and the step never divides by a zero length.
 */
public final class Spring implements Force {

    /** Distances from the anchor below this (in metres) give no direction, so no force. */
    public static final float MIN_LENGTH = 1e-6f;

    private final Vector3f anchor = new Vector3f();
    private final float restLength;
    private float springConstant;
    private float damping;

    /**
     * Create an undamped spring.
     *
     * @param anchor A, the fixed end (in metres, finite, not null, copied)
     * @param restLength L (in metres, finite, &ge;0)
     * @param springConstant k (in N/m, finite, &ge;0)
     */
    public Spring(Vector3f anchor, float restLength, float springConstant) {
        this(anchor, restLength, springConstant, 0f);
    }

    /**
     * Create a spring with damping along it.
     *
     * @param anchor A, the fixed end (in metres, finite, not null, copied)
     * @param restLength L (in metres, finite, &ge;0)
     * @param springConstant k (in N/m, finite, &ge;0)
     * @param damping c (in N·s/m = kg/s, finite, &ge;0)
     */
    public Spring(Vector3f anchor, float restLength, float springConstant, float damping) {
        setAnchor(anchor);
        this.restLength = Validate.nonNegative(restLength, "spring rest length L (m)");
        setSpringConstant(springConstant);
        setDamping(damping);
    }

    /**
     * Copy the anchor into storeResult.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult
     */
    public Vector3f copyAnchor(Vector3f storeResult) {
        return storeResult.set(anchor);
    }

    /**
     * Move the anchor.
     *
     * @param newAnchor A (in metres, finite, not null, not modified)
     */
    public void setAnchor(Vector3f newAnchor) {
        anchor.set(Validate.finite(newAnchor, "spring anchor A (m)"));
    }

    /**
     * Return the rest length.
     *
     * @return L (in metres, &ge;0)
     */
    public float getRestLength() {
        return restLength;
    }

    /**
     * Return the spring constant.
     *
     * @return k (in N/m, &ge;0)
     */
    public float getSpringConstant() {
        return springConstant;
    }

    /**
     * Alter the spring constant: the next step pulls with it (a spring is asked through the
     * {@link Force} interface every step, so there is nothing to refold).
     *
     * @param newSpringConstant k (in N/m, finite, &ge;0)
     */
    public void setSpringConstant(float newSpringConstant) {
        springConstant = Validate.nonNegative(newSpringConstant, "spring constant k (N/m)");
    }

    /**
     * Alter the damping along the spring, from the next step.
     *
     * @param newDamping c (in N·s/m = kg/s, finite, &ge;0)
     */
    public void setDamping(float newDamping) {
        damping = Validate.nonNegative(newDamping, "spring damping c (N*s/m)");
    }

    /**
     * Return the damping coefficient along the spring.
     *
     * @return c (in N·s/m, &ge;0)
     */
    public float getDamping() {
        return damping;
    }

    @Override
    public void addForce(Particle particle, Vector3f netForce) {
        Validate.notNull(particle, "particle");
        Validate.notNull(netForce, "netForce");
        Vector3f position = particle.position;
        float dx = position.x - anchor.x;
        float dy = position.y - anchor.y;
        float dz = position.z - anchor.z;
        float length = (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (!(length >= MIN_LENGTH)) {
            return;
        }
        float ux = dx / length;
        float uy = dy / length;
        float uz = dz / length;
        Vector3f v = particle.velocity;
        float alongVelocity = v.x * ux + v.y * uy + v.z * uz;
        // F = (−k·(|d| − L) − c·(V·u))·u
        float push = -springConstant * (length - restLength) - damping * alongVelocity;
        netForce.addLocal(push * ux, push * uy, push * uz);
    }

    /**
     * {@inheritDoc}
     *
     * <p>Here {@code λ = c/m}, for motion along the spring.
     */
    @Override
    public float dampingRate(Particle particle) {
        Validate.notNull(particle, "particle");
        return (float) Math.min((double) damping / particle.getMass(), Float.MAX_VALUE);
    }

    /**
     * {@inheritDoc}
     *
     * <p>Here {@code ω² = k/m}, along the spring (across it the pull is weaker:
     * {@code k·(1 − L/|d|)/m}).
     */
    @Override
    public float stiffness(Particle particle) {
        Validate.notNull(particle, "particle");
        return (float) Math.min((double) springConstant / particle.getMass(), Float.MAX_VALUE);
    }

    @Override
    public String describe() {
        String text = "F = -" + springConstant + "·(|d| - " + restLength + ")·u";
        if (damping > 0f) {
            text += " - " + damping + "·(V·u)·u";
        }
        return text + ", d = P - (" + anchor.x + ", " + anchor.y + ", " + anchor.z
                + "), u = d/|d|";
    }
}

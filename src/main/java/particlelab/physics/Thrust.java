package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Thrust {@code F = k·V/|V|}: a push of constant magnitude k along the particle's <em>own</em>
 * velocity, like a rocket motor that keeps pointing where it flies. (The original lecture code
 * pushed one sphere along another sphere's velocity; this one always uses its own.)
 *
 * <p>At rest there is no direction to push along. Below {@link #MIN_SPEED} the thrust is
 * therefore zero: a motor at rest stays at rest until another force (gravity, say) gives it a
 * heading, and the step never divides by a zero length.
 */
public final class Thrust extends FoldedForce {

    /** Speeds below this (in m/s) give no heading, so no thrust. */
    public static final float MIN_SPEED = 1e-6f;

    private float magnitude;

    /**
     * Create thrust.
     *
     * @param magnitude k (in newtons, finite, &ge;0)
     */
    public Thrust(float magnitude) {
        setMagnitude(magnitude);
    }

    /**
     * Return the magnitude.
     *
     * @return k (in newtons, &ge;0)
     */
    public float getMagnitude() {
        return magnitude;
    }

    /**
     * Alter the magnitude.
     *
     * @param magnitude k (in newtons, finite, &ge;0)
     */
    public void setMagnitude(float magnitude) {
        this.magnitude = Validate.nonNegative(magnitude, "thrust k (N)");
        changed();
    }

    @Override
    public void addForce(Particle particle, Vector3f netForce) {
        Validate.notNull(particle, "particle");
        Validate.notNull(netForce, "netForce");
        float speed = particle.velocity.length();
        if (speed < MIN_SPEED) {
            return;
        }
        // F = k V/|V|
        netForce.scaleAdd(magnitude / speed, particle.velocity, netForce);
    }

    @Override
    public String describe() {
        return "F = " + magnitude + "·V/|V|";
    }
}

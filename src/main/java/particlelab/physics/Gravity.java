package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Gravitational pull near the ground: the constant acceleration {@code g}, the same for every
 * mass. It enters the recipe as {@code g} in {@code a = g + F/m}, not as a force to divide by m.
 */
public final class Gravity extends FoldedForce {

    /** The lecture's standard gravity (in m/s², pointing down the y axis). */
    public static final float STANDARD_G = 9.8f;

    private final Vector3f acceleration = new Vector3f();

    /**
     * Create gravity of {@link #STANDARD_G} pointing down the y axis.
     */
    public Gravity() {
        this(new Vector3f(0f, -STANDARD_G, 0f));
    }

    /**
     * Create gravity with a given acceleration.
     *
     * @param acceleration g (in m/s², finite, not null, copied)
     */
    public Gravity(Vector3f acceleration) {
        setAcceleration(acceleration);
    }

    /**
     * Copy the acceleration g into storeResult.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult
     */
    public Vector3f copyAcceleration(Vector3f storeResult) {
        return Validate.notNull(storeResult, "storeResult").set(acceleration);
    }

    /**
     * Alter the acceleration g.
     *
     * @param newAcceleration g (in m/s², finite, not null, not modified)
     */
    public void setAcceleration(Vector3f newAcceleration) {
        acceleration.set(Validate.finite(newAcceleration, "gravity g (m/s^2)"));
        changed();
    }

    @Override
    public void addFieldAcceleration(Particle particle, Vector3f fieldAcceleration) {
        Validate.notNull(particle, "particle");
        Validate.notNull(fieldAcceleration, "fieldAcceleration");
        fieldAcceleration.addLocal(acceleration);
    }

    @Override
    public String describe() {
        return "g = (" + acceleration.x + ", " + acceleration.y + ", " + acceleration.z
                + ") m/s²";
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * A point mass: position P (m), velocity V (m/s) and mass m (kg).
 *
 * <p>The vectors are {@code public final}: update them in place ({@code addLocal},
 * {@code scaleAdd}, {@code set}), never by replacing them, so no step allocates.
 */
public final class Particle {

    /**
     * The smallest mass allowed (in kilograms): the smallest normal float, about 1.2e-38, so
     * that {@code 1/m} is a finite float (about 8.5e37).
     */
    public static final float MIN_MASS_KG = Float.MIN_NORMAL;

    /** Position P (in metres; live, modified in place by the integrator). */
    public final Vector3f position = new Vector3f();
    /** Velocity V (in metres per second; live, modified in place by the integrator). */
    public final Vector3f velocity = new Vector3f();

    private float massKg;
    /**
     * 1/m (in 1/kg), set with the mass: the per-particle step reads it, so a loop over
     * particles needs no division and no inverse remembered for one mass.
     */
    private float inverseMassPerKg;

    /**
     * Create a particle of mass 1 kg at rest at the origin.
     */
    public Particle() {
        setMass(1f);
    }

    /**
     * Create a particle.
     *
     * @param position the initial position (in metres, finite, not null, copied)
     * @param velocity the initial velocity (in metres per second, finite, not null, copied)
     * @param massKg the mass (in kilograms, finite, &ge;{@link #MIN_MASS_KG})
     */
    public Particle(Vector3f position, Vector3f velocity, float massKg) {
        setMass(massKg);
        setState(position, velocity);
    }

    /**
     * Return the mass.
     *
     * @return the mass (in kilograms, finite, &gt;0)
     */
    public float getMass() {
        return massKg;
    }

    /**
     * Alter the mass.
     *
     * @param massKg the new mass (in kilograms, finite, &ge;{@link #MIN_MASS_KG})
     */
    public void setMass(float massKg) {
        this.massKg = checkMass(massKg);
        inverseMassPerKg = 1f / massKg;
    }

    /**
     * Return 1/m, computed when the mass was set.
     *
     * @return {@code 1f / getMass()} (in 1/kg, finite, &gt;0)
     */
    float inverseMass() {
        return inverseMassPerKg;
    }

    /**
     * Copy a new position and velocity into this particle.
     *
     * @param newPosition the position (in metres, finite, not null, not modified)
     * @param newVelocity the velocity (in metres per second, finite, not null, not modified)
     */
    public void setState(Vector3f newPosition, Vector3f newVelocity) {
        Validate.finite(newPosition, "position (m)");
        Validate.finite(newVelocity, "velocity (m/s)");
        position.set(newPosition);
        velocity.set(newVelocity);
    }

    /**
     * Copy the whole state (position, velocity, mass) of another particle into this one.
     *
     * @param source the particle to copy (not null, not modified)
     */
    public void copyFrom(Particle source) {
        Validate.notNull(source, "source");
        position.set(source.position);
        velocity.set(source.velocity);
        massKg = source.massKg;
        inverseMassPerKg = source.inverseMassPerKg;
    }

    /**
     * Test whether the position and velocity are finite.
     *
     * @return true if no component is NaN or infinite
     */
    public boolean isFinite() {
        return Validate.isFinite(position) && Validate.isFinite(velocity);
    }

    /**
     * Require a mass this class accepts.
     *
     * @param massKg the mass to check (in kilograms)
     * @return massKg
     * @throws IllegalArgumentException unless finite and &ge;{@link #MIN_MASS_KG}
     */
    static float checkMass(float massKg) {
        if (!(Float.isFinite(massKg) && massKg >= MIN_MASS_KG)) {
            throw new IllegalArgumentException("mass (kg) must be finite and > 0, at least "
                    + MIN_MASS_KG + " so that 1/m is a finite float, but was " + massKg);
        }
        return massKg;
    }

    @Override
    public String toString() {
        return "Particle[P=" + position + ", V=" + velocity + ", m=" + massKg + "]";
    }
}

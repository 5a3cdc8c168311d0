package particlelab.accuracy;

import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleBatch;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Thrust;

/**
 * The force mixes of the demos, as the benchmarks time them: gravity alone, gravity + linear
 * drag, gravity + quadratic drag, gravity + linear drag + thrust along V. Particles of
 * {@value #MASS_KG} kg, g = {@link Gravity#STANDARD_G} m/s² down the y axis. The ids are the
 * {@code <mix>} of the benchmark rows {@code single/<mix>/<path>} and
 * {@code bulk/<mix>/<path>/<N>}, and the values of the JMH parameter {@code mix}.
 */
public enum ForceMix {
    /** Gravity alone. */
    GRAVITY("gravity", "gravity", 0f, 0f, 0f),
    /** Gravity + linear drag b = 0.5 kg/s (b/m = 0.5 /s, the bulk scene's). */
    LINEAR("linear", "gravity + linear drag", 0.5f, 0f, 0f),
    /** Gravity + quadratic drag c = 0.02 kg/m (terminal speed sqrt(m·g/c) = 22 m/s). */
    QUADRATIC("quadratic", "gravity + quadratic drag", 0f, 0.02f, 0f),
    /** Gravity + linear drag b = 0.5 kg/s + thrust k = 4 N (cruise speed k/b = 8 m/s). */
    THRUST_LINEAR("thrust-linear", "gravity + linear drag + thrust", 0.5f, 0f, 4f);

    /** Every particle's mass (kg). */
    public static final float MASS_KG = 1f;

    private final String id;
    private final String label;
    private final float linearDrag;
    private final float quadraticDrag;
    private final float thrustNewtons;

    ForceMix(String id, String label, float linearDrag, float quadraticDrag,
            float thrustNewtons) {
        this.id = id;
        this.label = label;
        this.linearDrag = linearDrag;
        this.quadraticDrag = quadraticDrag;
        this.thrustNewtons = thrustNewtons;
    }

    /**
     * Find a mix by its id.
     *
     * @param id one of gravity, linear, quadratic, thrust-linear (not null)
     * @return the mix
     * @throws IllegalArgumentException if no mix has that id
     */
    public static ForceMix named(String id) {
        for (ForceMix mix : values()) {
            if (mix.id.equals(id)) {
                return mix;
            }
        }
        throw new IllegalArgumentException("force mix must be gravity, linear, quadratic or "
                + "thrust-linear, but was " + id);
    }

    /**
     * Return the id used in row names and as the JMH parameter.
     *
     * @return e.g. {@code "thrust-linear"}
     */
    public String id() {
        return id;
    }

    /**
     * Return the mix in words, for tables and charts.
     *
     * @return e.g. {@code "gravity + quadratic drag"}
     */
    public String label() {
        return label;
    }

    /**
     * Return the linear drag b.
     *
     * @return b (in kg/s, &ge;0)
     */
    public float linearDrag() {
        return linearDrag;
    }

    /**
     * Return the quadratic drag c.
     *
     * @return c (in kg/m, &ge;0)
     */
    public float quadraticDrag() {
        return quadraticDrag;
    }

    /**
     * Return the thrust k along the velocity.
     *
     * @return k (in newtons, &ge;0)
     */
    public float thrustNewtons() {
        return thrustNewtons;
    }

    /**
     * Tell whether the batch step has two forms for this mix, the scalar passes and the
     * Vector API ({@link ParticleBatch#setVectorBatch}): only without speed-dependent
     * forces, where one velocity factor serves every particle.
     *
     * @return true for {@link #GRAVITY} and {@link #LINEAR}
     */
    public boolean hasVectorBatch() {
        return quadraticDrag == 0f && thrustNewtons == 0f;
    }

    /**
     * Create the shared integrator for this mix, holding only the forces the mix has.
     *
     * @return a new integrator (not null)
     */
    public ParticleIntegrator integrator() {
        switch (this) {
            case GRAVITY:
                return new ParticleIntegrator(new Gravity());
            case LINEAR:
                return new ParticleIntegrator(new Gravity(), new LinearDrag(linearDrag));
            case QUADRATIC:
                return new ParticleIntegrator(new Gravity(), new QuadraticDrag(quadraticDrag));
            case THRUST_LINEAR:
                return new ParticleIntegrator(new Force[] {new Gravity(),
                    new LinearDrag(linearDrag), new Thrust(thrustNewtons)});
            default:
                throw new AssertionError(this);
        }
    }
}

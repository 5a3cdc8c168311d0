package particlelab.aiming;

import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;

/**
 * Fires a bullet from the origin along the x axis and steps it with the shared integrator and
 * the scene's own forces until it comes down through the ground plane {@code y = 0} (a
 * {@link Flight}).
 * Reuses one particle: firing allocates nothing.
 */
public final class ShotSimulator {

    private final Flight flight;
    private final Particle bullet;
    /** The mass of the bullets fired by {@link #fire(float, float, Landing)}. */
    private final float massKg;
    private final float stepSeconds;
    private final int maxSteps;

    /**
     * Create a simulator.
     *
     * @param integrator the scene's integrator, with its forces (not null)
     * @param massKg the bullet's mass (in kilograms, finite, &gt;0)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @param maxFlightSeconds give up on a shot still in the air after this long (in seconds,
     *     finite, &gt;0)
     */
    public ShotSimulator(ParticleIntegrator integrator, float massKg, float stepSeconds,
            float maxFlightSeconds) {
        this.flight = new Flight(Validate.notNull(integrator, "integrator"));
        this.bullet = new Particle();
        bullet.setMass(massKg);
        this.massKg = massKg;
        this.stepSeconds = Validate.positive(stepSeconds, "step h (s)");
        Validate.positive(maxFlightSeconds, "max flight time (s)");
        this.maxSteps = (int) Math.min(Integer.MAX_VALUE - 1L,
                (long) Math.ceil(maxFlightSeconds / stepSeconds));
    }

    /**
     * Return the step.
     *
     * @return h (in seconds, &gt;0)
     */
    public float getStepSeconds() {
        return stepSeconds;
    }

    /**
     * Fire one shot of the simulator's mass from the origin with velocity {@code (vx, vy, 0)}.
     *
     * @param horizontalSpeed vx (in m/s, finite)
     * @param verticalSpeed vy (in m/s, finite)
     * @param storeResult storage for where it landed (not null, modified)
     * @return true if it landed within the time allowed
     */
    public boolean fire(float horizontalSpeed, float verticalSpeed, Landing storeResult) {
        Validate.notNull(storeResult, "storeResult");
        Validate.finite(horizontalSpeed, "horizontal speed vx (m/s)");
        Validate.finite(verticalSpeed, "vertical speed vy (m/s)");
        // fire(Particle, Landing) may have left another mass in the reused bullet.
        bullet.setMass(massKg);
        bullet.position.zero();
        bullet.velocity.set(horizontalSpeed, verticalSpeed, 0f);
        return flyUntilGround(storeResult);
    }

    /**
     * Fire one shot from a given state (its mass included) and step it until it comes down
     * through {@code y = 0}.
     *
     * @param start the bullet's initial state (its y should be &ge;0; not null, not modified)
     * @param storeResult storage for where it landed (not null, modified)
     * @return true if it landed within the time allowed
     */
    public boolean fire(Particle start, Landing storeResult) {
        Validate.notNull(start, "start");
        Validate.notNull(storeResult, "storeResult");
        bullet.copyFrom(start);
        return flyUntilGround(storeResult);
    }

    private boolean flyUntilGround(Landing storeResult) {
        return flight.fly(bullet, stepSeconds, maxSteps, storeResult);
    }
}

package particlelab.aiming;

import com.jme3.math.Vector3f;
import particlelab.collision.Plane;
import particlelab.collision.Surface;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Validate;

/**
 * Flies one particle with its scene's integrator, step by step, until it comes down through
 * the ground {@code y = 0}: the lecture's "stop at the ground" for the code that flies shots
 * outside a world (the aimer's shots, the camera's framing of a launch, the hitch study,
 * {@code particle-lab trajectory --until-ground}), or up to its apex ({@link #climb}: the
 * iterative aimer's framing of a round). A world's particles stop at the ground by the
 * world's own rule ({@code world.GroundStop}), which the world interpolates.
 *
 * <p>Within a step the particle moves on the straight segment from its old position to its
 * new one (semi-implicit Euler), so where it crossed the ground is found by the same swept
 * test the world's ground rule uses ({@link Plane#ground()}'s {@link Surface#sweep}), and the
 * point is interpolated on that segment here: the one place in the code where a flight's
 * ground crossing is interpolated. A hitscan's shot at a disc or a sphere steps the same way,
 * swept against its target ({@link Sweep}). Allocates nothing once made.
 */
public final class Flight {

    /** What {@link #step} returns for a step that did not reach the ground. */
    public static final double NO_LANDING = Surface.NO_HIT;

    /** A target a step's straight segment is swept against (a plane, a sphere). */
    @FunctionalInterface
    public interface Sweep {
        /**
         * Find where a segment first reaches the target.
         *
         * @param from the particle's position before the step (m; not null, unmodified)
         * @param to its position after the step (m; not null, unmodified)
         * @return where inside the step it reached the target (0 to 1), or
         *     {@link #NO_LANDING}
         */
        double sweep(Vector3f from, Vector3f to);
    }

    private ParticleIntegrator integrator;
    private final Plane ground = Plane.ground();
    /** Scratch: the particle's position before the step (m). */
    private final Vector3f previous = new Vector3f();
    /** Scratch: the ground's normal at the crossing (unused). */
    private final Vector3f normal = new Vector3f();
    /** The position after the last step (m), for {@link #crossingX}. */
    private final Vector3f current = new Vector3f();

    /**
     * Create a flight for the particles of one scene.
     *
     * @param integrator the scene's integrator, with its forces (not null)
     */
    public Flight(ParticleIntegrator integrator) {
        this.integrator = Validate.notNull(integrator, "integrator");
    }

    /**
     * Fly the particles of another scene from now on (no allocation).
     *
     * @param newIntegrator that scene's integrator (not null)
     */
    public void setIntegrator(ParticleIntegrator newIntegrator) {
        integrator = Validate.notNull(newIntegrator, "integrator");
    }

    /**
     * Take one step of the particle and tell whether it came down through the ground.
     *
     * @param particle the particle (not null, modified: stepped)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @return where inside the step it reached the ground (0 to 1), or {@link #NO_LANDING}
     */
    public double step(Particle particle, float stepSeconds) {
        previous.set(particle.position);
        integrator.step(particle, stepSeconds);
        current.set(particle.position);
        return ground.sweep(previous, current, 0f, normal);
    }

    /**
     * Take one step of the particle and tell whether its segment reached a target other than
     * the ground (a hitscan's disc or sphere).
     *
     * @param particle the particle (not null, modified: stepped)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @param target what the segment is swept against (not null)
     * @return where inside the step it reached the target (0 to 1), or {@link #NO_LANDING}
     */
    public double step(Particle particle, float stepSeconds, Sweep target) {
        previous.set(particle.position);
        integrator.step(particle, stepSeconds);
        current.set(particle.position);
        return target.sweep(previous, current);
    }

    /**
     * Return x where the last step's segment reached the ground (or the target).
     *
     * @param fraction what {@link #step} returned (0 to 1)
     * @return x at that point of the segment (in metres, in double)
     */
    public double crossingX(double fraction) {
        return previous.x + fraction * ((double) current.x - previous.x);
    }

    /**
     * Return y where the last step's segment reached the target.
     *
     * @param fraction what {@link #step} returned (0 to 1)
     * @return y at that point of the segment (in metres, in double)
     */
    public double crossingY(double fraction) {
        return previous.y + fraction * ((double) current.y - previous.y);
    }

    /**
     * Step the particle while it rises ({@code V.y > 0}), at most maxSteps steps: it stops at
     * the first state whose velocity no longer points up, the step after the highest state
     * of the stepped path (lower than it by at most {@code h·|V.y|}). Allocates nothing.
     *
     * @param particle the particle (not null, modified: stepped)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @param maxSteps give up after this many steps (&ge;0)
     * @return the number of steps taken (0 if it was not rising)
     */
    public int climb(Particle particle, float stepSeconds, int maxSteps) {
        int steps = 0;
        while (steps < maxSteps && particle.velocity.y > 0f) {
            integrator.step(particle, stepSeconds);
            ++steps;
        }
        return steps;
    }

    /**
     * Step the particle with a fixed h until it lands, and say where and when.
     *
     * @param particle the particle, at its launch (its y should be &ge;0; not null, modified:
     *     left at the end of its last step)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @param maxSteps give up after this many steps (&ge;1)
     * @param storeResult storage for where it landed (not null, modified)
     * @return true if it landed within maxSteps
     */
    public boolean fly(Particle particle, float stepSeconds, int maxSteps, Landing storeResult) {
        for (int step = 1; step <= maxSteps; ++step) {
            double fraction = step(particle, stepSeconds);
            if (fraction != NO_LANDING) {
                double time = (step - 1 + fraction) * stepSeconds;
                storeResult.set(true, crossingX(fraction), time, step);
                return true;
            }
        }
        storeResult.set(false, Double.NaN, Double.NaN, maxSteps);
        return false;
    }
}

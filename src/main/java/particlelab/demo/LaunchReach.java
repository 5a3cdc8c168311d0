package particlelab.demo;

import particlelab.aiming.Flight;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * The region of the x-y plane the current launches reach before they land, for the camera to
 * frame: each particle that stops at the ground is flown ahead, on a scratch copy, with its
 * own integrator and the demo's step h until it comes down through {@code y = 0}, so the box
 * holds the very path the demo will step, whatever the forces (gravity, drag, thrust, wind)
 * and whatever launch speed, angle or coefficients the parameters set. Without drag the
 * apex is near {@code vy²/2g}; with drag lower, so this is never larger than needed.
 *
 * <p>A flight that does not come down within {@value #MAX_STEPS} steps (thrust outrunning
 * gravity) or blows up is left out of the box: there is no landing to frame. Allocates
 * nothing.
 */
final class LaunchReach {

    /** The longest flight flown ahead (steps): 5.5 minutes at 60 steps per second. */
    static final int MAX_STEPS = 20_000;

    private final Particle scratch = new Particle();
    /** Flies the launches ahead, each with its own particle's integrator. */
    private final Flight flight = new Flight(new ParticleIntegrator());
    private float xMin;
    private float xMax;
    private float yMax;
    private boolean empty = true;

    /** Forget every flight: the box is empty. */
    void clear() {
        empty = true;
    }

    /**
     * Fly a particle ahead from its state now and widen the box by its path, if it lands.
     *
     * @param particle the demo particle, at its launch (not null, not modified)
     * @param stepSeconds the demo's step h (in seconds, &gt;0)
     * @return true if it landed within {@value #MAX_STEPS} steps (the box now holds its path)
     */
    boolean include(DemoParticle particle, float stepSeconds) {
        flight.setIntegrator(particle.getIntegrator());
        scratch.copyFrom(particle.getParticle());
        float left = scratch.position.x;
        float right = left;
        float top = scratch.position.y;
        try {
            for (int n = 0; n < MAX_STEPS; ++n) {
                double landing = flight.step(scratch, stepSeconds);
                left = Math.min(left, scratch.position.x);
                right = Math.max(right, scratch.position.x);
                top = Math.max(top, scratch.position.y);
                if (landing != Flight.NO_LANDING) {
                    widen(left, right, top);
                    return true;
                }
            }
        } catch (NonFiniteStepException blowUp) {
            return false;
        }
        return false;
    }

    /** @return true if no flight widened the box since {@link #clear()} */
    boolean isEmpty() {
        return empty;
    }

    /** @return the box's left edge (in metres) */
    float getXMin() {
        return xMin;
    }

    /** @return the box's right edge (in metres) */
    float getXMax() {
        return xMax;
    }

    /** @return the box's top (in metres) */
    float getYMax() {
        return yMax;
    }

    private void widen(float left, float right, float top) {
        if (empty) {
            xMin = left;
            xMax = right;
            yMax = top;
            empty = false;
        } else {
            xMin = Math.min(xMin, left);
            xMax = Math.max(xMax, right);
            yMax = Math.max(yMax, top);
        }
    }
}

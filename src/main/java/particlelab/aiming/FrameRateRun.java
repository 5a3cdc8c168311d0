package particlelab.aiming;

import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.physics.Validate;

/**
 * One launch flown by the game loop of a monitor refreshing at {@code f} Hz: each frame hands
 * the app's own {@link SimulationClock} a frame time, {@code 1/f} or a jittered draw around it
 * ({@link FrameJitter}), and the clock turns it into steps as the app's demos do:
 * <ul>
 * <li>{@link SimulationClock.Mode#RAW_TPF}, the lecture's loop {@code P += tpf·V}: one step
 * of the frame time per frame, so the path depends on the monitor;</li>
 * <li>{@link SimulationClock.Mode#FIXED_STEP}, the cure: steps of a fixed {@code h} from an
 * accumulator, the same steps at every rate.</li>
 * </ul>
 * Each step is the shared integrator's, swept against the ground by {@link Flight}, the
 * crossing interpolated inside the step that reached it. A level shot under gravity alone
 * lands {@code vx·h} short of the parabola's range (docs/numerics: the samples lie on the
 * parabola launched with {@code vy − g·h/2}), so at 30 Hz the raw loop lands {@code vx/30}
 * short and at 240 Hz {@code vx/240}. Allocates nothing once made.
 */
public final class FrameRateRun {

    /** The most frames one run takes before it gives up on a landing. */
    public static final int MAX_FRAMES = 1_000_000;

    private final SimulationClock clock = new SimulationClock();
    private final Flight flight;
    private final Particle particle = new Particle();
    private final Landing landing = new Landing();
    /** The clock's stepper, made once: one step of the flight until it lands. */
    private final SimulationClock.Stepper stepper = this::stepOnce;
    private float rateHz = 60f;
    private int steps;
    private double flownSeconds;
    private boolean landed;

    /**
     * Create a run flown with one scene's forces.
     *
     * @param integrator the scene's integrator (not null; shared, not modified)
     */
    public FrameRateRun(ParticleIntegrator integrator) {
        flight = new Flight(integrator);
    }

    /**
     * Return the frame time of a monitor at {@code f} Hz as the app and {@code trajectory
     * --tpf 1/f} both make it: {@code 1/f} in double, rounded once to float.
     *
     * @param rateHz the refresh rate (in Hz, finite, &gt;0)
     * @return the frame time (in seconds)
     */
    public static float frameSeconds(float rateHz) {
        Validate.positive(rateHz, "refresh rate (Hz)");
        return (float) (1.0 / rateHz);
    }

    /**
     * Put the run at a launch, no frame taken yet (no allocation).
     *
     * @param launch the particle at its launch (y &ge; 0; not null, copied)
     * @param newRateHz the monitor's refresh rate (in Hz, finite, &gt;0)
     * @param mode how the clock turns frames into steps (not null)
     * @param fixedStepSeconds h for {@link SimulationClock.Mode#FIXED_STEP} (in seconds, &gt;0)
     */
    public void start(Particle launch, float newRateHz, SimulationClock.Mode mode,
            float fixedStepSeconds) {
        rateHz = Validate.positive(newRateHz, "refresh rate (Hz)");
        particle.copyFrom(launch);
        clock.reset();
        clock.setMode(mode);
        clock.setStepSeconds(fixedStepSeconds);
        steps = 0;
        flownSeconds = 0.0;
        landed = false;
        landing.set(false, Double.NaN, Double.NaN, 0);
    }

    /**
     * Hand the clock one frame of the given time (nothing once landed). No allocation.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    public void frame(float tpf) {
        if (!landed) {
            clock.advance(tpf, stepper);
        }
    }

    /**
     * Hand the clock unjittered frames of {@code 1/f} until the run lands or
     * {@link #MAX_FRAMES} frames have passed.
     *
     * @return true if it landed
     */
    public boolean flyToLanding() {
        float tpf = frameSeconds(rateHz);
        for (int n = 0; n < MAX_FRAMES && !landed; ++n) {
            frame(tpf);
        }
        return landed;
    }

    /**
     * Hand the clock jittered frames until the run lands or {@link #MAX_FRAMES} frames have
     * passed.
     *
     * @param jitter the frame-time draws (not null, modified: drawn from)
     * @return true if it landed
     */
    public boolean flyToLanding(FrameJitter jitter) {
        float tpf = frameSeconds(rateHz);
        for (int n = 0; n < MAX_FRAMES && !landed; ++n) {
            frame(jitter.next(tpf));
        }
        return landed;
    }

    /**
     * Access the run's particle: after the last step taken.
     *
     * @return the live particle (do not modify)
     */
    public Particle getParticle() {
        return particle;
    }

    /**
     * Access where the run landed.
     *
     * @return the live landing (not landed before it lands; do not modify)
     */
    public Landing getLanding() {
        return landing;
    }

    /**
     * Test whether the run has come down through the ground.
     *
     * @return true once landed
     */
    public boolean hasLanded() {
        return landed;
    }

    /**
     * Return the steps taken so far.
     *
     * @return the count (&ge;0)
     */
    public int getSteps() {
        return steps;
    }

    /**
     * Return the simulated time so far, the sum of the steps' lengths (at the landing: the
     * end of the step that reached the ground).
     *
     * @return the time (in seconds)
     */
    public double getSimulatedSeconds() {
        return flownSeconds;
    }

    /**
     * Return the monitor's refresh rate.
     *
     * @return f (in Hz)
     */
    public float getRateHz() {
        return rateHz;
    }

    /**
     * Return how the clock steps.
     *
     * @return the mode (not null)
     */
    public SimulationClock.Mode getMode() {
        return clock.getMode();
    }

    /** One step of the clock's: the flight's, then the landing if it reached the ground. */
    private void stepOnce(float stepSeconds) {
        if (landed) {
            return;
        }
        double fraction = flight.step(particle, stepSeconds);
        ++steps;
        if (fraction != Flight.NO_LANDING) {
            landed = true;
            landing.set(true, flight.crossingX(fraction), flownSeconds + fraction * stepSeconds,
                    steps);
        }
        flownSeconds += stepSeconds;
    }
}

package particlelab.accuracy;

import com.jme3.math.Vector3f;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Spring;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.Scheme;
import particlelab.reference.Stepper;


/**
 * Measures the largest stable step of a method under gravity plus linear drag, by bisection,
 * and of the shared integrator on a damped spring.
 *
 * <p>A trial starts the particle away from its terminal velocity {@code V* = g/k} and takes a
 * fixed number of steps; it is stable if the distance from V* has not grown. Divergence is thus
 * detected by growth, long before any value becomes NaN; a shared-integrator step that does go
 * non-finite throws {@link NonFiniteStepException}, which counts as unstable too. Every method
 * here is stable below its limit and unstable above it, so bisection applies.
 *
 * <p>The spring series steps the demos' own {@link ParticleIntegrator} (float) with a
 * {@link Spring} of rest length 0, anchored at the origin, on a particle moving along x: the
 * force is then exactly {@code −k·x − c·v}, the damped oscillator whose limit theory gives as
 * {@link ParticleIntegrator#stableStepLimit}. A trial starts {@value #SPRING_OFFSET} m from the
 * anchor at rest and is stable if its swing {@code sqrt(ω²x² + v²)} has not grown.
 */
public final class StabilityMap {

    /** Steps per trial: near the limit a factor 1.0001 per step grows by 20% in 2000 steps. */
    public static final int TRIAL_STEPS = 2000;
    /** The largest step tried, in units of m/b; a method stable there is reported infinite. */
    public static final double CEILING_FACTOR = 1000.0;
    /** Bisection stops when the bracket is this narrow relative to the step. */
    public static final double RELATIVE_TOLERANCE = 1e-6;

    /** The stiffness k/m of the map's spring series (in 1/s²): ω = 10 rad/s, 2/ω = 0.2 s. */
    public static final double SPRING_STIFFNESS = 100.0;
    /** Where a spring trial starts, from the anchor (in metres). */
    public static final float SPRING_OFFSET = 1f;

    private static final double LAUNCH_OFFSET = 10.0;

    private StabilityMap() {
    }

    /**
     * Find the largest stable step.
     *
     * @param scheme the method (not null)
     * @param linearRate k = b/m (in 1/s, finite, &gt;0)
     * @param gDown the pull of gravity (in m/s², finite, &ge;0)
     * @return the largest stable h (in seconds), or positive infinity if stable at
     *     {@link #CEILING_FACTOR}·m/b
     */
    public static double maxStableStep(Scheme scheme, double linearRate, double gDown) {
        if (!(linearRate > 0.0) || linearRate == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "linear rate b/m (1/s) must be finite and > 0, but was " + linearRate);
        }
        ForceModel forces = ForceModel.perUnitMass(gDown, linearRate, 0.0, 0.0);
        Stepper stepper = scheme.create(forces);
        double stable = 0.0;
        double unstable = CEILING_FACTOR / linearRate;
        if (isStable(stepper, forces, unstable)) {
            return Double.POSITIVE_INFINITY;
        }
        while (unstable - stable > RELATIVE_TOLERANCE * unstable) {
            double mid = 0.5 * (stable + unstable);
            if (isStable(stepper, forces, mid)) {
                stable = mid;
            } else {
                unstable = mid;
            }
        }
        return stable;
    }

    /**
     * Run one trial: is the step stable?
     *
     * @param stepper the method bound to the forces (not null)
     * @param forces gravity plus linear drag (not null, k &gt; 0)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return true if the distance from the terminal velocity did not grow
     */
    public static boolean isStable(Stepper stepper, ForceModel forces, double stepSeconds) {
        double k = forces.linearRate();
        double terminalX = forces.gravity(0) / k;
        double terminalY = forces.gravity(1) / k;
        MotionState state = new MotionState(0.0, 0.0,
                terminalX + LAUNCH_OFFSET, terminalY + LAUNCH_OFFSET);
        double before = Math.hypot(state.velocity[0] - terminalX, state.velocity[1] - terminalY);
        try {
            stepper.advance(state, stepSeconds, TRIAL_STEPS);
        } catch (NonFiniteStepException nonFinite) {
            return false;
        }
        double after = Math.hypot(state.velocity[0] - terminalX, state.velocity[1] - terminalY);
        return after <= before;
    }

    /**
     * Find the largest stable step of the shared integrator on a damped spring, by bisection.
     *
     * @param dampingRate λ = c/m (in 1/s, finite, &gt;0: without damping the step is only
     *     marginally stable, and a trial cannot tell bounded from slowly growing)
     * @param stiffness ω² = k/m (in 1/s², finite, &gt;0)
     * @return the largest stable h (in seconds)
     */
    public static double maxStableStepSpring(double dampingRate, double stiffness) {
        if (!(dampingRate > 0.0) || dampingRate == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "damping rate c/m (1/s) must be finite and > 0, but was " + dampingRate);
        }
        if (!(stiffness > 0.0) || stiffness == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "stiffness k/m (1/s^2) must be finite and > 0, but was " + stiffness);
        }
        double stable = 0.0;
        // Above every limit of the oscillator (2/λ and 2/ω both exceed it), not from theory.
        double unstable = CEILING_FACTOR / (dampingRate + Math.sqrt(stiffness));
        while (unstable - stable > RELATIVE_TOLERANCE * unstable) {
            double mid = 0.5 * (stable + unstable);
            if (isSpringStable(dampingRate, stiffness, mid)) {
                stable = mid;
            } else {
                unstable = mid;
            }
        }
        return stable;
    }

    /**
     * Run one spring trial: is the step stable?
     *
     * @param dampingRate λ = c/m (in 1/s, &ge;0)
     * @param stiffness ω² = k/m (in 1/s², &gt;0)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return true if the swing did not grow in {@link #TRIAL_STEPS} steps
     */
    public static boolean isSpringStable(double dampingRate, double stiffness,
            double stepSeconds) {
        Particle particle = new Particle(new Vector3f(SPRING_OFFSET, 0f, 0f), Vector3f.ZERO, 1f);
        ParticleIntegrator integrator = new ParticleIntegrator(
                new Spring(Vector3f.ZERO, 0f, (float) stiffness, (float) dampingRate));
        double before = swing(particle, stiffness);
        try {
            for (int n = 0; n < TRIAL_STEPS; ++n) {
                integrator.step(particle, (float) stepSeconds);
            }
        } catch (NonFiniteStepException nonFinite) {
            return false;
        }
        return swing(particle, stiffness) <= before;
    }

    private static double swing(Particle particle, double stiffness) {
        double x = particle.position.x;
        double v = particle.velocity.x;
        return Math.sqrt(stiffness * x * x + v * v);
    }
}

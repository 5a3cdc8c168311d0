package particlelab.accuracy;

import particlelab.physics.NonFiniteStepException;

/**
 * Measures the largest stable step of a method under gravity plus linear drag, by bisection.
 *
 * <p>A trial starts the particle away from its terminal velocity {@code V* = g/k} and takes a
 * fixed number of steps; it is stable if the distance from V* has not grown. Divergence is thus
 * detected by growth, long before any value becomes NaN; a shared-integrator step that does go
 * non-finite throws {@link NonFiniteStepException}, which counts as unstable too. Every method
 * here is stable below its limit and unstable above it, so bisection applies.
 */
public final class StabilityMap {

    /** Steps per trial: near the limit a factor 1.0001 per step grows by 20% in 2000 steps. */
    public static final int TRIAL_STEPS = 2000;
    /** The largest step tried, in units of m/b; a method stable there is reported infinite. */
    public static final double CEILING_FACTOR = 1000.0;
    /** Bisection stops when the bracket is this narrow relative to the step. */
    public static final double RELATIVE_TOLERANCE = 1e-6;

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
}

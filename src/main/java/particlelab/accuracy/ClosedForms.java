package particlelab.accuracy;

import particlelab.reference.ExactDragStep;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.RungeKutta4;

/**
 * Reference solutions in double precision: the continuous closed form for gravity plus linear
 * drag, and a high-accuracy numerical solution for scenes without one.
 */
public final class ClosedForms {

    /**
     * RK4 steps per second for {@link #reference}: h = 1/30720 s, where RK4's truncation error
     * (about {@code h⁴}, below 1e-17 relative) lies far below double round-off.
     */
    public static final int REFERENCE_STEPS_PER_SECOND = 30720;

    private ClosedForms() {
    }

    /**
     * Solve gravity plus linear drag exactly. With {@code k = b/m} the textbook form is
     *
     * <pre>
     *   V(t) = V* + (V0 − V*)·e^{−kt},   P(t) = P0 + V*·t + (V0 − V*)·(1 − e^{−kt})/k
     * </pre>
     *
     * with terminal velocity {@code V* = g/k}; it cancels digits when k·t is small (V* is
     * huge), so it is evaluated in the equivalent form
     * {@code V(t) = e^{−kt}·V0 + t·φ1(kt)·g}, {@code P(t) = P0 + t·φ1(kt)·V0 + t²·φ2(kt)·g},
     * which holds for every k ≥ 0 (k = 0: the parabola).
     *
     * @param forces the scene (not null, {@link ForceModel#hasClosedForm()})
     * @param initial the state at t = 0 (not null, not modified)
     * @param timeSeconds t (in seconds, finite, &ge;0)
     * @param storeResult storage for the state at t (not null, modified; may be initial)
     * @return storeResult
     */
    public static MotionState gravityLinearDrag(ForceModel forces, MotionState initial,
            double timeSeconds, MotionState storeResult) {
        if (!forces.hasClosedForm()) {
            throw new IllegalArgumentException("no closed form for the forces "
                    + forces.describe() + ": only gravity + linear drag has one");
        }
        double t = timeSeconds;
        double z = forces.linearRate() * t;
        double decay = Math.exp(-z);
        double phi1 = ExactDragStep.phi1(z);
        double phi2 = ExactDragStep.phi2(z);
        for (int i = 0; i < 3; ++i) {
            double g = forces.gravity(i);
            double p0 = initial.position[i];
            double v0 = initial.velocity[i];
            storeResult.position[i] = p0 + t * phi1 * v0 + t * t * phi2 * g;
            storeResult.velocity[i] = decay * v0 + t * phi1 * g;
        }
        return storeResult;
    }

    /**
     * Calculate the reference state at time t: the closed form where the scene has one,
     * otherwise RK4 with {@link #REFERENCE_STEPS_PER_SECOND} steps per second.
     *
     * @param forces the scene (not null)
     * @param initial the state at t = 0 (not null, not modified)
     * @param timeSeconds t (in seconds, finite, &ge;0)
     * @param storeResult storage for the state at t (not null, modified)
     * @return storeResult
     */
    public static MotionState reference(ForceModel forces, MotionState initial,
            double timeSeconds, MotionState storeResult) {
        if (forces.hasClosedForm()) {
            return gravityLinearDrag(forces, initial, timeSeconds, storeResult);
        }
        int steps = (int) Math.ceil(timeSeconds * REFERENCE_STEPS_PER_SECOND);
        MotionState state = new MotionState().set(initial);
        if (steps > 0) {
            new RungeKutta4(forces).advance(state, timeSeconds / steps, steps);
        }
        return storeResult.set(state);
    }

    /**
     * Find when a level shot under gravity plus linear drag lands, from the closed form: the
     * first time after launch at which y is back at the launch height, by bisection then
     * Newton's method, to full double precision.
     *
     * @param forces the scene (not null, closed form, g.y &lt; 0)
     * @param launch the state at launch (not null, not modified, V.y &gt; 0)
     * @return the flight time (in seconds, &gt;0)
     */
    public static double landingTime(ForceModel forces, MotionState launch) {
        if (!(launch.velocity[1] > 0.0) || !(forces.gravity(1) < 0.0)) {
            throw new IllegalArgumentException("a level shot needs V.y > 0 and g.y < 0, but V.y"
                    + " was " + launch.velocity[1] + " and g.y " + forces.gravity(1));
        }
        MotionState at = new MotionState();
        double height = launch.position[1];
        // y(t) rises then falls: double the time until it is below the launch height
        double late = 1e-3;
        while (gravityLinearDrag(forces, launch, late, at).position[1] > height) {
            late *= 2.0;
        }
        double early = late / 2.0;
        for (int i = 0; i < 200 && late - early > 1e-15 * late; ++i) {
            double mid = 0.5 * (early + late);
            if (gravityLinearDrag(forces, launch, mid, at).position[1] > height) {
                early = mid;
            } else {
                late = mid;
            }
        }
        double t = 0.5 * (early + late);
        for (int i = 0; i < 3; ++i) {
            gravityLinearDrag(forces, launch, t, at);
            t -= (at.position[1] - height) / at.velocity[1];
        }
        return t;
    }
}

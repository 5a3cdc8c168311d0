package particlelab.reference;

/**
 * Velocity Verlet as games write it, in double precision:
 *
 * <pre>
 *   a0 = a(V)                          forces at the start of the step
 *   V½ = V + ½h·a0;   P ← P + h·V½     (that is, P + h·V + ½h²·a0)
 *   a1 = a(V½)                         "forces at the new position": the only V at hand is V½
 *   V  ← V½ + ½h·a1
 * </pre>
 *
 * For forces of position only this is the second-order, symplectic velocity Verlet. Drag
 * depends on the velocity, and evaluating it at V½ makes the velocity update
 * {@code V ← (1 − k·h/2)²·V} under linear drag: first order (the exact factor is
 * {@code e^{−kh} = 1 − kh + k²h²/2 − …}), but stable to {@code h < 4m/b}.
 */
public final class VelocityVerlet implements Stepper {

    private final ForceModel forces;
    private final double[] acceleration = new double[3];

    /**
     * Create a velocity-Verlet stepper.
     *
     * @param forces the scene's forces (not null)
     */
    public VelocityVerlet(ForceModel forces) {
        this.forces = Steppers.require(forces);
    }

    @Override
    public Scheme scheme() {
        return Scheme.VELOCITY_VERLET;
    }

    @Override
    public void step(MotionState state, double stepSeconds) {
        double[] p = state.position;
        double[] v = state.velocity;
        double halfStep = 0.5 * stepSeconds;
        forces.acceleration(v, acceleration);
        for (int i = 0; i < 3; ++i) {
            v[i] += halfStep * acceleration[i];
            p[i] += stepSeconds * v[i];
        }
        forces.acceleration(v, acceleration);
        for (int i = 0; i < 3; ++i) {
            v[i] += halfStep * acceleration[i];
        }
    }

    @Override
    public void advance(MotionState state, double stepSeconds, int steps) {
        for (int n = 0; n < steps; ++n) {
            step(state, stepSeconds);
        }
    }
}

package particlelab.reference;

/**
 * The explicit midpoint method, a second-order Runge–Kutta method, in double precision:
 *
 * <pre>
 *   Vm = V + ½h·a(V)          the velocity half a step ahead
 *   P ← P + h·Vm;   V ← V + h·a(Vm)
 * </pre>
 *
 * Under linear drag the velocity factor is {@code 1 − kh + (kh)²/2}: second order, stable for
 * {@code h < 2m/b}.
 */
public final class MidpointStepper implements Stepper {

    private final ForceModel forces;
    private final double[] acceleration = new double[3];
    private final double[] midVelocity = new double[3];

    /**
     * Create a midpoint stepper.
     *
     * @param forces the scene's forces (not null)
     */
    public MidpointStepper(ForceModel forces) {
        this.forces = Steppers.require(forces);
    }

    @Override
    public Scheme scheme() {
        return Scheme.MIDPOINT;
    }

    @Override
    public void step(MotionState state, double stepSeconds) {
        double[] p = state.position;
        double[] v = state.velocity;
        forces.acceleration(v, acceleration);
        for (int i = 0; i < 3; ++i) {
            midVelocity[i] = v[i] + 0.5 * stepSeconds * acceleration[i];
        }
        forces.acceleration(midVelocity, acceleration);
        for (int i = 0; i < 3; ++i) {
            p[i] += stepSeconds * midVelocity[i];
            v[i] += stepSeconds * acceleration[i];
        }
    }

    @Override
    public void advance(MotionState state, double stepSeconds, int steps) {
        for (int n = 0; n < steps; ++n) {
            step(state, stepSeconds);
        }
    }
}

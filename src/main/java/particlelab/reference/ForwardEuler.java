package particlelab.reference;

/**
 * Forward (explicit) Euler, in double precision: both updates use the state at the start of
 * the step, so the position moves with the <em>old</em> velocity.
 *
 * <pre>
 *   a = a(V);   P ← P + h·V;   V ← V + h·a
 * </pre>
 *
 * First order; stable under linear drag for {@code h < 2m/b}. A level shot lands
 * {@code vx·h} long (the lecture's semi-implicit step lands it {@code vx·h} short).
 */
public final class ForwardEuler implements Stepper {

    private final ForceModel forces;
    private final double[] acceleration = new double[3];

    /**
     * Create a forward-Euler stepper.
     *
     * @param forces the scene's forces (not null)
     */
    public ForwardEuler(ForceModel forces) {
        this.forces = Steppers.require(forces);
    }

    @Override
    public Scheme scheme() {
        return Scheme.FORWARD_EULER;
    }

    @Override
    public void step(MotionState state, double stepSeconds) {
        double[] p = state.position;
        double[] v = state.velocity;
        forces.acceleration(v, acceleration);
        for (int i = 0; i < 3; ++i) {
            p[i] += stepSeconds * v[i];
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

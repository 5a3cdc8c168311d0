package particlelab.reference;

/**
 * The classic fourth-order Runge–Kutta method, in double precision. The forces depend on V
 * only, so each stage needs a velocity and its acceleration:
 *
 * <pre>
 *   V1 = V;            A1 = a(V1)
 *   V2 = V + ½h·A1;    A2 = a(V2)
 *   V3 = V + ½h·A2;    A3 = a(V3)
 *   V4 = V + h·A3;     A4 = a(V4)
 *   P ← P + h/6·(V1 + 2V2 + 2V3 + V4);   V ← V + h/6·(A1 + 2A2 + 2A3 + A4)
 * </pre>
 *
 * Stable under linear drag for {@code h < 2.785293563405282·m/b}.
 */
public final class RungeKutta4 implements Stepper {

    private final ForceModel forces;
    private final double[] stageVelocity = new double[3];
    private final double[] stageAcceleration = new double[3];
    private final double[] velocitySum = new double[3];
    private final double[] accelerationSum = new double[3];

    /**
     * Create an RK4 stepper.
     *
     * @param forces the scene's forces (not null)
     */
    public RungeKutta4(ForceModel forces) {
        this.forces = Steppers.require(forces);
    }

    @Override
    public Scheme scheme() {
        return Scheme.RUNGE_KUTTA_4;
    }

    @Override
    public void step(MotionState state, double stepSeconds) {
        double[] p = state.position;
        double[] v = state.velocity;
        double halfStep = 0.5 * stepSeconds;
        // stage 1
        forces.acceleration(v, stageAcceleration);
        for (int i = 0; i < 3; ++i) {
            velocitySum[i] = v[i];
            accelerationSum[i] = stageAcceleration[i];
            stageVelocity[i] = v[i] + halfStep * stageAcceleration[i];
        }
        // stage 2
        forces.acceleration(stageVelocity, stageAcceleration);
        for (int i = 0; i < 3; ++i) {
            velocitySum[i] += 2.0 * stageVelocity[i];
            accelerationSum[i] += 2.0 * stageAcceleration[i];
            stageVelocity[i] = v[i] + halfStep * stageAcceleration[i];
        }
        // stage 3
        forces.acceleration(stageVelocity, stageAcceleration);
        for (int i = 0; i < 3; ++i) {
            velocitySum[i] += 2.0 * stageVelocity[i];
            accelerationSum[i] += 2.0 * stageAcceleration[i];
            stageVelocity[i] = v[i] + stepSeconds * stageAcceleration[i];
        }
        // stage 4
        forces.acceleration(stageVelocity, stageAcceleration);
        double sixth = stepSeconds / 6.0;
        for (int i = 0; i < 3; ++i) {
            p[i] += sixth * (velocitySum[i] + stageVelocity[i]);
            v[i] += sixth * (accelerationSum[i] + stageAcceleration[i]);
        }
    }

    @Override
    public void advance(MotionState state, double stepSeconds, int steps) {
        for (int n = 0; n < steps; ++n) {
            step(state, stepSeconds);
        }
    }
}

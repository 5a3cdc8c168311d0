package particlelab.reference;

/**
 * The exact update for gravity plus linear drag, the exponential step: with {@code k = b/m}
 * and {@code z = k·h},
 *
 * <pre>
 *   V' = e^{−z}·V + h·φ1(z)·g
 *   P' = P + h·φ1(z)·V + h²·φ2(z)·g
 *   φ1(z) = (1 − e^{−z})/z,   φ2(z) = (z − 1 + e^{−z})/z²     (φ1(0) = 1, φ2(0) = ½)
 * </pre>
 *
 * No truncation error for any h, so its error is round-off only, and it is stable for every
 * h. It exists only for scenes with a closed form ({@link ForceModel#hasClosedForm()}).
 */
public final class ExactDragStep implements Stepper {

    /** Below this z, φ2 comes from its series: the closed form would cancel digits. */
    private static final double SERIES_BELOW = 1e-2;

    private final double linearRate;
    private final double gravityX;
    private final double gravityY;
    private final double gravityZ;
    /** The step size the cached factors are for (NaN before the first step). */
    private double cachedStep = Double.NaN;
    private double decay;
    private double gravityFactor;
    private double positionVelocityFactor;
    private double positionGravityFactor;

    /**
     * Create an exact stepper.
     *
     * @param forces the scene's forces (not null, gravity and linear drag only)
     */
    public ExactDragStep(ForceModel forces) {
        Steppers.require(forces);
        if (!forces.hasClosedForm()) {
            throw new IllegalArgumentException("the exact step needs gravity + linear drag only,"
                    + " but the forces were " + forces.describe());
        }
        this.linearRate = forces.linearRate();
        this.gravityX = forces.gravity(0);
        this.gravityY = forces.gravity(1);
        this.gravityZ = forces.gravity(2);
    }

    /**
     * Calculate {@code φ1(z) = (1 − e^{−z})/z} without cancellation.
     *
     * @param z k·h (&ge;0)
     * @return φ1(z), 1 at z = 0
     */
    public static double phi1(double z) {
        if (z == 0.0) {
            return 1.0;
        }
        return -Math.expm1(-z) / z;
    }

    /**
     * Calculate {@code φ2(z) = (z − 1 + e^{−z})/z²} without cancellation: for small z from its
     * series {@code Σ (−z)ⁿ/(n+2)!}, whose first omitted term is below 1e-20 there.
     *
     * @param z k·h (&ge;0)
     * @return φ2(z), ½ at z = 0
     */
    public static double phi2(double z) {
        if (z < SERIES_BELOW) {
            double term = 0.5;
            double sum = term;
            for (int n = 1; n <= 6; ++n) {
                term *= -z / (n + 2);
                sum += term;
            }
            return sum;
        }
        return (z + Math.expm1(-z)) / (z * z);
    }

    @Override
    public Scheme scheme() {
        return Scheme.EXACT;
    }

    @Override
    public void step(MotionState state, double stepSeconds) {
        if (stepSeconds != cachedStep) {
            cacheFactors(stepSeconds);
        }
        double[] p = state.position;
        double[] v = state.velocity;
        for (int i = 0; i < 3; ++i) {
            double g = i == 0 ? gravityX : i == 1 ? gravityY : gravityZ;
            p[i] += positionVelocityFactor * v[i] + positionGravityFactor * g;
            v[i] = decay * v[i] + gravityFactor * g;
        }
    }

    @Override
    public void advance(MotionState state, double stepSeconds, int steps) {
        for (int n = 0; n < steps; ++n) {
            step(state, stepSeconds);
        }
    }

    private void cacheFactors(double stepSeconds) {
        double z = linearRate * stepSeconds;
        double phi1 = phi1(z);
        decay = Math.exp(-z);
        gravityFactor = stepSeconds * phi1;
        positionVelocityFactor = stepSeconds * phi1;
        positionGravityFactor = stepSeconds * stepSeconds * phi2(z);
        cachedStep = stepSeconds;
    }
}

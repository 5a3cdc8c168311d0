package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * The two launch angles that hit a target at any height with a fixed launch speed s, no drag:
 * {@code tan θ = (s² ∓ sqrt(s⁴ − g·(g·x² + 2·y·s²)))/(g·x)}. A negative discriminant means
 * the target is out of reach at that speed.
 */
public final class LaunchAngles {

    private final boolean reachable;
    private final double lowRadians;
    private final double highRadians;
    private final String explanation;

    private LaunchAngles(boolean reachable, double lowRadians, double highRadians,
            String explanation) {
        this.reachable = reachable;
        this.lowRadians = lowRadians;
        this.highRadians = highRadians;
        this.explanation = explanation;
    }

    /**
     * Solve for the angles.
     *
     * @param launchSpeed s (in m/s, finite, &gt;0)
     * @param targetDistance x, the horizontal distance to the target (in metres, finite, &gt;0)
     * @param targetHeight y, the target's height above the gun (in metres, finite)
     * @param gravity g (in m/s², finite, &gt;0)
     * @return the low and high angles, or an out-of-reach answer (not null)
     */
    public static LaunchAngles solve(double launchSpeed, double targetDistance,
            double targetHeight, double gravity) {
        Validate.positive(launchSpeed, "launch speed s (m/s)");
        Validate.positive(targetDistance, "target distance x (m)");
        Validate.finite(targetHeight, "target height y (m)");
        Validate.positive(gravity, "gravity g (m/s^2)");
        double s2 = launchSpeed * launchSpeed;
        double discriminant = s2 * s2 - gravity
                * (gravity * targetDistance * targetDistance + 2.0 * targetHeight * s2);
        if (discriminant < 0.0) {
            return new LaunchAngles(false, Double.NaN, Double.NaN, String.format(
                    "target at (%s m, %s m) is out of reach at launch speed %s m/s"
                            + " (no real angle: s^4 - g(g x^2 + 2 y s^2) = %s < 0)",
                    targetDistance, targetHeight, launchSpeed, discriminant));
        }
        double root = Math.sqrt(discriminant);
        double gx = gravity * targetDistance;
        double low = Math.atan((s2 - root) / gx);
        double high = Math.atan((s2 + root) / gx);
        return new LaunchAngles(true, low, high, "reachable");
    }

    /**
     * Test whether any angle reaches the target.
     *
     * @return true if reachable
     */
    public boolean isReachable() {
        return reachable;
    }

    /**
     * Return the low (flat) angle above the horizontal.
     *
     * @return the angle (in radians; NaN if out of reach)
     */
    public double getLowRadians() {
        return lowRadians;
    }

    /**
     * Return the high (lob) angle above the horizontal.
     *
     * @return the angle (in radians; NaN if out of reach)
     */
    public double getHighRadians() {
        return highRadians;
    }

    /**
     * Explain the answer: "reachable", or why the target is out of reach.
     *
     * @return a one-line explanation (not null)
     */
    public String getExplanation() {
        return explanation;
    }
}

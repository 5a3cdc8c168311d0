package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * The two launch angles that hit a target at any height with a fixed launch speed s, no drag:
 * {@code tan θ = (s² ∓ sqrt(s⁴ − g·(g·x² + 2·y·s²)))/(g·x)}. A negative discriminant means
 * the target is out of reach at that speed.
 *
 * <p>Computed without overflow or cancellation: with {@code u = s²/(g·x)} and
 * {@code k = y/x} the two tangents are the roots of {@code t² − 2u·t + (1 + 2k·u) = 0}, so
 * {@code q = (1/u + 2k)/u}, {@code tan θ_high = u·(1 + sqrt(1 − q))} and
 * {@code tan θ_low = (1/u + 2k)/(1 + sqrt(1 − q))} (their product is {@code 1 + 2k·u}). A
 * speed so large that u overflows gives the true limits, 90° and the straight line
 * {@code atan(y/x)}, never a −90° "solution".
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
     * @throws IllegalArgumentException if an input is out of its range, or the target's
     *     proportions ({@code s²/(g·x)}, {@code y/x}) are out of the double range
     */
    public static LaunchAngles solve(double launchSpeed, double targetDistance,
            double targetHeight, double gravity) {
        Validate.positive(launchSpeed, "launch speed s (m/s)");
        Validate.positive(targetDistance, "target distance x (m)");
        Validate.finite(targetHeight, "target height y (m)");
        Validate.positive(gravity, "gravity g (m/s^2)");
        double u = launchSpeed / gravity * (launchSpeed / targetDistance);
        double k = targetHeight / targetDistance;
        double inverseU = 1.0 / u;
        double q = (inverseU + 2.0 * k) / u;
        if (Double.isNaN(u) || Double.isInfinite(k) || Double.isNaN(q)) {
            throw new IllegalArgumentException(String.format("the target at (%s m, %s m) with"
                    + " launch speed %s m/s and g = %s m/s^2 is out of the double range:"
                    + " s^2/(g x) = %s, y/x = %s", targetDistance, targetHeight, launchSpeed,
                    gravity, u, k));
        }
        // 1 − q is the discriminant divided by (g·x)²·u², so it has the same sign.
        double scaledDiscriminant = 1.0 - q;
        if (scaledDiscriminant < 0.0) {
            return new LaunchAngles(false, Double.NaN, Double.NaN, String.format(
                    "target at (%s m, %s m) is out of reach at launch speed %s m/s"
                            + " (no real angle: 1 - g(g x^2 + 2 y s^2)/s^4 = %s < 0)",
                    targetDistance, targetHeight, launchSpeed, scaledDiscriminant));
        }
        double root = 1.0 + Math.sqrt(scaledDiscriminant);
        double low = Math.atan((inverseU + 2.0 * k) / root);
        double high = Math.atan(u * root);
        return new LaunchAngles(true, low, high, "reachable");
    }

    /**
     * The reachable envelope at a fixed launch speed s, no drag: the safety parabola
     * {@code y = s²/(2g) − g·x²/(2s²)}. Targets on or below it are reachable (the discriminant
     * of {@link #solve} is zero on it), targets above are not; it meets the gun's level at the
     * maximum range {@code s²/g}.
     *
     * @param launchSpeed s (in m/s, finite, &gt;0)
     * @param targetDistance x, the horizontal distance (in metres, finite, &ge;0)
     * @param gravity g (in m/s², finite, &gt;0)
     * @return the highest reachable height above the gun at x (in metres)
     */
    public static double envelopeHeight(double launchSpeed, double targetDistance,
            double gravity) {
        Validate.positive(launchSpeed, "launch speed s (m/s)");
        Validate.nonNegative(targetDistance, "target distance x (m)");
        Validate.positive(gravity, "gravity g (m/s^2)");
        double reach = launchSpeed / gravity * launchSpeed;
        return 0.5 * reach - 0.5 * targetDistance * (targetDistance / reach);
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

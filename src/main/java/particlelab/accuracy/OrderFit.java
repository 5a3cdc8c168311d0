package particlelab.accuracy;

/**
 * Measures a method's convergence order: the slope of log(error) against log(h), by least
 * squares over the points whose error stands clear of round-off.
 */
public final class OrderFit {

    /** Fewest points a slope is fitted through. */
    public static final int MIN_POINTS = 3;

    private OrderFit() {
    }

    /**
     * Fit {@code log10(error) = p·log10(h) + c} and return p.
     *
     * @param stepSeconds the step sizes (in seconds, each &gt;0, not null)
     * @param errors the errors at those steps (same length, not null)
     * @param floor errors at or below this are round-off and left out (&ge;0)
     * @return the measured order p, or NaN if fewer than {@link #MIN_POINTS} points are above
     *     the floor
     */
    public static double slope(double[] stepSeconds, double[] errors, double floor) {
        if (stepSeconds.length != errors.length) {
            throw new IllegalArgumentException("need one error per step, but had "
                    + stepSeconds.length + " steps and " + errors.length + " errors");
        }
        int count = 0;
        double sumX = 0.0;
        double sumY = 0.0;
        double sumXx = 0.0;
        double sumXy = 0.0;
        for (int i = 0; i < errors.length; ++i) {
            if (!(errors[i] > floor) || !Double.isFinite(errors[i])) {
                continue;
            }
            double x = Math.log10(stepSeconds[i]);
            double y = Math.log10(errors[i]);
            ++count;
            sumX += x;
            sumY += y;
            sumXx += x * x;
            sumXy += x * y;
        }
        if (count < MIN_POINTS) {
            return Double.NaN;
        }
        return (count * sumXy - sumX * sumY) / (count * sumXx - sumX * sumX);
    }
}

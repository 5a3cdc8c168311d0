package particlelab.accuracy;

/**
 * Measures a method's convergence order: the slope of log(error) against log(h), by least
 * squares over the points whose error stands clear of round-off.
 *
 * <p>Walking from the largest h down, a point is used while its error is above the floor and
 * at least {@value #MIN_DECREASE} times smaller than the previous point's: every method here is
 * at least first order, so halving h must shrink a truncation error by about 2 or more. The
 * first point that fails (round-off has taken over) ends the fit.
 */
public final class OrderFit {

    /** Fewest points a slope is fitted through. */
    public static final int MIN_POINTS = 3;
    /** How much smaller each next error must be for the point to count as truncation error. */
    public static final double MIN_DECREASE = 1.5;

    private OrderFit() {
    }

    /**
     * Fit {@code log10(error) = p·log10(h) + c} and return p.
     *
     * @param stepSeconds the step sizes (in seconds, each &gt;0, largest first, not null)
     * @param errors the errors at those steps (same length, not null)
     * @param floor errors at or below this are round-off and left out (&ge;0)
     * @return the measured order p, or NaN if fewer than {@link #MIN_POINTS} points qualify
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
        double previous = Double.POSITIVE_INFINITY;
        for (int i = 0; i < errors.length; ++i) {
            if (i > 0 && !(stepSeconds[i] < stepSeconds[i - 1])) {
                throw new IllegalArgumentException("steps must be largest first, but step " + i
                        + " was " + stepSeconds[i] + " after " + stepSeconds[i - 1]);
            }
            if (!(errors[i] > floor) || !Double.isFinite(errors[i])
                    || !(errors[i] * MIN_DECREASE <= previous)) {
                break;
            }
            previous = errors[i];
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

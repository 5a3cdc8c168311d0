package particlelab.accuracy;

import java.util.Arrays;
import java.util.Locale;

/**
 * The verdict of a side-by-side speed comparison, controlled by an A/A pass. Two builds (or two
 * paths) timed side by side in one JVM give per-round ratios B ÷ A; the same code timed against
 * itself in the same invocation (A ÷ A, a second copy of the same code in the same row order)
 * gives per-round ratios that show how far identical code can appear to differ: one measured
 * 0.73× for identical classes with a tight spread. A tight spread does not make a difference
 * real; only a B ÷ A median outside the row's own A/A band does.
 *
 * <p>The rule: the A/A band is [min, max] of the row's A/A rounds and of their reciprocals
 * (identical code has no direction: A′ ÷ A = 0.73 says as much as A ÷ A′ = 1.37, and which copy
 * the JIT favours is chance). If the median of the A/B rounds lies above the band, B is
 * slower; below it, B is faster; inside it (edges included), "no verdict". An A/A run judged
 * by itself therefore always gives "no verdict".
 */
public final class AaControl {

    /** Verdict of a row whose A/B median lies inside its A/A band. */
    public static final String NO_VERDICT = "no verdict";

    private AaControl() {
    }

    /**
     * Judge one row.
     *
     * @param aaRatios the A/A pass's ratio per round (A′ ÷ A; finite, &gt;0; not modified)
     * @param abRatios the A/B pass's ratio per round (B ÷ A; finite, &gt;0; not modified)
     * @return "slower (1.21× outside the A/A band 0.95–1.05)", "faster (…)" or
     *     {@link #NO_VERDICT}; "not measured" where either array is empty or holds a value
     *     that is not a positive finite number
     */
    public static String verdict(double[] aaRatios, double[] abRatios) {
        if (!measured(aaRatios) || !measured(abRatios)) {
            return "not measured";
        }
        double aaMin = Double.POSITIVE_INFINITY;
        double aaMax = 0.0;
        for (double ratio : aaRatios) {
            aaMin = Math.min(aaMin, ratio);
            aaMax = Math.max(aaMax, ratio);
        }
        double low = bandLow(aaMin, aaMax);
        double high = bandHigh(aaMin, aaMax);
        double median = median(abRatios);
        if (isInsideBand(aaMin, aaMax, median)) {
            return NO_VERDICT;
        }
        return String.format(Locale.ROOT, "%s (%.3f× outside the A/A band %.3f–%.3f)",
                median > high ? "slower" : "faster", median, low, high);
    }

    /**
     * The A/A band's lower edge: the least of the A/A rounds and of their reciprocals.
     *
     * @param aaMin the least A/A ratio over the rounds (&gt;0)
     * @param aaMax the largest A/A ratio over the rounds (&ge;aaMin)
     * @return min(aaMin, 1/aaMax)
     */
    public static double bandLow(double aaMin, double aaMax) {
        return Math.min(aaMin, 1.0 / aaMax);
    }

    /**
     * The A/A band's upper edge: the largest of the A/A rounds and of their reciprocals.
     *
     * @param aaMin the least A/A ratio over the rounds (&gt;0)
     * @param aaMax the largest A/A ratio over the rounds (&ge;aaMin)
     * @return max(aaMax, 1/aaMin)
     */
    public static double bandHigh(double aaMin, double aaMax) {
        return Math.max(aaMax, 1.0 / aaMin);
    }

    /**
     * Tell whether a ratio lies inside (edges included) the A/A band of rounds whose least
     * and largest A/A ratios are given: the rule of {@link #verdict}, for callers that keep
     * only a row's min and max (the report's side-by-side rows).
     *
     * @param aaMin the least A/A ratio over the rounds (&gt;0)
     * @param aaMax the largest A/A ratio over the rounds (&ge;aaMin)
     * @param ratio the ratio to judge (a median of rounds, or a median over a target)
     * @return true if identical code has been seen to differ by as much: no verdict
     */
    public static boolean isInsideBand(double aaMin, double aaMax, double ratio) {
        return ratio >= bandLow(aaMin, aaMax) && ratio <= bandHigh(aaMin, aaMax);
    }

    /**
     * The median of some values.
     *
     * @param values the values (at least one; not modified)
     * @return the middle value, or the mean of the two middle ones
     */
    public static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }

    private static boolean measured(double[] ratios) {
        if (ratios == null || ratios.length == 0) {
            return false;
        }
        for (double ratio : ratios) {
            if (!(ratio > 0.0) || Double.isInfinite(ratio)) {
                return false;
            }
        }
        return true;
    }
}

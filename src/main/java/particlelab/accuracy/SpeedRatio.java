package particlelab.accuracy;

import java.util.Locale;

/**
 * Words for one time against another that are true whichever is larger: "3.2× faster",
 * "1.3× slower" (never "0.77× faster", nor "1× faster" for 0.77), "about as fast" when the two
 * round to the same.
 */
final class SpeedRatio {

    /** Text for two times that round to a factor of 1.0. */
    static final String SAME = "about as fast";

    private SpeedRatio() {
    }

    /**
     * Compare a time with a reference time.
     *
     * @param nanos the time of the thing described (in ns, finite, &gt;0)
     * @param referenceNanos the time it is compared with (in ns, finite, &gt;0)
     * @return e.g. {@code "3.2× faster"} if nanos is 3.2 times shorter, {@code "1.3× slower"}
     *     if it is 1.3 times longer; "—" if either time is not a positive finite number
     */
    static String describe(double nanos, double referenceNanos) {
        if (!(nanos > 0.0 && referenceNanos > 0.0) || Double.isInfinite(nanos)
                || Double.isInfinite(referenceNanos)) {
            return "—";
        }
        boolean faster = nanos <= referenceNanos;
        String factor = factor(faster ? referenceNanos / nanos : nanos / referenceNanos);
        if (factor.equals("1.0")) {
            return SAME;
        }
        return factor + (faster ? "× faster" : "× slower");
    }

    /** A factor &ge; 1 to two significant digits, or whole above 10. */
    private static String factor(double factor) {
        return String.format(Locale.ROOT, factor < 9.95 ? "%.1f" : "%.0f", factor);
    }
}

package particlelab.view;

/**
 * Which distance marks along the ground are shown: every mark whose index is a multiple of a
 * stride, the smallest of 1, 2, 5, 10, 20, 50, … that spaces the marks' centres at least the
 * widest mark's text width plus a gap apart, in pixels at the window's scale. So two marks
 * shown never touch ("-6 m" and "-4 m" in a small window), 0 m is always one of them, and
 * the marks shown stay evenly spaced.
 */
public final class MarkThinning {

    /** The strides tried within each decade, smallest first. */
    private static final int[] STEPS = {1, 2, 5};
    /** The largest stride returned: beyond it a window has room for at most one mark. */
    private static final int MAX_STRIDE = 1_000_000;

    /** Not made: the rule is static. */
    private MarkThinning() {
    }

    /**
     * Return the smallest stride that leaves room between neighbouring marks shown: with the
     * marks' centres {@code k·spacing} apart, two neighbours of widths {@code a, b ≤ w} leave
     * {@code k·spacing − (a + b)/2 ≥ k·spacing − w} between them, so {@code k·spacing ≥ w +
     * gap} is enough.
     *
     * @param spacingPixels the distance between two neighbouring marks' centres (in pixels,
     *     &gt;0)
     * @param widestPixels the widest mark's text width (in pixels, &ge;0)
     * @param gapPixels the least room between two marks shown (in pixels, &ge;0)
     * @return the stride k (1, 2, 5, 10, 20, 50, … at most {@link #MAX_STRIDE})
     */
    public static int stride(float spacingPixels, float widestPixels, float gapPixels) {
        if (!(spacingPixels > 0f) || Float.isInfinite(spacingPixels)) {
            throw new IllegalArgumentException(
                    "mark spacing (px) must be finite and > 0, but was " + spacingPixels);
        }
        if (!(widestPixels >= 0f) || !(gapPixels >= 0f) || Float.isInfinite(widestPixels)
                || Float.isInfinite(gapPixels)) {
            throw new IllegalArgumentException("mark width and gap (px) must be finite and"
                    + " >= 0, but were " + widestPixels + " and " + gapPixels);
        }
        float needed = widestPixels + gapPixels;
        for (int decade = 1; decade <= MAX_STRIDE / 10; decade *= 10) {
            for (int step : STEPS) {
                if (step * decade * spacingPixels >= needed) {
                    return step * decade;
                }
            }
        }
        return MAX_STRIDE;
    }

    /**
     * Test whether a mark is shown at a stride.
     *
     * @param markIndex the mark's value in mark spacings (0 for 0 m, negative left of it)
     * @param stride from {@link #stride} (&ge;1)
     * @return true if the index is a multiple of the stride
     */
    public static boolean isShown(int markIndex, int stride) {
        return Math.floorMod(markIndex, stride) == 0;
    }
}

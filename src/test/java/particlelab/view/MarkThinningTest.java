package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The ground marks' thinning: the marks shown never touch, and no more are dropped. */
class MarkThinningTest {

    /** The strides in order, to find the one before a stride returned. */
    private static final int[] STRIDES = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};

    /**
     * Marks "-20 m" … "20 m" every 2 m, their widths as a font gives them (a minus sign and
     * a second digit widen a mark), at pixel scales from a phone-sized window to 4K: the
     * marks shown, neighbour to neighbour, leave at least the gap between their boxes.
     */
    @Test
    void theMarksShownLeaveAtLeastTheGapBetweenThem() {
        Random random = new Random(23);
        for (int trial = 0; trial < 2000; ++trial) {
            float spacing = 5f + 200f * random.nextFloat();
            float charWidth = 3f + 15f * random.nextFloat();
            float gap = charWidth * random.nextFloat();
            int first = -10;
            int last = 10;
            float widest = 0f;
            float[] widths = new float[last - first + 1];
            for (int m = first; m <= last; ++m) {
                String text = (2 * m) + " m";
                widths[m - first] = charWidth * text.length();
                widest = Math.max(widest, widths[m - first]);
            }
            int stride = MarkThinning.stride(spacing, widest, gap);
            float previousRight = Float.NEGATIVE_INFINITY;
            int shown = 0;
            for (int m = first; m <= last; ++m) {
                if (!MarkThinning.isShown(m, stride)) {
                    continue;
                }
                float centre = m * spacing;
                float left = centre - widths[m - first] / 2f;
                // Sums of a few floats of at most a few thousand pixels: a milli-pixel.
                assertTrue(left - previousRight >= gap - 1e-3f, "trial " + trial + ": mark "
                        + m + " at stride " + stride + " leaves " + (left - previousRight)
                        + " px, less than " + gap);
                previousRight = centre + widths[m - first] / 2f;
                ++shown;
            }
            assertTrue(MarkThinning.isShown(0, stride), "0 m is always shown");
            assertTrue(shown >= 1);
            // The smallest stride that does: the one before it would leave too little room.
            int before = 0;
            for (int i = 1; i < STRIDES.length; ++i) {
                if (STRIDES[i] == stride) {
                    before = STRIDES[i - 1];
                }
            }
            if (stride > 1) {
                assertTrue(before * spacing < widest + gap, "stride " + stride
                        + " where " + before + " had room");
            }
        }
    }

    /**
     * A 640x360 window's scene at the collisions demo's framing: marks every 2 m at about
     * 23 px apart, "-6 m" 22 px wide: they would touch, so every other mark goes.
     */
    @Test
    void marksThatWouldTouchAreThinnedToEveryOther() {
        assertEquals(1, MarkThinning.stride(46f, 22f, 6f));
        assertEquals(2, MarkThinning.stride(23f, 22f, 6f));
        assertEquals(5, MarkThinning.stride(10f, 22f, 6f));
        assertEquals(10, MarkThinning.stride(3f, 22f, 6f));
        assertTrue(MarkThinning.isShown(-4, 2));
        assertFalse(MarkThinning.isShown(-3, 2));
        assertTrue(MarkThinning.isShown(0, 5));
        assertFalse(MarkThinning.isShown(-1, 5));
    }

    @Test
    void badSpacingOrWidthIsRefusedNamingTheValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MarkThinning.stride(0f, 10f, 2f));
        assertTrue(e.getMessage().contains("spacing") && e.getMessage().contains("0.0"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> MarkThinning.stride(10f, Float.NaN, 2f));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
    }
}

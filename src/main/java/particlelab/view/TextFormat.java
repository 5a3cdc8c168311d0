package particlelab.view;

import com.jme3.math.Vector3f;

/**
 * Appends numbers to a {@link StringBuilder} with a fixed number of decimals and without
 * allocating, for HUD text rebuilt every refresh ({@code StringBuilder.append(float)} prints
 * every digit and goes through a decimal converter; these stay short and garbage-free).
 */
public final class TextFormat {

    /** The most decimals supported. */
    public static final int MAX_DECIMALS = 6;
    /** Beyond this magnitude numbers are printed as "huge" rather than overflow a long. */
    private static final double MAX_MAGNITUDE = 1e12;
    private static final long[] POWERS_OF_TEN = {1L, 10L, 100L, 1_000L, 10_000L, 100_000L,
        1_000_000L};

    private TextFormat() {
    }

    /**
     * Append a number rounded to a fixed number of decimals, e.g. {@code -0.333}.
     *
     * @param text where to append (not null, modified)
     * @param value the number (NaN and infinities are spelled out)
     * @param decimals how many digits after the point (0 to {@link #MAX_DECIMALS})
     * @return text
     */
    public static StringBuilder appendFixed(StringBuilder text, double value, int decimals) {
        if (decimals < 0 || decimals > MAX_DECIMALS) {
            throw new IllegalArgumentException("decimals must be from 0 to " + MAX_DECIMALS
                    + ", but was " + decimals);
        }
        if (Double.isNaN(value)) {
            return text.append("NaN");
        }
        double magnitude = Math.abs(value);
        if (magnitude > MAX_MAGNITUDE) {
            return text.append(value < 0.0 ? "-huge" : "huge");
        }
        long scale = POWERS_OF_TEN[decimals];
        long scaled = Math.round(magnitude * scale);
        if (value < 0.0 && scaled != 0L) {
            text.append('-');
        }
        text.append(scaled / scale);
        if (decimals > 0) {
            text.append('.');
            long fraction = scaled % scale;
            for (long digit = scale / 10L; digit > fraction && digit > 1L; digit /= 10L) {
                text.append('0');
            }
            text.append(fraction);
        }
        return text;
    }

    /**
     * Append a vector as {@code (x, y, z)} with a fixed number of decimals.
     *
     * @param text where to append (not null, modified)
     * @param vector the vector (not null, not modified)
     * @param decimals how many digits after the point (0 to {@link #MAX_DECIMALS})
     * @return text
     */
    public static StringBuilder appendVector(StringBuilder text, Vector3f vector, int decimals) {
        text.append('(');
        appendFixed(text, vector.x, decimals).append(", ");
        appendFixed(text, vector.y, decimals).append(", ");
        return appendFixed(text, vector.z, decimals).append(')');
    }

    /**
     * Test whether a character sequence spells the same text as another (a string, a
     * builder), without allocating.
     *
     * @param sequence the sequence (not null)
     * @param string the other sequence (null counts as empty)
     * @return true if both hold the same characters
     */
    public static boolean sameText(CharSequence sequence, CharSequence string) {
        CharSequence other = string == null ? "" : string;
        int length = sequence.length();
        if (length != other.length()) {
            return false;
        }
        for (int i = 0; i < length; ++i) {
            if (sequence.charAt(i) != other.charAt(i)) {
                return false;
            }
        }
        return true;
    }
}

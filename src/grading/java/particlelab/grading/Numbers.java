package particlelab.grading;

import com.jme3.math.Vector3f;
import java.util.Locale;

/** Comparisons that fail with a {@link Mistake}, and numbers written for a one-line message. */
final class Numbers {

    private Numbers() {
    }

    /** A number with 6 significant digits. */
    static String f(double value) {
        return String.format(Locale.ROOT, "%.6g", value);
    }

    /** A vector as (x, y, z) with 6 significant digits. */
    static String v(Vector3f value) {
        return "(" + f(value.x) + ", " + f(value.y) + ", " + f(value.z) + ")";
    }

    /** True when {@code actual} is finite and within {@code tolerance} of {@code expected}. */
    static boolean near(double expected, double actual, double tolerance) {
        return Double.isFinite(actual) && Math.abs(actual - expected) <= tolerance;
    }

    /** Fails with {@code "returned NaN"} when a vector is not finite. */
    static void requireFinite(Vector3f value, String what) {
        if (!Float.isFinite(value.x) || !Float.isFinite(value.y) || !Float.isFinite(value.z)) {
            throw new Mistake(what + " became " + v(value) + ": NaN or infinity");
        }
    }
}

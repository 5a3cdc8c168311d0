package particlelab;

import static org.junit.jupiter.api.Assertions.fail;

import com.jme3.math.Vector3f;

/**
 * Assertions on jME vectors: one call instead of three per-component assertions.
 *
 * <p>Components are compared one by one (the largest absolute difference must not exceed the
 * tolerance). A NaN or infinite component in {@code actual} always fails, even against an
 * infinite tolerance.
 */
public final class VectorAssert {

    private VectorAssert() {
    }

    /**
     * Assert that every component of {@code actual} is within {@code tolerance} of the same
     * component of {@code expected}.
     *
     * @param expected the expected vector (finite, not null, not modified)
     * @param actual the vector under test (not modified; null fails)
     * @param tolerance the largest difference allowed per component (in the vectors' units,
     *     &ge;0)
     */
    public static void assertVectorEquals(Vector3f expected, Vector3f actual, float tolerance) {
        assertVectorEquals(expected, actual, tolerance, null);
    }

    /**
     * Assert that every component of {@code actual} is within {@code tolerance} of the same
     * component of {@code expected}, naming what was compared if not.
     *
     * @param expected the expected vector (finite, not null, not modified)
     * @param actual the vector under test (not modified; null fails)
     * @param tolerance the largest difference allowed per component (in the vectors' units,
     *     &ge;0)
     * @param message what was compared, put first in the failure message (may be null)
     */
    public static void assertVectorEquals(Vector3f expected, Vector3f actual, float tolerance,
            String message) {
        String prefix = message == null ? "" : message + " ==> ";
        if (actual == null) {
            fail(prefix + "expected " + expected + " but was null");
        }
        float worst = Math.max(Math.abs(expected.x - actual.x),
                Math.max(Math.abs(expected.y - actual.y), Math.abs(expected.z - actual.z)));
        boolean finite = Float.isFinite(actual.x) && Float.isFinite(actual.y)
                && Float.isFinite(actual.z);
        // Written so that a NaN difference fails: NaN <= tolerance is false.
        if (!finite || !(worst <= tolerance)) {
            fail(prefix + "expected " + expected + " but was " + actual
                    + " (largest component difference " + worst + " > tolerance " + tolerance
                    + ")");
        }
    }
}

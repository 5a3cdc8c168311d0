package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * The orientation a rotating box is drawn at between two steps: the previous state at
 * α = 0, the current one at α = 1, drifted matrices included. The boxes as drawn, frame by
 * frame, are checked in {@code particlelab.lecture.LectureFramesHeadlessTest}.
 */
class OrientationBlendTest {

    @Test
    void theBlendIsThePreviousStateAtZeroAndTheCurrentAtOne() {
        Matrix3f previous = new Matrix3f();
        previous.fromAngleNormalAxis(0.3f, new Vector3f(0f, 0f, 1f));
        // A drifted matrix, as the plain Euler step leaves it: grown and sheared.
        Matrix3f current = new Matrix3f(1.01f, -0.3f, 0f, 0.31f, 0.99f, 0f, 0f, 0.02f, 1f);
        OrientationBlend blend = new OrientationBlend();
        Matrix3f drawn = new Matrix3f();
        assertEquals(previous, blend.blend(previous, current, 0f, drawn));
        assertEquals(current, blend.blend(previous, current, 1f, drawn));
        // Just inside: within float round-off of the ends (products of entries below 1.1).
        blend.blend(previous, current, 1e-6f, drawn);
        assertMatrixEquals(previous, drawn, 1e-5f);
        blend.blend(previous, current, 1f - 1e-6f, drawn);
        assertMatrixEquals(current, drawn, 1e-5f);
    }

    private static void assertMatrixEquals(Matrix3f expected, Matrix3f actual, float tol) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                assertEquals(expected.get(row, column), actual.get(row, column), tol,
                        "entry " + row + "," + column + " of " + actual);
            }
        }
    }
}

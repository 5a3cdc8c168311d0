package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

class TextFormatTest {

    @Test
    void fixedDecimalsRoundAndPad() {
        assertEquals("-0.333", fixed(-1.0 / 3.0, 3));
        assertEquals("99.667", fixed(99.66666, 3));
        assertEquals("0.005", fixed(0.005, 3));
        assertEquals("2.50", fixed(2.5, 2));
        assertEquals("10", fixed(9.6, 0));
        assertEquals("0.00", fixed(-0.001, 2)); // no "-0.00"
        assertEquals("NaN", fixed(Double.NaN, 2));
        assertEquals("-huge", fixed(Double.NEGATIVE_INFINITY, 2));
        assertThrows(IllegalArgumentException.class, () -> fixed(1.0, 7));
    }

    @Test
    void vectorsPrintInParentheses() {
        assertEquals("(1.0, -2.5, 0.0)", TextFormat.appendVector(new StringBuilder(),
                new Vector3f(1f, -2.5f, 0f), 1).toString());
    }

    @Test
    void sameTextComparesContents() {
        assertTrue(TextFormat.sameText(new StringBuilder("abc"), "abc"));
        assertFalse(TextFormat.sameText(new StringBuilder("abd"), "abc"));
        assertTrue(TextFormat.sameText("", null));
    }

    private static String fixed(double value, int decimals) {
        return TextFormat.appendFixed(new StringBuilder(), value, decimals).toString();
    }
}

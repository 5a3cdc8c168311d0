package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.input.KeyInput;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The bindings, and the help and footer written from them; no jME application needed. */
class DemoKeysTest {

    @Test
    void oneActionWithTwoKeysIsOneHelpLineAndLearnsWhichKeyWasPressed() {
        DemoKeys keys = new DemoKeys();
        List<Integer> pressed = new ArrayList<>();
        keys.addShared(new KeyBinding(new int[] {KeyInput.KEY_EQUALS, KeyInput.KEY_ADD},
                new String[] {"+", "keypad +"}, "time scale x2", null, pressed::add));

        String help = keys.buildHelp("Demo");
        KeyBinding faster = keys.copyMapped().get(0);
        faster.press(1);

        assertTrue(help.contains("+ / keypad +  -  time scale x2"), help);
        assertEquals(1, help.split("time scale x2", -1).length - 1, help);
        assertEquals(List.of(1), pressed);
        assertThrows(IllegalArgumentException.class, () -> faster.press(2));
    }

    @Test
    void footerListsTheSummarisedBindingsInOrderWithTheirLabels() {
        DemoKeys keys = new DemoKeys();
        keys.addShared(new KeyBinding(KeyInput.KEY_H, "H", "help", () -> { }).withSummary("help"));
        keys.addShared(new KeyBinding(KeyInput.KEY_T, "T", "mode", () -> { }));
        keys.addShared(new KeyBinding(KeyInput.KEY_P, "P", "pause", () -> { })
                .withSummary("pause"));
        keys.setApplicationBindings(List.of(new KeyBinding(KeyInput.KEY_TAB, "Tab", "next demo",
                () -> { }).withSummary("next demo")));

        // The camera's gesture last: the right button turns it (the left one picks).
        assertEquals("H  help     P  pause     Tab  next demo     right drag  camera",
                keys.buildFooter());
    }

    @Test
    void keysOfJmeOfTheApplicationAndOfAnotherActionAreRefusedNamingBoth() {
        DemoKeys keys = new DemoKeys();
        keys.setApplicationBindings(List.of(new KeyBinding(KeyInput.KEY_7, "7", "no demo",
                () -> { })));
        keys.addShared(new KeyBinding(KeyInput.KEY_V, "V", "arrows", () -> { }));

        IllegalArgumentException jme = assertThrows(IllegalArgumentException.class,
                () -> keys.addOwn(KeyInput.KEY_W, "W", "wind", () -> { }));
        IllegalArgumentException app = assertThrows(IllegalArgumentException.class,
                () -> keys.addOwn(KeyInput.KEY_7, "7", "seven", () -> { }));
        IllegalArgumentException twice = assertThrows(IllegalArgumentException.class,
                () -> keys.addShared(new KeyBinding(new int[] {KeyInput.KEY_B, KeyInput.KEY_V},
                        new String[] {"B", "V"}, "both", null, key -> { })));

        assertTrue(jme.getMessage().contains("W") && jme.getMessage().contains("jME")
                && jme.getMessage().contains("wind"), jme.getMessage());
        assertTrue(app.getMessage().contains("application for \"no demo\"")
                && app.getMessage().contains("seven"), app.getMessage());
        assertTrue(twice.getMessage().contains("key V is already bound to \"arrows\""),
                twice.getMessage());
        assertEquals(1, keys.copyMapped().size());
        assertFalse(keys.buildHelp("Demo").contains("both"));
    }

    @Test
    void bindingRefusesMismatchedOrRepeatedKeys() {
        assertThrows(IllegalArgumentException.class, () -> new KeyBinding(new int[] {1, 2},
                new String[] {"a"}, "x", null, key -> { }));
        IllegalArgumentException repeated = assertThrows(IllegalArgumentException.class,
                () -> new KeyBinding(new int[] {3, 3}, new String[] {"a", "b"}, "x", null,
                        key -> { }));
        assertTrue(repeated.getMessage().contains("a and b"), repeated.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new KeyBinding(new int[] {3},
                new String[] {"a"}, "x", "", key -> { }));
    }
}

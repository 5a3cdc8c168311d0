package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.event.KeyInputEvent;
import java.lang.reflect.Field;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.demo.DemoState;

/**
 * Choosing demos with real key events, in a headless application on the catalogue's 19
 * demos: each press and release goes through jME's input manager (its queue, the key
 * triggers, the switcher's mappings and its Shift tracking), as the keyboard's would. The
 * harness's frame time is 0, so a lone 1's wait is passed by hand; the two-digit numbers
 * complete at their second digit ({@code DemoSwitcherTest} covers the wait).
 */
class DemoSwitcherHeadlessTest {

    private static final List<DemoState> demos = DemoCatalog.createAll();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> demos);

    @Test
    void digitsTabAndShiftTabReachEveryDemoInLectureOrder() throws Exception {
        tap(KeyInput.KEY_1);
        tap(KeyInput.KEY_2);
        assertEquals(12, selectedNumber(), "1 then 2");

        shiftTab(KeyInput.KEY_LSHIFT);
        assertEquals(11, selectedNumber(), "Shift+Tab");
        shiftTab(KeyInput.KEY_RSHIFT);
        assertEquals(10, selectedNumber(), "Shift+Tab with the right Shift");
        tap(KeyInput.KEY_TAB);
        assertEquals(11, selectedNumber(), "Tab after Shift was released");

        tap(KeyInput.KEY_1);
        tap(KeyInput.KEY_9);
        assertEquals(19, selectedNumber(), "1 then 9");
        tap(KeyInput.KEY_TAB);
        assertEquals(1, selectedNumber(), "Tab wraps from the last demo to the first");
        shiftTab(KeyInput.KEY_LSHIFT);
        assertEquals(19, selectedNumber(), "Shift+Tab wraps back");

        tap(KeyInput.KEY_4);
        assertEquals(4, selectedNumber(), "4 chooses at once");
        // Every demo, by number, in lecture order.
        for (int number = 1; number <= demos.size(); ++number) {
            if (number >= 10) {
                tap(KeyInput.KEY_1);
                tap(digitKey(number % 10));
            } else {
                tap(digitKey(number));
                if (number == 1) {
                    // A lone 1 waits for a second digit, and the title says so; let its
                    // wait pass by hand.
                    assertTrue(harness.call(() -> harness.app().getSwitcher().isEntryPending()));
                    String title = harness.call(() -> harness.app().getSwitcher().getSelected()
                            .getHud().getTitleText());
                    assertEquals("4.  " + demos.get(3).getTitle()
                            + "      typed 1_  (a second digit for 10-19)", title);
                    harness.call(() -> {
                        harness.app().getSwitcher().update(DemoSwitcher.ENTRY_SECONDS);
                        return true;
                    });
                }
            }
            assertEquals(number, selectedNumber());
        }
    }

    @Test
    void theHelpAndFooterSayHowToChooseADemo() throws Exception {
        DemoState demo = harness.call(() -> harness.app().getSwitcher().getSelected());
        String help = demo.getKeys().getHelpText();

        assertTrue(help.contains("\nChoosing a demo\n   0-9  -  type a demo's number (1-19):"),
                help);
        assertTrue(help.contains("\n   Tab / Shift+Tab  -  next demo; with Shift, the previous"
                + " one"), help);
        assertTrue(help.contains("\nThe demos, by number\n   1  -  " + demos.get(0).getTitle()
                + ";   2  -  " + demos.get(1).getTitle() + "\n"), help);
        assertTrue(help.contains("\n   19  -  " + demos.get(18).getTitle() + "\n"), help);
        String footer = harness.call(() -> demo.getHud().getFooterText());
        assertTrue(footer.contains("Tab / Shift+Tab  demos (or 1-19)"), footer);
    }

    /** Press and release a key, and let two frames handle it and switch. */
    private static void tap(int keyCode) throws Exception {
        key(keyCode, true);
        key(keyCode, false);
        harness.awaitFrames(2);
    }

    /** Shift held down around a tap of Tab. */
    private static void shiftTab(int shiftCode) throws Exception {
        key(shiftCode, true);
        harness.awaitFrames(1);
        tap(KeyInput.KEY_TAB);
        key(shiftCode, false);
        harness.awaitFrames(1);
    }

    /**
     * Queue a key event in jME's input manager, as its key input does during the input
     * manager's update (the only time it accepts one); the next frame's update handles it.
     */
    private static void key(int keyCode, boolean pressed) throws Exception {
        harness.call(() -> {
            InputManager input = harness.app().getInputManager();
            Field permitted = InputManager.class.getDeclaredField("eventsPermitted");
            permitted.setAccessible(true);
            permitted.setBoolean(input, true);
            try {
                input.onKeyEvent(new KeyInputEvent(keyCode, '\0', pressed, false));
            } finally {
                permitted.setBoolean(input, false);
            }
            return true;
        });
    }

    private static int selectedNumber() throws Exception {
        return harness.call(() -> demos.indexOf(harness.app().getSwitcher().getSelected())) + 1;
    }

    private static int digitKey(int digit) {
        return digit == 0 ? KeyInput.KEY_0 : KeyInput.KEY_1 + digit - 1;
    }
}

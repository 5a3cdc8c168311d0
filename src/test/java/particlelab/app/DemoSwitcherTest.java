package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.demo.DemoState;
import particlelab.lecture.UniformMotionDemo;
import particlelab.demo.KeyBinding;

/**
 * The switcher's keys, generated from the number of demos, and the digit entry's rule; no jME
 * application needed (the switch happens in {@link DemoSwitcher#update}, called here with a
 * fixed frame time). Shift+Tab, which needs jME's key events, is in
 * {@code WindowControlsHeadlessTest}.
 */
class DemoSwitcherTest {

    /** A frame of the window (s). */
    private static final float FRAME = 1f / 60f;

    /**
     * Key sequences on the catalogue's 19 demos and the demo each ends on: digits 2-9 choose
     * at once, 1 waits for a second digit (1 then 0-9: demos 10-19), or, alone, is demo 1
     * once {@link DemoSwitcher#ENTRY_SECONDS} have passed.
     */
    @ParameterizedTest(name = "{0} -> demo {1}")
    @CsvSource({
        "'1 2', 12",
        "'1 0', 10",
        "'1 7', 17",
        "'1 8', 18",
        "'1 9', 19",
        "'2', 2",
        "'9', 9",
        "'1 wait', 1",
        "'1 wait 5', 5",
        "'5 1 3', 13",
        "'1 2 1 6', 16",
        "'9 1 4 wait', 14",
    })
    void aKeySequenceChoosesTheDemoOfItsNumber(String keys, int demo) {
        List<DemoState> demos = DemoCatalog.createAll();
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        type(switcher, keys);

        assertEquals(demo, demos.indexOf(switcher.getSelected()) + 1);
        assertFalse(switcher.isEntryPending());
    }

    @Test
    void aLoneOneWaitsForTheSecondDigitAndChoosesDemoOneOnlyAfterTheEntryTime() {
        List<DemoState> demos = DemoCatalog.createAll();
        DemoSwitcher switcher = new DemoSwitcher(demos, 4);
        press(switcher, "1");
        // Just short of the entry time (frames of 1/60 s, summed in float): still waiting.
        int frames = (int) (DemoSwitcher.ENTRY_SECONDS / FRAME) - 2;
        for (int i = 0; i < frames; ++i) {
            switcher.update(FRAME);
        }
        assertTrue(switcher.isEntryPending());
        assertEquals(4, demos.indexOf(switcher.getSelected()));
        assertEquals("typed 1_  (a second digit for 10-19)",
                demos.get(4).getDemoHud().getTitleNote());

        for (int i = 0; i < 4; ++i) {
            switcher.update(FRAME);
        }

        assertFalse(switcher.isEntryPending());
        assertEquals(0, demos.indexOf(switcher.getSelected()));
        assertNull(demos.get(4).getDemoHud().getTitleNote(),
                "the note leaves the title with the entry");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
        "'0', no demo 0: there are 19; Tab cycles",
    })
    void aNumberWithNoDemoSaysSoAndKeepsTheDemo(String keys, String notice) {
        List<DemoState> demos = DemoCatalog.createAll();
        DemoSwitcher switcher = new DemoSwitcher(demos, 2);

        type(switcher, keys);

        assertEquals(notice, demos.get(2).getDemoHud().getNotice());
        assertEquals(2, demos.indexOf(switcher.getSelected()));
    }

    @Test
    void withFewDemosEveryDigitChoosesAtOnceAndOneBeyondThemSaysSo() {
        List<DemoState> demos = DemoCatalog.createAll().subList(0, 2);
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        press(switcher, "1");
        assertFalse(switcher.isEntryPending(), "no demo 10 to wait for");
        press(switcher, "2");
        switcher.update(FRAME);
        assertEquals(1, demos.indexOf(switcher.getSelected()));
        press(switcher, "7");

        assertEquals("no demo 7: there are 2; Tab cycles", demos.get(1).getDemoHud().getNotice());
        assertNull(demos.get(0).getDemoHud().getNotice());
        assertEquals(1, demos.indexOf(switcher.getSelected()));
    }

    @Test
    void tabStepsOnFromTheLastDemoToTheFirstAndDropsAPendingEntry() {
        List<DemoState> demos = DemoCatalog.createAll();
        DemoSwitcher switcher = new DemoSwitcher(demos, demos.size() - 1);

        type(switcher, "Tab");
        assertEquals(0, demos.indexOf(switcher.getSelected()));
        type(switcher, "1 Tab");

        assertFalse(switcher.isEntryPending());
        assertNull(demos.get(0).getDemoHud().getTitleNote());
        assertEquals(1, demos.indexOf(switcher.getSelected()));
    }

    @Test
    void theTenDigitsAndTabAreBoundOnceAndTheFooterAndHelpSayHow() {
        List<DemoState> demos = DemoCatalog.createAll();
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        List<String> keys = new ArrayList<>();
        List<String> footer = new ArrayList<>();
        List<String> help = new ArrayList<>();
        for (KeyBinding binding : switcher.getBindings()) {
            for (int i = 0; i < binding.countKeys(); ++i) {
                keys.add(binding.getKeyLabel(i));
            }
            if (binding.getSummary() != null) {
                footer.add(binding.getKeyLabel() + "  " + binding.getSummary());
            }
            help.add(binding.toString());
        }

        assertEquals(List.of("1", "2", "3", "4", "5", "6", "7", "8", "9", "0", "Tab"), keys);
        assertEquals(List.of("Tab / Shift+Tab  demos (or 1-19)"), footer);
        assertEquals(List.of("0-9: type a demo's number (1-19): 2-9 choose at once; 1 waits"
                + " 1 s for a second digit (1 then 2: demo 12), else it is demo 1",
                "Tab / Shift+Tab: next demo; with Shift, the previous one (both wrap around)"),
                help);
    }

    /**
     * Issue 29 §4: a 20th demo makes 2 start a two-digit number, so 2 waits for a second
     * digit and the help says so; 3 still chooses at once, and 2 then 0 is demo 20.
     */
    @Test
    void aTwentiethDemoMakesTwoWaitAndTheHelpSaysSo() {
        List<DemoState> demos = new ArrayList<>(DemoCatalog.createAll());
        demos.add(new UniformMotionDemo());
        assertEquals(20, demos.size());
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        assertEquals("type a demo's number (1-20): 3-9 choose at once; 1-2 wait 1 s for a"
                + " second digit (1 then 2: demo 12), else they are demos 1-2",
                switcher.getBindings().get(0).getDescription());
        press(switcher, "2");
        assertTrue(switcher.isEntryPending(), "2 waits: demo 20 starts with it");
        press(switcher, "0");
        switcher.update(FRAME);
        assertEquals(19, demos.indexOf(switcher.getSelected()));
        press(switcher, "3");
        assertFalse(switcher.isEntryPending(), "no demo 30");
        switcher.update(FRAME);
        assertEquals(2, demos.indexOf(switcher.getSelected()));
    }

    @Test
    void withNineDemosOrFewerTheHelpSaysEveryNumberIsChosenAtOnce() {
        DemoSwitcher switcher = new DemoSwitcher(DemoCatalog.createAll().subList(0, 9), 0);

        assertEquals("type a demo's number (1-9): it is chosen at once",
                switcher.getBindings().get(0).getDescription());
    }

    /**
     * Press keys by label, "wait" for the entry time to pass, then let a frame switch.
     *
     * @param keys labels separated by spaces, e.g. "1 2" or "1 wait"
     */
    private static void type(DemoSwitcher switcher, String keys) {
        for (String key : keys.split(" ")) {
            if (key.equals("wait")) {
                for (float t = 0f; t < DemoSwitcher.ENTRY_SECONDS + FRAME; t += FRAME) {
                    switcher.update(FRAME);
                }
            } else {
                press(switcher, key);
                switcher.update(FRAME);
            }
        }
    }

    private static void press(DemoSwitcher switcher, String label) {
        for (KeyBinding binding : switcher.getBindings()) {
            for (int i = 0; i < binding.countKeys(); ++i) {
                if (binding.getKeyLabel(i).equals(label)) {
                    binding.press(i);
                    return;
                }
            }
        }
        throw new AssertionError("no key " + label);
    }
}

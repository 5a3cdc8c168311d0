package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;

/** The switcher's keys, generated from the number of demos; no jME application needed. */
class DemoSwitcherTest {

    @Test
    void aDigitWithNoDemoShowsANoticeNamingTheDigitAndTheCount() {
        List<DemoState> demos = DemoCatalog.createAll().subList(0, 2);
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        press(switcher, "7");

        assertEquals("no demo 7: there are 2; Tab cycles", demos.get(0).getNotice());
        assertNull(demos.get(1).getNotice());
        assertEquals(0, demos.indexOf(switcher.getSelected()));
    }

    @Test
    void everyDigitIsBoundOnceAndTheFooterNamesTheRangeInUse() {
        List<DemoState> demos = DemoCatalog.createAll().subList(0, 2);
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        List<String> digits = new ArrayList<>();
        String footer = null;
        for (KeyBinding binding : switcher.getBindings()) {
            for (int i = 0; i < binding.countKeys(); ++i) {
                if (binding.getKeyLabel(i).matches("[1-9]")) {
                    digits.add(binding.getKeyLabel(i));
                }
            }
            if (binding.getSummary() != null) {
                footer = binding.getKeyLabel() + "  " + binding.getSummary();
            }
        }

        assertEquals(List.of("1", "2", "3", "4", "5", "6", "7", "8", "9"), digits);
        assertEquals("Tab  next demo (1-2 by number)", footer);
    }

    @Test
    void withNineDemosOrMoreNoDigitIsLeftOver() {
        List<DemoState> demos = new ArrayList<>();
        while (demos.size() < 10) {
            demos.addAll(DemoCatalog.createAll());
        }
        DemoSwitcher switcher = new DemoSwitcher(demos, 0);

        int keys = 0;
        for (KeyBinding binding : switcher.getBindings()) {
            keys += binding.countKeys();
            assertTrue(!binding.getDescription().startsWith("no demo"), binding.toString());
        }
        assertEquals(10, keys); // 1-9 and Tab
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

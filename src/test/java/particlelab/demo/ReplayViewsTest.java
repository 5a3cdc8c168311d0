package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import particlelab.app.DemoCatalog;
import particlelab.world.StateRing;

/**
 * After a step back (Home's code path) every catalogued demo's HUD describes the step shown,
 * in plain JUnit (no jME): the demo runs, the HUD text of every step is kept; then Home step
 * by step, and at each step shown the HUD's lines (each particle's, the demo's own: scores,
 * shot results, readouts) are those the run had at that step, character for character. The
 * time line, the stepping line and the time-scale keys line are left out: they say paused
 * and replaying. The views that exist only with a window (ghosts, graph, kept shots) are in
 * {@code ExactGhostsHeadlessTest}.
 */
class ReplayViewsTest {

    private static final float H = 1f / 60f;
    private static final int STEPS = 360;

    static Stream<String> demoNames() {
        return DemoCatalog.names().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("demoNames")
    void hudBehindEqualsTheOriginalRun(String name) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
        StateRing ring = demo.getRun().getStateRing();
        String[] lines = new String[STEPS + 2];
        for (int i = 0; i < STEPS; ++i) {
            demo.getRun().advancePhysics(H);
            lines[(int) ring.getLastIndex()] = hud(demo);
        }
        long last = ring.getLastIndex();
        for (int k = 0; k < 300 && last - k > ring.getFirstIndex(); ++k) {
            assertTrue(demo.getReplayControls().stepBack());
            long shown = demo.getRun().getShownStep();
            if (lines[(int) shown] != null) {
                assertEquals(lines[(int) shown], hud(demo), name + ": step " + shown);
            }
        }
    }

    /** The HUD's text without the lines that say paused or replaying. */
    static String hud(DemoState demo) {
        StringBuilder text = new StringBuilder();
        demo.getWindow().formatHud(text);
        StringBuilder kept = new StringBuilder();
        for (String line : text.toString().split("\n")) {
            if (!line.contains("ms/frame") && !line.startsWith("t = ")
                    && !line.startsWith("Stepping") && !line.startsWith("   ]")) {
                kept.append(line).append('\n');
            }
        }
        return kept.toString();
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.physics.SimulationClock;
import particlelab.view.LiveGraph;
import particlelab.world.StateRing;

/**
 * Bounce's height graph follows a step back, in a real headless jME application: at each
 * step shown its last sample is, bit for bit, the one the run had at that step (the graph's
 * clock is part of the recorded state), and a step from there goes on at that step's time.
 */
class BounceReplayHeadlessTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    /** Two seconds: the drop and the first bounces. */
    private static final int STEPS = 120;
    private static final int BACK = 90;
    private static final BounceDemo bounce = new BounceDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(bounce));

    @Test
    void theGraphEndsAtTheStepShown() throws Exception {
        List<String> problems = harness.call(() -> {
            bounce.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            bounce.restart();
            bounce.getClock().setPaused(false);
            StateRing ring = bounce.getRun().getStateRing();
            String[] ends = new String[STEPS + 2];
            for (int i = 0; i < STEPS; ++i) {
                bounce.advance(H);
                ends[(int) ring.getLastIndex()] = graphEnd(bounce.getGraph());
            }
            List<String> found = new ArrayList<>();
            for (int k = 0; k < BACK; ++k) {
                bounce.getReplayControls().stepBack();
                bounce.advance(0f);
                long shown = bounce.getRun().getShownStep();
                String now = graphEnd(bounce.getGraph());
                if (ends[(int) shown] != null && !ends[(int) shown].equals(now)) {
                    found.add("step " + shown + ": was " + ends[(int) shown] + ", now " + now);
                }
            }
            // Going on from the step shown: the graph's clock is that step's.
            bounce.getClock().setPaused(false);
            long from = bounce.getRun().getShownStep();
            bounce.advance(H);
            long index = ring.getLastIndex();
            String now = graphEnd(bounce.getGraph());
            if (index != from + 1 || !ends[(int) index].equals(now)) {
                found.add("the step after " + from + ": was " + ends[(int) index] + ", now "
                        + now);
            }
            return found;
        });
        assertTrue(problems.isEmpty(), problems.toString());
    }

    /** The graph's last sample: its time and both lanes' values, as bits. */
    private static String graphEnd(LiveGraph graph) {
        StringBuilder text = new StringBuilder().append(Float.floatToIntBits(
                graph.getEndTime()));
        for (int lane = 0; lane < 2; ++lane) {
            for (int v = 0; v < 4; ++v) {
                text.append(' ').append(Float.floatToIntBits(graph.getEndValue(lane, v >= 2,
                        (v & 1) == 1)));
            }
        }
        return text.toString();
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.DragDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.HelloAimingDemo;
import particlelab.lecture.ThrustDemo;
import particlelab.lecture.UniformMotionDemo;
import particlelab.lecture.WindDemo;
import particlelab.physics.SimulationClock;
import particlelab.view.LiveGraph;
import particlelab.world.StateRing;

/**
 * After a step back (Home's code path) the demos' own views show the step shown, not the live
 * one, in a real headless jME application (the ghosts and the graph exist only with views):
 * in every demo with exact ghosts, the HUD's ghost lines (|P − P_exact|, the readouts Euler
 * against exact) and the live graph's last sample are, at each step shown, those the original
 * run had at that step, compared bit for bit (the text as written, the graph's floats by their
 * bits: the state read back is the state recorded, so no tolerance). And a shot kept after the
 * step shown is neither drawn nor listed while behind.
 */
class ReplayViewsHeadlessTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    /** Steps of the original run: the launch, the apex, and in most demos the landing. */
    private static final int STEPS = 200;
    private static final List<DemoState> GHOST_DEMOS = List.of(new UniformMotionDemo(),
            new GravitationalPullDemo(), new DragDemo(), new ThrustDemo(), new WindDemo(),
            new HelloAimingDemo());
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> GHOST_DEMOS);

    @Test
    void ghostLinesAndTheGraphEndAreThoseOfTheStepShown() throws Exception {
        for (DemoState demo : GHOST_DEMOS) {
            List<String> problems = harness.call(() -> checkStepsBack(demo));
            assertTrue(problems.isEmpty(), demo.getTitle() + ": " + problems);
        }
    }

    @Test
    void aShotKeptAfterTheStepShownIsHiddenWhileBehind() throws Exception {
        HelloAimingDemo aiming = (HelloAimingDemo) GHOST_DEMOS.get(5);
        int[] seen = harness.call(() -> {
            aiming.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            aiming.restart();
            aiming.getClock().setPaused(false);
            KeptShots shots = ((DemoState) aiming).getParameterControls().getKeptShots();
            shots.clear();
            aiming.fire();
            for (int i = 0; i < 40; ++i) {
                aiming.advance(H);
            }
            // The second launch keeps the first shot's path.
            aiming.fire();
            int keptLive = shots.size();
            int drawnLive = shots.countDrawnPaths();
            String legendLive = shots.formatLegend(new StringBuilder(),
                    aiming.getParameters()).toString();
            for (int i = 0; i < 20; ++i) {
                aiming.advance(H);
            }
            // Back past the launch: 20 steps, the launch's entry, one more.
            for (int i = 0; i < 22; ++i) {
                aiming.getReplayControls().stepBack();
            }
            int keptBehind = shots.size();
            String legendBehind = shots.formatLegend(new StringBuilder(),
                    aiming.getParameters()).toString();
            int drawnBehind = shots.countDrawnPaths();
            for (int i = 0; i < 22; ++i) {
                aiming.getReplayControls().stepForward();
            }
            int keptAgain = shots.size();
            return new int[] {keptLive, legendLive.isEmpty() ? 0 : 1, keptBehind,
                legendBehind.isEmpty() ? 0 : 1, drawnLive, drawnBehind, keptAgain,
                aiming.getRun().isReplaying() ? 1 : 0, shots.countDrawnPaths()};
        });
        // HelloAiming launches its two bullets one by one, and each launch keeps what moved:
        // the first shot is kept once or twice; what matters is that it is kept.
        assertTrue(seen[0] >= 1, "the first shot is kept at the second launch");
        assertEquals(1, seen[1], "and listed");
        assertEquals(0, seen[2], "before the launch that kept it, no shot is kept");
        assertEquals(0, seen[3], "nor listed");
        assertTrue(seen[4] > 0, "its paths are drawn at the live end");
        assertEquals(0, seen[5], "and not drawn before the launch that kept it");
        assertEquals(0, seen[7], "End came back to the live end");
        assertEquals(seen[0], seen[6], "back at the live end it is listed again");
        assertEquals(seen[4], seen[8], "and drawn again");
    }

    /** Run, remember each step's view lines and graph end, step back, compare. */
    private static List<String> checkStepsBack(DemoState demo) {
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        demo.restart();
        demo.getClock().setPaused(false);
        StateRing ring = demo.getRun().getStateRing();
        String[] lines = new String[STEPS + 2];
        String[] graphEnds = new String[STEPS + 2];
        for (int i = 0; i < STEPS && !demo.getRun().isSceneOver(); ++i) {
            demo.advance(H);
            lines[(int) ring.getLastIndex()] = ghostLines(demo);
            graphEnds[(int) ring.getLastIndex()] = graphEnd(demo);
        }
        List<String> problems = new ArrayList<>();
        long last = ring.getLastIndex();
        for (int k = 1; k <= last - ring.getFirstIndex(); ++k) {
            demo.getReplayControls().stepBack();
            demo.advance(0f);
            long shown = demo.getRun().getShownStep();
            if (lines[(int) shown] == null) {
                continue;
            }
            if (!lines[(int) shown].equals(ghostLines(demo))) {
                problems.add("step " + shown + " HUD: was\n" + lines[(int) shown] + "now\n"
                        + ghostLines(demo));
            }
            if (!graphEnds[(int) shown].equals(graphEnd(demo))) {
                problems.add("step " + shown + " graph end: was " + graphEnds[(int) shown]
                        + ", now " + graphEnd(demo));
            }
            LiveGraph graph = demo.getExactGhosts().getGraph();
            for (int s = 0; s < graph.countDrawn() - 1; ++s) {
                if (graph.getTime(s) >= graph.getEndTime()) {
                    problems.add("step " + shown + ": a sample after the step shown is drawn");
                }
            }
            if (problems.size() > 3) {
                break;
            }
        }
        if (problems.isEmpty() && !demo.getRun().isReplaying()) {
            problems.add("never behind the live end");
        }
        return problems;
    }

    /** The HUD's lines about the ghosts: the live distances and the readouts. */
    private static String ghostLines(DemoState demo) {
        StringBuilder kept = new StringBuilder();
        for (String line : demo.formatHud(new StringBuilder()).toString().split("\n")) {
            if (line.contains("P_exact") || line.contains("Euler | exact")) {
                kept.append(line).append('\n');
            }
        }
        return kept.toString();
    }

    /** The ghosts' graph's last sample: its time and every value, as bits. */
    private static String graphEnd(DemoState demo) {
        return graphEnd(demo.getExactGhosts().getGraph(), demo.getParticles().size());
    }

    /** A graph's last sample: its time and every value, as bits. */
    private static String graphEnd(LiveGraph graph, int series) {
        StringBuilder text = new StringBuilder().append(Float.floatToIntBits(
                graph.getEndTime()));
        for (int p = 0; p < series; ++p) {
            for (int v = 0; v < 4; ++v) {
                text.append(' ').append(Float.floatToIntBits(graph.getEndValue(p, v >= 2,
                        (v & 1) == 1)));
            }
        }
        return text.toString();
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.app.DemoCatalog;
import particlelab.lecture.DragDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.HelloAimingDemo;
import particlelab.world.StateRing;

/**
 * Step back, replay, bit for bit, in every catalogued demo, in plain JUnit (no jME): the
 * demo runs, its ring records every step; then Home N times and Space for N steps
 * re-simulates them, and every recorded state (every body's P, V, rotation, the alive set,
 * the particles' and the demo's own counters) has the same bits as the first time; Home N
 * times and End N times reads them back to the live end's state. No tolerance: the step is
 * deterministic, so any difference is state the ring failed to record. The demo's own HUD
 * lines, compared step by step too, catch counters that feed no step but are shown.
 */
class ReplayDeterminismTest {

    private static final float H = 1f / 60f;
    /** Six seconds of steps at the default h: launches, landings, bounces, spawns. */
    private static final int STEPS = 360;
    private static final int[] BACK = {1, 60, 300};

    static Stream<String> demoNames() {
        return DemoCatalog.names().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("demoNames")
    void stepBackThenReplayGivesTheSameBits(String name) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
        assertReplaysTheSameBits(demo, name);
    }

    /** The comparison lane's own state (double, slide code, readouts) goes into the ring. */
    @ParameterizedTest(name = "drag, lane={0}")
    @ValueSource(strings = {"rk4", "slide"})
    void aComparisonLaneReplaysTheSameBits(String lane) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf("drag")).create();
        DemoParameter parameter = demo.getParameters().get(
                demo.getParameters().indexOf(ComparisonLane.PARAMETER));
        demo.getParameters().set(ComparisonLane.PARAMETER, parameter.indexOfChoice(lane));
        demo.restart();
        assertReplaysTheSameBits(demo, "drag, lane=" + lane);
    }

    /**
     * Drag's what-if changes set for the whole run: forward Euler (its waiting velocities and
     * the forceless integrator in the ring), the swapped laws (the bodies' other integrators).
     */
    @ParameterizedTest(name = "drag, {0}")
    @ValueSource(strings = {"method=1", "drag=1"})
    void dragsMethodAndSwappedLawsReplayTheSameBits(String setting) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf("drag")).create();
        String[] nameValue = setting.split("=");
        demo.getParameters().set(nameValue[0], Float.parseFloat(nameValue[1]));
        demo.restart();
        assertReplaysTheSameBits(demo, "drag, " + setting);
    }

    /**
     * The student lane with the reference solution: stepped on again from a state read back,
     * the student's recipe gives the same bits (its state is the lane's, in the ring).
     */
    @Test
    void theStudentLaneReplaysTheSameBits() {
        DragDemo demo = new DragDemo();
        demo.getLane().useStudentClass("particlelab.solutions.Recipe", 10_000_000_000L);
        demo.getParameters().set(ComparisonLane.PARAMETER,
                ComparisonLane.Kind.STUDENT.ordinal());
        demo.restart();
        assertReplaysTheSameBits(demo, "drag, lane=student (the solution)");
        assertEquals(null, demo.getLane().getStudentProblem());
    }

    /**
     * A lane off by default, on here: HelloAiming's slide-code bullet beside the recipe's
     * (its own vectors and step count in the demo's record).
     */
    @Test
    void stepBackThenReplayGivesTheSameBitsWithTheSlideCodeLaneOn() {
        HelloAimingDemo aiming = new HelloAimingDemo();
        aiming.setCode(HelloAimingDemo.BOTH_CODES);
        assertReplaysTheSameBits(aiming, "aiming code=both");
    }

    /** The cheat's frontier with the drop-corrected way alone (its square's shot time). */
    @Test
    void stepBackThenReplayGivesTheSameBitsWithTheCheatFrontierOn() {
        FastBulletsDemo cheat = new FastBulletsDemo();
        cheat.getParameters().set("shot", 3);
        assertReplaysTheSameBits(cheat, "cheat shot=raised");
    }

    /** Step back and replay a demo, then End; compare every step's bits (class Javadoc). */
    private static void assertReplaysTheSameBits(DemoState demo, String name) {
        StateRing ring = demo.getRun().getStateRing();
        String[] ownLines = new String[STEPS + 2];
        for (int i = 0; i < STEPS; ++i) {
            demo.getRun().advancePhysics(H);
            ownLines[(int) ring.getLastIndex()] = ownLines(demo);
        }
        long last = ring.getLastIndex();
        assertTrue(last > 0, name + ": no step recorded");
        int[][] first = new int[(int) last + 1][];
        for (long i = ring.getFirstIndex(); i <= last; ++i) {
            first[(int) i] = ring.copyEntry(i);
        }
        for (int back : BACK) {
            int steps = (int) Math.min(back, last - ring.getFirstIndex());
            for (int i = 0; i < steps; ++i) {
                assertTrue(demo.getReplayControls().stepBack(), name + ": step back " + (i + 1));
            }
            assertTrue(demo.getRun().isReplaying());
            long from = demo.getRun().getShownStep();
            assertEquals(last - steps, from);
            assertArrayEquals(first[(int) from], writeNow(demo), name + ": read back");
            // Space: the clock runs again from the step shown, re-simulating.
            demo.getClock().setPaused(false);
            for (int i = 0; i < steps; ++i) {
                demo.getRun().advancePhysics(H);
                long index = ring.getLastIndex();
                assertArrayEquals(first[(int) index], ring.copyEntry(index),
                        name + ": step " + index + " re-simulated after " + steps + " back");
                // The demo's own HUD lines (its counters, scores, readouts) see state the ring
                // might have missed.
                assertEquals(ownLines[(int) index], ownLines(demo),
                        name + ": HUD at step " + index + " re-simulated after " + steps
                                + " back");
            }
            assertFalse(demo.getRun().isReplaying());
            assertEquals(last, ring.getLastIndex());
        }
        for (int i = 0; i < BACK[1]; ++i) {
            demo.getReplayControls().stepBack();
        }
        for (int i = 0; i < BACK[1]; ++i) {
            demo.getReplayControls().stepForward();
        }
        assertFalse(demo.getRun().isReplaying(), name + ": End came back to the live end");
        assertArrayEquals(first[(int) last], writeNow(demo), name + ": End read back");
    }

    /**
     * The demo's own HUD lines and its parts', without those that measure wall time (the
     * fountain's milliseconds per frame).
     */
    private static String ownLines(DemoState demo) {
        StringBuilder text = new StringBuilder();
        demo.writeOwnHudLines(text);
        StringBuilder kept = new StringBuilder();
        for (String line : text.toString().split("\n")) {
            if (line.contains("ms/frame")) {
                continue;
            }
            // a comparison lane's cost is measured on another thread, in wall time
            int cost = line.indexOf("   cost");
            kept.append(cost < 0 ? line : line.substring(0, cost)).append('\n');
        }
        return kept.toString();
    }

    /** The demo's state now, as one ring entry. */
    private static int[] writeNow(DemoState demo) {
        StateRing now = new StateRing();
        now.record(demo.getRun().getReplay().getRecord(), 0f);
        return now.copyEntry(0);
    }
}

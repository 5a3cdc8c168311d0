package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.Allocations;
import particlelab.app.DemoCatalog;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.DragDemo;
import particlelab.world.StateRing;

/**
 * What-if forks in plain JUnit (no jME): a twin of a demo takes a recorded state and runs on
 * with one change. Every comparison is of whole ring entries (t, each particle's P and V,
 * the world, the counters, the demo's own state) bit for bit: the step is deterministic, so
 * no tolerance; any difference is state the fork failed to copy or a change applied
 * differently.
 */
class WhatIfForkTest {

    /** The span: the fork's future compared over this many steps. */
    private static final int FUTURE_STEPS = 300;
    /** The recorded step forked from: the flight under way. */
    private static final int FORK_STEP = 40;
    /** The changed step h' (in seconds): one of the panel's stops, 1/30 s. */
    private static final float H_PRIME = 1f / 30f;

    /** A fork with nothing changed has the demo's own recorded future, bit for bit. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"uniform", "pull", "drag", "thrust", "bounce"})
    void aForkWithNothingChangedIsTheOriginalFuture(String name) {
        DemoState origin = create(name);
        StateRing ring = origin.getRun().getStateRing();
        stepSingly(origin, FORK_STEP + FUTURE_STEPS);
        WhatIfFork fork = new WhatIfFork(create(name));
        fork.start(origin, FORK_STEP, null, 0f);
        assertSameFuture(ring, fork, name);
    }

    /**
     * A fork with h' from a recorded step equals the run that reached that step and went on
     * at h' (h set with {@code --set}'s parameter at that step, then stepped). Not uniform:
     * at h' = 1/30 s its sphere leaves the screen within the span and the demo loops by a
     * reset, which clears the ring and numbers its entries from 0 again.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pull", "drag", "thrust", "bounce"})
    void aForkWithAnotherStepIsTheRunStartedThereAtThatStep(String name) {
        DemoState origin = create(name);
        stepSingly(origin, FORK_STEP);
        DemoState reference = create(name);
        stepSingly(reference, FORK_STEP);
        reference.getParameters().set("h", H_PRIME);
        StateRing referenceRing = reference.getRun().getStateRing();
        stepSingly(reference, FUTURE_STEPS);
        assertEquals(H_PRIME, referenceRing.getStepSeconds(referenceRing.getLastIndex()));

        WhatIfFork fork = new WhatIfFork(create(name));
        fork.start(origin, FORK_STEP, "h", H_PRIME);
        assertSameFuture(referenceRing, fork, name + " at h'");
    }

    /**
     * Three forks stepped long past the demo's ring: each twin keeps two entries, so all
     * three together cost less than the demo's own ring (without the limit each twin's ring
     * would size itself as the demo's does, three times its bytes).
     */
    @Test
    void forksStayWithinTheRingsCap() {
        DemoState origin = create("drag");
        stepSingly(origin, FORK_STEP);
        StateRing ring = origin.getRun().getStateRing();
        long twinBytes = 0L;
        String[] names = {null, "h", "b"};
        float[] values = {0f, H_PRIME, 0.5f};
        for (int f = 0; f < names.length; ++f) {
            WhatIfFork fork = new WhatIfFork(create("drag"));
            fork.start(origin, FORK_STEP, names[f], values[f]);
            for (int k = 0; k < 2 * StateRing.DEFAULT_MAX_STEPS; ++k) {
                fork.step();
            }
            StateRing twinRing = fork.getRun().getStateRing();
            assertEquals(WhatIfFork.TWIN_RING_STEPS, twinRing.getCapacity());
            assertTrue(twinRing.size() <= WhatIfFork.TWIN_RING_STEPS);
            twinBytes += twinRing.getBytes();
        }
        assertTrue(twinBytes <= ring.getBytes(), "three forks' rings take " + twinBytes
                + " bytes, the demo's ring " + ring.getBytes());
    }

    /**
     * Keeping a fork: the demo goes on from the forked step with the change and ends in the
     * fork's state, bit for bit; at bounce, whose e resets the drop, too.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"drag:h:0.033333335", "bounce:e:0.6", "bounce:h:0.033333335"})
    void keepingAForkGoesOnFromItsState(String spec) {
        String[] parts = spec.split(":");
        DemoState origin = create(parts[0]);
        stepSingly(origin, FORK_STEP + FUTURE_STEPS);
        WhatIfFork fork = new WhatIfFork(create(parts[0]));
        fork.start(origin, FORK_STEP, parts[1], Float.parseFloat(parts[2]));
        for (int k = 0; k < FUTURE_STEPS / 2; ++k) {
            fork.step();
        }
        fork.keep(origin);
        StateRing ring = origin.getRun().getStateRing();
        StateRing twinRing = fork.getRun().getStateRing();
        assertArrayEquals(twinRing.copyEntry(twinRing.getLastIndex()),
                ring.copyEntry(ring.getLastIndex()), spec + ": the kept state");
        assertEquals(Float.parseFloat(parts[2]), origin.getParameters().getValue(parts[1]));
    }

    /**
     * The part's keys without a window: Insert forks lanes with the changes offered in turn,
     * the HUD line names them, frames move them on, J keeps the newest (the demo's state is
     * then the lane's, bit for bit), and a fourth Insert drops three lanes.
     */
    @Test
    void thePartForksKeepsAndDropsLanes() {
        BounceDemo bounce = new BounceDemo();
        stepSingly(bounce, FORK_STEP);
        WhatIfPart whatIf = bounce.getWhatIf();
        for (int lane = 0; lane < WhatIfPart.MAX_LANES; ++lane) {
            whatIf.forkOrDrop();
        }
        assertEquals(WhatIfPart.MAX_LANES, whatIf.countLanes());
        StringBuilder hud = new StringBuilder();
        whatIf.writeHudLines(hud);
        assertEquals("what if (J keeps the newest, Insert drops them):  pink as recorded,"
                + "  yellow e = 0.6,  lilac h = 1/30 s;  next: as recorded\n", hud.toString());
        for (int frame = 0; frame < 60; ++frame) {
            whatIf.afterFrame();
        }
        // 60 frames of 1/60 s of lane time: 60 steps at h = 1/60 s, 30 at 1/30 s (a lane
        // steps up to the nearest step's end, so a float h a little over 1/60 loses none).
        assertEquals(60, whatIf.getLane(0).getSteps());
        assertEquals(60, whatIf.getLane(1).getSteps());
        assertEquals(30, whatIf.getLane(2).getSteps());
        WhatIfFork newest = whatIf.getLane(2);
        whatIf.keepNewest();
        assertEquals(0, whatIf.countLanes());
        StateRing ring = bounce.getRun().getStateRing();
        StateRing twinRing = newest.getRun().getStateRing();
        assertArrayEquals(twinRing.copyEntry(twinRing.getLastIndex()),
                ring.copyEntry(ring.getLastIndex()), "the kept lane's state");
        assertEquals(1f / 30f, bounce.getParameters().getValue("h"));
        for (int lane = 0; lane <= WhatIfPart.MAX_LANES; ++lane) {
            whatIf.forkOrDrop();
        }
        assertEquals(0, whatIf.countLanes(), "a fourth Insert drops the lanes");
    }

    /** Lanes going on frame by frame, and their HUD line, allocate nothing. */
    @Test
    void lanesGoingOnAllocateNothing() {
        DragDemo drag = new DragDemo();
        stepSingly(drag, FORK_STEP);
        WhatIfPart whatIf = drag.getWhatIf();
        for (int lane = 0; lane < WhatIfPart.MAX_LANES; ++lane) {
            whatIf.forkOrDrop();
        }
        whatIf.afterFrame();
        StringBuilder hud = new StringBuilder(256);
        Allocations.assertAllocatesNothing("what-if lanes, 60 frames", () -> {
            for (int frame = 0; frame < 60; ++frame) {
                whatIf.afterFrame();
                hud.setLength(0);
                whatIf.writeHudLines(hud);
            }
        });
        assertTrue(whatIf.getLane(0).getSteps() > 60, "the lanes moved on");
    }

    /**
     * Step a fork {@link #FUTURE_STEPS} times and compare each state with the recorded
     * future: a flight that lands stops there (its scene is over, no step is taken), and the
     * fork must land at the same step and stay there.
     */
    private static void assertSameFuture(StateRing expected, WhatIfFork fork, String name) {
        StateRing twinRing = fork.getRun().getStateRing();
        long expectedLast = expected.getLastIndex();
        for (int k = 1; k <= FUTURE_STEPS; ++k) {
            fork.step();
            long index = Math.min(FORK_STEP + k, expectedLast);
            assertArrayEquals(expected.copyEntry(index),
                    twinRing.copyEntry(twinRing.getLastIndex()),
                    name + ": step " + k + " after the fork");
        }
        // The twin's ring counts its steps from the fork's start (entry 0).
        assertEquals(expectedLast - FORK_STEP, twinRing.getLastIndex(),
                name + ": steps taken after the fork");
    }

    private static DemoState create(String name) {
        return DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
    }

    /** Take steps one at a time with the demo's single step, as N does. */
    private static void stepSingly(DemoState demo, int steps) {
        for (int i = 0; i < steps; ++i) {
            demo.getRun().singleStep();
            demo.getRun().advancePhysics(0f);
        }
    }
}

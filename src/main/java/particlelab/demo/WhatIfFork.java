package particlelab.demo;

import particlelab.world.StateRing;
import particlelab.world.StateSlab;

/**
 * One what-if fork: a twin of a demo (a second instance of the same demo class, without
 * views) that takes a recorded state of the demo and runs it forward with one parameter
 * changed, so the lecturer watches where the futures part. The twin is the demo's own code,
 * stepped by its own {@link DemoRun} exactly as the demo steps: with nothing changed its
 * future has the same bits as the demo's (WhatIfForkTest).
 *
 * <p>Bounded: the twin's replay ring keeps {@link #TWIN_RING_STEPS} entries (the newest
 * state, for the step after it) instead of the demo's minute, so forks cost a few entries of
 * the demo's stride each, not a ring each; the path the lane draws is the view's, in a
 * fixed array.
 *
 * <p>Forking: the twin takes the demo's parameter values (the values the scene runs with,
 * then those waiting for the next launch), is put back to its launch, gets the one change,
 * then reads the demo's ring entry: the change applies from the forked state on, as a change
 * of a live parameter in the panel would have at that step.
 */
final class WhatIfFork {

    /** Entries the twin's ring keeps: the fewest a ring keeps. */
    static final int TWIN_RING_STEPS = 2;

    private final DemoState twin;
    private final DemoRun run;
    /** The parameter changed, as {@code --set} names it; null: nothing changed. */
    private String parameter;
    /** Its value in the fork. */
    private float value;
    /** The ring entry of the demo the fork started from. */
    private long startIndex = -1L;
    /** Steps taken since the fork. */
    private int steps;

    /**
     * Wrap a twin: a new instance of the demo's class, never shown.
     *
     * @param twin the twin (not null, not yet stepped)
     */
    WhatIfFork(DemoState twin) {
        if (twin == null) {
            throw new IllegalArgumentException("fork twin must be a demo, but was null");
        }
        this.twin = twin;
        this.run = twin.getRun();
        run.getStateRing().limitSteps(TWIN_RING_STEPS);
    }

    /**
     * Start the fork from a recorded state of a demo, with one change.
     *
     * @param origin the demo forked (not null, the twin's class)
     * @param index the origin's ring entry to start from (one it holds)
     * @param name the parameter changed ({@code --set} name), or null for no change
     * @param newValue its value in the fork (within its range)
     * @throws IllegalArgumentException for an unknown name or a value out of range
     */
    void start(DemoState origin, long index, String name, float newValue) {
        DemoParameters from = origin.getParameters();
        DemoParameters to = twin.getParameters();
        for (int i = 0; i < from.size(); ++i) {
            to.set(i, from.getValueInScene(i));
        }
        run.restart();
        for (int i = 0; i < from.size(); ++i) {
            to.set(i, from.getValue(i));
        }
        if (name != null) {
            to.set(name, newValue);
        }
        parameter = name;
        value = newValue;
        StateRing ring = origin.getRun().getStateRing();
        run.getReplay().getRecord().readState(ring.read(index));
        run.getClock().restoreSimulatedSeconds(run.getWorld().getTimeSeconds());
        run.getClock().setPaused(true);
        startIndex = index;
        steps = 0;
    }

    /** Take one step of the twin's h, as the demo's single step does. Allocates nothing. */
    void step() {
        run.singleStep();
        run.advancePhysics(0f);
        ++steps;
    }

    /** @return the twin's run: its particles, world, clock (live, not null) */
    DemoRun getRun() {
        return run;
    }

    /** @return the twin: the demo's class, never shown (live, not null) */
    DemoState getTwin() {
        return twin;
    }

    /** @return the parameter changed, or null for none */
    String getParameter() {
        return parameter;
    }

    /** @return the changed parameter's value in the fork */
    float getValue() {
        return value;
    }

    /** @return the origin's ring entry the fork started from (-1 before a start) */
    long getStartIndex() {
        return startIndex;
    }

    /** @return the steps taken since the fork (&ge;0) */
    int getSteps() {
        return steps;
    }

    /**
     * Keep this fork: the demo goes on from the forked entry with the change, re-simulating
     * the fork's steps with its own run (so its trails, rows and ring follow): deterministic,
     * so it ends in the fork's state bit for bit. The entries after the forked one are
     * dropped, as a step taken behind the live end drops them.
     *
     * @param origin the demo forked (not null, holding the forked entry)
     */
    void keep(DemoState origin) {
        DemoRun originRun = origin.getRun();
        Replay replay = originRun.getReplay();
        StateRing ring = originRun.getStateRing();
        // A change may reset the demo (bounce drops the ball again at a new e): keep the
        // forked entry to read back then. A key press, not a frame: the copy may allocate.
        int[] forked = ring.copyEntry(startIndex);
        while (replay.getShownIndex() > startIndex && replay.stepBack()) {
            // each step back walks the trails with it
        }
        while (replay.getShownIndex() < startIndex && replay.stepForward()) {
            // likewise forward
        }
        if (parameter != null) {
            origin.getParameters().set(parameter, value);
        }
        if (ring.size() == 0) {
            StateSlab slab = new StateSlab();
            slab.point(forked, 0, forked.length);
            replay.getRecord().readState(slab);
            originRun.getClock().restoreSimulatedSeconds(originRun.getWorld().getTimeSeconds());
        }
        originRun.getClock().setPaused(true);
        for (int i = 0; i < steps; ++i) {
            originRun.singleStep();
            originRun.advancePhysics(0f);
        }
    }
}

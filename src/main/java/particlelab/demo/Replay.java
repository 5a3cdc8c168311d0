package particlelab.demo;

import java.util.List;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateRing;
import particlelab.world.StateSlab;
import particlelab.world.World;

/**
 * What {@link DemoState} does to step back, replay and scrub, and to draw between steps, in
 * one place. After every step of the clock the demo's whole state (its {@link World}, the
 * simulations beside it, the particles' own counters and the demo's declared state) goes into
 * a bounded {@link StateRing}; Home puts the previous entry back, End the next one, the
 * panel's timeline any one. While a recorded step is shown ("behind the live end"), the
 * next step the clock takes (Space, N) goes on from there and drops the ring's later
 * entries: they are no longer this run's future.
 *
 * <p>The view blends the last two physics states, {@code P_prev + α·(P − P_prev)} with
 * {@code α = leftover / h} ("fix your timestep"), unless interpolation is off (F6), the clock
 * runs raw tpf, is paused, or a recorded step is shown: then α = 1, the physics state itself.
 * The HUD's numbers are always the physics state; its replay line says what is drawn.
 */
final class Replay {

    /** The steps per second the HUD's span is given at (the default h). */
    static final int STEPS_PER_SECOND = 60;
    /** Bytes per mebibyte, for the HUD. */
    private static final double MIB = 1024.0 * 1024.0;

    private final StateRing ring;
    private final StateRecord record;
    private final SimulationClock clock;
    private final World world;
    private final List<DemoParticle> particles;
    /** The entry shown while behind the live end; -1 while live. */
    private long shownIndex = -1L;
    private boolean interpolating = true;
    /** False in a demo whose views draw the raw steps whatever F6 says (see below). */
    private boolean viewsBlend = true;
    /** The blend the views were drawn with this frame. */
    private float frameBlend = 1f;
    /** Bumped at every change the timeline shows (a step, a restore). */
    private int version;
    /** The views' trails, walked with the steps shown (null: no views). */
    private TrailWalk trails;

    /** What the views do when a recorded step is undone or redone. */
    interface TrailWalk {
        /**
         * Take the newest trail point of a particle the undone step moved.
         *
         * @param particle the particle (not null)
         */
        void undone(DemoParticle particle);

        /**
         * Add the position of a particle the redone step moved to its trail.
         *
         * @param particle the particle (not null)
         */
        void redone(DemoParticle particle);
    }

    /**
     * Create the replay of a demo.
     *
     * @param ring where the states go (not null)
     * @param record the demo's whole state (not null)
     * @param clock the demo's clock (not null)
     * @param world the demo's world (not null)
     * @param particles the demo's particles (not null, live)
     */
    Replay(StateRing ring, StateRecord record, SimulationClock clock, World world,
            List<DemoParticle> particles) {
        this.ring = ring;
        this.record = record;
        this.clock = clock;
        this.world = world;
        this.particles = particles;
    }

    /**
     * Walk the views' trails with the steps shown from now on.
     *
     * @param walk the trails (not null)
     */
    void setTrails(TrailWalk walk) {
        trails = walk;
    }

    /**
     * Say that the demo's own views (a point cloud, rotating boxes) draw the raw steps, so the
     * HUD does not claim an interpolated picture it does not draw.
     */
    void drawsRawSteps() {
        viewsBlend = false;
    }

    /** Before a step of the clock: leave the recorded past, and record the start if new. */
    void beforeStep() {
        if (shownIndex >= 0L) {
            ring.truncateAfter(shownIndex);
            shownIndex = -1L;
        }
        if (ring.size() == 0) {
            ring.record(record, 0f);
        }
    }

    /**
     * After a step of the clock (the world and every simulation beside it): record it.
     *
     * @param stepSeconds h (in seconds, &gt;0)
     */
    void afterStep(float stepSeconds) {
        ring.record(record, stepSeconds);
        ++version;
    }

    /** A reset: forget every entry (the next step records the start again). */
    void clear() {
        ring.clear();
        shownIndex = -1L;
        ++version;
    }

    /**
     * A launch outside a step changed the state: it becomes an entry of h 0, so a step back
     * and forth keeps it. Inside a step the step's own entry has it.
     */
    void stateChanged() {
        if (world.isStepping() || ring.size() == 0) {
            return;
        }
        beforeStep();
        ring.record(record, 0f);
        ++version;
    }

    /**
     * Show the entry before the one shown (pausing first).
     *
     * @return false if there is none (the ring's oldest, or empty)
     */
    boolean stepBack() {
        clock.setPaused(true);
        long current = getShownIndex();
        if (ring.size() == 0 || current <= ring.getFirstIndex()) {
            return false;
        }
        show(current - 1L);
        return true;
    }

    /**
     * Show the entry after the one shown (pausing first).
     *
     * @return false at the live end: the caller takes a step instead
     */
    boolean stepForward() {
        clock.setPaused(true);
        if (shownIndex < 0L) {
            return false;
        }
        show(shownIndex + 1L);
        return true;
    }

    /**
     * Show the entry at a place of the timeline (pausing first).
     *
     * @param fraction 0 for the oldest entry, 1 for the newest (clamped)
     */
    void scrub(double fraction) {
        if (ring.size() < 2) {
            return;
        }
        clock.setPaused(true);
        double clamped = Math.max(0.0, Math.min(1.0, fraction));
        long index = ring.getFirstIndex() + Math.round(clamped * (ring.size() - 1));
        if (index != getShownIndex()) {
            show(index);
        }
    }

    /** @return the timeline's place of the entry shown, 0 to 1 (1 while live) */
    double getFraction() {
        if (ring.size() < 2 || shownIndex < 0L) {
            return 1.0;
        }
        return (double) (shownIndex - ring.getFirstIndex()) / (ring.size() - 1);
    }

    /** @return true while the clock is paused */
    boolean isPaused() {
        return clock.isPaused();
    }

    /** @return the simulated time of the state shown (in seconds) */
    double getShownSeconds() {
        return world.getTimeSeconds();
    }

    /** @return true while a recorded step, not the live end, is shown */
    boolean isBehind() {
        return shownIndex >= 0L;
    }

    /** @return the number of the entry shown (the newest while live) */
    long getShownIndex() {
        return shownIndex >= 0L ? shownIndex : ring.getLastIndex();
    }

    /** @return a number that changes whenever the timeline would show something new */
    int getVersion() {
        return version;
    }

    /** Switch the drawing between the blend of the last two states and the raw steps. */
    void toggleInterpolation() {
        interpolating = !interpolating;
    }

    /** @return true if the view blends the last two states */
    boolean isInterpolating() {
        return interpolating;
    }

    /**
     * Return the blend the view draws with, {@code α = leftover / h} in 0 to 1: 1 (the
     * physics state) with interpolation off, in raw tpf, paused, behind the live end or once
     * the scene is over.
     *
     * @param sceneOver true once nothing moves
     * @return α (0 to 1)
     */
    float blend(boolean sceneOver) {
        if (!interpolating || clock.getMode() == SimulationClock.Mode.RAW_TPF
                || clock.isPaused() || shownIndex >= 0L || sceneOver) {
            return 1f;
        }
        double alpha = clock.getLeftoverSeconds() / clock.getStepSeconds();
        return (float) Math.max(0.0, Math.min(1.0, alpha));
    }

    /**
     * Work out the blend of this frame ({@link #blend}) and keep it for the HUD.
     *
     * @param sceneOver true once nothing moves
     * @return α (0 to 1)
     */
    float updateFrameBlend(boolean sceneOver) {
        frameBlend = blend(sceneOver);
        return frameBlend;
    }

    /** @return the blend of this frame (0 to 1; 1 before the first frame) */
    float getFrameBlend() {
        return frameBlend;
    }

    /**
     * Append, to the HUD's stepping line, what is drawn (the HUD's numbers are always the
     * last step's) or, while behind the live end, the step shown, or, while paused at the live
     * end, the replay keys and what the ring holds: always on the same line, so pausing or
     * stepping back never changes the HUD's height (nor the scene's rectangle, which would
     * move the picture under the mouse). Allocates nothing.
     *
     * @param text where to append (not null, modified)
     */
    void appendHudText(StringBuilder text) {
        if (shownIndex >= 0L) {
            text.append("   replay: step ").append(shownIndex - ring.getFirstIndex())
                    .append(" of ").append(ring.size() - 1)
                    .append("; Space or N go on from here, the later steps are dropped");
        } else if (clock.isPaused()) {
            appendRing(text.append("   Home steps back, End forward; "));
        } else if (!viewsBlend) {
            text.append("   drawn: raw steps (this demo's views)");
        } else if (!interpolating) {
            text.append("   drawn: raw steps (F6)");
        } else if (frameBlend < 1f) {
            text.append("   drawn: interpolated (α = ");
            TextFormat.appendFixed(text, frameBlend, 2)
                    .append("); numbers: the last step (F6)");
        } else {
            text.append("   drawn: interpolated, α = 1 (F6)");
        }
    }

    /**
     * Append what the ring holds and costs: "ring: 60.0 s of 60 steps/s, 4.3 MB".
     *
     * @param text where to append (not null, modified)
     * @return text
     */
    StringBuilder appendRing(StringBuilder text) {
        text.append("ring: ");
        int steps = ring.getCapacity() > 0 ? ring.getCapacity() : ring.getMaxSteps();
        TextFormat.appendFixed(text, (double) steps / STEPS_PER_SECOND, 1)
                .append(" s of ").append(STEPS_PER_SECOND).append(" steps/s, ");
        return TextFormat.appendFixed(text, ring.getBytes() / MIB, 1).append(" MB");
    }

    /** @return the demo's whole state, as the ring records it (for tests) */
    StateRecord getRecord() {
        return record;
    }

    /**
     * Access the ring.
     *
     * @return the live ring (not null)
     */
    StateRing getRing() {
        return ring;
    }

    /**
     * Put an entry back, and walk the trails there one step at a time: a step undone takes
     * each stepped particle's newest trail point off, a step redone adds its position.
     */
    private void show(long index) {
        long from = getShownIndex();
        while (from > index) {
            ring.restore(from, record);
            for (int i = 0; i < particles.size(); ++i) {
                DemoParticle particle = particles.get(i);
                if (particle.steppedThisStep && trails != null) {
                    trails.undone(particle);
                }
            }
            --from;
        }
        while (from < index) {
            ++from;
            ring.restore(from, record);
            for (int i = 0; i < particles.size(); ++i) {
                DemoParticle particle = particles.get(i);
                if (particle.steppedThisStep && trails != null
                        && ring.getStepSeconds(from) > 0f) {
                    trails.redone(particle);
                }
            }
        }
        ring.restore(index, record);
        shownIndex = index == ring.getLastIndex() ? -1L : index;
        clock.restoreSimulatedSeconds(world.getTimeSeconds());
        ++version;
    }

    /**
     * Read the time and each particle's P and V of an entry, as the demo's record writes them
     * first (for the export of the recorded span).
     *
     * @param index the entry's number
     * @param storeRow storage: t, then x, y, z, vx, vy, vz per particle (not null, modified)
     * @return storeRow
     */
    float[] copyRow(long index, float[] storeRow) {
        StateSlab slab = ring.read(index);
        storeRow[0] = (float) slab.getDouble();
        for (int i = 0; i < particles.size(); ++i) {
            for (int k = 0; k < 6; ++k) {
                storeRow[1 + 6 * i + k] = slab.getFloat();
            }
        }
        return storeRow;
    }
}

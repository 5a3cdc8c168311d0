package particlelab.physics;

/**
 * Turns the frame times a game loop hands us into integrator steps: pause, single step, time
 * scale, and two stepping modes.
 *
 * <ul>
 * <li>{@link Mode#RAW_TPF}: one step of exactly {@code tpf·timeScale} per frame, the lecture's
 * way. Frame-time spikes go straight into the physics: that is what the mode is there to
 * show.</li>
 * <li>{@link Mode#FIXED_STEP}: steps of a fixed {@code h} from an accumulator; the leftover
 * (less than h) is carried to the next frame. A frame longer than {@link #getMaxFrameSeconds()}
 * is clamped, and at most {@link #getMaxStepsPerFrame()} steps run per frame; simulated time
 * beyond either limit is dropped (and counted in {@link #getDroppedSeconds()}), so a 5 s hitch
 * neither explodes the simulation nor freezes the app catching up.</li>
 * </ul>
 *
 * Pause freezes only the simulation: the caller keeps rendering and reading input. While
 * paused, {@link #requestSingleStep()} makes the next frame take exactly one step of h.
 *
 * <p>The time scale asks for a speed; the clamp and the step cap decide what a frame can give.
 * The clock measures what it gave: {@link #getMeasuredTimeScale()} is simulated seconds per
 * frame-time second over the last window of at least {@link #RATE_WINDOW_SECONDS}, and
 * {@link #isDroppingTime()} says whether the clamp or the cap dropped time in that window or
 * the one under way. At 60 frames per second the defaults give at most x15 (0.25 s a frame);
 * {@link #getMaxMeasurableTimeScale()} gives that ceiling for the frames just measured.
 *
 * <p>A {@link #reset()} from inside the stepper (a scene that restarts itself during a step)
 * wins over the step that asked for it: that step is not counted and the rest of the frame is
 * forgotten, so {@code t} reads 0 with the scene at its start and the leftover stays in range.
 *
 * <p>A {@link #setPaused pause} from inside the stepper (a demo that stops at a contact) ends
 * the frame right after that step, which is counted: {@code t} reads the end of the step that
 * paused, not of the frame. The frame's remaining whole steps are dropped (resuming does not
 * catch up on them in one burst); the leftover below h is carried as usual.
 */
public final class SimulationClock {

    /** How frame times become steps. */
    public enum Mode {
        /** One step of the (scaled) frame time per frame: the lecture's loop. */
        RAW_TPF,
        /** Fixed steps of h from an accumulator, with the leftover carried. */
        FIXED_STEP
    }

    /** Receives the steps the clock decides on. */
    @FunctionalInterface
    public interface Stepper {
        /**
         * Advance the simulation by one step.
         *
         * @param stepSeconds h (in seconds, &gt;0)
         */
        void step(float stepSeconds);
    }

    /** The default fixed step (in seconds): 60 steps per second. */
    public static final float DEFAULT_STEP_SECONDS = 1f / 60f;
    /** The default longest frame accepted in fixed-step mode (in seconds). */
    public static final float DEFAULT_MAX_FRAME_SECONDS = 0.25f;
    /** The default cap on steps per frame: a clamped 0.25 s frame at 60 Hz fits. */
    public static final int DEFAULT_MAX_STEPS_PER_FRAME = 16;
    /** Smallest time scale accepted. */
    public static final float MIN_TIME_SCALE = 1f / 64f;
    /** Largest time scale accepted. */
    public static final float MAX_TIME_SCALE = 64f;
    /**
     * The shortest stretch of frame time over which the clock measures its effective time
     * scale (in seconds): long enough to hold many frames and steps, short enough that the HUD
     * follows a key press within a second.
     */
    public static final float RATE_WINDOW_SECONDS = 0.5f;
    /**
     * In fixed-step mode a measuring window also holds at least this many steps: steps are
     * whole, so a window may hold one more or less than its frame time, and at x1/64 one
     * step of 1/60 s takes 1.07 s of frame time, longer than {@link #RATE_WINDOW_SECONDS}
     * (the rate read x0.03 or x0.00). With 8 steps the reading is within 1/8 of the rate,
     * and the slowest scale is read every 8.5 s.
     */
    public static final int RATE_WINDOW_STEPS = 8;
    /**
     * A fixed step is due once the leftover reaches h less this fraction of h. Float frame
     * times and steps add up to whole steps only to round-off (three frames of 1/90 s fall
     * 9e-10 s short of two steps of 1/60 s; 0.25 s falls 1.3e-8 s short of 15 such steps), and
     * without this window such a step would slip to the next frame. Round-off is about 6e-8 of
     * each number summed, so 1e-4 covers frames up to several hundred steps long, and moves a
     * step earlier by at most 1.7 µs at 60 Hz. The time accounting stays exact: the leftover
     * may go below zero by up to this fraction of h.
     */
    private static final double STEP_DUE_FRACTION = 1e-4;

    private Mode mode = Mode.FIXED_STEP;
    private float stepSeconds = DEFAULT_STEP_SECONDS;
    private float maxFrameSeconds = DEFAULT_MAX_FRAME_SECONDS;
    private int maxStepsPerFrame = DEFAULT_MAX_STEPS_PER_FRAME;
    private float timeScale = 1f;
    private boolean paused;
    private boolean singleStepRequested;
    /** Fixed-step leftover carried between frames (in seconds, &ge;−h·1e-4, &lt;h). */
    private double accumulatorSeconds;
    private double simulatedSeconds;
    private double droppedSeconds;
    private float lastStepSeconds;
    /** True while the stepper runs, so that a reset from inside it is noticed. */
    private boolean stepping;
    /** Set by a reset while the stepper runs: the step under way is not counted. */
    private boolean resetWhileStepping;
    /** The window being measured: frame time, frames, simulated and dropped time (s). */
    private double windowFrameSeconds;
    private int windowFrames;
    private double windowSimulatedSeconds;
    private double windowDroppedSeconds;
    /** The last complete window's results; NaN before the first. */
    private float measuredTimeScale = Float.NaN;
    private float measuredFrameSeconds = Float.NaN;
    private boolean measuredDropping;

    /**
     * Turn one frame into steps and take them.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0; 0 takes no step)
     * @param stepper what to step (not null)
     * @return the number of steps taken this frame (&ge;0)
     */
    public int advance(float tpf, Stepper stepper) {
        if (!(tpf >= 0f) || tpf == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "frame time tpf (s) must be finite and >= 0, but was " + tpf);
        }
        Validate.notNull(stepper, "stepper");
        int steps = takeSteps(tpf, stepper);
        measure(tpf);
        return steps;
    }

    /**
     * Return the stepping mode.
     *
     * @return the mode (not null)
     */
    public Mode getMode() {
        return mode;
    }

    /**
     * Choose the stepping mode. Switching ends the fixed-step leftover: raw mode has none, and
     * a fresh fixed-step run starts from zero. The leftover (frame time accepted but not yet
     * simulated, less than h) is counted as dropped, so that {@code fed = simulated + dropped
     * + leftover} holds across switches too; a leftover below zero (a step taken up to h·1e-4
     * early on round-off) is simply forgotten, so dropped time never goes below zero.
     *
     * @param newMode the mode (not null)
     */
    public void setMode(Mode newMode) {
        if (newMode == null) {
            throw new IllegalArgumentException("mode must be RAW_TPF or FIXED_STEP, but was null");
        }
        if (newMode != mode) {
            restartMeasurement();
        }
        mode = newMode;
        if (accumulatorSeconds > 0.0) {
            droppedSeconds += accumulatorSeconds;
        }
        accumulatorSeconds = 0.0;
    }

    /**
     * Switch between raw tpf and fixed steps.
     */
    public void toggleMode() {
        setMode(mode == Mode.RAW_TPF ? Mode.FIXED_STEP : Mode.RAW_TPF);
    }

    /**
     * Return the fixed step h, also used by single steps.
     *
     * @return h (in seconds, &gt;0)
     */
    public float getStepSeconds() {
        return stepSeconds;
    }

    /**
     * Alter the fixed step h.
     *
     * @param newStepSeconds h (in seconds, finite, &gt;0)
     */
    public void setStepSeconds(float newStepSeconds) {
        stepSeconds = Validate.positive(newStepSeconds, "fixed step h (s)");
        restartMeasurement();
    }

    /**
     * Return the longest frame accepted in fixed-step mode.
     *
     * @return the limit (in seconds, &gt;0)
     */
    public float getMaxFrameSeconds() {
        return maxFrameSeconds;
    }

    /**
     * Alter the longest frame accepted in fixed-step mode; longer frames are clamped.
     *
     * @param seconds the limit (in seconds, finite, &gt;0)
     */
    public void setMaxFrameSeconds(float seconds) {
        maxFrameSeconds = Validate.positive(seconds, "max frame time (s)");
        restartMeasurement();
    }

    /**
     * Return the cap on fixed steps per frame.
     *
     * @return the cap (&ge;1)
     */
    public int getMaxStepsPerFrame() {
        return maxStepsPerFrame;
    }

    /**
     * Alter the cap on fixed steps per frame.
     *
     * @param steps the cap (&ge;1)
     */
    public void setMaxStepsPerFrame(int steps) {
        if (steps < 1) {
            throw new IllegalArgumentException(
                    "max steps per frame must be >= 1, but was " + steps);
        }
        maxStepsPerFrame = steps;
        restartMeasurement();
    }

    /**
     * Return the time scale (1 = real time).
     *
     * @return the factor applied to every frame time
     */
    public float getTimeScale() {
        return timeScale;
    }

    /**
     * Alter the time scale.
     *
     * @param scale the factor (finite, from {@link #MIN_TIME_SCALE} to
     *     {@link #MAX_TIME_SCALE})
     */
    public void setTimeScale(float scale) {
        if (!(scale >= MIN_TIME_SCALE && scale <= MAX_TIME_SCALE)) {
            throw new IllegalArgumentException("time scale must be from " + MIN_TIME_SCALE
                    + " to " + MAX_TIME_SCALE + ", but was " + scale);
        }
        if (scale != timeScale) {
            restartMeasurement();
        }
        timeScale = scale;
    }

    /**
     * Test whether the simulation is paused.
     *
     * @return true if paused
     */
    public boolean isPaused() {
        return paused;
    }

    /**
     * Pause or resume the simulation. Called from inside the stepper, a pause ends the frame
     * after the step under way (see the class comment).
     *
     * @param newPaused true to pause
     */
    public void setPaused(boolean newPaused) {
        if (newPaused != paused) {
            restartMeasurement();
        }
        paused = newPaused;
        singleStepRequested = false;
    }

    /**
     * Ask for exactly one step of h on the next frame; ignored unless paused.
     */
    public void requestSingleStep() {
        if (paused) {
            singleStepRequested = true;
        }
    }

    /**
     * Return the simulated time since the last reset.
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getSimulatedSeconds() {
        return simulatedSeconds;
    }

    /**
     * Return the frame time dropped since the last reset: by the clamp and the step cap, the
     * leftover ended by a mode switch, and the whole steps left in a frame that a pause from
     * inside a step cut short. In fixed-step mode, the scaled frame time fed while
     * running equals {@code simulated + dropped + leftover} (up to double round-off, and up to
     * h·1e-4 per mode switch), as long as no single step was taken.
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getDroppedSeconds() {
        return droppedSeconds;
    }

    /**
     * Return the fixed-step leftover: frame time accepted but not yet simulated, carried to the
     * next frame.
     *
     * @return the time (in seconds, less than h; it may be below zero by round-off, at most
     *     h·1e-4, when a step was taken on frame times that summed to h only up to round-off)
     */
    public double getLeftoverSeconds() {
        return accumulatorSeconds;
    }

    /**
     * Return the duration of the most recent step taken.
     *
     * @return h of the last step (in seconds, &ge;0; 0 before the first)
     */
    public float getLastStepSeconds() {
        return lastStepSeconds;
    }

    /**
     * Return the step size the current mode uses, for a HUD or a stability check: the fixed h,
     * or in raw mode the last step taken (h before the first).
     *
     * @return the step (in seconds, &gt;0)
     */
    public float getCurrentStepSeconds() {
        if (mode == Mode.RAW_TPF && lastStepSeconds > 0f) {
            return lastStepSeconds;
        }
        return stepSeconds;
    }

    /**
     * Return the effective time scale: simulated seconds per second of frame time, measured
     * over the last complete window of at least {@link #RATE_WINDOW_SECONDS} of frame time.
     * It is below the asked-for {@link #getTimeScale()} when the clamp or the step cap drop
     * time, 0 while paused, and it wobbles by up to one step per window in fixed-step mode
     * (steps are whole). Changing the scale, pause, mode, h or a limit starts the
     * measurement again, so a rate measured under other settings is never shown.
     *
     * @return the scale (&ge;0), or NaN until a window under the current settings is complete
     */
    public float getMeasuredTimeScale() {
        return measuredTimeScale;
    }

    /**
     * Return the mean frame time of the last complete measuring window.
     *
     * @return the time (in seconds, &gt;0), or NaN until the first window is complete
     */
    public float getMeasuredFrameSeconds() {
        return measuredFrameSeconds;
    }

    /**
     * Test whether the clamp or the step cap dropped simulated time in the last complete
     * measuring window or in the one under way: the simulation then runs slower than asked.
     *
     * @return true if time is being dropped
     */
    public boolean isDroppingTime() {
        return measuredDropping || windowDroppedSeconds > 0.0;
    }

    /**
     * Return the most simulated time one frame can give: in fixed-step mode the smaller of the
     * frame clamp and the step cap times h; raw tpf has no limit.
     *
     * @return the time (in seconds, &gt;0; infinite in raw mode)
     */
    public float getMaxSimulatedSecondsPerFrame() {
        if (mode == Mode.RAW_TPF) {
            return Float.POSITIVE_INFINITY;
        }
        return Math.min(maxFrameSeconds, maxStepsPerFrame * stepSeconds);
    }

    /**
     * Return the highest effective time scale the frames just measured allow: the most a frame
     * can simulate over the mean frame time (x15 for the defaults at 60 frames per second,
     * about x6 at 23).
     *
     * @return the scale (&gt;0; infinite in raw mode), or NaN until a window is complete
     */
    public float getMaxMeasurableTimeScale() {
        return getMaxSimulatedSecondsPerFrame() / measuredFrameSeconds;
    }

    /**
     * Forget the time counters and the leftover; keep mode, step, scale, pause and the
     * measured time scale. Called from inside the stepper, it also ends the frame: the step
     * under way is not counted and the frame's remaining time is forgotten.
     */
    public void reset() {
        accumulatorSeconds = 0.0;
        simulatedSeconds = 0.0;
        droppedSeconds = 0.0;
        lastStepSeconds = 0f;
        singleStepRequested = false;
        if (stepping) {
            resetWhileStepping = true;
        }
    }

    /**
     * Put the simulated time back to a recorded step's (a step back or a replay), keeping
     * everything else: the leftover, the dropped time, the mode, the scale and the pause.
     *
     * @param seconds the time of the step shown (in seconds, finite, &ge;0)
     */
    public void restoreSimulatedSeconds(double seconds) {
        if (!(seconds >= 0.0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("simulated time (s) must be finite and >= 0,"
                    + " but was " + seconds);
        }
        simulatedSeconds = seconds;
    }

    private int takeSteps(float tpf, Stepper stepper) {
        if (paused) {
            if (singleStepRequested) {
                singleStepRequested = false;
                take(stepper, stepSeconds);
                return 1;
            }
            return 0;
        }
        float scaled = tpf * timeScale;
        if (scaled == 0f) {
            return 0;
        }
        if (mode == Mode.RAW_TPF) {
            take(stepper, scaled);
            return 1;
        }
        return advanceFixed(scaled, stepper);
    }

    /** Forget the window under way and the last result: the settings changed. */
    private void restartMeasurement() {
        windowFrameSeconds = 0.0;
        windowFrames = 0;
        windowSimulatedSeconds = 0.0;
        windowDroppedSeconds = 0.0;
        measuredTimeScale = Float.NaN;
        measuredDropping = false;
    }

    /** Add one frame to the measuring window and close the window once it is long enough. */
    private void measure(float tpf) {
        windowFrameSeconds += tpf;
        ++windowFrames;
        // In steps of h, half a step short for float round-off; paused, the rate is 0.
        boolean enoughSteps = mode != Mode.FIXED_STEP || paused || windowSimulatedSeconds
                + windowDroppedSeconds >= (RATE_WINDOW_STEPS - 0.5) * stepSeconds;
        if (windowFrameSeconds >= RATE_WINDOW_SECONDS && enoughSteps) {
            measuredTimeScale = (float) (windowSimulatedSeconds / windowFrameSeconds);
            measuredFrameSeconds = (float) (windowFrameSeconds / windowFrames);
            measuredDropping = windowDroppedSeconds > 0.0;
            windowFrameSeconds = 0.0;
            windowFrames = 0;
            windowSimulatedSeconds = 0.0;
            windowDroppedSeconds = 0.0;
        }
    }

    private int advanceFixed(float scaledSeconds, Stepper stepper) {
        float accepted = scaledSeconds;
        if (accepted > maxFrameSeconds) {
            // In double: exact for any frame under 2^29 times the limit.
            drop((double) accepted - maxFrameSeconds);
            accepted = maxFrameSeconds;
        }
        accumulatorSeconds += accepted;
        double dueSeconds = stepSeconds * (1.0 - STEP_DUE_FRACTION);
        int steps = 0;
        while (accumulatorSeconds >= dueSeconds && steps < maxStepsPerFrame) {
            ++steps;
            if (!take(stepper, stepSeconds)) {
                // The stepper reset the clock: the frame ends with the reset's zeros.
                return steps;
            }
            accumulatorSeconds -= stepSeconds;
            if (paused) {
                // The stepper paused the clock: the frame ends with this step.
                dropWholeSteps(false);
                return steps;
            }
        }
        dropWholeSteps(true);
        return steps;
    }

    /**
     * Drop the whole steps left in the leftover, keeping the part below h: what the step cap
     * or a pause from inside a step left untaken.
     *
     * @param measured true to count them in the measuring window too (the cap: the HUD says
     *     time is being dropped), false for a pause (which started a new window)
     */
    private void dropWholeSteps(boolean measured) {
        double dueSeconds = stepSeconds * (1.0 - STEP_DUE_FRACTION);
        if (accumulatorSeconds >= dueSeconds) {
            // Drop the whole steps not taken, keep the leftover below h.
            double wholeSteps = Math.floor(accumulatorSeconds / stepSeconds + STEP_DUE_FRACTION);
            double excess = wholeSteps * stepSeconds;
            if (measured) {
                drop(excess);
            } else {
                droppedSeconds += excess;
            }
            accumulatorSeconds -= excess;
        }
    }

    private void drop(double seconds) {
        droppedSeconds += seconds;
        windowDroppedSeconds += seconds;
    }

    /**
     * Take one step and count it, unless the stepper reset the clock meanwhile.
     *
     * @return true if the step was counted, false if a reset from inside the stepper won
     */
    private boolean take(Stepper stepper, float seconds) {
        stepping = true;
        resetWhileStepping = false;
        try {
            stepper.step(seconds);
        } finally {
            stepping = false;
        }
        windowSimulatedSeconds += seconds;
        if (resetWhileStepping) {
            resetWhileStepping = false;
            return false;
        }
        simulatedSeconds += seconds;
        lastStepSeconds = seconds;
        return true;
    }
}

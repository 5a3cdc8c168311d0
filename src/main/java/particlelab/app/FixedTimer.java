package particlelab.app;

import com.jme3.system.Timer;

/**
 * A jME timer that reports the frame time it is given, whatever the wall clock says: the same
 * every frame, so a run of N frames simulates exactly N·tpf seconds and its screenshot is
 * reproducible, or a recording's own frame times, set before each frame of its replay.
 */
public final class FixedTimer extends Timer {

    /** Time is counted in nanoseconds. */
    private static final long RESOLUTION = 1_000_000_000L;

    private float frameSeconds;
    private long ticks;

    /**
     * Create a timer.
     *
     * @param frameSeconds the time per frame it reports (in seconds, finite, &ge;0)
     */
    public FixedTimer(float frameSeconds) {
        setFrameSeconds(frameSeconds);
    }

    /**
     * Change the time the next frames report.
     *
     * @param newFrameSeconds the time per frame (in seconds, finite, &ge;0)
     */
    public void setFrameSeconds(float newFrameSeconds) {
        if (!(newFrameSeconds >= 0f) || Float.isInfinite(newFrameSeconds)) {
            throw new IllegalArgumentException(
                    "fixed frame time (s) must be finite and >= 0, but was " + newFrameSeconds);
        }
        frameSeconds = newFrameSeconds;
    }

    @Override
    public long getTime() {
        return ticks;
    }

    @Override
    public long getResolution() {
        return RESOLUTION;
    }

    @Override
    public float getFrameRate() {
        return frameSeconds > 0f ? 1f / frameSeconds : 0f;
    }

    @Override
    public float getTimePerFrame() {
        return frameSeconds;
    }

    @Override
    public void update() {
        ticks += (long) (frameSeconds * RESOLUTION);
    }

    @Override
    public void reset() {
        ticks = 0L;
    }
}

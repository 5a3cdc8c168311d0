package particlelab.demo;

import java.util.Locale;

/**
 * Wall-clock durations of one kind of work, one per frame (e.g. the simulation's steps):
 * the mean and the largest over the whole run, and the mean and the largest over the last
 * {@link #RECENT_FRAMES} frames for a HUD. Recording allocates nothing.
 */
public final class FrameTimes {

    /** How many of the latest frames the recent figures cover. */
    public static final int RECENT_FRAMES = 60;
    private static final double NANOS_PER_MILLI = 1e6;

    private final long[] recent = new long[RECENT_FRAMES];
    private int recentCount;
    private int next;
    private long frames;
    private long totalNanos;
    private long maxNanos;

    /**
     * Record one frame's duration.
     *
     * @param nanos the duration (in nanoseconds; a negative one counts as 0)
     */
    public void record(long nanos) {
        long duration = Math.max(0L, nanos);
        ++frames;
        totalNanos += duration;
        maxNanos = Math.max(maxNanos, duration);
        recent[next] = duration;
        next = (next + 1) % RECENT_FRAMES;
        recentCount = Math.min(recentCount + 1, RECENT_FRAMES);
    }

    /** Forget every frame recorded. */
    public void clear() {
        frames = 0L;
        totalNanos = 0L;
        maxNanos = 0L;
        recentCount = 0;
        next = 0;
    }

    /**
     * Count the frames recorded.
     *
     * @return the count (&ge;0)
     */
    public long countFrames() {
        return frames;
    }

    /**
     * Return the mean over every frame recorded.
     *
     * @return the mean (in milliseconds; 0 if none)
     */
    public double meanMillis() {
        return frames == 0L ? 0.0 : totalNanos / NANOS_PER_MILLI / frames;
    }

    /**
     * Return the largest of every frame recorded.
     *
     * @return the largest (in milliseconds; 0 if none)
     */
    public double maxMillis() {
        return maxNanos / NANOS_PER_MILLI;
    }

    /**
     * Return the mean over the last {@link #RECENT_FRAMES} frames (fewer at the start).
     *
     * @return the mean (in milliseconds; 0 if none)
     */
    public double recentMeanMillis() {
        if (recentCount == 0) {
            return 0.0;
        }
        long sum = 0L;
        for (int i = 0; i < recentCount; ++i) {
            sum += recent[i];
        }
        return sum / NANOS_PER_MILLI / recentCount;
    }

    /**
     * Return the largest of the last {@link #RECENT_FRAMES} frames.
     *
     * @return the largest (in milliseconds; 0 if none)
     */
    public double recentMaxMillis() {
        long most = 0L;
        for (int i = 0; i < recentCount; ++i) {
            most = Math.max(most, recent[i]);
        }
        return most / NANOS_PER_MILLI;
    }

    /**
     * Write the line {@code demo --profile} prints at exit:
     * {@code physics_ms_mean=X physics_ms_max=Y particles=P frames=N}, milliseconds with three
     * decimals. Allocates (once, at exit).
     *
     * @param particles the particles each step moves (&ge;0)
     * @return the line, without a line end (not null)
     */
    public String formatProfile(int particles) {
        return String.format(Locale.ROOT, "physics_ms_mean=%.3f physics_ms_max=%.3f"
                + " particles=%d frames=%d", meanMillis(), maxMillis(), particles, frames);
    }
}

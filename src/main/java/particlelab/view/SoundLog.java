package particlelab.view;

import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * The sounds a {@link SoundPlayer} was asked to play, played or not: a bounded ring, oldest
 * first, readable by tests and by the HUD ({@code sound: impact vol 0.62 (no audio device)}).
 * Each one is also logged at {@code FINE} level, which java.util.logging hides unless asked.
 * Preallocated: recording allocates nothing; when full, the oldest entry is dropped.
 */
public final class SoundLog {

    /** Where every sound is logged, at FINE level. */
    public static final Logger LOGGER = Logger.getLogger(SoundLog.class.getName());
    /** The default number of entries kept. */
    public static final int DEFAULT_CAPACITY = 16;
    /** Decimals of the volume on the HUD. */
    private static final int VOLUME_DECIMALS = 2;

    private final SoundCue[] cues;
    private final float[] volumes;
    private final String silentReason;
    private int first;
    private int size;
    private long total;

    /**
     * Create an empty log.
     *
     * @param capacity the most entries kept (&ge;1)
     * @param silentReason why nothing is heard, shown after each entry (e.g. "no audio
     *     device"), or null when the sounds are played
     */
    public SoundLog(int capacity, String silentReason) {
        if (capacity < 1) {
            throw new IllegalArgumentException(
                    "sound log capacity must be >= 1, but was " + capacity);
        }
        cues = new SoundCue[capacity];
        volumes = new float[capacity];
        this.silentReason = silentReason;
    }

    /**
     * Check a volume before it is played or recorded.
     *
     * @param cue the sound (must not be null)
     * @param volume01 the volume (must be finite, from 0 to 1)
     */
    static void check(SoundCue cue, float volume01) {
        if (cue == null) {
            throw new IllegalArgumentException("sound cue must not be null");
        }
        if (!(volume01 >= 0f && volume01 <= 1f)) {
            throw new IllegalArgumentException(
                    "sound volume must be from 0 to 1, but was " + volume01);
        }
    }

    /**
     * Return why nothing is heard.
     *
     * @return the reason, or null when the sounds are played
     */
    public String getSilentReason() {
        return silentReason;
    }

    /** @return the count of entries kept (0 to the capacity) */
    public int size() {
        return size;
    }

    /** @return the count of sounds ever recorded, including those dropped from the ring */
    public long getTotal() {
        return total;
    }

    /**
     * Return an entry's sound, oldest first.
     *
     * @param index which one (&ge;0, &lt;{@link #size()})
     * @return the cue (not null)
     */
    public SoundCue getCue(int index) {
        return cues[slot(index)];
    }

    /**
     * Return an entry's volume, oldest first.
     *
     * @param index which one (&ge;0, &lt;{@link #size()})
     * @return the volume (0 to 1)
     */
    public float getVolume(int index) {
        return volumes[slot(index)];
    }

    /**
     * Append the latest sound as one HUD line without its newline, e.g.
     * {@code sound: impact vol 0.62 (no audio device)}. Allocates nothing (the text has room).
     *
     * @param text where to append (not null)
     * @return {@code text}
     */
    public StringBuilder appendLatest(StringBuilder text) {
        text.append("sound: ");
        if (size == 0) {
            text.append("none yet");
        } else {
            int last = size - 1;
            text.append(getCue(last).getLabel()).append(" vol ");
            TextFormat.appendFixed(text, getVolume(last), VOLUME_DECIMALS);
        }
        if (silentReason != null) {
            text.append(" (").append(silentReason).append(')');
        }
        return text;
    }

    /** Forget every entry (the total too). */
    public void clear() {
        first = 0;
        size = 0;
        total = 0L;
    }

    /** Record a sound (already checked) and log it at FINE level. */
    void record(SoundCue cue, float volume01) {
        int index;
        if (size < cues.length) {
            index = (first + size) % cues.length;
            ++size;
        } else {
            index = first;
            first = (first + 1) % cues.length;
        }
        cues[index] = cue;
        volumes[index] = volume01;
        ++total;
        if (LOGGER.isLoggable(Level.FINE)) {
            LOGGER.fine(appendLatest(new StringBuilder()).toString());
        }
    }

    private int slot(int index) {
        if (index < 0 || index >= size) {
            throw new IndexOutOfBoundsException(
                    "sound log index must be from 0 to " + (size - 1) + ", but was " + index);
        }
        return (first + index) % cues.length;
    }
}

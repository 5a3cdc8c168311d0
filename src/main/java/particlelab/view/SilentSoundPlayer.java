package particlelab.view;

import java.util.logging.Logger;

/**
 * A {@link SoundPlayer} for a machine without an audio device: it plays nothing and never
 * touches OpenAL, but records every sound in its {@link SoundLog} (shown on the HUD and
 * logged at {@code FINE} level), so the events stay visible and nothing fails.
 */
public final class SilentSoundPlayer implements SoundPlayer {

    private static final Logger LOGGER = Logger.getLogger(SilentSoundPlayer.class.getName());

    private final SoundLog log;

    /**
     * Create a silent player with a log of {@link SoundLog#DEFAULT_CAPACITY} entries.
     *
     * @param reason why nothing is heard, shown on the HUD (not null, e.g. "no audio device")
     */
    public SilentSoundPlayer(String reason) {
        this(reason, SoundLog.DEFAULT_CAPACITY);
    }

    /**
     * Create a silent player.
     *
     * @param reason why nothing is heard, shown on the HUD (not null)
     * @param logCapacity the most sounds the log keeps (&ge;1)
     */
    public SilentSoundPlayer(String reason, int logCapacity) {
        if (reason == null || reason.isEmpty()) {
            throw new IllegalArgumentException("a silent player needs a reason, but was "
                    + (reason == null ? "null" : "empty"));
        }
        log = new SoundLog(logCapacity, reason);
        LOGGER.config(() -> "sounds are recorded and shown, not played (" + reason + ")");
    }

    @Override
    public void play(SoundCue cue, float volume01) {
        SoundLog.check(cue, volume01);
        log.record(cue, volume01);
    }

    @Override
    public boolean isAudible() {
        return false;
    }

    @Override
    public SoundLog getLog() {
        return log;
    }
}

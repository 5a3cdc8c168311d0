package particlelab.view;

import com.jme3.app.Application;

/**
 * Plays the app's short sounds ({@link SoundCue}), or, on a machine without an audio device,
 * only records them: both kinds keep a {@link SoundLog} that the HUD can show, so a silent
 * machine shows the same events a loud one plays. Call {@link #play} on the jME thread;
 * it allocates nothing.
 */
public interface SoundPlayer {

    /** What the HUD says when there is no audio renderer. */
    String NO_AUDIO_DEVICE = "no audio device";

    /**
     * Choose the player for an application: jME's {@code AudioNode}s when it has an audio
     * renderer (the launcher gives it one only when an audio device was found), else a
     * silent player that records. Call on the jME thread, once the application is
     * initialised (e.g. in an AppState's {@code initialize}).
     *
     * @param app the application (not null)
     * @return a new player (not null)
     */
    static SoundPlayer forApplication(Application app) {
        if (app.getAudioRenderer() == null) {
            return new SilentSoundPlayer(NO_AUDIO_DEVICE);
        }
        return new AudioNodeSoundPlayer(app.getAssetManager());
    }

    /**
     * Play a sound once (several may overlap), and record it in the log.
     *
     * @param cue which sound (not null)
     * @param volume01 its volume (finite, 0 to 1; 1 is the file as recorded)
     */
    void play(SoundCue cue, float volume01);

    /**
     * Test whether sounds are heard.
     *
     * @return true if they go to an audio device, false if they are only recorded
     */
    boolean isAudible();

    /**
     * Access the record of the sounds asked for.
     *
     * @return the live log (not null)
     */
    SoundLog getLog();
}

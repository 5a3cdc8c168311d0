package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.audio.AudioData;
import com.jme3.audio.AudioNode;

/**
 * A {@link SoundPlayer} that plays through jME's audio: one buffered, non-positional
 * {@link AudioNode} per cue, created once, and {@link AudioNode#playInstance()} per sound, so
 * several impacts may overlap. Use it only in an application with an audio renderer
 * ({@link SoundPlayer#forApplication} chooses); without one, jME's {@code playInstance}
 * throws. Every sound is recorded in the {@link SoundLog} too.
 */
public final class AudioNodeSoundPlayer implements SoundPlayer {

    private final AudioNode[] nodes = new AudioNode[SoundCue.values().length];
    private final SoundLog log;

    /**
     * Load every cue's sound from {@code assets/Sounds} (on the classpath) into an audio node.
     * Loading needs no audio device; playing does.
     *
     * @param assets the application's asset manager (not null)
     */
    public AudioNodeSoundPlayer(AssetManager assets) {
        SoundCue[] cues = SoundCue.values();
        for (int i = 0; i < cues.length; ++i) {
            AudioNode node = new AudioNode(assets, cues[i].getAssetPath(),
                    AudioData.DataType.Buffer);
            node.setName("sound " + cues[i].getLabel());
            node.setPositional(false);
            node.setLooping(false);
            node.setReverbEnabled(false);
            nodes[i] = node;
        }
        log = new SoundLog(SoundLog.DEFAULT_CAPACITY, null);
    }

    /**
     * Access the audio node of a cue (for tests and for a demo that wants to attach it).
     *
     * @param cue which sound (not null)
     * @return the live node (not null)
     */
    public AudioNode getNode(SoundCue cue) {
        return nodes[cue.ordinal()];
    }

    /**
     * Play a sound once (an instance of its node: overlapping sounds are fine); call on the
     * jME thread.
     *
     * @param cue which sound (not null)
     * @param volume01 its volume (finite, 0 to 1)
     */
    @Override
    public void play(SoundCue cue, float volume01) {
        SoundLog.check(cue, volume01);
        log.record(cue, volume01);
        AudioNode node = nodes[cue.ordinal()];
        // playInstance copies the node's volume into the new instance when it starts.
        node.setVolume(volume01);
        node.playInstance();
    }

    @Override
    public boolean isAudible() {
        return true;
    }

    @Override
    public SoundLog getLog() {
        return log;
    }
}

package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.app.LegacyApplication;
import com.jme3.asset.DesktopAssetManager;
import com.jme3.audio.AudioContext;
import com.jme3.audio.AudioData;
import com.jme3.audio.AudioRenderer;
import com.jme3.audio.AudioSource;
import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.LogRecords;

class SoundPlayerTest {

    @Test
    void silentPlayerNeverThrowsAndRecordsEverySoundInABoundedLog() {
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE, 8);
        assertFalse(player.isAudible());
        int plays = 1000;
        for (int i = 0; i < plays; ++i) {
            player.play(i % 3 == 0 ? SoundCue.DESTROY : SoundCue.IMPACT, (i % 101) / 100f);
        }
        SoundLog log = player.getLog();
        assertEquals(8, log.size(), "the log keeps only its capacity");
        assertEquals(plays, log.getTotal());
        // Oldest first: entries 992..999.
        for (int k = 0; k < log.size(); ++k) {
            int i = plays - log.size() + k;
            assertSame(i % 3 == 0 ? SoundCue.DESTROY : SoundCue.IMPACT, log.getCue(k));
            assertEquals((i % 101) / 100f, log.getVolume(k), 0f);
        }
        assertThrows(IndexOutOfBoundsException.class, () -> log.getCue(8));
    }

    @Test
    void hudLineNamesTheLatestSoundItsVolumeAndWhyItIsSilent() {
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE);
        StringBuilder text = new StringBuilder();
        assertEquals("sound: none yet (no audio device)",
                player.getLog().appendLatest(text).toString());
        player.play(SoundCue.DESTROY, 1f);
        player.play(SoundCue.IMPACT, 0.62f);
        text.setLength(0);
        assertEquals("sound: impact vol 0.62 (no audio device)",
                player.getLog().appendLatest(text).toString());
    }

    @Test
    void badVolumesAndCuesAreRefusedNamingThem() {
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE);
        for (float bad : new float[] {Float.NaN, -0.01f, 1.01f, Float.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> player.play(SoundCue.IMPACT, bad));
            assertTrue(e.getMessage().contains("volume must be from 0 to 1, but was " + bad),
                    e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> player.play(null, 0.5f));
        assertEquals(0, player.getLog().getTotal(), "a refused sound is not recorded");
        assertThrows(IllegalArgumentException.class, () -> new SilentSoundPlayer(null));
        assertThrows(IllegalArgumentException.class, () -> new SoundLog(0, null));
    }

    @Test
    void playingSilentlyAllocatesNothing() {
        SilentSoundPlayer player = new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE);
        StringBuilder text = new StringBuilder(64);
        Allocations.assertAllocatesNothing("10_000 silent sounds and HUD lines", () -> {
            for (int i = 0; i < 10_000; ++i) {
                player.play(SoundCue.IMPACT, 0.5f);
                text.setLength(0);
                player.getLog().appendLatest(text);
            }
        });
    }

    @Test
    void everySoundIsLoggedAtFineLevel() {
        List<LogRecord> records = LogRecords.during(SoundLog.LOGGER, Level.FINE,
                () -> new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE)
                        .play(SoundCue.DESTROY, 1f));
        assertEquals(1, records.size());
        assertEquals(Level.FINE, records.get(0).getLevel());
        assertEquals("sound: destroy vol 1.00 (no audio device)", records.get(0).getMessage());
    }

    @Test
    void anApplicationWithAnAudioRendererGetsJmesPlayerAndOneWithoutGetsTheSilentOne() {
        AudioRenderer fakeAudio = (AudioRenderer) Proxy.newProxyInstance(
                AudioRenderer.class.getClassLoader(), new Class<?>[] {AudioRenderer.class},
                (proxy, method, args) -> method.getReturnType() == float.class ? 0f : null);
        LegacyApplication loud = new LegacyApplication() {
            {
                audioRenderer = fakeAudio;
                assetManager = new DesktopAssetManager(true);
            }
        };
        assertInstanceOf(AudioNodeSoundPlayer.class, SoundPlayer.forApplication(loud));
        LegacyApplication silent = new LegacyApplication();
        SoundPlayer player = SoundPlayer.forApplication(silent);
        assertInstanceOf(SilentSoundPlayer.class, player);
        assertEquals(SoundPlayer.NO_AUDIO_DEVICE, player.getLog().getSilentReason());
    }

    @Test
    void audioNodePlayerPlaysOneInstanceOfTheCueAtTheVolume() {
        // A stand-in for OpenAL: jME's audio nodes find the renderer of the current thread.
        List<AudioSource> played = new ArrayList<>();
        List<Float> volumes = new ArrayList<>();
        AudioRenderer recorder = (AudioRenderer) Proxy.newProxyInstance(
                AudioRenderer.class.getClassLoader(), new Class<?>[] {AudioRenderer.class},
                (proxy, method, args) -> {
                    if (method.getName().equals("playSourceInstance")) {
                        AudioSource source = (AudioSource) args[0];
                        played.add(source);
                        volumes.add(source.getVolume());
                    }
                    return method.getReturnType() == float.class ? 0f : null;
                });
        AudioContext.setAudioRenderer(recorder);
        try {
            AudioNodeSoundPlayer player = new AudioNodeSoundPlayer(new DesktopAssetManager(true));
            assertTrue(player.isAudible());
            player.play(SoundCue.IMPACT, 0.25f);
            player.play(SoundCue.DESTROY, 1f);
            assertEquals(List.of(player.getNode(SoundCue.IMPACT),
                    player.getNode(SoundCue.DESTROY)), played);
            assertEquals(List.of(0.25f, 1f), volumes);
            assertEquals(2, player.getLog().getTotal());
            assertEquals("sound: destroy vol 1.00",
                    player.getLog().appendLatest(new StringBuilder()).toString());
            for (SoundCue cue : SoundCue.values()) {
                // jME's own WAV loader read the file: mono, 16 bits, the stated length.
                AudioData data = player.getNode(cue).getAudioData();
                assertEquals(AudioData.DataType.Buffer, data.getDataType());
                assertEquals(1, data.getChannels());
                assertEquals(16, data.getBitsPerSample());
                assertEquals(SoundGenerator.SAMPLE_RATE_HZ, data.getSampleRate());
                assertEquals(cue.getDurationSeconds(), data.getDuration(),
                        1.0 / SoundGenerator.SAMPLE_RATE_HZ);
                assertFalse(player.getNode(cue).isPositional());
            }
        } finally {
            AudioContext.setAudioRenderer(null);
        }
    }
}

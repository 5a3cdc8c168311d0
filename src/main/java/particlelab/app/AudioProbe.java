package particlelab.app;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.Locale;
import java.util.logging.Logger;
import org.lwjgl.openal.ALC10;

/**
 * Checks, before the window starts, whether OpenAL can open an audio device. jME's own audio
 * start throws on a machine without a sound card and takes the whole application down with
 * it; asking first lets the app run silent instead. No demo plays sound yet, so a silent start
 * is not worth a warning on every launch: it is noted at {@code CONFIG} level, which
 * java.util.logging does not print unless asked to.
 */
final class AudioProbe {

    /** Where a silent start is noted (at CONFIG level). */
    static final Logger LOGGER = Logger.getLogger(AudioProbe.class.getName());

    private AudioProbe() {
    }

    /**
     * Note that the window starts without sound, in a log line that is hidden by default.
     *
     * @param problem why there is no audio, as {@link #findProblem} said (not null)
     */
    static void noteSilentStart(String problem) {
        LOGGER.config(() -> "no audio (" + problem + "): the window runs without sound");
    }

    /**
     * Try to open (and close again) the default OpenAL device.
     *
     * @return null if audio works, otherwise a one-line reason
     */
    static String findProblem() {
        if (isLinuxWithoutSound()) {
            // Opening OpenAL here would only fill the terminal with ALSA's complaints.
            return "no sound card or sound server found";
        }
        try {
            // LWJGL loads OpenAL when the ALC class is first used; jME reuses it later.
            long device = ALC10.alcOpenDevice((ByteBuffer) null);
            if (device == 0L) {
                return "OpenAL found no audio device";
            }
            ALC10.alcCloseDevice(device);
            return null;
        } catch (RuntimeException | LinkageError failure) {
            return "OpenAL could not start (" + failure.getMessage() + ")";
        }
    }

    /**
     * On Linux, tell whether there is plainly no way to play sound: no ALSA devices and no
     * PulseAudio or PipeWire server to talk to.
     *
     * @return true if sound is certainly unavailable
     */
    private static boolean isLinuxWithoutSound() {
        if (!System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("linux")) {
            return false;
        }
        if (Files.isDirectory(Paths.get("/dev/snd")) || System.getenv("PULSE_SERVER") != null) {
            return false;
        }
        String runtimeDir = System.getenv("XDG_RUNTIME_DIR");
        return runtimeDir == null
                || !Files.exists(Paths.get(runtimeDir, "pulse", "native"))
                        && !Files.exists(Paths.get(runtimeDir, "pipewire-0"));
    }
}

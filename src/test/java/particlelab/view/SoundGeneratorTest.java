package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class SoundGeneratorTest {

    /** Rounding to 16 bits moves each sample by at most half a step (LSB). */
    private static final double ROUNDING_LSB = 0.5;

    @ParameterizedTest
    @EnumSource(SoundCue.class)
    void committedFileIsExactlyWhatTheGeneratorWrites(SoundCue cue) throws IOException {
        assertArrayEquals(SoundGenerator.wav(cue), committed(cue),
                cue.getAssetPath() + " differs from SoundGenerator's output: run gradle sounds");
    }

    @ParameterizedTest
    @EnumSource(SoundCue.class)
    void fileIsAMonoSixteenBitPcmWavOfTheStatedLength(SoundCue cue) throws Exception {
        byte[] file = committed(cue);
        int samples = (int) Math.round(cue.getDurationSeconds() * SoundGenerator.SAMPLE_RATE_HZ);
        ByteBuffer header = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals("RIFF", tag(file, 0));
        assertEquals(file.length - 8, header.getInt(4));
        assertEquals("WAVE", tag(file, 8));
        assertEquals("fmt ", tag(file, 12));
        assertEquals(16, header.getInt(16));
        assertEquals(1, header.getShort(20), "PCM");
        assertEquals(1, header.getShort(22), "mono");
        assertEquals(SoundGenerator.SAMPLE_RATE_HZ, header.getInt(24));
        assertEquals(2 * SoundGenerator.SAMPLE_RATE_HZ, header.getInt(28), "byte rate");
        assertEquals(2, header.getShort(32), "block align");
        assertEquals(16, header.getShort(34), "bits per sample");
        assertEquals("data", tag(file, 36));
        assertEquals(2 * samples, header.getInt(40));
        assertEquals(SoundGenerator.WAV_HEADER_BYTES + 2 * samples, file.length);

        // An independent reader (the JDK's own) agrees, and so does the stated length.
        try (AudioInputStream in =
                AudioSystem.getAudioInputStream(new ByteArrayInputStream(file))) {
            AudioFormat format = in.getFormat();
            assertEquals(AudioFormat.Encoding.PCM_SIGNED, format.getEncoding());
            assertEquals(1, format.getChannels());
            assertEquals(16, format.getSampleSizeInBits());
            assertEquals(SoundGenerator.SAMPLE_RATE_HZ, format.getSampleRate(), 0f);
            assertTrue(!format.isBigEndian());
            assertEquals(samples, in.getFrameLength());
            // The length is a whole number of samples: within one sample period.
            assertEquals(cue.getDurationSeconds(),
                    (double) in.getFrameLength() / format.getFrameRate(),
                    1.0 / SoundGenerator.SAMPLE_RATE_HZ);
        }
    }

    @ParameterizedTest
    @EnumSource(SoundCue.class)
    void peakIsBelowFullScaleWithNoDcOffsetAndSilentEnds(SoundCue cue) throws IOException {
        short[] samples = samplesOf(committed(cue));
        int peak = 0;
        long sum = 0L;
        for (short sample : samples) {
            peak = Math.max(peak, Math.abs(sample));
            sum += sample;
        }
        // Scaled to PEAK_FRACTION of full scale, then rounded (half a step at most).
        double wantedPeak = SoundGenerator.PEAK_FRACTION * SoundGenerator.FULL_SCALE;
        assertEquals(wantedPeak, peak, ROUNDING_LSB);
        assertTrue(peak < SoundGenerator.FULL_SCALE, "clipped: " + peak);
        // The mean is removed exactly before rounding; rounding moves each sample, and so
        // their mean, by at most half a step.
        double mean = (double) sum / samples.length;
        assertTrue(Math.abs(mean) <= ROUNDING_LSB, "DC offset " + mean + " LSB");
        // The window is 0 at both ends, so a sound starts and stops without a click.
        assertEquals(0, samples[0]);
        assertEquals(0, samples[samples.length - 1]);
    }

    @ParameterizedTest
    @EnumSource(SoundCue.class)
    void soundDiesAway(SoundCue cue) throws IOException {
        short[] samples = samplesOf(committed(cue));
        int tenth = samples.length / 10;
        double start = rms(samples, 0, tenth);
        double end = rms(samples, samples.length - tenth, samples.length);
        // Decays of 12 ms (impact) and 100 ms (destroy) over most of the length, then the
        // release ramp: the last tenth is far quieter than the first.
        assertTrue(end < start / 10, "first tenth rms " + start + ", last tenth " + end);
    }

    @ParameterizedTest
    @EnumSource(value = SoundCue.class, names = "DESTROY")
    void destroySoundFallsInPitch(SoundCue cue) throws IOException {
        short[] samples = samplesOf(committed(cue));
        int quarter = samples.length / 4;
        double early = crossingsPerSample(samples, 0, quarter);
        double late = crossingsPerSample(samples, samples.length - 2 * quarter,
                samples.length - quarter);
        // The cut-off falls 20-fold and the tone 7.5-fold: the sound crosses zero far less
        // often late than early (the zero-crossing rate follows the dominant frequency).
        assertTrue(late < early / 2, "zero crossings per sample early " + early
                + ", late " + late);
    }

    @Test
    void mainWritesTheCommittedFiles(@TempDir Path folder) throws IOException {
        SoundGenerator.main(new String[] {folder.toString()});
        for (SoundCue cue : SoundCue.values()) {
            assertArrayEquals(committed(cue),
                    Files.readAllBytes(folder.resolve(cue.getFileName())), cue.getFileName());
        }
    }

    private static byte[] committed(SoundCue cue) throws IOException {
        // assets/ is on the classpath (build.gradle), as the app's asset manager sees it.
        try (InputStream in = SoundGeneratorTest.class.getResourceAsStream(
                "/" + cue.getAssetPath())) {
            assertNotNull(in, cue.getAssetPath() + " is not on the classpath");
            return in.readAllBytes();
        }
    }

    private static String tag(byte[] file, int offset) {
        return new String(file, offset, 4, StandardCharsets.US_ASCII);
    }

    private static short[] samplesOf(byte[] file) {
        ByteBuffer data = ByteBuffer.wrap(file, SoundGenerator.WAV_HEADER_BYTES,
                file.length - SoundGenerator.WAV_HEADER_BYTES).order(ByteOrder.LITTLE_ENDIAN);
        short[] samples = new short[data.remaining() / 2];
        data.asShortBuffer().get(samples);
        return samples;
    }

    private static double rms(short[] samples, int from, int to) {
        double sum = 0.0;
        for (int i = from; i < to; ++i) {
            sum += (double) samples[i] * samples[i];
        }
        return Math.sqrt(sum / (to - from));
    }

    private static double crossingsPerSample(short[] samples, int from, int to) {
        int crossings = 0;
        for (int i = from + 1; i < to; ++i) {
            if ((samples[i - 1] < 0) != (samples[i] < 0)) {
                ++crossings;
            }
        }
        return (double) crossings / (to - from);
    }
}

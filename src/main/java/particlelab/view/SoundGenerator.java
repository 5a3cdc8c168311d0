package particlelab.view;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;

/**
 * Synthesises the app's sounds ({@link SoundCue}) as mono 16-bit PCM WAV files, the same bytes
 * on every run and every JVM: only arithmetic, {@link StrictMath} and a fixed-seed xorshift
 * noise source, no clock and no platform maths. {@code gradle sounds} runs {@link #main} and
 * writes {@code assets/Sounds}; a test checks that the committed files are these bytes.
 *
 * <p>Each sound is a signal {@code s(t)} shaped by a window {@code w(t)} that ramps up from 0
 * over the attack and back down to 0 over the release, so a sound starts and ends on silence
 * (no click). The mean is then removed in proportion to the window,
 * {@code s ← s − (Σs/Σw)·w}, which leaves no DC offset and keeps both ends at 0, and the
 * result is scaled to a peak of {@link #PEAK_FRACTION} of full scale and rounded.
 * <ul>
 * <li>impact: two damped partials and a click of noise,
 * {@code e^(−t/12 ms)·sin(2π·520 Hz·t) + 0.45·e^(−t/6 ms)·sin(2π·1370 Hz·t)
 * + 0.6·e^(−t/1.5 ms)·noise};</li>
 * <li>destroy: noise through a one-pole low-pass whose cut-off falls from 4000 Hz to 200 Hz,
 * plus a tone gliding from 900 Hz down to 120 Hz, both exponentially in time, under
 * {@code e^(−t/100 ms)}.</li>
 * </ul>
 */
public final class SoundGenerator {

    /** The sample rate (in Hz): plenty for short knocks, and half the size of 44.1 kHz. */
    public static final int SAMPLE_RATE_HZ = 22_050;
    /** The largest sample value of 16-bit PCM. */
    public static final int FULL_SCALE = Short.MAX_VALUE;
    /** Every sound's peak, as a fraction of full scale (about −3 dB: headroom, no clipping). */
    public static final double PEAK_FRACTION = 0.7;
    /** The size of a canonical PCM WAV header (in bytes). */
    public static final int WAV_HEADER_BYTES = 44;

    private static final int BYTES_PER_SAMPLE = 2;
    private static final int BITS_PER_SAMPLE = 16;
    private static final short PCM_FORMAT = 1;
    private static final short MONO = 1;
    private static final int FMT_CHUNK_BYTES = 16;
    private static final double TWO_PI = 2.0 * StrictMath.PI;

    private static final double IMPACT_ATTACK_SECONDS = 0.001;
    private static final double IMPACT_RELEASE_SECONDS = 0.010;
    private static final double IMPACT_LOW_HZ = 520.0;
    private static final double IMPACT_LOW_DECAY_SECONDS = 0.012;
    private static final double IMPACT_HIGH_HZ = 1370.0;
    private static final double IMPACT_HIGH_DECAY_SECONDS = 0.006;
    private static final double IMPACT_HIGH_LEVEL = 0.45;
    private static final double IMPACT_CLICK_DECAY_SECONDS = 0.0015;
    private static final double IMPACT_CLICK_LEVEL = 0.6;
    private static final int IMPACT_SEED = 0x1A2B3C4D;

    private static final double DESTROY_ATTACK_SECONDS = 0.002;
    private static final double DESTROY_RELEASE_SECONDS = 0.030;
    private static final double DESTROY_DECAY_SECONDS = 0.100;
    private static final double DESTROY_CUTOFF_START_HZ = 4000.0;
    private static final double DESTROY_CUTOFF_END_HZ = 200.0;
    private static final double DESTROY_TONE_START_HZ = 900.0;
    private static final double DESTROY_TONE_END_HZ = 120.0;
    private static final double DESTROY_NOISE_LEVEL = 0.6;
    private static final double DESTROY_TONE_LEVEL = 0.5;
    private static final int DESTROY_SEED = 0x5EED0D35;

    private SoundGenerator() {
    }

    /**
     * Write every cue's WAV file into a folder.
     *
     * @param args one argument, the folder (created if missing); none: {@code assets/Sounds}
     */
    public static void main(String[] args) {
        if (args.length > 1) {
            System.err.println("SoundGenerator: expected at most one argument (the output"
                    + " folder), but got " + args.length);
            System.exit(2);
        }
        Path folder = Paths.get(args.length == 1 ? args[0] : "assets/Sounds");
        try {
            Files.createDirectories(folder);
            for (SoundCue cue : SoundCue.values()) {
                Path file = folder.resolve(cue.getFileName());
                Files.write(file, wav(cue));
                System.out.println("wrote " + file + " (" + countSamples(cue) + " samples at "
                        + SAMPLE_RATE_HZ + " Hz)");
            }
        } catch (IOException e) {
            System.err.println("SoundGenerator: cannot write " + folder + ": " + e.getMessage());
            System.exit(1);
        }
    }

    /**
     * Synthesise a cue and encode it as a WAV file.
     *
     * @param cue the sound (not null)
     * @return the file's bytes (new)
     */
    public static byte[] wav(SoundCue cue) {
        return encodeWav(synthesise(cue), SAMPLE_RATE_HZ);
    }

    /**
     * Return how many samples a cue has: its duration times the sample rate, rounded.
     *
     * @param cue the sound (not null)
     * @return the count (&gt;0)
     */
    public static int countSamples(SoundCue cue) {
        return (int) Math.round(cue.getDurationSeconds() * SAMPLE_RATE_HZ);
    }

    /**
     * Synthesise a cue's samples (see the class comment for the recipes).
     *
     * @param cue the sound (not null)
     * @return the 16-bit samples (new)
     */
    public static short[] synthesise(SoundCue cue) {
        int count = countSamples(cue);
        double[] signal = new double[count];
        double[] window;
        switch (cue) {
            case IMPACT:
                window = window(count, IMPACT_ATTACK_SECONDS, IMPACT_RELEASE_SECONDS);
                impact(signal);
                break;
            case DESTROY:
                window = window(count, DESTROY_ATTACK_SECONDS, DESTROY_RELEASE_SECONDS);
                destroy(signal);
                break;
            default:
                throw new IllegalArgumentException("no recipe for the sound " + cue);
        }
        for (int i = 0; i < count; ++i) {
            signal[i] *= window[i];
        }
        removeMean(signal, window);
        return quantise(signal);
    }

    /**
     * Encode samples as a canonical 44-byte-header PCM WAV file: mono, 16 bits, little-endian.
     *
     * @param samples the samples (not null)
     * @param sampleRateHz the sample rate (in Hz, &gt;0)
     * @return the file's bytes (new)
     */
    public static byte[] encodeWav(short[] samples, int sampleRateHz) {
        if (sampleRateHz <= 0) {
            throw new IllegalArgumentException(
                    "sample rate (Hz) must be > 0, but was " + sampleRateHz);
        }
        int dataBytes = samples.length * BYTES_PER_SAMPLE;
        ByteBuffer out = ByteBuffer.allocate(WAV_HEADER_BYTES + dataBytes)
                .order(ByteOrder.LITTLE_ENDIAN);
        out.put(ascii("RIFF")).putInt(WAV_HEADER_BYTES - 8 + dataBytes).put(ascii("WAVE"));
        out.put(ascii("fmt ")).putInt(FMT_CHUNK_BYTES).putShort(PCM_FORMAT).putShort(MONO)
                .putInt(sampleRateHz).putInt(sampleRateHz * BYTES_PER_SAMPLE)
                .putShort((short) BYTES_PER_SAMPLE).putShort((short) BITS_PER_SAMPLE);
        out.put(ascii("data")).putInt(dataBytes);
        for (short sample : samples) {
            out.putShort(sample);
        }
        return out.array();
    }

    private static void impact(double[] signal) {
        Noise noise = new Noise(IMPACT_SEED);
        for (int i = 0; i < signal.length; ++i) {
            double t = (double) i / SAMPLE_RATE_HZ;
            double low = StrictMath.exp(-t / IMPACT_LOW_DECAY_SECONDS)
                    * StrictMath.sin(TWO_PI * IMPACT_LOW_HZ * t);
            double high = IMPACT_HIGH_LEVEL * StrictMath.exp(-t / IMPACT_HIGH_DECAY_SECONDS)
                    * StrictMath.sin(TWO_PI * IMPACT_HIGH_HZ * t);
            double click = IMPACT_CLICK_LEVEL * StrictMath.exp(-t / IMPACT_CLICK_DECAY_SECONDS)
                    * noise.next();
            signal[i] = low + high + click;
        }
    }

    private static void destroy(double[] signal) {
        Noise noise = new Noise(DESTROY_SEED);
        double durationSeconds = (double) signal.length / SAMPLE_RATE_HZ;
        double lowPassed = 0.0;
        double tonePhase = 0.0;
        for (int i = 0; i < signal.length; ++i) {
            double t = (double) i / SAMPLE_RATE_HZ;
            double progress = t / durationSeconds;
            double cutoffHz = glide(DESTROY_CUTOFF_START_HZ, DESTROY_CUTOFF_END_HZ, progress);
            // One-pole low-pass y += a·(x − y), a = 1 − e^(−2π·fc/rate).
            double a = 1.0 - StrictMath.exp(-TWO_PI * cutoffHz / SAMPLE_RATE_HZ);
            lowPassed += a * (noise.next() - lowPassed);
            double toneHz = glide(DESTROY_TONE_START_HZ, DESTROY_TONE_END_HZ, progress);
            double tone = StrictMath.sin(tonePhase);
            tonePhase += TWO_PI * toneHz / SAMPLE_RATE_HZ;
            signal[i] = StrictMath.exp(-t / DESTROY_DECAY_SECONDS)
                    * (DESTROY_NOISE_LEVEL * lowPassed + DESTROY_TONE_LEVEL * tone);
        }
    }

    /** An exponential glide from one frequency to another as progress goes from 0 to 1. */
    private static double glide(double startHz, double endHz, double progress) {
        return startHz * StrictMath.pow(endHz / startHz, progress);
    }

    /**
     * The window: a linear ramp 0 → 1 over the attack, 1, then 1 → 0 over the release, with
     * the first and the last sample exactly 0.
     */
    private static double[] window(int count, double attackSeconds, double releaseSeconds) {
        int attack = (int) Math.round(attackSeconds * SAMPLE_RATE_HZ);
        int release = (int) Math.round(releaseSeconds * SAMPLE_RATE_HZ);
        double[] window = new double[count];
        for (int i = 0; i < count; ++i) {
            double up = Math.min(1.0, (double) i / attack);
            double down = Math.min(1.0, (double) (count - 1 - i) / release);
            window[i] = Math.min(up, down);
        }
        return window;
    }

    /** {@code s ← s − (Σs/Σw)·w}: zero mean, and still 0 where the window is. */
    private static void removeMean(double[] signal, double[] window) {
        double signalSum = 0.0;
        double windowSum = 0.0;
        for (int i = 0; i < signal.length; ++i) {
            signalSum += signal[i];
            windowSum += window[i];
        }
        double offset = signalSum / windowSum;
        for (int i = 0; i < signal.length; ++i) {
            signal[i] -= offset * window[i];
        }
    }

    /** Scale to a peak of {@link #PEAK_FRACTION} of full scale and round to 16 bits. */
    private static short[] quantise(double[] signal) {
        double peak = 0.0;
        for (double value : signal) {
            peak = Math.max(peak, Math.abs(value));
        }
        double scale = PEAK_FRACTION * FULL_SCALE / peak;
        short[] samples = new short[signal.length];
        for (int i = 0; i < signal.length; ++i) {
            samples[i] = (short) Math.round(signal[i] * scale);
        }
        return samples;
    }

    private static byte[] ascii(String tag) {
        byte[] bytes = new byte[tag.length()];
        for (int i = 0; i < bytes.length; ++i) {
            bytes[i] = (byte) tag.charAt(i);
        }
        return bytes;
    }

    /** White noise, uniform in [−1, 1): Marsaglia's xorshift32, fixed seed, so reproducible. */
    private static final class Noise {
        private static final double UNIT = 1.0 / (1 << 23);
        private int state;

        Noise(int seed) {
            state = seed;
        }

        double next() {
            state ^= state << 13;
            state ^= state >>> 17;
            state ^= state << 5;
            return (state >>> 8) * UNIT - 1.0;
        }
    }
}

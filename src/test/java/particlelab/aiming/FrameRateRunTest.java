package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.app.TrajectoryCommand;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;

/**
 * The lecture's loop at 30, 60, 144 and 240 Hz (issue 33 §1): the fixed step's lanes are
 * bit-identical, each raw-tpf lane is {@code trajectory --tpf 1/f} byte for byte, a level shot
 * lands {@code vx·h} short, and the jitter histogram is a re-simulation of its seeds.
 */
public class FrameRateRunTest {

    private static final float[] RATES_HZ = {30f, 60f, 144f, 240f};
    private static final float G = 9.8f;
    private static final float VX = 20f;
    /** vy of the level shot: its crossings fall inside steps at every rate (none at y = 0). */
    private static final float VY = 14.3f;
    private static final float FIXED_STEP = 1f / 60f;

    private static ParticleIntegrator gravity() {
        return new ParticleIntegrator(new Gravity(new Vector3f(0f, -G, 0f)));
    }

    private static Particle launch() {
        return new Particle(new Vector3f(), new Vector3f(VX, VY, 0f), 1f);
    }

    @Test
    void fixedStepLanesAreBitIdenticalAtEveryRate() {
        ParticleIntegrator integrator = gravity();
        FrameRateRun first = new FrameRateRun(integrator);
        first.start(launch(), RATES_HZ[0], SimulationClock.Mode.FIXED_STEP, FIXED_STEP);
        assertTrue(first.flyToLanding());
        FrameRateRun raw = new FrameRateRun(integrator);
        for (int i = 1; i < RATES_HZ.length; ++i) {
            FrameRateRun run = new FrameRateRun(integrator);
            run.start(launch(), RATES_HZ[i], SimulationClock.Mode.FIXED_STEP, FIXED_STEP);
            assertTrue(run.flyToLanding());
            // bit for bit: the same steps of h, whatever the frames that fed the accumulator
            assertEquals(first.getSteps(), run.getSteps());
            assertEquals(Double.doubleToLongBits(first.getLanding().getX()),
                    Double.doubleToLongBits(run.getLanding().getX()));
            assertEquals(Double.doubleToLongBits(first.getLanding().getTimeSeconds()),
                    Double.doubleToLongBits(run.getLanding().getTimeSeconds()));
            assertEquals(first.getParticle().position, run.getParticle().position);
            assertEquals(first.getParticle().velocity, run.getParticle().velocity);
            // while the lecture's raw loop lands elsewhere at every rate but 60 Hz
            raw.start(launch(), RATES_HZ[i], SimulationClock.Mode.RAW_TPF, FIXED_STEP);
            assertTrue(raw.flyToLanding());
            if (RATES_HZ[i] != 60f) {
                assertNotEquals(first.getLanding().getX(), raw.getLanding().getX());
            }
        }
    }

    @Test
    void rawTpfRunEqualsTrajectoryCommandByteForByte() {
        for (float rate : RATES_HZ) {
            FrameRateRun run = new FrameRateRun(gravity());
            run.start(launch(), rate, SimulationClock.Mode.RAW_TPF, FIXED_STEP);
            float tpf = FrameRateRun.frameSeconds(rate);
            StringBuilder csv = new StringBuilder(TrajectoryCommand.HEADER).append('\n');
            appendRow(csv, 0, tpf, run.getParticle());
            while (!run.hasLanded()) {
                run.frame(tpf);
                appendRow(csv, run.getSteps(), tpf, run.getParticle());
            }
            String expected = trajectory("--v0", VX + "," + VY + ",0", "--g", "0,-" + G + ",0",
                    "--tpf", "1/" + (int) rate, "--until-ground");
            assertEquals(expected, csv.toString(), "at " + rate + " Hz");
        }
    }

    @Test
    void levelShotLandsShortByVxTimesStepAtEveryRate() {
        double range = 2.0 * VX * (double) VY / G;
        for (float rate : RATES_HZ) {
            FrameRateRun run = new FrameRateRun(gravity());
            run.start(launch(), rate, SimulationClock.Mode.RAW_TPF, FIXED_STEP);
            assertTrue(run.flyToLanding());
            double h = FrameRateRun.frameSeconds(rate);
            double shortBy = range - run.getLanding().getX();
            // The samples lie exactly on the parabola launched with vy - g·h/2, which lands
            // vx·h short; the crossing is interpolated on the chord between two samples,
            // which lies at most g·h²/8 below that parabola, so x moves at most
            // g·h²/8 · vx/|vy_landing| (|vy_landing| > vy - g·h). Float round-off, worst
            // case over n steps: vy gains at most ulp(vy)/2 a step, so y strays by at most
            // n·T·ulp(vy)/2 from it and n·ulp(y_max)/2 from its own rounding, moved along x
            // by vx/|vy_landing|; x by n·ulp(x_max)/2. About 2e-3 m at 240 Hz, against a
            // shortfall of vx·h = 0.083 m there.
            int n = run.getSteps();
            double slope = VX / (VY - G * h);
            double roundOff = n * (run.getLanding().getTimeSeconds() * Math.ulp(VY) / 2.0
                    + Math.ulp((float) (VY * VY / (2.0 * G))) / 2.0) * slope
                    + n * Math.ulp((float) range) / 2.0;
            double chord = G * h * h / 8.0 * slope;
            assertEquals(VX * h, shortBy, chord + roundOff, "at " + rate + " Hz");
        }
    }

    @Test
    void jitterHistogramEqualsReSimulationOfTheSameSeeds() {
        float rate = 60f;
        float width = 0.004f;
        long seed = 33L;
        int runs = JitterHistogram.DEFAULT_RUNS;
        for (FrameJitter.Distribution distribution : FrameJitter.Distribution.values()) {
            JitterHistogram histogram = new JitterHistogram(gravity(), runs);
            histogram.compute(launch(), rate, distribution, width, seed, runs, FIXED_STEP);
            double[] expected = new double[runs];
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < runs; ++i) {
                expected[i] = reSimulate(distribution, width, seed + i, rate);
                assertEquals(Double.doubleToLongBits(expected[i]),
                        Double.doubleToLongBits(histogram.getLandingX(i)), "run " + i);
                min = Math.min(min, expected[i]);
                max = Math.max(max, expected[i]);
            }
            assertEquals(0, histogram.getMissed());
            // the fixed step: one bar, where the fixed-step lanes land
            FrameRateRun fixed = new FrameRateRun(gravity());
            fixed.start(launch(), rate, SimulationClock.Mode.FIXED_STEP, FIXED_STEP);
            assertTrue(fixed.flyToLanding());
            assertEquals(fixed.getLanding().getX(), histogram.getFixedX(), 0.0);
            min = Math.min(min, histogram.getFixedX());
            max = Math.max(max, histogram.getFixedX());
            int[] counts = new int[JitterHistogram.BINS];
            for (double x : expected) {
                int bin = (int) ((x - min) / (max - min) * JitterHistogram.BINS);
                ++counts[Math.min(JitterHistogram.BINS - 1, bin)];
            }
            int total = 0;
            for (int bin = 0; bin < JitterHistogram.BINS; ++bin) {
                assertEquals(counts[bin], histogram.getCount(bin), distribution + " bin " + bin);
                total += histogram.getCount(bin);
            }
            assertEquals(runs, total);
            // jitter spreads the landings: more than one bar
            assertTrue(max - min > 0.01, distribution + ": spread " + (max - min));
        }
    }

    @Test
    void runsAndTheHistogramAllocateNothing() {
        JitterHistogram histogram = new JitterHistogram(gravity(), 100);
        FrameRateRun run = new FrameRateRun(gravity());
        Particle launch = launch();
        Allocations.assertAllocatesNothing("a raw-tpf run at 144 Hz to its landing", () -> {
            run.start(launch, 144f, SimulationClock.Mode.RAW_TPF, FIXED_STEP);
            run.flyToLanding();
        });
        Allocations.assertAllocatesNothing("a histogram of 100 normal-jitter runs",
                () -> histogram.compute(launch, 60f, FrameJitter.Distribution.NORMAL, 0.003f,
                        7L, 100, FIXED_STEP));
    }

    /**
     * One jittered run written out plainly: draw each frame from a fresh Random with the run's
     * seed, take one step of it, stop at the first step that ends below the ground and
     * interpolate the crossing on the step's segment.
     */
    private static double reSimulate(FrameJitter.Distribution distribution, float width,
            long seed, float rate) {
        Random random = new Random(seed);
        float nominal = (float) (1.0 / rate);
        ParticleIntegrator integrator = gravity();
        Particle particle = launch();
        for (int frame = 0; frame < 100_000; ++frame) {
            double offset = distribution == FrameJitter.Distribution.UNIFORM
                    ? 2.0 * random.nextDouble() - 1.0 : random.nextGaussian();
            float tpf = Math.max(FrameJitter.MIN_FRAME_SECONDS,
                    (float) (nominal + width * offset));
            float x0 = particle.position.x;
            float y0 = particle.position.y;
            integrator.step(particle, tpf);
            float y1 = particle.position.y;
            if (y1 < 0f && y1 < y0) {
                double fraction = y0 <= 0f ? 0.0 : y0 / ((double) y0 - y1);
                return x0 + fraction * ((double) particle.position.x - x0);
            }
        }
        throw new AssertionError("never landed");
    }

    /** A row as {@code trajectory} prints it: t = n·h from the step count, floats' digits. */
    public static void appendRow(StringBuilder csv, int n, float tpf, Particle particle) {
        Vector3f p = particle.position;
        Vector3f v = particle.velocity;
        csv.append((float) (n * (double) tpf)).append(',').append(p.x).append(',').append(p.y)
                .append(',').append(p.z).append(',').append(v.x).append(',').append(v.y)
                .append(',').append(v.z).append('\n');
    }

    /** @return what {@code trajectory} prints for the arguments (exit 0 asserted), lines by \n */
    public static String trajectory(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = TrajectoryCommand.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, code, err.toString(StandardCharsets.UTF_8));
        return out.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n");
    }
}

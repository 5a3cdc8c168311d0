package particlelab.aiming;

import java.util.Arrays;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;

/**
 * Where one launch lands over N runs of the same monitor with jittered frame times
 * ({@link FrameJitter}, run {@code i} seeded with {@code seed + i}): the lecture's raw-tpf loop
 * lands somewhere new each run, while the fixed step lands every run at the same x, the
 * "single bar" the histogram is drawn against.
 *
 * <p>The landings are computed in one call of {@link #compute} (once per launch, not per
 * frame: a demo calls it when a launch starts); the arrays are sized once for the most runs.
 */
public final class JitterHistogram {

    /** The runs of a histogram unless told otherwise. */
    public static final int DEFAULT_RUNS = 1000;
    /** The histogram's bins across the landings' range. */
    public static final int BINS = 12;

    private final FrameRateRun run;
    private final FrameJitter jitter = new FrameJitter();
    private final double[] landings;
    private final int[] counts = new int[BINS];
    private int runs;
    private int missed;
    private double minX;
    private double maxX;
    private double fixedX;

    /**
     * Create a histogram flown with one scene's forces.
     *
     * @param integrator the scene's integrator (not null; shared, not modified)
     * @param maxRuns the most runs one histogram takes (&ge;1)
     */
    public JitterHistogram(ParticleIntegrator integrator, int maxRuns) {
        if (maxRuns < 1) {
            throw new IllegalArgumentException("runs must be >= 1, but was " + maxRuns);
        }
        run = new FrameRateRun(integrator);
        landings = new double[maxRuns];
    }

    /**
     * Fly the launch N times with jittered raw-tpf frames, and once with the fixed step
     * (jitter or not, the fixed step's frames give the same steps), and bin the landings.
     *
     * @param launch the particle at its launch (not null, unmodified)
     * @param rateHz the monitor's refresh rate (in Hz, &gt;0)
     * @param distribution the jitter's distribution (not null)
     * @param widthSeconds the jitter's width (in seconds, &ge;0)
     * @param seed run i is seeded with seed + i
     * @param runCount N (1 to the most runs)
     * @param fixedStepSeconds the fixed step h (in seconds, &gt;0)
     */
    public void compute(Particle launch, float rateHz, FrameJitter.Distribution distribution,
            float widthSeconds, long seed, int runCount, float fixedStepSeconds) {
        if (runCount < 1 || runCount > landings.length) {
            throw new IllegalArgumentException("runs must be from 1 to " + landings.length
                    + ", but was " + runCount);
        }
        runs = runCount;
        missed = 0;
        minX = Double.POSITIVE_INFINITY;
        maxX = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < runs; ++i) {
            jitter.start(distribution, widthSeconds, seed + i);
            run.start(launch, rateHz, SimulationClock.Mode.RAW_TPF, fixedStepSeconds);
            if (run.flyToLanding(jitter)) {
                landings[i] = run.getLanding().getX();
                minX = Math.min(minX, landings[i]);
                maxX = Math.max(maxX, landings[i]);
            } else {
                landings[i] = Double.NaN;
                ++missed;
            }
        }
        jitter.start(distribution, widthSeconds, seed);
        run.start(launch, rateHz, SimulationClock.Mode.FIXED_STEP, fixedStepSeconds);
        fixedX = run.flyToLanding(jitter) ? run.getLanding().getX() : Double.NaN;
        if (Double.isFinite(fixedX)) {
            minX = Math.min(minX, fixedX);
            maxX = Math.max(maxX, fixedX);
        }
        Arrays.fill(counts, 0);
        for (int i = 0; i < runs; ++i) {
            if (!Double.isNaN(landings[i])) {
                ++counts[bin(landings[i])];
            }
        }
    }

    /**
     * Return the bin a landing falls in: {@link #BINS} equal bins from the smallest landing
     * (the fixed step's included) to the largest, the largest in the last.
     *
     * @param x the landing (in metres, within the range)
     * @return the bin (0 to {@link #BINS} − 1)
     */
    public int bin(double x) {
        double span = maxX - minX;
        if (!(span > 0.0)) {
            return 0;
        }
        int bin = (int) ((x - minX) / span * BINS);
        return Math.max(0, Math.min(BINS - 1, bin));
    }

    /** @return N, the runs of the last computation */
    public int getRuns() {
        return runs;
    }

    /** @return the runs that did not land within {@link FrameRateRun#MAX_FRAMES} frames */
    public int getMissed() {
        return missed;
    }

    /**
     * Return run i's landing.
     *
     * @param i the run (0 to N − 1)
     * @return its x (in metres; NaN if it did not land)
     */
    public double getLandingX(int i) {
        return landings[i];
    }

    /**
     * Return how many runs landed in a bin.
     *
     * @param bin the bin (0 to {@link #BINS} − 1)
     * @return the count
     */
    public int getCount(int bin) {
        return counts[bin];
    }

    /** @return the smallest landing, the fixed step's included (m) */
    public double getMinX() {
        return minX;
    }

    /** @return the largest landing, the fixed step's included (m) */
    public double getMaxX() {
        return maxX;
    }

    /** @return where every fixed-step run lands (m; NaN if it did not land) */
    public double getFixedX() {
        return fixedX;
    }
}

package particlelab.demo;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import particlelab.aiming.FrameJitter;
import particlelab.aiming.FrameRateRun;
import particlelab.aiming.JitterHistogram;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.ParticleView;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * The lecture's loop at 30, 60, 144 and 240 Hz ({@code --set rates=on}): four more spheres
 * with the followed sphere's launch and forces, each moved by its own monitor's game loop,
 * one raw-tpf step {@code P += tpf·V} of {@code tpf = 1/f} per frame ({@link FrameRateRun}),
 * in step with the demo's time: a 30 Hz lane moves every other step of a 1/60 s demo, a
 * 240 Hz lane four times a step. The followed sphere itself is the cure beside them: the
 * demo's fixed step {@code h} from an accumulator, which takes the same steps whatever the
 * monitor (the HUD gives its landing, computed at 30 Hz, the same bits at every rate).
 *
 * <p>What to watch: under gravity a level shot lands {@code vx·h} short, so the 30 Hz lane
 * lands furthest short and the 240 Hz lane nearest the parabola; the HUD labels each lane's
 * landing and its miss against the fixed step's. With {@code --set jitter=uniform} or
 * {@code normal} and {@code jitter_ms=W}, frame times are drawn around 1/60 s (seeded,
 * {@link FrameJitter}) and the HUD adds a histogram of where 1000 such runs land
 * ({@link JitterHistogram}) against the fixed step's single bar.
 *
 * <p>The lanes and the histogram are computed when a launch starts (the first step after a
 * reset): the histogram's 1000 runs there, once per launch, not per frame. Per step and per
 * frame this allocates nothing. Builds upon {@link ComparisonLane}'s way of adding a sphere
 * beside the followed one.
 */
public final class RateLanes implements DemoPart {

    /** The parameter switching the lanes on: a preset, the lecture's four rates. */
    public static final String PARAMETER = "rates";
    /** The jitter's distribution parameter. */
    public static final String JITTER = "jitter";
    /** The jitter's width parameter (ms). */
    public static final String JITTER_WIDTH = "jitter_ms";
    /** The monitors' refresh rates of {@code rates=on} (Hz): lab machine, laptops, gamers'. */
    public static final float[] RATES_HZ = {30f, 60f, 144f, 240f};
    /** The monitor whose jittered frames the histogram flies (Hz): the lab machine's. */
    public static final float HISTOGRAM_RATE_HZ = 60f;
    /** The first run's seed; run i is seeded with this + i. */
    public static final long SEED = 33L;
    /** The jitter's widest width (ms): a frame of 1/60 s ± 8 ms still lasts 8.7 ms or more. */
    private static final float MAX_JITTER_MS = 8f;
    private static final float JITTER_STEP_MS = 0.5f;
    private static final float DEFAULT_JITTER_MS = 2f;
    private static final float MS_PER_SECOND = 1000f;
    /** A frame due within this of the demo's time is taken now (s): round-off of the sums. */
    private static final double FRAME_SLACK_SECONDS = 1e-9;
    private static final String[] SWITCH = {"off", "on"};
    private static final String[] JITTERS = {"none", "uniform", "normal"};
    private static final ColorRGBA[] COLORS = {
        new ColorRGBA(1f, 0.3f, 0.3f, 1f), new ColorRGBA(1f, 0.85f, 0.2f, 1f),
        new ColorRGBA(0.3f, 0.8f, 1f, 1f), new ColorRGBA(0.85f, 0.45f, 1f, 1f)};
    /** Levels of a histogram bar as one character, from none to the tallest. */
    private static final String LEVELS = " .:-=+*#%@";
    /** The histogram's metres to the millimetre: jitter spreads landings by centimetres. */
    private static final int HISTOGRAM_DECIMALS = 3;

    private DemoState demo;
    private DemoParticle followed;
    private final DemoParticle[] spheres = new DemoParticle[RATES_HZ.length];
    private final FrameRateRun[] runs = new FrameRateRun[RATES_HZ.length];
    private FrameRateRun fixed;
    private JitterHistogram histogram;
    private boolean on;
    private int jitterIndex;
    private float jitterMs = DEFAULT_JITTER_MS;
    /** The next step starts the lanes from the launch. */
    private boolean needsStart = true;
    /** The demo's time since the launch (s), the sum of its steps. */
    private double demoSeconds;
    /** Frames each lane has taken since the launch. */
    private final int[] frames = new int[RATES_HZ.length];
    private final Particle launch = new Particle();
    private final Vector3f scratchPosition = new Vector3f();
    private final Vector3f scratchVelocity = new Vector3f();

    /**
     * Add the lanes' spheres beside one of the demo's. Call from the demo's
     * {@code createScene()}, after the followed sphere was added, the part having been added
     * with {@link DemoState#addPart}.
     *
     * @param followedSphere the sphere whose launch and forces the lanes share (not null)
     */
    public void follow(DemoParticle followedSphere) {
        if (demo == null) {
            throw new IllegalStateException("add the rate lanes to their demo with addPart"
                    + " before they follow a sphere");
        }
        followed = followedSphere;
        ParticleIntegrator integrator = followed.getIntegrator();
        followed.copyLaunchPosition(scratchPosition);
        followed.copyLaunchVelocity(scratchVelocity);
        for (int i = 0; i < RATES_HZ.length; ++i) {
            spheres[i] = demo.addParticle(label(i), COLORS[i], scratchPosition,
                    scratchVelocity, followed.getParticle().getMass(), new ParticleIntegrator());
            // out of the HUD's particle lines (the part writes its own) and of the framing
            spheres[i].setParked(true);
            runs[i] = new FrameRateRun(integrator);
        }
        fixed = new FrameRateRun(integrator);
        histogram = new JitterHistogram(integrator, JitterHistogram.DEFAULT_RUNS);
    }

    /**
     * Test whether a particle is one of the lanes' spheres (parked while the lanes are off).
     *
     * @param particle a particle of the demo (may be null)
     * @return true for a lane's sphere
     */
    public boolean isLaneSphere(DemoParticle particle) {
        for (DemoParticle sphere : spheres) {
            if (sphere != null && sphere == particle) {
                return true;
            }
        }
        return false;
    }

    /**
     * Test whether the lanes are shown.
     *
     * @return true for {@code rates=on}
     */
    public boolean isOn() {
        return on;
    }

    /**
     * Return the jitter the histogram draws frames from.
     *
     * @return the distribution, or null for {@code jitter=none}
     */
    public FrameJitter.Distribution getJitter() {
        return jitterIndex == 0 ? null : distribution();
    }

    /**
     * Return the jitter's width.
     *
     * @return w (in ms, 0 to 8)
     */
    public float getJitterWidthMs() {
        return jitterMs;
    }

    /**
     * Access one lane's run.
     *
     * @param lane the lane (0 to 3: 30, 60, 144, 240 Hz)
     * @return the live run (do not modify; null before {@link #follow})
     */
    public FrameRateRun getRun(int lane) {
        return runs[lane];
    }

    /**
     * Access the fixed step's run (the cure), flown at 30 Hz.
     *
     * @return the live run (do not modify; null before {@link #follow})
     */
    public FrameRateRun getFixedRun() {
        return fixed;
    }

    /**
     * Access the jitter histogram of the launch (computed only while a jitter is chosen).
     *
     * @return the live histogram (do not modify; null before {@link #follow})
     */
    public JitterHistogram getHistogram() {
        return histogram;
    }

    @Override
    public void attach(DemoState owner) {
        demo = owner;
    }

    /**
     * Declare {@code rates=off|on} ({@code on}: 30, 60, 144 and 240 Hz),
     * {@code jitter=none|uniform|normal} and {@code jitter_ms} (0 to 8 ms), at the next launch.
     *
     * @param parameters the demo's parameters (not null, modified)
     */
    @Override
    public void declareParameters(DemoParameters parameters) {
        parameters.add(DemoParameter.choice(PARAMETER, "rate lanes 30/60/144/240 Hz", SWITCH,
                0, DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    on = value != 0f;
                    needsStart = true;
                }));
        parameters.add(DemoParameter.choice(JITTER, "frame-time jitter", JITTERS, 0,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    jitterIndex = Math.round(value);
                    needsStart = true;
                }));
        parameters.add(new DemoParameter(JITTER_WIDTH, "jitter width", "ms", 0f,
                MAX_JITTER_MS, JITTER_STEP_MS, DEFAULT_JITTER_MS, 1,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    jitterMs = value;
                    needsStart = true;
                }));
    }

    /**
     * Move each lane through its monitor's frames due by the end of this step, and put its
     * sphere where its last frame left it (no velocity: the world's step leaves it there).
     * At a launch, fly the fixed step's run and the histogram first. Allocates nothing.
     *
     * @param stepSeconds h (in seconds, &gt;0)
     */
    @Override
    public void beforeStep(float stepSeconds) {
        if (followed == null || !on) {
            return;
        }
        if (needsStart) {
            start();
        }
        demoSeconds += stepSeconds;
        for (int i = 0; i < RATES_HZ.length; ++i) {
            catchUp(i);
            place(i);
        }
    }

    /** Start the lanes again from the launch, at the demo's reset. */
    @Override
    public void onRestart() {
        needsStart = true;
    }

    /** Show the lanes' spheres only while on; their exact ghosts never (the ball has one). */
    @Override
    public void afterFrame() {
        if (followed == null) {
            return;
        }
        for (int i = 0; i < spheres.length; ++i) {
            ParticleView view = demo.getView(spheres[i]);
            if (view != null) {
                view.getNode().setCullHint(on ? Spatial.CullHint.Inherit
                        : Spatial.CullHint.Always);
            }
            demo.getExactGhosts().setGhostShown(demo.getParticles().indexOf(spheres[i]), false);
        }
    }

    /**
     * Append the lanes' lines (none while off): each lane's landing and miss against the fixed
     * step, the fixed step's landing, and with jitter the histogram. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     */
    @Override
    public void writeHudLines(StringBuilder text) {
        if (followed == null || !on || needsStart) {
            return;
        }
        text.append("Raw tpf lands (vs fixed):");
        for (int i = 0; i < RATES_HZ.length; ++i) {
            text.append("  ").append((int) RATES_HZ[i]).append(" Hz ");
            FrameRateRun run = runs[i];
            if (!run.hasLanded()) {
                text.append("flying");
            } else {
                TextFormat.appendFixed(text, run.getLanding().getX(), 2).append(" m (");
                appendSigned(text, run.getLanding().getX() - fixed.getLanding().getX());
                text.append(')');
            }
        }
        text.append('\n');
        text.append("Fixed step h = ");
        TextFormat.appendFixed(text, demo.getClock().getStepSeconds() * MS_PER_SECOND, 2)
                .append(" ms (the cure): ");
        if (fixed.hasLanded()) {
            TextFormat.appendFixed(text, fixed.getLanding().getX(), 2)
                    .append(" m at every rate, bit for bit\n");
        } else {
            text.append("does not land\n");
        }
        if (jitterIndex != 0) {
            appendHistogram(text);
        }
    }

    /** The part's own state: the launch's time, so a replayed step puts the lanes back. */
    @Override
    public StateRecord stateRecord() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 3;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putBoolean(needsStart);
                slab.putDouble(demoSeconds);
            }

            @Override
            public void readState(StateSlab slab) {
                boolean recordedNeedsStart = slab.getBoolean();
                double seconds = slab.getDouble();
                if (!recordedNeedsStart && followed != null && on) {
                    // fly the lanes again from the launch up to the recorded time: the same
                    // frames, so the same bits, and nothing to store per lane
                    if (needsStart) {
                        start();
                    } else {
                        restartLanes();
                    }
                    demoSeconds = seconds;
                    for (int i = 0; i < RATES_HZ.length; ++i) {
                        catchUp(i);
                        place(i);
                    }
                }
                needsStart = recordedNeedsStart;
                demoSeconds = seconds;
            }
        };
    }

    /** At a launch: the lanes at the launch, the fixed step's landing, the histogram. */
    private void start() {
        needsStart = false;
        restartLanes();
        float h = demo.getClock().getStepSeconds();
        fixed.start(launch, RATES_HZ[0], SimulationClock.Mode.FIXED_STEP, h);
        fixed.flyToLanding();
        if (jitterIndex != 0) {
            // once per launch, here and only here: N runs of about a thousand steps each
            histogram.compute(launch, HISTOGRAM_RATE_HZ, distribution(), jitterMs / MS_PER_SECOND,
                    SEED, JitterHistogram.DEFAULT_RUNS, h);
        }
    }

    /** Put every lane at the launch, no frame taken. */
    private void restartLanes() {
        followed.copyLaunchPosition(scratchPosition);
        followed.copyLaunchVelocity(scratchVelocity);
        launch.position.set(scratchPosition);
        launch.velocity.set(scratchVelocity);
        launch.setMass(followed.getParticle().getMass());
        demoSeconds = 0.0;
        float h = demo.getClock().getStepSeconds();
        for (int i = 0; i < RATES_HZ.length; ++i) {
            runs[i].start(launch, RATES_HZ[i], SimulationClock.Mode.RAW_TPF, h);
            frames[i] = 0;
        }
    }

    /** Take lane i's frames due by the demo's time. */
    private void catchUp(int i) {
        float tpf = FrameRateRun.frameSeconds(RATES_HZ[i]);
        while (!runs[i].hasLanded()
                && (frames[i] + 1) * (double) tpf <= demoSeconds + FRAME_SLACK_SECONDS) {
            runs[i].frame(tpf);
            ++frames[i];
        }
    }

    /** Put lane i's sphere at its run's state, or at its landing on the ground. */
    private void place(int i) {
        Particle body = spheres[i].getParticle();
        FrameRateRun run = runs[i];
        if (run.hasLanded()) {
            body.position.set((float) run.getLanding().getX(), 0f,
                    run.getParticle().position.z);
        } else {
            body.position.set(run.getParticle().position);
        }
        body.velocity.set(Vector3f.ZERO);
    }

    private FrameJitter.Distribution distribution() {
        return jitterIndex == 1 ? FrameJitter.Distribution.UNIFORM
                : FrameJitter.Distribution.NORMAL;
    }

    /** The histogram's two lines: its range and bars, and the fixed step's bar. */
    private void appendHistogram(StringBuilder text) {
        text.append("Jitter ").append(JITTERS[jitterIndex]).append(' ');
        TextFormat.appendFixed(text, jitterMs, 1).append(" ms at ")
                .append((int) HISTOGRAM_RATE_HZ).append(" Hz, ")
                .append(histogram.getRuns()).append(" runs land ");
        TextFormat.appendFixed(text, histogram.getMinX(), HISTOGRAM_DECIMALS).append(" m [");
        int tallest = 1;
        for (int bin = 0; bin < JitterHistogram.BINS; ++bin) {
            tallest = Math.max(tallest, histogram.getCount(bin));
        }
        for (int bin = 0; bin < JitterHistogram.BINS; ++bin) {
            int count = histogram.getCount(bin);
            int level = count == 0 ? 0
                    : 1 + (count * (LEVELS.length() - 2) + tallest - 1) / tallest;
            text.append(LEVELS.charAt(Math.min(LEVELS.length() - 1, level)));
        }
        text.append("] ");
        TextFormat.appendFixed(text, histogram.getMaxX(), HISTOGRAM_DECIMALS).append(" m");
        if (histogram.getMissed() > 0) {
            text.append(", ").append(histogram.getMissed()).append(" never land");
        }
        text.append('\n');
        text.append("   fixed step: all ").append(histogram.getRuns()).append(" runs in one bar"
                + " at ");
        TextFormat.appendFixed(text, histogram.getFixedX(), HISTOGRAM_DECIMALS)
                .append(" m (bin ")
                .append(histogram.bin(histogram.getFixedX()) + 1).append(" of ")
                .append(JitterHistogram.BINS).append(")\n");
    }

    private static void appendSigned(StringBuilder text, double metres) {
        if (metres >= 0.0) {
            text.append('+');
        }
        TextFormat.appendFixed(text, metres, 2);
    }

    private static String label(int lane) {
        return (int) RATES_HZ[lane] + " Hz raw tpf";
    }
}

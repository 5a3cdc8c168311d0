package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Quad;
import com.jme3.scene.shape.Sphere;
import particlelab.aiming.FrameJitter;
import particlelab.aiming.FrameRateRun;
import particlelab.aiming.JitterHistogram;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.HudFont;
import particlelab.view.HudLayout;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.view.TextMeasure;
import particlelab.view.Trail;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * The lecture's loop at 30, 60, 144 and 240 Hz ({@code --set rates=on}, issue 33 §1): four
 * spheres with the followed sphere's launch and forces, each moved by its own monitor's game
 * loop, one raw-tpf step {@code P += tpf·V} of {@code tpf = 1/f} per frame
 * ({@link FrameRateRun}, the code {@code trajectory --tpf 1/f} is checked against), in step
 * with the demo's time: a 30 Hz lane moves every other step of a 1/60 s demo, a 240 Hz lane
 * four times a step. Each stops at the ground where its run crosses it. The followed sphere
 * itself is the cure beside them: the demo's fixed step {@code h} from an accumulator, which
 * takes the same steps whatever the monitor.
 *
 * <p>What to watch: under gravity a level shot lands {@code vx·h} short of the parabola, so
 * the 30 Hz lane lands furthest short and the 240 Hz lane nearest; each lane's landing gets a
 * mark in its colour on the ground (the faster the monitor, the taller), the legend in the
 * scene's top right corner names each colour's rate and miss against the fixed step, and the
 * HUD gives each landing and the fixed step's. With
 * {@code rates=uniform} or {@code normal} and {@code jitter_ms=W}, frame times at 60 Hz are
 * drawn around 1/60 s from that distribution (seeded, {@link FrameJitter}) and the HUD adds a
 * histogram of where {@link JitterHistogram#DEFAULT_RUNS} such runs land
 * ({@link JitterHistogram}) against the fixed step's single bar.
 *
 * <p>The lanes are no bodies of the world: with {@code rates=off} the demo has the bodies,
 * steps, exports and scene end it had without them. While on, the scene's end waits for the
 * lanes to land ({@link DemoRun#waitForMotion}). The fixed step's landing and the histogram
 * are computed when a launch starts (the first step after a reset), once per launch; per step
 * and per frame the part allocates nothing (a legend line's text is set when its lane lands).
 * Builds upon {@link WhatIfPart}'s way of drawing flights that are not the world's.
 */
public final class RateLanes implements DemoPart {

    /** The parameter switching the lanes on, and the histogram's jitter with them. */
    public static final String PARAMETER = "rates";
    /** The jitter's width parameter (ms). */
    public static final String JITTER_WIDTH = "jitter_ms";
    /** {@code rates}'s values: off, the four lanes, the lanes and a jittered histogram. */
    public static final String[] MODES = {"off", "on", "uniform", "normal"};
    /** The monitors' refresh rates of the lanes (Hz): console, lab machine, laptop, gamer. */
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
    private static final ColorRGBA[] COLORS = {
        new ColorRGBA(1f, 0.3f, 0.3f, 1f), new ColorRGBA(1f, 0.85f, 0.2f, 1f),
        new ColorRGBA(0.3f, 0.8f, 1f, 1f), new ColorRGBA(0.85f, 0.45f, 1f, 1f)};
    /** Levels of a histogram bar as one character, from none to the tallest. */
    private static final String LEVELS = " .:-=+*#%@";
    /** The histogram's metres to the millimetre: jitter spreads landings by centimetres. */
    private static final int HISTOGRAM_DECIMALS = 3;
    /** A lane's sphere, as drawn, against the followed sphere's radius. */
    private static final float SPHERE_FRACTION = 0.45f;
    /**
     * Lane i's landing mark rises (i + 1) times this (in followed-sphere radii): the tallest
     * reaches the top of a sphere landed there, below the label the scene sets above it.
     */
    private static final float MARK_STEP_RADII = 0.25f;
    /** A landing mark's width (in followed-sphere radii). */
    private static final float MARK_WIDTH_RADII = 0.12f;
    /** The lanes' trails' width (in followed-sphere radii) and length (frames: 20 s). */
    private static final float TRAIL_WIDTH_RADII = 0.12f;
    private static final int TRAIL_POINTS = 1200;
    /** Drawn in front of the world's spheres and trails (m toward the camera). */
    private static final float FRONT_Z = 0.5f;
    private static final int SPHERE_SAMPLES = 12;

    private final float radiusMetres;
    private DemoState demo;
    private DemoParticle followed;
    private final FrameRateRun[] runs = new FrameRateRun[RATES_HZ.length];
    private FrameRateRun fixed;
    private JitterHistogram histogram;
    /** The {@code rates} value: an index into {@link #MODES}. */
    private int mode;
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
    /** The views (null without a window). */
    private Geometry[] spheres;
    private Geometry[] marks;
    private Trail[] trails;
    private BitmapText[] legend;
    private TextMeasure measure;
    /** Per lane: whether its legend line was written for a landing (false: "flying"). */
    private final boolean[] legendLanded = new boolean[RATES_HZ.length];
    /** The legend's lines must be written again (a launch, the lanes on). */
    private boolean legendStale = true;
    private final StringBuilder line = new StringBuilder();
    private final ScreenRect legendArea = new ScreenRect();
    private float legendSize = HudLayout.SCENE_LABEL_SIZE;
    private boolean laidOut;

    /**
     * Create the lanes.
     *
     * @param radiusMetres the followed sphere's drawn radius (in metres, &gt;0): the lanes'
     *     spheres and marks are drawn in proportion
     */
    public RateLanes(float radiusMetres) {
        if (!(radiusMetres > 0f) || Float.isInfinite(radiusMetres)) {
            throw new IllegalArgumentException("sphere radius (m) must be finite and > 0, but"
                    + " was " + radiusMetres);
        }
        this.radiusMetres = radiusMetres;
    }

    /**
     * Fly the lanes beside one of the demo's spheres. Call from the demo's
     * {@code createScene()}, the part having been added with {@link DemoState#addPart}.
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
        for (int i = 0; i < RATES_HZ.length; ++i) {
            runs[i] = new FrameRateRun(integrator);
        }
        fixed = new FrameRateRun(integrator);
        histogram = new JitterHistogram(integrator, JitterHistogram.DEFAULT_RUNS);
        demo.getRun().waitForMotion(this::isFlying);
    }

    /**
     * Test whether the lanes are shown.
     *
     * @return true for any {@code rates} but {@code off}
     */
    public boolean isOn() {
        return mode != 0;
    }

    /**
     * Test whether a lane is still in the air: the scene's end waits for it.
     *
     * @return true while the lanes are on, started and one of them has not landed
     */
    public boolean isFlying() {
        if (mode == 0 || followed == null || needsStart) {
            return false;
        }
        for (int i = 0; i < runs.length; ++i) {
            if (!runs[i].hasLanded()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Return the {@code rates} value.
     *
     * @return an index into {@link #MODES}
     */
    public int getMode() {
        return mode;
    }

    /**
     * Return the jitter the histogram draws frames from.
     *
     * @return the distribution, or null without a histogram ({@code rates=off} or {@code on})
     */
    public FrameJitter.Distribution getJitter() {
        return mode < 2 ? null : distribution();
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
     * Access the fixed step's run (the cure), flown at 30 Hz: the same steps at every rate.
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

    /**
     * Return the legend's line of a lane as the scene shows it.
     *
     * @param lane the lane (0 to 3)
     * @return its text ("" without a window)
     */
    public String getLegendLine(int lane) {
        return legend == null ? "" : legend[lane].getText();
    }

    @Override
    public void attach(DemoState owner) {
        demo = owner;
    }

    /**
     * Declare {@code rates=off|on|uniform|normal} ({@code on}: the 30, 60, 144 and 240 Hz
     * lanes; {@code uniform}, {@code normal}: the lanes and the histogram of frame times
     * jittered by that distribution) and {@code jitter_ms} (its width, 0 to 8 ms), at the
     * next launch.
     *
     * @param parameters the demo's parameters (not null, modified)
     */
    @Override
    public void declareParameters(DemoParameters parameters) {
        parameters.add(DemoParameter.choice(PARAMETER, "rate lanes", MODES,
                0, DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    mode = Math.round(value);
                    needsStart = true;
                }));
        parameters.add(new DemoParameter(JITTER_WIDTH, "frame jitter", "ms", 0f,
                MAX_JITTER_MS, JITTER_STEP_MS, DEFAULT_JITTER_MS, 1,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    jitterMs = value;
                    needsStart = true;
                }));
    }

    /**
     * Move each lane through its monitor's frames due by the end of this step. At a launch,
     * fly the fixed step's run and the histogram first. Allocates nothing.
     *
     * @param stepSeconds h (in seconds, &gt;0)
     */
    @Override
    public void beforeStep(float stepSeconds) {
        if (followed == null || mode == 0) {
            return;
        }
        if (needsStart) {
            start();
        }
        demoSeconds += stepSeconds;
        for (int i = 0; i < RATES_HZ.length; ++i) {
            catchUp(i);
        }
    }

    /** Start the lanes again from the launch, at the demo's reset. */
    @Override
    public void onRestart() {
        needsStart = true;
        legendStale = true;
        if (trails != null) {
            for (int i = 0; i < trails.length; ++i) {
                trails[i].clear();
                trails[i].refresh();
            }
        }
    }

    @Override
    public void buildViews(Application app) {
        Material unshaded = new Material(app.getAssetManager(),
                "Common/MatDefs/Misc/Unshaded.j3md");
        BitmapFont font = HudFont.load(app.getAssetManager());
        measure = TextMeasure.of(font);
        Node scene = demo.getSceneNode();
        spheres = new Geometry[RATES_HZ.length];
        marks = new Geometry[RATES_HZ.length];
        trails = new Trail[RATES_HZ.length];
        legend = new BitmapText[RATES_HZ.length];
        Sphere sphereMesh = new Sphere(SPHERE_SAMPLES, SPHERE_SAMPLES,
                SPHERE_FRACTION * radiusMetres);
        float markWidth = MARK_WIDTH_RADII * radiusMetres;
        for (int i = 0; i < RATES_HZ.length; ++i) {
            String name = "rate lane " + (int) RATES_HZ[i] + " Hz";
            Material colored = unshaded.clone();
            colored.setColor("Color", COLORS[i]);
            spheres[i] = new Geometry(name, sphereMesh);
            spheres[i].setMaterial(colored);
            marks[i] = new Geometry(name + " landing mark", new Quad(markWidth,
                    (i + 1) * MARK_STEP_RADII * radiusMetres));
            marks[i].setMaterial(colored);
            trails[i] = new Trail(name + " trail", TRAIL_POINTS,
                    TRAIL_WIDTH_RADII * radiusMetres, COLORS[i], unshaded);
            trails[i].setDotsVisible(false);
            scene.attachChild(trails[i].getGeometry());
            scene.attachChild(trails[i].getDotGeometry());
            scene.attachChild(spheres[i]);
            scene.attachChild(marks[i]);
            legend[i] = new BitmapText(font);
            legend[i].setName(name + " legend");
            legend[i].setColor(COLORS[i]);
        }
        showViews(false);
    }

    /**
     * Keep the legend's room: the scene's top right corner, below the warning band.
     *
     * @param layout the HUD's layout (not null)
     */
    @Override
    public void layOut(HudLayout layout) {
        ScreenRect scene = layout.getScene();
        float top = scene.getTop();
        ScreenRect warning = layout.getWarning();
        if (warning.getHeight() > 0f && warning.getY() < top) {
            top = warning.getY();
        }
        float margin = layout.getMargin();
        legendSize = layout.getSceneLabelSize();
        legendArea.set(scene.getX() + margin, scene.getY(),
                Math.max(0f, scene.getWidth() - 2f * margin), Math.max(0f,
                        top - margin - scene.getY()));
        laidOut = true;
        legendStale = true;
    }

    /** Put the lanes' spheres, trails, marks and legend where the runs are. No allocation. */
    @Override
    public void afterFrame() {
        if (spheres == null) {
            return;
        }
        boolean shown = mode != 0 && followed != null && !needsStart;
        showViews(shown);
        if (!shown) {
            return;
        }
        for (int i = 0; i < RATES_HZ.length; ++i) {
            FrameRateRun run = runs[i];
            if (run.hasLanded()) {
                scratchPosition.set((float) run.getLanding().getX(), 0f,
                        run.getParticle().position.z);
            } else {
                scratchPosition.set(run.getParticle().position);
            }
            if (trails[i].size() == 0 || !trails[i].copyPoint(0, scratchVelocity)
                    .equals(scratchPosition)) {
                trails[i].add(scratchPosition);
                trails[i].refresh();
            }
            spheres[i].setLocalTranslation(scratchPosition.x, scratchPosition.y,
                    scratchPosition.z + FRONT_Z);
            marks[i].setLocalTranslation(scratchPosition.x
                    - 0.5f * MARK_WIDTH_RADII * radiusMetres, 0f, scratchPosition.z + FRONT_Z);
            marks[i].setCullHint(run.hasLanded() ? Spatial.CullHint.Inherit
                    : Spatial.CullHint.Always);
        }
        placeLegend();
    }

    /**
     * Append the lanes' lines (none while off): each lane's landing and miss against the fixed
     * step, the fixed step's landing, and with a jitter the histogram. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     */
    @Override
    public void writeHudLines(StringBuilder text) {
        if (followed == null || mode == 0 || needsStart) {
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
                appendMiss(text, run);
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
        if (mode >= 2) {
            appendHistogram(text);
        }
    }

    /** The part's own state: the launch's time, so a replayed step puts the lanes back. */
    @Override
    public StateRecord stateRecord() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                // nothing while off: the demo's ring entries, and so its hashes, stay its own
                return mode == 0 ? 0 : 3;
            }

            @Override
            public void writeState(StateSlab slab) {
                if (mode == 0) {
                    return;
                }
                slab.putBoolean(needsStart);
                slab.putDouble(demoSeconds);
            }

            @Override
            public void readState(StateSlab slab) {
                if (mode == 0) {
                    return;
                }
                boolean recordedNeedsStart = slab.getBoolean();
                double seconds = slab.getDouble();
                if (!recordedNeedsStart && followed != null) {
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
                    }
                    legendStale = true;
                }
                needsStart = recordedNeedsStart;
                demoSeconds = seconds;
            }
        };
    }

    /** At a launch: the lanes at the launch, the fixed step's landing, the histogram. */
    private void start() {
        needsStart = false;
        legendStale = true;
        restartLanes();
        float h = demo.getClock().getStepSeconds();
        fixed.start(launch, RATES_HZ[0], SimulationClock.Mode.FIXED_STEP, h);
        fixed.flyToLanding();
        if (mode >= 2) {
            // once per launch, here and only here: N runs of about a hundred steps each
            histogram.compute(launch, HISTOGRAM_RATE_HZ, distribution(),
                    jitterMs / MS_PER_SECOND, SEED, JitterHistogram.DEFAULT_RUNS, h);
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

    private FrameJitter.Distribution distribution() {
        return mode == 2 ? FrameJitter.Distribution.UNIFORM : FrameJitter.Distribution.NORMAL;
    }

    private void showViews(boolean shown) {
        Spatial.CullHint hint = shown ? Spatial.CullHint.Inherit : Spatial.CullHint.Always;
        for (int i = 0; i < spheres.length; ++i) {
            spheres[i].setCullHint(hint);
            trails[i].getGeometry().setCullHint(hint);
            if (!shown) {
                marks[i].setCullHint(hint);
            }
        }
        boolean legendShown = shown && laidOut && demo.getWindow().getHud() != null
                && !demo.getWindow().getHud().isHelpVisible();
        for (int i = 0; i < legend.length; ++i) {
            if (legendShown && legend[i].getParent() == null) {
                // the HUD's node comes and goes with the demo: the legend with it
                demo.getWindow().getHud().getNode().attachChild(legend[i]);
            }
            legend[i].setCullHint(legendShown ? Spatial.CullHint.Inherit
                    : Spatial.CullHint.Always);
        }
    }

    /**
     * Write a lane's legend line when it lands (once per launch; the text allocates then),
     * and stack the lines right-aligned in the scene's top right corner: 240 Hz on top.
     */
    private void placeLegend() {
        boolean changed = legendStale;
        for (int i = 0; i < RATES_HZ.length; ++i) {
            if (legendStale || legendLanded[i] != runs[i].hasLanded()) {
                legendLanded[i] = runs[i].hasLanded();
                line.setLength(0);
                line.append((int) RATES_HZ[i]).append(" Hz: ");
                if (legendLanded[i]) {
                    appendMiss(line, runs[i]);
                    line.append(" m");
                } else {
                    line.append("flying");
                }
                legend[i].setSize(legendSize);
                legend[i].setText(line.toString());
                changed = true;
            }
        }
        legendStale = false;
        if (!changed) {
            return;
        }
        float lineHeight = measure.lineHeight(legendSize);
        float right = legendArea.getRight();
        float y = legendArea.getTop();
        for (int i = RATES_HZ.length - 1; i >= 0; --i) {
            float width = measure.width(legend[i].getText(), legendSize);
            legend[i].setLocalTranslation(Math.max(legendArea.getX(), right - width), y, 0f);
            y -= lineHeight;
        }
    }

    /** "-0.17": a lane's landing less the fixed step's (m), signed. */
    private void appendMiss(StringBuilder text, FrameRateRun run) {
        double miss = run.getLanding().getX() - fixed.getLanding().getX();
        if (miss >= 0.0) {
            text.append('+');
        }
        TextFormat.appendFixed(text, miss, 2);
    }

    /** The histogram's two lines: its range and bars, and the fixed step's bar. */
    private void appendHistogram(StringBuilder text) {
        text.append("Jitter ").append(MODES[mode]).append(' ');
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
}

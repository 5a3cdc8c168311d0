package particlelab.app;

import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.logging.Level;
import java.util.logging.Logger;
import particlelab.accuracy.ReportConfig;
import particlelab.demo.DemoState;
import particlelab.files.SafeFiles;
import particlelab.physics.SimulationClock;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * The report's last section: the share of a 16.7 ms frame that each demo of the
 * {@link DemoCatalog} spends on its simulation, measured headless. Every demo runs in a real
 * jME application in the headless context (no window, no rendering), fixed-step mode, fed a
 * fixed frame time of 1/60 s: some frames of warm-up, then each measured frame's
 * {@link particlelab.demo.DemoWindow#advance} is timed with {@link System#nanoTime}. That is
 * the whole simulation side of a frame: the clock, the world's steps (integration, collisions, the
 * contact phases), the stability bookkeeping, the demo's own hooks, trails and moving the
 * views; not the HUD text (rebuilt every frame, after the steps) and not rendering. A scene
 * that is over (every particle landed) is restarted between two frames, outside the timing,
 * so every measured frame simulates; a full garbage collection runs before each demo's
 * warm-up. Writes {@value #CSV} and appends its section to {@code index.md}.
 */
public final class PhysicsShare {

    /** The section's CSV file, in the report's folder. */
    public static final String CSV = "physics_share.csv";
    /** Its header, fixed so other tools can read it. */
    public static final String HEADER = "demo,particles,frames,steps_per_frame,"
            + "physics_ms_mean,physics_ms_max,share_of_frame_mean,share_of_frame_max";
    /** Every file the section writes (index.md appended). */
    public static final List<String> FILES = Collections.singletonList(CSV);
    /** The section's heading in {@code index.md}. */
    public static final String HEADING = "## Physics share of a frame, per demo";
    /** The frame time fed to every demo, and the frame budget (s): 60 frames per second. */
    public static final float FRAME_SECONDS = 1f / 60f;

    private static final double BUDGET_MS = 1000.0 * FRAME_SECONDS;
    /** How long the jME thread may take to start or to run one demo's frames (s). */
    private static final long TIMEOUT_SECONDS = 120;
    /** The headless loop's own frame rate cap, so it does not spin a core meanwhile. */
    private static final int IDLE_FRAME_RATE = 60;

    private final int warmupFrames;
    private final int frames;
    private final List<Row> rows;

    /** One demo's measurement. */
    public static final class Row {
        private final String name;
        private final String title;
        private final int particles;
        private final double stepsPerFrame;
        private final double meanMillis;
        private final double maxMillis;

        Row(String name, String title, int particles, double stepsPerFrame, double meanMillis,
                double maxMillis) {
            this.name = name;
            this.title = title;
            this.particles = particles;
            this.stepsPerFrame = stepsPerFrame;
            this.meanMillis = meanMillis;
            this.maxMillis = maxMillis;
        }

        /** @return the demo's command-line name (not null) */
        public String name() {
            return name;
        }

        /**
         * @return the particles it simulates
         *     ({@link particlelab.demo.DemoRun#countSimulatedParticles})
         */
        public int particles() {
            return particles;
        }

        /** @return the world's steps per measured frame, on average */
        public double stepsPerFrame() {
            return stepsPerFrame;
        }

        /** @return the mean time of one frame's {@code advance} (in milliseconds) */
        public double meanMillis() {
            return meanMillis;
        }

        /** @return the longest time of one frame's {@code advance} (in milliseconds) */
        public double maxMillis() {
            return maxMillis;
        }
    }

    private PhysicsShare(int warmupFrames, int frames, List<Row> rows) {
        this.warmupFrames = warmupFrames;
        this.frames = frames;
        this.rows = Collections.unmodifiableList(rows);
    }

    /**
     * Measure every demo of the catalogue, headless.
     *
     * @param size the report's size: full 300 warm-up and 600 measured frames per demo, quick
     *     120 and 300, tiny 10 and 20 (not null)
     * @return the measurements, one row per demo in catalogue order
     * @throws IOException if the headless application fails to start or to run a demo
     */
    public static PhysicsShare run(ReportConfig.Size size) throws IOException {
        int warmup = size == ReportConfig.Size.FULL ? 300
                : size == ReportConfig.Size.QUICK ? 120 : 10;
        int measured = size == ReportConfig.Size.FULL ? 600
                : size == ReportConfig.Size.QUICK ? 300 : 20;
        List<DemoState> demos = DemoCatalog.createAll();
        // jME's start-up banner and its asset warnings would break into the report's output
        Logger engineLog = Logger.getLogger("com.jme3");
        Level engineLevel = engineLog.getLevel();
        engineLog.setLevel(Level.SEVERE);
        ParticleLabApp app = new ParticleLabApp(demos, 0, 0, null, 0f);
        try {
            AppSettings settings = ParticleLabApp.createSettings(0f);
            settings.setFrameRate(IDLE_FRAME_RATE);
            app.setSettings(settings);
            app.start(JmeContext.Type.Headless);
            awaitInitialised(app, demos);
            List<Row> rows = new ArrayList<>();
            for (int i = 0; i < demos.size(); ++i) {
                DemoState demo = demos.get(i);
                String name = DemoCatalog.entries().get(i).getName();
                rows.add(onJmeThread(app, () -> measure(name, demo, warmup, measured)));
            }
            return new PhysicsShare(warmup, measured, rows);
        } finally {
            app.stop(true);
            engineLog.setLevel(engineLevel);
        }
    }

    /**
     * Access the rows.
     *
     * @return one row per demo, in catalogue order (unmodifiable)
     */
    public List<Row> rows() {
        return rows;
    }

    /**
     * Write {@value #CSV} into the report's folder and append the section to its
     * {@code index.md}.
     *
     * @param folder the report's folder (not null)
     * @throws IOException if a file cannot be written
     */
    public void write(Path folder) throws IOException {
        StringBuilder csv = new StringBuilder(HEADER).append('\n');
        for (Row row : rows) {
            csv.append(row.name).append(',').append(row.particles).append(',').append(frames)
                    .append(',').append(fix(row.stepsPerFrame, 3)).append(',')
                    .append(fix(row.meanMillis, 5)).append(',').append(fix(row.maxMillis, 5))
                    .append(',').append(fix(row.meanMillis / BUDGET_MS, 6)).append(',')
                    .append(fix(row.maxMillis / BUDGET_MS, 6)).append('\n');
        }
        SafeFiles.write(folder.resolve(CSV), csv, false);
        SafeFiles.append(folder.resolve("index.md"), markdown());
    }

    private String markdown() {
        StringBuilder md = new StringBuilder();
        md.append(HEADING).append("\n\n");
        md.append("Every demo of the catalogue (").append(rows.size()).append("), run headless "
                + "(jME's headless context: no window, no rendering) in fixed-step mode with a "
                + "fixed frame time of 1/").append(Math.round(1.0 / FRAME_SECONDS))
                .append(" s: ").append(warmupFrames).append(" frames of warm-up, then ")
                .append(frames).append(" measured frames. Timed per frame with `System.nanoTime`:"
                + " the demo's whole `DemoWindow.advance(tpf)`, the simulation side of a frame "
                + "(the clock, the world's steps with integration, collisions and the contact "
                + "phases, the stability bookkeeping, the demo's own hooks, trails and moving "
                + "the views), so it is an upper bound on the physics alone; the HUD text "
                + "(rebuilt every frame, after the steps) and rendering are not in it. A scene "
                + "that is over (every particle landed) is restarted between frames, outside "
                + "the timing, and a full garbage collection runs before each demo. Share = "
                + "time / ")
                .append(fix(BUDGET_MS, 1)).append(" ms, the budget of a frame at ")
                .append(Math.round(1.0 / FRAME_SECONDS)).append(" frames per second. The "
                + "largest times include whatever the garbage collector or the JIT compiler "
                + "did during that frame. `").append(CSV).append("` has the same numbers, "
                + "header `").append(HEADER).append("`.\n\n");
        md.append("| demo | particles | steps per frame | physics ms per frame: mean | max "
                + "| share of ").append(fix(BUDGET_MS, 1)).append(" ms: mean | max |\n"
                + "|---|---|---|---|---|---|---|\n");
        Row heaviest = null;
        Row longest = null;
        boolean anyWithoutParticles = false;
        for (Row row : rows) {
            md.append("| ").append(row.title).append(" (`").append(row.name).append("`) | ")
                    .append(row.particles).append(" | ").append(fix(row.stepsPerFrame, 2))
                    .append(" | ").append(fix(row.meanMillis, 4)).append(" | ")
                    .append(fix(row.maxMillis, 3)).append(" | ")
                    .append(percent(row.meanMillis / BUDGET_MS)).append(" | ")
                    .append(percent(row.maxMillis / BUDGET_MS)).append(" |\n");
            if (heaviest == null || row.meanMillis > heaviest.meanMillis) {
                heaviest = row;
            }
            if (longest == null || row.maxMillis > longest.maxMillis) {
                longest = row;
            }
            anyWithoutParticles |= row.particles == 0;
        }
        if (heaviest != null) {
            md.append("\nThe heaviest demo on average is ").append(heaviest.title).append(" (")
                    .append(heaviest.particles).append(" particles): ")
                    .append(fix(heaviest.meanMillis, 3)).append(" ms, ")
                    .append(percent(heaviest.meanMillis / BUDGET_MS)).append(" of the frame; "
                    + "the longest single frame, ").append(fix(longest.maxMillis, 2))
                    .append(" ms (").append(percent(longest.maxMillis / BUDGET_MS))
                    .append("), was ").append(longest.title).append("'s.");
            if (anyWithoutParticles) {
                md.append(" 0 particles: the demo moves rigid bodies of its own, outside the "
                        + "world.");
            }
            md.append("\n\n");
        }
        return md.toString();
    }

    /** Run a demo's frames on the jME thread; returns its row. */
    private static Row measure(String name, DemoState demo, int warmup, int measured) {
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        demo.restart();
        // the garbage of whatever ran before (the benchmarks) is not this demo's
        System.gc();
        for (int frame = 0; frame < warmup; ++frame) {
            restartIfOver(demo);
            demo.getWindow().advance(FRAME_SECONDS);
        }
        StepCounter counter = new StepCounter();
        demo.getWorld().addStepListener(counter);
        long totalNanos = 0;
        long longestNanos = 0;
        for (int frame = 0; frame < measured; ++frame) {
            restartIfOver(demo);
            long start = System.nanoTime();
            demo.getWindow().advance(FRAME_SECONDS);
            long elapsed = System.nanoTime() - start;
            totalNanos += elapsed;
            longestNanos = Math.max(longestNanos, elapsed);
        }
        demo.getWorld().removeStepListener(counter);
        return new Row(name, demo.getTitle(), demo.getRun().countSimulatedParticles(),
                (double) counter.steps / measured, totalNanos / 1e6 / measured,
                longestNanos / 1e6);
    }

    /** Counts a world's steps (its step count restarts with the scene). */
    private static final class StepCounter implements StepListener {
        private long steps;

        @Override
        public void afterStep(World world, float stepSeconds) {
            ++steps;
        }
    }

    private static void restartIfOver(DemoState demo) {
        if (demo.getRun().isSceneOver()) {
            demo.restart();
        }
    }

    private static void awaitInitialised(ParticleLabApp app, List<DemoState> demos)
            throws IOException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_SECONDS);
        while (!onJmeThread(app, () -> allInitialised(demos))) {
            if (System.nanoTime() > deadline || app.getFailure() != null) {
                throw new IOException("the headless application did not start"
                        + (app.getFailure() == null ? " in time" : ": " + app.getFailure()));
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException interrupted) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while the demos started", interrupted);
            }
        }
    }

    private static boolean allInitialised(List<DemoState> demos) {
        for (DemoState demo : demos) {
            if (!demo.isInitialized()) {
                return false;
            }
        }
        return true;
    }

    private static <T> T onJmeThread(ParticleLabApp app, Callable<T> task)
            throws IOException {
        try {
            return app.enqueue(task).get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while measuring the demos", interrupted);
        } catch (ExecutionException | TimeoutException failure) {
            throw new IOException("the headless application failed: " + failure.getMessage(),
                    failure);
        }
    }

    private static String percent(double fraction) {
        return String.format(Locale.ROOT, fraction < 0.01 ? "%.3f %%" : "%.1f %%",
                100.0 * fraction);
    }

    private static String fix(double value, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", value);
    }
}

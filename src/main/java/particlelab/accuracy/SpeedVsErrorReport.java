package particlelab.accuracy;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.XYChart;
import particlelab.files.SafeFiles;
import particlelab.physics.SimulationClock;
import particlelab.reference.CostMeter;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.Scheme;


/**
 * The speed-vs-error report: runs every study and writes {@code index.md}, CSV files and PNG
 * plots into one folder. See {@link #FILES} for what it promises.
 */
public final class SpeedVsErrorReport {

    /** Header of {@code orders.csv}, fixed so other tools can read it. */
    public static final String ORDERS_HEADER = "case,stepper,measured_order,theoretical_order";
    /** Header of {@code stability.csv}, fixed so other tools can read it. */
    public static final String STABILITY_HEADER = "stepper,b_over_m,max_stable_h,theory_h";
    /** Header of {@code work-precision.csv}. */
    public static final String WORK_PRECISION_HEADER =
            "case,stepper,h_s,steps,error_m,ns_per_step,ns_per_simulated_second";
    /** Header of {@code aiming.csv}. */
    public static final String AIMING_HEADER =
            "sweep,formula,h_s,b_over_m,vy_m_per_s,miss_m,shots";
    /** Header of {@code hitches.csv}. */
    public static final String HITCHES_HEADER = "b_over_m,mode,hitch_s,landing_x_m,"
            + "exact_range_m,landing_error_m,finite,landed,dropped_s,steps";
    /** The main plot: the work-precision charts of every case on one image. */
    public static final String MAIN_PLOT = "work-precision.png";

    /** Every file the report writes, relative to its folder. */
    public static final List<String> FILES;

    static {
        List<String> files = new ArrayList<>(Arrays.asList("index.md", "orders.csv",
                "stability.csv", "benchmarks.csv", "work-precision.csv", "aiming.csv",
                "hitches.csv", MAIN_PLOT, "stability.png", "bulk.png", MixTargets.PLOT,
                "aiming.png"));
        for (CanonicalCase scene : CanonicalCase.all()) {
            files.add(workPrecisionPlot(scene));
        }
        files.addAll(CollisionSection.FILES);
        files.addAll(RotationSection.FILES);
        files.addAll(EnergySection.FILES);
        FILES = Collections.unmodifiableList(files);
    }

    /** Target: the batch form at least this many times faster than the lecture style. */
    static final double TARGET_VS_LECTURE = 3.0;
    /** Target: the batch form at most this many times slower than the primitive loop. */
    static final double TARGET_VS_PRIMITIVE = 1.5;
    /** The demos' step h (in seconds): the clock's default, 1/60 s, exactly as a double. */
    static final double DEMO_STEP_SECONDS =
            1.0 / Math.round(1.0 / SimulationClock.DEFAULT_STEP_SECONDS);

    private final ReportConfig config;
    private final Path folder;
    private final Path jmhResults;

    /**
     * Prepare a report.
     *
     * @param config the sweep's size (not null)
     * @param folder where to write (not null; created if missing)
     * @param jmhResults a {@code benchmarks.csv} written by the JMH runner to use instead of
     *     the report's own timing loop, or null to time in-process
     */
    public SpeedVsErrorReport(ReportConfig config, Path folder, Path jmhResults) {
        if (config == null || folder == null) {
            throw new IllegalArgumentException("config and folder must not be null, but were "
                    + config + " and " + folder);
        }
        this.config = config;
        this.folder = folder;
        this.jmhResults = jmhResults;
    }

    /**
     * Run every study and write every file.
     *
     * @param progressOut where to draw the progress bar (not null)
     * @param interactive true if progressOut is a terminal (the bar redraws one line)
     * @throws IOException if a file cannot be written or the JMH results cannot be read
     */
    public void write(PrintStream progressOut, boolean interactive) throws IOException {
        Files.createDirectories(folder);
        // The machine is read first, so its load average is the one at the start.
        HostInfo host = HostInfo.now();
        BenchmarkTable jmh = jmhResults == null ? null : BenchmarkTable.read(jmhResults);
        CostMeter meter = new CostMeter(config.budget());
        ProgressBar progress = new ProgressBar(progressOut, WorkPrecisionStudy.units()
                + StabilityStudy.units(config)
                + (jmh == null ? BenchmarkStudy.units(config) : 0) + 4, interactive);
        // Benchmarks first, while the JIT has seen only their scene (gravity + linear drag):
        // later sweeps through every force type make the integrator's force calls megamorphic.
        BenchmarkTable benchmarks = jmh != null ? jmh : BenchmarkStudy.run(config, meter, progress);
        progress.phase("benchmarks: ratios side by side, jME's ParticleEmitter");
        StringBuilder spreads = new StringBuilder();
        SpeedSpreads.append(spreads, config, meter);
        progress.advance();
        WorkPrecisionStudy precision = WorkPrecisionStudy.run(config, meter, progress);
        StabilityStudy stability = StabilityStudy.run(config, progress);
        progress.phase("aiming and frame hitches");
        AimingStudy aiming = AimingStudy.run(config);
        progress.advance();
        HitchStudy hitches = HitchStudy.run();
        progress.advance();
        progress.phase("writing files and plots");
        writeCsvFiles(precision, stability, benchmarks, aiming, hitches);
        writePlots(precision, stability, benchmarks, aiming);
        writeIndex(host, precision, stability, benchmarks, aiming, hitches, jmh != null,
                spreads);
        CollisionSection.write(config, meter, folder);
        RotationSection.write(config, meter, folder);
        EnergySection.write(folder);
        progress.advance();
        progress.finish();
    }

    /**
     * Return the folder written to.
     *
     * @return the folder (not null)
     */
    public Path folder() {
        return folder;
    }

    static String workPrecisionPlot(CanonicalCase scene) {
        return "work-precision-" + scene.id() + ".png";
    }

    // ---- CSV ----------------------------------------------------------------------------------

    private void writeCsvFiles(WorkPrecisionStudy precision, StabilityStudy stability,
            BenchmarkTable benchmarks, AimingStudy aiming, HitchStudy hitches)
            throws IOException {
        StringBuilder text = new StringBuilder(WORK_PRECISION_HEADER).append('\n');
        for (WorkPrecisionStudy.Point p : precision.points) {
            text.append(p.scene.id()).append(',').append(p.scheme.id()).append(',')
                    .append(num(p.stepSeconds)).append(',').append(p.steps).append(',')
                    .append(num(p.errorMetres)).append(',').append(num(p.nanosPerStep))
                    .append(',').append(num(p.nanosPerSimulatedSecond())).append('\n');
        }
        writeText("work-precision.csv", text);

        text = new StringBuilder(ORDERS_HEADER).append('\n');
        for (WorkPrecisionStudy.Order o : precision.orders) {
            text.append(o.scene.id()).append(',').append(o.scheme.id()).append(',')
                    .append(num(o.measured)).append(',').append(num(o.theoretical)).append('\n');
        }
        writeText("orders.csv", text);

        text = new StringBuilder(STABILITY_HEADER).append('\n');
        for (StabilityStudy.Limit l : stability.limits) {
            text.append(l.scheme.id()).append(',').append(num(l.linearRate)).append(',')
                    .append(num(l.measuredSeconds)).append(',').append(num(l.theorySeconds))
                    .append('\n');
        }
        writeText("stability.csv", text);

        benchmarks.write(folder.resolve("benchmarks.csv"), false);

        text = new StringBuilder(AIMING_HEADER).append('\n');
        for (AimingStudy.Shot s : aiming.shots) {
            text.append(s.sweep).append(',').append(s.formula).append(',')
                    .append(num(s.stepSeconds)).append(',').append(num(s.linearRate)).append(',')
                    .append(num(s.vy)).append(',').append(num(s.missMetres)).append(',')
                    .append(s.shots).append('\n');
        }
        writeText("aiming.csv", text);

        text = new StringBuilder(HITCHES_HEADER).append('\n');
        for (HitchStudy.Run r : hitches.runs) {
            text.append(num(r.linearRate)).append(',').append(modeName(r.mode)).append(',')
                    .append(num(r.hitchSeconds)).append(',').append(num(r.landingX)).append(',')
                    .append(num(r.exactRange)).append(',').append(num(r.landingError()))
                    .append(',').append(r.finite).append(',').append(r.landed).append(',')
                    .append(num(r.droppedSeconds)).append(',').append(r.steps).append('\n');
        }
        writeText("hitches.csv", text);
    }

    // ---- plots --------------------------------------------------------------------------------

    /**
     * One case's work-precision chart: a line per stepper through its points (median cost per
     * simulated second, error), and through each point a horizontal bar from the cost of the
     * cheapest round to that of the dearest (no legend entry, the line's colour).
     *
     * @param scene the case (not null)
     * @param points every case's points (not null, not modified)
     * @return a new chart
     */
    static XYChart workPrecisionChart(CanonicalCase scene, List<WorkPrecisionStudy.Point> points) {
        XYChart chart = Charts.create("Work vs precision: " + scene.label(),
                "cost (ns per simulated second)", "position error after "
                        + (int) CanonicalCase.DURATION_SECONDS + " s (m)", true, true);
        for (Scheme scheme : Scheme.values()) {
            List<WorkPrecisionStudy.Point> line = new ArrayList<>();
            for (WorkPrecisionStudy.Point p : points) {
                if (p.scene == scene && p.scheme == scheme) {
                    line.add(p);
                }
            }
            if (line.isEmpty()) {
                continue;
            }
            double[] cost = new double[line.size()];
            double[] error = Charts.floored(errors(line));
            for (int i = 0; i < cost.length; ++i) {
                cost[i] = line.get(i).nanosPerSimulatedSecond();
            }
            Charts.line(chart, scheme.shortLabel(), cost, error, scheme.ordinal());
            for (int i = 0; i < cost.length; ++i) {
                WorkPrecisionStudy.Point p = line.get(i);
                Charts.horizontalBar(chart, scheme.shortLabel() + " spread " + i,
                        p.minNanosPerSimulatedSecond(), p.maxNanosPerSimulatedSecond(),
                        error[i], scheme.ordinal());
            }
        }
        return chart;
    }

    private static double[] errors(List<WorkPrecisionStudy.Point> line) {
        double[] error = new double[line.size()];
        for (int i = 0; i < error.length; ++i) {
            error[i] = line.get(i).errorMetres;
        }
        return error;
    }

    private void writePlots(WorkPrecisionStudy precision, StabilityStudy stability,
            BenchmarkTable benchmarks, AimingStudy aiming) throws IOException {
        List<XYChart> grid = new ArrayList<>();
        for (CanonicalCase scene : CanonicalCase.all()) {
            XYChart chart = workPrecisionChart(scene, precision.points);
            Charts.save(chart, folder.resolve(workPrecisionPlot(scene)));
            grid.add(chart);
        }
        Charts.saveGrid(grid, 2, 3, folder.resolve(MAIN_PLOT));

        XYChart map = Charts.create("Stability: largest stable step, linear drag and a spring",
                "b/m (1/s)", "largest stable h (s)", true, true);
        map.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNE);
        map.getStyler().setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Vertical);
        double[] rates = config.linearRates();
        for (Scheme scheme : Scheme.values()) {
            if (Double.isInfinite(scheme.stabilityFactor())) {
                continue;
            }
            double[] measured = new double[rates.length];
            for (StabilityStudy.Limit l : stability.limits) {
                if (l.scheme == scheme) {
                    measured[indexOf(rates, l.linearRate)] = l.measuredSeconds;
                }
            }
            Charts.markers(map, scheme.shortLabel() + " (measured)", rates, measured,
                    scheme.ordinal());
        }
        double[] factors = {2.0, Scheme.RUNGE_KUTTA_4.stabilityFactor(), 4.0};
        String[] names = {"theory 2m/b (both Eulers, midpoint)", "theory 2.785m/b (RK4)",
            "theory 4m/b (games' Verlet)"};
        int[] styles = {Scheme.FORWARD_EULER.ordinal(), Scheme.RUNGE_KUTTA_4.ordinal(),
            Scheme.VELOCITY_VERLET.ordinal()};
        for (int f = 0; f < factors.length; ++f) {
            double[] theory = new double[rates.length];
            for (int i = 0; i < rates.length; ++i) {
                theory[i] = factors[f] / rates[i];
            }
            Charts.dashed(map, names[f], rates, theory, styles[f]);
        }
        double[] springMeasured = new double[rates.length];
        double[] springTheory = new double[rates.length];
        for (StabilityStudy.Limit l : stability.springLimits) {
            springMeasured[indexOf(rates, l.linearRate)] = l.measuredSeconds;
            springTheory[indexOf(rates, l.linearRate)] = l.theorySeconds;
        }
        String spring = "SIE + spring k/m = " + num(StabilityMap.SPRING_STIFFNESS);
        Charts.markers(map, spring + " (measured)", rates, springMeasured, Scheme.EXACT.ordinal());
        Charts.dashed(map, "theory 4/(b/m + sqrt((b/m)^2 + 4k/m))", rates, springTheory,
                Scheme.EXACT.ordinal());
        Charts.save(map, folder.resolve("stability.png"));

        XYChart bulk = Charts.create("Cost per particle-step as N grows (gravity + linear drag)",
                "particles N", "ns per particle-step", true, true);
        // four long names: one a line below the plot, so none is cut off at the edges
        bulk.getStyler().setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Vertical);
        String[] kinds = {BenchmarkTable.BULK_LECTURE, BenchmarkTable.BULK_OBJECTS,
            BenchmarkTable.BULK_BATCH, BenchmarkTable.BULK_PRIMITIVE};
        String[] labels = {"lecture style (new Vector3f each step)",
            "shared integrator, Particle objects", "shared integrator, packed batch",
            "hand-written primitive loop"};
        int[] counts = bulkCounts(benchmarks);
        for (int k = 0; k < kinds.length; ++k) {
            double[] n = new double[counts.length];
            double[] ns = new double[counts.length];
            for (int i = 0; i < counts.length; ++i) {
                n[i] = counts[i];
                BenchmarkTable.Row row = benchmarks.find(BenchmarkTable.bulkName(kinds[k],
                        counts[i]));
                ns[i] = row == null ? Charts.LOG_FLOOR : row.nanosPerParticleStep();
            }
            if (counts.length > 0) {
                Charts.line(bulk, labels[k], n, ns, k);
            }
        }
        Charts.save(bulk, folder.resolve("bulk.png"));
        MixTargets.writePlot(benchmarks, folder);

        List<XYChart> aimCharts = new ArrayList<>();
        XYChart byStep = Charts.create("Level shot S = " + num(AimingStudy.DISTANCE)
                + " m, vx = " + num(AimingStudy.VX) + " m/s: miss against h",
                "step h (s)", "|miss| (m)", true, true);
        XYChart byDrag = Charts.create("Miss against linear drag (h = "
                + stepText(AimingStudy.DRAG_SWEEP_STEP) + ")", "b/m (1/s)",
                "miss: landing x - S (m)", false, false);
        String[] formulas = {AimingStudy.LECTURE, AimingStudy.DISCRETE, AimingStudy.ITERATIVE};
        String[] formulaLabels = {"lecture vy = gS/(2vx)", "discrete vy = gS/(2vx) + gh/2",
            "iterative (tolerance " + AimingStudy.TOLERANCE + " m)"};
        for (int f = 0; f < formulas.length; ++f) {
            aimingLine(byStep, aiming, AimingStudy.STEP_SWEEP, formulas[f], formulaLabels[f], f,
                    true);
            aimingLine(byDrag, aiming, AimingStudy.DRAG_SWEEP, formulas[f], formulaLabels[f], f,
                    false);
        }
        // log axes label decades only: span three of them
        byStep.getStyler().setXAxisMin(1e-3);
        byStep.getStyler().setXAxisMax(0.1);
        aimCharts.add(byStep);
        aimCharts.add(byDrag);
        Charts.saveGrid(aimCharts, 1, 2, folder.resolve("aiming.png"));
    }

    private static void aimingLine(XYChart chart, AimingStudy aiming, String sweep,
            String formula, String label, int style, boolean byStep) {
        List<AimingStudy.Shot> shots = new ArrayList<>();
        for (AimingStudy.Shot s : aiming.shots) {
            // out-of-reach targets have no miss to plot
            if (s.sweep.equals(sweep) && s.formula.equals(formula)
                    && !Double.isNaN(s.missMetres)) {
                shots.add(s);
            }
        }
        double[] x = new double[shots.size()];
        double[] y = new double[shots.size()];
        for (int i = 0; i < x.length; ++i) {
            x[i] = byStep ? shots.get(i).stepSeconds : shots.get(i).linearRate;
            y[i] = shots.get(i).missMetres;
        }
        Charts.line(chart, label, x, byStep ? Charts.floored(y) : y, style);
    }

    // ---- index.md -----------------------------------------------------------------------------

    private void writeIndex(HostInfo host, WorkPrecisionStudy precision, StabilityStudy stability,
            BenchmarkTable benchmarks, AimingStudy aiming, HitchStudy hitches, boolean fromJmh,
            CharSequence spreads) throws IOException {
        StringBuilder md = new StringBuilder();
        md.append("# Speed against error\n\n");
        md.append("Particle Lab's shared Euler integrator beside reference steppers: how far "
                + "each is off, what it costs, when it blows up, and what that means for the "
                + "demos. Regenerate with `gradle report` (or `particle-lab report`).\n\n");
        md.append("## The host\n\n");
        md.append("Every time and ratio below was measured on this machine; on another "
                + "processor the ratios differ, so quote them with it.\n\n");
        md.append(host.block()).append('\n');
        md.append("## How this was measured\n\n");
        md.append("- Size: **").append(config.size().name().toLowerCase(Locale.ROOT))
                .append("**.\n");
        md.append("- Every case launches from the origin at ").append(launchText())
                .append(" m/s under g = ").append(num(CanonicalCase.G)).append(" m/s² on ")
                .append(num(CanonicalCase.all().get(0).forces().getMassKg()))
                .append(" kg and flies ").append(num(CanonicalCase.DURATION_SECONDS))
                .append(" s. Error = distance from the reference position at that time: the "
                + "closed form for gravity and linear drag, RK4 at h = 1/")
                .append(ClosedForms.REFERENCE_STEPS_PER_SECOND)
                .append(" s otherwise (its own error is below 1e-11 m).\n");
        md.append("- The reference steppers run in double precision on the same force laws. "
                + "Semi-implicit Euler is the shared `ParticleIntegrator` itself, run in float "
                + "on jME vectors exactly as the demos run it; its line goes on to smaller h "
                + "to show where float round-off stops the error from falling.\n");
        md.append("- Costs are timed in this one JVM by ").append(CostMeter.clockName())
                .append(", each after a warm-up, over ").append(config.rounds())
                .append(" rounds of at least ").append(config.roundNanos() / 1_000_000)
                .append(" ms: the tables give the median and, where it says, min–max over "
                + "the rounds; read them as ratios to each other, not as absolute numbers. "
                + "The ratios the targets are judged by are taken within rotating rounds "
                + "(\"Side by side, with spreads\"). Cost per simulated second = cost per "
                + "step / h.\n");
        if (fromJmh) {
            md.append("- `benchmarks.csv` comes from JMH (`gradle jmh`: forked JVM, warm-up "
                    + "and measured iterations, gc profiler for bytes), read from `")
                    .append(jmhResults).append("`.\n");
        } else {
            md.append("- `benchmarks.csv` comes from the same in-process timing loop; bytes "
                    + "per step from `ThreadMXBean.getThreadAllocatedBytes` around the measured "
                    + "rounds. For JMH numbers run `gradle jmh` and pass its CSV with "
                    + "`--jmh build/reports/jmh/benchmarks.csv`.\n");
        }
        md.append('\n');

        appendWorkPrecision(md, precision);
        appendOrders(md, precision);
        appendStability(md, stability);
        appendBenchmarks(md, benchmarks, fromJmh, spreads);
        appendAiming(md, aiming);
        appendHitches(md, hitches);
        appendRecommendations(md, precision, stability, benchmarks, aiming, hitches);
        writeText("index.md", md);
    }

    private void appendWorkPrecision(StringBuilder md, WorkPrecisionStudy precision) {
        md.append("## Work against precision\n\n");
        md.append("![work-precision plots of every case](").append(MAIN_PLOT).append(")\n\n");
        md.append("How to read it: each line is one stepper, each point one step size h, "
                + "from ").append(stepText(config.steps()[0])).append(" (left, cheap, "
                + "inaccurate) to ").append(stepText(config.steps()[config.steps().length - 1]))
                .append(" (right); the thin horizontal bar through a point spans its cost "
                + "from the cheapest to the dearest of the meter's rounds. Lower is more "
                + "accurate, further left is cheaper; the best "
                + "method for a given error budget is the line furthest down-left. The slope is "
                + "minus the order: a first-order method gains one digit of accuracy for ten "
                + "times the work, RK4 four. Points at the bottom are exact up to round-off (an "
                + "error of exactly 0 is drawn at ").append(sci(Charts.LOG_FLOOR))
                .append(" m, where the log axis ends). One chart per case: ");
        for (CanonicalCase scene : CanonicalCase.all()) {
            md.append('[').append(scene.id()).append("](").append(workPrecisionPlot(scene))
                    .append(") ");
        }
        md.append("\n\nPosition error after ").append(num(CanonicalCase.DURATION_SECONDS))
                .append(" s at the demos' h = ").append(stepText(DEMO_STEP_SECONDS))
                .append(" (m):\n\n");
        md.append("| case | reference |");
        for (Scheme scheme : Scheme.values()) {
            md.append(' ').append(scheme.label()).append(" |");
        }
        md.append("\n|---|---|");
        for (int i = 0; i < Scheme.values().length; ++i) {
            md.append("---|");
        }
        md.append('\n');
        for (CanonicalCase scene : CanonicalCase.all()) {
            md.append("| ").append(scene.label()).append(" | ").append(scene.referenceKind())
                    .append(" |");
            for (Scheme scheme : Scheme.values()) {
                WorkPrecisionStudy.Point p = point(precision, scene, scheme,
                        DEMO_STEP_SECONDS);
                md.append(' ').append(p == null ? "—" : sci(p.errorMetres)).append(" |");
            }
            md.append('\n');
        }
        CanonicalCase timed = benchmarkCase();
        if (timed != null) {
            md.append("\nCost of one step on one particle (ns, case `").append(timed.id())
                    .append("`): ");
            for (Scheme scheme : Scheme.values()) {
                WorkPrecisionStudy.Point p = point(precision, timed, scheme,
                        WorkPrecisionStudy.TIMING_STEP_SECONDS);
                md.append(scheme.id()).append(' ').append(fix(p.nanosPerStep, 1)).append("; ");
            }
        }
        md.append("full table in `work-precision.csv`. These are timed after the "
                + "benchmarks, with every force type seen, so the shared integrator's calls "
                + "to its forces are no longer inlined: compare the benchmark table for a "
                + "single scene.\n\n");
    }

    private void appendOrders(StringBuilder md, WorkPrecisionStudy precision) {
        md.append("## Convergence orders\n\n");
        md.append("Measured order = least-squares slope of log(error) against log(h) over "
                + "h = ").append(stepText(config.steps()[0])).append(" … ")
                .append(stepText(config.steps()[config.steps().length - 1]))
                .append(", from the largest h down while the error is above ")
                .append(sci(WorkPrecisionStudy.ROUND_OFF_FLOOR)).append(" m and still "
                + "falls at least ").append(num(OrderFit.MIN_DECREASE))
                .append("× per halving of h (past that it is round-off). "
                + "Theory in brackets; ∞ means exact for that case: only round-off remains, "
                + "shown as the largest error. "
                + "Games' velocity Verlet is second order only for forces of position alone: "
                + "drag makes it first order.\n\n");
        md.append("| case |");
        for (Scheme scheme : Scheme.values()) {
            md.append(' ').append(scheme.label()).append(" |");
        }
        md.append("\n|---|");
        for (int i = 0; i < Scheme.values().length; ++i) {
            md.append("---|");
        }
        md.append('\n');
        for (CanonicalCase scene : CanonicalCase.all()) {
            md.append("| ").append(scene.label()).append(" |");
            for (Scheme scheme : Scheme.values()) {
                WorkPrecisionStudy.Order o = order(precision, scene, scheme);
                if (o == null) {
                    md.append(" — |");
                } else if (Double.isNaN(o.measured)) {
                    md.append(" round-off (≤ ").append(sci(o.largestErrorMetres)).append(" m) [")
                            .append(orderText(o.theoretical)).append("] |");
                } else {
                    md.append(' ').append(fix(o.measured, 2)).append(" [")
                            .append(orderText(o.theoretical)).append("] |");
                }
            }
            md.append('\n');
        }
        md.append("\nIn `orders.csv`, `NaN` marks a measured order lost in round-off and "
                + "`Infinity` a method exact for that case.\n\n");
    }

    private void appendStability(StringBuilder md, StabilityStudy stability) {
        md.append("## Stability map\n\n");
        md.append("![largest stable step against b/m](stability.png)\n\n");
        md.append("Largest stable h under gravity + linear drag, found by bisection (a trial "
                + "takes ").append(StabilityMap.TRIAL_STEPS).append(" steps from 10 m/s off "
                + "the terminal velocity and is stable if that distance did not grow), beside "
                + "theory. Measured / theory:\n\n");
        double[] rates = config.linearRates();
        md.append("| stepper | theory |");
        for (double rate : rates) {
            md.append(" b/m = ").append(num(rate)).append(" |");
        }
        md.append("\n|---|---|");
        for (int i = 0; i < rates.length; ++i) {
            md.append("---|");
        }
        md.append('\n');
        for (Scheme scheme : Scheme.values()) {
            md.append("| ").append(scheme.label()).append(" | ")
                    .append(Double.isInfinite(scheme.stabilityFactor()) ? "any h"
                            : fix(scheme.stabilityFactor(), 6) + "·m/b").append(" |");
            for (StabilityStudy.Limit l : stability.limits) {
                if (l.scheme != scheme) {
                    continue;
                }
                if (Double.isInfinite(l.measuredSeconds)) {
                    md.append(" stable to ").append(num(StabilityMap.CEILING_FACTOR))
                            .append("·m/b |");
                } else {
                    md.append(' ').append(sig(l.measuredSeconds)).append(" s (")
                            .append(fix(l.measuredSeconds / l.theorySeconds, 5)).append(") |");
                }
            }
            md.append('\n');
        }
        md.append("| ").append(Scheme.SEMI_IMPLICIT_EULER.label()).append(" + spring k/m = ")
                .append(num(StabilityMap.SPRING_STIFFNESS)).append(" /s² | 4/(b/m + sqrt((b/m)²"
                + " + 4k/m)) |");
        for (StabilityStudy.Limit l : stability.springLimits) {
            md.append(' ').append(sig(l.measuredSeconds)).append(" s (")
                    .append(fix(l.measuredSeconds / l.theorySeconds, 5)).append(") |");
        }
        md.append("\n\nThe spring row is the damped oscillator x'' = −ω²x − (b/m)·x' stepped by the"
                + " shared integrator with a `Spring` (a trial: ").append(StabilityMap.TRIAL_STEPS)
                .append(" steps from 1 m off rest; stable if the swing sqrt(ω²x² + v²) did not "
                + "grow): 2/ω = ").append(sig(2 / Math.sqrt(StabilityMap.SPRING_STIFFNESS)))
                .append(" s without drag, 2m/b with strong drag (docs/numerics.md derives it). "
                + "It is not in `stability.csv`, whose rows stay one per stepper and b/m.\n");
        md.append("\nIn `stability.csv`, `Infinity` means stable at every step tried, up to ")
                .append(num(StabilityMap.CEILING_FACTOR)).append("·m/b.\n\n");
    }

    private void appendBenchmarks(StringBuilder md, BenchmarkTable benchmarks,
            boolean fromJmh, CharSequence spreads) {
        md.append("## Benchmarks\n\n");
        BenchmarkTable.Row lecture = benchmarks.find(BenchmarkTable.LECTURE_STYLE);
        BenchmarkTable.Row primitive = benchmarks.find(BenchmarkTable.PRIMITIVE_LOOP);
        md.append("One particle, gravity + linear drag b/m = ")
                .append(num(OneParticleScene.LINEAR_RATE)).append(" /s, h = ")
                .append(stepText(OneParticleScene.STEP_SECONDS)).append(", relaunched every ")
                .append(OneParticleScene.STEPS_PER_LAUNCH).append(" steps. Consecutive "
                + "steps of one particle wait for each other, so this is the latency of a "
                + "step. The reference steppers work in double precision on plain arrays; the "
                + "lecture style and the primitive loop in float.\n\n");
        md.append("| benchmark | ns per particle-step | min–max over rounds | bytes per step "
                + "| against lecture style | against primitive loop |\n"
                + "|---|---|---|---|---|---|\n");
        for (BenchmarkTable.Row row : benchmarks.rows()) {
            if (row.name().startsWith("bulk/")) {
                continue;
            }
            md.append("| ").append(row.name()).append(" | ")
                    .append(fix(row.nanosPerParticleStep(), 2)).append(" | ")
                    .append(range(row, 2)).append(" | ")
                    .append(fix(row.bytesPerStep(), 1)).append(" | ")
                    .append(ratio(row, lecture)).append(" | ").append(ratio(row, primitive))
                    .append(" |\n");
        }
        md.append("\n### Many particles\n\n![cost per particle-step against N](bulk.png)\n\n");
        md.append("The same scene for N particles, one step of all of them per call, each "
                + "storage relaunched every ").append(BulkScene.STEPS_PER_LAUNCH)
                .append(" of its steps. Targets (this run, side by side): the shared integrator "
                + "allocates 0 bytes per step, is at least ").append(num(TARGET_VS_LECTURE))
                .append("× faster than the lecture style and at most ")
                .append(num(TARGET_VS_PRIMITIVE)).append("× slower than the primitive loop at "
                + "every N. Objects holding `Vector3f`s cannot get there, so "
                + "the integrator has a batch form over packed float arrays, "
                + "`ParticleBatch.stepPacked`.\n\n");
        md.append("| N | lecture style | Particle objects | packed batch (min–max) "
                + "| primitive loop (min–max) | batch bytes/step | batch vs lecture "
                + "| batch vs primitive | targets |\n"
                + "|---|---|---|---|---|---|---|---|---|\n");
        for (int count : bulkCounts(benchmarks)) {
            BenchmarkTable.Row lec = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_LECTURE, count));
            BenchmarkTable.Row obj = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_OBJECTS, count));
            BenchmarkTable.Row batch = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_BATCH, count));
            BenchmarkTable.Row prim = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_PRIMITIVE, count));
            if (lec == null || obj == null || batch == null || prim == null) {
                continue;
            }
            double faster = lec.nanosPerParticleStep() / batch.nanosPerParticleStep();
            double slower = batch.nanosPerParticleStep() / prim.nanosPerParticleStep();
            boolean met = faster >= TARGET_VS_LECTURE && slower <= TARGET_VS_PRIMITIVE
                    && batch.bytesPerStep() < 0.5;
            boolean noisy = lec.isTooNoisy(SpeedSpreads.SPREAD_BOUND)
                    || batch.isTooNoisy(SpeedSpreads.SPREAD_BOUND)
                    || prim.isTooNoisy(SpeedSpreads.SPREAD_BOUND);
            md.append("| ").append(count).append(" | ")
                    .append(fix(lec.nanosPerParticleStep(), 2)).append(" | ")
                    .append(fix(obj.nanosPerParticleStep(), 2)).append(" | ")
                    .append(fix(batch.nanosPerParticleStep(), 3)).append(" (")
                    .append(range(batch, 3)).append(") | ")
                    .append(fix(prim.nanosPerParticleStep(), 3)).append(" (")
                    .append(range(prim, 3)).append(") | ")
                    .append(fix(batch.bytesPerStep(), 2)).append(" | ")
                    .append(SpeedRatio.describe(batch.nanosPerParticleStep(),
                            lec.nanosPerParticleStep())).append(" | ")
                    .append(SpeedRatio.describe(batch.nanosPerParticleStep(),
                            prim.nanosPerParticleStep())).append(" | ")
                    .append(noisy ? SpeedSpreads.TOO_NOISY : met ? "met" : "**missed**")
                    .append(" |\n");
        }
        md.append("\nAll times in ns per particle-step. \"bytes/step\" is heap allocated per "
                + "particle-step (0 = nothing; the JVM's counters round to a few bytes per "
                + "measured round). The lecture style's time depends on the garbage "
                + "collector's state (new vectors stored into long-lived particles), so it "
                + "moves by several times from run to run; the allocation-free forms are "
                + "steady. \"targets\" says \"").append(SpeedSpreads.TOO_NOISY).append("\" "
                + "where a row's rounds spread by more than ")
                .append(num(SpeedSpreads.SPREAD_BOUND)).append("× (max ÷ min).\n\n");
        MixTargets.appendTable(md, benchmarks, fromJmh);
        md.append(spreads);
        appendSubnormalLesson(md);
    }

    private static void appendSubnormalLesson(StringBuilder md) {
        double leftSpeed = CanonicalCase.launch().velocity[0] * Math.pow(1.0
                - OneParticleScene.LINEAR_RATE * OneParticleScene.STEP_SECONDS,
                BulkScene.STEPS_PER_LAUNCH);
        md.append("### Why the benchmark scenes relaunch\n\n");
        md.append("Under drag a velocity component decays as vx·(1 − h·b/m)ⁿ. Left alone it "
                + "becomes a subnormal float (below ").append(sci(Float.MIN_NORMAL))
                .append(") after about ").append(stepsToSubnormal(OneParticleScene.LINEAR_RATE,
                        OneParticleScene.STEP_SECONDS)).append(" steps at b/m = ")
                .append(num(OneParticleScene.LINEAR_RATE)).append(" /s, h = ")
                .append(stepText(OneParticleScene.STEP_SECONDS)).append(" (")
                .append(fix(stepsToSubnormal(OneParticleScene.LINEAR_RATE,
                        OneParticleScene.STEP_SECONDS) * OneParticleScene.STEP_SECONDS, 0))
                .append(" s of flight), and x86 processors do arithmetic on subnormal numbers "
                + "30–40× slower than on normal ones. A benchmark that never relaunched would "
                + "time that slow path, not the step; a game loop whose velocities decay to "
                + "~1e-40 slows down the same way. So every benchmark scene here relaunches "
                + "its particles: the one-particle scene before every flight of ")
                .append(OneParticleScene.STEPS_PER_LAUNCH).append(" steps, the bulk scene "
                + "every ").append(BulkScene.STEPS_PER_LAUNCH).append(" steps (vx is then "
                + "still about ").append(sci(leftSpeed)).append(" m/s); a relaunch costs "
                + "about one step in ").append(BulkScene.STEPS_PER_LAUNCH).append(". A test runs "
                + "each scene far past the decay point and checks that no component is "
                + "subnormal. The demos never get there: the particles of the motion and "
                + "aiming demos fall under gravity and stop at the ground, where their velocity "
                + "is set to exactly 0 (zero is not subnormal) and they are no longer stepped; "
                + "the uniform-motion sphere feels no force and restarts; the collision demos "
                + "have no drag, so speeds change only at impacts, and a ball that comes to "
                + "rest is held at exactly 0 by the resting contact. A scene of your own with "
                + "drag and no "
                + "ground would decay: snap tiny velocities to zero or recycle particles.\n\n");
    }

    /** Steps after which the canonical launch's vx decays below the smallest normal float. */
    static long stepsToSubnormal(double linearRate, double stepSeconds) {
        return Math.round(Math.log(Float.MIN_NORMAL / CanonicalCase.launch().velocity[0])
                / Math.log(1.0 - linearRate * stepSeconds));
    }

    private void appendAiming(StringBuilder md, AimingStudy aiming) {
        md.append("## Aiming\n\n![miss distance against h and drag](aiming.png)\n\n");
        md.append("HelloAiming's level shot (S = ").append(num(AimingStudy.DISTANCE))
                .append(" m, vx = ").append(num(AimingStudy.VX)).append(" m/s) flown by the shared "
                + "integrator; the landing point is interpolated inside the step that crosses "
                + "the ground. The lecture's vy = g·S/(2·vx) lands vx·h short; the discrete "
                + "correction lands on target up to float round-off. Neither knows about drag. "
                + "Iterative aiming (shoot, see where it lands, adjust vy: bracketing, then "
                + "regula falsi) flies the scene's own forces and lands within its tolerance of "
                + AimingStudy.TOLERANCE + " m whenever the target is in reach; with linear drag "
                + "no launch reaches past vx·(1 − k·h)/k");
        double unreachable = weakestUnreachableDrag(aiming);
        if (!Double.isNaN(unreachable)) {
            md.append(", so at b/m ≥ ").append(num(unreachable)).append(" /s the ")
                    .append(num(AimingStudy.DISTANCE)).append(" m target is out of reach "
                    + "(shown as —)");
        }
        md.append(".\n\n| h (s) | lecture miss (m) | discrete miss (m) | iterative miss (m) "
                + "| shots "
                + "| vx·h (m) |\n|---|---|---|---|---|---|\n");
        for (double h : config.steps()) {
            md.append("| 1/").append(Math.round(1 / h)).append(" | ")
                    .append(sig(miss(aiming, AimingStudy.STEP_SWEEP, AimingStudy.LECTURE, h,
                            0.0))).append(" | ")
                    .append(sci(miss(aiming, AimingStudy.STEP_SWEEP, AimingStudy.DISCRETE, h,
                            0.0))).append(" | ")
                    .append(reach(miss(aiming, AimingStudy.STEP_SWEEP, AimingStudy.ITERATIVE, h,
                            0.0))).append(" | ")
                    .append(shotCount(aiming, AimingStudy.STEP_SWEEP, h, 0.0)).append(" | ")
                    .append(sig(AimingStudy.VX * h)).append(" |\n");
        }
        md.append("\n| b/m (1/s), h = ").append(stepText(AimingStudy.DRAG_SWEEP_STEP))
                .append(" | lecture miss (m) | discrete miss (m) "
                + "| iterative miss (m) | shots |\n|---|---|---|---|---|\n");
        for (double k : AimingStudy.DRAG_RATES) {
            double h = AimingStudy.DRAG_SWEEP_STEP;
            md.append("| ").append(num(k)).append(" | ")
                    .append(sig(miss(aiming, AimingStudy.DRAG_SWEEP, AimingStudy.LECTURE, h,
                            k))).append(" | ")
                    .append(sig(miss(aiming, AimingStudy.DRAG_SWEEP, AimingStudy.DISCRETE, h,
                            k))).append(" | ")
                    .append(reach(miss(aiming, AimingStudy.DRAG_SWEEP, AimingStudy.ITERATIVE, h,
                            k))).append(" | ")
                    .append(shotCount(aiming, AimingStudy.DRAG_SWEEP, h, k)).append(" |\n");
        }
        md.append('\n');
    }

    private static void appendHitches(StringBuilder md, HitchStudy hitches) {
        md.append("## Frame hitches\n\n");
        md.append("The canonical shot ").append(launchText()).append(" m/s under linear drag "
                + "at ").append(Math.round(1.0 / HitchStudy.FRAME_SECONDS)).append(" frames per "
                + "second, with a long frame after every ")
                .append(HitchStudy.FRAMES_BETWEEN_HITCHES)
                .append(" ordinary ones. Raw tpf takes one step per frame, however long; the "
                + "fixed-step clock (defaults: h = ").append(stepText(DEMO_STEP_SECONDS))
                .append(", frames clamped to ")
                .append(num(SimulationClock.DEFAULT_MAX_FRAME_SECONDS))
                .append(" s, at most ").append(SimulationClock.DEFAULT_MAX_STEPS_PER_FRAME)
                .append(" steps a frame) keeps h and drops the time it cannot take. Landing "
                + "error against the exact range.\n\n");
        md.append("| b/m (1/s) | long frame (s) | raw tpf: landing error (m) | finite "
                + "| fixed step: landing error (m) | finite | time dropped in all (s) |\n"
                + "|---|---|---|---|---|---|---|\n");
        for (double k : HitchStudy.LINEAR_RATES) {
            for (double hitch : HitchStudy.HITCH_SECONDS) {
                HitchStudy.Run raw = hitchRun(hitches, k, SimulationClock.Mode.RAW_TPF, hitch);
                HitchStudy.Run fixed = hitchRun(hitches, k, SimulationClock.Mode.FIXED_STEP,
                        hitch);
                md.append("| ").append(num(k)).append(" | ")
                        .append(hitch == 0.0 ? "none" : num(hitch)).append(" | ")
                        .append(landingText(raw)).append(" | ")
                        .append(raw.finite ? "yes" : "**no**")
                        .append(" | ").append(landingText(fixed)).append(" | ")
                        .append(fixed.finite ? "yes" : "**no**").append(" | ")
                        .append(fix(fixed.droppedSeconds, 2)).append(" |\n");
            }
        }
        md.append('\n');
    }

    private void appendRecommendations(StringBuilder md, WorkPrecisionStudy precision,
            StabilityStudy stability, BenchmarkTable benchmarks, AimingStudy aiming,
            HitchStudy hitches) {
        double h = DEMO_STEP_SECONDS;
        String duration = num(CanonicalCase.DURATION_SECONDS) + " s";
        md.append("## Recommendations\n\n");
        md.append("The demos step with the lecture's semi-implicit Euler at a fixed h = ")
                .append(stepText(h)).append(" through the fixed-step clock. From the numbers "
                + "above:\n\n");
        CanonicalCase gravity = gravityCase();
        if (gravity != null) {
            WorkPrecisionStudy.Point sie = point(precision, gravity, Scheme.SEMI_IMPLICIT_EULER,
                    h);
            md.append("- **Uniform motion, gravitational pull.** Semi-implicit Euler is off by ")
                    .append(sig(sie.errorMetres)).append(" m after ").append(duration)
                    .append(" (theory g·h·t/2 = ").append(sig(CanonicalCase.G * h
                            * CanonicalCase.DURATION_SECONDS / 2)).append(" m): the curve is "
                    + "the right parabola launched g·h/2 lower. That offset is what the lecture "
                    + "teaches; keep it, and show the exact step as a ghost if the difference "
                    + "should be seen.\n");
        }
        appendAimingRecommendation(md, aiming, h);
        appendDragRecommendation(md, precision, h, duration);
        CanonicalCase thrust = thrustCase();
        if (thrust != null) {
            md.append("- **Thrust (").append(thrust.label()).append(").** Error ")
                    .append(sig(point(precision, thrust, Scheme.SEMI_IMPLICIT_EULER, h)
                            .errorMetres)).append(" m after ").append(duration).append(" at ")
                    .append(stepText(h)).append(": keep the lecture's step.\n");
        }
        md.append("- **Stiff scenes.** The ").append(stepText(h)).append(" step meets the "
                + "limit ").append(num(Scheme.SEMI_IMPLICIT_EULER.stabilityFactor()))
                .append("m/b of both Euler forms at b/m = ")
                .append(sig(stiffRate(Scheme.SEMI_IMPLICIT_EULER, h))).append(" /s; RK4 only "
                + "moves it to ").append(fix(Scheme.RUNGE_KUTTA_4.stabilityFactor(), 3))
                .append("m/b (b/m = ").append(sig(stiffRate(Scheme.RUNGE_KUTTA_4, h)))
                .append(" /s). For very strong drag use the exact step (stable at any h), "
                + "not a higher-order method.\n");
        appendBulkRecommendation(md, benchmarks);
        double k = max(HitchStudy.LINEAR_RATES);
        double hitch = max(HitchStudy.HITCH_SECONDS);
        HitchStudy.Run raw = hitchRun(hitches, k, SimulationClock.Mode.RAW_TPF, hitch);
        HitchStudy.Run fixed = hitchRun(hitches, k, SimulationClock.Mode.FIXED_STEP, hitch);
        md.append("- **Frame hitches.** With ").append(num(hitch)).append(" s frames at b/m = ")
                .append(num(k)).append(" /s, raw tpf lands ").append(landingText(raw))
                .append(" m off; the fixed-step clock ").append(landingText(fixed))
                .append(" m, at the price of ").append(fix(fixed.droppedSeconds, 2))
                .append(" s of dropped time. Demos use the fixed-step clock; raw tpf stays as "
                + "the lesson's switch (`T`).\n");
    }

    private static void appendAimingRecommendation(StringBuilder md, AimingStudy aiming,
            double h) {
        double lectureMiss = miss(aiming, AimingStudy.STEP_SWEEP, AimingStudy.LECTURE, h, 0.0);
        double discreteMiss = miss(aiming, AimingStudy.STEP_SWEEP, AimingStudy.DISCRETE, h,
                0.0);
        md.append("- **HelloAiming.** At ").append(stepText(h)).append(" the lecture's formula "
                + "lands ").append(sig(Math.abs(lectureMiss)))
                .append(lectureMiss < 0 ? " m short" : " m long").append(" (vx·h = ")
                .append(sig(AimingStudy.VX * h)).append(" m); the discrete correction lands "
                + "within ").append(sci(Math.abs(discreteMiss))).append(" m. Aim with the "
                + "correction (or show both), and only at a fixed h: with raw tpf the landing "
                + "jitters.");
        double reachable = strongestReachableDrag(aiming);
        if (reachable > 0.0) {
            double dragMiss = miss(aiming, AimingStudy.DRAG_SWEEP, AimingStudy.DISCRETE,
                    AimingStudy.DRAG_SWEEP_STEP, reachable);
            md.append(" With drag neither formula hits (b/m = ").append(num(reachable))
                    .append(" /s: the correction lands ").append(sig(Math.abs(dragMiss)))
                    .append(dragMiss < 0 ? " m short" : " m long")
                    .append("); iterative aiming hits within ").append(AimingStudy.TOLERANCE)
                    .append(" m in ").append(shotCount(aiming, AimingStudy.DRAG_SWEEP,
                            AimingStudy.DRAG_SWEEP_STEP, reachable))
                    .append(" simulated shots, cheap enough to run when the player changes vx.");
        }
        md.append('\n');
    }

    private static void appendDragRecommendation(StringBuilder md, WorkPrecisionStudy precision,
            double h, String duration) {
        CanonicalCase worst = null;
        double worstError = -1.0;
        double strongest = 0.0;
        for (CanonicalCase scene : linearDragCases()) {
            double error = point(precision, scene, Scheme.SEMI_IMPLICIT_EULER, h).errorMetres;
            if (error > worstError) {
                worstError = error;
                worst = scene;
            }
            strongest = Math.max(strongest, scene.forces().linearRate());
        }
        if (worst != null) {
            double limit = Scheme.SEMI_IMPLICIT_EULER.stabilityFactor() / strongest;
            WorkPrecisionStudy.Point sie = point(precision, worst, Scheme.SEMI_IMPLICIT_EULER, h);
            WorkPrecisionStudy.Point rk4 = point(precision, worst, Scheme.RUNGE_KUTTA_4, h);
            md.append("- **Linear drag.** Up to b/m = ").append(num(strongest))
                    .append(" /s the Euler limit ")
                    .append(num(Scheme.SEMI_IMPLICIT_EULER.stabilityFactor()))
                    .append("m/b is at least ").append(sig(limit)).append(" s, ")
                    .append(fix(limit / h, 0)).append(" steps of h. In the cases measured (b/m = ")
                    .append(rateList()).append(" /s) the error after ").append(duration)
                    .append(" is at most ").append(sig(worstError)).append(" m (")
                    .append(worst.label()).append("); the error is not monotone in b/m, so a "
                    + "rate between these cases can be off by somewhat more. RK4 would cut it "
                    + "to ")
                    .append(sci(rk4.errorMetres)).append(" m at ")
                    .append(fix(rk4.nanosPerStep / sie.nanosPerStep, 1)).append("× the cost "
                    + "per step, which no viewer would notice; keep the lecture's step.\n");
        }
        CanonicalCase quadratic = quadraticCase();
        if (quadratic != null) {
            ForceModel forces = quadratic.forces();
            double rate = forces.getQuadraticDrag() / forces.getMassKg();
            double terminal = Math.sqrt(CanonicalCase.G / rate);
            // lambda = 2·c·|V|/m; the Euler limit 2/lambda at terminal speed is 1/(rate·v_t)
            double limit = Scheme.SEMI_IMPLICIT_EULER.stabilityFactor()
                    / (2.0 * rate * terminal);
            md.append("- **Quadratic drag (").append(quadratic.label()).append(").** Error ")
                    .append(sig(point(precision, quadratic, Scheme.SEMI_IMPLICIT_EULER, h)
                            .errorMetres)).append(" m after ").append(duration)
                    .append("; its limit at terminal speed v_t = ").append(sig(terminal))
                    .append(" m/s is ").append(sig(limit)).append(" s, far above h.\n");
        }
    }

    private static void appendBulkRecommendation(StringBuilder md, BenchmarkTable benchmarks) {
        int[] counts = bulkCounts(benchmarks);
        if (counts.length == 0) {
            return;
        }
        int largest = counts[counts.length - 1];
        BenchmarkTable.Row lec = benchmarks.find(BenchmarkTable.bulkName(
                BenchmarkTable.BULK_LECTURE, largest));
        BenchmarkTable.Row batch = benchmarks.find(BenchmarkTable.bulkName(
                BenchmarkTable.BULK_BATCH, largest));
        BenchmarkTable.Row obj = benchmarks.find(BenchmarkTable.bulkName(
                BenchmarkTable.BULK_OBJECTS, largest));
        BenchmarkTable.Row prim = benchmarks.find(BenchmarkTable.bulkName(
                BenchmarkTable.BULK_PRIMITIVE, largest));
        if (lec == null || batch == null || obj == null || prim == null) {
            return;
        }
        md.append("- **Many particles.** At N = ").append(largest).append(" the packed batch "
                + "form costs ").append(fix(batch.nanosPerParticleStep(), 2))
                .append(" ns per particle-step (")
                .append(SpeedRatio.describe(batch.nanosPerParticleStep(),
                        prim.nanosPerParticleStep())).append(" than the primitive loop), against ")
                .append(fix(obj.nanosPerParticleStep(), 1)).append(" ns for Particle objects ("
                + "the batch is ").append(SpeedRatio.describe(batch.nanosPerParticleStep(),
                        obj.nanosPerParticleStep())).append(") and ")
                .append(fix(lec.nanosPerParticleStep(), 1)).append(" ns for the lecture's "
                + "style (the batch is ").append(SpeedRatio.describe(
                        batch.nanosPerParticleStep(), lec.nanosPerParticleStep()))
                .append("). Scenes with thousands of particles should use `stepPacked`.\n");
    }

    /** The drag rate b/m at which a scheme's stability limit equals the step h (in 1/s). */
    static double stiffRate(Scheme scheme, double stepSeconds) {
        return scheme.stabilityFactor() / stepSeconds;
    }

    /** The case with gravity alone, or null. */
    static CanonicalCase gravityCase() {
        for (CanonicalCase scene : CanonicalCase.all()) {
            ForceModel f = scene.forces();
            if (f.getLinearDrag() == 0.0 && f.getQuadraticDrag() == 0.0
                    && f.getThrustNewtons() == 0.0) {
                return scene;
            }
        }
        return null;
    }

    /** The cases with gravity and linear drag only. */
    static List<CanonicalCase> linearDragCases() {
        List<CanonicalCase> cases = new ArrayList<>();
        for (CanonicalCase scene : CanonicalCase.all()) {
            ForceModel f = scene.forces();
            if (f.getLinearDrag() > 0.0 && f.getQuadraticDrag() == 0.0
                    && f.getThrustNewtons() == 0.0) {
                cases.add(scene);
            }
        }
        return cases;
    }

    private static CanonicalCase quadraticCase() {
        for (CanonicalCase scene : CanonicalCase.all()) {
            if (scene.forces().getQuadraticDrag() > 0.0) {
                return scene;
            }
        }
        return null;
    }

    private static CanonicalCase thrustCase() {
        for (CanonicalCase scene : CanonicalCase.all()) {
            if (scene.forces().getThrustNewtons() > 0.0) {
                return scene;
            }
        }
        return null;
    }

    /** The linear-drag cases' rates b/m, as text: 0.1, 0.5, 2. */
    private static String rateList() {
        StringBuilder text = new StringBuilder();
        for (CanonicalCase scene : linearDragCases()) {
            text.append(text.length() == 0 ? "" : ", ").append(num(scene.forces().linearRate()));
        }
        return text.toString();
    }

    /** The linear-drag case the one-particle benchmarks fly, or null. */
    private static CanonicalCase benchmarkCase() {
        for (CanonicalCase scene : linearDragCases()) {
            if (same(scene.forces().linearRate(), OneParticleScene.LINEAR_RATE)) {
                return scene;
            }
        }
        return null;
    }

    /** The strongest drag of the aiming sweep at which iterative aiming still hits, or 0. */
    private static double strongestReachableDrag(AimingStudy aiming) {
        double strongest = 0.0;
        for (AimingStudy.Shot s : aiming.shots) {
            if (s.sweep.equals(AimingStudy.DRAG_SWEEP) && s.formula.equals(AimingStudy.ITERATIVE)
                    && !Double.isNaN(s.missMetres)) {
                strongest = Math.max(strongest, s.linearRate);
            }
        }
        return strongest;
    }

    /** The weakest drag of the aiming sweep at which the target is out of reach, or NaN. */
    private static double weakestUnreachableDrag(AimingStudy aiming) {
        double weakest = Double.NaN;
        for (AimingStudy.Shot s : aiming.shots) {
            if (s.sweep.equals(AimingStudy.DRAG_SWEEP) && s.formula.equals(AimingStudy.ITERATIVE)
                    && Double.isNaN(s.missMetres) && !(s.linearRate >= weakest)) {
                weakest = s.linearRate;
            }
        }
        return weakest;
    }

    private static double max(double[] values) {
        double largest = Double.NEGATIVE_INFINITY;
        for (double v : values) {
            largest = Math.max(largest, v);
        }
        return largest;
    }

    /** The canonical launch velocity as text: (20, 30). */
    private static String launchText() {
        MotionState launch = CanonicalCase.launch();
        return "(" + num(launch.velocity[0]) + ", " + num(launch.velocity[1]) + ")";
    }

    /** A step as the report writes it: 1/60 s. */
    static String stepText(double stepSeconds) {
        return "1/" + Math.round(1.0 / stepSeconds) + " s";
    }

    /** Equal up to round-off of the decimal literals the studies are configured with. */
    private static boolean same(double a, double b) {
        return Math.abs(a - b) <= 1e-9 * Math.max(Math.abs(a), Math.abs(b));
    }

    // ---- helpers ------------------------------------------------------------------------------

    private static WorkPrecisionStudy.Point point(WorkPrecisionStudy study, CanonicalCase scene,
            Scheme scheme, double h) {
        for (WorkPrecisionStudy.Point p : study.points) {
            if (p.scene == scene && p.scheme == scheme
                    && Math.abs(p.stepSeconds - h) < 1e-12 * h) {
                return p;
            }
        }
        return null;
    }

    private static WorkPrecisionStudy.Order order(WorkPrecisionStudy study, CanonicalCase scene,
            Scheme scheme) {
        for (WorkPrecisionStudy.Order o : study.orders) {
            if (o.scene == scene && o.scheme == scheme) {
                return o;
            }
        }
        return null;
    }

    /** A miss for the table, or a dash where the target was out of reach. */
    private static String reach(double missMetres) {
        return Double.isNaN(missMetres) ? "—" : sci(missMetres);
    }

    private static int shotCount(AimingStudy aiming, String sweep, double h, double k) {
        for (AimingStudy.Shot s : aiming.shots) {
            if (s.sweep.equals(sweep) && s.formula.equals(AimingStudy.ITERATIVE)
                    && same(s.stepSeconds, h) && same(s.linearRate, k)) {
                return s.shots;
            }
        }
        return 0;
    }

    private static double miss(AimingStudy aiming, String sweep, String formula, double h,
            double k) {
        for (AimingStudy.Shot s : aiming.shots) {
            if (s.sweep.equals(sweep) && s.formula.equals(formula)
                    && same(s.stepSeconds, h) && same(s.linearRate, k)) {
                return s.missMetres;
            }
        }
        return Double.NaN;
    }

    private static HitchStudy.Run hitchRun(HitchStudy hitches, double k,
            SimulationClock.Mode mode, double hitch) {
        for (HitchStudy.Run r : hitches.runs) {
            if (same(r.linearRate, k) && r.mode == mode && same(r.hitchSeconds, hitch)) {
                return r;
            }
        }
        throw new IllegalStateException("no hitch run for b/m=" + k + ", " + mode + ", " + hitch);
    }

    private static String landingText(HitchStudy.Run run) {
        if (!run.finite) {
            return "diverged";
        }
        if (!run.landed) {
            return "never landed";
        }
        return String.format(Locale.ROOT, "%+.3g", run.landingError());
    }

    private static int[] bulkCounts(BenchmarkTable table) {
        List<Integer> counts = new ArrayList<>();
        String prefix = "bulk/" + BenchmarkTable.BULK_BATCH + "/";
        for (BenchmarkTable.Row row : table.rows()) {
            if (row.name().startsWith(prefix)) {
                counts.add(Integer.parseInt(row.name().substring(prefix.length())));
            }
        }
        Collections.sort(counts);
        int[] result = new int[counts.size()];
        for (int i = 0; i < result.length; ++i) {
            result[i] = counts.get(i);
        }
        return result;
    }

    /** "min–max" of a row's rounds, or "—" for a row without a spread (JMH's). */
    static String range(BenchmarkTable.Row row, int decimals) {
        if (Double.isNaN(row.minNanos())) {
            return "—";
        }
        return fix(row.minNanos(), decimals) + "–" + fix(row.maxNanos(), decimals);
    }

    private static String ratio(BenchmarkTable.Row row, BenchmarkTable.Row reference) {
        if (reference == null) {
            return "—";
        }
        return SpeedRatio.describe(row.nanosPerParticleStep(),
                reference.nanosPerParticleStep());
    }

    private static int indexOf(double[] values, double value) {
        for (int i = 0; i < values.length; ++i) {
            if (values[i] == value) {
                return i;
            }
        }
        throw new IllegalArgumentException("value " + value + " not among " +
                Arrays.toString(values));
    }

    private static String orderText(double order) {
        return Double.isInfinite(order) ? "∞" : fix(order, 0);
    }

    private static String modeName(SimulationClock.Mode mode) {
        return mode == SimulationClock.Mode.RAW_TPF ? "raw-tpf" : "fixed-step";
    }

    /** A number for CSV: full precision, Java's spelling of NaN and Infinity. */
    private static String num(double value) {
        if (Double.isNaN(value) || Double.isInfinite(value)) {
            return Double.toString(value);
        }
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }

    private static String sci(double value) {
        return String.format(Locale.ROOT, "%.2e", value);
    }

    private static String sig(double value) {
        return String.format(Locale.ROOT, "%.3g", value);
    }

    private static String fix(double value, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", value);
    }

    private void writeText(String name, CharSequence text) throws IOException {
        SafeFiles.write(folder.resolve(name), text, false);
    }
}

package particlelab.accuracy;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.XYChart;
import particlelab.physics.SimulationClock;

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
                "hitches.csv", MAIN_PLOT, "stability.png", "bulk.png", "aiming.png"));
        for (CanonicalCase scene : CanonicalCase.all()) {
            files.add(workPrecisionPlot(scene));
        }
        FILES = Collections.unmodifiableList(files);
    }

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
        BenchmarkTable jmh = jmhResults == null ? null : BenchmarkTable.read(jmhResults);
        CostMeter meter = new CostMeter(config);
        ProgressBar progress = new ProgressBar(progressOut, WorkPrecisionStudy.units()
                + StabilityStudy.units(config)
                + (jmh == null ? BenchmarkStudy.units(config) : 0) + 3, interactive);
        // Benchmarks first, while the JIT has seen only their scene (gravity + linear drag):
        // later sweeps through every force type make the integrator's force calls megamorphic.
        BenchmarkTable benchmarks = jmh != null ? jmh : BenchmarkStudy.run(config, meter, progress);
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
        writeIndex(precision, stability, benchmarks, aiming, hitches, jmh != null);
        CollisionSection.write(config, meter, folder);
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

        benchmarks.write(folder.resolve("benchmarks.csv"));

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

    private void writePlots(WorkPrecisionStudy precision, StabilityStudy stability,
            BenchmarkTable benchmarks, AimingStudy aiming) throws IOException {
        List<XYChart> grid = new ArrayList<>();
        for (CanonicalCase scene : CanonicalCase.all()) {
            XYChart chart = Charts.create("Work vs precision: " + scene.label(),
                    "cost (ns per simulated second)", "position error after "
                            + (int) CanonicalCase.DURATION_SECONDS + " s (m)", true, true);
            for (Scheme scheme : Scheme.values()) {
                List<WorkPrecisionStudy.Point> line = new ArrayList<>();
                for (WorkPrecisionStudy.Point p : precision.points) {
                    if (p.scene == scene && p.scheme == scheme) {
                        line.add(p);
                    }
                }
                if (line.isEmpty()) {
                    continue;
                }
                double[] cost = new double[line.size()];
                double[] error = new double[line.size()];
                for (int i = 0; i < cost.length; ++i) {
                    cost[i] = line.get(i).nanosPerSimulatedSecond();
                    error[i] = line.get(i).errorMetres;
                }
                Charts.line(chart, scheme.shortLabel(), cost, Charts.floored(error),
                        scheme.ordinal());
            }
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

        List<XYChart> aimCharts = new ArrayList<>();
        XYChart byStep = Charts.create("Level shot S = 100 m, vx = 20 m/s: miss against h",
                "step h (s)", "|miss| (m)", true, true);
        XYChart byDrag = Charts.create("Miss against linear drag (h = 1/60 s)", "b/m (1/s)",
                "miss: landing x - S (m)", false, false);
        String[] formulas = {"lecture", "discrete", "iterative"};
        String[] formulaLabels = {"lecture vy = gS/(2vx)", "discrete vy = gS/(2vx) + gh/2",
            "iterative (tolerance " + AimingStudy.TOLERANCE + " m)"};
        for (int f = 0; f < formulas.length; ++f) {
            aimingLine(byStep, aiming, "step", formulas[f], formulaLabels[f], f, true);
            aimingLine(byDrag, aiming, "drag", formulas[f], formulaLabels[f], f, false);
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

    private void writeIndex(WorkPrecisionStudy precision, StabilityStudy stability,
            BenchmarkTable benchmarks, AimingStudy aiming, HitchStudy hitches, boolean fromJmh)
            throws IOException {
        StringBuilder md = new StringBuilder();
        md.append("# Speed against error\n\n");
        md.append("Particle Lab's shared Euler integrator beside reference steppers: how far "
                + "each is off, what it costs, when it blows up, and what that means for the "
                + "demos. Regenerate with `gradle report` (or `particle-lab report`).\n\n");
        md.append("## How this was measured\n\n");
        md.append("- Size: **").append(config.size().name().toLowerCase(Locale.ROOT))
                .append("**; JVM ").append(System.getProperty("java.vm.name")).append(' ')
                .append(System.getProperty("java.version")).append(", ")
                .append(Runtime.getRuntime().availableProcessors()).append(" cores, ")
                .append(System.getProperty("os.name")).append(' ')
                .append(System.getProperty("os.arch")).append(".\n");
        md.append("- Every case launches from the origin at (20, 30) m/s under g = 9.8 m/s² "
                + "on 1 kg and flies ").append((int) CanonicalCase.DURATION_SECONDS)
                .append(" s. Error = distance from the reference position at that time: the "
                + "closed form for gravity and linear drag, RK4 at h = 1/")
                .append(ClosedForms.REFERENCE_STEPS_PER_SECOND)
                .append(" s otherwise (its own error is below 1e-11 m).\n");
        md.append("- The reference steppers run in double precision on the same force laws. "
                + "Semi-implicit Euler is the shared `ParticleIntegrator` itself, run in float "
                + "on jME vectors exactly as the demos run it; its line goes on to smaller h "
                + "to show where float round-off stops the error from falling.\n");
        md.append("- Costs are timed in this one JVM, one after another (side by side), each "
                + "after a warm-up, as the median of ").append(config.rounds())
                .append(" rounds of at least ").append(config.roundNanos() / 1_000_000)
                .append(" ms; read them as ratios to each other, not as absolute numbers. "
                + "Cost per simulated second = cost per step / h.\n");
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
        appendBenchmarks(md, benchmarks);
        appendAiming(md, aiming);
        appendHitches(md, hitches);
        appendRecommendations(md, precision, stability, benchmarks, aiming, hitches);
        writeText("index.md", md);
    }

    private void appendWorkPrecision(StringBuilder md, WorkPrecisionStudy precision) {
        md.append("## Work against precision\n\n");
        md.append("![work-precision plots of every case](").append(MAIN_PLOT).append(")\n\n");
        md.append("How to read it: each line is one stepper, each point one step size h, "
                + "from 1/15 s (left, cheap, inaccurate) to 1/")
                .append(Math.round(1 / config.steps()[config.steps().length - 1]))
                .append(" s (right). Lower is more accurate, further left is cheaper; the best "
                + "method for a given error budget is the line furthest down-left. The slope is "
                + "minus the order: a first-order method gains one digit of accuracy for ten "
                + "times the work, RK4 four. Points at the bottom (1e-16 and below) are exact up "
                + "to round-off. One chart per case: ");
        for (CanonicalCase scene : CanonicalCase.all()) {
            md.append('[').append(scene.id()).append("](").append(workPrecisionPlot(scene))
                    .append(") ");
        }
        md.append("\n\nPosition error after ").append((int) CanonicalCase.DURATION_SECONDS)
                .append(" s at the demos' h = 1/60 s (m):\n\n");
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
                WorkPrecisionStudy.Point p = point(precision, scene, scheme, 1.0 / 60);
                md.append(' ').append(p == null ? "—" : sci(p.errorMetres)).append(" |");
            }
            md.append('\n');
        }
        md.append("\nCost of one step on one particle (ns, gravity + drag case `drag-0.5`): ");
        for (Scheme scheme : Scheme.values()) {
            WorkPrecisionStudy.Point p = point(precision, CanonicalCase.all().get(2), scheme,
                    1.0 / 60);
            md.append(scheme.id()).append(' ').append(fix(p.nanosPerStep, 1)).append("; ");
        }
        md.append("full table in `work-precision.csv`. These are timed after the "
                + "benchmarks, with every force type seen, so the shared integrator's calls "
                + "to its forces are no longer inlined: compare the benchmark table for a "
                + "single scene.\n\n");
    }

    private void appendOrders(StringBuilder md, WorkPrecisionStudy precision) {
        md.append("## Convergence orders\n\n");
        md.append("Measured order = least-squares slope of log(error) against log(h) over "
                + "h = 1/15 … 1/").append(Math.round(1 / config.steps()[config.steps().length
                - 1])).append(" s, from the largest h down while the error is above ")
                .append(sci(WorkPrecisionStudy.ROUND_OFF_FLOOR)).append(" m and still "
                + "falls at least 1.5× per halving of h (past that it is round-off). "
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

    private void appendBenchmarks(StringBuilder md, BenchmarkTable benchmarks) {
        md.append("## Benchmarks\n\n");
        BenchmarkTable.Row lecture = benchmarks.find(BenchmarkTable.LECTURE_STYLE);
        BenchmarkTable.Row primitive = benchmarks.find(BenchmarkTable.PRIMITIVE_LOOP);
        md.append("One particle, gravity + linear drag b/m = 0.5 /s, h = 1/60 s. Consecutive "
                + "steps of one particle wait for each other, so this is the latency of a "
                + "step. The reference steppers work in double precision on plain arrays; the "
                + "lecture style and the primitive loop in float.\n\n");
        md.append("| benchmark | ns per particle-step | bytes per step | × lecture style "
                + "| × primitive loop |\n|---|---|---|---|---|\n");
        for (BenchmarkTable.Row row : benchmarks.rows()) {
            if (row.name().startsWith("bulk/")) {
                continue;
            }
            md.append("| ").append(row.name()).append(" | ")
                    .append(fix(row.nanosPerParticleStep(), 2)).append(" | ")
                    .append(fix(row.bytesPerStep(), 1)).append(" | ")
                    .append(ratio(row, lecture)).append(" | ").append(ratio(row, primitive))
                    .append(" |\n");
        }
        md.append("\n### Many particles\n\n![cost per particle-step against N](bulk.png)\n\n");
        md.append("The same scene for N particles, one step of all of them per call. Targets "
                + "(this run, side by side): the shared integrator allocates 0 bytes per step, "
                + "is at least 3× faster than the lecture style and within 1.5× of the "
                + "primitive loop at every N. Objects holding `Vector3f`s cannot get there, so "
                + "the integrator has a batch form over packed float arrays, "
                + "`ParticleIntegrator.stepPacked`.\n\n");
        md.append("| N | lecture style | Particle objects | packed batch | primitive loop "
                + "| batch bytes/step | batch vs lecture | batch vs primitive | targets |\n"
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
            boolean met = faster >= 3.0 && slower <= 1.5 && batch.bytesPerStep() < 0.5;
            md.append("| ").append(count).append(" | ")
                    .append(fix(lec.nanosPerParticleStep(), 2)).append(" | ")
                    .append(fix(obj.nanosPerParticleStep(), 2)).append(" | ")
                    .append(fix(batch.nanosPerParticleStep(), 3)).append(" | ")
                    .append(fix(prim.nanosPerParticleStep(), 3)).append(" | ")
                    .append(fix(batch.bytesPerStep(), 2)).append(" | ")
                    .append(fix(faster, 0)).append("× faster | ").append(fix(slower, 2))
                    .append("× | ").append(met ? "met" : "**missed**").append(" |\n");
        }
        md.append("\nAll times in ns per particle-step. \"bytes/step\" is heap allocated per "
                + "particle-step (0 = nothing; the JVM's counters round to a few bytes per "
                + "measured round). The lecture style's time depends on the garbage "
                + "collector's state (new vectors stored into long-lived particles), so it "
                + "moves by several times from run to run; the allocation-free forms are "
                + "steady.\n\n");
    }

    private void appendAiming(StringBuilder md, AimingStudy aiming) {
        md.append("## Aiming\n\n![miss distance against h and drag](aiming.png)\n\n");
        md.append("HelloAiming's level shot (S = 100 m, vx = 20 m/s) flown by the shared "
                + "integrator; the landing point is interpolated inside the step that crosses "
                + "the ground. The lecture's vy = g·S/(2·vx) lands vx·h short; the discrete "
                + "correction lands on target up to float round-off. Neither knows about drag. "
                + "Iterative aiming (shoot, see where it lands, adjust vy: bracketing, then "
                + "regula falsi) flies the scene's own forces and lands within its tolerance of "
                + AimingStudy.TOLERANCE + " m whenever the target is in reach; with linear drag "
                + "no launch reaches past vx·(1 − k·h)/k, so at b/m ≥ 0.2 /s the 100 m target "
                + "is out of reach (shown as —).\n\n"
                + "| h (s) | lecture miss (m) | discrete miss (m) | iterative miss (m) | shots "
                + "| vx·h (m) |\n|---|---|---|---|---|---|\n");
        for (double h : config.steps()) {
            md.append("| 1/").append(Math.round(1 / h)).append(" | ")
                    .append(sig(miss(aiming, "step", "lecture", h, 0.0))).append(" | ")
                    .append(sci(miss(aiming, "step", "discrete", h, 0.0))).append(" | ")
                    .append(reach(miss(aiming, "step", "iterative", h, 0.0))).append(" | ")
                    .append(shotCount(aiming, "step", h, 0.0)).append(" | ")
                    .append(sig(AimingStudy.VX * h)).append(" |\n");
        }
        md.append("\n| b/m (1/s), h = 1/60 s | lecture miss (m) | discrete miss (m) "
                + "| iterative miss (m) | shots |\n|---|---|---|---|---|\n");
        for (double k : AimingStudy.DRAG_RATES) {
            double h = AimingStudy.DRAG_SWEEP_STEP;
            md.append("| ").append(num(k)).append(" | ")
                    .append(sig(miss(aiming, "drag", "lecture", h, k))).append(" | ")
                    .append(sig(miss(aiming, "drag", "discrete", h, k))).append(" | ")
                    .append(reach(miss(aiming, "drag", "iterative", h, k))).append(" | ")
                    .append(shotCount(aiming, "drag", h, k)).append(" |\n");
        }
        md.append('\n');
    }

    private static void appendHitches(StringBuilder md, HitchStudy hitches) {
        md.append("## Frame hitches\n\n");
        md.append("The canonical shot (20, 30) m/s under linear drag at 60 frames per second, "
                + "with a long frame after every ").append(HitchStudy.FRAMES_BETWEEN_HITCHES)
                .append(" ordinary ones. Raw tpf takes one step per frame, however long; the "
                + "fixed-step clock (defaults: h = 1/60 s, frames clamped to 0.25 s, at most "
                + "16 steps a frame) keeps h and drops the time it cannot take. Landing error "
                + "against the exact range.\n\n");
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
        List<CanonicalCase> cases = CanonicalCase.all();
        double h = 1.0 / 60;
        md.append("## Recommendations\n\n");
        md.append("The demos step with the lecture's semi-implicit Euler at a fixed h = 1/60 s "
                + "through the fixed-step clock. From the numbers above:\n\n");
        WorkPrecisionStudy.Point gravitySie = point(precision, cases.get(0),
                Scheme.SEMI_IMPLICIT_EULER, h);
        md.append("- **Uniform motion, gravitational pull (demos 1–2).** Semi-implicit Euler "
                + "is off by ").append(sig(gravitySie.errorMetres)).append(" m after 4 s "
                + "(theory g·h·t/2 = ").append(sig(CanonicalCase.G * h * 4 / 2))
                .append(" m): the curve is the right parabola launched g·h/2 lower. That "
                + "offset is what the lecture teaches; keep it, and show the exact step as a "
                + "ghost if the difference should be seen.\n");
        double lectureMiss = miss(aiming, "step", "lecture", h, 0.0);
        double discreteMiss = miss(aiming, "step", "discrete", h, 0.0);
        md.append("- **HelloAiming (demo 5).** At 1/60 s the lecture's formula lands ")
                .append(sig(-lectureMiss)).append(" m short (vx·h = ").append(sig(20 * h))
                .append(" m); the discrete correction lands within ")
                .append(sci(Math.abs(discreteMiss))).append(" m. Aim with the correction "
                + "(or show both), and only at a fixed h: with raw tpf the landing jitters. "
                + "With drag neither formula hits (b/m = 0.1 /s: the correction misses by ")
                .append(sig(miss(aiming, "drag", "discrete", h, 0.1))).append(" m); "
                + "iterative aiming hits within ").append(AimingStudy.TOLERANCE)
                .append(" m in ").append(shotCount(aiming, "drag", h, 0.1))
                .append(" simulated shots, cheap enough to run when the player changes vx.\n");
        WorkPrecisionStudy.Point drag2 = point(precision, cases.get(3),
                Scheme.SEMI_IMPLICIT_EULER, h);
        WorkPrecisionStudy.Point drag2Rk4 = point(precision, cases.get(3),
                Scheme.RUNGE_KUTTA_4, h);
        md.append("- **Drag (demo 3).** Up to b/m = 2 /s the Euler limit 2m/b is at least 1 s, "
                + "60 steps above h; the error after 4 s is at most ").append(sig(drag2
                .errorMetres)).append(" m. RK4 would cut it to ").append(sci(drag2Rk4
                .errorMetres)).append(" m for ").append(fix(drag2Rk4.nanosPerStep
                / drag2.nanosPerStep, 1)).append("× the cost per step, which no viewer "
                + "would notice; keep the lecture's step. Quadratic drag: ")
                .append(sig(point(precision, cases.get(4), Scheme.SEMI_IMPLICIT_EULER, h)
                        .errorMetres)).append(" m, its limit near terminal speed v_t/g "
                + "(3.2 s at c/m = 0.01) is far away.\n");
        md.append("- **Thrust (demo 4).** Error ").append(sig(point(precision, cases.get(5),
                Scheme.SEMI_IMPLICIT_EULER, h).errorMetres)).append(" m after 4 s at "
                + "1/60 s: keep the lecture's step.\n");
        md.append("- **Stiff scenes.** Near b/m = 60 /s the 1/60 s step meets the limit 2m/b "
                + "of both Euler forms; RK4 only moves it to 2.79m/b. For very strong drag use "
                + "the exact step (stable at any h), not a higher-order method.\n");
        int[] counts = bulkCounts(benchmarks);
        if (counts.length > 0) {
            int largest = counts[counts.length - 1];
            BenchmarkTable.Row lec = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_LECTURE, largest));
            BenchmarkTable.Row batch = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_BATCH, largest));
            BenchmarkTable.Row obj = benchmarks.find(BenchmarkTable.bulkName(
                    BenchmarkTable.BULK_OBJECTS, largest));
            if (lec != null && batch != null && obj != null) {
                md.append("- **Many particles.** At N = ").append(largest).append(" the "
                        + "packed batch form costs ").append(fix(batch.nanosPerParticleStep(), 2))
                        .append(" ns per particle-step, against ")
                        .append(fix(obj.nanosPerParticleStep(), 1)).append(" ns for Particle "
                        + "objects and ").append(fix(lec.nanosPerParticleStep(), 1))
                        .append(" ns for the lecture's style: scenes with thousands of particles "
                        + "should use `stepPacked`.\n");
            }
        }
        HitchStudy.Run raw = hitchRun(hitches, 2.0, SimulationClock.Mode.RAW_TPF, 2.0);
        HitchStudy.Run fixed = hitchRun(hitches, 2.0, SimulationClock.Mode.FIXED_STEP, 2.0);
        md.append("- **Frame hitches.** With 2 s frames at b/m = 2 /s, raw tpf lands ")
                .append(landingText(raw)).append(" m off; the fixed-step clock ")
                .append(landingText(fixed)).append(" m, at the price of ")
                .append(fix(fixed.droppedSeconds, 2)).append(" s of dropped time. Demos use "
                + "the fixed-step clock; raw tpf stays as the lesson's switch (`T`).\n");
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
            if (s.sweep.equals(sweep) && s.formula.equals("iterative")
                    && Math.abs(s.stepSeconds - h) < 1e-12 && s.linearRate == k) {
                return s.shots;
            }
        }
        return 0;
    }

    private static double miss(AimingStudy aiming, String sweep, String formula, double h,
            double k) {
        for (AimingStudy.Shot s : aiming.shots) {
            if (s.sweep.equals(sweep) && s.formula.equals(formula)
                    && Math.abs(s.stepSeconds - h) < 1e-12 && s.linearRate == k) {
                return s.missMetres;
            }
        }
        return Double.NaN;
    }

    private static HitchStudy.Run hitchRun(HitchStudy hitches, double k,
            SimulationClock.Mode mode, double hitch) {
        for (HitchStudy.Run r : hitches.runs) {
            if (r.linearRate == k && r.mode == mode && r.hitchSeconds == hitch) {
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

    private static String ratio(BenchmarkTable.Row row, BenchmarkTable.Row reference) {
        if (reference == null) {
            return "—";
        }
        return fix(row.nanosPerParticleStep() / reference.nanosPerParticleStep(), 2);
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
        Files.write(folder.resolve(name), text.toString().getBytes(StandardCharsets.UTF_8));
    }
}

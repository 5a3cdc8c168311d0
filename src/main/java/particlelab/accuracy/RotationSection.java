package particlelab.accuracy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.XYChart;
import particlelab.files.SafeFiles;
import particlelab.reference.CostMeter;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;


/**
 * The report's rotation section: runs {@link RotationStudy}, writes its CSV files and plot
 * into the report's folder and appends its section to {@code index.md}.
 */
public final class RotationSection {

    /** Header of {@code rotation_error.csv}. */
    public static final String ERROR_HEADER =
            "method,h_s,steps,angle_error_rad,orthogonality_error,ns_per_step";
    /** Header of {@code racket_drift.csv}. */
    public static final String DRIFT_HEADER =
            "method,h_s,steps,energy_drift,angular_momentum_drift";
    /** The error against cost plot. */
    public static final String ERROR_PLOT = "rotation-error.png";
    /** Every file the section writes, relative to the report's folder (index.md appended). */
    public static final List<String> FILES = Collections.unmodifiableList(Arrays.asList(
            "rotation_error.csv", "racket_drift.csv", ERROR_PLOT));
    /** The section's heading in {@code index.md}. */
    public static final String HEADING = "## Rotation: orientation methods and angular methods";

    private RotationSection() {
    }

    /**
     * Run the rotation study, write its files and append its section to {@code index.md}.
     *
     * @param config the report's size (not null; the timing loop's length comes from it)
     * @param meter the report's timing loop (not null)
     * @param folder the report's folder, where {@code index.md} already is (not null)
     * @throws IOException if a file cannot be written
     */
    public static void write(ReportConfig config, CostMeter meter, Path folder)
            throws IOException {
        if (config == null) {
            throw new IllegalArgumentException("config must not be null");
        }
        write(RotationStudy.run(meter), folder);
    }

    static void write(RotationStudy study, Path folder) throws IOException {
        writeText(folder, "rotation_error.csv", errorCsv(study));
        writeText(folder, "racket_drift.csv", driftCsv(study));
        writePlot(study, folder);
        SafeFiles.append(folder.resolve("index.md"), markdown(study));
    }

    // ---- CSV ----------------------------------------------------------------------------------

    /** The text of {@code rotation_error.csv}: one row per method and step. */
    static String errorCsv(RotationStudy study) {
        StringBuilder text = new StringBuilder(ERROR_HEADER).append('\n');
        for (RotationStudy.OrientationError e : study.errors) {
            text.append(name(e.method)).append(',').append(num(e.stepSeconds)).append(',')
                    .append(e.steps).append(',').append(num(e.angleError)).append(',')
                    .append(num(e.orthogonalityError)).append(',')
                    .append(num(study.nanosPerStep[e.method.ordinal()])).append('\n');
        }
        return text.toString();
    }

    /** The text of {@code racket_drift.csv}: one row per angular method and step. */
    static String driftCsv(RotationStudy study) {
        StringBuilder text = new StringBuilder(DRIFT_HEADER).append('\n');
        for (RotationStudy.Drift d : study.drifts) {
            text.append(name(d.method)).append(',').append(num(d.stepSeconds)).append(',')
                    .append(d.steps).append(',').append(num(d.energyDrift)).append(',')
                    .append(num(d.momentumDrift)).append('\n');
        }
        return text.toString();
    }

    // ---- plot ---------------------------------------------------------------------------------

    private static void writePlot(RotationStudy study, Path folder) throws IOException {
        String xTitle = "cost of the " + num(RotationStudy.ORIENTATION_SECONDS)
                + " s run: ns per step × steps (µs)";
        XYChart angle = Charts.create("Angle error after " + num(RotationStudy.ORIENTATION_SECONDS)
                + " s, h = 1/15 … 1/1920 s", xTitle, "angle error (rad)", true, true);
        XYChart orthogonality = Charts.create("Orthogonality error ‖RᵀR − I‖ after "
                + num(RotationStudy.ORIENTATION_SECONDS) + " s", xTitle,
                "‖RᵀR − I‖", true, true);
        int style = 0;
        for (Orientation method : Orientation.values()) {
            List<RotationStudy.OrientationError> line = study.errors(method);
            double[] cost = new double[line.size()];
            double[] a = new double[line.size()];
            double[] o = new double[line.size()];
            for (int i = 0; i < cost.length; ++i) {
                RotationStudy.OrientationError e = line.get(i);
                cost[i] = study.nanosPerStep[method.ordinal()] * e.steps / 1000.0;
                a[i] = e.angleError;
                o[i] = e.orthogonalityError;
            }
            Charts.line(angle, name(method), cost, Charts.floored(a), style);
            Charts.line(orthogonality, name(method), cost, Charts.floored(o), style);
            ++style;
        }
        Charts.saveGrid(Arrays.asList(angle, orthogonality), 1, 2, folder.resolve(ERROR_PLOT));
    }

    // ---- index.md -----------------------------------------------------------------------------

    /** The section's text for {@code index.md}: every number from the study. */
    static String markdown(RotationStudy study) {
        StringBuilder md = new StringBuilder();
        md.append(HEADING).append("\n\n");
        md.append("![angle and orthogonality error against cost](").append(ERROR_PLOT)
                .append(")\n\n");
        double omega = RotationStudy.OMEGA.length();
        md.append("A uniform sphere spinning at constant ω = 2π(1, 1, 1)/√3 rad/s (|ω| = ")
                .append(fix(omega, 4)).append(" rad/s) from R = I for ")
                .append(num(RotationStudy.ORIENTATION_SECONDS)).append(" s, stepped by each "
                + "orientation method of the rotation integrator (docs/numerics.md) at h = 1/")
                .append(Math.round(1.0 / study.steps[0])).append(" … 1/")
                .append(Math.round(1.0 / study.steps[study.steps.length - 1]))
                .append(" s: the angle between the nearest rotation to R and the exact "
                + "rotation, and ‖RᵀR − I‖, against the cost of the run (ns per step, timed "
                + "side by side in this run at h = 1/")
                .append(Math.round(1.0 / RotationStudy.COST_STEP_SECONDS))
                .append(" s, times the steps). Orders: least-squares slope of log(error) "
                + "against log(h) over h ≤ 1/")
                .append(Math.round(1.0 / RotationStudy.FIT_MAX_STEP_SECONDS))
                .append(" s, leaving out errors at or below round-off (")
                .append(fix(RotationStudy.ROUND_OFF_MARGIN, 0)).append(" × the exact step's "
                + "largest error: ").append(sci(study.roundOffFloor(true))).append(" rad, ")
                .append(sci(study.roundOffFloor(false))).append(" for ‖RᵀR − I‖).\n\n");
        int fine = study.steps.length - 1;
        md.append("| method | ns per step | cost / exact's | angle error at h = 1/")
                .append(Math.round(1.0 / study.steps[fine])).append(" s (rad) "
                + "| angle order | ‖RᵀR − I‖ at h = 1/")
                .append(Math.round(1.0 / study.steps[fine])).append(" s | ‖RᵀR − I‖ order |\n");
        md.append("|---|---|---|---|---|---|---|\n");
        double exactNanos = study.nanosPerStep[Orientation.EXACT.ordinal()];
        for (Orientation method : Orientation.values()) {
            RotationStudy.OrientationError last = study.errors(method).get(fine);
            double nanos = study.nanosPerStep[method.ordinal()];
            md.append("| ").append(name(method)).append(" | ").append(fix(nanos, 1))
                    .append(" | ").append(fix(nanos / exactNanos, 2)).append(" | ")
                    .append(sci(last.angleError)).append(" | ")
                    .append(order(study.order(method, true))).append(" | ")
                    .append(sci(last.orthogonalityError)).append(" | ")
                    .append(order(study.order(method, false))).append(" |\n");
        }
        md.append('\n').append(orientationSummary(study)).append("\n\n");

        md.append("### Tennis racket: energy and |L| drift\n\n");
        md.append("A torque-free box with moments (")
                .append(fix(RotationStudy.RACKET.getMoment(0), 0)).append(", ")
                .append(fix(RotationStudy.RACKET.getMoment(1), 0)).append(", ")
                .append(fix(RotationStudy.RACKET.getMoment(2), 0)).append(") kg·m² spun at ω = (")
                .append(num(RotationStudy.RACKET_OMEGA.x)).append(", ")
                .append(num(RotationStudy.RACKET_OMEGA.y)).append(", ")
                .append(num(RotationStudy.RACKET_OMEGA.z)).append(") rad/s, near its middle "
                + "axis, for ").append(num(RotationStudy.RACKET_SECONDS)).append(" s (it flips "
                + "over every few seconds), with the exact orientation step and each angular "
                + "method: relative drift (value at the end − at the start)/(at the start).\n\n");
        md.append("| h (s) | explicit: energy | explicit: abs(L) | midpoint: energy "
                + "| midpoint: abs(L) |\n");
        md.append("|---|---|---|---|---|\n");
        List<RotationStudy.Drift> explicit = study.drifts(Angular.EXPLICIT);
        List<RotationStudy.Drift> midpoint = study.drifts(Angular.IMPLICIT_MIDPOINT);
        for (int i = 0; i < explicit.size(); ++i) {
            RotationStudy.Drift e = explicit.get(i);
            RotationStudy.Drift m = midpoint.get(i);
            md.append("| 1/").append(Math.round(1.0 / e.stepSeconds)).append(" | ")
                    .append(sci(e.energyDrift)).append(" | ").append(sci(e.momentumDrift))
                    .append(" | ").append(sci(m.energyDrift)).append(" | ")
                    .append(sci(m.momentumDrift)).append(" |\n");
        }
        md.append('\n').append(racketSummary(study)).append("\n\n");
        md.append("Files of this section, with their fixed headers: `rotation_error.csv` (`")
                .append(ERROR_HEADER).append("`), `racket_drift.csv` (`").append(DRIFT_HEADER)
                .append("`).\n\n");
        return md.toString();
    }

    /** The generated sentence on the orientation lines. */
    static String orientationSummary(RotationStudy study) {
        StringBuilder s = new StringBuilder("Measured angle orders: ");
        Orientation[] methods = Orientation.values();
        for (int i = 0; i < methods.length; ++i) {
            s.append(i == 0 ? "" : i == methods.length - 1 ? " and " : ", ")
                    .append(name(methods[i])).append(' ')
                    .append(order(study.order(methods[i], true)));
        }
        s.append(". ");
        double euler = study.order(Orientation.EULER, true);
        double polar = study.order(Orientation.POLAR, true);
        if (Math.abs(euler - polar) < 0.1) {
            s.append("For constant ω the plain Euler matrix I + h·[ω]× is a rotation by "
                    + "atan(|ω|h) times a uniform stretch across ω, so its nearest rotation is "
                    + "exactly the polar method's and its angle error is the same, second "
                    + "order; its fault is the shape: ‖RᵀR − I‖ = √2·((1 + (|ω|h)²)ⁿ − 1) has "
                    + "order ").append(order(study.order(Orientation.EULER, false)))
                    .append(" while every cure keeps R a rotation to round-off. ");
        }
        s.append("Gram–Schmidt favours the x axis and is first order off it; quaternion and "
                + "polar lag by about (|ω|h)³/12 and (|ω|h)³/3 per step, second order");
        s.append(Double.isNaN(study.order(Orientation.EXACT, true))
                ? "; the exact step's error does not fall with h: it is round-off."
                : "; the exact step's error falls with h, so it is not round-off here.");
        return s.toString();
    }

    /** The generated sentence on the racket table. */
    static String racketSummary(RotationStudy study) {
        List<RotationStudy.Drift> explicit = study.drifts(Angular.EXPLICIT);
        RotationStudy.Drift coarse = explicit.get(0);
        RotationStudy.Drift fine = explicit.get(explicit.size() - 1);
        boolean allGain = true;
        for (RotationStudy.Drift d : explicit) {
            allGain &= d.energyDrift > 0.0;
        }
        RotationStudy.Drift before = explicit.get(explicit.size() - 2);
        return "Explicit Euler " + (allGain ? "gains energy at every step size" : "drifts")
                + ", from " + sci(coarse.energyDrift) + " at h = 1/"
                + Math.round(1.0 / coarse.stepSeconds) + " s to " + sci(fine.energyDrift)
                + " at 1/" + Math.round(1.0 / fine.stepSeconds) + " s (halving h from 1/"
                + Math.round(1.0 / before.stepSeconds) + " s divides it by "
                + fix(before.energyDrift / fine.energyDrift, 2) + ": first order); implicit "
                + "midpoint keeps energy and |L| to float round-off, at most "
                + sci(study.worstDrift(Angular.IMPLICIT_MIDPOINT, true)) + " and "
                + sci(study.worstDrift(Angular.IMPLICIT_MIDPOINT, false))
                + " in size over the sweep.";
    }

    // ---- helpers ------------------------------------------------------------------------------

    /** An order with 2 decimals, or {@code round-off} where none was fitted. */
    static String order(double value) {
        return Double.isNaN(value) ? "round-off" : fix(value, 2);
    }

    static String name(Orientation method) {
        return method.name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    static String name(Angular method) {
        return method == Angular.IMPLICIT_MIDPOINT ? "midpoint"
                : method.name().toLowerCase(Locale.ROOT);
    }

    static String num(double value) {
        return CollisionSection.num(value);
    }

    static String num(float value) {
        return CollisionSection.num(value);
    }

    static String sci(double value) {
        return CollisionSection.sci(value);
    }

    static String fix(double value, int decimals) {
        return CollisionSection.fix(value, decimals);
    }

    private static void writeText(Path folder, String name, CharSequence text)
            throws IOException {
        SafeFiles.write(folder.resolve(name), text, false);
    }
}

package particlelab.accuracy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.XYChart;
import particlelab.files.SafeFiles;
import particlelab.reference.CostMeter;
import particlelab.world.Detection;
import particlelab.world.World;


/**
 * The report's collision section: runs {@link CollisionStudy}, writes its CSV files and plots
 * into the report's folder and appends its section to {@code index.md}.
 */
public final class CollisionSection {

    /** Header of {@code tunnelling.csv}. */
    public static final String TUNNELLING_HEADER = "v_h_over_2r_plus_d,shots,overlap_misses,"
            + "overlap_miss_rate,swept_misses,predicted_miss_probability,overlap_low_95,"
            + "overlap_high_95";
    /** Header of {@code collision_cost.csv}. */
    public static final String COST_HEADER =
            "detection,balls,ns_per_step,bytes_per_step,contacts_per_step,cap_hits,"
            + "cost_over_overlap";
    /** Header of {@code bounce_error.csv}. */
    public static final String BOUNCE_HEADER = "detection,h_s,impact,t_s,ideal_t_s,t_error_s,"
            + "apex_m,ideal_apex_m,apex_error_m";
    /** The tunnelling plot. */
    public static final String TUNNELLING_PLOT = "tunnelling.png";
    /** The bounce error plot. */
    public static final String BOUNCE_PLOT = "bounce-error.png";
    /** Every file the section writes, relative to the report's folder (index.md appended). */
    public static final List<String> FILES = Collections.unmodifiableList(Arrays.asList(
            "tunnelling.csv", "collision_cost.csv", "bounce_error.csv", TUNNELLING_PLOT,
            BOUNCE_PLOT));
    /** The section's heading in {@code index.md}. */
    public static final String HEADING = "## Collisions: the overlap test against the swept test";

    private CollisionSection() {
    }

    /**
     * Run the collision study, write its files and append its section to {@code index.md}.
     *
     * @param config the report's size (not null)
     * @param meter the report's timing loop (not null)
     * @param folder the report's folder, where {@code index.md} already is (not null)
     * @throws IOException if a file cannot be written
     */
    public static void write(ReportConfig config, CostMeter meter, Path folder)
            throws IOException {
        write(CollisionStudy.run(config, meter), folder);
    }

    static void write(CollisionStudy study, Path folder) throws IOException {
        writeCsvFiles(study, folder);
        writePlots(study, folder);
        SafeFiles.append(folder.resolve("index.md"), markdown(study));
    }

    // ---- CSV ----------------------------------------------------------------------------------

    private static void writeCsvFiles(CollisionStudy study, Path folder) throws IOException {
        StringBuilder text = new StringBuilder(TUNNELLING_HEADER).append('\n');
        for (CollisionStudy.Tunnel t : study.tunnels) {
            double[] interval = t.overlapInterval();
            text.append(num(t.travelRatio)).append(',').append(t.shots).append(',')
                    .append(t.overlapMisses).append(',').append(num(t.overlapRate()))
                    .append(',').append(t.sweptMisses).append(',').append(num(t.predicted))
                    .append(',').append(num(interval[0])).append(',').append(num(interval[1]))
                    .append('\n');
        }
        writeText(folder, "tunnelling.csv", text);

        text = new StringBuilder(COST_HEADER).append('\n');
        double overlapNanos = cost(study, Detection.OVERLAP).nanosPerStep;
        for (CollisionStudy.Cost c : study.costs) {
            text.append(name(c.detection)).append(',').append(CollisionStudy.COST_BALLS)
                    .append(',').append(num(c.nanosPerStep)).append(',')
                    .append(num(c.bytesPerStep)).append(',').append(num(c.contactsPerStep))
                    .append(',').append(c.capHits).append(',')
                    .append(num(c.nanosPerStep / overlapNanos)).append('\n');
        }
        writeText(folder, "collision_cost.csv", text);

        text = new StringBuilder(BOUNCE_HEADER).append('\n');
        for (CollisionStudy.Impact i : study.impacts) {
            text.append(name(i.detection)).append(',').append(num(i.stepSeconds)).append(',')
                    .append(i.number).append(',').append(num(i.timeSeconds)).append(',')
                    .append(num(i.idealTimeSeconds)).append(',').append(num(i.timeError()))
                    .append(',').append(num(i.apexMetres)).append(',')
                    .append(num(i.idealApexMetres)).append(',').append(num(i.apexError()))
                    .append('\n');
        }
        writeText(folder, "bounce_error.csv", text);
    }

    // ---- plots --------------------------------------------------------------------------------

    private static void writePlots(CollisionStudy study, Path folder) throws IOException {
        int n = study.tunnels.size();
        double[] ratio = new double[n];
        double[] overlap = new double[n];
        double[] swept = new double[n];
        double[] low = new double[n];
        double[] high = new double[n];
        for (int i = 0; i < n; ++i) {
            CollisionStudy.Tunnel t = study.tunnels.get(i);
            ratio[i] = t.travelRatio;
            overlap[i] = t.overlapRate();
            swept[i] = (double) t.sweptMisses / t.shots;
            low[i] = Math.max(0.0, t.predicted - CollisionStudy.Z95 * t.predictedSigma());
            high[i] = t.predicted + CollisionStudy.Z95 * t.predictedSigma();
        }
        int fine = 200;
        double first = ratio[0];
        double last = ratio[n - 1];
        double[] curveX = new double[fine];
        double[] curveY = new double[fine];
        for (int i = 0; i < fine; ++i) {
            curveX[i] = first + (last - first) * i / (fine - 1);
            curveY[i] = Math.max(0.0, 1.0 - 1.0 / curveX[i]);
        }
        XYChart tunnel = Charts.create("Tunnelling through a thin wall: "
                + study.tunnels.get(0).shots + " random-phase shots per speed",
                "v·h / (2r + D)", "miss rate", false, false);
        Charts.dashed(tunnel, "1 − (2r+D)/(v·h)", curveX, curveY, 0);
        Charts.dashed(tunnel, "± 1.96 binomial σ", ratio, low, 7);
        Charts.dashed(tunnel, " ", ratio, high, 7).setShowInLegend(false);
        Charts.markers(tunnel, "overlap test", ratio, overlap, 1);
        Charts.markers(tunnel, "swept test", ratio, swept, 2);
        Charts.save(tunnel, folder.resolve(TUNNELLING_PLOT));

        XYChart bounce = Charts.create("Bouncing ball (h0 = "
                + num(CollisionStudy.BOUNCE_HEIGHT_METRES) + " m, e = "
                + num(CollisionStudy.BOUNCE_RESTITUTION) + "): worst error of the first "
                + CollisionStudy.BOUNCE_IMPACTS + " impacts", "step h (s)",
                "worst error (s or m)", true, true);
        int style = 0;
        for (Detection detection : new Detection[] {Detection.OVERLAP, Detection.SWEPT}) {
            List<CollisionStudy.BounceError> line = errors(study, detection);
            double[] h = new double[line.size()];
            double[] time = new double[line.size()];
            double[] apex = new double[line.size()];
            for (int i = 0; i < h.length; ++i) {
                h[i] = line.get(i).stepSeconds;
                time[i] = line.get(i).worstTimeError;
                apex[i] = line.get(i).worstApexError;
            }
            Charts.line(bounce, name(detection) + ": time (s)", h, Charts.floored(time),
                    style++);
            Charts.line(bounce, name(detection) + ": apex (m)", h, Charts.floored(apex),
                    style++);
        }
        // first order through the coarsest swept apex error, for the eye
        List<CollisionStudy.BounceError> sweptLine = errors(study, Detection.SWEPT);
        CollisionStudy.BounceError coarsest = sweptLine.get(0);
        double[] ends = {coarsest.stepSeconds, sweptLine.get(sweptLine.size() - 1).stepSeconds};
        double[] slope = {coarsest.worstApexError, coarsest.worstApexError * ends[1] / ends[0]};
        Charts.dashed(bounce, "∝ h", ends, slope, 7);
        bounce.getStyler().setXAxisMin(1e-4);
        bounce.getStyler().setXAxisMax(0.1);
        Charts.save(bounce, folder.resolve(BOUNCE_PLOT));
    }

    // ---- index.md -----------------------------------------------------------------------------

    static String markdown(CollisionStudy study) {
        StringBuilder md = new StringBuilder();
        double band = 2.0 * CollisionStudy.SHOT_RADIUS_METRES
                + CollisionStudy.WALL_THICKNESS_METRES;
        md.append(HEADING).append("\n\n");
        md.append("The world's two detection tests (docs/collisions.md): the **overlap test** "
                + "looks at the step's end, the **swept test** (intersection test) solves for "
                + "the time of impact along the step's straight segment.\n\n");

        md.append("### Tunnelling\n\n");
        md.append("![miss rate against v·h/(2r+D)](").append(TUNNELLING_PLOT).append(")\n\n");
        int shots = study.tunnels.get(0).shots;
        md.append("The scene of `particle-lab tunnel`: shots of radius r = ")
                .append(num(CollisionStudy.SHOT_RADIUS_METRES)).append(" m at a wall D = ")
                .append(num(CollisionStudy.WALL_THICKNESS_METRES)).append(" m thick (2r + D = ")
                .append(fix(band, 2)).append(" m), h = 1/")
                .append(Math.round(1 / CollisionStudy.STEP_SECONDS)).append(" s, ")
                .append(shots).append(" shots per speed, each from a random phase (row i, "
                + "from 0, uses seed ")
                .append(CollisionStudy.SEED).append(" + i; `particle-lab tunnel "
                + "--speed V --radius r --thickness D --shots N --seed S` gives the same "
                + "counts). Measured overlap miss rate with its 95 % Wilson interval beside "
                + "the formula `max(0, 1 − (2r+D)/(v·h))`; at 95 % about one row in twenty "
                + "lies outside by chance.\n\n");
        md.append("| v·h/(2r+D) | v (m/s) | formula | overlap misses | measured rate "
                + "| 95 % interval | formula inside | swept misses |\n");
        md.append("|---|---|---|---|---|---|---|---|\n");
        int inside = 0;
        int sweptTotal = 0;
        for (CollisionStudy.Tunnel t : study.tunnels) {
            double[] interval = t.overlapInterval();
            boolean in = t.predicted >= interval[0] && t.predicted <= interval[1];
            inside += in ? 1 : 0;
            sweptTotal += t.sweptMisses;
            md.append("| ").append(num(t.travelRatio)).append(" | ").append(fix(t.speed, 2))
                    .append(" | ").append(fix(t.predicted, 4)).append(" | ")
                    .append(t.overlapMisses).append(" | ").append(fix(t.overlapRate(), 4))
                    .append(" | ").append(fix(interval[0], 4)).append("–")
                    .append(fix(interval[1], 4)).append(" | ").append(in ? "yes" : "**no**")
                    .append(" | ").append(t.sweptMisses).append(" |\n");
        }
        md.append("\nThe formula lies inside the interval in ").append(inside).append(" of ")
                .append(study.tunnels.size()).append(" rows; the swept test missed ")
                .append(sweptTotal).append(" of ").append(shots * study.tunnels.size())
                .append(" shots. Below v·h = 2r + D every shot has a step end inside the "
                + "wall, so the overlap test cannot miss; above it the miss rate climbs "
                + "towards 1.");
        for (CollisionStudy.Tunnel t : study.tunnels) {
            if (t.travelRatio <= 1.0 && t.overlapMisses > 0) {
                md.append(" At v·h/(2r+D) = ").append(num(t.travelRatio)).append(", where "
                        + "the formula says 0, ").append(t.overlapMisses).append(" of ")
                        .append(t.shots).append(" shots got through: their only step end "
                        + "inside the wall lay within the world's overlap slop of the far "
                        + "face, moving out, a contact that needs no work and so is never "
                        + "resolved. The slop (`World`'s penetration tolerance) narrows the "
                        + "band the overlap test resolves a little below 2r + D.");
            }
        }
        md.append("\n\n");

        md.append("### Cost per step\n\n");
        CollisionStudy.Cost overlap = cost(study, Detection.OVERLAP);
        CollisionStudy.Cost swept = cost(study, Detection.SWEPT);
        md.append(CollisionStudy.COST_BALLS).append(" balls of radius ")
                .append(num(CollisionStudy.COST_RADIUS_METRES)).append(" m bounce on the "
                + "ground, off walls at x = ±").append(num(CollisionStudy.COST_HALF_WIDTH_METRES))
                .append(" m and off each other (every pair tested each step), h = 1/")
                .append(Math.round(1 / CollisionStudy.STEP_SECONDS)).append(" s, restarted "
                + "from the launch every ").append(CollisionStudy.COST_RESTART_STEPS)
                .append(" steps. Timed side by side in this JVM, the two tests alternating ")
                .append(CollisionStudy.COST_PASSES).append(" times, each test's fastest pass "
                + "kept; contacts per step counted in "
                + "a separate untimed run of ").append(study.costCountSteps)
                .append(" steps.\n\n");
        md.append("| detection | ns per world step | bytes per step | contacts per step "
                + "| impact cap reached | cost / overlap |\n|---|---|---|---|---|---|\n");
        for (CollisionStudy.Cost c : study.costs) {
            md.append("| ").append(name(c.detection)).append(" | ")
                    .append(fix(c.nanosPerStep, 0)).append(" | ")
                    .append(fix(c.bytesPerStep, 2)).append(" | ")
                    .append(fix(c.contactsPerStep, 3)).append(" | ").append(c.capHits)
                    .append(" | ")
                    .append(fix(c.nanosPerStep / overlap.nanosPerStep, 2)).append(" |\n");
        }
        md.append("\nThe swept test costs ").append(fix(swept.nanosPerStep
                / overlap.nanosPerStep, 2)).append("× the overlap test per step here: it solves "
                + "a quadratic per pair instead of comparing a distance, and after each "
                + "impact it moves the bodies to that moment and looks again, so its cost "
                + "grows with the impacts per step. Read the ratio, not the absolute times.");
        if (swept.capHits > 0) {
            md.append(" In the counted run the swept world reached its cap of ")
                    .append(World.DEFAULT_MAX_IMPACTS_PER_STEP).append(" impacts in one step ")
                    .append(swept.capHits).append(" times; the bodies with impacts left "
                    + "then wait at their last contact for the rest of that step.");
        }
        md.append("\n\n");

        md.append("### Bounce sequence against h\n\n");
        md.append("![bounce errors against h](").append(BOUNCE_PLOT).append(")\n\n");
        md.append("A ball dropped from h0 = ").append(num(CollisionStudy.BOUNCE_HEIGHT_METRES))
                .append(" m, e = ").append(num(CollisionStudy.BOUNCE_RESTITUTION))
                .append(", no threshold, no resting fix. Worst error over the first ")
                .append(CollisionStudy.BOUNCE_IMPACTS).append(" impacts of the impact time "
                + "(ideal t_1 = t0, t_(k+1) = t_k + 2·t0·e^k, t0 = √(2·h0/g)) and of the apex "
                + "after it (ideal e^(2k)·h0, the highest step end). Every impact in "
                + "`bounce_error.csv`.\n\n");
        md.append("| h (s) | overlap: time (s) | overlap: apex (m) | swept: time (s) "
                + "| swept: apex (m) |\n|---|---|---|---|---|\n");
        List<CollisionStudy.BounceError> overlapErrors = errors(study, Detection.OVERLAP);
        List<CollisionStudy.BounceError> sweptErrors = errors(study, Detection.SWEPT);
        for (int i = 0; i < overlapErrors.size(); ++i) {
            CollisionStudy.BounceError o = overlapErrors.get(i);
            CollisionStudy.BounceError s = sweptErrors.get(i);
            md.append("| 1/").append(Math.round(1 / o.stepSeconds)).append(" | ")
                    .append(sci(o.worstTimeError)).append(" | ").append(sci(o.worstApexError))
                    .append(" | ").append(sci(s.worstTimeError)).append(" | ")
                    .append(sci(s.worstApexError)).append(" |\n");
        }
        md.append("| **fitted order** |");
        for (Detection detection : new Detection[] {Detection.OVERLAP, Detection.SWEPT}) {
            CollisionStudy.BounceOrder order = order(study, detection);
            md.append(' ').append(fix(order.timeOrder, 2)).append(" | ")
                    .append(fix(order.apexOrder, 2)).append(" |");
        }
        double lowest = Double.POSITIVE_INFINITY;
        double highest = Double.NEGATIVE_INFINITY;
        for (CollisionStudy.BounceOrder o : study.bounceOrders) {
            lowest = Math.min(lowest, Math.min(o.timeOrder, o.apexOrder));
            highest = Math.max(highest, Math.max(o.timeOrder, o.apexOrder));
        }
        md.append("\n\nFitted order: least-squares slope of log(error) against log(h) through "
                + "all ").append(study.bounceSteps.length).append(" step sizes (the bounce "
                + "part always uses the full sweep's steps, whatever the report's size). "
                + "Where in its step each impact falls changes with h, so the errors zigzag "
                + "around the trend. The orders lie between ").append(fix(lowest, 2))
                .append(" and ").append(fix(highest, 2)).append(": with either test the "
                + "bounce sequence converges at the first order of the Euler step itself. "
                + "The swept test finds each impact inside its step; the overlap test finds "
                + "it at the step's end, inside the ground, and pushes the ball out.\n\n");
        md.append("Files of this section, with their fixed headers: `tunnelling.csv` (`")
                .append(TUNNELLING_HEADER).append("`), `collision_cost.csv` (`")
                .append(COST_HEADER).append("`), `bounce_error.csv` (`").append(BOUNCE_HEADER)
                .append("`).\n\n");
        return md.toString();
    }

    // ---- helpers ------------------------------------------------------------------------------

    static CollisionStudy.Cost cost(CollisionStudy study, Detection detection) {
        for (CollisionStudy.Cost c : study.costs) {
            if (c.detection == detection) {
                return c;
            }
        }
        throw new IllegalStateException("no cost measured for " + detection);
    }

    static CollisionStudy.BounceOrder order(CollisionStudy study, Detection detection) {
        for (CollisionStudy.BounceOrder o : study.bounceOrders) {
            if (o.detection == detection) {
                return o;
            }
        }
        throw new IllegalStateException("no bounce order for " + detection);
    }

    static List<CollisionStudy.BounceError> errors(CollisionStudy study, Detection detection) {
        List<CollisionStudy.BounceError> result = new ArrayList<>();
        for (CollisionStudy.BounceError b : study.bounceErrors) {
            if (b.detection == detection) {
                result.add(b);
            }
        }
        return result;
    }

    static String name(Detection detection) {
        return detection.name().toLowerCase(Locale.ROOT);
    }

    /** A number for CSV: full precision, Java's spelling of NaN and Infinity. */
    static String num(double value) {
        if (Double.isNaN(value) || Double.isInfinite(value)) {
            return Double.toString(value);
        }
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }

    static String num(float value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Float.toString(value);
    }

    static String sci(double value) {
        return String.format(Locale.ROOT, "%.2e", value);
    }

    static String fix(double value, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", value);
    }

    private static void writeText(Path folder, String name, CharSequence text)
            throws IOException {
        SafeFiles.write(folder.resolve(name), text, false);
    }
}

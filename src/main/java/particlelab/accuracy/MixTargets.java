package particlelab.accuracy;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import org.knowm.xchart.XYChart;

/**
 * The report's speed targets for every force mix: a table of each path's cost against the
 * primitive loop for the same mix (rows {@code single/<mix>/<path>} and
 * {@code bulk/<mix>/<path>/<N>} of {@code benchmarks.csv}) with the targets as columns, and a
 * plot of the cost per particle-step against N, one panel per mix, one line per path.
 */
final class MixTargets {

    /** The plot's file in the report's folder. */
    static final String PLOT = "mixes.png";
    /** Target: one particle through {@code step(Particle, h)} at most this × the loop. */
    static final double PER_PARTICLE_VS_PRIMITIVE = 2.0;
    /** Target: one particle through {@code step(Particle, h)} at least this × faster. */
    static final double PER_PARTICLE_VS_LECTURE = 5.0;
    /** Target: the batch form at most this × the primitive loop. */
    static final double BATCH_VS_PRIMITIVE = 1.5;
    /**
     * The particle counts at which the lecture-style target is set (1 and 1000 objects: the
     * lecture style against {@code step(Particle, h)} of the same N).
     */
    static final List<Integer> PER_PARTICLE_COUNTS = List.of(1, 1000);
    /**
     * The one count at which "objects ≤ 2× primitive" is judged: one particle against the
     * one-particle primitive loop, the same chain of dependent steps. Against the bulk loop
     * (1000 particles overlapping, vectorised) a step through an object cannot get near, and
     * against the one-particle loop 1000 objects would compare two different workloads.
     */
    static final int OBJECTS_VS_PRIMITIVE_COUNT = 1;
    /** Allocation below this (bytes per particle-step) counts as none: counter granularity. */
    static final double NO_BYTES = 0.5;

    /** The plot's paths, in its order: the report's bulk paths, then the Vector API batch. */
    private static final List<String> PLOT_PATHS = List.of(BenchmarkTable.PATH_LECTURE,
            BenchmarkTable.PATH_OBJECTS, BenchmarkTable.PATH_BATCH,
            BenchmarkTable.PATH_PRIMITIVE, BenchmarkTable.PATH_BATCH_VECTOR);
    private static final String[] PATH_LABELS = {"lecture style (new Vector3f each step)",
        "shared integrator, step(Particle, h)", "shared integrator, stepPacked",
        "hand-written primitive loop", "stepPacked on the Vector API (opt-in)"};

    private MixTargets() {
    }

    /**
     * Append the targets' table and its summary to the report.
     *
     * @param md the report's text (modified)
     * @param table the benchmark rows (not modified)
     * @param fromJmh true if the rows come from JMH (forked JVMs), false if timed in-process
     */
    static void appendTable(StringBuilder md, BenchmarkTable table, boolean fromJmh) {
        md.append("### Speed targets for every force mix\n\n");
        md.append("![cost per particle-step against N, one panel per mix](").append(PLOT)
                .append(")\n\n");
        md.append("Each force mix along every path: one particle (N = 1, ")
                .append(OneParticleMixScene.STEPS_PER_LAUNCH).append(" dependent steps per "
                + "call: latency) and N particles (one step of all N per call: throughput), "
                + "h = ").append(SpeedVsErrorReport.stepText(BulkScene.STEP_SECONDS))
                .append(", ").append(num(ForceMix.MASS_KG)).append(" kg. Mixes: ");
        for (ForceMix mix : ForceMix.values()) {
            md.append('`').append(mix.id()).append("` ").append(mix.label());
            if (mix.linearDrag() > 0f) {
                md.append(", b = ").append(num(mix.linearDrag())).append(" kg/s");
            }
            if (mix.quadraticDrag() > 0f) {
                md.append(", c = ").append(num(mix.quadraticDrag())).append(" kg/m");
            }
            if (mix.thrustNewtons() > 0f) {
                md.append(", k = ").append(num(mix.thrustNewtons())).append(" N");
            }
            md.append("; ");
        }
        md.append("each relaunched every ").append(BulkScene.STEPS_PER_LAUNCH)
                .append(" steps. Columns \"÷ primitive\" divide a path's time by the "
                + "hand-written primitive loop's for the same mix and N (1 = as fast; less "
                + "than 1 = faster than the loop), \"lecture ÷ objects\" is how many times "
                + "faster `step(Particle, h)` is than the lecture's allocating style. The "
                + "targets: one particle through `step(Particle, h)` at most ")
                .append(num(PER_PARTICLE_VS_PRIMITIVE)).append("× the one-particle primitive "
                + "loop (judged at N = ").append(OBJECTS_VS_PRIMITIVE_COUNT).append(" only: "
                + "the same chain of dependent steps, written by hand; at N = 1000 the "
                + "primitive loop overlaps the particles and vectorises, a different "
                + "workload) and at least ").append(num(PER_PARTICLE_VS_LECTURE))
                .append("× faster than the lecture style (N = ").append(countList())
                .append("); the batch `stepPacked` at most ")
                .append(num(BATCH_VS_PRIMITIVE)).append("× the primitive loop at every N; both "
                + "0 bytes per step. \"Vector API batch\" is `stepPacked` in a JVM started "
                + "with `--add-modules=jdk.incubator.vector` (gravity and linear drag only; "
                + "the app leaves it off unless asked, see docs/speed.md); \"batch\" is the "
                + "form the app runs by default. \"—\": the target is not set at that N or "
                + "the row was not measured. \"").append(SpeedSpreads.TOO_NOISY).append("\": "
                + "a path the verdict needs spread by more than ")
                .append(num(SpeedSpreads.SPREAD_BOUND)).append("× (max ÷ min) over its "
                + "rounds. These ratios divide medians timed one after another; \"Side by "
                + "side, with spreads\" below takes the same targets' ratios within rotating "
                + "rounds.\n\n");
        md.append("| mix | N | primitive loop (ns) | lecture ÷ primitive | objects ÷ primitive "
                + "| batch ÷ primitive | Vector API batch ÷ primitive | lecture ÷ objects "
                + "| bytes/step objects, batch | objects ≤ ")
                .append(num(PER_PARTICLE_VS_PRIMITIVE)).append("× primitive | objects ≥ ")
                .append(num(PER_PARTICLE_VS_LECTURE)).append("× faster than lecture | batch ≤ ")
                .append(num(BATCH_VS_PRIMITIVE)).append("× primitive | Vector API batch ≤ ")
                .append(num(BATCH_VS_PRIMITIVE)).append("× primitive | 0 bytes |\n"
                + "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        Tally perParticle = new Tally();
        Tally lecture = new Tally();
        Tally batch = new Tally();
        Tally vectorBatch = new Tally();
        Tally bytes = new Tally();
        for (ForceMix mix : ForceMix.values()) {
            List<Integer> counts = new ArrayList<>();
            counts.add(1);
            counts.addAll(bulkCounts(table, mix));
            for (int count : counts) {
                BenchmarkTable.Row prim = row(table, mix, BenchmarkTable.PATH_PRIMITIVE, count);
                BenchmarkTable.Row lec = row(table, mix, BenchmarkTable.PATH_LECTURE, count);
                BenchmarkTable.Row obj = row(table, mix, BenchmarkTable.PATH_OBJECTS, count);
                BenchmarkTable.Row bat = count == 1 ? null
                        : row(table, mix, BenchmarkTable.PATH_BATCH, count);
                BenchmarkTable.Row vec = count == 1 ? null
                        : row(table, mix, BenchmarkTable.PATH_BATCH_VECTOR, count);
                if (prim == null || obj == null) {
                    continue;
                }
                String where = mix.id() + " N = " + count;
                boolean noisy = noisy(prim) || noisy(obj);
                boolean lectureNoisy = noisy || noisy(lec);
                boolean batchNoisy = noisy(prim) || noisy(bat);
                boolean vectorNoisy = noisy(prim) || noisy(vec);
                double objects = ratio(obj, prim);
                double overLecture = ratio(lec, obj);
                double batched = ratio(bat, prim);
                double vectorised = ratio(vec, prim);
                boolean perParticleSet = PER_PARTICLE_COUNTS.contains(count);
                boolean objectsSet = count == OBJECTS_VS_PRIMITIVE_COUNT;
                md.append("| ").append(mix.id()).append(" | ").append(count).append(" | ")
                        .append(fix(prim.nanosPerParticleStep(), 3)).append(" | ")
                        .append(times(ratio(lec, prim))).append(" | ")
                        .append(times(objects)).append(" | ")
                        .append(times(batched)).append(" | ")
                        .append(times(vectorised)).append(" | ")
                        .append(times(overLecture)).append(" | ")
                        .append(fix(obj.bytesPerStep(), 1)).append(", ")
                        .append(bat == null ? "—" : fix(bat.bytesPerStep(), 1)).append(" | ")
                        .append(objectsSet ? perParticle.judge(
                                objects <= PER_PARTICLE_VS_PRIMITIVE, objects, where, noisy)
                                : "—")
                        .append(" | ")
                        .append(perParticleSet && lec != null ? lecture.judge(
                                overLecture >= PER_PARTICLE_VS_LECTURE, overLecture, where,
                                lectureNoisy) : "—").append(" | ")
                        .append(bat != null ? batch.judge(batched <= BATCH_VS_PRIMITIVE,
                                batched, where, batchNoisy) : "—").append(" | ")
                        .append(vec != null ? vectorBatch.judge(
                                vectorised <= BATCH_VS_PRIMITIVE, vectorised, where,
                                vectorNoisy) : "—")
                        .append(" | ");
                boolean measured = !Double.isNaN(obj.bytesPerStep())
                        && (bat == null || !Double.isNaN(bat.bytesPerStep()));
                double most = Math.max(Math.max(obj.bytesPerStep(),
                        bat == null ? 0.0 : bat.bytesPerStep()),
                        vec == null || Double.isNaN(vec.bytesPerStep()) ? 0.0
                                : vec.bytesPerStep());
                md.append(measured ? bytes.judge(most < NO_BYTES, most, where, false)
                        : "unknown")
                        .append(" |\n");
            }
        }
        md.append("\nMet in this run: objects ≤ ").append(num(PER_PARTICLE_VS_PRIMITIVE))
                .append("× primitive ").append(perParticle.summary(true, "×"))
                .append("; objects ≥ ").append(num(PER_PARTICLE_VS_LECTURE))
                .append("× faster than lecture ").append(lecture.summary(false, "×"))
                .append("; batch ≤ ").append(num(BATCH_VS_PRIMITIVE)).append("× primitive ")
                .append(batch.summary(true, "×")).append("; Vector API batch ≤ ")
                .append(num(BATCH_VS_PRIMITIVE)).append("× primitive ")
                .append(vectorBatch.summary(true, "×")).append("; 0 bytes per step ")
                .append(bytes.summary(true, " bytes"))
                .append(". The primitive loops are written per mix, folded by hand "
                + "(V ← (1 − h·σ)·V + h·g, one pass per axis when σ is a constant, one pass "
                + "over the particles with a square root when it depends on |V|) and check "
                + "nothing; the shared paths refuse to return a NaN or an infinity.")
                .append(fromJmh ? " Each JMH benchmark ran in its own forked JVM, so the "
                        + "shared integrator saw one mix at a time.\n\n"
                        : " The mixes run after the gravity + linear drag rows above, in one "
                        + "JVM, so the shared integrator has seen every mix by then, as in a "
                        + "session that opens several demos.\n\n");
    }

    /**
     * Draw the cost per particle-step against N: one panel per mix, one line per path.
     *
     * @param table the benchmark rows (not modified)
     * @param folder the report's folder (not null)
     * @throws IOException if the plot cannot be written
     */
    static void writePlot(BenchmarkTable table, Path folder) throws IOException {
        List<XYChart> charts = new ArrayList<>();
        for (ForceMix mix : ForceMix.values()) {
            XYChart chart = Charts.create("Cost per particle-step: " + mix.label(),
                    "particles N", "ns per particle-step", true, true);
            chart.getStyler().setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout
                    .Vertical);
            List<Integer> counts = bulkCounts(table, mix);
            for (int p = 0; p < PLOT_PATHS.size(); ++p) {
                List<double[]> points = new ArrayList<>();
                for (int count : counts) {
                    BenchmarkTable.Row row = row(table, mix, PLOT_PATHS.get(p), count);
                    if (row != null && row.nanosPerParticleStep() > 0.0) {
                        points.add(new double[] {count, row.nanosPerParticleStep()});
                    }
                }
                double[] n = new double[points.size()];
                double[] ns = new double[points.size()];
                for (int i = 0; i < n.length; ++i) {
                    n[i] = points.get(i)[0];
                    ns[i] = points.get(i)[1];
                }
                if (n.length == 0 && p == PLOT_PATHS.size() - 1) {
                    // the Vector API batch exists only for some mixes and JVMs: no line
                    continue;
                }
                if (n.length == 0) {
                    // XChart refuses an empty chart: keep the panel, with the floor's point
                    n = new double[] {1000};
                    ns = new double[] {Charts.LOG_FLOOR};
                }
                Charts.line(chart, PATH_LABELS[p], n, ns, p);
            }
            charts.add(chart);
        }
        Charts.saveGrid(charts, 2, 2, folder.resolve(PLOT));
    }

    /** The N of a mix's bulk rows in the table, ascending. */
    static List<Integer> bulkCounts(BenchmarkTable table, ForceMix mix) {
        TreeSet<Integer> counts = new TreeSet<>();
        String prefix = "bulk/" + mix.id() + "/";
        for (BenchmarkTable.Row row : table.rows()) {
            String name = row.name();
            int last = name.lastIndexOf('/');
            if (name.startsWith(prefix) && last > prefix.length()) {
                try {
                    counts.add(Integer.parseInt(name.substring(last + 1)));
                } catch (NumberFormatException notACount) {
                    // a row of another shape (JMH extras): not a count
                }
            }
        }
        return Collections.unmodifiableList(new ArrayList<>(counts));
    }

    private static BenchmarkTable.Row row(BenchmarkTable table, ForceMix mix, String path,
            int count) {
        return table.find(count == 1 ? BenchmarkTable.singleName(mix, path)
                : BenchmarkTable.bulkName(mix, path, count));
    }

    /** a / b for two rows, NaN if either is missing. */
    private static double ratio(BenchmarkTable.Row a, BenchmarkTable.Row b) {
        if (a == null || b == null) {
            return Double.NaN;
        }
        return a.nanosPerParticleStep() / b.nanosPerParticleStep();
    }

    /** True if a row's rounds spread beyond the report's bound (a missing row is not). */
    private static boolean noisy(BenchmarkTable.Row row) {
        return row != null && row.isTooNoisy(SpeedSpreads.SPREAD_BOUND);
    }

    private static String times(double ratio) {
        return Double.isNaN(ratio) ? "—" : fix(ratio, 2) + "×";
    }

    private static String countList() {
        StringBuilder text = new StringBuilder();
        for (int count : PER_PARTICLE_COUNTS) {
            text.append(text.length() == 0 ? "" : " and ").append(count);
        }
        return text.toString();
    }

    private static String num(double value) {
        return value == Math.rint(value) ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%s", (float) value);
    }

    private static String fix(double value, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", value);
    }

    /** Counts a target's verdicts and remembers the extreme values and where they were. */
    private static final class Tally {
        private int met;
        private int judged;
        /** Rows left unjudged: their rounds spread too widely. */
        private int noisy;
        private double largest = Double.NEGATIVE_INFINITY;
        private String largestWhere;
        private double smallest = Double.POSITIVE_INFINITY;
        private String smallestWhere;

        /** Record one verdict (none for a noisy row); returns the cell's text. */
        String judge(boolean ok, double value, String where, boolean tooNoisy) {
            if (Double.isNaN(value)) {
                return "—";
            }
            if (tooNoisy) {
                ++noisy;
                return SpeedSpreads.TOO_NOISY;
            }
            ++judged;
            if (ok) {
                ++met;
            }
            if (value > largest) {
                largest = value;
                largestWhere = where;
            }
            if (value < smallest) {
                smallest = value;
                smallestWhere = where;
            }
            return ok ? "met" : "**missed**";
        }

        /** "3 of 8 (worst 2.41× at linear N = 1)"; the worst is the largest or smallest. */
        String summary(boolean largerIsWorse, String unit) {
            String unjudged = noisy == 0 ? "" : ", " + noisy + " too noisy to judge";
            if (judged == 0) {
                return noisy == 0 ? "(not measured)" : "(none judged" + unjudged + ")";
            }
            double value = largerIsWorse ? largest : smallest;
            String where = largerIsWorse ? largestWhere : smallestWhere;
            return met + " of " + judged + " (worst " + fix(value, 2) + unit + " at " + where
                    + unjudged + ")";
        }
    }
}

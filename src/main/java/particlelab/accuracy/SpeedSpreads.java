package particlelab.accuracy;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import particlelab.reference.CostMeter;


/**
 * The report's ratios side by side, with their spreads: every ratio a speed target is judged
 * by, each taken within a round of {@link CostMeter#measureSideBySide} (rotating rounds, one
 * JVM, thread CPU time) and given as min / median / max over the rounds. A row whose max ÷ min
 * exceeds {@link #SPREAD_BOUND} says "too noisy: no verdict" instead of met or missed. The
 * lecture style's row is measured twice: in this JVM, under its collector, and in a child JVM
 * started with {@value #PARALLEL_GC} (same class path, same code, same heap flags), because
 * that figure measures the collector as much as the integrator. Then jME's ParticleEmitter
 * beside the fountain's whole step and {@code stepPacked} ({@link PeerScenes}).
 *
 * <p>Every ratio comes with an A/A pass measured in the same rounds: the ratio's reference
 * path timed a second time (a second copy of its scene, the same code) beside the first, so
 * the A/A ratio per round shows how far identical work appears to differ in this run. A row
 * is judged only where its median lies outside that A/A band ({@link AaControl}'s rule) and
 * its target lies outside the band around the median; otherwise it says so, "no verdict".
 */
final class SpeedSpreads {

    /** A ratio row whose rounds' max ÷ min exceeds this gets no verdict. */
    static final double SPREAD_BOUND = 1.5;
    /** The child JVM's collector flag. */
    static final String PARALLEL_GC = "-XX:+UseParallelGC";
    /** The line the child JVM prints its ratio on, then min, median, max and collector. */
    static final String PROBE_PREFIX = "lecture-over-objects";
    /** The line the child JVM prints its A/A ratio on (objects ÷ objects), min, median, max. */
    static final String PROBE_AA_PREFIX = "objects-over-objects";
    /** Verdict of a row too noisy to judge. */
    static final String TOO_NOISY = "too noisy: no verdict";
    /** Verdict of a row from a sweep too short to warm its paths to a steady state. */
    static final String NOT_WARMED = "not warmed: no verdict";
    /** Verdict of a row whose ratio lies inside the A/A band measured beside it. */
    static final String INSIDE_AA = "inside the A/A band: no verdict";
    /** Verdict of a row whose target lies inside the A/A band around its median. */
    static final String NEAR_TARGET = "target within the A/A band: no verdict";
    /** {@link #oneParticle}'s workloads: the primitive loop ... */
    static final int PRIMITIVE = 0;
    /** ... {@code step(Particle, h)} ... */
    static final int OBJECTS = 1;
    /** ... the primitive loop again, a second scene (the A/A pass of ratios over it) ... */
    static final int PRIMITIVE_AGAIN = 2;
    /** ... {@code step(Particle, h)} again, a second scene (the A/A of ratios over it) ... */
    static final int OBJECTS_AGAIN = 3;
    /** ... and, if asked, the lecture style. */
    static final int LECTURE_STYLE = 4;
    /** Verdict of a peer row timed with no full collection before it (heap layout unknown). */
    static final String NO_FULL_GC = "no full GC before timing: no verdict";
    /** The peer rows' particle counts (the quick sweep leaves out the last). */
    static final int[] PEER_COUNTS = {10_000, 100_000, 1_000_000};
    /** Row: one particle through the integrator against the one-particle loop, linear drag. */
    static final String OBJECTS_LINEAR =
            "`step(Particle, h)` ÷ one-particle primitive loop, linear drag";
    /** Row: the same under gravity alone. */
    static final String OBJECTS_GRAVITY =
            "`step(Particle, h)` ÷ one-particle primitive loop, gravity";
    /** Row: the lecture style against the integrator, one particle (two collectors). */
    static final String LECTURE =
            "lecture style ÷ `step(Particle, h)`, one particle, linear drag";
    /** Row prefix: the batch against the primitive loop at N. */
    static final String BATCH = "`stepPacked` ÷ primitive loop, linear drag, N = ";
    /** The child JVM's longest run (s). */
    private static final long CHILD_TIMEOUT_SECONDS = 300;

    /**
     * One judged ratio: what over what, under which collector, its spread, the A/A pass
     * beside it and its target.
     */
    static final class Line {
        private final String comparison;
        private final String collector;
        private final CostMeter.Spread ratio;
        /** The ratio's reference path over itself, per round (null if not measured). */
        private final CostMeter.Spread aa;
        /** The target: at most this (atMost) or at least this. NaN: no target. */
        private final double target;
        private final boolean atMost;
        /** False for a sweep too short to warm the paths to a steady state. */
        private final boolean warmed;
        private final String failure;

        /**
         * A measured row.
         *
         * @param ratio the ratio per round (not null)
         * @param aa the A/A ratio per round, measured in the same rounds (not null)
         * @param warmed false if the sweep's warm-up is too short for a steady state
         */
        Line(String comparison, String collector, CostMeter.Spread ratio, CostMeter.Spread aa,
                double target, boolean atMost, boolean warmed) {
            this(comparison, collector, ratio, aa, target, atMost, warmed, null);
        }

        /** A row that could not be measured, and why. */
        Line(String comparison, String collector, double target, boolean atMost,
                String failure) {
            this(comparison, collector, null, null, target, atMost, true, failure);
        }

        private Line(String comparison, String collector, CostMeter.Spread ratio,
                CostMeter.Spread aa, double target, boolean atMost, boolean warmed,
                String failure) {
            this.comparison = comparison;
            this.collector = collector;
            this.ratio = ratio;
            this.aa = aa;
            this.target = target;
            this.atMost = atMost;
            this.warmed = warmed;
            this.failure = failure;
        }

        /** @return the row's first cell */
        String comparison() {
            return comparison;
        }

        /**
         * The verdict: met or missed only where the median lies outside the A/A band (the
         * two paths differ by more than identical work did) and the target lies outside the
         * band around the median (the verdict would not flip within that noise).
         *
         * @return the verdict cell: met, missed, why there is none, or why it was not
         *     measured
         */
        String verdict() {
            if (failure != null) {
                return "not measured: " + failure;
            }
            if (!warmed) {
                return NOT_WARMED;
            }
            if (ratio.exceeds(SPREAD_BOUND)) {
                return TOO_NOISY;
            }
            if (AaControl.isInsideBand(aa.min(), aa.max(), ratio.median())) {
                return INSIDE_AA;
            }
            if (Double.isNaN(target)) {
                return "—";
            }
            if (AaControl.isInsideBand(aa.min(), aa.max(), ratio.median() / target)) {
                return NEAR_TARGET;
            }
            boolean met = atMost ? ratio.median() <= target : ratio.median() >= target;
            return met ? "met" : "**missed**";
        }

        /** @return the table row */
        String row() {
            return "| " + comparison + " | " + collector + " | "
                    + (failure != null ? "—" : spread(ratio, 2) + "×") + " | "
                    + (failure != null ? "—" : spread(aa, 3) + "×") + " | "
                    + (Double.isNaN(target) ? "—" : (atMost ? "≤ " : "≥ ") + num(target) + "×")
                    + " | " + verdict() + " |";
        }
    }

    /** One N of the peer table. */
    static final class PeerRow {
        private final int count;
        private final CostMeter.Spread emitter;
        private final CostMeter.Spread fountain;
        private final CostMeter.Spread packed;
        private final CostMeter.Spread emitterOverPacked;
        private final CostMeter.Spread emitterOverFountain;
        /** {@code stepPacked} over a second copy of itself, per round (null: not measured). */
        private final CostMeter.Spread packedAa;
        private final double emitterHeap;
        private final double emitterDirect;
        private final double fountainHeap;
        private final boolean warmed;
        /**
         * Whether a full collection ran between building the scenes and timing them; null
         * for a row of a run that did not record it (pasted before the report ran one).
         */
        private final Boolean afterFullGc;

        PeerRow(int count, CostMeter.Spread emitter, CostMeter.Spread fountain,
                CostMeter.Spread packed, CostMeter.Spread emitterOverPacked,
                CostMeter.Spread emitterOverFountain, CostMeter.Spread packedAa,
                double emitterHeap, double emitterDirect, double fountainHeap, boolean warmed,
                Boolean afterFullGc) {
            this.warmed = warmed;
            this.afterFullGc = afterFullGc;
            this.count = count;
            this.emitter = emitter;
            this.fountain = fountain;
            this.packed = packed;
            this.emitterOverPacked = emitterOverPacked;
            this.emitterOverFountain = emitterOverFountain;
            this.packedAa = packedAa;
            this.emitterHeap = emitterHeap;
            this.emitterDirect = emitterDirect;
            this.fountainHeap = fountainHeap;
        }

        /** @return the table row */
        String row() {
            boolean noisy = emitterOverPacked.exceeds(SPREAD_BOUND)
                    || emitterOverFountain.exceeds(SPREAD_BOUND);
            boolean insideAa = packedAa != null && (AaControl.isInsideBand(packedAa.min(),
                    packedAa.max(), emitterOverPacked.median())
                    || AaControl.isInsideBand(packedAa.min(), packedAa.max(),
                            emitterOverFountain.median()));
            return "| " + count + " | " + spread(emitter, 2) + " | " + spread(fountain, 2)
                    + " | " + spread(packed, 2) + " | " + spread(emitterOverPacked, 1) + "× | "
                    + spread(emitterOverFountain, 1) + "× | "
                    + (packedAa == null ? "—" : spread(packedAa, 3) + "×") + " | "
                    + fix(emitterHeap, 0) + " + "
                    + fix(emitterDirect, 0) + " | " + fix(fountainHeap, 0) + " | "
                    + fix(PeerScenes.packedBytes(), 0) + " | "
                    + (!warmed ? NOT_WARMED : Boolean.FALSE.equals(afterFullGc) ? NO_FULL_GC
                    : noisy ? TOO_NOISY : insideAa ? INSIDE_AA : "judged") + " |";
        }
    }

    private SpeedSpreads() {
    }

    /**
     * Measure every line and write the section.
     *
     * @param md the report's text (modified)
     * @param config the report's size (not null)
     * @param meter the meter (not null)
     */
    static void append(StringBuilder md, ReportConfig config, CostMeter meter) {
        List<Line> lines = new ArrayList<>();
        String here = collectorLabel(thisCollector(), heapFlags());
        boolean warmed = isWarmed(config);
        CostMeter.SideBySide linear = oneParticle(ForceMix.LINEAR, meter, true);
        CostMeter.SideBySide gravity = oneParticle(ForceMix.GRAVITY, meter, false);
        lines.add(new Line(OBJECTS_LINEAR, here, linear.ratio(OBJECTS, PRIMITIVE),
                linear.ratio(PRIMITIVE_AGAIN, PRIMITIVE), MixTargets.PER_PARTICLE_VS_PRIMITIVE,
                true, warmed));
        lines.add(new Line(OBJECTS_GRAVITY, here, gravity.ratio(OBJECTS, PRIMITIVE),
                gravity.ratio(PRIMITIVE_AGAIN, PRIMITIVE),
                MixTargets.PER_PARTICLE_VS_PRIMITIVE, true, warmed));
        lines.add(new Line(LECTURE, here, linear.ratio(LECTURE_STYLE, OBJECTS),
                linear.ratio(OBJECTS_AGAIN, OBJECTS), MixTargets.PER_PARTICLE_VS_LECTURE,
                false, warmed));
        lines.add(childLine(config));
        for (int count : config.particleCounts()) {
            BulkScene scene = new BulkScene(ForceMix.LINEAR, count);
            // the A/A pass: the primitive loop again, on a second scene
            BulkScene again = new BulkScene(ForceMix.LINEAR, count);
            CostMeter.SideBySide bulk = meter.measureSideBySide(new CostMeter.Workload[] {
                units -> scene.stepPrimitiveLoop(), units -> scene.stepSharedBatch(),
                units -> again.stepPrimitiveLoop()}, new int[] {count, count, count});
            lines.add(new Line(BATCH + count, here, bulk.ratio(1, 0), bulk.ratio(2, 0),
                    MixTargets.BATCH_VS_PRIMITIVE, true, warmed));
        }
        List<PeerRow> peers = new ArrayList<>();
        for (int count : peerCounts(config)) {
            PeerScenes scenes = new PeerScenes(count);
            // the emitter's objects, compacted: issue 35 read its 10^5 row at 9.0 or 25.4 ns
            // per particle in otherwise identical JVMs, before or after one full collection
            boolean collected = fullCollection();
            peers.add(peer(scenes, meter, warmed, collected));
        }
        appendTables(md, lines, peers, meter.rounds(), config);
    }

    /**
     * List the comparisons {@link #append} measures for a size, in order.
     *
     * @param config the report's size (not null)
     * @return a new list of the rows' first cells
     */
    static List<String> comparisons(ReportConfig config) {
        List<String> names = new ArrayList<>(List.of(OBJECTS_LINEAR, OBJECTS_GRAVITY, LECTURE,
                LECTURE));
        for (int count : config.particleCounts()) {
            names.add(BATCH + count);
        }
        return names;
    }

    /**
     * Tell whether a sweep warms its paths to a steady state: only the full one does. The
     * quick sweep's 80 ms of warm-up and rounds of 20 ms are too short (its fountain at
     * N = 10^4 read 6.83 ns per particle against 1.81 in a full run), and the tiny one's
     * are shorter still, so their side-by-side rows say {@value #NOT_WARMED}.
     *
     * @param config the report's size (not null)
     * @return true for the full sweep
     */
    static boolean isWarmed(ReportConfig config) {
        return config.size() == ReportConfig.Size.FULL;
    }

    /**
     * List the peer table's N for a size.
     *
     * @param config the report's size (not null)
     * @return a new array
     */
    static int[] peerCounts(ReportConfig config) {
        switch (config.size()) {
            case FULL:
                return PEER_COUNTS.clone();
            case QUICK:
                return new int[] {PEER_COUNTS[0], PEER_COUNTS[1]};
            default:
                return new int[] {PEER_COUNTS[0]};
        }
    }

    /**
     * Write the section's text and tables from measured lines (split from {@link #append}
     * so a test can check the tables of fixed numbers).
     *
     * @param md the report's text (modified)
     * @param lines the ratio rows (not null)
     * @param peers the peer rows (not null)
     * @param rounds how many rounds each spread is over
     * @param config the report's size (not null)
     */
    static void appendTables(StringBuilder md, List<Line> lines, List<PeerRow> peers,
            int rounds, ReportConfig config) {
        md.append("### Side by side, with spreads\n\n");
        md.append("The ratios the targets are judged by, each taken within one round: the "
                + "paths of a row run in rotating rounds in one JVM (every round times each "
                + "path once, for at least ").append(config.roundNanos() / 1_000_000)
                .append(" ms, the order shifting by one from round to round), timed by ")
                .append(CostMeter.clockName()).append(", so slices the machine gives to "
                + "other jobs do not count. Each cell is min / **median** / max over ")
                .append(rounds).append(" rounds. A row whose max ÷ min exceeds ")
                .append(num(SPREAD_BOUND)).append(" says \"").append(TOO_NOISY)
                .append("\" instead of met or missed. The A/A column is the row's reference "
                + "path (the divisor) timed a second time in the same rounds, on a second copy "
                + "of its scene, over the first: how far identical work appeared to differ in "
                + "this run. Its band is the least and largest of those rounds and of their "
                + "reciprocals; a row whose median lies inside it says \"").append(INSIDE_AA)
                .append("\", and one whose target lies inside the band around the median "
                + "(median ÷ target inside it) says \"").append(NEAR_TARGET).append("\"");
        if (!isWarmed(config)) {
            md.append(". This sweep's warm-up and rounds are too short for a steady state, "
                    + "so every row says \"").append(NOT_WARMED).append("\": run the full "
                    + "report to judge them");
        }
        md.append(". \"Objects ≤ ")
                .append(num(MixTargets.PER_PARTICLE_VS_PRIMITIVE)).append("× primitive\" is "
                + "judged against the one-particle primitive loop, the same chain of dependent "
                + "steps written by hand: the fair loop for one particle (the bulk loop "
                + "overlaps thousands of particles and vectorises, which one particle cannot). "
                + "The lecture style's ratio measures the garbage collector as much as the "
                + "integrator (it stores two new `Vector3f` into a long-lived particle every "
                + "step), so it is measured under this JVM's collector and again in a child "
                + "JVM started with `").append(PARALLEL_GC).append("` (same class path, same "
                + "heap flags).\n\n");
        md.append("| comparison | collector, heap | min / **median** / max | A/A: reference "
                + "÷ itself | target | verdict |\n|---|---|---|---|---|---|\n");
        for (Line line : lines) {
            md.append(line.row()).append('\n');
        }
        md.append("\n### jME's ParticleEmitter beside the fountain and `stepPacked`\n\n");
        md.append("The same N in each, one frame of h = 1/60 s per call, in rotating rounds "
                + "as above: jME's `ParticleEmitter` (`Point` mesh, gravity, a life longer "
                + "than the run so all N stay alive, none spawned; a frame is "
                + "`updateLogicalState` + `updateGeometricState`, the emitter's control: "
                + "life, gravity, position, colour, size, angle, bounds), the fountain's "
                + "whole `Fountain.step` after ").append(PeerScenes.FLOW_STEPS)
                .append(" steps of flow (Euler step, ground bounce, lifecycle, fireworks), and "
                + "the bare `stepPacked` of all N (gravity + the fountain's drag, the scalar "
                + "form). ns per particle, min / **median** / max. Bytes per particle: the "
                + "emitter's heap as the thread allocation counter saw it while the emitter "
                + "was built and filled, plus its mesh buffers' capacities (direct memory); "
                + "the fountain's heap likewise (its point mesh belongs to the view and is "
                + "not counted); the packed state is its two arrays, 6 floats. The A/A column "
                + "is `stepPacked` timed a second time in the same rounds, on a second copy of "
                + "its state, over the first; a row whose emitter ratio lies inside its band "
                + "says \"").append(INSIDE_AA).append("\".");
        if (peers.stream().anyMatch(peer -> peer.afterFullGc != null)) {
            md.append(" Each N's scenes are built and filled, then one full collection runs "
                    + "(`System.gc()`) before the rounds start, so the emitter's objects are "
                    + "timed in a compacted heap: without it its N = 100000 row depended on "
                    + "what the heap held before. A row where the JVM ran no full collection "
                    + "(e.g. `-XX:+DisableExplicitGC`) says \"").append(NO_FULL_GC)
                    .append("\".");
        }
        if (config.size() != ReportConfig.Size.FULL) {
            md.append(" This sweep leaves out the larger N (the full report has ")
                    .append(PEER_COUNTS[PEER_COUNTS.length - 1]).append(") and its rounds are "
                    + "too short to warm these scenes to a steady state, so its rows say \"")
                    .append(NOT_WARMED).append("\": run the full report to judge them.");
        }
        md.append("\n\n| N | emitter (ns) | `Fountain.step` (ns) | `stepPacked` (ns) "
                + "| emitter ÷ `stepPacked` | emitter ÷ `Fountain.step` | A/A: `stepPacked` "
                + "÷ itself | emitter B/particle (heap + direct) | fountain B/particle | packed "
                + "B/particle | spread |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (PeerRow peer : peers) {
            md.append(peer.row()).append('\n');
        }
        md.append("\nWhat the batch form gains a jME user: the emitter keeps a "
                + "`Particle` object per particle (two `Vector3f` and a `ColorRGBA` each) and "
                + "updates them one by one, so every frame chases objects through the heap; "
                + "particles kept as planar float arrays and moved by `stepPacked` take 24 "
                + "bytes each and one pass the JIT vectorises, with drag and a check that no "
                + "particle became NaN or infinite, and the row above says how many times "
                + "less a frame costs at each N. The emitter does more per particle (colour, "
                + "size, angle, bounds), so the fountain's whole step, with its bounce and "
                + "lifecycle, is the fairer peer for a game's effect.\n\n");
    }

    /**
     * The child JVM's command line: this JVM's {@code java}, its heap flags, the Parallel
     * collector, this class path, the probe and the report's size.
     *
     * @param config the report's size (not null)
     * @return a new list
     */
    static List<String> childCommand(ReportConfig config) {
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(heapFlags());
        command.add(PARALLEL_GC);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(LectureCollectorProbe.class.getName());
        command.add(config.size().name());
        return command;
    }

    /**
     * Name a collector with its heap flags for a row's label.
     *
     * @param collector e.g. "G1"
     * @param heapFlags the JVM's heap flags (not null)
     * @return e.g. "G1, default heap" or "Parallel, `-Xmx2g`"
     */
    static String collectorLabel(String collector, List<String> heapFlags) {
        if (heapFlags.isEmpty()) {
            return collector + ", default heap";
        }
        return collector + ", `" + String.join(" ", heapFlags) + "`";
    }

    /**
     * Name this JVM's collector from its beans ("G1 Young Generation" → G1, "PS Scavenge" →
     * Parallel, "Copy" → Serial, ...).
     *
     * @return a short name (not null)
     */
    static String thisCollector() {
        List<String> names = new ArrayList<>();
        for (GarbageCollectorMXBean bean : ManagementFactory.getGarbageCollectorMXBeans()) {
            names.add(bean.getName());
        }
        return collectorName(names);
    }

    /**
     * Name a collector from its beans' names.
     *
     * @param beanNames the names (not null)
     * @return a short name
     */
    static String collectorName(List<String> beanNames) {
        String all = String.join(", ", beanNames);
        if (all.contains("G1")) {
            return "G1";
        }
        if (all.contains("PS Scavenge") || all.contains("PS MarkSweep")) {
            return "Parallel";
        }
        if (all.contains("Copy") || all.contains("MarkSweepCompact")) {
            return "Serial";
        }
        if (all.contains("ZGC")) {
            return "ZGC";
        }
        if (all.contains("Shenandoah")) {
            return "Shenandoah";
        }
        return all.isEmpty() ? "unknown collector" : all;
    }

    /**
     * The heap flags this JVM was started with (-Xms, -Xmx, -Xmn and -XX:…Heap…/RAM…).
     *
     * @return a new list, empty for the defaults
     */
    static List<String> heapFlags() {
        List<String> flags = new ArrayList<>();
        for (String arg : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (arg.startsWith("-Xms") || arg.startsWith("-Xmx") || arg.startsWith("-Xmn")
                    || arg.startsWith("-XX:") && (arg.contains("Heap") || arg.contains("RAM")
                    || arg.contains("NewSize"))) {
                flags.add(arg);
            }
        }
        return flags;
    }

    /**
     * Parse one of the probe's lines.
     *
     * @param line e.g. {@value #PROBE_PREFIX} min median max collector
     * @param prefix the line's first word, {@value #PROBE_PREFIX} or {@value #PROBE_AA_PREFIX}
     * @return the spread, or null if the line is not that one of the probe's
     */
    static CostMeter.Spread parseProbe(String line, String prefix) {
        String[] cells = line.trim().split(" ");
        if (cells.length < 4 || !cells[0].equals(prefix)) {
            return null;
        }
        try {
            return new CostMeter.Spread(Double.parseDouble(cells[1]),
                    Double.parseDouble(cells[2]), Double.parseDouble(cells[3]));
        } catch (NumberFormatException notNumbers) {
            return null;
        }
    }

    /**
     * One particle of a mix side by side: workloads {@link #PRIMITIVE}, {@link #OBJECTS},
     * the same two again on a second scene ({@link #PRIMITIVE_AGAIN}, {@link #OBJECTS_AGAIN}:
     * the A/A passes) and, if asked, {@link #LECTURE_STYLE}.
     */
    static CostMeter.SideBySide oneParticle(ForceMix mix, CostMeter meter, boolean lecture) {
        OneParticleMixScene scene = new OneParticleMixScene(mix);
        OneParticleMixScene again = new OneParticleMixScene(mix);
        int steps = OneParticleMixScene.STEPS_PER_LAUNCH;
        CostMeter.Workload primitive = units -> scene.flyPrimitiveLoop();
        CostMeter.Workload objects = units -> scene.flySharedObjects();
        CostMeter.Workload primitiveAgain = units -> again.flyPrimitiveLoop();
        CostMeter.Workload objectsAgain = units -> again.flySharedObjects();
        CostMeter.Workload[] workloads = lecture
                ? new CostMeter.Workload[] {primitive, objects, primitiveAgain, objectsAgain,
                    units -> scene.flyLectureStyle()}
                : new CostMeter.Workload[] {primitive, objects, primitiveAgain, objectsAgain};
        int[] units = new int[workloads.length];
        java.util.Arrays.fill(units, steps);
        return meter.measureSideBySide(workloads, units);
    }

    /**
     * Run one full collection ({@code System.gc()}), so the peer scenes just built are timed
     * in a compacted heap whatever garbage came before them.
     *
     * @return true if a collector that collects the whole heap (the old generation's bean)
     *     counted a collection, false if the JVM ran none (e.g.
     *     {@code -XX:+DisableExplicitGC}) or only a concurrent one
     */
    static boolean fullCollection() {
        long before = fullCollections();
        System.gc();
        return fullCollections() > before;
    }

    /** The collections counted by the beans that collect the old generation or whole heap. */
    private static long fullCollections() {
        long count = 0;
        for (GarbageCollectorMXBean bean : ManagementFactory.getGarbageCollectorMXBeans()) {
            String name = bean.getName();
            if (name.contains("Old") || name.contains("MarkSweep") || name.equals("ZGC")
                    || name.contains("Cycles") || name.contains("Major")) {
                count += Math.max(0L, bean.getCollectionCount());
            }
        }
        return count;
    }

    private static PeerRow peer(PeerScenes scenes, CostMeter meter, boolean warmed,
            boolean afterFullGc) {
        int n = scenes.count();
        CostMeter.SideBySide timed = meter.measureSideBySide(new CostMeter.Workload[] {
            units -> scenes.emitterFrame(), units -> scenes.fountainStep(),
            units -> scenes.packedStep(), units -> scenes.packedStepAgain()},
            new int[] {n, n, n, n});
        return new PeerRow(n, timed.nanosPerUnit(0), timed.nanosPerUnit(1),
                timed.nanosPerUnit(2), timed.ratio(0, 2), timed.ratio(0, 1), timed.ratio(3, 2),
                scenes.emitterHeapBytes(), scenes.emitterDirectBytes(),
                scenes.fountainHeapBytes(), warmed, afterFullGc);
    }

    /** The lecture row under the Parallel collector, from the child JVM. */
    private static Line childLine(ReportConfig config) {
        String label = collectorLabel("Parallel", heapFlags()) + " (child JVM, `"
                + PARALLEL_GC + "`)";
        String comparison = LECTURE;
        if (config.size() == ReportConfig.Size.TINY) {
            return new Line(comparison, label, MixTargets.PER_PARTICLE_VS_LECTURE, false,
                    "the tiny sweep starts no child JVM");
        }
        try {
            Process child = new ProcessBuilder(childCommand(config))
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            CostMeter.Spread found = null;
            CostMeter.Spread foundAa = null;
            try (BufferedReader out = new BufferedReader(new InputStreamReader(
                    child.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = out.readLine(); line != null; line = out.readLine()) {
                    CostMeter.Spread parsed = parseProbe(line, PROBE_PREFIX);
                    found = parsed != null ? parsed : found;
                    CostMeter.Spread parsedAa = parseProbe(line, PROBE_AA_PREFIX);
                    foundAa = parsedAa != null ? parsedAa : foundAa;
                }
            }
            if (!child.waitFor(CHILD_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                child.destroy();
                return new Line(comparison, label, MixTargets.PER_PARTICLE_VS_LECTURE,
                        false, "the child JVM took longer than " + CHILD_TIMEOUT_SECONDS + " s");
            }
            if (found == null || foundAa == null || child.exitValue() != 0) {
                return new Line(comparison, label, MixTargets.PER_PARTICLE_VS_LECTURE,
                        false, "the child JVM exited with " + child.exitValue()
                        + " and no ratio");
            }
            return new Line(comparison, label, found, foundAa,
                    MixTargets.PER_PARTICLE_VS_LECTURE, false, isWarmed(config));
        } catch (IOException e) {
            return new Line(comparison, label, MixTargets.PER_PARTICLE_VS_LECTURE, false,
                    "the child JVM did not start (" + e.getMessage() + ")");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Line(comparison, label, MixTargets.PER_PARTICLE_VS_LECTURE, false,
                    "interrupted");
        }
    }

    /** "min / **median** / max" to a number of decimals. */
    static String spread(CostMeter.Spread spread, int decimals) {
        return fix(spread.min(), decimals) + " / **" + fix(spread.median(), decimals) + "** / "
                + fix(spread.max(), decimals);
    }

    private static String num(double value) {
        return value == Math.rint(value) ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%s", value);
    }

    private static String fix(double value, int decimals) {
        return Double.isNaN(value) ? "—"
                : String.format(Locale.ROOT, "%." + decimals + "f", value);
    }
}

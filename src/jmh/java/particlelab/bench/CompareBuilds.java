package particlelab.bench;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import particlelab.accuracy.AaControl;
import particlelab.accuracy.HostInfo;

/**
 * Two builds of the project side by side in one JVM: the same workloads ({@code MixBenchmark}'s
 * single and bulk rows) of an older and a newer build, each loaded by a class loader of its
 * own, timed in rotating rounds (the order of the two alternates from row to row and round to
 * round) by the thread's CPU time, so time the machine gives to other jobs does not count.
 * Each row is timed three ways in every round: the older build (A), the older build again
 * in a class loader of its own (A′, the A/A control: the same code on both sides, in the same
 * row order), and the newer build (B). Prints each row's median ns per particle-step of A and
 * B, the A/A ratio A′ ÷ A per round and the ratio B ÷ A per round (min / median / max each),
 * and a verdict only where B ÷ A's median lies outside that row's A/A band
 * ({@link particlelab.accuracy.AaControl}); otherwise "no verdict". Identical code has read as
 * 0.73× here with a tight spread: a spread does not make a difference real, the A/A band does.
 *
 * <p>Usage: {@code CompareBuilds OLDER_CLASSES NEWER_CLASSES [ROUNDS [MILLIS [REGEX]]]}, where
 * REGEX keeps only the rows whose name it finds (default: every row), and each
 * classes folder is a build's {@code build/classes/java/main}; jME's core jar comes from this
 * JVM's class path. Defaults: 7 rounds of 300 ms per row and build. Run it with
 * {@code --add-modules jdk.incubator.vector} to include the Vector API rows.
 */
public final class CompareBuilds {

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private static final String[] MIXES = {"gravity", "linear", "quadratic", "thrust-linear"};
    private static final int[] COUNTS = {1000, 100_000};
    /** The one-particle rows: the scene's method and the path's row name. */
    private static final String[][] SINGLE = {
        {"flySharedObjects", "shared-objects"},
        {"flySharedWithRegime", "shared-objects-regime"},
        {"flyPrimitiveLoop", "primitive-loop"},
    };
    /** The bulk rows. */
    private static final String[][] BULK = {
        {"stepSharedEach", "shared-objects"},
        {"stepSharedBatch", "shared-batch"},
        {"stepSharedBatchVector", "shared-batch-vector"},
        {"stepPrimitiveLoop", "primitive-loop"},
    };
    /** The three timed sides: the older build, its A/A copy, the newer build. */
    private static final int BUILDS = 3;
    private static final int OLDER = 0;
    private static final int CONTROL = 1;
    private static final int NEWER = 2;
    /** Keeps the results alive so no work is dead code. */
    private static volatile Object sink;

    private CompareBuilds() {
    }

    /**
     * Compare two builds.
     *
     * @param args the older and newer classes folders, then rounds and milliseconds per row
     * @throws Throwable if a build cannot be loaded or a workload fails
     */
    public static void main(String[] args) throws Throwable {
        if (args.length < 2) {
            System.err.println("usage: CompareBuilds OLDER_CLASSES NEWER_CLASSES [ROUNDS"
                    + " [MILLIS [REGEX]]]");
            System.exit(2);
        }
        HostInfo host = HostInfo.now();
        int rounds = args.length > 2 ? Integer.parseInt(args[2]) : 7;
        long budget = (args.length > 3 ? Long.parseLong(args[3]) : 300L) * 1_000_000L;
        java.util.regex.Pattern keep = java.util.regex.Pattern.compile(
                args.length > 4 ? args[4] : "");
        // A, the A/A control A′ (the older build again, in a loader of its own) and B.
        ClassLoader[] builds = {loader(args[0]), loader(args[0]), loader(args[1])};
        List<String> names = new ArrayList<>();
        List<MethodHandle[]> workloads = new ArrayList<>();
        List<Integer> units = new ArrayList<>();
        boolean vector = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();
        for (String mix : MIXES) {
            for (String[] path : SINGLE) {
                if (!keep.matcher("single/" + mix + "/" + path[1]).find()) {
                    continue;
                }
                MethodHandle[] pair = new MethodHandle[BUILDS];
                for (int b = 0; b < BUILDS; ++b) {
                    Object scene = scene(builds[b], "OneParticleMixScene", mix, -1);
                    pair[b] = bind(scene, path[0]);
                }
                names.add("single/" + mix + "/" + path[1]);
                workloads.add(pair);
                units.add(1000);
            }
            for (int count : COUNTS) {
                for (String[] path : BULK) {
                    boolean vectorRow = path[0].endsWith("Vector");
                    if (vectorRow && (!vector || !(mix.equals("gravity")
                            || mix.equals("linear")))
                            || !keep.matcher("bulk/" + mix + "/" + path[1] + "/" + count).find()) {
                        continue;
                    }
                    MethodHandle[] pair = new MethodHandle[BUILDS];
                    for (int b = 0; b < BUILDS; ++b) {
                        pair[b] = bind(scene(builds[b], "BulkScene", mix, count), path[0]);
                    }
                    names.add("bulk/" + mix + "/" + path[1] + "/" + count);
                    workloads.add(pair);
                    units.add(count);
                }
            }
        }
        int rows = names.size();
        double[][][] nanos = new double[rows][BUILDS][rounds];
        for (int r = 0; r < rows; ++r) {
            for (int b = 0; b < BUILDS; ++b) {
                time(workloads.get(r)[b], 2 * budget);
            }
        }
        for (int round = 0; round < rounds; ++round) {
            for (int r = 0; r < rows; ++r) {
                // The order of A, A′ and B rotates from row to row and round to round.
                int first = (round + r) % BUILDS;
                for (int k = 0; k < BUILDS; ++k) {
                    int b = (first + k) % BUILDS;
                    nanos[r][b][round] = time(workloads.get(r)[b], budget) / units.get(r);
                }
            }
        }
        System.out.print("Host:\n" + host.block() + "\n");
        System.out.printf("| row | older (ns) | newer (ns) | A/A: older ÷ older per round |"
                + " newer ÷ older per round | verdict |%n|---|---|---|---|---|---|%n");
        for (int r = 0; r < rows; ++r) {
            double[] control = ratios(nanos[r][CONTROL], nanos[r][OLDER]);
            double[] ratio = ratios(nanos[r][NEWER], nanos[r][OLDER]);
            String unchanged = names.get(r).contains("primitive-loop") ? " (control)" : "";
            System.out.printf("| `%s`%s | %.3f | %.3f | %s | %s | %s |%n", names.get(r),
                    unchanged, AaControl.median(nanos[r][OLDER]),
                    AaControl.median(nanos[r][NEWER]), spread(control), spread(ratio),
                    AaControl.verdict(control, ratio));
        }
    }

    /** Per round, numerator ÷ denominator. */
    private static double[] ratios(double[] numerator, double[] denominator) {
        double[] ratio = new double[numerator.length];
        for (int i = 0; i < ratio.length; ++i) {
            ratio[i] = numerator[i] / denominator[i];
        }
        return ratio;
    }

    /** min / **median** / max of per-round ratios. */
    private static String spread(double[] ratios) {
        double[] sorted = ratios.clone();
        Arrays.sort(sorted);
        return String.format(java.util.Locale.ROOT, "%.3f / **%.3f** / %.3f", sorted[0],
                AaControl.median(sorted), sorted[sorted.length - 1]);
    }

    private static ClassLoader loader(String classes) throws Exception {
        Path folder = Paths.get(classes);
        if (!Files.isDirectory(folder.resolve("particlelab"))) {
            throw new IllegalArgumentException("not a build's classes folder (no particlelab/"
                    + " in it): " + classes);
        }
        URL jme = com.jme3.math.Vector3f.class.getProtectionDomain().getCodeSource()
                .getLocation();
        return new URLClassLoader(new URL[] {folder.toUri().toURL(), jme},
                ClassLoader.getPlatformClassLoader());
    }

    private static Object scene(ClassLoader build, String name, String mix, int count)
            throws Exception {
        Class<?> mixes = build.loadClass("particlelab.accuracy.ForceMix");
        Object forces = mixes.getMethod("named", String.class).invoke(null, mix);
        Class<?> type = build.loadClass("particlelab.accuracy." + name);
        return count < 0 ? type.getConstructor(mixes).newInstance(forces)
                : type.getConstructor(mixes, int.class).newInstance(forces, count);
    }

    private static MethodHandle bind(Object scene, String method) throws Exception {
        java.lang.reflect.Method found = scene.getClass().getMethod(method);
        return MethodHandles.publicLookup().unreflect(found).bindTo(scene)
                .asType(MethodType.methodType(Object.class));
    }

    /** The CPU time of one call, over calls that fill the budget (ns). */
    private static double time(MethodHandle workload, long budgetNanos) throws Throwable {
        long start = THREADS.getCurrentThreadCpuTime();
        long calls = 0;
        long now;
        do {
            for (int i = 0; i < 16; ++i) {
                sink = workload.invoke();
            }
            calls += 16;
            now = THREADS.getCurrentThreadCpuTime();
        } while (now - start < budgetNanos);
        return (double) (now - start) / calls;
    }
}

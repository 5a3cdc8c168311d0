package particlelab.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;
import particlelab.accuracy.BulkScene;
import particlelab.accuracy.ForceMix;

/**
 * The batch's scalar finiteness check against the primitive loop, gravity + linear drag, at
 * N = 10^3 … 10^6, in one JVM: the batch ({@code stepPacked}, the scalar form) and the
 * hand-written loop of {@link BulkScene} timed in rotating rounds (the order of the two
 * alternates from round to round and from N to N) by the thread's CPU time, so time the
 * machine gives to other jobs does not count. The check's form is the JVM's: run it once
 * with {@code -Dparticlelab.check=tree} and once with {@code -Dparticlelab.check=fused} on
 * each JDK. Prints, per N, both medians and batch ÷ primitive per round, min / median / max.
 *
 * <p>Usage: {@code CheckForms [ROUNDS [MILLIS]]}; defaults 11 rounds of 200 ms per row.
 */
public final class CheckForms {

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private static final int[] COUNTS = {1_000, 10_000, 100_000, 1_000_000};
    /** Keeps the results alive so no work is dead code. */
    private static volatile Object sink;

    private CheckForms() {
    }

    /**
     * Time both paths at every N.
     *
     * @param args rounds, then milliseconds per row and round
     */
    public static void main(String[] args) {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 11;
        long budget = (args.length > 1 ? Long.parseLong(args[1]) : 200L) * 1_000_000L;
        BulkScene[] scenes = new BulkScene[COUNTS.length];
        for (int c = 0; c < COUNTS.length; ++c) {
            scenes[c] = new BulkScene(ForceMix.LINEAR, COUNTS[c]);
            // warm-up: both paths, long enough for C2
            time(scenes[c], 0, 3 * budget);
            time(scenes[c], 1, 3 * budget);
        }
        double[][][] nanos = new double[COUNTS.length][2][rounds];
        for (int round = 0; round < rounds; ++round) {
            for (int c = 0; c < COUNTS.length; ++c) {
                int first = (round + c) % 2;
                for (int k = 0; k < 2; ++k) {
                    int path = (first + k) % 2;
                    nanos[c][path][round] = time(scenes[c], path, budget) / COUNTS[c];
                }
            }
        }
        System.out.printf(Locale.ROOT, "JDK %s, check=%s, %d rounds of %d ms%n",
                System.getProperty("java.version"),
                System.getProperty("particlelab.check", "(JDK default)"), rounds,
                budget / 1_000_000L);
        System.out.printf("| N | primitive (ns) | batch (ns) | batch ÷ primitive per round:"
                + " min / median / max |%n|---|---|---|---|%n");
        for (int c = 0; c < COUNTS.length; ++c) {
            double[] ratio = new double[rounds];
            for (int i = 0; i < rounds; ++i) {
                ratio[i] = nanos[c][1][i] / nanos[c][0][i];
            }
            Arrays.sort(ratio);
            System.out.printf(Locale.ROOT, "| %d | %.3f | %.3f | %.2f / **%.2f** / %.2f |%n",
                    COUNTS[c], median(nanos[c][0]), median(nanos[c][1]), ratio[0],
                    median(ratio), ratio[rounds - 1]);
        }
    }

    /** The CPU time of one call of a path (0 primitive, 1 batch), over a budget (ns). */
    private static double time(BulkScene scene, int path, long budgetNanos) {
        // the clock is read once per 10^5 particle-steps or more: reading it costs about 1 µs
        int callsPerRead = Math.max(1, 100_000 / scene.count());
        long start = THREADS.getCurrentThreadCpuTime();
        long calls = 0;
        long now;
        do {
            for (int i = 0; i < callsPerRead; ++i) {
                sink = path == 0 ? scene.stepPrimitiveLoop() : scene.stepSharedBatch();
            }
            calls += callsPerRead;
            now = THREADS.getCurrentThreadCpuTime();
        } while (now - start < budgetNanos);
        return (double) (now - start) / calls;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
}

package particlelab.accuracy;

import java.lang.management.ManagementFactory;
import java.util.Arrays;

/**
 * The report's in-process timing loop: runs a piece of work until the JIT has settled, then
 * times several rounds and keeps the median, and counts the bytes the thread allocated. All
 * timings of one report come from one JVM, one after another, so they are meant as ratios to
 * each other (side by side), not as absolute numbers.
 */
public final class CostMeter {

    /** Work to time: {@code run(n)} does n units (particle-steps) and returns any result. */
    @FunctionalInterface
    public interface Workload {
        /**
         * Do some units of work.
         *
         * @param units how many (&gt;0)
         * @return anything computed, so the JIT cannot drop the work
         */
        Object run(int units);
    }

    /** One measurement. */
    public static final class Measurement {
        private final double nanosPerUnit;
        private final double bytesPerUnit;

        Measurement(double nanosPerUnit, double bytesPerUnit) {
            this.nanosPerUnit = nanosPerUnit;
            this.bytesPerUnit = bytesPerUnit;
        }

        /**
         * Return the median time per unit.
         *
         * @return the time (in nanoseconds)
         */
        public double nanosPerUnit() {
            return nanosPerUnit;
        }

        /**
         * Return the heap allocated per unit over the measured rounds.
         *
         * @return the allocation (in bytes; NaN if the JVM cannot count it)
         */
        public double bytesPerUnit() {
            return bytesPerUnit;
        }
    }

    /** {@link #measureOnceCompiled}'s longest wait for an allocation-free call (ms). */
    static final long MAX_COMPILE_WAIT_MILLIS = 5_000L;

    private final long warmupNanos;
    private final long roundNanos;
    private final int rounds;
    /** Keeps results alive so no work is dead code. */
    private int sink;

    /**
     * Create a meter.
     *
     * @param config the timing budget (not null)
     */
    public CostMeter(ReportConfig config) {
        this.warmupNanos = config.warmupNanos();
        this.roundNanos = config.roundNanos();
        this.rounds = config.rounds();
    }

    /**
     * Measure a workload.
     *
     * @param workload the work (not null)
     * @param unitsPerCall how many units one call should do (&gt;0): enough for a few
     *     microseconds, so the clock's resolution does not matter
     * @return the median time and the allocation per unit
     */
    public Measurement measure(Workload workload, int unitsPerCall) {
        warmUp(workload, unitsPerCall);
        return measureWarm(workload, unitsPerCall);
    }

    /**
     * Measure a workload that allocates nothing once the JIT has compiled it, but a lot
     * before (the batch on the Vector API: its vectors are objects until C2 keeps them in
     * registers, some hundred milliseconds and thousands of calls into a run): warm up as
     * {@link #measure} does, then on while a call still allocates, for at most
     * {@value #MAX_COMPILE_WAIT_MILLIS} ms more.
     *
     * @param workload the work (not null)
     * @param unitsPerCall as for {@link #measure}
     * @return the median time and the allocation per unit
     */
    public Measurement measureOnceCompiled(Workload workload, int unitsPerCall) {
        warmUp(workload, unitsPerCall);
        // what reading the counter twice allocates by itself (a few dozen bytes on some JVMs)
        long overhead = 0;
        for (int i = 0; i < 5; ++i) {
            long first = allocatedBytes();
            overhead = Math.max(overhead, allocatedBytes() - first);
        }
        long start = System.nanoTime();
        long before;
        do {
            before = allocatedBytes();
            sink += System.identityHashCode(workload.run(unitsPerCall));
        } while (before >= 0 && allocatedBytes() - before > overhead
                && System.nanoTime() - start < MAX_COMPILE_WAIT_MILLIS * 1_000_000L);
        return measureWarm(workload, unitsPerCall);
    }

    private void warmUp(Workload workload, int unitsPerCall) {
        long calls = 0;
        long start = System.nanoTime();
        while (System.nanoTime() - start < warmupNanos || calls < 3) {
            sink += System.identityHashCode(workload.run(unitsPerCall));
            ++calls;
        }
    }

    private Measurement measureWarm(Workload workload, int unitsPerCall) {
        double[] perUnit = new double[rounds];
        long totalUnits = 0;
        long bytesBefore = allocatedBytes();
        for (int r = 0; r < rounds; ++r) {
            long units = 0;
            long roundStart = System.nanoTime();
            long elapsed;
            do {
                sink += System.identityHashCode(workload.run(unitsPerCall));
                units += unitsPerCall;
                elapsed = System.nanoTime() - roundStart;
            } while (elapsed < roundNanos);
            perUnit[r] = (double) elapsed / units;
            totalUnits += units;
        }
        long bytesAfter = allocatedBytes();
        Arrays.sort(perUnit);
        double bytes = bytesBefore < 0 ? Double.NaN
                : (double) (bytesAfter - bytesBefore) / totalUnits;
        return new Measurement(perUnit[rounds / 2], bytes);
    }

    /**
     * Return a value derived from every result, so the work cannot be optimised away.
     *
     * @return a meaningless number
     */
    public int sink() {
        return sink;
    }

    private static long allocatedBytes() {
        java.lang.management.ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        if (threads instanceof com.sun.management.ThreadMXBean) {
            return ((com.sun.management.ThreadMXBean) threads).getCurrentThreadAllocatedBytes();
        }
        return -1;
    }
}

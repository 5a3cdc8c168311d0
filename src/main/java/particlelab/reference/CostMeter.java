package particlelab.reference;

import java.lang.management.ManagementFactory;
import java.util.Arrays;


/**
 * The report's in-process timing loop: runs a piece of work until the JIT has settled, then
 * times several rounds, keeps the min / median / max, and counts the bytes the thread
 * allocated. Time is the measuring thread's CPU time ({@code
 * ThreadMXBean.getCurrentThreadCpuTime}), so slices the machine gives to other jobs do not
 * count. {@link #measureSideBySide} times several workloads in rotating rounds (each round
 * times every workload once, the order shifting by one from round to round), so a ratio can be
 * taken within a round. All timings of one report come from one JVM, so they are meant as
 * ratios to each other, not as absolute numbers.
 */
public final class CostMeter {

    /**
     * How long each timing loop runs: the report's sizes (a full report, a quick one, a tiny
     * one for tests) and the demos' in-process meters use these three budgets.
     */
    public enum Budget {
        /** Timings long enough to be steady: 300 ms warm-up, 7 rounds of 60 ms. */
        FULL(300, 60, 7),
        /** A first look: 80 ms warm-up, 5 rounds of 20 ms. */
        QUICK(80, 20, 5),
        /** Seconds for a whole report, for tests: 5 ms warm-up, 3 rounds of 2 ms. */
        TINY(5, 2, 3);

        private static final long NANOS_PER_MILLI = 1_000_000L;
        private final long warmupMillis;
        private final long roundMillis;
        private final int rounds;

        Budget(long warmupMillis, long roundMillis, int rounds) {
            this.warmupMillis = warmupMillis;
            this.roundMillis = roundMillis;
            this.rounds = rounds;
        }

        /** @return how long each timing loop warms up before measuring (in nanoseconds) */
        public long warmupNanos() {
            return warmupMillis * NANOS_PER_MILLI;
        }

        /** @return how long each measured round lasts, at least (in nanoseconds) */
        public long roundNanos() {
            return roundMillis * NANOS_PER_MILLI;
        }

        /** @return how many rounds are measured; the median is reported (&ge;1) */
        public int rounds() {
            return rounds;
        }
    }

    /** A clock: the thread's CPU time in the report, a scripted one in tests. */
    @FunctionalInterface
    interface Clock {
        /**
         * Read the clock.
         *
         * @return the time (in nanoseconds, from any origin)
         */
        long nanos();
    }

    /** Several values' min, median and max: the spread of one figure over rounds. */
    public static final class Spread {
        private final double min;
        private final double median;
        private final double max;

        /**
         * Create a spread.
         *
         * @param min the least value
         * @param median the median
         * @param max the largest value
         */
        public Spread(double min, double median, double max) {
            this.min = min;
            this.median = median;
            this.max = max;
        }

        /**
         * Find the spread of values.
         *
         * @param values the values (not null, at least one; not modified)
         * @return their min, median (the mean of the middle two for an even count) and max
         */
        static Spread of(double[] values) {
            if (values.length == 0) {
                throw new IllegalArgumentException("a spread needs at least one value, but"
                        + " got none");
            }
            double[] sorted = values.clone();
            Arrays.sort(sorted);
            int n = sorted.length;
            double median = n % 2 == 1 ? sorted[n / 2]
                    : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
            return new Spread(sorted[0], median, sorted[n - 1]);
        }

        /** @return the least value */
        public double min() {
            return min;
        }

        /** @return the median */
        public double median() {
            return median;
        }

        /** @return the largest value */
        public double max() {
            return max;
        }

        /**
         * Tell whether the spread is too wide for a verdict: max ÷ min above a bound (or
         * not a positive finite spread at all).
         *
         * @param bound the largest max ÷ min still judged (&gt;1)
         * @return true if no verdict should be drawn from it
         */
        public boolean exceeds(double bound) {
            return !(min > 0.0 && max / min <= bound);
        }
    }

    /** {@link #measureSideBySide}'s result: every workload's time per unit in every round. */
    public static final class SideBySide {
        /** [workload][round] ns per unit. */
        private final double[][] nanos;

        SideBySide(double[][] nanos) {
            this.nanos = nanos;
        }

        /**
         * Return a workload's time per unit over the rounds.
         *
         * @param workload its index in the order given to {@link #measureSideBySide}
         * @return min / median / max (in nanoseconds per unit)
         */
        public Spread nanosPerUnit(int workload) {
            return Spread.of(nanos[workload]);
        }

        /**
         * Return one workload's time over another's, taken within each round.
         *
         * @param workload the numerator's index
         * @param reference the denominator's index
         * @return min / median / max of the per-round ratios
         */
        public Spread ratio(int workload, int reference) {
            double[] ratios = new double[nanos[workload].length];
            for (int r = 0; r < ratios.length; ++r) {
                ratios[r] = nanos[workload][r] / nanos[reference][r];
            }
            return Spread.of(ratios);
        }
    }

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
        private final Spread nanosPerUnit;
        private final double bytesPerUnit;

        Measurement(Spread nanosPerUnit, double bytesPerUnit) {
            this.nanosPerUnit = nanosPerUnit;
            this.bytesPerUnit = bytesPerUnit;
        }

        /**
         * Return the median time per unit.
         *
         * @return the time (in nanoseconds)
         */
        public double nanosPerUnit() {
            return nanosPerUnit.median();
        }

        /**
         * Return the time per unit over the rounds.
         *
         * @return min / median / max (in nanoseconds)
         */
        public Spread spread() {
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
    /** A round reads its clock after at most this many units (see {@link #timeRound}). */
    static final int UNITS_PER_CLOCK_READ = 20_000;
    /** A round reads its clock about this many times (see {@link #timeRound}). */
    static final int READS_PER_ROUND = 32;

    private final long warmupNanos;
    private final long roundNanos;
    private final int rounds;
    private final Clock clock;
    /** Keeps results alive so no work is dead code. */
    private int sink;
    /** The units of the last {@link #timeRound}. */
    private long lastRoundUnits;

    /**
     * Create a meter on the thread's CPU time.
     *
     * @param budget the timing budget (not null)
     */
    public CostMeter(Budget budget) {
        this(budget, threadCpuClock());
    }

    /**
     * Create a meter on a given clock (tests: a scripted one).
     *
     * @param budget the timing budget (not null)
     * @param clock the clock (not null)
     */
    CostMeter(Budget budget, Clock clock) {
        this.warmupNanos = budget.warmupNanos();
        this.roundNanos = budget.roundNanos();
        this.rounds = budget.rounds();
        this.clock = clock;
    }

    /**
     * Return the number of measured rounds.
     *
     * @return the count (&ge;1)
     */
    public int rounds() {
        return rounds;
    }

    /**
     * Return what the clock measures, for the report's text.
     *
     * @return e.g. "thread CPU time"
     */
    public static String clockName() {
        return ManagementFactory.getThreadMXBean().isCurrentThreadCpuTimeSupported()
                ? "the measuring thread's CPU time" : "wall-clock time (this JVM has no"
                + " thread CPU clock)";
    }

    /**
     * Time several workloads side by side: each warmed up, then {@link #rounds()} rounds in
     * which every workload runs for at least a round's budget, in an order that shifts by one
     * each round (round r starts with workload r mod k).
     *
     * @param workloads the work (not null, not empty)
     * @param unitsPerCall units of each workload's call (same length, each &gt;0)
     * @return every workload's time per unit in every round
     */
    public SideBySide measureSideBySide(Workload[] workloads, int[] unitsPerCall) {
        int k = workloads.length;
        if (k == 0 || unitsPerCall.length != k) {
            throw new IllegalArgumentException("side by side needs at least one workload and"
                    + " a unit count for each, but got " + k + " and " + unitsPerCall.length);
        }
        for (int w = 0; w < k; ++w) {
            warmUp(workloads[w], unitsPerCall[w]);
        }
        double[][] nanos = new double[k][rounds];
        for (int r = 0; r < rounds; ++r) {
            for (int i = 0; i < k; ++i) {
                int w = (r + i) % k;
                nanos[w][r] = timeRound(workloads[w], unitsPerCall[w]);
            }
        }
        return new SideBySide(nanos);
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
        long start = clock.nanos();
        long before;
        do {
            before = allocatedBytes();
            sink += System.identityHashCode(workload.run(unitsPerCall));
        } while (before >= 0 && allocatedBytes() - before > overhead
                && clock.nanos() - start < MAX_COMPILE_WAIT_MILLIS * 1_000_000L);
        return measureWarm(workload, unitsPerCall);
    }

    private void warmUp(Workload workload, int unitsPerCall) {
        long calls = 0;
        long start = clock.nanos();
        while (clock.nanos() - start < warmupNanos || calls < 3) {
            sink += System.identityHashCode(workload.run(unitsPerCall));
            ++calls;
        }
    }

    private Measurement measureWarm(Workload workload, int unitsPerCall) {
        double[] perUnit = new double[rounds];
        long totalUnits = 0;
        long bytesBefore = allocatedBytes();
        for (int r = 0; r < rounds; ++r) {
            perUnit[r] = timeRound(workload, unitsPerCall);
            totalUnits += lastRoundUnits;
        }
        long bytesAfter = allocatedBytes();
        double bytes = bytesBefore < 0 ? Double.NaN
                : (double) (bytesAfter - bytesBefore) / totalUnits;
        return new Measurement(Spread.of(perUnit), bytes);
    }

    /**
     * One round: calls until the round's budget is spent. Reading the thread's CPU clock
     * costs a fraction of a microsecond, as much as a call of a thousand particle-steps, so
     * after the first call (timed alone) the clock is read once per batch of calls: as many
     * as take about {@value #READS_PER_ROUND}th of the round by the first call's time, and at
     * most {@value #UNITS_PER_CLOCK_READ} units. A round overruns its budget by at most one
     * batch.
     *
     * @return the time per unit (ns); {@link #lastRoundUnits} says how many units ran
     */
    private double timeRound(Workload workload, int unitsPerCall) {
        long roundStart = clock.nanos();
        sink += System.identityHashCode(workload.run(unitsPerCall));
        long units = unitsPerCall;
        long elapsed = clock.nanos() - roundStart;
        int mostCalls = Math.max(1, UNITS_PER_CLOCK_READ / unitsPerCall);
        int callsPerRead = elapsed <= 0 ? mostCalls
                : (int) Math.max(1, Math.min(mostCalls, roundNanos / READS_PER_ROUND / elapsed));
        while (elapsed < roundNanos) {
            for (int i = 0; i < callsPerRead; ++i) {
                sink += System.identityHashCode(workload.run(unitsPerCall));
            }
            units += (long) callsPerRead * unitsPerCall;
            elapsed = clock.nanos() - roundStart;
        }
        lastRoundUnits = units;
        return (double) elapsed / units;
    }

    private static Clock threadCpuClock() {
        java.lang.management.ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        if (threads.isCurrentThreadCpuTimeSupported()) {
            return threads::getCurrentThreadCpuTime;
        }
        return System::nanoTime;
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

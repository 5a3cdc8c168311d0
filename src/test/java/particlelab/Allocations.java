package particlelab;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;

/**
 * Measures the heap bytes the current thread allocates while it runs some code, to prove that
 * per-step and per-frame code allocates nothing.
 *
 * <p>It reads HotSpot's per-thread allocation counter
 * ({@code com.sun.management.ThreadMXBean#getThreadAllocatedBytes}), which counts every object
 * the thread allocates, whatever the garbage collector does; allocations by other threads
 * (the JIT compiler, the garbage collector) are not counted. Typical use:
 *
 * <pre>
 * Allocations.assertAllocatesNothing("100_000 steps", () -&gt; {
 *     for (int i = 0; i &lt; 100_000; ++i) {
 *         integrator.step(particle, h);
 *     }
 * });
 * </pre>
 *
 * Create the {@code Runnable} and everything it uses before the call: only what happens
 * inside {@code run()} is measured.
 */
public final class Allocations {

    /**
     * Runs before measuring, so that class loading, lambda linkage and the first (interpreted)
     * calls, which may allocate once, are not counted.
     */
    private static final int WARM_UP_RUNS = 3;
    /**
     * Warm-up runs at most, and time at most (ns), while a run still allocates: code the JIT
     * has not compiled yet can allocate where its compiled form does not (the Vector API's
     * vectors are objects until C2 keeps them in registers, a few hundred ms into a run).
     */
    private static final int MAX_WARM_UP_RUNS = 40;
    private static final long MAX_WARM_UP_NANOS = 3_000_000_000L;
    /** Measurements taken; the smallest counts, so a one-off allocation cannot fail a test. */
    private static final int MEASURED_RUNS = 3;
    /** Empty runs measured to calibrate the counter's own overhead. */
    private static final int CALIBRATION_RUNS = 20;
    /** Does nothing: what the calibration measures. */
    private static final Runnable NOTHING = () -> {
    };

    private Allocations() {
    }

    /**
     * Measure the bytes the current thread allocates while running {@code action} once, with no
     * warm-up. The figure includes the counter's own overhead, see {@link #overheadBytes()}.
     *
     * @param action the code to measure (not null)
     * @return the bytes allocated (&ge;0)
     */
    public static long bytesAllocatedBy(Runnable action) {
        com.sun.management.ThreadMXBean threads = threadBean();
        long threadId = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(threadId);
        action.run();
        long after = threads.getThreadAllocatedBytes(threadId);
        return after - before;
    }

    /**
     * Measure what reading the counter itself allocates: the largest figure measured around an
     * empty action, after warm-up (0 on current HotSpot JVMs, but not promised).
     *
     * @return the overhead (in bytes, &ge;0)
     */
    public static long overheadBytes() {
        for (int i = 0; i < WARM_UP_RUNS; ++i) {
            bytesAllocatedBy(NOTHING);
        }
        long overhead = 0L;
        for (int i = 0; i < CALIBRATION_RUNS; ++i) {
            overhead = Math.max(overhead, bytesAllocatedBy(NOTHING));
        }
        return overhead;
    }

    /**
     * Measure the bytes {@code action} allocates once warm: run it a few times unmeasured
     * (more while it still allocates, within limits), then return the smallest of a few measurements, less the calibrated overhead.
     *
     * @param action the code to measure; it runs several times, so it must be repeatable
     *     (not null)
     * @return the bytes allocated by one warm run (&ge;0)
     */
    public static long warmBytesAllocatedBy(Runnable action) {
        for (int i = 0; i < WARM_UP_RUNS; ++i) {
            action.run();
        }
        long overhead = overheadBytes();
        long warmStart = System.nanoTime();
        for (int i = WARM_UP_RUNS; i < MAX_WARM_UP_RUNS
                && System.nanoTime() - warmStart < MAX_WARM_UP_NANOS; ++i) {
            if (bytesAllocatedBy(action) <= overhead) {
                break;
            }
        }
        long least = Long.MAX_VALUE;
        for (int i = 0; i < MEASURED_RUNS; ++i) {
            least = Math.min(least, bytesAllocatedBy(action));
        }
        return Math.max(0L, least - overhead);
    }

    /**
     * Assert that {@code action}, once warm, allocates nothing beyond the counter's own
     * calibrated overhead.
     *
     * @param what what the action does, for the failure message (e.g. "100_000 steps")
     * @param action the code to check; it runs several times, so it must be repeatable
     *     (not null)
     */
    public static void assertAllocatesNothing(String what, Runnable action) {
        long bytes = warmBytesAllocatedBy(action);
        assertTrue(bytes == 0L, () -> what + " allocated " + bytes + " bytes, expected none");
    }

    private static com.sun.management.ThreadMXBean threadBean() {
        java.lang.management.ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        if (!(bean instanceof com.sun.management.ThreadMXBean)) {
            throw new IllegalStateException(
                    "this JVM has no per-thread allocation counter (com.sun.management)");
        }
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) bean;
        if (!threads.isThreadAllocatedMemorySupported()) {
            throw new IllegalStateException("this JVM cannot count bytes allocated per thread");
        }
        if (!threads.isThreadAllocatedMemoryEnabled()) {
            threads.setThreadAllocatedMemoryEnabled(true);
        }
        return threads;
    }
}

package particlelab.world;

/**
 * The last steps' states of a simulation, in a bounded ring: after every step
 * {@link #record} writes the state of a {@link StateRecord} (and the step's h) into the next
 * entry, over the oldest once the ring is full; {@link #restore} puts any entry back. Entries
 * are numbered from the first state recorded since the last {@link #clear}, so a number keeps
 * meaning the same step while older entries are dropped.
 *
 * <p>Bounded: every entry has the same size (the stride, the largest state recorded so far);
 * the ring holds at most {@code maxSteps} entries, fewer if that many would not fit in the
 * byte budget ({@code capacity = min(maxSteps, budget / (4·(stride + 2)))}, at least 2). So a
 * world of many bodies keeps fewer seconds. The arrays are allocated at the first record and
 * again only when a state outgrows the stride (a body spawned for the first time), when the
 * newest entries are copied over; otherwise recording allocates nothing.
 */
public final class StateRing {

    /** The default byte budget of the ring's arrays (64 MiB). */
    public static final long DEFAULT_BUDGET_BYTES = 64L << 20;
    /** The default cap on entries: a minute of steps at 60 per second. */
    public static final int DEFAULT_MAX_STEPS = 3600;
    /** Bytes per int. */
    private static final int INT_BYTES = Integer.BYTES;
    /** Ints per entry beside the state: its length and its h. */
    private static final int ENTRY_OVERHEAD_INTS = 2;
    /** The fewest entries a ring keeps, whatever the budget: a step back needs two. */
    private static final int MIN_CAPACITY = 2;

    private final long budgetBytes;
    private int maxSteps;
    private final StateSlab slab = new StateSlab();
    private int[] data = new int[0];
    private int[] lengths = new int[0];
    private float[] stepSeconds = new float[0];
    private int stride;
    private int capacity;
    /** The number of the oldest entry kept. */
    private long first;
    private int count;

    /** Create a ring of {@link #DEFAULT_BUDGET_BYTES} and {@link #DEFAULT_MAX_STEPS}. */
    public StateRing() {
        this(DEFAULT_BUDGET_BYTES, DEFAULT_MAX_STEPS);
    }

    /**
     * Create an empty ring.
     *
     * @param budgetBytes the most bytes its arrays may take (&gt;0; a state too large for two
     *     entries in it still gets two)
     * @param maxSteps the most entries it keeps (&ge;2)
     */
    public StateRing(long budgetBytes, int maxSteps) {
        if (budgetBytes <= 0L) {
            throw new IllegalArgumentException(
                    "ring budget (bytes) must be > 0, but was " + budgetBytes);
        }
        if (maxSteps < MIN_CAPACITY) {
            throw new IllegalArgumentException("ring steps must be >= " + MIN_CAPACITY
                    + ", but was " + maxSteps);
        }
        this.budgetBytes = budgetBytes;
        this.maxSteps = maxSteps;
    }

    /**
     * Cap the entries lower before anything is recorded: a what-if fork's twin keeps only
     * its newest states, so forks do not cost a ring each.
     *
     * @param newMaxSteps the most entries it keeps (&ge;2, &le;{@link #getMaxSteps()})
     * @throws IllegalStateException once the ring recorded (its arrays are sized)
     */
    public void limitSteps(int newMaxSteps) {
        if (newMaxSteps < MIN_CAPACITY || newMaxSteps > maxSteps) {
            throw new IllegalArgumentException("ring steps must be from " + MIN_CAPACITY
                    + " to " + maxSteps + ", but was " + newMaxSteps);
        }
        if (capacity != 0) {
            throw new IllegalStateException("ring steps can be limited only before the first"
                    + " record");
        }
        maxSteps = newMaxSteps;
    }

    /**
     * Record a state after the newest entry, dropping the oldest if the ring is full.
     * Allocates nothing unless the state outgrew the stride.
     *
     * @param record what to write (not null)
     * @param stepSecondsTaken h of the step that led to this state (in seconds, &ge;0; 0 for
     *     a state not reached by a step: a start, a launch)
     */
    public void record(StateRecord record, float stepSecondsTaken) {
        int needed = record.countStateInts();
        if (needed > stride || capacity == 0) {
            grow(needed);
        }
        if (count == capacity) {
            ++first;
            --count;
        }
        long index = first + count;
        int slot = slot(index);
        slab.point(data, slot * stride, slot * stride + needed);
        record.writeState(slab);
        lengths[slot] = slab.position();
        stepSeconds[slot] = stepSecondsTaken;
        ++count;
    }

    /**
     * Put a recorded state back.
     *
     * @param index the entry's number (from {@link #getFirstIndex()} to
     *     {@link #getLastIndex()})
     * @param record what to read into (not null, the one that wrote it)
     */
    public void restore(long index, StateRecord record) {
        record.readState(read(index));
    }

    /**
     * Point a slab at a recorded state, to read parts of it (the export reads positions).
     *
     * @param index the entry's number (from {@link #getFirstIndex()} to
     *     {@link #getLastIndex()})
     * @return the ring's own slab, at the entry's start (valid until the next call)
     */
    public StateSlab read(long index) {
        int slot = slot(check(index));
        slab.point(data, slot * stride, slot * stride + lengths[slot]);
        return slab;
    }

    /**
     * Drop every entry after one: the simulation goes on from that state, so the later steps
     * are no longer its future.
     *
     * @param index the entry kept as the newest (from {@link #getFirstIndex()} to
     *     {@link #getLastIndex()})
     */
    public void truncateAfter(long index) {
        count = (int) (check(index) - first + 1);
    }

    /** Forget every entry; the next one recorded is number 0. Keeps the arrays. */
    public void clear() {
        first = 0L;
        count = 0;
    }

    /**
     * Count the entries kept.
     *
     * @return the count (&ge;0, &le;{@link #getCapacity()})
     */
    public int size() {
        return count;
    }

    /**
     * Return the number of the oldest entry kept.
     *
     * @return the number (&ge;0)
     */
    public long getFirstIndex() {
        return first;
    }

    /**
     * Return the number of the newest entry.
     *
     * @return the number ({@link #getFirstIndex()} − 1 when empty)
     */
    public long getLastIndex() {
        return first + count - 1;
    }

    /**
     * Return h of the step that led to an entry's state.
     *
     * @param index the entry's number
     * @return h (in seconds, &ge;0; 0 for a start or a launch)
     */
    public float getStepSeconds(long index) {
        return stepSeconds[slot(check(index))];
    }

    /**
     * Return the simulated time the entries span: the sum of h from the oldest to the newest.
     * Allocates nothing.
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getSpanSeconds() {
        double sum = 0.0;
        for (long i = first + 1; i < first + count; ++i) {
            sum += stepSeconds[slot(i)];
        }
        return sum;
    }

    /**
     * Copy an entry's ints, for a test that compares two runs bit for bit.
     *
     * @param index the entry's number
     * @return a new array of the entry's ints (not null)
     */
    public int[] copyEntry(long index) {
        int slot = slot(check(index));
        int[] copy = new int[lengths[slot]];
        System.arraycopy(data, slot * stride, copy, 0, copy.length);
        return copy;
    }

    /**
     * Return how many entries the ring holds at its current stride.
     *
     * @return the capacity (0 before the first record, else &ge;2)
     */
    public int getCapacity() {
        return capacity;
    }

    /**
     * Return the ints of the largest state recorded so far: every entry's size.
     *
     * @return the stride (&ge;0)
     */
    public int getStrideInts() {
        return stride;
    }

    /**
     * Return the bytes the ring's arrays take now.
     *
     * @return the size (in bytes, &ge;0; at most the budget unless a state is too large for
     *     two entries of it)
     */
    public long getBytes() {
        return (long) INT_BYTES * (data.length + lengths.length + stepSeconds.length);
    }

    /** @return the most bytes the arrays may take (the budget) */
    public long getBudgetBytes() {
        return budgetBytes;
    }

    /** @return the most entries the ring keeps, whatever the budget */
    public int getMaxSteps() {
        return maxSteps;
    }

    /** Size the arrays for a larger stride, keeping the newest entries that still fit. */
    private void grow(int needed) {
        int newStride = Math.max(needed, stride + stride / 2);
        long fit = budgetBytes / ((long) INT_BYTES * (newStride + ENTRY_OVERHEAD_INTS));
        int newCapacity = (int) Math.max(MIN_CAPACITY, Math.min(maxSteps, fit));
        int[] newData = new int[newStride * newCapacity];
        int[] newLengths = new int[newCapacity];
        float[] newSteps = new float[newCapacity];
        int kept = Math.min(count, newCapacity);
        long newFirst = first + count - kept;
        for (long i = newFirst; i < newFirst + kept; ++i) {
            int from = slot(i);
            int to = (int) (i % newCapacity);
            System.arraycopy(data, from * stride, newData, to * newStride, lengths[from]);
            newLengths[to] = lengths[from];
            newSteps[to] = stepSeconds[from];
        }
        data = newData;
        lengths = newLengths;
        stepSeconds = newSteps;
        stride = newStride;
        capacity = newCapacity;
        first = newFirst;
        count = kept;
    }

    private int slot(long index) {
        return (int) (index % capacity);
    }

    private long check(long index) {
        if (index < first || index >= first + count) {
            throw new IllegalArgumentException("ring entry must be from " + first + " to "
                    + (first + count - 1) + ", but was " + index);
        }
        return index;
    }
}

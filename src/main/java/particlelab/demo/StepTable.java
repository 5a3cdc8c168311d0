package particlelab.demo;

import java.io.IOException;
import java.io.Writer;
import particlelab.world.StateSlab;

/**
 * Numbers a demo records for its export where it has no free particle to trace (the rotation
 * boxes' orientations, the fountain's counts, the iterative aimer's shots): one CSV file with
 * a fixed header and one row per step or shot.
 *
 * <p>Bounded and allocation-free while recording: the rows live in one {@code float} array
 * sized at construction; past its capacity the first rows are kept and later ones only
 * counted ({@link #countDropped()}), as {@link TrajectoryRecord} does.
 */
public final class StepTable {

    /** The rows a step table keeps by default: 8192, about 2 min 16 s of steps at 60/s. */
    public static final int DEFAULT_CAPACITY = 1 << 13;

    /** Below this, a float holds every integer exactly (2^24). */
    private static final float EXACT_INTEGERS = 1 << 24;

    private final String name;
    private final String header;
    private final int columns;
    private final int capacity;
    private final float[] values;
    private int size;
    private long dropped;
    /** The next column of the row being written, or -1 between rows. */
    private int column = -1;
    /** Whether the row being written is kept (false past the capacity). */
    private boolean keeping;

    /**
     * Create an empty table.
     *
     * @param name its file name without {@code .csv}, file-safe (not null, not empty)
     * @param header the CSV header, column names separated by commas (not null)
     * @param capacity the most rows kept (&ge;1)
     */
    public StepTable(String name, String header, int capacity) {
        if (name == null || name.isEmpty() || !name.equals(TrajectoryExport.fileSafeName(name))
                || header == null || header.isEmpty() || capacity < 1) {
            throw new IllegalArgumentException("a step table needs a file-safe name, a header"
                    + " and a capacity >= 1, but had " + name + ", " + header + ", "
                    + capacity);
        }
        this.name = name;
        this.header = header;
        this.columns = header.split(",", -1).length;
        this.capacity = capacity;
        this.values = new float[capacity * columns];
    }

    /** @return the file name without {@code .csv} (not null) */
    public String getName() {
        return name;
    }

    /** @return the CSV header (not null) */
    public String getHeader() {
        return header;
    }

    /** @return the rows kept (&ge;0) */
    public int size() {
        return size;
    }

    /** @return the most rows kept (&ge;1) */
    public int capacity() {
        return capacity;
    }

    /** @return the rows past the capacity that were counted, not kept (&ge;0) */
    public long countDropped() {
        return dropped;
    }

    /**
     * Write the table's counters into a state slab (the rows are only appended to by the
     * steps): 3 ints. For a demo's state record, so a step back forgets the rows after it.
     *
     * @param slab where to write (not null, modified)
     */
    public void writeState(StateSlab slab) {
        slab.putInt(size);
        slab.putLong(dropped);
    }

    /**
     * Put back counters {@link #writeState} wrote: the rows after that state's are forgotten.
     *
     * @param slab where to read (not null, modified)
     */
    public void readState(StateSlab slab) {
        size = slab.getInt();
        dropped = slab.getLong();
        column = -1;
    }

    /** Forget every row (a reset). Allocates nothing. */
    public void clear() {
        size = 0;
        dropped = 0L;
        column = -1;
    }

    /**
     * Start a row; give its values with {@link #put}, in the header's order. Allocates
     * nothing.
     *
     * @return this table, for chaining
     */
    public StepTable startRow() {
        keeping = size < capacity;
        if (!keeping) {
            ++dropped;
        }
        column = 0;
        return this;
    }

    /**
     * Give the next value of the row started last; the row is complete with its last column.
     * Allocates nothing.
     *
     * @param value the value (in the unit its column names)
     * @return this table, for chaining
     * @throws IllegalStateException if no row was started or the row is already complete
     */
    public StepTable put(double value) {
        if (column < 0) {
            throw new IllegalStateException("start a row of " + name + " first");
        }
        if (keeping) {
            values[size * columns + column] = (float) value;
        }
        if (++column == columns) {
            if (keeping) {
                ++size;
            }
            column = -1;
        }
        return this;
    }

    /**
     * Write the header and every row kept, one line each, numbers as Java prints a float
     * (whole numbers without {@code .0}).
     *
     * @param out where (not null; not closed)
     * @throws IOException if writing fails
     */
    public void writeCsv(Writer out) throws IOException {
        String newline = System.lineSeparator();
        out.write(header);
        out.write(newline);
        StringBuilder line = new StringBuilder(16 * columns);
        for (int row = 0; row < size; ++row) {
            line.setLength(0);
            for (int c = 0; c < columns; ++c) {
                if (c > 0) {
                    line.append(',');
                }
                float value = values[row * columns + c];
                if (value == Math.rint(value) && Math.abs(value) < EXACT_INTEGERS) {
                    // counts and shot numbers: 334, not 334.0
                    line.append((int) value);
                } else {
                    line.append(value);
                }
            }
            out.append(line).append(newline);
        }
    }
}

package particlelab.demo;

import java.io.IOException;
import java.io.Writer;
import java.util.Arrays;
import particlelab.physics.Particle;
import particlelab.world.StateSlab;

/**
 * Every state one particle has had since its launch, kept for the export: one row
 * {@code t, x, y, z, vx, vy, vz} for the launch state and one after each step, exactly the rows
 * {@code particle-lab trajectory} prints for the same launch and h.
 *
 * <p>The rows are the integrator's states: the row of the step that came down through the
 * ground is the stepped state below {@code y = 0}, as {@code trajectory --until-ground}
 * prints it, not the landing point the demo then holds the particle at (the HUD shows that).
 * {@code t} is computed like the trajectory command's, {@code n·h} from the step count, so it
 * does not drift; when h changes (raw tpf, or a new fixed step) the count starts again from
 * the time reached: {@code t = t_change + n'·h}.
 *
 * <p>Bounded: the rows live in one preallocated {@code float} array of
 * {@value #INITIAL_ROWS} rows that doubles when full (a rare allocation, never once it is
 * large enough for the flights the demo has), up to {@value #MAX_ROWS} rows, about 18 minutes
 * of steps at 60 per second (1.8 MB). Past the cap the first {@value #MAX_ROWS} rows are kept
 * and later steps are only counted ({@link #countDropped()}), so an export still starts at the
 * launch and says how many steps it lost.
 */
public final class TrajectoryRecord {

    /** The CSV header, exactly that of {@code particle-lab trajectory}. */
    public static final String HEADER = "t,x,y,z,vx,vy,vz";
    /** The rows an empty record has room for. */
    public static final int INITIAL_ROWS = 256;
    /** The most rows a record keeps; later steps are counted, not kept. */
    public static final int MAX_ROWS = 1 << 16;
    /** The ints of {@link #writeState}. */
    static final int STATE_INTS = 1 + 2 + 2 + 1 + 2;
    /** Values per row: t, P, V. */
    private static final int ROW_VALUES = 7;

    private float[] rows = new float[INITIAL_ROWS * ROW_VALUES];
    private int size;
    private long dropped;
    /** The time reached when h last changed (in seconds). */
    private double baseSeconds;
    /** The h of the steps since then (in seconds; 0 before the first step). */
    private float uniformStepSeconds;
    /** Steps of uniformStepSeconds since baseSeconds. */
    private long uniformSteps;

    /**
     * Make room for the whole cap at once, {@value #MAX_ROWS} rows (1.8 MB): for a flight
     * that never ends (a mass on a spring), whose record would otherwise double now and then
     * for 18 minutes. Allocates once; the rows kept are kept.
     */
    public void reserveAll() {
        if (rows.length < MAX_ROWS * ROW_VALUES) {
            rows = Arrays.copyOf(rows, MAX_ROWS * ROW_VALUES);
        }
    }

    /**
     * Forget every row: the particle is launched again. Allocates nothing.
     */
    public void clear() {
        size = 0;
        dropped = 0L;
        baseSeconds = 0.0;
        uniformStepSeconds = 0f;
        uniformSteps = 0L;
    }

    /**
     * Record the launch state as the row at {@code t = 0}, if no row is recorded yet.
     * Allocates nothing.
     *
     * @param particle the particle, before its first step (not null, not modified)
     */
    public void begin(Particle particle) {
        if (size == 0 && dropped == 0L) {
            append(0f, particle);
        }
    }

    /**
     * Record the state after a step. Allocates only when the rows outgrow their array (it
     * doubles), never past {@value #MAX_ROWS} rows.
     *
     * @param particle the particle, just stepped (not null, not modified)
     * @param stepSeconds h of the step (in seconds, &gt;0)
     */
    public void add(Particle particle, float stepSeconds) {
        if (stepSeconds != uniformStepSeconds) {
            baseSeconds = currentSeconds();
            uniformStepSeconds = stepSeconds;
            uniformSteps = 0L;
        }
        ++uniformSteps;
        append((float) currentSeconds(), particle);
    }

    /**
     * Count the rows kept.
     *
     * @return the count (&ge;0, at most {@value #MAX_ROWS})
     */
    public int size() {
        return size;
    }

    /**
     * Count the steps taken after the record was full, whose rows were not kept.
     *
     * @return the count (&ge;0)
     */
    public long countDropped() {
        return dropped;
    }

    /**
     * Return one value of a row.
     *
     * @param row the row (&ge;0, &lt;{@link #size()})
     * @param column 0 for t, 1–3 for x, y, z, 4–6 for vx, vy, vz
     * @return the value
     */
    public float get(int row, int column) {
        if (row < 0 || row >= size || column < 0 || column >= ROW_VALUES) {
            throw new IllegalArgumentException("row must be from 0 to " + (size - 1)
                    + " and column from 0 to " + (ROW_VALUES - 1) + ", but were " + row + ", "
                    + column);
        }
        return rows[row * ROW_VALUES + column];
    }

    /**
     * Append one row as CSV, without a line end, in the trajectory command's number format:
     * every value as {@link StringBuilder#append(float)} writes it, the shortest decimal that
     * reads back as the same float.
     *
     * @param row the row (&ge;0, &lt;{@link #size()})
     * @param storeResult where to append (not null, modified)
     * @return storeResult
     */
    public StringBuilder appendCsvRow(int row, StringBuilder storeResult) {
        // Refuses a row out of range, with the range.
        get(row, 0);
        int base = row * ROW_VALUES;
        storeResult.append(rows[base]);
        for (int column = 1; column < ROW_VALUES; ++column) {
            storeResult.append(',').append(rows[base + column]);
        }
        return storeResult;
    }

    /**
     * Write the header and every row, each line ending in the platform's line separator (as
     * {@code PrintStream.println} ends the trajectory command's lines).
     *
     * @param out where to write (not null)
     * @throws IOException if writing fails
     */
    public void writeCsv(Writer out) throws IOException {
        String newline = System.lineSeparator();
        out.write(HEADER);
        out.write(newline);
        StringBuilder line = new StringBuilder(128);
        for (int row = 0; row < size; ++row) {
            line.setLength(0);
            appendCsvRow(row, line).append(newline);
            out.append(line);
        }
    }

    /**
     * Write the record's counters (not its rows, which the steps only append to) into a
     * state slab: {@value #STATE_INTS} ints. Allocates nothing.
     *
     * @param slab where to write (not null, modified)
     */
    void writeState(StateSlab slab) {
        slab.putInt(size);
        slab.putLong(dropped);
        slab.putDouble(baseSeconds);
        slab.putFloat(uniformStepSeconds);
        slab.putLong(uniformSteps);
    }

    /**
     * Put back counters {@link #writeState} wrote: the rows after that state's are forgotten.
     * A state older than the last launch (whose rows were written over since) leaves the
     * rows it names as they are now.
     *
     * @param slab where to read (not null, modified)
     */
    void readState(StateSlab slab) {
        size = slab.getInt();
        dropped = slab.getLong();
        baseSeconds = slab.getDouble();
        uniformStepSeconds = slab.getFloat();
        uniformSteps = slab.getLong();
    }

    /** t after the steps since the last change of h: {@code t_change + n'·h}. */
    private double currentSeconds() {
        return baseSeconds + uniformSteps * (double) uniformStepSeconds;
    }

    private void append(float seconds, Particle particle) {
        if (size == MAX_ROWS) {
            ++dropped;
            return;
        }
        int base = size * ROW_VALUES;
        if (base + ROW_VALUES > rows.length) {
            rows = Arrays.copyOf(rows, Math.min(2 * rows.length, MAX_ROWS * ROW_VALUES));
        }
        rows[base] = seconds;
        rows[base + 1] = particle.position.x;
        rows[base + 2] = particle.position.y;
        rows[base + 3] = particle.position.z;
        rows[base + 4] = particle.velocity.x;
        rows[base + 5] = particle.velocity.y;
        rows[base + 6] = particle.velocity.z;
        ++size;
    }
}

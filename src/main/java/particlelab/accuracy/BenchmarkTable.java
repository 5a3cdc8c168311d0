package particlelab.accuracy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import particlelab.files.SafeFiles;
import particlelab.reference.CostMeter;
import particlelab.reference.Scheme;


/**
 * The rows of {@code benchmarks.csv}, written by the JMH runner and by the report's own
 * timing loop alike, with the fixed header {@value #HEADER}. Row names:
 * each scheme's {@link Scheme#id()} (one particle), {@value #LECTURE_STYLE} and
 * {@value #PRIMITIVE_LOOP} (one particle), and {@code bulk/KIND/N} for N particles, KIND one of
 * {@value #BULK_LECTURE}, {@value #BULK_OBJECTS}, {@value #BULK_BATCH}, {@value #BULK_PRIMITIVE}
 * (gravity + linear drag); then for every {@link ForceMix} {@code single/<mix>/<path>} (one
 * particle, {@link OneParticleMixScene}) and {@code bulk/<mix>/<path>/<N>} (N particles,
 * {@link BulkScene}), {@code <path>} one of {@value #PATH_LECTURE}, {@value #PATH_OBJECTS}
 * ({@code step(Particle, h)} on each particle), {@value #PATH_BATCH} (bulk only, the scalar
 * form the app runs by default), {@value #PATH_BATCH_VECTOR} (bulk only, gravity and linear
 * drag in a JVM with the Vector API) and {@value #PATH_PRIMITIVE}.
 */
public final class BenchmarkTable {

    /** The CSV header, fixed so other tools can read the file. */
    public static final String HEADER = "benchmark,ns_per_particle_step,bytes_per_step";
    /** The lecture's allocating Vector3f code, one particle. */
    public static final String LECTURE_STYLE = "lecture-style";
    /** The hand-written primitive float loop, one particle. */
    public static final String PRIMITIVE_LOOP = "primitive-loop";
    /** Bulk: lecture-style objects. */
    public static final String BULK_LECTURE = "lecture-style";
    /** Bulk: an array of Particle objects through ParticleIntegrator.step(Particle[], h). */
    public static final String BULK_OBJECTS = "shared-objects";
    /** Bulk: ParticleBatch.stepPacked over planar float arrays. */
    public static final String BULK_BATCH = "shared-batch";
    /** Bulk: the hand-written primitive loop. */
    public static final String BULK_PRIMITIVE = "primitive-loop";

    /** Path of a mix row: the lecture's allocating Vector3f code. */
    public static final String PATH_LECTURE = "lecture-style";
    /** Path of a mix row: Particle objects, one {@code step(Particle, h)} each. */
    public static final String PATH_OBJECTS = "shared-objects";
    /** Path of a bulk mix row: {@code ParticleBatch.stepPacked} over planar arrays. */
    public static final String PATH_BATCH = "shared-batch";
    /**
     * Path of a bulk mix row: {@code stepPacked} on the Vector API, only for the mixes that
     * have that form ({@link ForceMix#hasVectorBatch}) and in a JVM that has the API.
     */
    public static final String PATH_BATCH_VECTOR = "shared-batch-vector";
    /** Path of a mix row: the hand-written primitive loop for the mix. */
    public static final String PATH_PRIMITIVE = "primitive-loop";

    private final List<Row> rows = new ArrayList<>();

    /** One measured benchmark. */
    public static final class Row {
        private final String name;
        private final double nanosPerParticleStep;
        private final double bytesPerStep;
        /** The least and largest time per particle-step over the rounds (ns; NaN: unknown). */
        private final double minNanos;
        private final double maxNanos;

        /**
         * Create a row whose spread is unknown (read from a CSV: JMH's or an earlier run's).
         *
         * @param name the benchmark's name (not null, no comma)
         * @param nanosPerParticleStep the time per particle-step (in ns)
         * @param bytesPerStep the heap allocated per particle-step (in bytes; NaN if unknown)
         */
        public Row(String name, double nanosPerParticleStep, double bytesPerStep) {
            this(name, nanosPerParticleStep, Double.NaN, Double.NaN, bytesPerStep);
        }

        /**
         * Create a row with its spread over rounds.
         *
         * @param name the benchmark's name (not null, no comma)
         * @param nanosPerParticleStep the median time per particle-step (in ns)
         * @param minNanos the least round's time per particle-step (in ns; NaN if unknown)
         * @param maxNanos the largest round's (in ns; NaN if unknown)
         * @param bytesPerStep the heap allocated per particle-step (in bytes; NaN if unknown)
         */
        public Row(String name, double nanosPerParticleStep, double minNanos, double maxNanos,
                double bytesPerStep) {
            this.minNanos = minNanos;
            this.maxNanos = maxNanos;
            if (name == null || name.indexOf(',') >= 0) {
                throw new IllegalArgumentException(
                        "benchmark name must be text without commas, but was " + name);
            }
            this.name = name;
            this.nanosPerParticleStep = nanosPerParticleStep;
            this.bytesPerStep = bytesPerStep;
        }

        /**
         * Return the benchmark's name.
         *
         * @return e.g. {@code "rk4"} or {@code "bulk/shared-batch/1000"}
         */
        public String name() {
            return name;
        }

        /**
         * Return the time per particle-step.
         *
         * @return the time (in nanoseconds)
         */
        public double nanosPerParticleStep() {
            return nanosPerParticleStep;
        }

        /**
         * Return the heap allocated per particle-step.
         *
         * @return the allocation (in bytes; NaN if unknown)
         */
        public double bytesPerStep() {
            return bytesPerStep;
        }

        /**
         * Return the least round's time per particle-step.
         *
         * @return the time (in nanoseconds; NaN if the row has no spread)
         */
        public double minNanos() {
            return minNanos;
        }

        /**
         * Return the largest round's time per particle-step.
         *
         * @return the time (in nanoseconds; NaN if the row has no spread)
         */
        public double maxNanos() {
            return maxNanos;
        }

        /**
         * Tell whether the row's rounds spread too widely for a verdict ({@link
         * CostMeter.Spread#exceeds}); a row without a spread (JMH's) is judged.
         *
         * @param bound the largest max ÷ min still judged
         * @return true if max ÷ min exceeds the bound
         */
        public boolean isTooNoisy(double bound) {
            return !Double.isNaN(minNanos) && new CostMeter.Spread(minNanos,
                    nanosPerParticleStep, maxNanos).exceeds(bound);
        }
    }

    /**
     * Name a bulk benchmark.
     *
     * @param kind one of the {@code BULK_*} kinds (not null)
     * @param particles N (&gt;0)
     * @return {@code bulk/KIND/N}
     */
    public static String bulkName(String kind, int particles) {
        return "bulk/" + kind + "/" + particles;
    }

    /**
     * Name a one-particle benchmark of a force mix.
     *
     * @param mix the forces (not null)
     * @param path one of the {@code PATH_*} paths but {@link #PATH_BATCH} (not null)
     * @return {@code single/<mix>/<path>}
     */
    public static String singleName(ForceMix mix, String path) {
        return "single/" + mix.id() + "/" + path;
    }

    /**
     * Name an N-particle benchmark of a force mix.
     *
     * @param mix the forces (not null)
     * @param path one of the {@code PATH_*} paths (not null)
     * @param particles N (&gt;0)
     * @return {@code bulk/<mix>/<path>/<N>}
     */
    public static String bulkName(ForceMix mix, String path, int particles) {
        return "bulk/" + mix.id() + "/" + path + "/" + particles;
    }

    /**
     * Add a row.
     *
     * @param row the row (not null)
     */
    public void add(Row row) {
        rows.add(row);
    }

    /**
     * Access the rows in the order added.
     *
     * @return an unmodifiable view
     */
    public List<Row> rows() {
        return Collections.unmodifiableList(rows);
    }

    /**
     * Find a row by name.
     *
     * @param name the benchmark's name (not null)
     * @return the row, or null if absent
     */
    public Row find(String name) {
        for (Row row : rows) {
            if (row.name.equals(name)) {
                return row;
            }
        }
        return null;
    }

    /**
     * Write the table as CSV, replacing a regular file there (gradle jmh writes its table
     * anew each run) but never writing through a symbolic link ({@link SafeFiles}).
     *
     * @param file where to write (not null; parent folders are created)
     * @throws IOException if the file cannot be written or is refused
     */
    public void write(Path file) throws IOException {
        write(file, true);
    }

    /**
     * Write the table as CSV by the rules of {@link SafeFiles}: created new, never through a
     * symbolic link, an existing regular file replaced only if allowed.
     *
     * @param file where to write (not null; parent folders are created)
     * @param replace true if an existing regular file may be replaced
     * @throws IOException if the file cannot be written or is refused (the message says why)
     */
    public void write(Path file, boolean replace) throws IOException {
        StringBuilder text = new StringBuilder(HEADER).append('\n');
        for (Row row : rows) {
            text.append(row.name).append(',')
                    .append(String.format(Locale.ROOT, "%.4f", row.nanosPerParticleStep))
                    .append(',')
                    .append(String.format(Locale.ROOT, "%.2f", row.bytesPerStep)).append('\n');
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        SafeFiles.write(file, text, replace);
    }

    /**
     * Read a table written by {@link #write}.
     *
     * @param file the CSV file (not null)
     * @return a new table
     * @throws IOException if the file cannot be read
     * @throws IllegalArgumentException if the header or a row is malformed
     */
    public static BenchmarkTable read(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        if (lines.isEmpty() || !lines.get(0).trim().equals(HEADER)) {
            throw new IllegalArgumentException(file + " must start with the header " + HEADER
                    + ", but began " + (lines.isEmpty() ? "empty" : lines.get(0)));
        }
        BenchmarkTable table = new BenchmarkTable();
        for (int i = 1; i < lines.size(); ++i) {
            String line = lines.get(i).trim();
            if (line.isEmpty()) {
                continue;
            }
            String[] cells = line.split(",");
            if (cells.length != 3) {
                throw new IllegalArgumentException(file + " line " + (i + 1)
                        + " must have 3 cells, but was " + line);
            }
            table.add(new Row(cells[0], Double.parseDouble(cells[1]),
                    Double.parseDouble(cells[2])));
        }
        return table;
    }
}

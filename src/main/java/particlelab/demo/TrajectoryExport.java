package particlelab.demo;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import particlelab.files.SafeFiles;
import particlelab.world.StateRing;

/**
 * Writes a demo's trajectories as CSV, one file per particle, {@code FOLDER/<particle>.csv}
 * with the {@code particle-lab trajectory} header and number format ({@link TrajectoryRecord}):
 * every step since the particle's launch. A particle parked by the demo (out of its current
 * preset, left out of the HUD) is left out here too; a particle not stepped since its launch
 * gets its one launch row. A demo's own tables ({@link DemoState#collectExportTables}, e.g.
 * the rotation boxes per step) follow, one {@code FOLDER/<table>.csv} each with its header,
 * then the energy ledger's {@code FOLDER/energy.csv} ({@link EnergyPart#getTable}; at the
 * live end only). Last, beside any file written, the settings that made the run:
 * {@code FOLDER/parameters.csv} ({@link ParametersTable}: name, value, unit), a name no
 * particle or table takes.
 * While the demo shows a recorded step (stepped back with Home, or scrubbed on the timeline),
 * each particle's states over the ring's whole recorded span follow its own file, as
 * {@code FOLDER/<particle>-recorded.csv}, same header and format.
 *
 * <p>File names are made file-safe ({@link #fileSafeName}): lower case, letters, digits, dots
 * and hyphens only, so {@code "linear drag  F = -0.9 V"} becomes
 * {@code linear-drag-f-0.9-v.csv}; two particles with the same name get {@code -2}, {@code -3}.
 */
public final class TrajectoryExport {

    /** The name of a particle whose label has nothing file-safe in it. */
    private static final String UNNAMED = "particle";

    private TrajectoryExport() {
    }

    /**
     * One file written.
     */
    public static final class Written {
        private final Path file;
        private final int rows;
        private final long dropped;
        private final int cap;

        Written(Path file, int rows, long dropped, int cap) {
            this.file = file;
            this.rows = rows;
            this.dropped = dropped;
            this.cap = cap;
        }

        /** @return the file written (not null) */
        public Path getFile() {
            return file;
        }

        /** @return the rows written, header not counted (&ge;0) */
        public int getRows() {
            return rows;
        }

        /** @return the steps past the record's capacity left out (&ge;0) */
        public long getDropped() {
            return dropped;
        }

        /**
         * Describe the file in one line for a listing: the path, its rows and, past the cap,
         * the steps left out.
         *
         * @return the line (not null)
         */
        public String describe() {
            return file + ": " + rows + (rows == 1 ? " row" : " rows")
                    + (dropped == 0L ? "" : " (the first " + cap + " states; " + dropped
                            + " later steps were not kept)");
        }
    }

    /**
     * Write every particle's trajectory into a folder, by the rules of {@link SafeFiles}:
     * each file created new, never through a symbolic link, an existing regular file
     * replaced only if allowed. Call on the jME thread, or after the application stopped.
     *
     * @param demo the demo (not null, initialised or not)
     * @param folder where to write (not null, an existing folder)
     * @param replace true if the user allowed existing regular files to be replaced
     * @return the files written, in the particles' order, parameters.csv last when anything
     *     else was written (not null)
     * @throws IOException if a file cannot be written or is refused (the message says why)
     */
    public static List<Written> write(DemoState demo, Path folder, boolean replace)
            throws IOException {
        List<Written> written = new ArrayList<>();
        Set<String> taken = new HashSet<>();
        // parameters.csv is the settings' name in every export (issue 33): no table takes it
        taken.add(ParametersTable.NAME);
        List<DemoParticle> particles = demo.getParticles();
        TrajectoryRecord launchOnly = new TrajectoryRecord();
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.isParked()) {
                continue;
            }
            String base = fileSafeName(particle.getLabel());
            String name = base;
            for (int copy = 2; !taken.add(name); ++copy) {
                name = base + "-" + copy;
            }
            TrajectoryRecord record = particle.getRecord();
            if (record.size() == 0) {
                // Not stepped since its launch: its state now is its launch state.
                launchOnly.clear();
                launchOnly.begin(particle.getParticle());
                record = launchOnly;
            }
            Path file = folder.resolve(name + ".csv");
            try (Writer out = SafeFiles.newWriter(file, replace)) {
                record.writeCsv(out);
            }
            written.add(new Written(file, record.size(), record.countDropped(),
                    TrajectoryRecord.MAX_ROWS));
        }
        if (demo.getRun().isReplaying()) {
            writeRecordedSpan(demo, folder, replace, taken, written);
        }
        List<StepTable> tables = new ArrayList<>();
        demo.collectExportTables(tables);
        // the energy ledger's columns per step (issue 32), once the demo has stepped; not
        // while a recorded step is shown: the ledger is the live end's, not the state shown;
        // not where there is no ledger (a world without bodies and no ledger of the demo's
        // own, or the fountain's own while off): a table of zeros would say its particles had
        // no energy
        StepTable energy = demo.getEnergyPart().getTable();
        if (energy != null && !demo.getRun().isReplaying()
                && demo.getEnergyPart().hasLedger()) {
            tables.add(energy);
        }
        for (int i = 0; i < tables.size(); ++i) {
            StepTable table = tables.get(i);
            String name = table.getName();
            for (int copy = 2; !taken.add(name); ++copy) {
                name = table.getName() + "-" + copy;
            }
            Path file = folder.resolve(name + ".csv");
            try (Writer out = SafeFiles.newWriter(file, replace)) {
                table.writeCsv(out);
            }
            written.add(new Written(file, table.size(), table.countDropped(),
                    table.capacity()));
        }
        if (!written.isEmpty()) {
            // the settings travel with the tables they made (issue 33)
            Path file = folder.resolve(ParametersTable.NAME + ".csv");
            int rows;
            try (Writer out = SafeFiles.newWriter(file, replace)) {
                rows = ParametersTable.writeCsv(demo.getParameters(), out);
            }
            written.add(new Written(file, rows, 0L, rows));
        }
        return written;
    }

    /**
     * While a recorded step is shown (stepped back, scrubbed): every particle's states over
     * the ring's whole span, oldest first, {@code FOLDER/<particle>-recorded.csv}, with the
     * same header and number format. A row per entry: t is the world's time of the entry
     * (a launch outside a step is an entry of its own, at the same t as the step before).
     */
    private static void writeRecordedSpan(DemoState demo, Path folder, boolean replace,
            Set<String> taken, List<Written> written) throws IOException {
        Replay replay = demo.getRun().getReplay();
        StateRing ring = replay.getRing();
        List<DemoParticle> particles = demo.getParticles();
        float[] row = new float[1 + 6 * particles.size()];
        String newline = System.lineSeparator();
        StringBuilder line = new StringBuilder(128);
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.isParked()) {
                continue;
            }
            String base = fileSafeName(particle.getLabel()) + "-recorded";
            String name = base;
            for (int copy = 2; !taken.add(name); ++copy) {
                name = base + "-" + copy;
            }
            Path file = folder.resolve(name + ".csv");
            try (Writer out = SafeFiles.newWriter(file, replace)) {
                out.write(TrajectoryRecord.HEADER);
                out.write(newline);
                for (long entry = ring.getFirstIndex(); entry <= ring.getLastIndex(); ++entry) {
                    replay.copyRow(entry, row);
                    line.setLength(0);
                    line.append(row[0]);
                    for (int k = 0; k < 6; ++k) {
                        line.append(',').append(row[1 + 6 * i + k]);
                    }
                    out.append(line.append(newline));
                }
            }
            written.add(new Written(file, ring.size(), 0L, ring.getCapacity()));
        }
    }

    /**
     * Turn a label into a file name (without extension) safe on every desktop system: lower
     * case; letters, digits, dots and hyphens kept; every other run of characters becomes one
     * hyphen; no hyphen or dot at either end.
     *
     * @param label the label (not null)
     * @return the name (not null, not empty)
     */
    public static String fileSafeName(String label) {
        StringBuilder name = new StringBuilder(label.length());
        boolean gap = false;
        for (int i = 0; i < label.length(); ++i) {
            char c = Character.toLowerCase(label.charAt(i));
            boolean keep = c >= 'a' && c <= 'z' || c >= '0' && c <= '9' || c == '.' || c == '-';
            if (keep) {
                if (gap && c != '-' && name.length() > 0
                        && name.charAt(name.length() - 1) != '-') {
                    name.append('-');
                }
                gap = false;
                name.append(c);
            } else {
                gap = true;
            }
        }
        int start = 0;
        int end = name.length();
        while (start < end && (name.charAt(start) == '-' || name.charAt(start) == '.')) {
            ++start;
        }
        while (end > start && (name.charAt(end - 1) == '-' || name.charAt(end - 1) == '.')) {
            --end;
        }
        String safe = name.substring(start, end);
        return safe.isEmpty() ? UNNAMED : safe;
    }
}

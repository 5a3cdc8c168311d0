package particlelab.app;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import particlelab.accuracy.BenchmarkTable;
import particlelab.accuracy.ReportConfig;
import particlelab.accuracy.SpeedVsErrorReport;
import particlelab.files.SafeFiles;

/**
 * {@code particle-lab report}: writes the speed-against-error report (see
 * {@link SpeedVsErrorReport}) to a folder. A progress bar goes to stderr, the summary to
 * stdout. The Gradle task {@code report} runs this command.
 */
public final class ReportCommand {

    /** The subcommand's name. */
    public static final String NAME = "report";
    /** The default output folder, relative to the working directory. */
    public static final String DEFAULT_OUT = "build/reports/speed-vs-error";

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String OUT = "--out";
    private static final String QUICK = "--quick";
    private static final String TINY = "--tiny";
    private static final String JMH = "--jmh";

    private ReportCommand() {
    }

    /**
     * Declare the command's options, for parsing and for the help text.
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Write the speed-against-error report: the shared Euler"
                + " integrator against forward Euler, Verlet, midpoint, RK4 and the exact step;"
                + " work-precision plots, measured orders, the stability map, benchmarks,"
                + " aiming misses and frame hitches, and the physics share of a frame for every"
                + " demo (run headless), as index.md, CSV files and PNG plots.")
                .value(OUT, "DIR", "the folder to write (created if missing). Default "
                        + DEFAULT_OUT + ". If one of the report's files is already in DIR,"
                        + " nothing runs unless " + SafeFiles.FORCE + " is given; a symbolic"
                        + " link or anything but a regular file at one of their names is"
                        + " always refused.")
                .flag(SafeFiles.FORCE, "replace the report's files already in DIR: they are"
                        + " removed when the command line is accepted, before the work starts;"
                        + " links are never written through, not even with it.")
                .flag(QUICK, "a smaller sweep: 171 s measured on 2 cores busy with other"
                        + " work (load average 16), less on idle ones.")
                .flag(TINY, "the smallest sweep (a few seconds): every file, rough numbers.")
                .value(JMH, "FILE", "take the benchmark rows from this benchmarks.csv, written"
                        + " by gradle jmh, instead of timing in-process.")
                .note("Without " + QUICK + " or " + TINY + " the full sweep runs: 946 s"
                        + " measured on 2 cores busy with other work (load average 17), a few"
                        + " minutes on idle ones;"
                        + " it times jME's ParticleEmitter up to 10^6 particles and starts one"
                        + " child JVM (-XX:+UseParallelGC) for the lecture style's row.")
                .note("Exit status: 0 when written; 2 on a bad command line or a folder that"
                        + " cannot be written (checked before the work starts), with one line"
                        + " on stderr; 1 if the demos cannot run headless.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "report" (not null)
     * @param out where the summary or help goes (not null)
     * @param err where the progress bar and the error line go (not null)
     * @return the exit status: {@link Program#OK}; {@link Program#FAILED} when the demos
     *     could not run in jME's headless context (no report section); {@link Program#USAGE}
     *     for a bad command line or files that could not be written (an unwritable
     *     {@code --out} is a bad command line, as the help has always promised)
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                options -> write(options, out, err));
    }

    /**
     * Write the report on an accepted command line.
     *
     * @throws UsageException for a bad command line or files that could not be written
     */
    private static int write(Options options, PrintStream out, PrintStream err) {
        options.atMostOneOf(QUICK, TINY);
        ReportConfig.Size size = options.has(QUICK) ? ReportConfig.Size.QUICK
                : options.has(TINY) ? ReportConfig.Size.TINY : ReportConfig.Size.FULL;
        Path folder = path(OUT, options.string(OUT, DEFAULT_OUT));
        String blocked = SafeFiles.folderRefusal(folder);
        if (blocked != null) {
            throw new UsageException(OUT + ": cannot write to "
                    + SafeFiles.printable(folder) + ": " + blocked);
        }
        Path jmh = options.has(JMH) ? benchmarks(options.string(JMH)) : null;
        boolean force = options.has(SafeFiles.FORCE);
        checkTargets(folder, force);
        // The whole command line was accepted: only now is the folder made.
        OutputFolders.create(OUT, folder);
        if (force) {
            try {
                for (String name : targets()) {
                    SafeFiles.removeToReplace(folder.resolve(name));
                }
            } catch (IOException failure) {
                throw unwritable(folder, failure);
            }
        }
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        // The headless demos start Lemur, which logs its version at INFO: quiet as in demo.
        DemoCommand.quietLogs();
        long start = System.nanoTime();
        PhysicsShare share;
        try {
            new SpeedVsErrorReport(ReportConfig.of(size), folder, jmh)
                    .write(err, System.console() != null);
        } catch (IOException failure) {
            throw unwritable(folder, failure);
        }
        try {
            // the demos live in this package, so their section is measured and added here
            share = PhysicsShare.run(size);
        } catch (IOException failure) {
            err.println(COMMAND + ": the demos could not run headless for the physics share: "
                    + UsageException.reason(failure));
            return Program.FAILED;
        }
        try {
            share.write(folder);
        } catch (IOException failure) {
            throw unwritable(folder, failure);
        }
        out.printf("Wrote the speed-vs-error report (%d files) to %s in %.0f s; open index.md%n",
                SpeedVsErrorReport.FILES.size() + PhysicsShare.FILES.size(),
                folder.toAbsolutePath(),
                (System.nanoTime() - start) / 1e9);
        return Program.OK;
    }

    /** Files that could not be written: a bad --out, reported as a bad command line. */
    private static UsageException unwritable(Path folder, IOException failure) {
        return new UsageException(OUT + ": could not write to " + SafeFiles.printable(folder)
                + ": " + UsageException.reason(failure));
    }

    private static Path path(String option, String text) {
        try {
            return Paths.get(text);
        } catch (InvalidPathException bad) {
            throw new UsageException(option + ": not a valid path, but was "
                    + Options.show(text));
        }
    }

    /** Every file the report writes, relative to its folder. */
    private static List<String> targets() {
        List<String> names = new ArrayList<>(SpeedVsErrorReport.FILES);
        names.addAll(PhysicsShare.FILES);
        return names;
    }

    /**
     * Refuse, before the work starts, a folder in which one of the report's files is in the
     * way: an existing regular file without {@code --force}, or a symbolic link, a folder or
     * a device at its name (always). Each file is then also created new when written.
     */
    private static void checkTargets(Path folder, boolean replace) {
        if (!Files.isDirectory(folder)) {
            return;
        }
        for (String name : targets()) {
            String why = SafeFiles.refusal(folder.resolve(name), replace,
                    "choose an empty folder");
            if (why != null) {
                throw new UsageException(OUT + ": " + why);
            }
        }
    }

    private static Path benchmarks(String text) {
        Path file = path(JMH, text);
        String shown = Options.show(text);
        if (Files.isDirectory(file)) {
            throw new UsageException(JMH + ": " + shown + " is a folder, not a file; give the"
                    + " benchmarks.csv that gradle jmh writes");
        }
        if (!Files.exists(file)) {
            throw new UsageException(JMH + ": the file " + shown + " does not exist");
        }
        if (!Files.isRegularFile(file)) {
            throw new UsageException(JMH + ": " + shown + " is not a regular file ("
                    + SafeFiles.kind(file) + ")");
        }
        BenchmarkTable table;
        try {
            table = BenchmarkTable.read(file);
        } catch (IllegalArgumentException | IOException bad) {
            throw new UsageException(JMH + ": " + shown + " is not a benchmarks.csv ("
                    + Options.show(String.valueOf(bad.getMessage())) + ")");
        }
        List<BenchmarkTable.Row> rows = table.rows();
        for (int i = 0; i < rows.size(); ++i) {
            BenchmarkTable.Row row = rows.get(i);
            double nanos = row.nanosPerParticleStep();
            double bytes = row.bytesPerStep();
            // bytes_per_step may be NaN: unknown. A time must be a measurement.
            if (!(Double.isFinite(nanos) && nanos > 0.0) || Double.isInfinite(bytes)
                    || bytes < 0.0) {
                throw new UsageException(JMH + ": " + shown + " row " + (i + 1) + " ("
                        + Options.show(row.name()) + ") must have a finite time > 0 and"
                        + " bytes >= 0 or NaN, but has ns_per_particle_step=" + nanos
                        + ", bytes_per_step=" + bytes);
            }
        }
        return file;
    }
}

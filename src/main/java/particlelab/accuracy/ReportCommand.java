package particlelab.accuracy;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;

/**
 * The command line of the speed-vs-error report, {@code particle-lab report [options]}:
 *
 * <pre>
 *   --out DIR     write there (default build/reports/speed-vs-error)
 *   --quick       a smaller sweep, well under a minute
 *   --tiny        the smallest sweep that fills every file (seconds; for tests)
 *   --jmh FILE    take benchmarks.csv from a JMH run (gradle jmh) instead of timing in-process
 *   --help        print this help
 * </pre>
 *
 * A progress bar goes to the error stream, the summary to the output stream. Exit codes: 0
 * done, 1 the files could not be written, 2 bad options (with a one-line message).
 */
public final class ReportCommand {

    /** The default output folder, relative to the working directory. */
    public static final String DEFAULT_OUT = "build/reports/speed-vs-error";
    /** Exit code: the report was written. */
    public static final int EXIT_OK = 0;
    /** Exit code: writing failed. */
    public static final int EXIT_FAILED = 1;
    /** Exit code: bad options. */
    public static final int EXIT_USAGE = 2;

    private static final String USAGE = "usage: report [--out DIR] [--quick | --tiny] "
            + "[--jmh FILE] [--help]";

    private ReportCommand() {
    }

    /**
     * Run the command and exit with its code.
     *
     * @param args the options (see the class comment)
     */
    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /**
     * Run the command.
     *
     * @param args the options (not null)
     * @param out where the summary and help go (not null)
     * @param err where the progress bar and error messages go (not null)
     * @return the exit code: {@link #EXIT_OK}, {@link #EXIT_FAILED} or {@link #EXIT_USAGE}
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        String outDir = DEFAULT_OUT;
        String jmhFile = null;
        ReportConfig.Size size = ReportConfig.Size.FULL;
        String sizeOption = null;
        for (int i = 0; i < args.length; ++i) {
            String arg = args[i];
            String value = null;
            int equals = arg.indexOf('=');
            if (arg.startsWith("--") && equals > 0) {
                value = arg.substring(equals + 1);
                arg = arg.substring(0, equals);
            }
            switch (arg) {
                case "--help":
                case "-h":
                    out.println(USAGE);
                    out.println("Writes index.md, CSV files and PNG plots comparing the shared "
                            + "Euler integrator with reference steppers.");
                    return EXIT_OK;
                case "--quick":
                case "--tiny":
                    if (sizeOption != null && !sizeOption.equals(arg)) {
                        return usage(err, "choose one of --quick and --tiny, not both");
                    }
                    sizeOption = arg;
                    size = arg.equals("--quick") ? ReportConfig.Size.QUICK
                            : ReportConfig.Size.TINY;
                    break;
                case "--out":
                case "--jmh":
                    if (value == null) {
                        if (i + 1 >= args.length || args[i + 1].startsWith("--")) {
                            return usage(err, arg + " needs a "
                                    + (arg.equals("--out") ? "folder" : "file") + " after it");
                        }
                        value = args[++i];
                    }
                    if (value.isEmpty()) {
                        return usage(err, arg + " needs a non-empty path, but was ''");
                    }
                    if (arg.equals("--out")) {
                        outDir = value;
                    } else {
                        jmhFile = value;
                    }
                    break;
                default:
                    return usage(err, "unknown option '" + args[i] + "'");
            }
        }
        Path folder;
        Path jmh = null;
        try {
            folder = Paths.get(outDir);
            if (jmhFile != null) {
                jmh = Paths.get(jmhFile);
            }
        } catch (InvalidPathException bad) {
            return usage(err, "not a valid path: '" + bad.getInput() + "'");
        }
        if (Files.exists(folder) && !Files.isDirectory(folder)) {
            return usage(err, "--out '" + outDir + "' is a file, not a folder");
        }
        if (jmh != null) {
            if (!Files.isRegularFile(jmh)) {
                return usage(err, "--jmh file '" + jmhFile + "' does not exist");
            }
            try {
                BenchmarkTable.read(jmh);
            } catch (IllegalArgumentException | IOException bad) {
                return usage(err, "--jmh file '" + jmhFile + "' is not a benchmarks.csv: "
                        + bad.getMessage());
            }
        }
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
        long start = System.nanoTime();
        SpeedVsErrorReport report = new SpeedVsErrorReport(ReportConfig.of(size), folder, jmh);
        try {
            report.write(err, System.console() != null);
        } catch (IOException failure) {
            err.println("report: could not write to '" + outDir + "': " + failure.getMessage());
            return EXIT_FAILED;
        }
        out.printf("Wrote the speed-vs-error report (%d files) to %s in %.0f s; open index.md%n",
                SpeedVsErrorReport.FILES.size(), folder.toAbsolutePath(),
                (System.nanoTime() - start) / 1e9);
        return EXIT_OK;
    }

    private static int usage(PrintStream err, String message) {
        err.println("report: " + message + " (" + USAGE + ")");
        return EXIT_USAGE;
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.accuracy.SpeedVsErrorReport;

/** {@code particle-lab report} through the launcher: options, errors, and a tiny run. */
class ReportCommandTest {

    /**
     * The tiny run writes every file; and Lemur, started by the headless demos, logs nothing
     * below a warning (it printed two INFO lines on stderr on JDK 17 and 25). The test JVM's
     * logging file quiets INFO everywhere, so Lemur's logger is set back to the JDK's default
     * INFO for the run, as in the installed app.
     */
    @Test
    void tinyRunWritesEveryPromisedFileAndSaysWhere(@TempDir Path temp) {
        Path out = temp.resolve("report");
        Logger lemur = Logger.getLogger("com.simsilica.lemur");
        Level level = lemur.getLevel();
        List<LogRecord> records = new ArrayList<>();
        Handler recorder = new Handler() {
            @Override
            public void publish(LogRecord logged) {
                records.add(logged);
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        lemur.setLevel(Level.INFO);
        lemur.addHandler(recorder);
        CommandRun run;
        try {
            run = CommandRun.of("report", "--tiny", "--out", out.toString());
        } finally {
            lemur.removeHandler(recorder);
            lemur.setLevel(level);
        }
        assertEquals(0, run.code, run.toString());
        for (LogRecord logged : records) {
            assertTrue(logged.getLevel().intValue() >= Level.WARNING.intValue(),
                    logged.getLevel() + " " + logged.getMessage());
        }
        assertTrue(run.out.startsWith("Wrote the speed-vs-error report"), run.out);
        for (String name : SpeedVsErrorReport.FILES) {
            assertTrue(Files.isRegularFile(out.resolve(name)), "missing " + name);
        }
        for (String name : PhysicsShare.FILES) {
            assertTrue(Files.isRegularFile(out.resolve(name)), "missing " + name);
        }
        assertTrue(run.out.contains("(" + (SpeedVsErrorReport.FILES.size()
                + PhysicsShare.FILES.size()) + " files)"), run.out);
    }

    @Test
    void badCommandLinesAreOneLineNamingTheOptionAndExitTwo(@TempDir Path temp)
            throws IOException {
        Path notBenchmarks = temp.resolve("not-benchmarks.csv");
        Files.write(notBenchmarks, "a,b\n".getBytes(StandardCharsets.UTF_8));
        Path aFile = temp.resolve("a-file");
        Files.write(aFile, new byte[] {1});
        String[][] cases = {
            {"--quik", "report", "--quik"},
            {"--out", "report", "--out"},
            {"--quick", "report", "--quick", "--tiny"},
            {"--jmh", "report", "--jmh", temp.resolve("nowhere.csv").toString()},
            {"--jmh", "report", "--jmh", notBenchmarks.toString()},
            {"--out", "report", "--out", aFile.toString()},
        };
        for (String[] c : cases) {
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            CommandRun run = CommandRun.of(args);
            assertEquals(2, run.code, run.toString());
            assertEquals(1, run.errLines().size(), run.toString());
            assertTrue(run.err.startsWith("particle-lab report: " + c[0]), run.toString());
            assertFalse(run.err.contains("Exception"), run.toString());
        }
    }

    @Test
    void helpDescribesEveryOption() {
        CommandRun run = CommandRun.of("report", "--help");
        assertEquals(0, run.code);
        for (String option : ReportCommand.options().names()) {
            assertTrue(run.out.contains("\n  " + option), option + " in\n" + run.out);
        }
    }
}

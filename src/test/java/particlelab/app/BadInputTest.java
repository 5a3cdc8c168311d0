package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.physics.Particle;

/**
 * The promise for bad input, through the real entry point {@link Main#run}: exactly one line
 * on stderr, exit 2 (or 1 when the output cannot be written), no stack trace, and never a
 * silent wrong answer. Each case here once broke it.
 */
class BadInputTest {

    /**
     * A computed vy beyond the float range once escaped as an IllegalArgumentException's stack
     * trace (exit 1), after every option had passed its own check.
     */
    @Test
    void aVyBeyondTheFloatRangeIsOneLine() {
        assertOneLine("--vx", "aim", "--distance", "100", "--vx", "1e-45");
        assertOneLine("--vx", "aim", "--distance", "100", "--vx", "20", "--g", "3e38");
        assertOneLine("beyond the float range", "aim", "--distance", "100", "--vx", "20",
                "--g", "1e38", "--method", "iterative");
    }

    /**
     * Steps too small to move a float position: aim once ran for minutes and then reported a
     * false "out of reach", or landed at 64 m for S = 100 m; trajectory printed an x that
     * never moved.
     */
    @Test
    void aStepTooSmallToMoveTheParticleIsRefusedNamingTheLimit() {
        for (String step : new String[] {"1e-7", "1e-9", "1e-45"}) {
            CommandRun run = assertOneLine("--tpf", "aim", "--distance", "100", "--vx", "20",
                    "--tpf", step);
            assertTrue(run.err.contains("more than the limit " + AimCommand.MAX_STEPS_PER_SHOT),
                    run.toString());
        }
        CommandRun run = assertOneLine("--tpf", "trajectory", "--tpf", "1e-7", "--p0",
                "1000,0,0", "--steps", "3");
        assertTrue(run.err.contains("x could never change"), run.toString());
        // The smallest step the message suggests does move x.
        assertEquals(0, CommandRun.of("aim", "--distance", "100", "--vx", "20", "--tpf",
                "5.0000005e-6", "--csv").code);
        CommandRun moving = CommandRun.of("trajectory", "--tpf", "6.2e-6", "--p0", "1000,0,0",
                "--steps", "1", "--g", "0,0,0");
        assertEquals(0, moving.code, moving.toString());
        assertFalse(moving.outLines().get(2).startsWith("6.2E-6,1000.0,"), moving.toString());
    }

    /** Masses whose 1/m overflows were accepted, then every step failed blaming --tpf. */
    @Test
    void aMassWhoseInverseIsNotAFloatIsRefusedAtTheBoundary() {
        CommandRun run = assertOneLine("--mass", "trajectory", "--mass", "1e-39", "--steps",
                "1");
        assertTrue(run.err.contains(String.valueOf(Particle.MIN_MASS_KG)), run.toString());
        assertOneLine("--mass", "aim", "--distance", "100", "--vx", "20", "--mass", "3e-39");
        assertEquals(0, CommandRun.of("trajectory", "--mass", "1.2e-38", "--steps", "1").code);
    }

    /** A run that blew up printed the stability warning and then the error: two lines. */
    @Test
    void aRunThatBlowsUpIsOneLine() {
        CommandRun run = assertOneLine("--tpf", "trajectory", "--steps", "100",
                "--linear-drag", "10", "--tpf", "5");
        assertTrue(run.err.contains("non-finite"), run.toString());
    }

    /** Control characters in an echoed word could move the cursor or clear the terminal. */
    @Test
    void controlCharactersInEchoedWordsAreEscaped(@TempDir Path temp) {
        String escape = "\u001b[2J";
        assertEscaped(CommandRun.of(escape + "x"));
        assertEscaped(CommandRun.of("demo", "red" + escape));
        assertEscaped(CommandRun.of("report", "--jmh", temp.resolve("a" + escape).toString()));
        assertEscaped(CommandRun.of("trajectory", "--steps", "1", "--bogus" + escape));
    }

    /**
     * The decimal pattern once backtracked quadratically: 131 000 digits took 165 s. Numbers
     * are now scanned once and capped at {@link Options#MAX_NUMBER_LENGTH} characters, and the
     * message shows only the start of the value.
     */
    @Test
    void aHugeNumberIsRefusedByItsLengthInAShortMessage() {
        String digits = "1".repeat(131_000) + "x";
        CommandRun run = assertOneLine("--mass", "trajectory", "--steps", "1", "--mass",
                digits);
        assertTrue(run.err.contains("at most " + Options.MAX_NUMBER_LENGTH + " characters"),
                run.err);
        assertTrue(run.err.length() < 300, run.err);
        assertTrue(run.err.contains("(131001 characters)"), run.err);
        String longest = "0." + "1".repeat(Options.MAX_NUMBER_LENGTH - 2);
        assertEquals(0, CommandRun.of("trajectory", "--steps", "1", "--mass", longest).code);
    }

    /** Output lost to a full disk or a closed pipe once exited 0. */
    @Test
    void outputThatCannotBeWrittenExitsOneWithOneLine() {
        ByteArrayOutputStream errBytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(errBytes, true, StandardCharsets.UTF_8);
        FailingStream full = new FailingStream(0);
        int code = Main.run(new String[] {"aim", "--distance", "100", "--vx", "20"},
                new PrintStream(full, false, StandardCharsets.UTF_8), err);
        String message = errBytes.toString(StandardCharsets.UTF_8);
        assertEquals(Program.FAILED, code, message);
        assertEquals(1, message.split("\\R").length, message);
        assertTrue(message.startsWith("particle-lab: could not write the output"), message);
    }

    /**
     * {@code trajectory --steps 1000000 | head -1} kept formatting every row after the reader
     * had gone. Now it stops at the next check, a few thousand rows in: far from the 58 MB
     * the whole run prints.
     */
    @Test
    void aTrajectoryStopsSoonAfterItsReaderHasGone() {
        FailingStream closed = new FailingStream(100);
        ByteArrayOutputStream errBytes = new ByteArrayOutputStream();
        int code = Main.run(new String[] {"trajectory", "--steps", "1000000"},
                new PrintStream(closed, false, StandardCharsets.UTF_8),
                new PrintStream(errBytes, true, StandardCharsets.UTF_8));
        assertEquals(Program.FAILED, code);
        // At most one check interval of rows (1024 rows of at most 100 bytes) after the
        // failure, plus the buffer of the PrintStream.
        assertTrue(closed.attempted < 200_000, "attempted " + closed.attempted + " bytes");
        assertEquals(1, errBytes.toString(StandardCharsets.UTF_8).split("\\R").length);
    }

    /** An unwritable --out exited 1 with a message that lacked the reason. */
    @Test
    void anUnwritableReportFolderIsExitTwoWithTheReason(@TempDir Path temp) throws IOException {
        Path file = Files.write(temp.resolve("a-file"), new byte[] {1});
        CommandRun run = assertOneLine("--out", "report", "--tiny", "--out",
                file.resolve("sub").toString());
        assertTrue(run.err.contains("cannot write to"), run.toString());
        assertTrue(run.err.toLowerCase().contains("not a"), run.toString());
    }

    /** --jmh accepted rows whose time was NaN, and the report printed "NaN×". */
    @Test
    void benchmarkRowsWithoutAMeasurementAreRefusedByRow(@TempDir Path temp)
            throws IOException {
        Path csv = temp.resolve("benchmarks.csv");
        Files.write(csv, ("benchmark,ns_per_particle_step,bytes_per_step\n"
                + "rk4,12.5,0\n\nprimitive-loop,NaN,0\n").getBytes(StandardCharsets.UTF_8));
        CommandRun run = assertOneLine("--jmh", "report", "--jmh", csv.toString());
        assertTrue(run.err.contains("row 2 (primitive-loop)"), run.toString());
    }

    /**
     * The screenshot path is checked before the window opens, so these fail at once, with no
     * display needed; a folder is never replaced.
     */
    @Test
    void aScreenshotThatCannotBeWrittenIsRefusedBeforeTheWindow(@TempDir Path temp)
            throws IOException {
        Path folder = Files.createDirectory(temp.resolve("folder"));
        Path file = Files.write(temp.resolve("a-file"), new byte[] {1});
        CommandRun run = assertOneLine("--screenshot", "demo", "drag", "--frames", "1",
                "--screenshot", folder.toString());
        assertTrue(run.err.contains("is a folder"), run.toString());
        assertTrue(Files.isDirectory(folder));
        run = assertOneLine("--screenshot", "demo", "drag", "--frames", "1", "--screenshot",
                file.resolve("x.png").toString());
        assertTrue(run.err.contains("is a file, not a folder"), run.toString());
        assertOneLine("--screenshot", "demo", "drag", "--frames", "1", "--screenshot",
                "/proc/particle-lab/x.png");
    }

    private static CommandRun assertOneLine(String named, String... args) {
        CommandRun run = CommandRun.of(args);
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals("", run.out, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains(named), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertFalse(run.err.contains("at particlelab"), run.toString());
        return run;
    }

    private static void assertEscaped(CommandRun run) {
        assertEquals(Program.USAGE, run.code, run.toString());
        String line = run.err.substring(0, run.err.length() - System.lineSeparator().length());
        for (int i = 0; i < line.length(); ++i) {
            assertFalse(Character.isISOControl(line.charAt(i)), run.toString());
        }
        assertTrue(line.contains("\\u001b[2J"), line);
    }

    /** An output stream that fails every write after its first bytes, counting the attempts. */
    private static final class FailingStream extends OutputStream {
        private final int capacity;
        private int written;
        long attempted;

        FailingStream(int capacity) {
            this.capacity = capacity;
        }

        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] bytes, int offset, int length) throws IOException {
            attempted += length;
            if (written + length > capacity) {
                throw new IOException("No space left on device");
            }
            written += length;
        }
    }
}

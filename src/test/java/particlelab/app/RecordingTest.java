package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 33, part 3: what {@code demo --record FILE} and {@code --replay FILE} refuse, each in
 * one line and before any run (no jME application starts): a damaged or hand-edited line by
 * its number, another version, another demo, an existing file without {@code --force}, a
 * symbolic link even with it. The round trip and the divergence are in {@link StateShareTest},
 * which runs the headless app.
 */
class RecordingTest {

    /** A recording as the recorder writes it, cut short: header, frames, hashes, end. */
    private static final String GOOD = Recording.VERSION_LINE + "\n"
            + "demo pull\n"
            + "setting g=2.0\n"
            + "step 0.016666668\n"
            + "frames 60 tpf 0.016666668\n"
            + "hash 60 08ffe4c6ab9095b5\n"
            + "key Space\n"
            + "frames 3 tpf 0.016666668\n"
            + "end the run ended\n";

    /** The longest a child JVM may take before the test gives up on it (in seconds). */
    private static final long CHILD_SECONDS = 300L;

    @TempDir
    Path folder;

    @Test
    void aDamagedLineIsRefusedWithItsNumber() throws IOException {
        Run run = replay(GOOD.replace("frames 3 tpf", "frames 3 tfp"));
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals("particle-lab demo: --replay " + file() + " line 8: 'frames 3 tfp"
                + " 0.016666668' is refused: frames N tpf T", run.err.strip());
        assertEquals("", run.out);
        Run number = replay(GOOD.replace("hash 60 08ffe4c6ab9095b5", "hash 60 08ffe4c6ab9095bz"));
        assertTrue(number.err.contains(" line 6: 'hash 60 08ffe4c6ab9095bz' is refused: hash"
                + " STEP HEX (16 hex digits)"), number.toString());
        Run infinite = replay(GOOD.replace("frames 3 tpf 0.016666668", "frames 3 tpf Infinity"));
        assertEquals(Program.USAGE, infinite.code, infinite.toString());
        assertTrue(infinite.err.contains(" line 8: "), infinite.toString());
        assertTrue(infinite.err.contains("Infinity is not a finite number"), infinite.toString());
    }

    /** A line that reads but names what the demo does not have is refused by its number. */
    @Test
    void anEditedLineNamingNoKeyOrParameterIsRefused() throws IOException {
        Run key = replay(GOOD.replace("key Space", "key Spacebar"));
        assertEquals(Program.USAGE, key.code, key.toString());
        assertTrue(key.err.strip().endsWith(" line 7: 'key Spacebar' is refused: the demo has"
                + " no key Spacebar"), key.toString());
        Run set = replay(GOOD.replace("key Space", "set gee 1.0"));
        assertTrue(set.err.contains(" line 7: 'set gee 1.0' is refused: the demo has no"
                + " parameter gee"), set.toString());
    }

    @Test
    void anotherVersionOrDemoIsSaidSo() throws IOException {
        Run version = replay(GOOD.replace("recording 1", "recording 2"));
        assertEquals(Program.USAGE, version.code, version.toString());
        assertEquals("particle-lab demo: --replay " + file() + " is a recording of version 2;"
                + " this particle-lab reads version 1 only", version.err.strip());
        Run notOne = replay("time,x,y\n");
        assertTrue(notOne.err.contains(" is not a recording: its first line should be"
                + " 'particle-lab recording 1'"), notOne.toString());
        Path recording = folder.resolve("run.txt");
        Files.writeString(recording, GOOD, StandardCharsets.UTF_8);
        Run demo = run("drag", Replayer.REPLAY, recording.toString());
        assertEquals(Program.USAGE, demo.code, demo.toString());
        assertEquals("particle-lab demo: --replay " + recording + " is a recording of demo"
                + " pull, not drag; replay it with: particle-lab demo pull --replay "
                + recording, demo.err.strip());
    }

    /** The file rules of {@code files/}: the command line is refused and nothing changes. */
    @Test
    void anExistingFileOrALinkIsNotWritten() throws IOException {
        Path existing = folder.resolve("run.txt");
        Files.writeString(existing, "a student's notes\n", StandardCharsets.UTF_8);
        Run kept = run("pull", "--frames", "10", "--record", existing.toString());
        assertEquals(Program.USAGE, kept.code, kept.toString());
        assertEquals("particle-lab demo: --record: " + existing + " exists; use --force to"
                + " replace it, or choose another name", kept.err.strip());
        assertEquals("a student's notes\n", Files.readString(existing));
        Path target = folder.resolve("elsewhere.txt");
        Path link = Files.createSymbolicLink(folder.resolve("link.txt"), target);
        Run linked = run("pull", "--frames", "10", "--record", link.toString(), "--force");
        assertEquals(Program.USAGE, linked.code, linked.toString());
        assertTrue(linked.err.contains(link + " is a symbolic link; files are never written"
                + " through a link, not even with --force"), linked.toString());
        assertFalse(Files.exists(target), "the link was followed");
        Run both = run("pull", "--frames", "10", Replayer.REPLAY, existing.toString());
        assertEquals(Program.USAGE, both.code, both.toString());
        assertTrue(both.err.contains("--frames cannot be given with it"), both.toString());
    }

    /**
     * A run that never starts (no display, in a new JVM without DISPLAY) leaves no empty
     * recording behind: the file created for it is removed, and the exit status says why.
     */
    @Test
    void aRunThatCannotOpenItsWindowLeavesNoRecording() throws Exception {
        Path recording = folder.resolve("never.txt");
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(Main.class.getName());
        command.addAll(List.of("demo", "pull", "--record", recording.toString()));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().remove("DISPLAY");
        builder.environment().remove("WAYLAND_DISPLAY");
        Process process = builder.start();
        String output = new String(process.getInputStream().readAllBytes(),
                StandardCharsets.UTF_8);
        // a guard against a hung child, not a timing: it stops at the display check
        assertTrue(process.waitFor(CHILD_SECONDS, TimeUnit.SECONDS), output);
        assertEquals(Program.FAILED, process.exitValue(), output);
        assertTrue(output.contains("cannot open the window: no display"), output);
        assertFalse(Files.exists(recording, LinkOption.NOFOLLOW_LINKS), output);
    }

    private Path file() {
        return folder.resolve("recording.txt");
    }

    /** Write a recording to {@link #file()} and replay it as the pull demo. */
    private Run replay(String text) throws IOException {
        Files.writeString(file(), text, StandardCharsets.UTF_8);
        return run("pull", Replayer.REPLAY, file().toString());
    }

    private static Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = DemoCommand.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        return new Run(code, out.toString(StandardCharsets.UTF_8),
                err.toString(StandardCharsets.UTF_8));
    }

    /** A command's exit status and output. */
    private static final class Run {
        final int code;
        final String out;
        final String err;

        Run(int code, String out, String err) {
            this.code = code;
            this.out = out;
            this.err = err;
        }

        @Override
        public String toString() {
            return "exit " + code + ", out: " + out + ", err: " + err;
        }
    }
}

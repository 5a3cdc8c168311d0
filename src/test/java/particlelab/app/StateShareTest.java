package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.StateHash;
import particlelab.physics.SimulationClock;

/**
 * Issue 33, part 2: a state as a command line. {@code --print-command} and the C key print
 * {@code particle-lab demo NAME --frames K --fixed-tpf H --set ...}, and that command, run in
 * a new JVM, ends in the same state, bit for bit (the same hash of the whole simulation's
 * ring entry); a state no command line can reach says so.
 */
class StateShareTest {

    /** The demos' default step h = 1/60 s as a float, as --fixed-tpf prints it. */
    private static final String FRAME = "0.016666668";
    /** A guard against a hung child JVM, not a timing: on a loaded machine it took 75 s. */
    private static final long CHILD_SECONDS = 600L;

    /**
     * A launch as an arrow drag leaves it (speed and angle) on a weak g, so the ball flies
     * the whole 600 steps: the printed command, run in a new JVM (the installed app's
     * entry point on this classpath), prints the same command and the same state line, its
     * hash included.
     */
    @Test
    void thePrintedCommandGivesTheSameStateInAFreshJvm() throws Exception {
        CommandRun first = CommandRun.of("demo", "pull", "--set", "speed=12.5", "--set",
                "angle=60", "--set", "g=2", "--frames", "600", "--fixed-tpf", FRAME,
                "--print-command");
        assertEquals(0, first.code, first.toString());
        List<String> lines = first.outLines();
        assertEquals(2, lines.size(), first.toString());
        // only what differs from the defaults, in the panel's order; 600 frames of one step
        assertEquals("particle-lab demo pull --frames 600 --fixed-tpf " + FRAME
                + " --set speed=12.5 --set angle=60.0 --set g=2.0", lines.get(0));
        assertTrue(lines.get(1).startsWith("state: step 600, t = 10.0000 s, hash "),
                lines.get(1));
        assertTrue(lines.get(1).endsWith("the command re-run gives the same bits"),
                lines.get(1));
        List<String> args = new ArrayList<>(Arrays.asList(lines.get(0).split(" ")));
        assertEquals(Program.NAME, args.remove(0));
        args.add(StateShare.PRINT_COMMAND);
        Child child = runInNewJvm(args);
        assertEquals(0, child.code, child.err);
        // the same command and the same hash: the new JVM's state is this one's, to the bit
        assertEquals(lines, Arrays.asList(child.out.split("\\R")), child.err);
    }

    /**
     * The window's C key shares the state shown: stepped back ten steps from the live end,
     * the command gives the step shown, and re-run it gives the shown state's bits. Fixed
     * steps of h make a state a count of steps whatever the frame times were. The key's
     * code and the demo run without jME (plain JUnit): the key reads the switcher's demo.
     */
    @Test
    void theKeyCSharesTheRecordedStepShown() throws Exception {
        DemoState bounce = DemoCatalog.entries().get(DemoCatalog.indexOf("bounce")).create();
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        // the check runs at once, on this thread: no application to hand the verdict to
        ShareKey key = new ShareKey(new DemoSwitcher(List.of(bounce), 0),
                new PrintStream(printed, true, StandardCharsets.UTF_8), Runnable::run);
        bounce.restart();
        bounce.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        bounce.getClock().setPaused(false);
        for (int frame = 0; frame < 300; ++frame) {
            bounce.advancePhysics(1f / 60f);
        }
        bounce.getClock().setPaused(true);
        for (int i = 0; i < 10; ++i) {
            bounce.getReplayControls().stepBack();
        }
        StateShare share = key.share().get(CHILD_SECONDS, TimeUnit.SECONDS);
        assertEquals("particle-lab demo bounce --frames 290 --fixed-tpf " + FRAME,
                share.command);
        assertTrue(share.reproduces(), share.stateLine());
        assertEquals(share.command + "\n" + share.stateLine() + "\n",
                printed.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n"));
        String notice = bounce.getNotice();
        assertTrue(notice.startsWith("C: command printed to the terminal (step 290, hash "
                + StateHash.hex(share.hash).substring(0, 8)), notice);
        assertTrue(notice.endsWith("re-run: same bits)"), notice);
    }

    /**
     * The C key prints the command at once and checks it aside: until the re-run ends the
     * window goes on (the key returned), the HUD says the check is running and only the
     * command is printed; the verdict comes to the terminal and the HUD when the check ends.
     * The checks are held back here, so "not yet" is no matter of timing.
     */
    @Test
    void theKeyCChecksAsideAndTheWindowGoesOn() throws Exception {
        DemoState uniform = DemoCatalog.entries().get(DemoCatalog.indexOf("uniform"))
                .create();
        List<Runnable> held = new ArrayList<>();
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        ShareKey key = new ShareKey(new DemoSwitcher(List.of(uniform), 0),
                new PrintStream(printed, true, StandardCharsets.UTF_8), held::add);
        uniform.restart();
        uniform.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        uniform.getClock().setPaused(false);
        for (int frame = 0; frame < 40; ++frame) {
            uniform.advancePhysics(1f / 60f);
        }
        uniform.getClock().setPaused(true);
        CompletableFuture<StateShare> pending = key.share();
        // the key returned with the check still held: the window's frame goes on
        assertFalse(pending.isDone());
        assertEquals(1, held.size());
        assertTrue(uniform.getNotice().endsWith("re-running it to check...)"),
                uniform.getNotice());
        assertEquals("particle-lab demo uniform --frames 40 --fixed-tpf " + FRAME + "\n",
                printed.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n"));
        held.get(0).run();
        StateShare share = pending.get(CHILD_SECONDS, TimeUnit.SECONDS);
        assertTrue(share.reproduces(), share.stateLine());
        assertEquals(share.command + "\n" + share.stateLine() + "\n",
                printed.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n"));
        assertTrue(uniform.getNotice().endsWith("re-run: same bits)"), uniform.getNotice());
    }

    /**
     * A state changed by hand mid-flight (as a drag of a body's velocity does) is no count
     * of steps of any command line: the share says so and gives the two hashes.
     */
    @Test
    void aStateNoCommandReachesIsSaidToBeOne() {
        DemoState uniform = DemoCatalog.entries().get(DemoCatalog.indexOf("uniform"))
                .create();
        for (int i = 0; i < 30; ++i) {
            uniform.advancePhysics(1f / 60f);
        }
        StateShare untouched = StateShare.of(uniform);
        assertTrue(untouched.reproduces(), untouched.stateLine());
        uniform.getParticles().get(0).getParticle().velocity.x += 1f;
        uniform.advancePhysics(1f / 60f);
        StateShare changed = StateShare.of(uniform);
        assertEquals("particle-lab demo uniform --frames 31 --fixed-tpf " + FRAME,
                changed.command);
        assertFalse(changed.reproduces());
        assertNotEquals(changed.hash, changed.commandHash);
        assertTrue(changed.stateLine().contains("the command gives hash "
                + StateHash.hex(changed.commandHash) + ": this state came from inputs a"
                + " command line does not carry"), changed.stateLine());
    }

    /** A command's run in a new JVM: exit code, stdout, stderr. */
    private static final class Child {
        final int code;
        final String out;
        final String err;

        Child(int code, String out, String err) {
            this.code = code;
            this.out = out;
            this.err = err;
        }
    }

    /** Run {@code particle-lab ARGS} in a new JVM with this one's classpath and modules. */
    private static Child runInNewJvm(List<String> args) throws IOException,
            InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            // the Vector API module the build adds; nothing of the test runner's agents
            if (option.startsWith("--add-modules")) {
                command.add(option);
            }
        }
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(Main.class.getName());
        command.addAll(args);
        Process process = new ProcessBuilder(command).start();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Thread errReader = new Thread(() -> copy(process.getErrorStream(), err));
        errReader.start();
        String out = new String(process.getInputStream().readAllBytes(),
                StandardCharsets.UTF_8);
        assertTrue(process.waitFor(CHILD_SECONDS, TimeUnit.SECONDS), "the child ran too long");
        errReader.join();
        return new Child(process.exitValue(), out, err.toString(StandardCharsets.UTF_8));
    }

    private static void copy(InputStream in, ByteArrayOutputStream out) {
        try {
            in.transferTo(out);
        } catch (IOException ignored) {
            // the child's stderr is only shown when it fails
        }
    }
}

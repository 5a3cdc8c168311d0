package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --present} on {@code demo} and {@code tour}: listed by their help, and refused with
 * one line and exit status 2 where it means nothing (an export run without a window).
 */
class DemoPresentOptionTest {

    @Test
    void demoAndTourHelpListPresent() {
        for (String command : new String[] {"demo", "tour"}) {
            CommandRun run = CommandRun.of(command, "--help");
            assertEquals(Program.OK, run.code, run.toString());
            assertTrue(run.out.contains("--present"), command + ": " + run.out);
            assertTrue(run.out.contains("F8"), command + ": " + run.out);
        }
    }

    @Test
    void presentWithAWindowlessExportIsOneLineAndExitTwo(@TempDir Path folder) {
        Path out = folder.resolve("out");
        CommandRun run = CommandRun.of("demo", "drag", "--present", "--frames", "10",
                "--export", out.toString());
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.startsWith("particle-lab demo: --present: shows the window in"
                + " presentation mode, but --export without --screenshot runs with no window"),
                run.toString());
        // Refused before anything was made.
        assertTrue(!Files.exists(out), out + " was made");
    }
}

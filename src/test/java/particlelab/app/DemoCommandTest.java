package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class DemoCommandTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @Test
    void listPrintsTheDemoNamesOnePerLine() {
        assertEquals(Program.OK, run("--list"));
        assertEquals(String.join(System.lineSeparator(), DemoCatalog.names())
                + System.lineSeparator(), text(out));
    }

    @Test
    void badArgumentsAreUsageErrorsThatSayWhy() {
        assertEquals(Program.USAGE, run("--frames", "zero"));
        assertTrue(text(err).startsWith("particle-lab demo: --frames: must be a whole number"),
                text(err));
        err.reset();
        assertEquals(Program.USAGE, run("--fixed-tpf", "-1"));
        assertTrue(text(err).contains("--fixed-tpf"), text(err));
        err.reset();
        assertEquals(Program.USAGE, run("--fixed-tpf", "2"));
        assertTrue(text(err).contains("--fixed-tpf: must be at most 1.0 s, but was 2.0"),
                text(err));
        err.reset();
        assertEquals(Program.USAGE, run("gyroscope"));
        assertTrue(text(err).contains("no demo named 'gyroscope'; the demos are uniform,"));
        err.reset();
        assertEquals(Program.USAGE, run("aiming", "--screenshot", "x.png"));
        assertTrue(text(err).contains("--screenshot: needs --frames N"), text(err));
        err.reset();
        assertEquals(Program.USAGE, run("aiming", "--frames"));
        assertTrue(text(err).contains("--frames: needs a value"), text(err));
        err.reset();
        assertEquals(Program.USAGE, run("aiming", "--demo", "drag"));
        assertTrue(text(err).contains("already named aiming"), text(err));
    }

    private int run(String... args) {
        return DemoCommand.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private static String text(ByteArrayOutputStream stream) {
        return stream.toString(StandardCharsets.UTF_8);
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@link DemoState} stays a thin AppState over the demo's run (issue 30): the jME lifecycle,
 * the hooks a demo writes and one-line forwarders. A new job goes into a part or a class beside
 * it ({@link DemoRun}, {@link DemoWindow}, {@link DemoHud}, ...), not into the base class every
 * student's autocompletion lists. Read from the source file.
 */
class DemoStateSourceTest {

    private static final Path SOURCE = Paths.get("src/main/java/particlelab/demo/DemoState.java");
    /** Issue 30's bound on the base class, Javadoc included (lines). */
    private static final int MAX_LINES = 800;

    @Test
    void theBaseClassStaysWithinItsLineBound() throws IOException {
        List<String> lines = Files.readAllLines(SOURCE);
        assertTrue(lines.size() <= MAX_LINES, SOURCE + " has " + lines.size()
                + " lines, more than " + MAX_LINES + ": move the new job into a part"
                + " (DemoPart) or a class beside it, and keep a one-line forwarder at most");
    }
}

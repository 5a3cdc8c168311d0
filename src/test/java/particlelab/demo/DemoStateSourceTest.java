package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@link DemoState} stays a thin AppState over the demo's run (issue 30): the jME lifecycle,
 * the hooks a demo writes and one-line forwarders. A new job goes into a part or a class beside
 * it ({@link DemoRun}, {@link DemoWindow}, {@link DemoHud}, ...), not into the base class every
 * student's autocompletion lists. The lines are read from the source file, the methods from
 * the class.
 */
class DemoStateSourceTest {

    private static final Path SOURCE = Paths.get("src/main/java/particlelab/demo/DemoState.java");
    /** Issue 30's bound on the base class, Javadoc included (lines). */
    private static final int MAX_LINES = 800;
    /**
     * Issue 30's bound on the members a student's autocompletion lists of the base class
     * itself: its own public or protected methods (constructors not counted), about 45. The
     * jME lifecycle (5), the hooks a demo writes (14), the tools it calls, the scene's parts
     * and the five owners the rest went to.
     */
    private static final int MAX_OWN_METHODS = 46;

    @Test
    void theBaseClassStaysWithinItsLineBound() throws IOException {
        List<String> lines = Files.readAllLines(SOURCE);
        assertTrue(lines.size() <= MAX_LINES, SOURCE + " has " + lines.size()
                + " lines, more than " + MAX_LINES + ": move the new job into a part"
                + " (DemoPart) or a class beside it, and keep a one-line forwarder at most");
    }

    @Test
    void theBaseClassOffersAStudentAtMostItsBoundOfOwnMethods() {
        List<String> own = new ArrayList<>();
        for (Method method : DemoState.class.getDeclaredMethods()) {
            int modifiers = method.getModifiers();
            if (!method.isSynthetic() && !method.isBridge()
                    && (Modifier.isPublic(modifiers) || Modifier.isProtected(modifiers))) {
                own.add(method.getName());
            }
        }
        assertTrue(own.size() <= MAX_OWN_METHODS, "DemoState declares " + own.size()
                + " public or protected methods, more than " + MAX_OWN_METHODS + ": " + own
                + ". What only the application, the tour, the tests or the parts call belongs"
                + " to its owner (getRun(), getWindow(), getDemoHud(), getKeys(),"
                + " getReplayControls()), not to the class every demo's autocompletion lists");
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.scene.control.AbstractControl;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.demo.DemoState;

/**
 * Issue 36: an exception on the render thread closed the window with a line that named
 * neither the exception nor where it came from. Here a view of the scene (a control on the
 * root node, updated in jME's loop as every view is) throws once: the window stays up, the
 * demo restarts with the notice "recovered from ... at t = ...; see LOG", and the log holds
 * the whole stack. A second failure closes it, with one line naming the exception, its
 * message, the project's frame it came from and a new log file.
 */
class RecoveryHeadlessTest {

    private static final long TIMEOUT_SECONDS = 30;
    private static final String MESSAGE = "a view failed on purpose";
    private static final Pattern LOG = Pattern.compile("see (\\S+\\.log)$");

    @Test
    void aFailingViewRestartsTheDemoOnceAndASecondFailureClosesTheWindow(@TempDir Path logs)
            throws Exception {
        String previous = System.getProperty(CrashLog.FOLDER_PROPERTY);
        System.setProperty(CrashLog.FOLDER_PROPERTY, logs.toString());
        HeadlessHarness harness = HeadlessHarness.start(DemoCatalog.createAll().subList(0, 1));
        try {
            ParticleLabApp app = harness.app();
            DemoState demo = app.getSwitcher().getSelected();
            harness.call(() -> {
                HeadlessHarness.fly(demo, 30, 1f / 60f);
                app.getRootNode().addControl(new FailingView());
                return true;
            });
            harness.awaitFrames(3);
            String recovered = app.getRecovered();
            assertTrue(recovered != null && recovered.startsWith("recovered from "
                    + "IllegalStateException: " + MESSAGE + " at particlelab.app."
                    + "RecoveryHeadlessTest$FailingView.controlUpdate("), recovered);
            // The demo restarted: its clock is back at 0 (the harness's frames have tpf 0).
            assertEquals(0.0, harness.call(() -> demo.getClock().getSimulatedSeconds()));
            assertEquals(recovered, harness.call(demo.getDemoHud()::getNotice));
            assertNull(app.getFailure());
            Matcher log = LOG.matcher(recovered);
            assertTrue(log.find(), recovered);
            String stack = Files.readString(Path.of(log.group(1)));
            assertTrue(stack.contains("RecoveryHeadlessTest$FailingView.controlUpdate"), stack);

            harness.call(() -> {
                app.getRootNode().addControl(new FailingView());
                return true;
            });
            assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "a second failure is fatal");
            String failure = app.getFailure();
            assertTrue(failure.contains(": IllegalStateException: " + MESSAGE
                    + " at particlelab.app.RecoveryHeadlessTest$FailingView"), failure);
            assertTrue(failure.contains("; the full stack is in " + logs), failure);
            // One log per failure, none overwritten.
            try (var files = Files.list(logs)) {
                assertEquals(2L, files.count());
            }
        } finally {
            harness.close();
            if (previous == null) {
                System.clearProperty(CrashLog.FOLDER_PROPERTY);
            } else {
                System.setProperty(CrashLog.FOLDER_PROPERTY, previous);
            }
        }
    }

    /** A view that throws in its first update and then takes itself off. */
    private static final class FailingView extends AbstractControl {

        @Override
        protected void controlUpdate(float tpf) {
            spatial.removeControl(this);
            throw new IllegalStateException(MESSAGE);
        }

        @Override
        protected void controlRender(RenderManager renderManager, ViewPort viewPort) {
        }
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;

/**
 * Issue 17: when a demo failed while the demos were initialising, jME's failure handler threw
 * too ("NullPointerException thrown from the UncaughtExceptionHandler"): jME's window
 * ({@code LwjglWindow}) reports the failure with {@link ParticleLabApp#handleError} and then
 * destroys the application, which cleans up every attached state, and a demo attached after
 * the failing one, enabled but never initialised, threw in its cleanup. The headless context
 * reports the failure the same way but does not destroy the application: this test does that
 * second half, as the window would, once the jME thread has died.
 */
class FailureHandlerTest {

    private static final long TIMEOUT_SECONDS = 30;
    private static final String REASON = "this demo cannot build its scene";

    @Test
    void aDemoFailingWhileTheDemosInitialiseIsReportedAndTidyingUpThrowsNothing()
            throws Exception {
        List<DemoState> demos = new ArrayList<>();
        demos.add(new FailingDemo());
        // The demo shown: attached after the failing one, so never initialised.
        demos.add(DemoCatalog.createAll().get(0));
        ParticleLabApp app = new ParticleLabApp(demos, 1, 0, null, 0f);
        AppSettings settings = ParticleLabApp.createSettings(0f);
        settings.setFrameRate(60);
        app.setSettings(settings);
        // The headless context installs its own default handler (it calls handleError).
        Thread.UncaughtExceptionHandler previous = Thread.getDefaultUncaughtExceptionHandler();
        try {
            app.start(JmeContext.Type.Headless);
            assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "no failure reported");
            assertTrue(app.getFailure().contains(": IllegalStateException: " + REASON + " at "),
                    app.getFailure());
            // What the window's handler does next, on the jME thread (dead by now).
            assertDoesNotThrow(app::destroy, "tidying up after the failure threw");
        } finally {
            Thread.setDefaultUncaughtExceptionHandler(previous);
        }
        assertEquals(0, app.countFrames());
    }

    /** A demo whose scene cannot be built: it throws while the demos initialise. */
    private static final class FailingDemo extends DemoState {

        FailingDemo() {
            super("Failing");
        }

        @Override
        protected void createScene() {
            throw new IllegalStateException(REASON);
        }
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.system.JmeContext;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;

/** What the window does first: the frames it counts. */
class ParticleLabAppStartTest {

    private static final float FRAME_SECONDS = 1f / 60f;
    private static final long TIMEOUT_SECONDS = 30;

    /**
     * {@code --frames 1 --screenshot} once saved a blank picture: frame 1 was counted (and
     * captured) before the demo had initialised. Now the one counted frame is one in which the
     * demo ran: its clock has taken its step of 1/60 s.
     */
    @Test
    void theFirstCountedFrameIsOneInWhichTheDemoRan() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        ParticleLabApp app = new ParticleLabApp(demos, 2, 1, null, FRAME_SECONDS);
        app.start(JmeContext.Type.Headless);
        try {
            assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "the app did not stop");
        } finally {
            app.stop(true);
        }
        assertEquals(1, app.countFrames());
        // one fixed step of 1/60 s per frame of 1/60 s
        assertEquals(FRAME_SECONDS, demos.get(2).getClock().getSimulatedSeconds(), 1e-6);
    }
}

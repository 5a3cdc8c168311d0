package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.physics.SimulationClock;
import particlelab.view.ScreenRect;

/**
 * The lecture hall's scene: in every catalogue demo, at the window sizes a projector gives and
 * with the default HUD, the rectangle the scene is drawn into (its grid and ground as the
 * plane view maps them) covers at least {@value #MIN_SCENE_AREA_SHARE} of the window, through
 * launch, flight and landing, and no empty band is left between the HUD and the scene.
 */
class SceneShareHeadlessTest {

    /** The least share of the window's area the scene is drawn into. */
    static final float MIN_SCENE_AREA_SHARE = 0.55f;
    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{1280, 720}, {1024, 768}, {1920, 1080}};
    private static final int FRAMES = 240;
    private static final int SAMPLE_EVERY = 20;
    /** A pixel's rounding between the HUD's band and the scene's edge. */
    private static final float PIXEL = 1f;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void theSceneFillsMostOfTheWindowInEveryDemoAtProjectorSizes() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            for (int[] window : WINDOWS) {
                problems.addAll(harness.call(() -> run(demo, window[0], window[1])));
            }
            harness.call(() -> {
                demo.getDemoHud().layOut(1280, 720);
                return true;
            });
        }
        assertEquals(List.of(), problems.subList(0, Math.min(60, problems.size())),
                problems.size() + " problems");
    }

    private static List<String> run(DemoState demo, int width, int height) {
        List<String> problems = new ArrayList<>();
        demo.getDemoHud().layOut(width, height);
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        demo.restart();
        ScreenRect drawn = new ScreenRect();
        for (int frame = 0; frame < FRAMES; frame += SAMPLE_EVERY) {
            demo.getWindow().copySceneRect(drawn);
            float share = drawn.getWidth() * drawn.getHeight() / (width * (float) height);
            String where = demo.getTitle() + " " + width + "x" + height + " frame " + frame;
            if (share < MIN_SCENE_AREA_SHARE) {
                problems.add(where + ": the scene " + drawn + " covers only "
                        + Math.round(100f * share) + " % of the window");
                break;
            }
            // No empty gap: the scene is drawn up to the HUD's bands.
            float gap = demo.getWindow().getHud().getLayout().getScene().getTop() - drawn.getTop();
            if (gap > PIXEL) {
                problems.add(where + ": " + Math.round(gap) + " px empty above the scene");
            }
            for (int i = 0; i < SAMPLE_EVERY; ++i) {
                demo.update(H);
            }
        }
        return problems;
    }
}

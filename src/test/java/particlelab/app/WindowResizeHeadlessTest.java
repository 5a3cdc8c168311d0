package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.demo.DemoState;
import particlelab.view.HudLayout;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;

/**
 * Issue 17: a running window resized to 400x300 died. Here each catalogue demo in turn, shown
 * in a real headless application that opened at 1280x720, has its window (the camera, as jME
 * resizes it on a reshape) taken down to the smallest size {@code --window} accepts and back,
 * with frames of jME's loop between: each size is laid out by the next frames, with the scene
 * inside the window, and back at 1280x720 the layout is the one the fresh window had (a band
 * grown on the small window gives its lines back).
 */
class WindowResizeHeadlessTest {

    private static final int[][] SEQUENCE = {{640, 360}, {400, 300},
        {HudLayout.MIN_WIDTH, HudLayout.MIN_HEIGHT}, {1280, 720}};
    private static final int FRAMES_BETWEEN = 3;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void everyDemoSurvivesAResizeDownToTheSmallestWindowAndComesBackAsFresh()
            throws Exception {
        ParticleLabApp app = harness.app();
        int count = app.getSwitcher().getDemos().size();
        for (int index = 0; index < count; ++index) {
            int chosen = index;
            harness.call(() -> {
                app.getSwitcher().select(chosen);
                return true;
            });
            harness.awaitFrames(FRAMES_BETWEEN);
            DemoState demo = app.getSwitcher().getDemos().get(index);
            String fresh = harness.call(() -> describe(demo));
            for (int[] size : SEQUENCE) {
                harness.call(() -> {
                    app.getCamera().resize(size[0], size[1], true);
                    return true;
                });
                harness.awaitFrames(FRAMES_BETWEEN);
                String where = demo.getTitle() + " at " + size[0] + "x" + size[1];
                assertTrue(harness.call(
                        () -> demo.getDemoHud().isLaidOutFor(size[0], size[1], 1f)), where);
                ScreenRect scene = harness.call(() -> demo.getHud().getLayout().getScene());
                assertTrue(!scene.isEmpty() && new ScreenRect(0f, 0f, size[0], size[1])
                        .contains(scene), where + ": scene " + scene);
            }
            assertEquals(fresh, harness.call(() -> describe(demo)), demo.getTitle());
        }
    }

    /** Every rectangle and number of a demo's layout, exactly, as text to compare. */
    private static String describe(DemoState demo) {
        HudLayout layout = demo.getHud().getLayout();
        List<String> parts = new ArrayList<>();
        for (ScreenRect rect : new ScreenRect[] {layout.getWindow(), layout.getTitle(),
            layout.getBody(), layout.getWarning(), layout.getFooter(), layout.getScene(),
            layout.getSidePanel(), layout.getGraph(), layout.getHelpPanel()}) {
            parts.add(rect.getX() + "," + rect.getY() + "," + rect.getWidth() + ","
                    + rect.getHeight());
        }
        PlaneView plane = demo.getPlaneView();
        parts.add("scale " + layout.getScale() + ", body lines " + layout.getBodyLines()
                + ", help " + layout.getHelpSize() + ", " + plane.getPixelsPerMetre()
                + " px/m at " + plane.getCentreX() + ", " + plane.getCentreY());
        parts.add(demo.getHud().getFooterText());
        // The HUD is rebuilt every frame, so a line of wall-clock figures (the fountain's
        // "physics ... ms/frame ... fps") differs from frame to frame: its text is left out,
        // the lines it took are kept.
        for (String line : demo.getHud().getBodyText().split("\n", -1)) {
            parts.add(line.contains(" ms/frame") ? "(measured line)" : line);
        }
        return String.join("\n", parts);
    }
}

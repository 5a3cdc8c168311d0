package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.physics.SimulationClock;
import particlelab.view.HudLayout;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;

/**
 * Issue 17: every demo died at start on a 640x360 window, and after about 250 random keys on
 * an 800x450 one, because the scene's area could shrink to nothing and the plane view threw
 * on the render thread. Here every catalogue demo, in a real headless jME application, is laid
 * out at every size from the smallest {@code --window} accepts to 4K, with and without the
 * side panel's and the graph's slots and with the help shown, and run through its launch:
 * nothing throws, every view's rectangle is non-empty and inside the window, the scene keeps
 * its share of the height, and no two texts overlap or leave the window (the HUD's at every
 * size, the scene's labels too from 640x360 up). {@link RandomKeysHeadlessTest} presses the
 * keys.
 */
class SmallWindowHeadlessTest {

    private static final float H = 1f / 60f;
    /** From the smallest window --window accepts up to 4K. */
    private static final int[][] WINDOWS = {{HudLayout.MIN_WIDTH, HudLayout.MIN_HEIGHT},
        {320, 240}, {400, 300}, {640, 360}, {800, 450}, {1024, 768}, {1280, 720},
        {1920, 1080}, {3840, 2160}};
    /** Slots as large as a parameter panel and a live graph ask for (pixels at scale 1). */
    private static final float PANEL_WIDTH = 320f;
    private static final float GRAPH_WIDTH = 360f;
    private static final float GRAPH_HEIGHT = 200f;
    /** The smallest window whose scene labels are checked too (pixels). */
    private static final int SCENE_LABELS_WIDTH = 640;
    private static final int SCENE_LABELS_HEIGHT = 360;
    /** A launch and its flight, sampled every few frames. */
    private static final int FRAMES = 120;
    private static final int SAMPLE_EVERY = 20;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void everyDemoKeepsItsViewsInsideTheWindowAtEverySizeFromTheSmallestUp() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            for (int[] window : WINDOWS) {
                for (boolean slots : new boolean[] {false, true}) {
                    problems.addAll(harness.call(() -> run(demo, window[0], window[1],
                            slots)));
                }
            }
        }
        assertEquals(List.of(), problems.subList(0, Math.min(10, problems.size())),
                problems.size() + " problems");
    }

    /** Lay a demo out for a window, run its launch and check it every few frames. */
    private static List<String> run(DemoState demo, int width, int height, boolean slots) {
        HudLayout layout = demo.getWindow().getHud().getLayout();
        if (slots) {
            layout.setPanelWidth(PANEL_WIDTH);
            layout.setGraphSize(GRAPH_WIDTH, GRAPH_HEIGHT);
        }
        String where = demo.getTitle() + " " + width + "x" + height
                + (slots ? " with slots" : "") + " ";
        List<String> problems = new ArrayList<>();
        try {
            demo.getDemoHud().layOut(width, height);
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < FRAMES; ++frame) {
                demo.update(H);
                if (frame % SAMPLE_EVERY == 0) {
                    problems.addAll(check(demo, width, height, slots, where + "frame "
                            + frame));
                }
            }
            demo.getWindow().getHud().setHelpVisible(true);
            problems.addAll(check(demo, width, height, slots, where + "help"));
        } finally {
            demo.getWindow().getHud().setHelpVisible(false);
            layout.setPanelWidth(0f);
            layout.setGraphSize(0f, 0f);
            demo.getDemoHud().layOut(1280, 720);
        }
        return problems;
    }

    /** The views and the texts: inside the window, non-empty views, no overlaps. */
    private static List<String> check(DemoState demo, int width, int height, boolean slots,
            String where) {
        List<String> problems = checkViews(demo, width, height, slots, slots, where);
        // The scene's own labels follow the particles and dodge each other in the scene's
        // area; in a scene a few dozen pixels high (below 640x360) one may stick out of it
        // or touch another, so there only the HUD's texts and slots are checked.
        List<ScreenRect> rects = width >= SCENE_LABELS_WIDTH && height >= SCENE_LABELS_HEIGHT
                ? demo.getWindow().copyTextRects(new ArrayList<>())
                : demo.getWindow().getHud().copyTextRects(new ArrayList<>());
        if (!demo.getWindow().getHud().isHelpVisible()) {
            rects.add(demo.getWindow().getHud().getLayout().getSidePanel());
            rects.add(demo.getWindow().getHud().getLayout().getGraph());
        }
        problems.addAll(ScreenChecks.textsApartInside(rects, width, height, where));
        return problems;
    }

    /**
     * The scene and the slots asked for: each non-empty and inside the window; the scene
     * with its share of the height; the plane's mapping finite.
     */
    static List<String> checkViews(DemoState demo, int width, int height, boolean panel,
            boolean graph, String where) {
        List<String> problems = new ArrayList<>();
        HudLayout layout = demo.getWindow().getHud().getLayout();
        ScreenRect window = new ScreenRect(0f, 0f, width, height);
        List<ScreenRect> views = new ArrayList<>(List.of(layout.getScene()));
        if (panel) {
            views.add(layout.getSidePanel());
        }
        if (graph) {
            views.add(layout.getGraph());
        }
        for (ScreenRect view : views) {
            if (view.isEmpty() || !window.contains(view)) {
                problems.add(where + ": view " + view + " is empty or leaves the window");
            }
        }
        if (layout.getScene().getHeight() < HudLayout.MIN_SCENE_SHARE * height) {
            problems.add(where + ": the scene gets only " + layout.getScene());
        }
        PlaneView plane = demo.getWindow().getPlaneView();
        if (!(plane.getPixelsPerMetre() > 0f && Float.isFinite(plane.getCentreX())
                && Float.isFinite(plane.getCentreY()))) {
            problems.add(where + ": the plane view is " + plane.getPixelsPerMetre()
                    + " px/m at " + plane.getCentreX() + ", " + plane.getCentreY());
        }
        return problems;
    }
}

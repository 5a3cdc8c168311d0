package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.physics.SimulationClock;
import particlelab.view.HudLayout;
import particlelab.view.HudScale;
import particlelab.view.ScreenRect;

/**
 * The lecture hall's layouts: every catalogue demo at the four window sizes and at the HUD
 * factors of {@code --ui-scale} (its two ends and 1), with the side panel's and the graph's
 * slots asked for, in a real headless jME application: no two text rectangles intersect (the
 * two slots count as texts), every text stays inside the window, and the scene keeps its
 * share of the window. Its own application, so the body bands the extreme factors grow do
 * not carry over into {@link ScreenLayoutHeadlessTest}'s demos.
 */
class WindowLayoutHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{1024, 768}, {1280, 720}, {1920, 1080},
        {3840, 2160}};
    /** The HUD factors checked: the range's ends and the default. */
    private static final float[] FACTORS = {HudScale.MIN_FACTOR, 1f, HudScale.MAX_FACTOR};
    /** Slots as large as a parameter panel and a live graph ask for (pixels at scale 1). */
    private static final float PANEL_WIDTH = 320f;
    private static final float GRAPH_WIDTH = 360f;
    private static final float GRAPH_HEIGHT = 200f;
    /** Launch, flight and landing of every demo, sampled every few frames. */
    private static final int FRAMES = 240;
    private static final int SAMPLE_EVERY = 12;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void noTwoTextsIntersectAtAnySizeAndFactorWithThePanelAndGraphSlots() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            for (int[] window : WINDOWS) {
                for (float factor : FACTORS) {
                    problems.addAll(harness.call(() -> run(demo, window[0], window[1],
                            factor)));
                }
            }
        }
        assertEquals(List.of(), problems.subList(0, Math.min(10, problems.size())),
                problems.size() + " problems");
    }

    @Test
    void aSmallWindowAtFactorTwoNamesTheFactorItReducedAndTheOneItGot() throws Exception {
        // Issue 19: at --ui-scale 2 in a small window the footer said "window too small"
        // without saying that the text was smaller than asked, nor how much.
        DemoState demo = harness.app().getSwitcher().getDemos().get(2);
        String[] shown = harness.call(() -> {
            try {
                demo.getDemoHud().layOut(640, 360, HudScale.MAX_FACTOR);
                // The factor the window got: the scale laid out over the one that suits it.
                float got = demo.getWindow().getHud().getLayout().getScale()
                        / HudLayout.scaleFor(640, 360);
                long tenths = Math.round(10.0 * got);
                return new String[] {demo.getWindow().getHud().getFooterText().replace("\n    ",
                        " "),
                    tenths / 10 + "." + tenths % 10};
            } finally {
                demo.getDemoHud().layOut(1280, 720);
            }
        });
        String footer = shown[0];
        assertTrue(Float.parseFloat(shown[1]) < HudScale.MAX_FACTOR, shown[1]);
        assertEquals("text x2.0 reduced to x" + shown[1]
                + ": window too small (640x360), HUD lines hidden", footer);
    }

    private static List<String> run(DemoState demo, int width, int height, float factor) {
        HudLayout layout = demo.getWindow().getHud().getLayout();
        layout.setPanelWidth(PANEL_WIDTH);
        layout.setGraphSize(GRAPH_WIDTH, GRAPH_HEIGHT);
        List<String> problems = new ArrayList<>();
        String where = demo.getTitle() + " " + width + "x" + height + " x" + factor + " ";
        try {
            demo.getDemoHud().layOut(width, height, factor);
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            ScreenRect scene = layout.getScene();
            if (scene.getHeight() < HudScale.MIN_SCENE_SHARE * height) {
                problems.add(where + "the scene gets only " + scene);
            }
            for (int frame = 0; frame < FRAMES; ++frame) {
                demo.update(H);
                if (frame % SAMPLE_EVERY == 0) {
                    problems.addAll(check(demo, width, height, where + "frame " + frame));
                }
            }
        } finally {
            layout.setPanelWidth(0f);
            layout.setGraphSize(0f, 0f);
            demo.getDemoHud().layOut(1280, 720);
        }
        return problems;
    }

    /** No two texts (the slots included) intersect, and all are inside the window. */
    private static List<String> check(DemoState demo, int width, int height, String where) {
        List<String> problems = new ArrayList<>();
        List<ScreenRect> rects = demo.getWindow().copyTextRects(new ArrayList<>());
        rects.add(demo.getWindow().getHud().getLayout().getSidePanel());
        rects.add(demo.getWindow().getHud().getLayout().getGraph());
        problems.addAll(ScreenChecks.textsApartInside(rects, width, height, where));
        return problems;
    }
}

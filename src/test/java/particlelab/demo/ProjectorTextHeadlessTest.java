package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.view.HudLayout;
import particlelab.view.ParameterPanel;
import particlelab.view.ScreenRect;

/**
 * Issue 19, the lecture hall: text sizes that work on a projector, measured in a real headless
 * jME application from the HUD's laid-out rectangles. The HUD factor ({@code --ui-scale}, F9 /
 * F10) makes every demo's body text larger, never smaller; the help overlay is set in columns
 * across the window with legible text; the parameter panel's text is legible.
 */
class ProjectorTextHeadlessTest {

    /** The factors of {@code --ui-scale} measured, in increasing order. */
    private static final float[] FACTORS = {0.5f, 1f, 1.5f, 2f};
    private static final int[][] WINDOWS = {{1280, 720}, {1920, 1080}};
    /** The least help text height at 1280x720 (in pixels). */
    private static final float MIN_HELP_PIXELS = 16f;
    /** The least parameter panel text height at 1280x720 (in pixels). */
    private static final float MIN_PANEL_PIXELS = 14f;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void aLargerHudFactorGivesLargerBodyTextInEveryDemo() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            for (int[] window : WINDOWS) {
                problems.addAll(harness.call(() -> {
                    List<String> found = new ArrayList<>();
                    float before = 0f;
                    for (float factor : FACTORS) {
                        demo.getDemoHud().layOut(window[0], window[1], factor);
                        HudLayout layout = demo.getWindow().getHud().getLayout();
                        // The body band's real line height on the screen.
                        float line = layout.getBody().getHeight() / layout.getBodyLines();
                        if (!(line > before)) {
                            found.add(demo.getTitle() + " " + window[0] + "x" + window[1]
                                    + " x" + factor + ": body line " + line
                                    + " px, not above " + before + " px");
                        }
                        before = line;
                    }
                    demo.getDemoHud().layOut(1280, 720);
                    return found;
                }));
            }
        }
        assertEquals(List.of(), problems);
    }

    @Test
    void theHelpUsesTheWindowsWidthInLegibleColumnsAt1280x720() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            problems.addAll(harness.call(() -> {
                List<String> found = new ArrayList<>();
                demo.getDemoHud().layOut(1280, 720);
                demo.getWindow().getHud().setHelpVisible(true);
                HudLayout layout = demo.getWindow().getHud().getLayout();
                List<ScreenRect> columns = layout.getHelpColumns();
                float right = columns.get(columns.size() - 1).getRight();
                if (layout.getHelpSize() < MIN_HELP_PIXELS) {
                    found.add(demo.getTitle() + ": help text " + layout.getHelpSize() + " px");
                }
                if (columns.size() > 1 && right < 0.5f * 1280) {
                    found.add(demo.getTitle() + ": help columns end at " + right + " px");
                }
                demo.getWindow().getHud().setHelpVisible(false);
                return found;
            }));
        }
        assertEquals(List.of(), problems);
    }

    @Test
    void theParameterPanelsTextIsLegibleAt1280x720() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            if (demo.getParameters().size() == 0) {
                continue;
            }
            problems.addAll(harness.call(() -> {
                List<String> found = new ArrayList<>();
                demo.getDemoHud().layOut(1280, 720);
                HeadlessHarness.press(demo, "F2");
                demo.update(1f / 60f);
                ParameterPanel panel = demo.getParameterControls().getPanel();
                if (!(panel.getTextSize() >= MIN_PANEL_PIXELS)) {
                    found.add(demo.getTitle() + ": panel text " + panel.getTextSize() + " px");
                }
                HeadlessHarness.press(demo, "F2");
                demo.update(1f / 60f);
                return found;
            }));
        }
        assertEquals(List.of(), problems);
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.scene.Spatial;
import com.simsilica.lemur.Container;
import com.simsilica.lemur.Label;
import com.simsilica.lemur.Panel;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;
import particlelab.view.HudFont;
import particlelab.view.HudLayout;
import particlelab.view.ParameterPanel;
import particlelab.view.ScreenRect;
import particlelab.view.TextMeasure;

/**
 * Issue 29 §3: nothing in the parameter panel covers anything else, and its text is legible.
 * Every demo of the catalogue opens its panel (F2) with a kept shot in its legend, in a real
 * headless application, at 640x360, 1280x720 and 3840x2160, and after whole frames (Lemur
 * lays the panel out in the GUI node's logical update):
 * <ul>
 * <li>every text fits its own element: its lines, as the font measures them, no wider than
 * the label Lemur gave it (a wider one is wrapped by Lemur inside a box one line high, and
 * its other lines are drawn over the slider or text below: pull's kept-shot line over the
 * timeline, "strategy" and "horizontal" over sliders in iterate and targets);</li>
 * <li>the elements follow one another down the panel without overlapping;</li>
 * <li>the panel stays inside the window;</li>
 * <li>the text is at least {@value ParameterPanel#MIN_TEXT_PIXELS} px where the window suits
 * it (1280x720 and up; it was 10 px at 1280x720 when the HUD's band shrank its scale).</li>
 * </ul>
 */
class PanelLayoutHeadlessTest {

    private static final int[][] WINDOWS = {{640, 360}, {1280, 720}, {3840, 2160}};
    /** Frames after a change: the panel is placed and laid out within one or two. */
    private static final int FRAMES = 4;
    /**
     * Lemur places children at float sums of sizes: a hundredth of a pixel is round-off,
     * far below a pixel of real overlap.
     */
    private static final float PIXEL_TOLERANCE = 0.01f;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void noPanelElementCoversAnotherAndItsTextIsLegible() throws Exception {
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        int count = harness.call(() -> app.getSwitcher().getDemos().size());
        for (int index = 0; index < count; ++index) {
            int chosen = index;
            harness.call(() -> {
                app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
                app.getSwitcher().select(chosen);
                return true;
            });
            // the switch happens in the application's next update
            harness.awaitFrames(2);
            problems.addAll(harness.call(() -> {
                List<String> found = new ArrayList<>();
                DemoState demo = app.getSwitcher().getSelected();
                HeadlessHarness.press(demo, "F2");
                // a flight, then a reset: its launch stays as a kept shot in the legend
                for (int frame = 0; frame < 30; ++frame) {
                    SmallPanelHeadlessTest.frame(app);
                }
                HeadlessHarness.press(demo, "R");
                for (int[] window : WINDOWS) {
                    app.reshape(window[0], window[1]);
                    for (int frame = 0; frame < FRAMES; ++frame) {
                        SmallPanelHeadlessTest.frame(app);
                    }
                    check(demo, window, found);
                }
                HeadlessHarness.press(demo, "F2");
                SmallPanelHeadlessTest.frame(app);
                return found;
            }));
        }
        harness.call(() -> {
            app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
            app.getSwitcher().select(0);
            return true;
        });
        assertEquals(List.of(), problems.subList(0, Math.min(12, problems.size())),
                problems.size() + " problems");
    }

    private static void check(DemoState demo, int[] window, List<String> found) {
        String where = demo.getTitle() + " at " + window[0] + "x" + window[1] + ": ";
        ParameterPanel panel = demo.getParameterControls().getPanel();
        ScreenRect rect = panel.copyRect(new ScreenRect());
        if (rect.isEmpty()) {
            found.add(where + "the panel is not shown");
            return;
        }
        if (rect.getX() < -PIXEL_TOLERANCE
                || rect.getX() + rect.getWidth() > window[0] + PIXEL_TOLERANCE
                || rect.getY() < -PIXEL_TOLERANCE
                || rect.getTop() > window[1] + PIXEL_TOLERANCE) {
            found.add(where + "the panel " + rect + " leaves the window");
        }
        float textSize = panel.getTextSize();
        if (HudLayout.scaleFor(window[0], window[1])
                >= ParameterPanel.MIN_TEXT_PIXELS / ParameterPanel.TEXT_SIZE
                && textSize < ParameterPanel.MIN_TEXT_PIXELS) {
            found.add(where + "text " + textSize + " px");
        }
        TextMeasure measure = TextMeasure.of(HudFont.load(
                demo.getApplication().getAssetManager()));
        Container container = panel.getContainer();
        float previousBottom = Float.NaN;
        String previous = "";
        for (Spatial child : container.getChildren()) {
            if (!(child instanceof Panel)) {
                continue;
            }
            Panel element = (Panel) child;
            float top = element.getLocalTranslation().y;
            float bottom = top - element.getSize().y;
            String name = child instanceof Label ? "\"" + ((Label) child).getText() + "\""
                    : child.getClass().getSimpleName();
            if (top > previousBottom + PIXEL_TOLERANCE) {
                found.add(where + name + " overlaps " + previous);
            }
            if (child instanceof Label) {
                Label label = (Label) child;
                float width = measure.width(label.getText(), label.getFontSize());
                if (width > element.getSize().x + PIXEL_TOLERANCE) {
                    found.add(where + name + " is " + width + " px wide in a label "
                            + element.getSize().x + " px wide: Lemur wraps it over what"
                            + " lies below");
                }
            }
            previousBottom = bottom;
            previous = name;
        }
    }
}

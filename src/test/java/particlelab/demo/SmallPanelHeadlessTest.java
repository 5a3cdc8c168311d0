package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.app.state.AppStateManager;
import com.jme3.math.Vector3f;
import com.jme3.renderer.RenderManager;
import com.simsilica.lemur.Panel;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;
import particlelab.view.ParameterPanel;
import particlelab.view.ScreenRect;

/**
 * Issue 36: a small window with the parameter panel open ended the window with Lemur's
 * "Size cannot be negative" on the render thread, because the panel was made exactly as wide
 * as its slot (40 % of the window) and Lemur's layout then gave the sliders' tracks and the
 * buttons less than nothing. Here every demo of the catalogue, in a real headless
 * application, opens its panel (F2) at 200x150, 320x240 and 640x360, presenting (F8) and
 * not, and runs whole frames of jME's loop (Lemur lays the panel out in the GUI node's
 * logical update): nothing throws, no Lemur panel has a negative or NaN size, and nothing in
 * the GUI is placed or scaled by NaN.
 */
class SmallPanelHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{200, 150}, {320, 240}, {640, 360}};
    /**
     * Frames after each change: the panel is placed and laid out within one or two (Lemur
     * lays it out in the logical update of the frame after it was placed).
     */
    private static final int FRAMES = 2;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void everyDemosOpenPanelSurvivesSmallWindowsPresentingAndNot() throws Exception {
        List<String> problems = new ArrayList<>();
        ParticleLabApp app = harness.app();
        int count = app.getSwitcher().getDemos().size();
        for (int index = 0; index < count; ++index) {
            int chosen = index;
            DemoState demo = app.getSwitcher().getDemos().get(index);
            harness.call(() -> {
                app.getSwitcher().select(chosen);
                frame(app);
                HeadlessHarness.press(demo, "F2");
                return true;
            });
            for (boolean presenting : new boolean[] {false, true}) {
                for (int[] window : WINDOWS) {
                    problems.add(harness.call(() -> {
                        try {
                            app.getWindowControls().setPresenting(presenting);
                            app.reshape(window[0], window[1]);
                            for (int frame = 0; frame < FRAMES; ++frame) {
                                frame(app);
                            }
                            return check(demo, window, presenting);
                        } catch (RuntimeException e) {
                            return demo.getTitle() + " at " + window[0] + "x" + window[1]
                                    + (presenting ? " presenting" : "") + ": " + e;
                        }
                    }));
                }
            }
            // The panel closed again; the next demo opens at the last window (its first case
            // sets the window and the mode anyway).
            harness.call(() -> {
                HeadlessHarness.press(demo, "F2");
                return true;
            });
        }
        harness.call(() -> {
            app.getWindowControls().setPresenting(false);
            app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
            frame(app);
            return true;
        });
        problems.removeIf(String::isEmpty);
        assertEquals(List.of(), problems.subList(0, Math.min(5, problems.size())),
                problems.size() + " problems");
    }

    /**
     * Issue 36's BufferOverflowException: at 200x150 with the HUD factor 2 (F10), presenting
     * and the panel open, the HUD leaves the scene about a pixel high, and the frame
     * stretched to that shape asked for a distance grid of 10^9 lines or more: its line
     * count overflowed (the buffer it sized overflowed in the window) or its loop never
     * ended (this test timed out in the first demo). Every demo lays out and runs its
     * frames there, and nothing is recovered from.
     */
    @Test
    void everyDemoLaysOutItsGridWhenTheHudLeavesTheSceneAPixelHigh() throws Exception {
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        int count = app.getSwitcher().getDemos().size();
        for (int index = 0; index < count; ++index) {
            int chosen = index;
            DemoState demo = app.getSwitcher().getDemos().get(index);
            problems.add(harness.call(() -> {
                app.getSwitcher().select(chosen);
                frame(app);
                HeadlessHarness.press(demo, "F2");
                try {
                    app.getWindowControls().setUiFactor(2f);
                    app.getWindowControls().setPresenting(true);
                    app.reshape(200, 150);
                    for (int frame = 0; frame < FRAMES; ++frame) {
                        frame(app);
                    }
                    return app.getRecovered() == null ? check(demo, new int[] {200, 150}, true)
                            : demo.getTitle() + ": " + app.getRecovered();
                } catch (RuntimeException e) {
                    return demo.getTitle() + ": " + e;
                } finally {
                    HeadlessHarness.press(demo, "F2");
                    app.getWindowControls().setPresenting(false);
                    app.getWindowControls().setUiFactor(1f);
                    app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
                    frame(app);
                }
            }));
        }
        problems.removeIf(String::isEmpty);
        assertEquals(List.of(), problems);
    }

    /**
     * The panel put into slots from a pixel wide up, at the HUD scales from the smallest to
     * the largest, and laid out by Lemur as a frame does: nothing is handed a negative size.
     */
    @Test
    void thePanelInASlotNarrowerThanItsContentIsLaidOutWithoutANegativeSize()
            throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            problems.addAll(harness.call(() -> {
                List<String> found = new ArrayList<>();
                ParameterPanel panel = demo.getParameterControls().getPanel();
                for (float scale : new float[] {0.5f, 0.9f, 1f, 2f, 4f}) {
                    for (float width : new float[] {1f, 10f, 40f, 80f, 160f}) {
                        try {
                            panel.place(new ScreenRect(0f, 0f, width, 400f), scale);
                            panel.getNode().updateLogicalState(H);
                        } catch (RuntimeException e) {
                            found.add(demo.getTitle() + " " + width + " px at x" + scale
                                    + ": " + e.getMessage());
                        }
                    }
                }
                panel.place(new ScreenRect(0f, 0f, 0f, 0f), 1f);
                return found;
            }));
        }
        assertEquals(List.of(), problems.subList(0, Math.min(5, problems.size())),
                problems.size() + " problems");
    }

    /**
     * Check what a frame laid out: the demo is on screen with its panel asked for (F2),
     * every Lemur panel in the GUI has a size of no
     * negative or NaN side, and every GUI spatial is placed and scaled by finite numbers.
     *
     * @return "" or what is wrong
     */
    private static String check(DemoState demo, int[] window, boolean presenting) {
        ParticleLabApp app = harness.app();
        String where = demo.getTitle() + " at " + window[0] + "x" + window[1]
                + (presenting ? " presenting" : "");
        if (app.getSwitcher().getSelected() != demo) {
            return where + ": not on screen";
        }
        if (!demo.getParameterControls().isPanelVisible()) {
            return where + ": the panel (F2) is closed";
        }
        List<String> found = new ArrayList<>();
        app.getGuiNode().depthFirstTraversal(spatial -> {
            if (spatial instanceof Panel) {
                Vector3f size = ((Panel) spatial).getSize();
                if (!(size.x >= 0f && size.y >= 0f && size.z >= 0f)
                        || !Float.isFinite(size.x + size.y + size.z)) {
                    found.add(spatial.getName() + " has size " + size);
                }
            }
            Vector3f at = spatial.getWorldTranslation();
            Vector3f scale = spatial.getWorldScale();
            if (!Float.isFinite(at.x + at.y + at.z + scale.x + scale.y + scale.z)) {
                found.add(spatial.getName() + " at " + at + " scaled " + scale);
            }
        });
        return found.isEmpty() ? "" : where + ": " + found;
    }

    /** One whole frame as {@code SimpleApplication.update()} runs it. */
    static void frame(ParticleLabApp app) {
        app.getInputManager().update(H);
        AppStateManager states = app.getStateManager();
        RenderManager render = app.getRenderManager();
        states.update(H);
        app.simpleUpdate(H);
        app.getRootNode().updateLogicalState(H);
        app.getGuiNode().updateLogicalState(H);
        app.getRootNode().updateGeometricState();
        app.getGuiNode().updateGeometricState();
        states.render(render);
        render.render(H, app.getContext().isRenderable());
        app.simpleRender(render);
        states.postRender();
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.input.KeyInput;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.LensPart;
import particlelab.lecture.DragDemo;
import particlelab.view.LensGraph;
import particlelab.view.ScreenRect;
import particlelab.world.StateSlab;

/**
 * The window's mouse on DragDemo in a real headless application, through the application's
 * pick input and its framed camera: a press on a sphere, a move, a release move the launch to
 * where the mouse is (the new launch is drawn under the mouse) and the scene waits at t = 0;
 * a press on the parameter panel or with the help up picks nothing; the help and the footer
 * name the mouse's gestures; with the derivative lens on, a click on a step dot shows that
 * step and the lens's graph stands beside the scene. The drag's physics (ghosts, kept shots,
 * inspector) is {@code particlelab.demo.DragHeadlessTest}'s.
 */
class PickHeadlessTest {

    private static final float H = 1f / 60f;
    /**
     * Where the new launch is drawn against where the mouse was: two float projections
     * through the camera, a thousandth of a pixel.
     */
    private static final float PIXEL_TOLERANCE = 0.01f;
    private static final DragDemo drag = new DragDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(drag));

    @Test
    void aDragThroughTheWindowMovesTheLaunchUnderTheMouse()
            throws Exception {
        float[] result = harness.call(() -> {
            HeadlessHarness.fly(drag, 40, H);
            Camera camera = harness.app().getCamera();
            DemoParticle first = drag.getParticles().get(0);
            Vector3f screen = camera.getScreenCoordinates(first.copyLaunchPosition(
                    new Vector3f()));
            // The sphere has flown off: its launch point is empty space, its sphere is
            // where it is now.
            Vector3f now = camera.getScreenCoordinates(first.getParticle().position);
            PickInput input = harness.app().getPickInput();
            boolean taken = input.press(now.x, now.y);
            input.move(screen.x + 10f, screen.y + 10f);
            input.move(screen.x + 90f, screen.y + 60f);
            // Drawn where the mouse is while the button is down (the camera holds still).
            drag.update(H);
            Vector3f launch = first.copyLaunchPosition(new Vector3f());
            Vector3f drawn = camera.getScreenCoordinates(launch);
            input.release();
            drag.update(H);
            launch.subtractLocal(first.copyLaunchPosition(new Vector3f()));
            return new float[] {taken ? 1f : 0f, drawn.x - screen.x, drawn.y - screen.y,
                (float) drag.getClock().getSimulatedSeconds(),
                drag.getClock().isPaused() ? 1f : 0f,
                drag.getParticles().get(2).copyLaunchPosition(new Vector3f())
                        .distance(first.copyLaunchPosition(new Vector3f())), launch.length()};
        });
        assertEquals(1f, result[0], "the press took hold of a sphere");
        assertEquals(90f, result[1], PIXEL_TOLERANCE);
        assertEquals(60f, result[2], PIXEL_TOLERANCE);
        // The scene waits at t = 0, paused.
        assertEquals(0f, result[3]);
        assertEquals(1f, result[4]);
        // The three spheres share the launch, which the release left where it was.
        assertEquals(0f, result[5]);
        assertEquals(0f, result[6]);
    }

    @Test
    void aPressOnTheParameterPanelOrUnderTheHelpPicksNothing() throws Exception {
        List<Object> result = harness.call(() -> {
            drag.restart();
            drag.getWindow().getDragControl().clearPick();
            KeyBinding panelKey = binding(drag, KeyInput.KEY_F2);
            panelKey.press(0);
            drag.update(H);
            // The panel's slot down the right edge; its first rows are at the slot's top.
            ScreenRect panel = new ScreenRect()
                    .set(drag.getWindow().getHud().getLayout().getSidePanel());
            boolean onPanel = harness.app().getPickInput().press(
                    panel.getX() + panel.getWidth() / 2f, panel.getTop() - 20f);
            harness.app().getPickInput().release();
            panelKey.press(0);
            drag.update(H);
            drag.getWindow().getHud().setHelpVisible(true);
            Vector3f sphere = harness.app().getCamera().getScreenCoordinates(
                    drag.getParticles().get(0).getParticle().position);
            boolean underHelp = harness.app().getPickInput().press(sphere.x, sphere.y);
            harness.app().getPickInput().release();
            DemoParticle picked = drag.getWindow().getDragControl().getPicked();
            drag.getWindow().getHud().setHelpVisible(false);
            boolean visible = harness.app().getPickInput().press(sphere.x, sphere.y);
            harness.app().getPickInput().release();
            return java.util.Arrays.asList(panel.isEmpty(), onPanel, underHelp, picked,
                    visible);
        });
        assertFalse((Boolean) result.get(0), "the panel was shown");
        assertFalse((Boolean) result.get(1));
        assertFalse((Boolean) result.get(2));
        assertNull(result.get(3));
        assertTrue((Boolean) result.get(4));
    }

    @Test
    void withTheLensOnAClickOnAStepDotShowsThatStepAndTheGraphStandsBesideTheScene()
            throws Exception {
        Object[] result = harness.call(() -> {
            drag.restart();
            drag.getWindow().getDragControl().clearPick();
            drag.getParameters().set(LensPart.PARAMETER, 1f);
            HeadlessHarness.fly(drag, 40, H);
            // the lens follows the linear-drag sphere, the second particle: its position at
            // the ring's 15th entry, as the run wrote it (t, then each particle's P and V)
            long chosen = drag.getRun().getStateRing().getFirstIndex() + 15;
            StateSlab slab = drag.getRun().getStateRing().read(chosen);
            slab.getDouble();
            for (int skip = 0; skip < 6; ++skip) {
                slab.getFloat();
            }
            Vector3f dot = new Vector3f(slab.getFloat(), slab.getFloat(), slab.getFloat());
            Vector3f screen = harness.app().getCamera().getScreenCoordinates(dot);
            PickInput input = harness.app().getPickInput();
            boolean taken = input.press(screen.x, screen.y);
            input.release();
            drag.update(H);
            LensGraph graph = drag.getLens().getGraph();
            ScreenRect area = new ScreenRect().set(graph.getArea());
            ScreenRect strip = new ScreenRect()
                    .set(drag.getWindow().getHud().getLayout().getLedger());
            ScreenRect scene = drag.getWindow().copySceneRect(new ScreenRect());
            List<ScreenRect> graphTexts = graph.copyTextRects(new java.util.ArrayList<>());
            List<ScreenRect> hudTexts = drag.getWindow().copyTextRects(new java.util.ArrayList<>());
            Object[] found = {taken, drag.getRun().isReplaying(), drag.getRun().getShownStep() - chosen,
                dot.equals(drag.getLens().getLens().startPosition), graph.isVisible(), area,
                strip, scene, graphTexts, hudTexts, graph.getTextSize(),
                graph.getSlopeYText(), harness.app().getCamera().getWidth()};
            drag.getParameters().set(LensPart.PARAMETER, 0f);
            drag.restart();
            drag.update(H);
            return found;
        });
        assertTrue((Boolean) result[0], "the press on the dot was taken");
        assertTrue((Boolean) result[1], "the click shows a recorded step");
        assertEquals(0L, result[2], "the step of the dot clicked");
        assertTrue((Boolean) result[3], "the lens looks from the dot, bit for bit");
        assertTrue((Boolean) result[4], "the graph is shown");
        ScreenRect area = (ScreenRect) result[5];
        ScreenRect strip = (ScreenRect) result[6];
        ScreenRect scene = (ScreenRect) result[7];
        // in the strip down the scene's right edge, which the scene stays left of
        assertTrue(strip.contains(area), area + " in " + strip);
        assertTrue(area.getX() >= scene.getRight(), area + " right of the scene " + scene);
        @SuppressWarnings("unchecked")
        List<ScreenRect> graphTexts = (List<ScreenRect>) result[8];
        @SuppressWarnings("unchecked")
        List<ScreenRect> hudTexts = (List<ScreenRect>) result[9];
        for (ScreenRect text : graphTexts) {
            // a pixel's rounding at the edges (HudText's measured widths)
            assertTrue(new ScreenRect(area.getX() - 1f, area.getY() - 1f, area.getWidth() + 2f,
                    area.getHeight() + 2f).contains(text), text + " in the graph " + area);
            for (ScreenRect other : hudTexts) {
                assertFalse(text.intersects(other), text + " covers " + other);
            }
        }
        // readable from the back row: the window's scene labels' size, at least 14 px
        assertTrue((Float) result[10] >= 14f, "graph text " + result[10] + " px at "
                + result[12] + " px wide");
        assertTrue(((String) result[11]).startsWith("slope of V_y: -"), (String) result[11]);
    }

    @Test
    void theHelpAndTheFooterNameTheMouse() throws Exception {
        String[] texts = harness.call(() -> new String[] {drag.getKeys().getHelpText(),
            drag.getWindow().getHud().getLayout().getFooterText()});
        // The sphere and its arrow tip share a row.
        assertTrue(texts[0].contains("Mouse\n   drag a sphere / its arrow tip  -  launch P0 of"
                + " all 3 / launch V0 of all 3 = speed, angle (pauses, t = 0)\n"
                + "   click a sphere  -  inspect"), texts[0]);
        assertTrue(texts[0].contains("right drag / wheel  -  turn / zoom the camera"),
                texts[0]);
        assertTrue(texts[1].contains("right drag  camera"), texts[1]);
    }

    private static KeyBinding binding(DemoState demo, int keyCode) {
        for (KeyBinding binding : demo.getKeys().getBindings()) {
            for (int k = 0; k < binding.countKeys(); ++k) {
                if (binding.getKeyCode(k) == keyCode) {
                    return binding;
                }
            }
        }
        throw new IllegalStateException("no binding for key " + keyCode);
    }
}

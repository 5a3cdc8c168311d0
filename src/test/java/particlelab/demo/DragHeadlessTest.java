package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.reference.ExactPath;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.DragDemo;
import particlelab.physics.Gravity;
import particlelab.view.ScreenRect;

/**
 * A drag on DragDemo in a real headless application, with the window's framed camera: the
 * exact ghosts start from the dragged launch (the gravity-only one is the parabola of the new
 * P0 and V0), the flight the drag ended is kept as a shot, and the inspector a click opens
 * shows the picked sphere without covering any other text.
 */
class DragHeadlessTest {

    private static final float H = 1f / 60f;
    private static final DragDemo drag = new DragDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(drag));

    @Test
    void theGhostsAndKeptShotsFollowTheDraggedLaunch() throws Exception {
        double[] result = harness.call(() -> {
            drag.restart();
            HeadlessHarness.fly(drag, 40, H);
            int kept = ((DemoState) drag).getParameterControls().getKeptShots().countKept();
            Camera camera = harness.app().getCamera();
            DemoParticle first = drag.getParticles().get(0);
            DemoParticle quadratic = drag.getParticles().get(2);
            DragControl drags = drag.getDragControl();
            // The launch point: drag it right and up, then the arrow's tip left and up.
            Vector3f screen = camera.getScreenCoordinates(first.getParticle().position);
            drags.press(camera, screen.x, screen.y);
            drags.move(camera, screen.x + 70f, screen.y + 40f);
            drags.release();
            int keptAfterDrag = ((DemoState) drag).getParameterControls().getKeptShots()
                    .countKept();
            Vector3f tip = DragControl.copyGripPoint(Draggable.Grip.ARROW_TIP, first,
                    new Vector3f());
            Vector3f tipScreen = camera.getScreenCoordinates(tip);
            drags.press(camera, tipScreen.x, tipScreen.y);
            drags.move(camera, tipScreen.x - 50f, tipScreen.y + 30f);
            drags.release();
            Vector3f v0 = first.copyLaunchVelocity(new Vector3f());
            Vector3f p0 = first.copyLaunchPosition(new Vector3f());
            HeadlessHarness.fly(drag, 30, H);
            ExactPath ghost = ((DemoState) drag).getExactGhosts().getPath(0);
            ExactPath quadraticGhost = ((DemoState) drag).getExactGhosts().getPath(2);
            return new double[] {kept, keptAfterDrag, v0.x, v0.y, p0.x, p0.y,
                ghost.getTimeSeconds(), ghost.getPosition(0), ghost.getPosition(1),
                quadraticGhost.distanceTo(quadratic.getParticle().position),
                drag.getClock().getSimulatedSeconds()};
        });
        // The flight the first drag ended became a kept shot; the second, at t = 0, none.
        assertEquals(result[0] + 1, result[1]);
        double t = result[6];
        assertEquals(result[10], t, 1e-9);
        assertTrue(t > 0.4, "flew " + t + " s");
        // The arrow tip moved 50 px left and 30 px up: V0 turned away from (10, 10) m/s.
        assertTrue(result[2] < 10.0 && result[3] > 10.0, result[2] + ", " + result[3]);
        assertTrue(result[4] > 0.5 && result[5] > 0.5, "P0 " + result[4] + ", " + result[5]);
        // x = x0 + vx·t, y = y0 + vy·t − g·t²/2, in double from the float launch: the ghost
        // is the closed form of the new launch, to double round-off of numbers of 10 m.
        assertEquals(result[4] + result[2] * t, result[7], 1e-9);
        assertEquals(result[5] + result[3] * t - 0.5 * Gravity.STANDARD_G * t * t, result[8],
                1e-9);
        // The quadratic-drag ghost flies from the same launch: the Euler sphere within O(h)
        // of it, 0.17 m at h = 1/60 s after some 0.5 s (ExactGhostsHeadlessTest's bound).
        assertTrue(result[9] < 0.17, "Euler to exact " + result[9] + " m");
    }

    @Test
    void aClickOpensTheInspectorWhichCoversNoOtherText() throws Exception {
        List<String> problems = harness.call(() -> {
            drag.restart();
            HeadlessHarness.fly(drag, 20, H);
            drag.getClock().setPaused(true);
            Camera camera = harness.app().getCamera();
            DemoParticle quadratic = drag.getParticles().get(2);
            Vector3f screen = camera.getScreenCoordinates(quadratic.getParticle().position);
            DragControl drags = drag.getDragControl();
            drags.press(camera, screen.x, screen.y);
            drags.release();
            drag.update(H);
            List<String> found = new ArrayList<>();
            if (drags.getPicked() != quadratic) {
                found.add("picked " + drags.getPicked());
            }
            List<ScreenRect> rects = drag.getWindow().copyTextRects(new ArrayList<>());
            ScreenRect box = ((DemoState) drag).getMouse().getInspectorRect();
            if (box.isEmpty()) {
                found.add("the inspector is not shown");
            }
            for (int i = 0; i < rects.size(); ++i) {
                for (int j = i + 1; j < rects.size(); ++j) {
                    if (rects.get(i).intersects(rects.get(j))) {
                        found.add(rects.get(i) + " x " + rects.get(j));
                    }
                }
            }
            if (!drag.getHud().getLayout().getScene().contains(box)) {
                found.add("inspector " + box + " outside the scene "
                        + drag.getHud().getLayout().getScene());
            }
            String text = ((DemoState) drag).getMouse().formatInspector(new StringBuilder())
                    .toString();
            if (!text.startsWith(quadratic.getLabel() + "\n")) {
                found.add("inspector shows " + text);
            }
            drags.clearPick();
            drag.update(H);
            if (!((DemoState) drag).getMouse().getInspectorRect().isEmpty()) {
                found.add("the inspector stayed after the pick was cleared");
            }
            return found;
        });
        assertEquals(List.of(), problems);
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.reference.ExactPath;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.DragDemo;
import particlelab.physics.Gravity;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;

/**
 * A drag on DragDemo in a real headless application, with the window's framed camera: the
 * exact ghosts start from the dragged launch (the gravity-only one is the parabola of the new
 * P0 and V0), the flight the drag ended is kept as a shot, and the inspector a click opens
 * shows the picked sphere without covering any other text. A launch changed (by a drag or
 * the panel) is framed by the camera: its whole flight stays in the scene.
 */
class DragHeadlessTest {

    private static final float H = 1f / 60f;
    private static final Vector3f LECTURE_V0 = new Vector3f(10f, 10f, 0f);
    private static final DragDemo drag = new DragDemo();
    /** Demos of their own whose launches are changed to be framed. */
    private static final GravitationalPullDemo framedPull = new GravitationalPullDemo();
    private static final DragDemo framedDrag = new DragDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(
            () -> List.of(drag, framedPull, framedDrag));

    @Test
    void theGhostsAndKeptShotsFollowTheDraggedLaunch() throws Exception {
        double[] result = harness.call(() -> {
            drag.restart();
            HeadlessHarness.fly(drag, 40, H);
            int kept = ((DemoState) drag).getParameterControls().getKeptShots().countKept();
            Camera camera = harness.app().getCamera();
            DemoParticle first = drag.getParticles().get(0);
            DemoParticle quadratic = drag.getParticles().get(2);
            DragControl drags = drag.getWindow().getDragControl();
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
            DragControl drags = drag.getWindow().getDragControl();
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
            if (!drag.getWindow().getHud().getLayout().getScene().contains(box)) {
                found.add("inspector " + box + " outside the scene "
                        + drag.getWindow().getHud().getLayout().getScene());
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

    /**
     * The camera frames what the launch reaches: the lecture's launch keeps the declared
     * view, a higher or longer one zooms out until its whole flight stays in the scene's
     * area, and going back to the lecture's launch frames the declared view again.
     */
    @Test
    void aHigherLaunchZoomsOutAndItsWholeFlightStaysInTheScene() throws Exception {
        DemoState pull = framedPull;
        List<String> problems = harness.call(() -> {
            List<String> found = new ArrayList<>();
            DemoParticle ball = pull.getParticles().get(0);
            pull.restart();
            float lecturePixelsPerMetre = pull.getWindow().getPlaneView().getPixelsPerMetre();
            // Apex vy²/2g = 20.4 m, range 2·vx·vy/g = 81.6 m: four times the lecture's.
            ball.setLaunch(Vector3f.ZERO, new Vector3f(20f, 20f, 0f));
            pull.restart();
            float higherPixelsPerMetre = pull.getWindow().getPlaneView().getPixelsPerMetre();
            if (!(higherPixelsPerMetre < 0.5f * lecturePixelsPerMetre)) {
                found.add("no zoom out: " + lecturePixelsPerMetre + " then "
                        + higherPixelsPerMetre + " px/m");
            }
            found.addAll(flyInsideScene(pull, ball, 600));
            ball.setLaunch(Vector3f.ZERO, LECTURE_V0);
            pull.restart();
            assertEquals(lecturePixelsPerMetre, pull.getWindow().getPlaneView().getPixelsPerMetre(),
                    "back to the lecture's launch, back to the declared view");
            return found;
        });
        assertEquals(List.of(), problems);
    }

    @Test
    void eachDragBallsLongerFlightIsFramedAtItsLaunch() throws Exception {
        DemoState drag = framedDrag;
        List<String> problems = harness.call(() -> {
            List<DemoParticle> balls = drag.getParticles();
            for (DemoParticle ball : balls) {
                ball.setLaunch(Vector3f.ZERO, new Vector3f(25f, 15f, 0f));
            }
            drag.restart();
            List<String> found = flyInsideScene(drag, balls.get(0), 600);
            for (DemoParticle ball : balls) {
                ball.setLaunch(Vector3f.ZERO, LECTURE_V0);
            }
            drag.restart();
            return found;
        });
        assertEquals(List.of(), problems);
    }

    /** Step a demo until the ball lands, checking its sphere stays in the scene's area. */
    private static List<String> flyInsideScene(DemoState demo, DemoParticle ball, int frames) {
        List<String> found = new ArrayList<>();
        ScreenRect area = demo.getWindow().getHud().getLayout().getScene();
        for (int frame = 0; frame < frames && !ball.hasLanded(); ++frame) {
            demo.update(H);
            PlaneView plane = demo.getWindow().getPlaneView();
            Vector3f p = ball.getParticle().position;
            float radius = demo.getWindow().getView(ball).getRadius() * plane.getPixelsPerMetre();
            ScreenRect sphere = new ScreenRect(plane.screenX(p.x) - radius,
                    plane.screenY(p.y) - radius, 2f * radius, 2f * radius);
            if (!area.contains(sphere)) {
                found.add(demo.getTitle() + " frame " + frame + ": ball " + sphere
                        + " leaves " + area);
                break;
            }
        }
        assertTrue(ball.hasLanded(), demo.getTitle() + ": the ball did not land");
        return found;
    }
}

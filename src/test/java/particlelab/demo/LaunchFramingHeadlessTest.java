package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.DragDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;

/**
 * The camera frames what the launch reaches: the lecture's launch keeps the declared view, a
 * higher or longer one zooms out until its whole flight stays in the scene's area, and going
 * back to the lecture's launch frames the declared view again.
 */
class LaunchFramingHeadlessTest {

    private static final float H = 1f / 60f;
    private static final Vector3f LECTURE_V0 = new Vector3f(10f, 10f, 0f);
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(
            () -> List.of(new GravitationalPullDemo(), new DragDemo()));

    @Test
    void aHigherLaunchZoomsOutAndItsWholeFlightStaysInTheScene() throws Exception {
        DemoState pull = harness.app().getSwitcher().getDemos().get(0);
        List<String> problems = harness.call(() -> {
            List<String> found = new ArrayList<>();
            DemoParticle ball = pull.getParticles().get(0);
            pull.restart();
            float lecturePixelsPerMetre = pull.getPlaneView().getPixelsPerMetre();
            // Apex vy²/2g = 20.4 m, range 2·vx·vy/g = 81.6 m: four times the lecture's.
            ball.setLaunch(Vector3f.ZERO, new Vector3f(20f, 20f, 0f));
            pull.restart();
            float higherPixelsPerMetre = pull.getPlaneView().getPixelsPerMetre();
            if (!(higherPixelsPerMetre < 0.5f * lecturePixelsPerMetre)) {
                found.add("no zoom out: " + lecturePixelsPerMetre + " then "
                        + higherPixelsPerMetre + " px/m");
            }
            found.addAll(flyInsideScene(pull, ball, 600));
            ball.setLaunch(Vector3f.ZERO, LECTURE_V0);
            pull.restart();
            assertEquals(lecturePixelsPerMetre, pull.getPlaneView().getPixelsPerMetre(),
                    "back to the lecture's launch, back to the declared view");
            return found;
        });
        assertEquals(List.of(), problems);
    }

    @Test
    void eachDragBallsLongerFlightIsFramedAtItsLaunch() throws Exception {
        DemoState drag = harness.app().getSwitcher().getDemos().get(1);
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
        ScreenRect area = demo.getHud().getLayout().getScene();
        for (int frame = 0; frame < frames && !ball.hasLanded(); ++frame) {
            demo.update(H);
            PlaneView plane = demo.getPlaneView();
            Vector3f p = ball.getParticle().position;
            float radius = demo.getView(ball).getRadius() * plane.getPixelsPerMetre();
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

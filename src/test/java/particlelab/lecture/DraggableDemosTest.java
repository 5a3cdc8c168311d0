package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.DragControl;
import particlelab.demo.Draggable;

/**
 * The drags the collisions and height demos declare, simulated in plain JUnit through a jME
 * {@link Camera} looking straight at the plane (a pixel is {@code D·tan(fov/2)/(H/2)} metres
 * of it): a ball's start and start velocity, and the target, which snaps to the metre and
 * fires both solutions again without pausing.
 */
class DraggableDemosTest {

    private static final int WIDTH = 1280;
    private static final int HEIGHT = 720;
    private static final float FIELD_OF_VIEW_DEGREES = 45f;
    private static final float H = 1f / 60f;

    @Test
    void aDraggedBallStartsThereAndStaysInsideTheBox() {
        CollisionsDemo demo = new CollisionsDemo();
        Camera camera = faceOn(6f, 3f, 20f);
        float metresPerPixel = metresPerPixel(20f);
        DemoParticle ball = demo.getParticles().get(0);
        Vector3f start = ball.copyLaunchPosition(new Vector3f());
        Vector3f screen = camera.getScreenCoordinates(start);
        DragControl drags = demo.getWindow().getDragControl();
        assertTrue(drags.press(camera, screen.x, screen.y));
        assertSame(Draggable.Grip.BODY, drags.getHeld().getGrip());
        drags.move(camera, screen.x + 30f, screen.y + 45f);
        drags.release();
        Vector3f launch = ball.copyLaunchPosition(new Vector3f());
        // The projection's float round-off at 20 m, some 1e-6 relative.
        assertEquals(start.x + 30f * metresPerPixel, launch.x, 1e-4f);
        assertEquals(start.y + 45f * metresPerPixel, launch.y, 1e-4f);
        assertEquals(launch, ball.getParticle().position);
        assertTrue(demo.getClock().isPaused());
        // Only the ball dragged moved: ball 2 starts where the preset put it.
        assertEquals(8f, demo.getParticles().get(1).copyLaunchPosition(new Vector3f()).x);

        // Far beyond the right wall and under the floor: held inside the box, a radius in.
        screen = camera.getScreenCoordinates(ball.getParticle().position);
        drags.press(camera, screen.x, screen.y);
        drags.move(camera, WIDTH - 1f, 1f);
        drags.release();
        launch = ball.copyLaunchPosition(new Vector3f());
        assertEquals(13f - CollisionsDemo.RADIUS, launch.x);
        assertEquals(CollisionsDemo.RADIUS, launch.y);
    }

    @Test
    void aBallsArrowTipSetsItsStartVelocity() {
        CollisionsDemo demo = new CollisionsDemo();
        Camera camera = faceOn(6f, 3f, 20f);
        float metresPerPixel = metresPerPixel(20f);
        DemoParticle ball = demo.getParticles().get(0);
        Vector3f tip = DragControl.copyGripPoint(Draggable.Grip.ARROW_TIP, ball,
                new Vector3f());
        Vector3f screen = camera.getScreenCoordinates(tip);
        DragControl drags = demo.getWindow().getDragControl();
        assertTrue(drags.press(camera, screen.x, screen.y));
        assertSame(Draggable.Grip.ARROW_TIP, drags.getHeld().getGrip());
        drags.move(camera, screen.x - 20f, screen.y + 40f);
        drags.release();
        Vector3f start = ball.copyLaunchPosition(new Vector3f());
        Vector3f expected = new Vector3f(tip.x - 20f * metresPerPixel,
                tip.y + 40f * metresPerPixel, 0f).subtractLocal(start).divideLocal(0.4f);
        Vector3f velocity = ball.copyLaunchVelocity(new Vector3f());
        // The tip's round-off (1e-4 m) over the arrow's 0.4 s.
        assertEquals(expected.x, velocity.x, 1e-3f);
        assertEquals(expected.y, velocity.y, 1e-3f);
        assertEquals(velocity, ball.getParticle().velocity);
    }

    @Test
    void theDraggedTargetSnapsToTheMetreAndBothShotsFireAgainWhileRunning() {
        AnyHeightDemo demo = new AnyHeightDemo();
        Camera camera = faceOn(25f, 14f, 60f);
        float metresPerPixel = metresPerPixel(60f);
        for (int i = 0; i < 30; ++i) {
            demo.getRun().advancePhysics(H);
        }
        DemoParticle target = find(demo, "target");
        Vector3f before = new Vector3f(target.getParticle().position);
        Vector3f screen = camera.getScreenCoordinates(before);
        DragControl drags = demo.getWindow().getDragControl();
        assertTrue(drags.press(camera, screen.x, screen.y));
        // 5.3 m left and 2.6 m up: the target goes to the nearest metre, 5 m and 3 m away.
        drags.move(camera, screen.x - 5.3f / metresPerPixel, screen.y + 2.6f / metresPerPixel);
        drags.release();
        assertEquals(before.x - 5f, target.getParticle().position.x);
        assertEquals(before.y + 3f, target.getParticle().position.y);
        assertFalse(demo.getClock().isPaused());
        // Fired again at once: the two shots are back at the muzzle at t = 0 of their flight.
        for (DemoParticle shot : demo.getParticles()) {
            if (shot != target && !shot.isParked()) {
                assertEquals(0.0, shot.getFlightSeconds());
                assertEquals(new Vector3f(0f, AnyHeightDemo.GUN_HEIGHT, 0f),
                        shot.getParticle().position);
            }
        }
    }

    private static DemoParticle find(DemoState demo, String label) {
        for (DemoParticle particle : demo.getParticles()) {
            if (particle.getLabel().equals(label)) {
                return particle;
            }
        }
        throw new IllegalStateException("no particle " + label);
    }

    private static float metresPerPixel(float distance) {
        return distance * FastMath.tan(FastMath.DEG_TO_RAD * FIELD_OF_VIEW_DEGREES / 2f)
                / (HEIGHT / 2f);
    }

    /** A camera at a distance in front of the plane, looking straight at (x, y, 0). */
    private static Camera faceOn(float x, float y, float distance) {
        Camera camera = new Camera(WIDTH, HEIGHT);
        camera.setFrustumPerspective(FIELD_OF_VIEW_DEGREES, (float) WIDTH / HEIGHT, 1f, 1000f);
        camera.setLocation(new Vector3f(x, y, distance));
        camera.lookAt(new Vector3f(x, y, 0f), Vector3f.UNIT_Y);
        return camera;
    }
}

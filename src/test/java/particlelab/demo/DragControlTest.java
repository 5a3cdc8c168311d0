package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.lecture.DragDemo;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.ParticleView;
import particlelab.view.TextFormat;

/**
 * A simulated drag on a demo in plain JUnit (no application): a press at a body's projected
 * screen point, a move of some pixels, a release, through a jME {@link Camera} looking
 * straight at the plane, whose closed form (a pixel is {@code D·tan(fov/2)/(H/2)} metres of
 * the plane) gives the point under the mouse independently of the picking code.
 */
class DragControlTest {

    private static final int WIDTH = 1280;
    private static final int HEIGHT = 720;
    private static final float FIELD_OF_VIEW_DEGREES = 45f;
    private static final float DISTANCE = 30f;
    private static final Vector3f LOOK_AT = new Vector3f(11f, 3f, 0f);
    /** The plane's metres per screen pixel, face on from {@link #DISTANCE}. */
    private static final float METRES_PER_PIXEL = DISTANCE
            * FastMath.tan(FastMath.DEG_TO_RAD * FIELD_OF_VIEW_DEGREES / 2f) / (HEIGHT / 2f);
    /**
     * Positions: float round-off of the camera's projection and its inverse for points some
     * 30 m from the eye, about 1e-6 relative (a thousandth of a pixel).
     */
    private static final float POSITION_TOLERANCE = 1e-4f;
    private static final float H = 1f / 60f;

    private final Camera camera = faceOnCamera();

    @Test
    void draggingASphereMovesTheLaunchOfAllThreeToThePointUnderTheMouse() {
        DragDemo demo = new DragDemo();
        DragControl drags = demo.getWindow().getDragControl();
        Vector3f screen = camera.getScreenCoordinates(Vector3f.ZERO);
        assertTrue(drags.press(camera, screen.x, screen.y));
        assertSame(Draggable.Grip.BODY, drags.getHeld().getGrip());
        float dx = 80f;
        float dy = 50f;
        assertTrue(drags.move(camera, screen.x + dx, screen.y + dy));
        assertTrue(drags.release());

        Vector3f expected = new Vector3f(dx * METRES_PER_PIXEL, dy * METRES_PER_PIXEL, 0f);
        Vector3f launch = new Vector3f();
        Vector3f velocity = new Vector3f();
        for (DemoParticle particle : demo.getParticles()) {
            assertVector(expected, particle.copyLaunchPosition(launch), POSITION_TOLERANCE);
            // The position drag leaves V0 as it was, to the bit.
            assertEquals(new Vector3f(10f, 10f, 0f), particle.copyLaunchVelocity(velocity));
            // The scene started again from the new launch, paused at t = 0.
            assertEquals(launch, particle.getParticle().position);
        }
        assertTrue(demo.getClock().isPaused());
        assertEquals(0.0, demo.getClock().getSimulatedSeconds());

        // One step from there, as N takes it: V1 = V0 + h·g, P1 = P0 + h·V1.
        demo.getClock().requestSingleStep();
        demo.getRun().advancePhysics(H);
        float h = demo.getClock().getStepSeconds();
        Vector3f p1 = demo.getParticles().get(0).getParticle().position;
        float v1y = 10f - h * Gravity.STANDARD_G;
        Vector3f p0 = demo.getParticles().get(0).copyLaunchPosition(new Vector3f());
        // The recipe's float operations from P0 ~ 3 m: a few ulps.
        assertEquals(p0.x + h * 10f, p1.x, 1e-5f);
        assertEquals(p0.y + h * v1y, p1.y, 1e-5f);
    }

    @Test
    void draggingAnArrowTipSetsTheLaunchVelocityThroughTheSpeedAndAngle() {
        DragDemo demo = new DragDemo();
        DragControl drags = demo.getWindow().getDragControl();
        DemoParticle first = demo.getParticles().get(0);
        Vector3f tip = DragControl.copyGripPoint(Draggable.Grip.ARROW_TIP, first,
                new Vector3f());
        // The arrow shows 0.4 s of travel: V0 = (10, 10) m/s ends at (4, 4) m.
        assertVector(new Vector3f(4f, 4f, 0f), tip, 1e-6f);
        Vector3f screen = camera.getScreenCoordinates(tip);
        assertTrue(drags.press(camera, screen.x, screen.y));
        assertSame(Draggable.Grip.ARROW_TIP, drags.getHeld().getGrip());
        float dx = 60f;
        float dy = -40f;
        drags.move(camera, screen.x + dx, screen.y + dy);
        drags.release();

        Vector3f newTip = new Vector3f(4f + dx * METRES_PER_PIXEL, 4f + dy * METRES_PER_PIXEL,
                0f);
        Vector3f expected = newTip.divide(ParticleView.ARROW_SECONDS);
        DemoParameters parameters = demo.getParameters();
        // The parameters hold |V| and its angle: the tip's float round-off over 0.4 s.
        assertEquals(expected.length(), parameters.getValue("speed"), 1e-3f);
        assertEquals(FastMath.RAD_TO_DEG * FastMath.atan2(expected.y, expected.x),
                parameters.getValue("angle"), 1e-3f);
        Vector3f velocity = new Vector3f();
        for (DemoParticle particle : demo.getParticles()) {
            // speed·(cos θ, sin θ) in double, from float speed and angle: 1e-6 relative of
            // 15 m/s, on top of the tip's round-off divided by 0.4 s.
            assertVector(expected, particle.copyLaunchVelocity(velocity), 1e-3f);
            assertEquals(velocity, particle.getParticle().velocity);
            assertEquals(Vector3f.ZERO, particle.getParticle().position);
        }
        assertTrue(demo.getClock().isPaused());
    }

    @Test
    void aClickOnAFlyingSpherePicksItForTheInspectorAndChangesNothing() {
        DragDemo demo = new DragDemo();
        for (int i = 0; i < 30; ++i) {
            demo.getRun().advancePhysics(H);
        }
        double seconds = demo.getClock().getSimulatedSeconds();
        DemoParticle linear = demo.getParticles().get(1);
        Vector3f screen = camera.getScreenCoordinates(linear.getParticle().position);
        DragControl drags = demo.getWindow().getDragControl();
        drags.press(camera, screen.x + 1f, screen.y);
        // A jitter below the drag's threshold is no drag.
        assertFalse(drags.move(camera, screen.x + 2f, screen.y + 1f));
        assertFalse(drags.release());
        assertSame(linear, drags.getPicked());
        assertFalse(demo.getClock().isPaused());
        assertEquals(seconds, demo.getClock().getSimulatedSeconds());
        assertEquals(Vector3f.ZERO, linear.copyLaunchPosition(new Vector3f()));

        String text = ((DemoState) demo).getMouse().formatInspector(new StringBuilder())
                .toString();
        Vector3f v = linear.getParticle().velocity;
        StringBuilder drag = new StringBuilder("linear drag -b V  F = (");
        // F = -b·V with b = 0.9 N·s/m, printed to 2 decimals as the box prints it.
        TextFormat.appendFixed(drag, -DragDemo.LINEAR_B * v.x, 2).append(", ");
        TextFormat.appendFixed(drag, -DragDemo.LINEAR_B * v.y, 2).append(") N");
        StringBuilder speed = new StringBuilder("|V| = ");
        TextFormat.appendFixed(speed, v.length(), 2);
        assertTrue(text.startsWith(linear.getLabel() + "\nP = ("), text);
        assertTrue(text.contains(speed), text);
        assertTrue(text.contains("m = 1.00 kg"), text);
        // Gravity's force is m·g: 1 kg · 9.8 m/s² down.
        assertTrue(text.contains("gravity m g  F = (0.00, -9.80) N"), text);
        assertTrue(text.contains(drag), text);

        // A press on empty space closes the inspector.
        assertFalse(drags.press(camera, 5f, HEIGHT - 5f));
        assertNull(drags.getPicked());
        assertEquals("", ((DemoState) demo).getMouse().formatInspector(new StringBuilder())
                .toString());
    }

    @Test
    void aLaunchDraggedBelowTheGroundStaysOnIt() {
        DragDemo demo = new DragDemo();
        DragControl drags = demo.getWindow().getDragControl();
        Vector3f screen = camera.getScreenCoordinates(Vector3f.ZERO);
        drags.press(camera, screen.x, screen.y);
        drags.move(camera, screen.x + 40f, screen.y - 100f);
        Vector3f launch = demo.getParticles().get(2).copyLaunchPosition(new Vector3f());
        assertEquals(40f * METRES_PER_PIXEL, launch.x, POSITION_TOLERANCE);
        assertEquals(0f, launch.y);
    }

    @Test
    void theDeclarationsOfTheFreeFlightDemosOfferTheLaunch() {
        DragDemo demo = new DragDemo();
        List<Draggable> declared = demo.getWindow().getDragControl().getDraggables();
        assertEquals(2, declared.size());
        assertEquals("drag a sphere", declared.get(0).getGestureLabel());
        assertEquals("drag a sphere's arrow tip", declared.get(1).getGestureLabel());
        assertEquals(Draggable.Effect.LAUNCH, declared.get(1).getEffect());
        assertFalse(declared.get(0).isDraggableWhileRunning());
        // The three spheres and the comparison lane's (parked: the help counts the shown).
        assertEquals(4, declared.get(0).getParticles().size());
        List<String[]> rows = DragControl.helpRows(declared);
        // The sphere and its arrow tip share the help's first row; the click is the second.
        assertEquals(2, rows.size());
        assertEquals("drag a sphere / its arrow tip", rows.get(0)[0]);
        assertEquals("launch P0 of all 3 / launch V0 of all 3 = speed, angle"
                + Draggable.PAUSED_NOTE, rows.get(0)[1]);
        assertEquals(DragControl.CLICK_GESTURE, rows.get(1)[0]);
    }

    @Test
    void badDeclarationsAreRefusedWithTheirName() {
        DragDemo demo = new DragDemo();
        DragDemo other = new DragDemo();
        Draggable foreign = Draggable.launchPosition("a sphere", other.getParticles());
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> demo.getWindow().getDragControl().add(foreign));
        assertTrue(refused.getMessage().contains("is not the demo's"), refused.getMessage());
        IllegalArgumentException empty = assertThrows(IllegalArgumentException.class,
                () -> Draggable.launchPosition("nothing", List.of()));
        assertTrue(empty.getMessage().contains("at least one particle"), empty.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Draggable("", Draggable.Grip.BODY,
                Draggable.Effect.STATE, demo.getParticles(), "x", true, (p, v) -> { }));
    }

    /** A demo of one particle with no declaration: a click still inspects it. */
    @Test
    void aDemoThatDeclaresNothingStillInspects() {
        DemoState bare = new DemoState("bare") {
            @Override
            protected void createScene() {
                addParticle("ball", ColorRGBA.White, new Vector3f(3f, 2f, 0f),
                        new Vector3f(1f, 0f, 0f), 2f, new ParticleIntegrator());
            }
        };
        Vector3f screen = camera.getScreenCoordinates(new Vector3f(3f, 2f, 0f));
        assertTrue(bare.getWindow().getDragControl().press(camera, screen.x, screen.y));
        assertNull(bare.getWindow().getDragControl().getHeld());
        assertEquals("ball\nP = (3.00, 2.00) m\nV = (1.00, 0.00) m/s   |V| = 1.00 m/s\n"
                + "m = 2.00 kg\nno force",
                bare.getMouse().formatInspector(new StringBuilder()).toString());
    }

    private static void assertVector(Vector3f expected, Vector3f actual, float tolerance) {
        assertEquals(expected.x, actual.x, tolerance, "x of " + actual);
        assertEquals(expected.y, actual.y, tolerance, "y of " + actual);
        assertEquals(expected.z, actual.z, tolerance, "z of " + actual);
    }

    private static Camera faceOnCamera() {
        Camera camera = new Camera(WIDTH, HEIGHT);
        camera.setFrustumPerspective(FIELD_OF_VIEW_DEGREES, (float) WIDTH / HEIGHT, 1f, 1000f);
        camera.setLocation(new Vector3f(LOOK_AT.x, LOOK_AT.y, DISTANCE));
        camera.lookAt(LOOK_AT, Vector3f.UNIT_Y);
        return camera;
    }
}

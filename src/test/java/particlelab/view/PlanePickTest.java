package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.FastMath;
import com.jme3.math.Vector2f;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import org.junit.jupiter.api.Test;

/**
 * The screen point to plane point mapping of picking, with a jME {@link Camera} and no
 * application: against the pinhole camera's closed form, round trips through the projection,
 * a turned camera, and the rays that miss.
 */
class PlanePickTest {

    private static final int WIDTH = 1280;
    private static final int HEIGHT = 720;
    private static final float FIELD_OF_VIEW_DEGREES = 45f;
    /** The camera's distance from the plane z = 0 (m). */
    private static final float DISTANCE = 30f;
    private static final Vector3f LOOK_AT = new Vector3f(10f, 3f, 0f);

    private final PlanePick pick = new PlanePick();

    @Test
    void aPointOfTheScreenMeetsThePlaneWhereThePinholeCameraSaysSo() {
        Camera camera = faceOnCamera();
        // Looking straight down -z from distance D, a pixel off the centre is
        // D·tan(fov/2)/(H/2) metres of the plane, the same along x and y (square pixels).
        float metresPerPixel = DISTANCE * FastMath.tan(FastMath.DEG_TO_RAD
                * FIELD_OF_VIEW_DEGREES / 2f) / (HEIGHT / 2f);
        float[][] points = {{640f, 360f}, {0f, 0f}, {1280f, 720f}, {123.5f, 601.25f}};
        Vector3f hit = new Vector3f();
        for (float[] screen : points) {
            assertTrue(pick.screenToPlane(camera, screen[0], screen[1], 0f, hit));
            // Float round-off of the view-projection inverse, some 1e-6 of the 30 m distance
            // (a thousandth of a pixel here, 0.035 m per pixel).
            assertEquals(LOOK_AT.x + (screen[0] - WIDTH / 2f) * metresPerPixel, hit.x, 1e-4f);
            assertEquals(LOOK_AT.y + (screen[1] - HEIGHT / 2f) * metresPerPixel, hit.y, 1e-4f);
            assertEquals(0f, hit.z);
        }
    }

    @Test
    void theProjectionOfAPlanePointPicksThatPointBackEvenWithATurnedCamera() {
        Camera turned = faceOnCamera();
        // The right button turns the camera: the plane is then seen at a slant.
        turned.setLocation(new Vector3f(-8f, 12f, 22f));
        turned.lookAt(LOOK_AT, Vector3f.UNIT_Y);
        Vector3f[] points = {new Vector3f(0f, 0f, 0f), new Vector3f(10f, 3f, 0f),
            new Vector3f(21.5f, 6.25f, 0f), new Vector3f(-1f, 0.5f, 0f)};
        Vector2f screen = new Vector2f();
        Vector3f hit = new Vector3f();
        for (Camera camera : new Camera[] {faceOnCamera(), turned}) {
            for (Vector3f point : points) {
                pick.planeToScreen(camera, point, screen);
                assertTrue(pick.screenToPlane(camera, screen.x, screen.y, 0f, hit));
                // Two float projections of points some 30 m away: 1e-6 relative, 1e-4 m.
                assertEquals(point.x, hit.x, 1e-4f, point + " x");
                assertEquals(point.y, hit.y, 1e-4f, point + " y");
            }
        }
    }

    @Test
    void aPlaneAtAnotherDepthIsMetThere() {
        Camera camera = faceOnCamera();
        Vector3f hit = new Vector3f();
        assertTrue(pick.screenToPlane(camera, WIDTH, HEIGHT / 2f, 10f, hit));
        // 10 m nearer the eye: the same pixel is 20/30 of the way out from the centre line.
        float halfWidthAtPlane = (DISTANCE - 10f) * FastMath.tan(FastMath.DEG_TO_RAD
                * FIELD_OF_VIEW_DEGREES / 2f) * WIDTH / HEIGHT;
        assertEquals(LOOK_AT.x + halfWidthAtPlane, hit.x, 1e-4f);
        assertEquals(10f, hit.z);
    }

    @Test
    void raysAlongThePlaneOrAwayFromItMissAndLeaveTheResultAlone() {
        Camera camera = faceOnCamera();
        // Looking along the plane: every ray runs parallel to z = 0 at the centre.
        camera.setLocation(new Vector3f(0f, 1f, 0f));
        camera.lookAt(new Vector3f(30f, 1f, 0f), Vector3f.UNIT_Y);
        Vector3f hit = new Vector3f(7f, 7f, 7f);
        assertFalse(pick.screenToPlane(camera, WIDTH / 2f, HEIGHT / 2f, 0f, hit));
        assertEquals(new Vector3f(7f, 7f, 7f), hit);
        // A plane behind the eye.
        assertFalse(pick.screenToPlane(faceOnCamera(), WIDTH / 2f, HEIGHT / 2f, 40f, hit));
        assertEquals(new Vector3f(7f, 7f, 7f), hit);
    }

    @Test
    void screenDistancesArePixels() {
        Camera camera = faceOnCamera();
        float metresPerPixel = DISTANCE * FastMath.tan(FastMath.DEG_TO_RAD
                * FIELD_OF_VIEW_DEGREES / 2f) / (HEIGHT / 2f);
        Vector3f a = new Vector3f(LOOK_AT);
        Vector3f b = new Vector3f(LOOK_AT).addLocal(100f * metresPerPixel, 0f, 0f);
        // 100 pixels to float round-off of the projection (1e-3 pixel).
        assertEquals(100f, pick.screenDistance(camera, a, b), 1e-2f);
        assertEquals(5f, pick.screenDistance(camera, a, WIDTH / 2f + 3f, HEIGHT / 2f + 4f),
                1e-2f);
    }

    /** A camera 30 m in front of the plane, looking straight at (10, 3, 0). */
    private static Camera faceOnCamera() {
        Camera camera = new Camera(WIDTH, HEIGHT);
        camera.setFrustumPerspective(FIELD_OF_VIEW_DEGREES, (float) WIDTH / HEIGHT, 1f, 1000f);
        camera.setLocation(new Vector3f(LOOK_AT.x, LOOK_AT.y, DISTANCE));
        camera.lookAt(LOOK_AT, Vector3f.UNIT_Y);
        return camera;
    }
}

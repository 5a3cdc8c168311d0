package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import org.junit.jupiter.api.Test;

/**
 * From a screen point to the nearest step dot ({@link StepDotPick}), with a jME
 * {@link Camera} and no application: the steps of the lecture's launch under gravity,
 * projected by the pinhole camera's closed form, each picked back from its own pixel and
 * from a point between two dots; nothing beyond the radius; the earlier of two equal dots.
 */
class StepDotPickTest {

    private static final int WIDTH = 1280;
    private static final int HEIGHT = 720;
    private static final float FIELD_OF_VIEW_DEGREES = 45f;
    /** The camera's distance from the plane z = 0 (m): the launch's 100 m fill the view. */
    private static final float DISTANCE = 90f;
    private static final Vector3f LOOK_AT = new Vector3f(50f, 15f, 0f);
    private static final float H = 1f / 60f;
    private static final float G = 9.8f;
    private static final int STEPS = 300;

    private final StepDotPick pick = new StepDotPick();

    private static Camera faceOnCamera() {
        Camera camera = new Camera(WIDTH, HEIGHT);
        camera.setFrustumPerspective(FIELD_OF_VIEW_DEGREES, (float) WIDTH / HEIGHT, 1f, 1000f);
        camera.setLocation(new Vector3f(LOOK_AT.x, LOOK_AT.y, DISTANCE));
        camera.lookAt(LOOK_AT, Vector3f.UNIT_Y);
        return camera;
    }

    /** The lecture's step from (0, 0) at (20, 24.58) m/s: x_n = n·h·vx, y_n as stepped. */
    private static float[] launch() {
        float[] positions = new float[3 * STEPS];
        float x = 0f;
        float y = 0f;
        float vy = 24.58f;
        for (int n = 0; n < STEPS; ++n) {
            positions[3 * n] = x;
            positions[3 * n + 1] = y;
            vy += H * -G;
            x += H * 20f;
            y += H * vy;
        }
        return positions;
    }

    /** Where the face-on pinhole camera draws a point of the plane z = 0 (pixels). */
    private static float[] screenOf(float x, float y) {
        float pixelsPerMetre = (HEIGHT / 2f) / (DISTANCE * FastMath.tan(FastMath.DEG_TO_RAD
                * FIELD_OF_VIEW_DEGREES / 2f));
        return new float[] {WIDTH / 2f + (x - LOOK_AT.x) * pixelsPerMetre,
            HEIGHT / 2f + (y - LOOK_AT.y) * pixelsPerMetre};
    }

    @Test
    void eachDotIsPickedFromItsOwnPixel() {
        Camera camera = faceOnCamera();
        float[] positions = launch();
        for (int n = 0; n < STEPS; n += 7) {
            float[] screen = screenOf(positions[3 * n], positions[3 * n + 1]);
            // the dots are 3 to 5 px apart here (|V|·h from 0.33 to 0.53 m at 9.7 px/m): a
            // press on a dot's own pixel is nearer it than the next by half of that, far more
            // than the projection's float round-off (a thousandth of a pixel, PlanePickTest)
            assertEquals(n, pick.nearest(camera, positions, STEPS, screen[0], screen[1], 12f),
                    "step " + n);
        }
    }

    @Test
    void aPressBetweenTwoDotsPicksTheNearer() {
        Camera camera = faceOnCamera();
        float[] positions = launch();
        int n = 100;
        float[] here = screenOf(positions[3 * n], positions[3 * n + 1]);
        float[] next = screenOf(positions[3 * n + 3], positions[3 * n + 4]);
        // a quarter of the way to the next dot: still n; three quarters: n + 1
        assertEquals(n, pick.nearest(camera, positions, STEPS, here[0] + 0.25f
                * (next[0] - here[0]), here[1] + 0.25f * (next[1] - here[1]), 12f));
        assertEquals(n + 1, pick.nearest(camera, positions, STEPS, here[0] + 0.75f
                * (next[0] - here[0]), here[1] + 0.75f * (next[1] - here[1]), 12f));
    }

    @Test
    void aPressBeyondTheRadiusPicksNothing() {
        Camera camera = faceOnCamera();
        float[] positions = launch();
        // the apex is at about y = 30.8 m: 20 m above it no dot is within 12 px (190 px away)
        float[] sky = screenOf(50f, 50.8f);
        assertEquals(-1, pick.nearest(camera, positions, STEPS, sky[0], sky[1], 12f));
        // and none at all of an empty run
        assertEquals(-1, pick.nearest(camera, positions, 0, sky[0], sky[1], 12f));
    }

    @Test
    void ofTwoDotsAtTheSamePlaceTheEarlierStepWins() {
        Camera camera = faceOnCamera();
        // a sphere at rest: the same place three steps running
        float[] positions = {10f, 0f, 0f, 20f, 0f, 0f, 20f, 0f, 0f, 20f, 0f, 0f};
        float[] screen = screenOf(20f, 0f);
        assertEquals(1, pick.nearest(camera, positions, 4, screen[0], screen[1], 12f));
    }

    @Test
    void aCountBeyondTheArrayIsRefused() {
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> pick.nearest(faceOnCamera(), new float[6], 3, 0f, 0f, 12f));
        assertEquals("count must be from 0 to 2, but was 3", refused.getMessage());
    }
}

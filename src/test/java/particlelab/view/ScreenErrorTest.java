package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import org.junit.jupiter.api.Test;

/**
 * The error as the viewer sees it: {@link ScreenError}'s pixels against the projection the
 * demos' camera makes, computed here with jME's own {@code Camera} (no application).
 */
class ScreenErrorTest {

    /** The drag demo's region in a 1280x720 window's scene area (metres, pixels). */
    private static PlaneView dragView() {
        ScreenRect area = new ScreenRect().set(20f, 60f, 1240f, 420f);
        return new PlaneView().fit(-2f, 24f, -1f, 7f, area, 1280f, 720f);
    }

    @Test
    void pixelsAreTheCamerasProjectedDistance() {
        PlaneView view = dragView();
        Camera camera = new Camera(1280, 720);
        CameraFraming.frame(camera, view);
        Vector3f exact = new Vector3f(12.25f, 3.5f, 0f);
        Vector3f[] drawn = {new Vector3f(12.25f, 3.0f, 0f), new Vector3f(12.6f, 3.8f, 0f),
            new Vector3f(0.5f, 0.25f, 0f), new Vector3f(12.2501f, 3.5f, 0f)};
        Vector3f a = new Vector3f();
        Vector3f b = new Vector3f();
        for (Vector3f point : drawn) {
            camera.getScreenCoordinates(point, a);
            camera.getScreenCoordinates(exact, b);
            double projected = Math.hypot(a.x - b.x, a.y - b.y);
            double pixels = ScreenError.pixels(view, point.x - exact.x, point.y - exact.y);
            // The camera projects in float: screen coordinates near 1000 px carry ~1e-4 px
            // of round-off each, and the perspective of a plane seen face-on is exact; 2e-3
            // px covers that with room, far below the 1 px threshold the readout uses.
            assertEquals(projected, pixels, 2e-3, "at " + point);
        }
    }

    @Test
    void pixelsScaleWithTheMetresAndKeepTinyErrors() {
        PlaneView view = dragView();
        double ppm = view.getPixelsPerMetre();
        // 3-4-5: exactly 5 cm, drawn 0.05 m times the scale
        assertEquals(0.05 * ppm, ScreenError.pixels(view, 0.03, 0.04), 1e-12 * ppm);
        // in double, an RK4-sized error is not lost to a float screen coordinate
        assertEquals(1e-9 * ppm, ScreenError.pixels(view, 1e-9, 0.0), 1e-21 * ppm);
    }

    @Test
    void visibleFromOnePixelOrOneRadius() {
        assertFalse(ScreenError.isVisible(0.99, 0.99));
        assertTrue(ScreenError.isVisible(1.0, 0.01));
        assertTrue(ScreenError.isVisible(0.2, 1.0));
        assertEquals(2.0, ScreenError.radii(0.6, 0.3), 1e-15);
    }
}

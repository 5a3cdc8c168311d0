package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The plane's mapping onto the window: the region fills the area as far as it can, centred. */
class PlaneViewTest {

    @Test
    void regionFillsTheAreaCentred() {
        ScreenRect area = new ScreenRect(0f, 50f, 1280f, 400f);
        // 20 m x 8 m into 1280 x 400 px: height-limited, 50 px per metre (not 64).
        PlaneView view = new PlaneView().fit(-2f, 18f, -1f, 7f, area, 1280f, 720f);
        assertEquals(50f, view.getPixelsPerMetre(), 0f);
        // Tolerances: a few float roundings of numbers below 2000 px (ulp 1.2e-4).
        assertEquals(50f, view.screenY(-1f), 1e-3f);
        assertEquals(450f, view.screenY(7f), 1e-3f);
        assertEquals(640f, view.screenX(8f), 1e-3f);
        assertEquals(8f, view.planeX(640f), 1e-5f);
        assertEquals(7f, view.planeY(450f), 1e-5f);
        assertEquals(720f / 2f / 50f, view.getHalfHeightMetres(), 1e-6f);
        // Width-limited (40 m into 1280 px: 32 px per metre): centred up and down.
        view.fit(0f, 40f, 0f, 5f, area, 1280f, 720f);
        assertEquals(32f, view.getPixelsPerMetre(), 0f);
        assertEquals(250f, view.screenY(2.5f), 1e-3f);
        assertEquals(0f, view.screenX(0f), 1e-3f);
    }

    @Test
    void aDegenerateAreaIsTakenAsOnePixelRatherThanRefused() {
        // Issue 17: an empty scene area threw on the render thread and killed the window.
        ScreenRect empty = new ScreenRect(0f, 32.4f, 640f, 0f);
        PlaneView view = new PlaneView().fit(-4f, 74f, -6f, 23.6f, empty, 640f, 360f);
        // One pixel for 29.6 m: height-limited.
        assertEquals(PlaneView.MIN_PIXELS / 29.6f, view.getPixelsPerMetre(), 1e-6f);
        assertTrue(Float.isFinite(view.getCentreX()) && Float.isFinite(view.getCentreY()));
        view.fit(0f, 10f, 0f, 5f, new ScreenRect(), 0f, 0f);
        assertEquals(PlaneView.MIN_PIXELS / 10f, view.getPixelsPerMetre(), 1e-6f);
        assertEquals(PlaneView.MIN_PIXELS, view.getWindowWidth(), 0f);
    }
}

package particlelab.view;

/**
 * How the side view maps the x-y plane (z = 0) onto the window: a region of the plane fills a
 * screen area at one scale, {@link #getPixelsPerMetre()}, as large as fits, centred in it.
 * Pure arithmetic, shared by the camera ({@link CameraFraming}) and the label layout, so
 * labels are placed in pixels for exactly the picture the camera shows.
 */
public final class PlaneView {

    /** The least size an area or a window is taken to have (in pixels). */
    public static final float MIN_PIXELS = 1f;

    private float pixelsPerMetre = 1f;
    /** The plane point at the window's centre (in metres). */
    private float centreX;
    private float centreY;
    private float windowWidth = 1f;
    private float windowHeight = 1f;

    /**
     * Fit a region of the plane into a screen area. A degenerate area or window (empty, as a
     * window shrunk to nothing may give) is taken as {@value #MIN_PIXELS} pixel(s) on each
     * side, so the mapping stays finite and the view is drawn tiny, rather than refused on
     * the render thread.
     *
     * @param xMin the region's left edge (in metres)
     * @param xMax its right edge (in metres, &gt;xMin)
     * @param yMin its bottom edge (in metres)
     * @param yMax its top edge (in metres, &gt;yMin)
     * @param area where it goes on the window (in pixels, not null, not modified)
     * @param width the window's width (in pixels)
     * @param height the window's height (in pixels)
     * @return this
     */
    public PlaneView fit(float xMin, float xMax, float yMin, float yMax, ScreenRect area,
            float width, float height) {
        if (!(xMax > xMin && yMax > yMin)) {
            throw new IllegalArgumentException("plane view needs xMin < xMax and yMin < yMax,"
                    + " but got x " + xMin + ".." + xMax + ", y " + yMin + ".." + yMax);
        }
        float areaWidth = atLeastOnePixel(area.getWidth());
        float areaHeight = atLeastOnePixel(area.getHeight());
        pixelsPerMetre = Math.min(areaWidth / (xMax - xMin), areaHeight / (yMax - yMin));
        windowWidth = atLeastOnePixel(width);
        windowHeight = atLeastOnePixel(height);
        // The region's centre goes to the area's centre; then find the plane point that
        // lands on the window's centre.
        float areaCentreX = area.getX() + areaWidth / 2f;
        float areaCentreY = area.getY() + areaHeight / 2f;
        centreX = (xMin + xMax) / 2f + (windowWidth / 2f - areaCentreX) / pixelsPerMetre;
        centreY = (yMin + yMax) / 2f + (windowHeight / 2f - areaCentreY) / pixelsPerMetre;
        return this;
    }

    /** @return the scale (in pixels per metre, &gt;0) */
    public float getPixelsPerMetre() {
        return pixelsPerMetre;
    }

    /** @return the x of the plane point at the window's centre (in metres) */
    public float getCentreX() {
        return centreX;
    }

    /** @return the y of the plane point at the window's centre (in metres) */
    public float getCentreY() {
        return centreY;
    }

    /** @return half the plane's visible height (in metres) */
    public float getHalfHeightMetres() {
        return windowHeight / 2f / pixelsPerMetre;
    }

    /** @return the window's width (in pixels) */
    public float getWindowWidth() {
        return windowWidth;
    }

    /** @return the window's height (in pixels) */
    public float getWindowHeight() {
        return windowHeight;
    }

    /**
     * Map a plane x to the screen.
     *
     * @param x in metres
     * @return in pixels from the window's left edge
     */
    public float screenX(float x) {
        return windowWidth / 2f + (x - centreX) * pixelsPerMetre;
    }

    /**
     * Map a plane y to the screen.
     *
     * @param y in metres
     * @return in pixels from the window's bottom edge
     */
    public float screenY(float y) {
        return windowHeight / 2f + (y - centreY) * pixelsPerMetre;
    }

    /**
     * Map a screen x to the plane.
     *
     * @param x in pixels from the window's left edge
     * @return in metres
     */
    public float planeX(float x) {
        return centreX + (x - windowWidth / 2f) / pixelsPerMetre;
    }

    /**
     * Map a screen y to the plane.
     *
     * @param y in pixels from the window's bottom edge
     * @return in metres
     */
    public float planeY(float y) {
        return centreY + (y - windowHeight / 2f) / pixelsPerMetre;
    }

    /** Clamp a size to at least {@link #MIN_PIXELS} (NaN too). */
    private static float atLeastOnePixel(float pixels) {
        return pixels >= MIN_PIXELS ? pixels : MIN_PIXELS;
    }
}

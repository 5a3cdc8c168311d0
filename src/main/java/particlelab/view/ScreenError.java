package particlelab.view;

/**
 * An error as the viewer sees it: how far apart two points of the plane of motion are drawn
 * on the screen, in pixels, and in the drawn spheres' radii, with the thresholds below which
 * nobody can see it. "It's all about illusion": a method whose error stays under a pixel and
 * under a radius looks right, whatever it is in metres.
 *
 * <p>The demos' camera ({@link CameraFraming}) looks straight at the plane z = 0 through the
 * mapping of {@link PlaneView}, so a distance {@code d} in that plane is drawn
 * {@code d·pixelsPerMetre} pixels long everywhere on the screen (the projection's
 * {@code Camera.getScreenCoordinates} agrees, see the test). Pure arithmetic in double, so an
 * error of 1e-9 m is not lost in a float screen coordinate; allocates nothing.
 */
public final class ScreenError {

    /** An error drawn at least this long is visible (in pixels). */
    public static final double VISIBLE_PIXELS = 1.0;
    /** An error at least this many sphere radii is visible as a misplaced body (radii). */
    public static final double VISIBLE_RADII = 1.0;

    private ScreenError() {
    }

    /**
     * Measure how far apart two points of the plane z = 0 are drawn.
     *
     * @param view the mapping the scene is drawn with (not null, not modified)
     * @param dx the points' difference in x (in metres)
     * @param dy the points' difference in y (in metres)
     * @return the distance on the screen (in pixels, &ge;0)
     */
    public static double pixels(PlaneView view, double dx, double dy) {
        return Math.hypot(dx, dy) * view.getPixelsPerMetre();
    }

    /**
     * Express a distance in sphere radii.
     *
     * @param metres the distance (in metres, &ge;0)
     * @param radiusMetres the drawn sphere's radius (in metres, &gt;0)
     * @return the distance (in radii)
     */
    public static double radii(double metres, double radiusMetres) {
        return metres / radiusMetres;
    }

    /**
     * Tell whether an error can be seen: a pixel or more on the screen, or a radius or more
     * of the body it displaces.
     *
     * @param pixels the error on the screen (in pixels)
     * @param radii the error in sphere radii
     * @return true if visible
     */
    public static boolean isVisible(double pixels, double radii) {
        return pixels >= VISIBLE_PIXELS || radii >= VISIBLE_RADII;
    }
}

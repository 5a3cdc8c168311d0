package particlelab.view;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;

/**
 * Points a perspective camera straight at the x-y plane so that the plane appears exactly as
 * a {@link PlaneView} maps it: the side view every lecture demo uses.
 */
public final class CameraFraming {

    /** The vertical field of view (in degrees). */
    public static final float FIELD_OF_VIEW_DEGREES = 40f;

    private CameraFraming() {
    }

    /**
     * Frame the plane as a view maps it; a camera of no size (a minimised window) is left
     * as it is.
     *
     * @param camera the camera (not null, modified)
     * @param view the mapping of the plane to the window (not null, not modified)
     */
    public static void frame(Camera camera, PlaneView view) {
        if (camera.getWidth() <= 0 || camera.getHeight() <= 0) {
            // A window minimised to nothing: no aspect to frame for; the next size frames.
            return;
        }
        float aspect = camera.getWidth() / (float) camera.getHeight();
        float halfHeight = view.getHalfHeightMetres();
        // At this distance the plane z = 0 fills the view's height with 2·halfHeight metres.
        float distance = halfHeight / FastMath.tan(FIELD_OF_VIEW_DEGREES * FastMath.DEG_TO_RAD
                / 2f);
        camera.setFrustumPerspective(FIELD_OF_VIEW_DEGREES, aspect, distance * 0.05f,
                distance * 4f);
        camera.setLocation(new Vector3f(view.getCentreX(), view.getCentreY(), distance));
        camera.lookAtDirection(new Vector3f(0f, 0f, -1f), Vector3f.UNIT_Y);
    }
}

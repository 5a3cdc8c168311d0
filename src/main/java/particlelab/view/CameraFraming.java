package particlelab.view;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;

/**
 * Points a perspective camera straight at the x-y plane so that a rectangle of it fills the
 * view below the HUD: the side view every lecture demo uses.
 */
public final class CameraFraming {

    /** The vertical field of view (in degrees). */
    public static final float FIELD_OF_VIEW_DEGREES = 40f;
    /** The fraction of the screen's height kept free at the top for the HUD. */
    public static final float HUD_FRACTION = 0.36f;

    private CameraFraming() {
    }

    /**
     * Frame a rectangle of the x-y plane.
     *
     * @param camera the camera (not null, modified)
     * @param xMin the left edge to show (in metres)
     * @param xMax the right edge to show (in metres, &gt;xMin)
     * @param yMin the bottom edge to show (in metres)
     * @param yMax the top edge to show below the HUD (in metres, &gt;yMin)
     */
    public static void frame(Camera camera, float xMin, float xMax, float yMin, float yMax) {
        float aspect = camera.getWidth() / (float) camera.getHeight();
        // Stretch the top so that [yMin, yMax] fills the screen below the HUD band.
        float height = (yMax - yMin) / (1f - HUD_FRACTION);
        float halfHeight = Math.max(height, (xMax - xMin) / aspect) / 2f;
        float centreX = (xMin + xMax) / 2f;
        float centreY = yMin + halfHeight;
        float distance = halfHeight / FastMath.tan(FIELD_OF_VIEW_DEGREES * FastMath.DEG_TO_RAD
                / 2f);
        camera.setFrustumPerspective(FIELD_OF_VIEW_DEGREES, aspect, distance * 0.05f,
                distance * 4f);
        camera.setLocation(new Vector3f(centreX, centreY, distance));
        camera.lookAtDirection(new Vector3f(0f, 0f, -1f), Vector3f.UNIT_Y);
    }
}

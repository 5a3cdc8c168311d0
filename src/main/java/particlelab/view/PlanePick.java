package particlelab.view;

import com.jme3.math.Vector2f;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;

/**
 * From a point on the screen to a point of a demo's plane of motion and back, through a
 * camera: the pure part of picking and dragging with the mouse. The pick ray runs from the
 * eye E through the screen point's place N on the near plane
 * ({@link Camera#getWorldCoordinates} at depth 0; for a parallel projection, from N along the
 * view direction); where it crosses the plane {@code z = planeZ} is the point the mouse is
 * over, {@code P = E + t·(N − E)}, {@code t = (planeZ − E.z)/(N.z − E.z)}.
 * That is exact for any camera, turned or not, so a drag moves a body in the plane of its
 * motion (most demos are 2-D, in the x-y plane at z = 0), never towards or away from the eye.
 *
 * <p>Needs only a {@link Camera} (no application): {@code new Camera(w, h)} with a frustum, a
 * location and {@code lookAt} is enough, so it is tested in plain JUnit. Screen coordinates
 * are jME's: pixels from the window's bottom-left corner. One instance holds its scratch
 * vectors; use it on one thread.
 */
public final class PlanePick {

    /** A ray more nearly parallel to the plane than this (|dz| per unit length) misses it. */
    private static final float MIN_DIRECTION_Z = 1e-6f;

    /** Scratch: the screen point (pixels). */
    private final Vector2f screen = new Vector2f();
    /** Scratch: the pick ray's origin and direction (world units, m). */
    private final Vector3f origin = new Vector3f();
    private final Vector3f direction = new Vector3f();
    /** Scratch: a projected point (x, y in pixels, z the depth from 0 to 1). */
    private final Vector3f projected = new Vector3f();

    /**
     * Find the point of the plane {@code z = planeZ} under a screen point.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param screenX the screen point's x (in pixels from the window's left edge)
     * @param screenY the screen point's y (in pixels from the window's bottom edge)
     * @param planeZ the plane's z (in metres, finite)
     * @param storeResult storage for the point (in metres, not null; modified only on a hit)
     * @return true if the ray crosses the plane in front of the camera (storeResult set);
     *     false if it runs parallel to the plane or crosses it behind the eye
     */
    public boolean screenToPlane(Camera camera, float screenX, float screenY, float planeZ,
            Vector3f storeResult) {
        screen.set(screenX, screenY);
        camera.getWorldCoordinates(screen, 0f, origin);
        if (camera.isParallelProjection()) {
            direction.set(camera.getDirection());
        } else {
            // From the eye through the near plane's point: the far plane's point would carry
            // the projection's round-off at depth 1 (far/near times the near plane's).
            direction.set(origin).subtractLocal(camera.getLocation());
            origin.set(camera.getLocation());
        }
        float length = direction.length();
        if (!(length > 0f) || Math.abs(direction.z) < MIN_DIRECTION_Z * length) {
            return false;
        }
        float t = (planeZ - origin.z) / direction.z;
        if (!(t >= 0f) || Float.isInfinite(t)) {
            return false;
        }
        storeResult.set(origin.x + t * direction.x, origin.y + t * direction.y, planeZ);
        return true;
    }

    /**
     * Find where a point of the world is drawn on the screen.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param world the point (in metres, not null, not modified)
     * @param storeResult storage for the screen point (in pixels from the bottom-left
     *     corner, not null, modified)
     * @return storeResult
     */
    public Vector2f planeToScreen(Camera camera, Vector3f world, Vector2f storeResult) {
        camera.getScreenCoordinates(world, projected);
        return storeResult.set(projected.x, projected.y);
    }

    /**
     * Measure how far apart two points of the world are drawn on the screen.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param a one point (in metres, not null, not modified)
     * @param b the other point (in metres, not null, not modified)
     * @return the distance (in pixels, &ge;0)
     */
    public float screenDistance(Camera camera, Vector3f a, Vector3f b) {
        camera.getScreenCoordinates(a, projected);
        float ax = projected.x;
        float ay = projected.y;
        camera.getScreenCoordinates(b, projected);
        return (float) Math.hypot(projected.x - ax, projected.y - ay);
    }

    /**
     * Measure how far a point of the world is drawn from a screen point.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param world the point (in metres, not null, not modified)
     * @param screenX the screen point's x (in pixels)
     * @param screenY the screen point's y (in pixels)
     * @return the distance (in pixels, &ge;0; infinite if the point is behind the camera)
     */
    public float screenDistance(Camera camera, Vector3f world, float screenX, float screenY) {
        camera.getScreenCoordinates(world, projected);
        if (!(projected.z >= 0f && projected.z <= 1f)) {
            return Float.POSITIVE_INFINITY;
        }
        return (float) Math.hypot(projected.x - screenX, projected.y - screenY);
    }
}

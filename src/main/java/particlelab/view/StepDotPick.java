package particlelab.view;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;

/**
 * From a screen point to the step dot under it: the nearest of a run of step positions as
 * the camera draws them, within a pick radius. The pure part of clicking a step dot (the
 * derivative lens's step), tested in plain JUnit with a {@link Camera} alone, as
 * {@link PlanePick} is. Of two dots at the same distance (a sphere at rest repeats its
 * place) the earlier step wins. One instance holds its scratch; use it on one thread.
 */
public final class StepDotPick {

    private static final int FLOATS_PER_POINT = 3;

    private final PlanePick pick = new PlanePick();
    /** Scratch: one step's position (m). */
    private final Vector3f point = new Vector3f();

    /**
     * Find the step whose dot is drawn nearest a screen point, within a radius.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param positions the steps' positions, x, y, z per step, oldest first (in metres, not
     *     null, not modified)
     * @param count how many steps the array holds (&ge;0, at most its length / 3)
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @param radiusPixels how far from a dot's centre a press still picks it (in pixels, &ge;0)
     * @return the step's place in the array (from 0), or -1 if no dot is that near
     */
    public int nearest(Camera camera, float[] positions, int count, float screenX,
            float screenY, float radiusPixels) {
        if (count < 0 || FLOATS_PER_POINT * count > positions.length) {
            throw new IllegalArgumentException("count must be from 0 to "
                    + positions.length / FLOATS_PER_POINT + ", but was " + count);
        }
        if (!(radiusPixels >= 0f)) {
            throw new IllegalArgumentException("pick radius must be >= 0 pixels, but was "
                    + radiusPixels);
        }
        int best = -1;
        float bestDistance = Float.POSITIVE_INFINITY;
        for (int i = 0; i < count; ++i) {
            int at = FLOATS_PER_POINT * i;
            point.set(positions[at], positions[at + 1], positions[at + 2]);
            float distance = pick.screenDistance(camera, point, screenX, screenY);
            if (distance <= radiusPixels && distance < bestDistance) {
                bestDistance = distance;
                best = i;
            }
        }
        return best;
    }
}

package particlelab.view;

import java.nio.FloatBuffer;

/**
 * The two vertices of a ribbon (a line drawn as a thin strip of triangles) at one point of a
 * path in the x-y plane: the point offset by half the ribbon's width either side,
 * perpendicular to the path's direction there. Shared by every path view (trails, kept
 * shots, drawn curves) so that they are drawn alike. Allocates nothing.
 */
final class RibbonVertices {

    /** Directions shorter than this (in metres) count as none: the offset goes straight up. */
    private static final float MIN_DIRECTION = 1e-6f;

    private RibbonVertices() {
    }

    /**
     * Write the pair of vertices of one slot: 6 floats from {@code slot * 6}.
     *
     * @param positions the ribbon's position buffer (not null, room for the slot)
     * @param slot which pair (&ge;0)
     * @param x the point's x (in metres)
     * @param y the point's y (in metres)
     * @param z the point's z (in metres)
     * @param dx the path's direction there, x (next point minus previous; any length)
     * @param dy the path's direction there, y
     * @param halfWidth half the ribbon's width (in metres, &gt;0)
     */
    static void write(FloatBuffer positions, int slot, float x, float y, float z, float dx,
            float dy, float halfWidth) {
        float length = (float) Math.sqrt(dx * dx + dy * dy);
        float nx = 0f;
        float ny = halfWidth;
        if (length > MIN_DIRECTION) {
            // Perpendicular to the path, in the x-y plane.
            nx = -dy / length * halfWidth;
            ny = dx / length * halfWidth;
        }
        int out = slot * 6;
        positions.put(out, x + nx).put(out + 1, y + ny).put(out + 2, z);
        positions.put(out + 3, x - nx).put(out + 4, y - ny).put(out + 5, z);
    }
}

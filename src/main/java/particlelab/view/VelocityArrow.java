package particlelab.view;

import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;

/**
 * A flat arrow in the x-y plane showing a velocity: it starts at the particle and is as long as
 * the distance the particle would cover in {@link #getSecondsShown()} at that velocity. Seven
 * vertices in a preallocated buffer, rewritten in place each frame.
 */
public final class VelocityArrow {

    private static final int VERTICES = 7;
    /** Shorter arrows than this (in metres) are hidden. */
    private static final float MIN_LENGTH = 1e-4f;

    private final float shaftHalfWidth;
    private final float secondsShown;
    private final FloatBuffer positions;
    private final VertexBuffer positionBuffer;
    private final Geometry geometry;
    private boolean visible = true;
    /** The lowest the arrow reaches (in metres; -∞: no floor). */
    private float floorY = Float.NEGATIVE_INFINITY;

    /**
     * Create an arrow.
     *
     * @param name the geometry's name (not null)
     * @param shaftWidthMetres the shaft's width (in metres, &gt;0)
     * @param secondsShown the arrow's length is the velocity times this (in seconds, &gt;0)
     * @param color the colour (not null, not modified)
     * @param material an Unshaded material to copy the settings from (not null, cloned)
     */
    public VelocityArrow(String name, float shaftWidthMetres, float secondsShown,
            ColorRGBA color, Material material) {
        this.shaftHalfWidth = shaftWidthMetres / 2f;
        this.secondsShown = secondsShown;
        this.positions = BufferUtils.createFloatBuffer(VERTICES * 3);
        Mesh mesh = new Mesh();
        mesh.setBuffer(VertexBuffer.Type.Position, 3, positions);
        // Shaft: a quad (0 1 2 3); head: a triangle (4 5 6).
        mesh.setBuffer(VertexBuffer.Type.Index, 3, BufferUtils.createShortBuffer(
                new short[] {0, 1, 2, 0, 2, 3, 4, 5, 6}));
        mesh.setStreamed();
        this.positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
        this.geometry = new Geometry(name, mesh);
        Material arrow = material.clone();
        arrow.setColor("Color", color);
        arrow.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
        geometry.setMaterial(arrow);
        geometry.setCullHint(Spatial.CullHint.Always);
    }

    /**
     * Access the geometry to attach to a scene.
     *
     * @return the live geometry (not null)
     */
    public Geometry getGeometry() {
        return geometry;
    }

    /**
     * Return how many seconds of travel the arrow's length stands for.
     *
     * @return the time (in seconds, &gt;0)
     */
    public float getSecondsShown() {
        return secondsShown;
    }

    /**
     * Show or hide the arrow.
     *
     * @param newVisible true to show it
     */
    public void setVisible(boolean newVisible) {
        visible = newVisible;
        if (!visible) {
            geometry.setCullHint(Spatial.CullHint.Always);
        }
    }

    /**
     * Test whether the arrow is shown (when long enough).
     *
     * @return true if shown
     */
    public boolean isVisible() {
        return visible;
    }

    /**
     * Keep the arrow above a height: an arrow from above it that would reach lower is drawn
     * shorter, along the same direction, its head just above it (the ground, so that no arrow
     * crosses the ground band and its distance marks into the footer). From below it the
     * arrow is drawn whole.
     *
     * @param yMetres the height (in metres, finite; -∞ for none)
     */
    public void setFloor(float yMetres) {
        if (Float.isNaN(yMetres) || yMetres == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("floor y " + yMetres
                    + " m: allowed a finite height or -infinity");
        }
        floorY = yMetres;
    }

    /**
     * Point the arrow along a velocity from a start point, shortened at the floor
     * ({@link #setFloor}).
     *
     * @param start the particle's position (in metres, not null, not modified)
     * @param velocity the particle's velocity (in m/s, not null, not modified)
     */
    public void update(Vector3f start, Vector3f velocity) {
        float dx = velocity.x * secondsShown;
        float dy = velocity.y * secondsShown;
        float length = (float) Math.sqrt(dx * dx + dy * dy);
        if (!visible || !(length > MIN_LENGTH) || Float.isInfinite(length)) {
            geometry.setCullHint(Spatial.CullHint.Always);
            return;
        }
        float headHalfWidth = 2.5f * shaftHalfWidth;
        // The head's corners reach at most its half width below the tip.
        float lowest = floorY + headHalfWidth;
        if (dy < 0f && start.y >= lowest && start.y + dy < lowest) {
            float keep = (start.y - lowest) / -dy;
            dx *= keep;
            dy *= keep;
            length *= keep;
        } else if (dy < 0f && start.y < lowest && start.y >= floorY) {
            // On the floor already, moving down: nothing to draw above it.
            length = 0f;
        }
        if (!(length > MIN_LENGTH)) {
            geometry.setCullHint(Spatial.CullHint.Always);
            return;
        }
        geometry.setCullHint(Spatial.CullHint.Never);
        float ux = dx / length;
        float uy = dy / length;
        // Perpendicular in the x-y plane.
        float px = -uy;
        float py = ux;
        float headLength = Math.min(0.35f * length, 6f * shaftHalfWidth);
        float neckX = start.x + ux * (length - headLength);
        float neckY = start.y + uy * (length - headLength);
        float z = start.z + 0.01f;
        float w = shaftHalfWidth;
        put(0, start.x + px * w, start.y + py * w, z);
        put(1, start.x - px * w, start.y - py * w, z);
        put(2, neckX - px * w, neckY - py * w, z);
        put(3, neckX + px * w, neckY + py * w, z);
        put(4, neckX + px * headHalfWidth, neckY + py * headHalfWidth, z);
        put(5, neckX - px * headHalfWidth, neckY - py * headHalfWidth, z);
        put(6, start.x + dx, start.y + dy, z);
        positions.rewind();
        positionBuffer.updateData(positions);
    }

    private void put(int vertex, float x, float y, float z) {
        int base = vertex * 3;
        positions.put(base, x).put(base + 1, y).put(base + 2, z);
    }
}

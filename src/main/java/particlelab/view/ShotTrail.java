package particlelab.view;

import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;

/**
 * The path of one kept shot: a copy of a particle's {@link Trail} at the moment it was
 * launched again, drawn as a thin ribbon of one even, faint colour, so older shots can fade.
 * All storage is allocated up front; {@link #copyFrom} and {@link #setOpacity} allocate
 * nothing.
 */
public final class ShotTrail {

    private static final int FLOATS_PER_POINT = 3;

    private final int capacity;
    private final float halfWidth;
    private final float[] points;
    private int count;
    private final FloatBuffer positions;
    private final VertexBuffer positionBuffer;
    private final Geometry geometry;
    private final Material faint;
    private final ColorRGBA color = new ColorRGBA();
    private final Vector3f point = new Vector3f();

    /**
     * Create an empty kept path.
     *
     * @param name the geometry's name (not null)
     * @param capacity the most points it holds (&ge;2; a trail's capacity)
     * @param widthMetres the ribbon's width (in metres, &gt;0)
     * @param material an Unshaded material to copy the settings from (not null, cloned)
     */
    public ShotTrail(String name, int capacity, float widthMetres, Material material) {
        if (capacity < 2 || !(widthMetres > 0f)) {
            throw new IllegalArgumentException("a kept path needs capacity >= 2 and width > 0,"
                    + " but had " + capacity + " and " + widthMetres);
        }
        this.capacity = capacity;
        this.halfWidth = widthMetres / 2f;
        this.points = new float[capacity * FLOATS_PER_POINT];
        this.positions = BufferUtils.createFloatBuffer(2 * capacity * FLOATS_PER_POINT);
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.TriangleStrip);
        mesh.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_POINT, positions);
        mesh.setStreamed();
        this.positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
        this.geometry = new Geometry(name, mesh);
        faint = material.clone();
        faint.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        faint.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
        faint.getAdditionalRenderState().setDepthWrite(false);
        faint.setColor("Color", color);
        geometry.setMaterial(faint);
        geometry.setQueueBucket(RenderQueue.Bucket.Transparent);
        geometry.setCullHint(Spatial.CullHint.Always);
    }

    /** @return the live geometry, to attach to a scene (not null) */
    public Geometry getGeometry() {
        return geometry;
    }

    /** @return how many points it holds (0 when empty) */
    public int size() {
        return count;
    }

    /**
     * Copy a trail's points (up to this path's capacity, the newest kept) and show them.
     *
     * @param trail the trail to copy (not null, not modified)
     */
    public void copyFrom(Trail trail) {
        int first = Math.max(0, trail.size() - capacity);
        count = trail.size() - first;
        for (int i = 0; i < count; ++i) {
            trail.copyPoint(first + i, point);
            points[i * FLOATS_PER_POINT] = point.x;
            points[i * FLOATS_PER_POINT + 1] = point.y;
            points[i * FLOATS_PER_POINT + 2] = point.z;
        }
        if (count < 2) {
            clear();
            return;
        }
        for (int slot = 0; slot < capacity; ++slot) {
            writeSlot(slot, Math.min(slot, count - 1));
        }
        positions.rewind();
        positionBuffer.updateData(positions);
        geometry.setCullHint(Spatial.CullHint.Never);
    }

    /** Forget the points and hide the path. */
    public void clear() {
        count = 0;
        geometry.setCullHint(Spatial.CullHint.Always);
    }

    /**
     * Colour the path: its particle's colour at an opacity.
     *
     * @param base the particle's colour (not null, not modified)
     * @param opacity from 0 (invisible) to 1
     */
    public void setOpacity(ColorRGBA base, float opacity) {
        color.set(base.r, base.g, base.b, base.a * opacity);
        faint.setColor("Color", color);
    }

    /** @return the colour drawn now (live, do not modify) */
    public ColorRGBA getColor() {
        return color;
    }

    /** Write one slot's two ribbon vertices, offset sideways from its point. */
    private void writeSlot(int slot, int index) {
        int here = index * FLOATS_PER_POINT;
        int before = Math.max(index - 1, 0) * FLOATS_PER_POINT;
        int after = Math.min(index + 1, count - 1) * FLOATS_PER_POINT;
        RibbonVertices.write(positions, slot, points[here], points[here + 1], points[here + 2],
                points[after] - points[before], points[after + 1] - points[before + 1],
                halfWidth);
    }
}

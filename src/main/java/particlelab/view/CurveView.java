package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;

/**
 * A curve in the x-y plane drawn as a flat ribbon of one colour: a predicted arc, a reachable
 * envelope. Unlike a {@link Trail} it does not fade and is not a ring: the demo hands it all
 * its points at once ({@link #setPoints}), e.g. when a target moved. All storage is allocated
 * up front; setting points allocates nothing.
 */
public final class CurveView {

    private static final int FLOATS_PER_POINT = 3;

    private final int capacity;
    private final float halfWidth;
    private final FloatBuffer positions;
    private final VertexBuffer positionBuffer;
    private final Geometry geometry;

    /**
     * Create an empty curve.
     *
     * @param assetManager loads the material (not null)
     * @param name the geometry's name (not null)
     * @param capacity the most points it can show (&ge;2)
     * @param widthMetres the ribbon's width (in metres, finite, &gt;0)
     * @param color its colour (not null, copied; an alpha below 1 is drawn see-through)
     */
    public CurveView(AssetManager assetManager, String name, int capacity, float widthMetres,
            ColorRGBA color) {
        if (capacity < 2) {
            throw new IllegalArgumentException("curve capacity must be >= 2, but was "
                    + capacity);
        }
        if (!(widthMetres > 0f) || Float.isInfinite(widthMetres)) {
            throw new IllegalArgumentException(
                    "curve width (m) must be finite and > 0, but was " + widthMetres);
        }
        this.capacity = capacity;
        this.halfWidth = widthMetres / 2f;
        positions = BufferUtils.createFloatBuffer(2 * capacity * FLOATS_PER_POINT);
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.TriangleStrip);
        mesh.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_POINT, positions);
        mesh.setStreamed();
        positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
        geometry = new Geometry(name, mesh);
        Material material = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", color.clone());
        material.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
        if (color.a < 1f) {
            material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
            material.getAdditionalRenderState().setDepthWrite(false);
            geometry.setQueueBucket(RenderQueue.Bucket.Transparent);
        }
        geometry.setMaterial(material);
        // The curve changes shape; skip bounds and culling instead of recomputing them.
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
     * Return the most points the curve can show.
     *
     * @return the capacity (&ge;2)
     */
    public int getCapacity() {
        return capacity;
    }

    /**
     * Show the curve through points, in order; fewer than two hide it. More points than the
     * capacity (or than the arrays hold) are not drawn: the curve shows the first ones, rather
     * than fail on the render thread.
     *
     * @param xs the points' x (in metres, not null, not modified)
     * @param ys the points' y (in metres, not null, not modified)
     * @param requested how many points to use (0 to the capacity, at most the arrays'
     *     length; clamped to those)
     */
    public void setPoints(float[] xs, float[] ys, int requested) {
        int count = Math.min(requested, Math.min(capacity, Math.min(xs.length, ys.length)));
        if (count < 2) {
            geometry.setCullHint(Spatial.CullHint.Always);
            return;
        }
        for (int slot = 0; slot < capacity; ++slot) {
            // Slots past the last point repeat it: zero-area triangles.
            int i = Math.min(slot, count - 1);
            int before = Math.max(i - 1, 0);
            int after = Math.min(i + 1, count - 1);
            RibbonVertices.write(positions, slot, xs[i], ys[i], 0f, xs[after] - xs[before],
                    ys[after] - ys[before], halfWidth);
        }
        positions.rewind();
        positionBuffer.updateData(positions);
        geometry.setCullHint(Spatial.CullHint.Never);
    }

    /**
     * Hide the curve until points are set again.
     */
    public void hide() {
        geometry.setCullHint(Spatial.CullHint.Always);
    }
}

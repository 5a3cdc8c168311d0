package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.bounding.BoundingBox;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

/**
 * Many particles drawn as one mesh of points: one draw call, whatever the count. The position
 * buffer (three floats a point) and the colour buffer (four bytes a point) are made once and
 * rewritten in place every frame, then marked updated, so jME uploads them again without a
 * new buffer: nothing is allocated per frame. Colours add up (additive blending), so a black
 * point is invisible and a dense spray glows.
 */
public final class PointCloudView {

    private final int count;
    private final Mesh mesh = new Mesh();
    private final Geometry geometry;
    private final FloatBuffer positions;
    private final ByteBuffer colours;
    private final VertexBuffer positionBuffer;
    private final VertexBuffer colourBuffer;

    /**
     * Create the mesh, every point at the origin and black.
     *
     * @param assetManager where to load the material from (not null)
     * @param name the geometry's name (not null)
     * @param count how many points (&ge;1)
     * @param pointSizePixels each point's size on the screen (in pixels, &gt;0)
     * @param boundsHalfExtent half the side of a box about the origin that holds every point
     *     (in metres, &gt;0): the bound the camera culls against
     */
    public PointCloudView(AssetManager assetManager, String name, int count,
            float pointSizePixels, float boundsHalfExtent) {
        if (count < 1 || !(pointSizePixels > 0f) || !(boundsHalfExtent > 0f)) {
            throw new IllegalArgumentException("a point cloud needs count >= 1, point size > 0"
                    + " and bounds > 0, but got " + count + ", " + pointSizePixels + " px, "
                    + boundsHalfExtent + " m");
        }
        this.count = count;
        positions = BufferUtils.createFloatBuffer(3 * count);
        colours = BufferUtils.createByteBuffer(4 * count);
        mesh.setMode(Mesh.Mode.Points);
        mesh.setBuffer(VertexBuffer.Type.Position, 3, positions);
        mesh.setBuffer(VertexBuffer.Type.Color, 4, VertexBuffer.Format.UnsignedByte, colours);
        positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
        colourBuffer = mesh.getBuffer(VertexBuffer.Type.Color);
        colourBuffer.setNormalized(true);
        positionBuffer.setUsage(VertexBuffer.Usage.Stream);
        colourBuffer.setUsage(VertexBuffer.Usage.Stream);
        mesh.setBound(new BoundingBox(Vector3f.ZERO, boundsHalfExtent, boundsHalfExtent,
                boundsHalfExtent));
        mesh.updateCounts();

        Material material = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setBoolean("VertexColor", true);
        material.setFloat("PointSize", pointSizePixels);
        RenderState state = material.getAdditionalRenderState();
        state.setBlendMode(RenderState.BlendMode.Additive);
        state.setDepthWrite(false);
        geometry = new Geometry(name, mesh);
        geometry.setMaterial(material);
        geometry.setQueueBucket(RenderQueue.Bucket.Transparent);
        // the bound is fixed and generous: the points move inside it without a new bound
        geometry.setCullHint(Spatial.CullHint.Never);
    }

    /**
     * Access the geometry, to attach it to the scene.
     *
     * @return the live geometry (not null)
     */
    public Geometry getGeometry() {
        return geometry;
    }

    /**
     * Return how many points the mesh has.
     *
     * @return the count (&ge;1)
     */
    public int getCount() {
        return count;
    }

    /**
     * Copy every point's position from planar arrays (all x, then all y, then all z, as
     * {@code ParticleIntegrator.stepPacked} packs them) into the mesh's buffer, in place.
     *
     * @param planar the positions (in metres, length &ge; 3·{@link #getCount()}, not
     *     modified)
     */
    public void copyPlanarPositions(float[] planar) {
        int n = count;
        for (int i = 0, at = 0; i < n; ++i, at += 3) {
            positions.put(at, planar[i]);
            positions.put(at + 1, planar[n + i]);
            positions.put(at + 2, planar[2 * n + i]);
        }
    }

    /**
     * Set one point's colour, in place.
     *
     * @param index the point (from 0 to {@link #getCount()} − 1)
     * @param rgb the colour, 0xRRGGBB
     * @param brightness what to multiply it by (0 to 1; 0 hides the point)
     */
    public void setColour(int index, int rgb, float brightness) {
        int at = 4 * index;
        colours.put(at, scale((rgb >> 16) & 0xff, brightness));
        colours.put(at + 1, scale((rgb >> 8) & 0xff, brightness));
        colours.put(at + 2, scale(rgb & 0xff, brightness));
        colours.put(at + 3, (byte) 0xff);
    }

    /**
     * Tell jME that the buffers changed, so they are uploaded before the next draw.
     */
    public void markUpdated() {
        positionBuffer.setUpdateNeeded();
        colourBuffer.setUpdateNeeded();
    }

    private static byte scale(int channel, float brightness) {
        return (byte) Math.round(channel * brightness);
    }
}

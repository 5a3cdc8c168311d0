package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;

/**
 * Many particles drawn as one mesh of points: one draw call, whatever the count. The mesh
 * ({@link PointCloudMesh}: the positions planar, three buffers of one float a point, and a
 * colour buffer of four bytes a point) is made once and rewritten in place, then marked
 * updated, so jME uploads it again without a new buffer: nothing is allocated per frame. The
 * material ({@value #MATERIAL}, a small shader of this project's) puts x, y and z together and
 * draws each point unlit in its vertex colour at a fixed size in pixels, as Unshaded.j3md with
 * VertexColor and PointSize does. Colours add up (additive blending), so a black point is
 * invisible and a dense spray glows.
 */
public final class PointCloudView {

    /** The material definition: planar positions, vertex colour, point size. */
    public static final String MATERIAL = "MatDefs/PlanarPoints.j3md";

    private final PointCloudMesh points;
    private final Geometry geometry;

    /**
     * Create the mesh, every point at the origin and transparent black, and its material.
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
        points = new PointCloudMesh(count, boundsHalfExtent);
        Material material = new Material(assetManager, MATERIAL);
        material.setFloat("PointSize", pointSizePixels);
        RenderState state = material.getAdditionalRenderState();
        state.setBlendMode(RenderState.BlendMode.Additive);
        state.setDepthWrite(false);
        geometry = new Geometry(name, points.getMesh());
        geometry.setMaterial(material);
        geometry.setQueueBucket(RenderQueue.Bucket.Transparent);
        // the bound is fixed and generous: the points move inside it without a new bound
        geometry.setCullHint(Spatial.CullHint.Never);
    }

    /**
     * Alter the points' size on the screen (e.g. for a larger window).
     *
     * @param pointSizePixels the size (in pixels, finite, &gt;0)
     */
    public void setPointSize(float pointSizePixels) {
        if (!(pointSizePixels > 0f) || pointSizePixels == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("point size must be finite and > 0, but was "
                    + pointSizePixels + " px");
        }
        geometry.getMaterial().setFloat("PointSize", pointSizePixels);
    }

    /**
     * Return the points' size on the screen.
     *
     * @return the size (in pixels, &gt;0)
     */
    public float getPointSize() {
        return (Float) geometry.getMaterial().getParam("PointSize").getValue();
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
     * Access the mesh and its buffers, to write the points into.
     *
     * @return the live mesh (not null)
     */
    public PointCloudMesh getPoints() {
        return points;
    }

    /**
     * Return how many points the mesh has.
     *
     * @return the count (&ge;1)
     */
    public int getCount() {
        return points.getCount();
    }
}

package particlelab.view;

import com.jme3.bounding.BoundingBox;
import com.jme3.math.Vector3f;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;

/**
 * The mesh of a {@link PointCloudView} without its material: the positions planar, in three
 * vertex buffers of one float a point (x in {@link VertexBuffer.Type#Position}, y in
 * {@link VertexBuffer.Type#TexCoord}, z in {@link VertexBuffer.Type#TexCoord2}, which the
 * material {@value PointCloudView#MATERIAL} puts together as {@code vec4(x, y, z, 1)}), and
 * the colour buffer (four bytes a point, R, G, B, A), made once and rewritten in place, so it
 * can be filled and timed without a window or an asset manager.
 *
 * <p>Positions are written as three bulk copies of a range of points straight from the
 * caller's planar array (all x, then all y, then all z, as the particles are packed): no
 * interleaving, no scratch. Colours one point at a time or a run of points in bulk, only
 * where they change, as packed ints through a little-endian int view of the byte buffer, so
 * the int
 * {@code R | G<<8 | B<<16 | A<<24} lands as the bytes R, G, B, A whatever the machine's
 * order. The bound is set once, explicitly: jME must never compute it from the one-float
 * position buffer (it would read x, y, z of three different points as one). Nothing is
 * allocated after the constructor.
 */
public final class PointCloudMesh {

    /** A packed colour's alpha byte, opaque. */
    private static final int OPAQUE = 0xff << 24;
    private static final int CHANNEL = 0xff;
    /** The vertex buffers holding x, y and z, one float a point each. */
    private static final VertexBuffer.Type[] AXES = {VertexBuffer.Type.Position,
        VertexBuffer.Type.TexCoord, VertexBuffer.Type.TexCoord2};

    /** The largest float below 0.5, for {@link #roundLevel}. */
    private static final float JUST_BELOW_HALF = Math.nextDown(0.5f);

    private final int count;
    private final Mesh mesh = new Mesh();
    /** x, y and z of every point, one buffer an axis (m). */
    private final FloatBuffer[] positions = new FloatBuffer[AXES.length];
    private final ByteBuffer colours;
    /** The colour bytes as little-endian ints: one int a point. */
    private final IntBuffer colourInts;
    /** The vertex buffers of {@link #positions}, to mark them updated. */
    private final VertexBuffer[] positionBuffers = new VertexBuffer[AXES.length];
    /** The vertex buffer of {@link #colours}, to mark it updated. */
    private final VertexBuffer colourBuffer;

    /**
     * Create the mesh, every point at the origin and transparent black.
     *
     * @param count how many points (&ge;1)
     * @param boundsHalfExtent half the side of a box about the origin that holds every point
     *     (in metres, &gt;0): the bound the camera culls against
     */
    public PointCloudMesh(int count, float boundsHalfExtent) {
        if (count < 1 || !(boundsHalfExtent > 0f) || boundsHalfExtent == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("a point cloud needs count >= 1 and finite"
                    + " bounds > 0, but got " + count + ", " + boundsHalfExtent + " m");
        }
        this.count = count;
        colours = BufferUtils.createByteBuffer(4 * count);
        colourInts = colours.duplicate().order(ByteOrder.LITTLE_ENDIAN).asIntBuffer();
        mesh.setMode(Mesh.Mode.Points);
        for (int axis = 0; axis < AXES.length; ++axis) {
            positions[axis] = BufferUtils.createFloatBuffer(count);
            mesh.setBuffer(AXES[axis], 1, positions[axis]);
            positionBuffers[axis] = mesh.getBuffer(AXES[axis]);
            positionBuffers[axis].setUsage(VertexBuffer.Usage.Stream);
        }
        mesh.setBuffer(VertexBuffer.Type.Color, 4, VertexBuffer.Format.UnsignedByte, colours);
        colourBuffer = mesh.getBuffer(VertexBuffer.Type.Color);
        colourBuffer.setNormalized(true);
        colourBuffer.setUsage(VertexBuffer.Usage.Stream);
        mesh.setBound(new BoundingBox(Vector3f.ZERO, boundsHalfExtent, boundsHalfExtent,
                boundsHalfExtent));
        // the vertex count from the Position buffer: one float a point, so count points
        mesh.updateCounts();
    }

    /**
     * Pack a colour and a brightness as {@link #writeColours} takes it: each channel times the
     * brightness, rounded, alpha opaque.
     *
     * @param rgb the colour, 0xRRGGBB
     * @param brightness what to multiply it by (0 to 1; 0 gives black, which adds nothing)
     * @return {@code R | G<<8 | B<<16 | 0xff<<24}
     */
    public static int pack(int rgb, float brightness) {
        return scale((rgb >> 16) & CHANNEL, brightness) | scale((rgb >> 8) & CHANNEL,
                brightness) << 8 | scale(rgb & CHANNEL, brightness) << 16 | OPAQUE;
    }

    /**
     * Access the mesh, to make a geometry of it.
     *
     * @return the live mesh (not null)
     */
    public Mesh getMesh() {
        return mesh;
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
     * Access the buffer of one axis of the positions (one float a point), e.g. to compare its
     * contents.
     *
     * @param axis 0 for x, 1 for y, 2 for z
     * @return the live buffer (in metres, do not modify)
     */
    public FloatBuffer getPositionData(int axis) {
        return positions[axis];
    }

    /**
     * Access the colour buffer (R, G, B, A bytes per point).
     *
     * @return the live buffer (do not modify)
     */
    public ByteBuffer getColourData() {
        return colours;
    }

    /**
     * Copy the positions of points first to first + points − 1 into the mesh, in place: one
     * bulk copy an axis from the caller's planar array; the other points keep theirs. Points
     * past the mesh's last are not written (nor is anything from a negative first or count),
     * rather than fail on the render thread.
     *
     * @param first the first point to write (&ge;0)
     * @param planar all x, then all y, then all z, point first's x at index first (in metres,
     *     length &ge; 3·stride, not modified)
     * @param stride how far y is from x and z from y in planar (&ge; first + points)
     * @param points how many to copy (&ge;0, first + points at most {@link #getCount()};
     *     clamped to it)
     */
    public void writePositions(int first, float[] planar, int stride, int points) {
        int written = clamp(first, points);
        if (written == 0) {
            return;
        }
        if (stride < first + written || planar.length < 2 * stride + first + written) {
            throw new IllegalArgumentException("the planar array must hold " + written
                    + " points from " + first + " at a stride of " + stride + ", but holds "
                    + planar.length + " floats");
        }
        positions[0].put(first, planar, first, written);
        positions[1].put(first, planar, stride + first, written);
        positions[2].put(first, planar, 2 * stride + first, written);
    }

    /**
     * Set the colours of points first to first + points − 1, in place, one bulk copy (a put
     * per point into a direct buffer costs several times more). Points past the mesh's last
     * are not written.
     *
     * @param first the first point (&ge;0)
     * @param packed the colours as {@link #pack} makes them, from index 0 (length &ge;
     *     points, not modified)
     * @param points how many (&ge;0, first + points at most {@link #getCount()}; clamped to
     *     it)
     */
    public void writeColours(int first, int[] packed, int points) {
        int written = Math.min(clamp(first, points), packed.length);
        if (written > 0) {
            colourInts.put(first, packed, 0, written);
        }
    }

    /**
     * Set one point's colour, in place; a point not in the mesh is not written.
     *
     * @param index the point (from 0 to {@link #getCount()} − 1)
     * @param packed the colour as {@link #pack} makes it
     */
    public void writeColour(int index, int packed) {
        if (index >= 0 && index < count) {
            colourInts.put(index, packed);
        }
    }

    /**
     * Tell jME that the buffers changed, so they are uploaded before the next draw.
     */
    public void markUpdated() {
        for (VertexBuffer buffer : positionBuffers) {
            buffer.setUpdateNeeded();
        }
        colourBuffer.setUpdateNeeded();
    }

    /** @return how many of points from first lie in the mesh (0 if first is outside) */
    private int clamp(int first, int points) {
        if (first < 0 || first >= count || points <= 0) {
            return 0;
        }
        return Math.min(points, count - first);
    }

    private static int scale(int channel, float brightness) {
        return roundLevel(channel * brightness) & CHANNEL;
    }

    /**
     * {@link Math#round(float)} of a colour level from 0 to 255, in two instructions: the
     * largest float below one half added, then truncated. (Plus 0.5f would round
     * 0.49999997f up, the sum rounding to 1; a test compares this with Math.round at every
     * float from 0 to 255.) Math.round's own care for every float was 44 % of the fireworks'
     * colour pass.
     *
     * @param level the level (0 to 255)
     * @return the nearest integer, halves up
     */
    static int roundLevel(float level) {
        return (int) (level + JUST_BELOW_HALF);
    }
}

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
 * The mesh of a {@link PointCloudView} without its material: the position buffer (three
 * floats a point) and the colour buffer (four bytes a point, R, G, B, A), made once and
 * rewritten in place, so it can be filled and timed without a window or an asset manager.
 *
 * <p>Positions are written as a bulk copy of a range of points from a small array the caller
 * fills a chunk at a time (the mesh wants x, y, z per point, the particles are planar);
 * colours one point at a time, only where they change, as packed ints through a
 * little-endian int view of the byte buffer, so the int {@code R | G<<8 | B<<16 | A<<24}
 * lands as the bytes R, G, B, A whatever the machine's order. Nothing is allocated
 * after the constructor.
 */
public final class PointCloudMesh {

    /** A packed colour's alpha byte, opaque. */
    private static final int OPAQUE = 0xff << 24;
    private static final int CHANNEL = 0xff;
    /** The most points a caller should fill and write at a time (its scratch's size). */
    public static final int CHUNK_POINTS = 1024;

    private final int count;
    private final Mesh mesh = new Mesh();
    private final FloatBuffer positions;
    private final ByteBuffer colours;
    /** The colour bytes as little-endian ints: one int a point. */
    private final IntBuffer colourInts;
    private final VertexBuffer positionBuffer;
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
        positions = BufferUtils.createFloatBuffer(3 * count);
        colours = BufferUtils.createByteBuffer(4 * count);
        colourInts = colours.duplicate().order(ByteOrder.LITTLE_ENDIAN).asIntBuffer();
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
     * Access the position buffer (x, y, z per point), e.g. to compare its contents.
     *
     * @return the live buffer (in metres, do not modify)
     */
    public FloatBuffer getPositionData() {
        return positions;
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
     * Copy the positions of points first to first + points − 1 into the mesh, in place, one
     * bulk copy; the other points keep theirs. The caller interleaves a chunk at a time (at
     * most {@value #CHUNK_POINTS} points, 12 KiB, which stays in the processor's nearest
     * cache), so the memory a frame touches is its own arrays and the buffer, as for a plain
     * copy.
     *
     * @param first the first point to write (&ge;0)
     * @param xyz x, y, z per point, from index 0 (in metres, length &ge; 3·points, not
     *     modified)
     * @param points how many to copy (&ge;0, first + points at most {@link #getCount()})
     */
    public void writePositions(int first, float[] xyz, int points) {
        if (first < 0 || points < 0 || points > count - first) {
            throw new IllegalArgumentException("points to write must lie within 0 to "
                    + count + ", but were " + points + " from " + first);
        }
        positions.put(3 * first, xyz, 0, 3 * points);
    }

    /**
     * Set one point's colour, in place.
     *
     * @param index the point (from 0 to {@link #getCount()} − 1)
     * @param packed the colour as {@link #pack} makes it
     */
    public void writeColour(int index, int packed) {
        colourInts.put(index, packed);
    }

    /**
     * Tell jME that the buffers changed, so they are uploaded before the next draw.
     */
    public void markUpdated() {
        positionBuffer.setUpdateNeeded();
        colourBuffer.setUpdateNeeded();
    }

    private static int scale(int channel, float brightness) {
        return Math.round(channel * brightness) & CHANNEL;
    }
}

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
import java.nio.IntBuffer;

/**
 * The recent path of one particle: a bounded ring buffer of points drawn as a flat ribbon in
 * the x-y plane (wide enough to read on a projector, unlike a 1-pixel line), fading from the
 * oldest point to the newest.
 *
 * <p>All storage is allocated up front. {@link #add} writes one point into the ring;
 * {@link #refresh} copies the ring, oldest first, into the mesh's preallocated vertex buffer.
 * Slots not yet filled repeat the oldest point, which makes zero-area triangles.
 *
 * <p>Step dots: a demo adds one point per simulation step, so each point is also drawn as a
 * small square dot, a second geometry ({@link #getDotGeometry()}) in a lighter shade of the
 * trail's colour, fading like it. The dots' spacing is {@code |V|·h}: a longer step shows as
 * sparser dots. {@link #setDotsVisible} hides them.
 */
public final class Trail {

    private static final int FLOATS_PER_POINT = 3;
    /** Opacity of the oldest point; the newest is opaque. */
    private static final float OLDEST_ALPHA = 0.05f;
    /** A step dot's side, as a multiple of the ribbon's width. */
    private static final float DOT_WIDTHS = 1.4f;
    /** How far a dot's colour is mixed toward white, so it stands out on the ribbon. */
    private static final float DOT_LIGHTEN = 0.55f;
    private static final int DOT_CORNERS = 4;
    private static final int DOT_INDICES = 6;

    private final int capacity;
    private final float halfWidth;
    /** The ring: x, y, z of each point (in metres). */
    private final float[] ring;
    /** Index of the newest point in the ring (-1 when empty). */
    private int newest = -1;
    private int count;
    private boolean changed;
    private final FloatBuffer positions;
    private final VertexBuffer positionBuffer;
    private final Geometry geometry;
    /** Half a step dot's side (in metres). */
    private final float dotHalfSide;
    private final FloatBuffer dotPositions;
    private final VertexBuffer dotPositionBuffer;
    private final Geometry dotGeometry;
    private boolean dotsVisible = true;

    /**
     * Create an empty trail.
     *
     * @param name the geometry's name (not null)
     * @param capacity how many points it remembers (&ge;2)
     * @param widthMetres the ribbon's width (in metres, &gt;0)
     * @param color the colour of the newest point (not null, not modified)
     * @param material an Unshaded material to copy the settings from (not null, cloned)
     */
    public Trail(String name, int capacity, float widthMetres, ColorRGBA color,
            Material material) {
        if (capacity < 2) {
            throw new IllegalArgumentException("trail capacity must be >= 2, but was " + capacity);
        }
        if (!(widthMetres > 0f) || Float.isInfinite(widthMetres)) {
            throw new IllegalArgumentException(
                    "trail width (m) must be finite and > 0, but was " + widthMetres);
        }
        this.capacity = capacity;
        this.halfWidth = widthMetres / 2f;
        this.ring = new float[capacity * FLOATS_PER_POINT];
        int vertices = 2 * capacity;
        this.positions = BufferUtils.createFloatBuffer(vertices * FLOATS_PER_POINT);
        FloatBuffer colors = BufferUtils.createFloatBuffer(vertices * 4);
        for (int slot = 0; slot < capacity; ++slot) {
            // Slots are drawn oldest first, so a fixed ramp fades the tail.
            float alpha = OLDEST_ALPHA + (1f - OLDEST_ALPHA) * slot / (capacity - 1);
            for (int side = 0; side < 2; ++side) {
                colors.put(color.r).put(color.g).put(color.b).put(alpha * color.a);
            }
        }
        colors.flip();
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.TriangleStrip);
        mesh.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_POINT, positions);
        mesh.setBuffer(VertexBuffer.Type.Color, 4, colors);
        mesh.setStreamed();
        this.positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
        this.geometry = new Geometry(name, mesh);
        Material ribbon = material.clone();
        ribbon.setBoolean("VertexColor", true);
        ribbon.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        ribbon.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
        ribbon.getAdditionalRenderState().setDepthWrite(false);
        geometry.setMaterial(ribbon);
        geometry.setQueueBucket(RenderQueue.Bucket.Transparent);
        // The ribbon moves every frame; skip bounds and culling instead of recomputing them.
        geometry.setCullHint(Spatial.CullHint.Always);

        this.dotHalfSide = 0.5f * DOT_WIDTHS * widthMetres;
        this.dotPositions = BufferUtils.createFloatBuffer(
                capacity * DOT_CORNERS * FLOATS_PER_POINT);
        FloatBuffer dotColors = BufferUtils.createFloatBuffer(capacity * DOT_CORNERS * 4);
        IntBuffer dotIndices = BufferUtils.createIntBuffer(capacity * DOT_INDICES);
        for (int slot = 0; slot < capacity; ++slot) {
            float alpha = OLDEST_ALPHA + (1f - OLDEST_ALPHA) * slot / (capacity - 1);
            for (int corner = 0; corner < DOT_CORNERS; ++corner) {
                dotColors.put(lighten(color.r)).put(lighten(color.g)).put(lighten(color.b))
                        .put(alpha * color.a);
            }
            // Two triangles per dot: corners 0-1-2 and 0-2-3, counter-clockwise.
            int first = slot * DOT_CORNERS;
            dotIndices.put(first).put(first + 1).put(first + 2)
                    .put(first).put(first + 2).put(first + 3);
        }
        dotColors.flip();
        dotIndices.flip();
        Mesh dots = new Mesh();
        dots.setMode(Mesh.Mode.Triangles);
        dots.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_POINT, dotPositions);
        dots.setBuffer(VertexBuffer.Type.Color, 4, dotColors);
        dots.setBuffer(VertexBuffer.Type.Index, 3, dotIndices);
        dots.setStreamed();
        this.dotPositionBuffer = dots.getBuffer(VertexBuffer.Type.Position);
        this.dotGeometry = new Geometry(name + " step dots", dots);
        dotGeometry.setMaterial(ribbon);
        dotGeometry.setQueueBucket(RenderQueue.Bucket.Transparent);
        dotGeometry.setCullHint(Spatial.CullHint.Always);
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
     * Tint the whole ribbon, e.g. to fade an old shot's trail: the colour multiplies the
     * per-point colours. Give each tint its own colour object and pass another object to
     * change it (jME uploads a parameter only when it is set to a different value).
     * Allocates nothing.
     *
     * @param tint the tint, alpha included (not null, kept: do not modify it afterwards)
     */
    public void setTint(ColorRGBA tint) {
        if (tint == null) {
            throw new IllegalArgumentException("trail tint must be a colour, but was null");
        }
        geometry.getMaterial().setColor("Color", tint);
    }

    /**
     * Access the step dots' geometry, one dot per point, to attach beside the ribbon.
     *
     * @return the live geometry (not null)
     */
    public Geometry getDotGeometry() {
        return dotGeometry;
    }

    /**
     * Show or hide the step dots.
     *
     * @param visible true to show them
     */
    public void setDotsVisible(boolean visible) {
        dotsVisible = visible;
        changed = true;
    }

    /**
     * Test whether the step dots are shown.
     *
     * @return true if shown
     */
    public boolean areDotsVisible() {
        return dotsVisible;
    }

    /**
     * Return how many points the trail holds.
     *
     * @return the count (from 0 to the capacity)
     */
    public int size() {
        return count;
    }

    /**
     * Return the most points the trail remembers.
     *
     * @return the capacity (&ge;2)
     */
    public int getCapacity() {
        return capacity;
    }

    /**
     * Forget every point.
     */
    public void clear() {
        newest = -1;
        count = 0;
        changed = true;
    }

    /**
     * Forget the newest point, if any: a step taken back. Allocates nothing.
     */
    public void removeNewest() {
        if (count > 0) {
            newest = (newest - 1 + capacity) % capacity;
            --count;
            changed = true;
        }
    }

    /**
     * Return how far the trail is drawn on each side of its points: the ribbon's half width,
     * or a step dot's half side where that is more (dots shown or not).
     *
     * @return the half width (in metres, &gt;0)
     */
    public float getDrawnHalfWidth() {
        return Math.max(halfWidth, dotHalfSide);
    }

    /**
     * Remember a point, dropping the oldest when full.
     *
     * @param point the position (in metres, not null, not modified)
     */
    public void add(Vector3f point) {
        newest = (newest + 1) % capacity;
        int base = newest * FLOATS_PER_POINT;
        ring[base] = point.x;
        ring[base + 1] = point.y;
        ring[base + 2] = point.z;
        if (count < capacity) {
            ++count;
        }
        changed = true;
    }

    /**
     * Copy the i-th oldest point into storeResult.
     *
     * @param age 0 for the oldest point held, {@code size() − 1} for the newest
     * @param storeResult storage for the point (not null, modified)
     * @return storeResult
     */
    public Vector3f copyPoint(int age, Vector3f storeResult) {
        if (age < 0 || age >= count) {
            throw new IllegalArgumentException(
                    "age must be from 0 to " + (count - 1) + ", but was " + age);
        }
        int base = ringIndex(age) * FLOATS_PER_POINT;
        return storeResult.set(ring[base], ring[base + 1], ring[base + 2]);
    }

    /**
     * Write the points into the mesh if they changed since the last refresh.
     */
    public void refresh() {
        if (!changed) {
            return;
        }
        changed = false;
        boolean showDots = dotsVisible && count > 0;
        dotGeometry.setCullHint(showDots ? Spatial.CullHint.Never : Spatial.CullHint.Always);
        boolean showRibbon = count >= 2;
        geometry.setCullHint(showRibbon ? Spatial.CullHint.Never : Spatial.CullHint.Always);
        if (!showRibbon && !showDots) {
            return;
        }
        int padding = capacity - count;
        for (int slot = 0; slot < capacity; ++slot) {
            int age = slot < padding ? 0 : slot - padding;
            if (showRibbon) {
                writeSlot(slot, age);
            }
            if (showDots) {
                writeDot(slot, age, slot >= padding);
            }
        }
        if (showRibbon) {
            positions.rewind();
            positionBuffer.updateData(positions);
        }
        if (showDots) {
            dotPositions.rewind();
            dotPositionBuffer.updateData(dotPositions);
        }
    }

    /** Write the two ribbon vertices of one slot, offset sideways from the point. */
    private void writeSlot(int slot, int age) {
        int here = ringIndex(age) * FLOATS_PER_POINT;
        int before = ringIndex(Math.max(age - 1, 0)) * FLOATS_PER_POINT;
        int after = ringIndex(Math.min(age + 1, count - 1)) * FLOATS_PER_POINT;
        RibbonVertices.write(positions, slot, ring[here], ring[here + 1], ring[here + 2],
                ring[after] - ring[before], ring[after + 1] - ring[before + 1], halfWidth);
    }

    /** Write the four corners of one slot's dot; a slot not yet filled gets no area. */
    private void writeDot(int slot, int age, boolean filled) {
        int here = ringIndex(age) * FLOATS_PER_POINT;
        float x = ring[here];
        float y = ring[here + 1];
        float z = ring[here + 2];
        float d = filled ? dotHalfSide : 0f;
        int out = slot * DOT_CORNERS * FLOATS_PER_POINT;
        dotPositions.put(out, x - d).put(out + 1, y - d).put(out + 2, z);
        dotPositions.put(out + 3, x + d).put(out + 4, y - d).put(out + 5, z);
        dotPositions.put(out + 6, x + d).put(out + 7, y + d).put(out + 8, z);
        dotPositions.put(out + 9, x - d).put(out + 10, y + d).put(out + 11, z);
    }

    private static float lighten(float channel) {
        return channel + DOT_LIGHTEN * (1f - channel);
    }

    private int ringIndex(int age) {
        return (newest - (count - 1) + age + capacity) % capacity;
    }
}

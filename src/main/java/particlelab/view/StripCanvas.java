package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.shape.Quad;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;

/**
 * What the HUD's drawn strips share ({@link EnergyBars}, {@link LiveGraph}, {@link LensGraph}):
 * a node in the GUI bucket on a shaded background, texts attached to it, a switch to show or
 * hide it all, the round numbers their scales end at, and a preallocated mesh of quads
 * rewritten in place ({@link Quads}), so that drawing a frame allocates nothing.
 *
 * <p>The children are drawn in the order they are attached (the GUI bucket keeps it for equal
 * depths): the background first, then what the strip attaches, in its order.
 */
final class StripCanvas {

    /** The strips' background: dark, slightly see-through. */
    static final ColorRGBA BACKGROUND = new ColorRGBA(0.05f, 0.06f, 0.09f, 0.85f);
    /** Where an unused quad goes: off the screen (pixels). */
    static final float HIDDEN = -1000f;
    /** The round numbers a scale ends at, times a power of ten. */
    private static final double[] ROUND_STEPS = {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0};
    private static final int FLOATS_PER_VERTEX = 3;
    private static final int COLOR_FLOATS = 4;
    /** The quads' depth inside their geometry. */
    private static final float QUAD_Z = 0.5f;

    private final Node node;
    private final Geometry background;
    private final Material unshaded;

    /**
     * Create the node and its background, which covers nothing until placed.
     *
     * @param assetManager loads the materials (not null)
     * @param name the node's name; the background's is the name and " background" (not null)
     */
    StripCanvas(AssetManager assetManager, String name) {
        node = new Node(name);
        unshaded = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        Material shade = unshaded.clone();
        shade.setColor("Color", BACKGROUND);
        shade.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        background = new Geometry(name + " background", new Quad(1f, 1f));
        background.setMaterial(shade);
        background.setQueueBucket(RenderQueue.Bucket.Gui);
        node.attachChild(background);
    }

    /**
     * The round number at or above a value: 1, 1.5, 2, 3, 4, 5, 6 or 8 times a power of ten.
     *
     * @param value the value (finite; &le;0 or not finite gives 1)
     * @return the round number (&ge;value, &gt;0)
     */
    static double roundUp(double value) {
        if (!(value > 0.0) || Double.isInfinite(value)) {
            return 1.0;
        }
        double decade = Math.pow(10.0, Math.floor(Math.log10(value)));
        for (double step : ROUND_STEPS) {
            if (step * decade >= value) {
                return step * decade;
            }
        }
        return 10.0 * decade;
    }

    /** @return the node to attach to the GUI scene (live, not null) */
    Node getNode() {
        return node;
    }

    /**
     * Show or hide the strip.
     *
     * @param visible true to show it
     */
    void setVisible(boolean visible) {
        node.setCullHint(visible ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
    }

    /** @return true if shown */
    boolean isVisible() {
        return node.getCullHint() != Spatial.CullHint.Always;
    }

    /**
     * Place the background, relative to the node.
     *
     * @param x its left (in pixels)
     * @param y its bottom (in pixels)
     * @param width its width (in pixels)
     * @param height its height (in pixels)
     */
    void placeBackground(float x, float y, float width, float height) {
        background.setLocalTranslation(x, y, 0f);
        background.setLocalScale(width, height, 1f);
    }

    /** Shrink the background to nothing. */
    void hideBackground() {
        background.setLocalScale(0f);
    }

    /**
     * A new unshaded material, for a geometry the strip attaches itself.
     *
     * @return the material (new)
     */
    Material newUnshaded() {
        return unshaded.clone();
    }

    /**
     * Attach a new text to the node.
     *
     * @param font the font (not null)
     * @param color the colour (not null)
     * @return the text (attached, empty)
     */
    HudText addText(BitmapFont font, ColorRGBA color) {
        HudText text = new HudText(font, color);
        text.setQueueBucket(RenderQueue.Bucket.Gui);
        node.attachChild(text);
        return text;
    }

    /**
     * Attach a mesh of quads, each hidden until written, each vertex coloured.
     *
     * @param name the geometry's name (not null)
     * @param count how many quads (&gt;0, at most 16383: the indices are shorts)
     * @return the quads (attached)
     */
    Quads addQuads(String name, int count) {
        Quads quads = new Quads(count);
        Material material = newUnshaded();
        material.setBoolean("VertexColor", true);
        Geometry geometry = new Geometry(name, quads.mesh);
        geometry.setMaterial(material);
        geometry.setQueueBucket(RenderQueue.Bucket.Gui);
        geometry.setCullHint(Spatial.CullHint.Never);
        node.attachChild(geometry);
        return quads;
    }

    /**
     * A preallocated mesh of quads, two triangles each, rewritten in place: {@link #write}
     * and {@link #color} change the buffers, {@link #upload} hands them to the renderer.
     * Allocates nothing after construction.
     */
    static final class Quads {

        private final int count;
        private final Mesh mesh = new Mesh();
        private final FloatBuffer positions;
        private final FloatBuffer colors;
        private final VertexBuffer positionBuffer;
        private final VertexBuffer colorBuffer;

        private Quads(int count) {
            if (count <= 0 || 4 * count > Short.MAX_VALUE) {
                throw new IllegalArgumentException("quads must be from 1 to "
                        + Short.MAX_VALUE / 4 + ", but was " + count);
            }
            this.count = count;
            positions = BufferUtils.createFloatBuffer(count * 4 * FLOATS_PER_VERTEX);
            colors = BufferUtils.createFloatBuffer(count * 4 * COLOR_FLOATS);
            ShortBuffer indices = BufferUtils.createShortBuffer(count * 6);
            for (int q = 0; q < count; ++q) {
                short base = (short) (4 * q);
                indices.put(base).put((short) (base + 1)).put((short) (base + 2))
                        .put(base).put((short) (base + 2)).put((short) (base + 3));
                hide(q);
            }
            indices.flip();
            mesh.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_VERTEX, positions);
            mesh.setBuffer(VertexBuffer.Type.Color, COLOR_FLOATS, colors);
            mesh.setBuffer(VertexBuffer.Type.Index, 3, indices);
            mesh.setStreamed();
            positionBuffer = mesh.getBuffer(VertexBuffer.Type.Position);
            colorBuffer = mesh.getBuffer(VertexBuffer.Type.Color);
        }

        /** @return how many quads the mesh holds */
        int size() {
            return count;
        }

        /**
         * Write an upright rectangle.
         *
         * @param quad which (from 0, &lt; size)
         * @param left its left (in pixels)
         * @param bottom its bottom (in pixels)
         * @param right its right (in pixels)
         * @param top its top (in pixels)
         */
        void write(int quad, float left, float bottom, float right, float top) {
            int at = quad * 4 * FLOATS_PER_VERTEX;
            positions.put(at, left).put(at + 1, bottom).put(at + 2, QUAD_Z)
                    .put(at + 3, right).put(at + 4, bottom).put(at + 5, QUAD_Z)
                    .put(at + 6, right).put(at + 7, top).put(at + 8, QUAD_Z)
                    .put(at + 9, left).put(at + 10, top).put(at + 11, QUAD_Z);
        }

        /**
         * Write a segment as a thin quad: its ends moved sideways by half its thickness.
         *
         * @param quad which (from 0, &lt; size)
         * @param x0 the first end's x (in pixels)
         * @param y0 the first end's y (in pixels)
         * @param x1 the second end's x (in pixels)
         * @param y1 the second end's y (in pixels)
         * @param half half the thickness (in pixels, &ge;0)
         */
        void writeSegment(int quad, float x0, float y0, float x1, float y1, float half) {
            float dx = x1 - x0;
            float dy = y1 - y0;
            float length = (float) Math.sqrt(dx * dx + dy * dy);
            float nx = length > 0f ? -dy / length * half : 0f;
            float ny = length > 0f ? dx / length * half : half;
            int at = quad * 4 * FLOATS_PER_VERTEX;
            positions.put(at, x0 + nx).put(at + 1, y0 + ny).put(at + 2, QUAD_Z)
                    .put(at + 3, x0 - nx).put(at + 4, y0 - ny).put(at + 5, QUAD_Z)
                    .put(at + 6, x1 - nx).put(at + 7, y1 - ny).put(at + 8, QUAD_Z)
                    .put(at + 9, x1 + nx).put(at + 10, y1 + ny).put(at + 11, QUAD_Z);
        }

        /**
         * Move a quad off the screen.
         *
         * @param quad which (from 0, &lt; size)
         */
        void hide(int quad) {
            write(quad, HIDDEN, HIDDEN, HIDDEN, HIDDEN);
        }

        /**
         * Colour a quad's four vertices.
         *
         * @param quad which (from 0, &lt; size)
         * @param color the colour (not null, not kept)
         */
        void color(int quad, ColorRGBA color) {
            int at = quad * 4 * COLOR_FLOATS;
            for (int v = 0; v < 4; ++v) {
                colors.put(at + 4 * v, color.r).put(at + 4 * v + 1, color.g)
                        .put(at + 4 * v + 2, color.b).put(at + 4 * v + 3, color.a);
            }
        }

        /** Hand the positions written since the last upload to the renderer. */
        void upload() {
            positionBuffer.updateData(positions);
        }

        /** Hand the positions and the colours to the renderer. */
        void uploadWithColors() {
            positionBuffer.updateData(positions);
            colorBuffer.updateData(colors);
        }

        /**
         * Read one coordinate back, for tests.
         *
         * @param quad which (from 0, &lt; size)
         * @param vertex which corner (0 to 3: left bottom, right bottom, right top, left top)
         * @param axis 0 for x, 1 for y
         * @return the coordinate (in pixels)
         */
        float coordinate(int quad, int vertex, int axis) {
            return positions.get((quad * 4 + vertex) * FLOATS_PER_VERTEX + axis);
        }
    }
}

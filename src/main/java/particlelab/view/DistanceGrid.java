package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.shape.Quad;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.List;

/**
 * The backdrop of a side view: graph paper in the x-y plane behind the particles, the ground
 * as a band below {@code y = 0}, and distance marks ("20 m") along the ground and up the left
 * edge, which the scene's layout sizes and places ({@link #getLabels}). Built once; nothing in
 * it changes per frame.
 */
public final class DistanceGrid {

    private static final ColorRGBA LINE_COLOR = new ColorRGBA(0.30f, 0.34f, 0.42f, 1f);
    private static final ColorRGBA MAJOR_COLOR = new ColorRGBA(0.45f, 0.50f, 0.60f, 1f);
    private static final ColorRGBA GROUND_COLOR = new ColorRGBA(0.16f, 0.22f, 0.14f, 1f);
    private static final ColorRGBA GROUND_EDGE_COLOR = new ColorRGBA(0.55f, 0.75f, 0.45f, 1f);
    private static final ColorRGBA LABEL_COLOR = new ColorRGBA(0.85f, 0.88f, 0.95f, 1f);
    /** The backdrop sits this far behind the particles' plane (in metres). */
    private static final float BACK_Z = -0.05f;

    private final Node node = new Node("distance grid");
    private final List<SceneLabel> labels = new ArrayList<>();
    private final Geometry ground;
    private final float left;
    /** Each ground mark's value in mark spacings (0 for 0 m), in {@link #getLabels} order. */
    private final int[] groundMarkIndices;
    /** The distance between two neighbouring ground marks (in metres). */
    private final float markSpacing;

    /**
     * Build a grid.
     *
     * @param assetManager loads materials (not null)
     * @param font the label font (not null)
     * @param xMin the left edge (in metres)
     * @param xMax the right edge (in metres, &gt;xMin)
     * @param yMin the bottom of the ground band (in metres, &lt;0)
     * @param yMax the top edge (in metres, &gt;0)
     * @param spacing the distance between lines (in metres, &gt;0)
     * @param labelEvery label every this many lines (&ge;1)
     */
    public DistanceGrid(AssetManager assetManager, BitmapFont font, float xMin, float xMax,
            float yMin, float yMax, float spacing, int labelEvery) {
        if (!(xMax > xMin && yMax > 0f && yMin < 0f && spacing > 0f && labelEvery >= 1)) {
            throw new IllegalArgumentException("grid needs xMin < xMax, yMin < 0 < yMax,"
                    + " spacing > 0 and labelEvery >= 1, but got x " + xMin + ".." + xMax
                    + ", y " + yMin + ".." + yMax + ", spacing " + spacing
                    + ", labelEvery " + labelEvery);
        }
        Material unshaded = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        int firstColumn = (int) Math.ceil(xMin / spacing);
        int lastColumn = (int) Math.floor(xMax / spacing);
        int lastRow = (int) Math.floor(yMax / spacing);
        node.attachChild(lines("grid lines", unshaded, LINE_COLOR, firstColumn, lastColumn,
                lastRow, spacing, xMin, xMax, yMax, labelEvery, false));
        node.attachChild(lines("grid major lines", unshaded, MAJOR_COLOR, firstColumn,
                lastColumn, lastRow, spacing, xMin, xMax, yMax, labelEvery, true));

        float width = xMax - xMin;
        left = xMin;
        // A unit-high band, scaled to the depth the frame shows (setGroundDepth).
        ground = new Geometry("ground", new Quad(width, 1f));
        Material groundMaterial = unshaded.clone();
        groundMaterial.setColor("Color", GROUND_COLOR);
        ground.setMaterial(groundMaterial);
        setGroundDepth(-yMin);
        node.attachChild(ground);

        float edgeHeight = spacing * 0.06f;
        Geometry edge = new Geometry("ground edge", new Quad(width, edgeHeight));
        Material edgeMaterial = unshaded.clone();
        edgeMaterial.setColor("Color", GROUND_EDGE_COLOR);
        edge.setMaterial(edgeMaterial);
        edge.setLocalTranslation(xMin, -edgeHeight / 2f, BACK_Z / 2f);
        node.attachChild(edge);

        int marks = 0;
        for (int column = firstColumn; column <= lastColumn; ++column) {
            if (column % labelEvery == 0) {
                ++marks;
            }
        }
        groundMarkIndices = new int[marks];
        markSpacing = spacing * labelEvery;
        for (int column = firstColumn; column <= lastColumn; ++column) {
            if (column % labelEvery == 0) {
                groundMarkIndices[labels.size()] = column / labelEvery;
                addLabel(font, column * spacing, 0f, SceneLabel.Anchor.BELOW);
            }
        }
        for (int row = labelEvery; row <= lastRow; row += labelEvery) {
            addLabel(font, xMin, row * spacing, SceneLabel.Anchor.ABOVE_RIGHT);
        }
    }

    /**
     * Make the ground band as deep as the frame shows below {@code y = 0}.
     *
     * @param depthMetres the band's depth (in metres, &gt;0)
     */
    public void setGroundDepth(float depthMetres) {
        ground.setLocalScale(1f, depthMetres, 1f);
        ground.setLocalTranslation(left, -depthMetres, BACK_Z);
    }

    /**
     * Access the distance marks, along the ground first, then up the left edge; the scene's
     * layout sizes and places them.
     *
     * @return the live list (not null, do not modify)
     */
    public List<SceneLabel> getLabels() {
        return labels;
    }

    /** @return how many of {@link #getLabels} are marks along the ground (they come first) */
    public int countGroundMarks() {
        return groundMarkIndices.length;
    }

    /**
     * Return a ground mark's value in mark spacings, for {@link MarkThinning#isShown}.
     *
     * @param mark 0 to {@link #countGroundMarks()} - 1, in {@link #getLabels} order
     * @return the value divided by {@link #getMarkSpacing()} (0 for 0 m)
     */
    public int getGroundMarkIndex(int mark) {
        return groundMarkIndices[mark];
    }

    /** @return the distance between two neighbouring ground marks (in metres, &gt;0) */
    public float getMarkSpacing() {
        return markSpacing;
    }

    /**
     * Access the node holding the grid.
     *
     * @return the live node (not null)
     */
    public Node getNode() {
        return node;
    }

    private static String metres(float value) {
        return Math.round(value) + " m";
    }

    private void addLabel(BitmapFont font, float x, float y, SceneLabel.Anchor anchor) {
        float value = anchor == SceneLabel.Anchor.BELOW ? x : y;
        SceneLabel label = new SceneLabel(font, metres(value), LABEL_COLOR, x, y, anchor);
        labels.add(label);
        node.attachChild(label.getText());
    }

    private static Geometry lines(String name, Material unshaded, ColorRGBA color,
            int firstColumn, int lastColumn, int lastRow, float spacing, float xMin, float xMax,
            float yMax, int labelEvery, boolean major) {
        int segments = 0;
        for (int column = firstColumn; column <= lastColumn; ++column) {
            if ((column % labelEvery == 0) == major) {
                ++segments;
            }
        }
        for (int row = 1; row <= lastRow; ++row) {
            if ((row % labelEvery == 0) == major) {
                ++segments;
            }
        }
        FloatBuffer points = BufferUtils.createFloatBuffer(Math.max(segments, 1) * 6);
        for (int column = firstColumn; column <= lastColumn; ++column) {
            if ((column % labelEvery == 0) == major) {
                float x = column * spacing;
                points.put(x).put(0f).put(BACK_Z).put(x).put(yMax).put(BACK_Z);
            }
        }
        for (int row = 1; row <= lastRow; ++row) {
            if ((row % labelEvery == 0) == major) {
                float y = row * spacing;
                points.put(xMin).put(y).put(BACK_Z).put(xMax).put(y).put(BACK_Z);
            }
        }
        if (segments == 0) {
            points.put(new float[6]);
        }
        points.flip();
        Mesh mesh = new Mesh();
        mesh.setMode(Mesh.Mode.Lines);
        mesh.setBuffer(VertexBuffer.Type.Position, 3, points);
        mesh.updateBound();
        Geometry geometry = new Geometry(name, mesh);
        Material material = unshaded.clone();
        material.setColor("Color", color);
        geometry.setMaterial(material);
        return geometry;
    }
}

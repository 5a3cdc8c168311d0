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
    /**
     * The most grid lines across the grid, and the most up it: past it the spacing grows
     * tenfold until the lines fit, so the line meshes and the marks stay bounded whatever
     * region a frame asks for. A window whose scene was left a pixel high (a small window,
     * the panel open, a large HUD factor) framed a region 3·10^9 spacings wide: the lines
     * overflowed their count and the buffer it sized (issue 36). A frame of any window
     * the HUD leaves room in holds a few hundred at most.
     */
    public static final int MAX_LINES = 1000;
    /** How much the spacing grows at a time when the lines would not fit: 1, 2, 5 stay so. */
    private static final float SPACING_GROWTH = 10f;

    private final Node node = new Node("distance grid");
    private final List<SceneLabel> labels = new ArrayList<>();
    private final Geometry ground;
    private final float left;
    /** Each ground mark's value in mark spacings (0 for 0 m), in {@link #getLabels} order. */
    private final int[] groundMarkIndices;
    /** The distance between two neighbouring ground marks (in metres). */
    private final float markSpacing;
    /** The distance between two neighbouring lines (in metres). */
    private final float spacing;

    /**
     * Build a grid.
     *
     * @param assetManager loads materials (not null)
     * @param font the label font (not null)
     * @param xMin the left edge (in metres)
     * @param xMax the right edge (in metres, &gt;xMin)
     * @param yMin the bottom of the ground band (in metres, &lt;0)
     * @param yMax the top edge (in metres, &gt;0)
     * @param asked the distance between lines (in metres, &gt;0; grown tenfold until at
     *     most {@link #MAX_LINES} lines go across and up)
     * @param labelEvery label every this many lines (&ge;1)
     */
    public DistanceGrid(AssetManager assetManager, BitmapFont font, float xMin, float xMax,
            float yMin, float yMax, float asked, int labelEvery) {
        if (!(xMax > xMin && yMax > 0f && yMin < 0f && asked > 0f && labelEvery >= 1)
                || Float.isInfinite(xMax - xMin) || Float.isInfinite(yMin)
                || Float.isInfinite(yMax) || Float.isInfinite(asked)) {
            throw new IllegalArgumentException("grid needs finite xMin < xMax, yMin < 0 < yMax,"
                    + " spacing > 0 and labelEvery >= 1, but got x " + xMin + ".." + xMax
                    + ", y " + yMin + ".." + yMax + ", spacing " + asked
                    + ", labelEvery " + labelEvery);
        }
        float spacing = asked;
        while (countColumns(xMin, xMax, spacing) > MAX_LINES
                || Math.floor((double) yMax / spacing) > MAX_LINES) {
            spacing *= SPACING_GROWTH;
        }
        this.spacing = spacing;
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
     * Return the distance between two neighbouring lines: the spacing asked, or ten, a
     * hundred, ... times it where the region would hold more than {@link #MAX_LINES}.
     *
     * @return the spacing (in metres, &gt;0)
     */
    public float getSpacing() {
        return spacing;
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
        return Math.round((double) value) + " m";
    }

    /** The lines from xMin to xMax at a spacing, in double: no int overflows (&ge;0). */
    private static double countColumns(float xMin, float xMax, float spacing) {
        return Math.floor((double) xMax / spacing) - Math.ceil((double) xMin / spacing) + 1.0;
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

package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.AssetManager;
import com.jme3.asset.DesktopAssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import java.nio.Buffer;
import java.nio.FloatBuffer;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * Issue 36: a {@code java.nio.BufferOverflowException} (a put into a direct buffer beyond its
 * capacity) was seen on the render thread. Every direct buffer the app writes is sized for
 * the most it can be given, or grows, or clamps what it is given: here each is built and
 * written, with no display, at its boundary and one past it, and must neither throw nor
 * leave a buffer whose data runs past its capacity.
 *
 * <p>What bounds each: the HUD's glyph mesh grows with its text up to
 * {@link HudText#MAX_GLYPHS} (16-bit indices) and shows the first that many characters of a
 * longer text; a trail is a ring of its capacity (the oldest point goes); a kept shot copies
 * the newest points of a trail up to its own capacity; a curve draws at most its capacity of
 * points; the point cloud writes only points of its mesh; the live graph keeps
 * {@link LiveGraph#CAPACITY} samples by thinning; an arrow, a box and a graph's frame have a
 * fixed number of vertices, whatever the numbers; jME's {@link BitmapText} (scene labels,
 * the panel's Lemur labels) grows its buffers itself.
 */
class BufferBoundsTest {

    private static final AssetManager ASSETS = new DesktopAssetManager(true);
    private static final Material UNSHADED = new Material(ASSETS,
            "Common/MatDefs/Misc/Unshaded.j3md");
    private static final BitmapFont FONT = HudFont.load(ASSETS);

    @Test
    void hudTextGrowsPastItsCapacityAndClampsPastItsLargestText() {
        HudText text = new HudText(FONT, ColorRGBA.White);
        int[] lengths = {63, 64, 65, 129, HudText.MAX_GLYPHS - 1, HudText.MAX_GLYPHS,
            HudText.MAX_GLYPHS + 1, 2 * HudText.MAX_GLYPHS + 3};
        for (int length : lengths) {
            String shown = glyphs(length);
            text.setText(shown);
            int kept = Math.min(length, HudText.MAX_GLYPHS);
            assertEquals(shown.substring(0, kept), text.getText(), length + " characters");
            // Every character of the repeated pattern but the line breaks has a glyph.
            assertEquals(kept - kept / 40, text.countGlyphs(), length + " characters");
            assertBuffersHold(meshOf(text), kept * 4, length + " characters");
        }
        // Setting the same over-long text again changes nothing: it compares what it shows.
        assertEquals(false, text.setText(glyphs(2 * HudText.MAX_GLYPHS + 3)));
    }

    @Test
    void aTrailPastItsCapacityDropsItsOldestPoint() {
        int capacity = 5;
        Trail trail = new Trail("trail", capacity, 0.1f, ColorRGBA.Red, UNSHADED);
        Vector3f point = new Vector3f();
        for (int i = 0; i < 3 * capacity + 1; ++i) {
            trail.add(point.set(i, 2f * i, 0f));
            trail.refresh();
            assertEquals(Math.min(i + 1, capacity), trail.size());
            assertBuffersHold(trail.getGeometry().getMesh(), 2 * capacity, "ribbon at " + i);
            assertBuffersHold(trail.getDotGeometry().getMesh(), 4 * capacity, "dots at " + i);
        }
        // The newest five of sixteen points: 11 to 15.
        assertEquals(11f, trail.copyPoint(0, point).x);
        assertEquals(15f, trail.copyPoint(capacity - 1, point).x);
        for (int i = 0; i < capacity + 2; ++i) {
            trail.removeNewest();
            trail.refresh();
        }
        assertEquals(0, trail.size());
    }

    @Test
    void aKeptShotCopiesTheNewestPointsOfALongerTrail() {
        int capacity = 4;
        ShotTrail kept = new ShotTrail("kept", capacity, 0.1f, UNSHADED);
        for (int points = capacity - 1; points <= capacity + 1; ++points) {
            Trail trail = new Trail("trail", capacity + 1, 0.1f, ColorRGBA.Red, UNSHADED);
            for (int i = 0; i < points; ++i) {
                trail.add(new Vector3f(i, 0f, 0f));
            }
            kept.copyFrom(trail);
            assertEquals(Math.min(points, capacity), kept.size(), points + " points");
            assertBuffersHold(kept.getGeometry().getMesh(), 2 * capacity, points + " points");
        }
    }

    /** Before issue 36 a count past the capacity threw on the render thread. */
    @Test
    void aCurveDrawsAtMostItsCapacityOfPoints() {
        int capacity = 6;
        CurveView curve = new CurveView(ASSETS, "curve", capacity, 0.1f, ColorRGBA.Blue);
        float[] xs = new float[capacity + 3];
        float[] ys = new float[capacity + 3];
        for (int i = 0; i < xs.length; ++i) {
            xs[i] = i;
            ys[i] = i * i;
        }
        for (int count : new int[] {-1, 0, 1, 2, capacity, capacity + 1, capacity + 3,
            capacity + 4}) {
            curve.setPoints(xs, ys, count);
            assertBuffersHold(curve.getGeometry().getMesh(), 2 * capacity, count + " points");
            boolean drawn = curve.getGeometry().getCullHint() != Spatial.CullHint.Always;
            assertEquals(count >= 2, drawn, count + " points");
        }
        // Past the capacity the first points are drawn: the last slot is the capacity's.
        curve.setPoints(xs, ys, capacity + 3);
        float[] positions = floats(curve.getGeometry().getMesh());
        float lastX = (positions[positions.length - 6] + positions[positions.length - 3]) / 2f;
        // The two vertices straddle the point, so their mean is it (to float rounding).
        assertEquals(capacity - 1, lastX, 1e-5f);
    }

    /** Before issue 36 points past the mesh's count threw on the render thread. */
    @Test
    void thePointCloudWritesOnlyPointsOfItsMesh() {
        int count = 8;
        PointCloudMesh mesh = new PointCloudMesh(count, 10f);
        float[] planar = new float[3 * (count + 4)];
        Arrays.fill(planar, 1.5f);
        int[] colours = new int[count + 4];
        Arrays.fill(colours, PointCloudMesh.pack(0xffffff, 1f));
        for (int points = count - 1; points <= count + 1; ++points) {
            mesh.writePositions(0, planar, count + 4, points);
            mesh.writeColours(0, colours, points);
            mesh.writePositions(count - 1, planar, count + 4, points);
            mesh.writeColours(count - 1, colours, points);
        }
        mesh.writeColour(count - 1, colours[0]);
        mesh.writeColour(count, colours[0]);
        mesh.writePositions(count, planar, count + 4, 1);
        mesh.writeColours(count + 3, colours, 1);
        mesh.markUpdated();
        for (int axis = 0; axis < 3; ++axis) {
            Buffer data = mesh.getPositionData(axis);
            assertEquals(count, data.capacity());
            assertEquals(1.5f, mesh.getPositionData(axis).get(count - 1));
        }
        assertEquals(4 * count, mesh.getColourData().capacity());
        assertBuffersHold(mesh.getMesh(), count, "the point cloud");
    }

    @Test
    void theLiveGraphThinsPastItsCapacityAndWritesAFixedMesh() {
        LiveGraph graph = new LiveGraph(ASSETS, FONT, new ColorRGBA[] {ColorRGBA.Red,
            ColorRGBA.Green, ColorRGBA.Blue});
        graph.layOut(new ScreenRect(10f, 10f, 400f, 200f), 19f);
        float[] heights = {1f, 2f, 3f};
        float[] exact = {Float.NaN, 2f, 1e30f};
        int samples = 4 * LiveGraph.CAPACITY + 1;
        for (int i = 0; i < samples; ++i) {
            graph.record(i / 60f, heights, heights, exact, exact);
            if (i % 97 == 0 || i >= samples - 2) {
                graph.refresh();
            }
        }
        assertTrue(graph.size() <= LiveGraph.CAPACITY, graph.size() + " samples");
        assertTrue(graph.countDrawn() <= LiveGraph.CAPACITY + 1, graph.countDrawn() + " drawn");
        // One area of nothing and one of the largest window, with the samples kept.
        graph.layOut(new ScreenRect(0f, 0f, 0f, 0f), 19f);
        graph.refresh();
        graph.layOut(new ScreenRect(0f, 0f, 3840f, 2160f), 80f);
        graph.refresh();
        for (Spatial child : graph.getNode().getChildren()) {
            if (child instanceof Geometry) {
                Mesh mesh = ((Geometry) child).getMesh();
                assertBuffersHold(mesh, mesh.getVertexCount(), child.getName());
            }
        }
    }

    @Test
    void anArrowHasItsSevenVerticesWhateverTheVelocity() {
        VelocityArrow arrow = new VelocityArrow("arrow", 0.1f, 0.5f, ColorRGBA.Yellow,
                UNSHADED);
        arrow.setFloor(0f);
        Vector3f start = new Vector3f(1f, 2f, 0f);
        float[] speeds = {0f, 1e-6f, 1f, 1e20f, Float.MAX_VALUE, Float.POSITIVE_INFINITY,
            Float.NaN, -1e20f};
        for (float vx : speeds) {
            for (float vy : speeds) {
                arrow.update(start, new Vector3f(vx, vy, 0f));
                assertBuffersHold(arrow.getGeometry().getMesh(), 7, vx + ", " + vy);
            }
        }
    }

    @Test
    void aBoxHasItsTwentyFourVerticesWhateverTheRotation() {
        BoxView box = new BoxView(ASSETS, "box", new Vector3f(1f, 2f, 3f), ColorRGBA.Gray);
        Matrix3f[] rotations = {Matrix3f.IDENTITY, new Matrix3f(1e20f, 0f, 0f, 0f, 0f, 0f, 0f,
            0f, Float.NaN), new Matrix3f()};
        for (Matrix3f r : rotations) {
            box.update(r, new Vector3f(Float.MAX_VALUE, 0f, 0f));
            box.update(r, Vector3f.ZERO, Matrix3f.IDENTITY, Vector3f.ZERO, 2f);
            assertBuffersHold(box.getGeometry().getMesh(), 24, r.toString());
        }
    }

    /**
     * Issue 36's BufferOverflowException, as a window recorded it (DistanceGrid.lines, at a
     * layout): a small window with the panel open and a large HUD factor left the scene a
     * pixel high, and the frame stretched to that shape asked for a grid about 3·10^9
     * spacings wide. Counted in an int, its lines wrapped to a negative count, the buffer
     * was sized for one line and the second overflowed it. The grid now grows its spacing
     * tenfold until at most {@link DistanceGrid#MAX_LINES} lines go each way.
     */
    @Test
    void aGridOverAVastRegionGrowsItsSpacingAndHoldsItsLines() {
        DistanceGrid grid = new DistanceGrid(ASSETS, FONT, -1.5e9f, 1.5e9f, -4.4e6f, 20f,
                1f, 5);
        // 3·10^9 m at 10^6 m would be 3001 lines, at 10^7 m 301 (from -150 to 150).
        assertEquals(1e7f, grid.getSpacing());
        assertEquals(5e7f, grid.getMarkSpacing());
        assertEquals(301, countLines(grid));
        // The ground marks every 5th line, -150 to 150 in steps of 5; nothing up (20 m).
        assertEquals(61, grid.countGroundMarks());
        assertEquals(61, grid.getLabels().size());
        assertEquals("-1500000000 m", grid.getLabels().get(0).getText().getText());
        assertEquals("1500000000 m", grid.getLabels().get(60).getText().getText());
    }

    /**
     * At its boundary: {@link DistanceGrid#MAX_LINES} lines across (or up) keep the spacing
     * asked; one more grows it tenfold. Each line mesh holds its lines, two vertices each.
     */
    @Test
    void aGridKeepsItsSpacingUpToItsMostLinesAndGrowsItOnePast() {
        int most = DistanceGrid.MAX_LINES;
        // Lines at x = 1 to most, and none up (y up to 0.5).
        DistanceGrid across = new DistanceGrid(ASSETS, FONT, 0.5f, most + 0.5f, -1f, 0.5f,
                1f, 5);
        assertEquals(1f, across.getSpacing());
        assertEquals(most, countLines(across));
        // One more across: every 10 m, x = 10 to 1000.
        DistanceGrid pastAcross = new DistanceGrid(ASSETS, FONT, 0.5f, most + 1.5f, -1f,
                0.5f, 1f, 5);
        assertEquals(10f, pastAcross.getSpacing());
        assertEquals(most / 10, countLines(pastAcross));
        // Up: lines at y = 1 to most (and x = 1 across).
        DistanceGrid up = new DistanceGrid(ASSETS, FONT, 0.5f, 1.5f, -1f, most, 1f, 5);
        assertEquals(1f, up.getSpacing());
        assertEquals(most + 1, countLines(up));
        DistanceGrid pastUp = new DistanceGrid(ASSETS, FONT, 0.5f, 1.5f, -1f, most + 1f, 1f,
                5);
        assertEquals(10f, pastUp.getSpacing());
        // y = 10 to 1000, and no column at 10 m steps between 0.5 and 1.5.
        assertEquals(most / 10, countLines(pastUp));
    }

    /** A region no grid can cover is refused where it enters, naming it. */
    @Test
    void aGridRefusesARegionWithNoFiniteSize() {
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> new DistanceGrid(ASSETS, FONT, -3e38f, 3e38f, -1f, 20f, 1f, 5));
        assertTrue(refused.getMessage().contains("x -3.0E38..3.0E38"), refused.getMessage());
        refused = assertThrows(IllegalArgumentException.class,
                () -> new DistanceGrid(ASSETS, FONT, 0f, 10f, -1f, Float.POSITIVE_INFINITY,
                        1f, 5));
        assertTrue(refused.getMessage().contains("y -1.0..Infinity"), refused.getMessage());
    }

    /** jME's own text (scene labels, the panel's labels) grows its buffers as text grows. */
    @Test
    void jmeBitmapTextGrowsWithItsText() {
        BitmapText text = new BitmapText(FONT);
        for (int length : new int[] {1, 64, 65, 5000, 3, 5001}) {
            text.setText(glyphs(length));
            text.updateLogicalState(0f);
            Geometry glyphs = (Geometry) text.getChild(0);
            assertBuffersHold(glyphs.getMesh(), glyphs.getMesh().getVertexCount(),
                    length + " characters");
        }
    }

    /**
     * Count a grid's lines, checking that each line mesh holds two vertices a line within
     * its buffers (a mesh with no line holds one of zero length).
     */
    private static int countLines(DistanceGrid grid) {
        int lines = 0;
        for (Spatial child : grid.getNode().getChildren()) {
            // The two line meshes, by their names (the marks' texts have none).
            if (!"grid lines".equals(child.getName())
                    && !"grid major lines".equals(child.getName())) {
                continue;
            }
            Mesh mesh = ((Geometry) child).getMesh();
            assertEquals(Mesh.Mode.Lines, mesh.getMode());
            assertBuffersHold(mesh, mesh.getVertexCount(), child.getName());
            float[] positions = floats(mesh);
            boolean none = true;
            for (float value : positions) {
                none &= value == 0f;
            }
            lines += none ? 0 : mesh.getVertexCount() / 2;
        }
        return lines;
    }

    /** A text of printable characters and a line break every 40. */
    private static String glyphs(int length) {
        StringBuilder text = new StringBuilder(length);
        for (int i = 0; i < length; ++i) {
            text.append(i % 40 == 39 ? '\n' : (char) ('A' + i % 26));
        }
        return text.toString();
    }

    private static Mesh meshOf(HudText text) {
        return ((Geometry) text.getChild(0)).getMesh();
    }

    /** The positions of a mesh, as written. */
    private static float[] floats(Mesh mesh) {
        FloatBuffer data = (FloatBuffer) mesh.getBuffer(
                VertexBuffer.Type.Position).getData();
        float[] out = new float[data.limit()];
        for (int i = 0; i < out.length; ++i) {
            out[i] = data.get(i);
        }
        return out;
    }

    /**
     * Check that every vertex buffer of a mesh holds at least a number of vertices, within
     * its capacity, and that every index names a vertex its position buffer holds.
     */
    private static void assertBuffersHold(Mesh mesh, int vertices, String what) {
        VertexBuffer positions = mesh.getBuffer(VertexBuffer.Type.Position);
        int held = positions.getData().limit() / positions.getNumComponents();
        for (VertexBuffer buffer : mesh.getBufferList()) {
            Buffer data = buffer.getData();
            assertTrue(data.limit() <= data.capacity(), what + ": " + buffer.getBufferType());
            if (buffer.getBufferType() != VertexBuffer.Type.Index) {
                assertTrue(data.limit() >= vertices * buffer.getNumComponents(), what + ": "
                        + buffer.getBufferType() + " holds " + data.limit() + " values for "
                        + vertices + " vertices");
                continue;
            }
            for (int i = 0; i < data.limit(); ++i) {
                Object component = buffer.getElementComponent(i / 3, i % 3);
                int index = component instanceof Short ? Short.toUnsignedInt((Short) component)
                        : ((Number) component).intValue();
                assertTrue(index < held, what + ": index " + index + " of " + held
                        + " vertices");
            }
        }
    }

    /**
     * The energy strip's rows: every row up to its most is written; a row past the count is
     * refused by name, not written into an array past its end (an index error on the render
     * thread before).
     */
    @Test
    void theEnergyBarsTakeEveryRowUpToTheirMostAndRefuseOnePast() {
        EnergyBars bars = new EnergyBars(ASSETS, FONT, 3);
        bars.setRowCount(3);
        for (int row = 0; row < 3; ++row) {
            bars.setRow(row, "row " + row, 10.0 * row - 5.0, ColorRGBA.White);
        }
        IllegalArgumentException past = assertThrows(IllegalArgumentException.class,
                () -> bars.setRow(3, "past", 1.0, ColorRGBA.White));
        assertEquals("row must be from 0 to 2 (the row count is 3, at most 3), but was 3",
                past.getMessage());
        bars.setRowCount(1);
        assertThrows(IllegalArgumentException.class,
                () -> bars.setRow(1, "hidden", 1.0, ColorRGBA.White));
        assertThrows(IllegalArgumentException.class, () -> bars.setRowCount(4));
    }
}

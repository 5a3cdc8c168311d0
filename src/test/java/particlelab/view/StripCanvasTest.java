package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.DesktopAssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;

/**
 * The strip-drawing helper the energy bars, the live graph and the lens graph share, without
 * rendering: what each strip's node holds and in which order (the GUI bucket draws equal
 * depths in that order, so the order is the picture), and the quads' corners.
 */
class StripCanvasTest {

    private static final DesktopAssetManager ASSETS = new DesktopAssetManager(true);
    private static final BitmapFont FONT = HudFont.load(ASSETS);

    @Test
    void everyStripIsItsBackgroundFirstThenWhatItDrawsAllInTheGuiBucket() {
        Node[] strips = {new EnergyBars(ASSETS, FONT, 3).getNode(),
            new LiveGraph(ASSETS, FONT, new ColorRGBA[] {ColorRGBA.Red}).getNode(),
            new LensGraph(ASSETS, FONT).getNode()};
        String[] names = {"energy bars", "live graph", "lens graph"};
        // bars: 1 title + 3 names + 3 values; live graph: frame, curves + 4 labels;
        // lens graph: curves + 6 texts
        int[] children = {1 + 1 + 7, 1 + 2 + 4, 1 + 1 + 6};
        for (int i = 0; i < strips.length; ++i) {
            Node node = strips[i];
            assertEquals(names[i], node.getName());
            assertEquals(children[i], node.getQuantity(), names[i]);
            Geometry background = (Geometry) node.getChild(0);
            assertEquals(names[i] + " background", background.getName());
            assertEquals(StripCanvas.BACKGROUND,
                    background.getMaterial().getParamValue("Color"), names[i]);
            for (Spatial child : node.getChildren()) {
                assertEquals(RenderQueue.Bucket.Gui, child.getQueueBucket(), child.getName());
            }
            assertTrue(node.getChild(node.getQuantity() - 1) instanceof HudText, names[i]);
        }
    }

    @Test
    void hidingShowingAndTheBackgroundsPlace() {
        StripCanvas canvas = new StripCanvas(ASSETS, "strip");
        assertTrue(canvas.isVisible());
        canvas.setVisible(false);
        assertFalse(canvas.isVisible());
        assertEquals(Spatial.CullHint.Always, canvas.getNode().getLocalCullHint());
        canvas.setVisible(true);
        assertEquals(Spatial.CullHint.Inherit, canvas.getNode().getLocalCullHint());

        canvas.placeBackground(10f, 20f, 300f, 40f);
        Spatial background = canvas.getNode().getChild(0);
        assertEquals(10f, background.getLocalTranslation().x, 0f);
        assertEquals(20f, background.getLocalTranslation().y, 0f);
        assertEquals(300f, background.getLocalScale().x, 0f);
        assertEquals(40f, background.getLocalScale().y, 0f);
        canvas.hideBackground();
        assertEquals(0f, background.getLocalScale().x, 0f);

        HudText text = canvas.addText(FONT, ColorRGBA.White);
        assertSame(canvas.getNode(), text.getParent());
    }

    @Test
    void aQuadsCornersGoRoundFromTheLeftBottomAndASegmentIsWidenedAcrossItself() {
        StripCanvas canvas = new StripCanvas(ASSETS, "strip");
        StripCanvas.Quads quads = canvas.addQuads("quads", 2);
        assertEquals(2, quads.size());
        // every quad starts hidden, off the screen
        assertEquals(StripCanvas.HIDDEN, quads.coordinate(1, 2, 0), 0f);

        quads.write(0, 1f, 2f, 5f, 7f);
        float[][] corners = {{1f, 2f}, {5f, 2f}, {5f, 7f}, {1f, 7f}};
        for (int v = 0; v < 4; ++v) {
            assertEquals(corners[v][0], quads.coordinate(0, v, 0), 0f, "x of corner " + v);
            assertEquals(corners[v][1], quads.coordinate(0, v, 1), 0f, "y of corner " + v);
        }

        // a horizontal segment from (0, 0) to (4, 0), half thickness 1: the corners lie 1 px
        // above and below its ends (exact: every value is a small integer in float)
        quads.writeSegment(1, 0f, 0f, 4f, 0f, 1f);
        float[][] band = {{0f, 1f}, {0f, -1f}, {4f, -1f}, {4f, 1f}};
        for (int v = 0; v < 4; ++v) {
            assertEquals(band[v][0], quads.coordinate(1, v, 0), 0f, "x of corner " + v);
            assertEquals(band[v][1], quads.coordinate(1, v, 1), 0f, "y of corner " + v);
        }
        quads.hide(1);
        assertEquals(StripCanvas.HIDDEN, quads.coordinate(1, 0, 1), 0f);

        assertThrows(IllegalArgumentException.class, () -> canvas.addQuads("none", 0));
        assertThrows(IllegalArgumentException.class, () -> canvas.addQuads("many", 8192));
    }

    @Test
    void theThreeStripsEndTheirScalesAtTheSameRoundNumbers() {
        // one table of round numbers: the live graph's float axes are the bars' double
        // scale rounded to float (exact: each is a decimal of at most two digits)
        float[] values = {1f, 1.01f, 5.1f, 8.5f, 14.14f, 0.25f, 321.07f};
        for (float value : values) {
            assertEquals((float) EnergyBars.roundUp(value), LiveGraph.roundUp(value), 0f,
                    "roundUp(" + value + ")");
            assertEquals(StripCanvas.roundUp(value), EnergyBars.roundUp(value), 0.0);
        }
    }

    @Test
    void drawingAFrameOfEachStripAllocatesNothing() {
        // what the demos call every frame, on strips laid out once: the bars' rows and
        // refresh, the live graph's record and refresh (axes that stay put, so no label is
        // set), the lens graph's plot
        EnergyBars bars = new EnergyBars(ASSETS, FONT, 3);
        bars.setRowCount(3);
        bars.layOut(new ScreenRect(900f, 300f, 360f, 200f), 19f, "kinetic");
        LiveGraph graph = new LiveGraph(ASSETS, FONT, new ColorRGBA[] {ColorRGBA.Orange});
        graph.layOut(new ScreenRect(700f, 300f, 500f, 180f), 19f);
        LensGraph lens = new LensGraph(ASSETS, FONT);
        lens.layOut(new ScreenRect(900f, 50f, 360f, 240f), 19f);
        double[] times = new double[64];
        float[] vx = new float[64];
        float[] vy = new float[64];
        for (int i = 0; i < times.length; ++i) {
            times[i] = i / 60.0;
            vx[i] = 10f;
            vy[i] = 10f - 9.8f * i / 60f;
        }
        float[] height = new float[1];
        float[] speed = new float[1];
        float[] none = {Float.NaN};
        Runnable frames = () -> {
            graph.clear();
            for (int f = 0; f < 60; ++f) {
                bars.setRow(0, "kinetic", 50.0 - f, ColorRGBA.Blue);
                bars.setRow(1, "potential", f, ColorRGBA.Green);
                bars.setRow(2, "numerical", -0.01 * f, ColorRGBA.White);
                bars.refresh();
                height[0] = 0.5f + 0.4f * (f % 7) / 7f;
                speed[0] = 0.5f;
                graph.record(f / 64f, height, speed, none, none);
                graph.refresh();
                lens.plot(times, vx, vy, times.length, f, f, 0.0, -9.8);
            }
        };
        Allocations.assertAllocatesNothing("60 frames of the three strips", frames);
    }
}

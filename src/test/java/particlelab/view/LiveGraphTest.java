package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.asset.DesktopAssetManager;
import com.jme3.math.ColorRGBA;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The live graph's samples, thinning, axes and labels, without a window. */
class LiveGraphTest {

    private static final DesktopAssetManager ASSETS = new DesktopAssetManager(true);

    @Test
    void axesEndAtTheNextRoundNumber() {
        assertEquals(1f, LiveGraph.roundUp(1f));
        assertEquals(1.5f, LiveGraph.roundUp(1.01f));
        assertEquals(6f, LiveGraph.roundUp(5.1f));
        assertEquals(10f, LiveGraph.roundUp(8.5f));
        assertEquals(15f, LiveGraph.roundUp(14.14f));
        assertEquals(0.3f, LiveGraph.roundUp(0.25f), 1e-7f);
    }

    @Test
    void aFullBufferDropsEveryOtherSampleAndKeepsTheWholeFlightFromZero() {
        LiveGraph graph = graph();
        float h = 1f / 60f;
        float[] euler = new float[1];
        float[] exact = new float[1];
        int steps = 1000;
        for (int n = 0; n <= steps; ++n) {
            euler[0] = n;
            exact[0] = -n;
            graph.record(n * h, euler, euler, exact, exact);
        }
        // 1001 samples offered: halved twice (256 → 128 at stride 2, again at stride 4).
        assertTrue(graph.size() <= LiveGraph.CAPACITY && graph.size() > LiveGraph.CAPACITY / 2,
                "size " + graph.size());
        assertEquals(0f, graph.getTime(0));
        // Every kept sample is the one recorded at its time, stride 4 apart at the end.
        for (int s = 0; s < graph.size(); ++s) {
            int n = Math.round(graph.getTime(s) / h);
            assertEquals(n, graph.getValue(s, 0, false, false));
            assertEquals(-n, graph.getValue(s, 0, true, true));
        }
        int last = Math.round(graph.getTime(graph.size() - 1) / h);
        assertTrue(last > steps - 4, "last kept step " + last);
        graph.clear();
        assertEquals(0, graph.size());
    }

    @Test
    void labelsNameTheRangesAndStayInsideTheGraph() {
        LiveGraph graph = graph();
        ScreenRect area = new ScreenRect(700f, 300f, 560f, 200f);
        graph.layOut(area, HudLayout.SCENE_LABEL_SIZE);
        float[] height = {5.1f};
        float[] speed = {14.1f};
        graph.record(0f, height, speed, height, speed);
        graph.record(2.04f, height, speed, height, speed);
        graph.refresh();
        List<ScreenRect> rects = graph.copyTextRects(new ArrayList<>());
        assertEquals(4, rects.size());
        for (int i = 0; i < rects.size(); ++i) {
            assertTrue(area.contains(rects.get(i)), rects.get(i) + " outside " + area);
            for (int j = 0; j < i; ++j) {
                assertTrue(!rects.get(i).intersects(rects.get(j)), rects.get(i) + " covers "
                        + rects.get(j));
            }
        }
        assertEquals(3, graph.countLabelChanges(), "height, speed and time set once each");
        graph.refresh();
        assertEquals(3, graph.countLabelChanges(), "nothing new, nothing set");
    }

    @Test
    void theLegendPromisesADashedExactCurveOnlyWhereOneIsDrawn() {
        LiveGraph graph = graph();
        graph.layOut(new ScreenRect(700f, 300f, 560f, 200f), HudLayout.SCENE_LABEL_SIZE);
        float[] euler = {5f};
        float[] none = {Float.NaN};
        graph.record(0f, euler, euler, none, none);
        graph.record(1f, euler, euler, none, none);
        graph.refresh();
        // Bounce's balls have no exact ghost: no dashed curve, so no "dashed exact".
        assertEquals(LiveGraph.LEGEND_EULER_ONLY, graph.getLegend());
        graph.record(2f, euler, euler, euler, euler);
        graph.refresh();
        assertEquals("solid Euler, dashed exact", graph.getLegend());
        graph.clear();
        graph.record(0f, euler, euler, none, none);
        graph.refresh();
        assertEquals(LiveGraph.LEGEND_EULER_ONLY, graph.getLegend());
    }

    private static LiveGraph graph() {
        return new LiveGraph(ASSETS, HudFont.load(ASSETS), new ColorRGBA[] {ColorRGBA.Orange});
    }
}

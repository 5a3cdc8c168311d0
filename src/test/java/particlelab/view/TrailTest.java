package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.jme3.asset.DesktopAssetManager;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import java.nio.FloatBuffer;
import org.junit.jupiter.api.Test;

class TrailTest {

    private static final Material UNSHADED = new Material(new DesktopAssetManager(true),
            "Common/MatDefs/Misc/Unshaded.j3md");

    @Test
    void keepsOnlyTheNewestPointsOldestFirst() {
        Trail trail = new Trail("t", 4, 0.1f, ColorRGBA.White, UNSHADED);
        for (int i = 0; i < 10; ++i) {
            trail.add(new Vector3f(i, 2f * i, 0f));
        }
        assertEquals(4, trail.size());
        Vector3f point = new Vector3f();
        for (int age = 0; age < 4; ++age) {
            assertEquals(new Vector3f(6 + age, 2f * (6 + age), 0f), trail.copyPoint(age, point));
        }
        assertThrows(IllegalArgumentException.class, () -> trail.copyPoint(4, point));
    }

    @Test
    void refreshWritesARibbonAroundThePathIntoTheSameBuffer() {
        Trail trail = new Trail("t", 3, 0.2f, ColorRGBA.White, UNSHADED);
        FloatBuffer before = (FloatBuffer) trail.getGeometry().getMesh()
                .getBuffer(VertexBuffer.Type.Position).getData();
        trail.add(new Vector3f(0f, 0f, 0f));
        trail.refresh();
        assertEquals(Spatial.CullHint.Always, trail.getGeometry().getCullHint());
        trail.add(new Vector3f(1f, 0f, 0f));
        trail.refresh();
        assertEquals(Spatial.CullHint.Never, trail.getGeometry().getCullHint());
        FloatBuffer after = (FloatBuffer) trail.getGeometry().getMesh()
                .getBuffer(VertexBuffer.Type.Position).getData();
        assertEquals(before, after);
        assertEquals(before.capacity(), after.capacity());
        // Slot 0 repeats the oldest point; the path runs along x, so the ribbon's two
        // vertices sit 0.1 m above and below it.
        assertEquals(0f, after.get(0), 0f);
        assertEquals(0.1f, after.get(1), 1e-7f);
        assertEquals(-0.1f, after.get(4), 1e-7f);
        assertEquals(1f, after.get(12), 0f);
    }

    @Test
    void eachPointIsAStepDotCentredOnItAndSlotsNotFilledHaveNoArea() {
        float width = 0.2f;
        Trail trail = new Trail("t", 3, width, ColorRGBA.White, UNSHADED);
        trail.add(new Vector3f(2f, 3f, 0f));
        trail.refresh();
        // One point: no ribbon yet, but its dot.
        assertEquals(Spatial.CullHint.Always, trail.getGeometry().getCullHint());
        assertEquals(Spatial.CullHint.Never, trail.getDotGeometry().getCullHint());
        trail.add(new Vector3f(4f, 3f, 0f));
        trail.refresh();
        FloatBuffer dots = (FloatBuffer) trail.getDotGeometry().getMesh()
                .getBuffer(VertexBuffer.Type.Position).getData();
        // Slot 0 is not filled: its four corners sit on the oldest point.
        for (int corner = 0; corner < 4; ++corner) {
            assertEquals(2f, dots.get(3 * corner), 0f);
            assertEquals(3f, dots.get(3 * corner + 1), 0f);
        }
        // Slots 1 and 2 are the two points, each a square of side 1.4 widths around it.
        float half = 0.7f * width;
        int slot1 = 12;
        assertEquals(2f - half, dots.get(slot1), 1e-6f);
        assertEquals(3f - half, dots.get(slot1 + 1), 1e-6f);
        assertEquals(2f + half, dots.get(slot1 + 6), 1e-6f);
        assertEquals(3f + half, dots.get(slot1 + 7), 1e-6f);
        int slot2 = 24;
        assertEquals(4f - half, dots.get(slot2), 1e-6f);
        assertEquals(4f + half, dots.get(slot2 + 6), 1e-6f);
        trail.setDotsVisible(false);
        trail.refresh();
        assertEquals(Spatial.CullHint.Always, trail.getDotGeometry().getCullHint());
        assertEquals(Spatial.CullHint.Never, trail.getGeometry().getCullHint());
    }
}

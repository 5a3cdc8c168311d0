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

/** The velocity arrow's mesh: its tip, and its floor at the ground (no renderer). */
class VelocityArrowTest {

    private static final float SHAFT = 0.1f;
    private static final float SECONDS = 0.25f;

    @Test
    void anArrowFromAboveTheFloorEndsAboveItAlongTheSameDirection() {
        // Issue 29 §3: landing balls' arrows crossed the ground band into the footer.
        VelocityArrow arrow = newArrow();
        arrow.setFloor(0f);
        // From (1, 0.3) at (4, -12) m/s: 0.25 s of travel would end at y = -2.7.
        arrow.update(new Vector3f(1f, 0.3f, 0f), new Vector3f(4f, -12f, 0f));
        FloatBuffer mesh = positions(arrow);
        float lowest = Float.POSITIVE_INFINITY;
        for (int v = 0; v < 7; ++v) {
            lowest = Math.min(lowest, mesh.get(3 * v + 1));
        }
        // The head's half width is 2.5 shaft half widths: the tip stops that far above the
        // floor, and no vertex goes below it (float round-off of a few ulps of 0.3 allowed).
        float headHalfWidth = 2.5f * SHAFT / 2f;
        assertEquals(headHalfWidth, mesh.get(3 * 6 + 1), 1e-6f);
        assertEquals(true, lowest >= -1e-6f, "lowest vertex at y = " + lowest);
        // Same direction: the tip is on the line through the start along the velocity.
        float tipX = mesh.get(3 * 6);
        float tipY = mesh.get(3 * 6 + 1);
        assertEquals(-12f / 4f, (tipY - 0.3f) / (tipX - 1f), 1e-4f);
    }

    @Test
    void anArrowThatStaysAboveTheFloorIsDrawnWhole() {
        VelocityArrow arrow = newArrow();
        arrow.setFloor(0f);
        arrow.update(new Vector3f(1f, 5f, 0f), new Vector3f(4f, -12f, 0f));
        FloatBuffer mesh = positions(arrow);
        // The tip is the start plus 0.25 s of travel: (2, 2), exact in float.
        assertEquals(2f, mesh.get(3 * 6), 0f);
        assertEquals(2f, mesh.get(3 * 6 + 1), 0f);
        assertEquals(Spatial.CullHint.Never, arrow.getGeometry().getCullHint());
    }

    @Test
    void aFloorMustBeAHeight() {
        VelocityArrow arrow = newArrow();
        assertThrows(IllegalArgumentException.class, () -> arrow.setFloor(Float.NaN));
        assertThrows(IllegalArgumentException.class,
                () -> arrow.setFloor(Float.POSITIVE_INFINITY));
    }

    private static VelocityArrow newArrow() {
        DesktopAssetManager assets = new DesktopAssetManager(true);
        Material unshaded = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
        return new VelocityArrow("arrow", SHAFT, SECONDS, ColorRGBA.White, unshaded);
    }

    private static FloatBuffer positions(VelocityArrow arrow) {
        return (FloatBuffer) arrow.getGeometry().getMesh()
                .getBuffer(VertexBuffer.Type.Position).getData();
    }
}

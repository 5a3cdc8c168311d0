package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.shape.Quad;

/**
 * The view of a static thing of a collision scene in the x-y plane: a wall, a pane, a
 * platform, a target, drawn as a flat unshaded rectangle just behind the particles. The
 * physics shapes are unbounded planes and slabs; the view shows the part the scene uses.
 */
public final class WallView {

    private WallView() {
    }

    /**
     * Build a rectangle from {@code (xMin, yMin)} to {@code (xMax, yMax)}.
     *
     * @param assetManager loads the material (not null)
     * @param name the geometry's name (not null)
     * @param xMin the left edge (in metres)
     * @param yMin the bottom edge (in metres)
     * @param xMax the right edge (in metres, &gt;xMin)
     * @param yMax the top edge (in metres, &gt;yMin)
     * @param color its colour (not null, copied; an alpha below 1 is drawn see-through)
     * @return a new geometry (not null)
     */
    public static Geometry create(AssetManager assetManager, String name, float xMin,
            float yMin, float xMax, float yMax, ColorRGBA color) {
        if (!(xMax > xMin) || !(yMax > yMin)) {
            throw new IllegalArgumentException("a wall needs xMax > xMin and yMax > yMin, but"
                    + " was x " + xMin + " to " + xMax + ", y " + yMin + " to " + yMax);
        }
        Material material = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", color.clone());
        Geometry wall = new Geometry(name + " wall", new Quad(xMax - xMin, yMax - yMin));
        if (color.a < 1f) {
            material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
            wall.setQueueBucket(RenderQueue.Bucket.Transparent);
        }
        wall.setMaterial(material);
        wall.setLocalTranslation(xMin, yMin, -0.01f);
        return wall;
    }

    /**
     * Show a wall in another colour (a pane turned ghost, a target hit).
     *
     * @param wall a geometry built by {@link #create} (not null)
     * @param color the new colour (not null, copied)
     */
    public static void setColor(Geometry wall, ColorRGBA color) {
        wall.getMaterial().setColor("Color", color.clone());
    }
}

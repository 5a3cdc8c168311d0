package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Sphere;

/**
 * A particle's exact ghost, drawn faint: a translucent sphere where the continuous path is now
 * and a thin trail of where it has been (without step dots: the path has no steps). The demo
 * feeds it points along the exact path; {@link #update} moves it in place and allocates
 * nothing.
 */
public final class GhostView {

    /** The ghost's opacity: faint beside the opaque Euler sphere. */
    public static final float GHOST_ALPHA = 0.4f;
    /** How far the ghost's colour is mixed toward white. */
    private static final float LIGHTEN = 0.35f;
    /** The ghost trail's width, as a fraction of the sphere's radius. */
    private static final float TRAIL_WIDTH_RADII = 0.3f;
    private static final int SPHERE_SAMPLES = 16;

    private final Node node;
    private final Geometry sphere;
    private final Trail trail;

    /**
     * Create the ghost of one particle.
     *
     * @param assetManager loads the materials (not null)
     * @param name the particle's label (not null)
     * @param color the particle's colour (not null, not modified)
     * @param radiusMetres the particle's radius as drawn (in metres, &gt;0)
     * @param trailPoints how many points of the path the trail keeps (&ge;2)
     */
    public GhostView(AssetManager assetManager, String name, ColorRGBA color,
            float radiusMetres, int trailPoints) {
        node = new Node(name + " ghost");
        ColorRGBA faint = new ColorRGBA(color.r + LIGHTEN * (1f - color.r),
                color.g + LIGHTEN * (1f - color.g), color.b + LIGHTEN * (1f - color.b),
                GHOST_ALPHA);
        Material unshaded = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        Material glass = unshaded.clone();
        glass.setColor("Color", faint);
        glass.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        glass.getAdditionalRenderState().setDepthWrite(false);
        sphere = new Geometry(name + " ghost sphere",
                new Sphere(SPHERE_SAMPLES, SPHERE_SAMPLES, radiusMetres));
        sphere.setMaterial(glass);
        sphere.setQueueBucket(RenderQueue.Bucket.Transparent);
        node.attachChild(sphere);
        trail = new Trail(name + " ghost trail", trailPoints, TRAIL_WIDTH_RADII * radiusMetres,
                faint, unshaded);
        trail.setDotsVisible(false);
        node.attachChild(trail.getGeometry());
        node.attachChild(trail.getDotGeometry());
    }

    /**
     * Access the node holding the ghost.
     *
     * @return the live node (not null)
     */
    public Node getNode() {
        return node;
    }

    /**
     * Access the ghost's trail.
     *
     * @return the live trail (not null)
     */
    public Trail getTrail() {
        return trail;
    }

    /**
     * Start again at a point: forget the trail.
     *
     * @param start the launch position (in metres, not null, not modified)
     */
    public void restart(Vector3f start) {
        trail.clear();
        trail.add(start);
        sphere.setLocalTranslation(start.x, start.y, start.z);
    }

    /**
     * Show or hide the ghost.
     *
     * @param visible true to show it
     */
    public void setVisible(boolean visible) {
        node.setCullHint(visible ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
    }

    /**
     * Move the sphere to the path's position now and push the trail to its mesh.
     *
     * @param position where the exact path is now (in metres, not null, not modified)
     */
    public void update(Vector3f position) {
        sphere.setLocalTranslation(position.x, position.y, position.z);
        trail.refresh();
    }
}

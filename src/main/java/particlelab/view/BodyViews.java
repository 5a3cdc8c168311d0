package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Sphere;
import particlelab.world.Body;
import particlelab.world.BodyListener;
import particlelab.world.World;

/**
 * Plain spheres for bodies a demo adds and destroys while it runs (targets, fragments), from
 * a fixed pool of geometries: {@link #show} gives a body a sphere of its radius, the sphere
 * follows it in {@link #update}, and when the body leaves the world (destroyed in an
 * epilogue, or removed) its sphere is hidden and goes back to the pool, so nothing refers to
 * a body the world has recycled. Register it with {@link World#addBodyListener}. The spheres
 * stay attached to {@link #getNode()} and are shown or hidden by their cull hint, since
 * attaching and detaching a jME child copies the child list: nothing here allocates once
 * built.
 */
public final class BodyViews implements BodyListener {

    private final Node node = new Node("body views");
    private final Geometry[] spheres;
    private final Body[] bodies;
    private int shown;
    /** Scratch: a body's drawn position (m). */
    private final Vector3f drawn = new Vector3f();

    /**
     * Create the pool.
     *
     * @param assetManager loads the materials (not null)
     * @param capacity the most bodies shown at once (&ge;1)
     */
    public BodyViews(AssetManager assetManager, int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be >= 1, but was " + capacity);
        }
        spheres = new Geometry[capacity];
        bodies = new Body[capacity];
        Sphere mesh = new Sphere(12, 16, 1f);
        for (int i = 0; i < capacity; ++i) {
            Material lit = new Material(assetManager, "Common/MatDefs/Light/Lighting.j3md");
            lit.setBoolean("UseMaterialColors", true);
            lit.setColor("Diffuse", ColorRGBA.White.clone());
            lit.setColor("Ambient", ColorRGBA.White.clone());
            spheres[i] = new Geometry("body view " + i, mesh);
            spheres[i].setMaterial(lit);
            spheres[i].setCullHint(Spatial.CullHint.Always);
            node.attachChild(spheres[i]);
        }
    }

    /**
     * Access the node the shown spheres hang from; attach it to the scene.
     *
     * @return the live node (not null)
     */
    public Node getNode() {
        return node;
    }

    /**
     * Give a body a sphere of its radius and a colour. Does nothing if the pool is full.
     *
     * @param body a body in a world (not null)
     * @param color its colour (not null, copied into the material's colour)
     * @return true if shown
     */
    public boolean show(Body body, ColorRGBA color) {
        for (int i = 0; i < bodies.length; ++i) {
            if (bodies[i] == null) {
                bodies[i] = body;
                Geometry sphere = spheres[i];
                Material material = sphere.getMaterial();
                ((ColorRGBA) material.getParam("Diffuse").getValue()).set(color);
                ((ColorRGBA) material.getParam("Ambient").getValue()).set(color);
                sphere.setLocalScale(Math.max(body.getRadius(), 1e-3f));
                sphere.setLocalTranslation(body.getPosition());
                sphere.setCullHint(Spatial.CullHint.Inherit);
                ++shown;
                return true;
            }
        }
        return false;
    }

    /** Move every shown sphere to its body. Allocates nothing. */
    public void update() {
        update(1f);
    }

    /**
     * Move every shown sphere to its body, drawn between its last two physics states.
     * Allocates nothing.
     *
     * @param alpha the blend ({@link Body#copyDrawnPosition}: 0 the previous state, 1 now)
     */
    public void update(float alpha) {
        for (int i = 0; i < bodies.length; ++i) {
            if (bodies[i] != null) {
                spheres[i].setLocalTranslation(bodies[i].copyDrawnPosition(alpha, drawn));
            }
        }
    }

    /**
     * Count the bodies shown.
     *
     * @return the count (&ge;0)
     */
    public int countShown() {
        return shown;
    }

    /**
     * Count the pool's places, shown or not: {@link #getDrawnRadius} and
     * {@link #copyDrawnCentre} take an index below it.
     *
     * @return the capacity (&ge;1)
     */
    public int capacity() {
        return spheres.length;
    }

    /**
     * Return the radius of the sphere in a place of the pool as drawn.
     *
     * @param index the place (0 to {@link #capacity()} - 1)
     * @return the radius (in metres; 0 if the place shows no body)
     */
    public float getDrawnRadius(int index) {
        return bodies[index] == null ? 0f : spheres[index].getLocalScale().x;
    }

    /**
     * Copy the centre of the sphere in a place of the pool as last drawn ({@link #update}).
     *
     * @param index the place (0 to {@link #capacity()} - 1)
     * @param storeResult storage for the centre (in metres, not null, modified)
     * @return storeResult
     */
    public Vector3f copyDrawnCentre(int index, Vector3f storeResult) {
        return storeResult.set(spheres[index].getLocalTranslation());
    }

    /**
     * Test whether a body has a sphere.
     *
     * @param body the body (not null)
     * @return true if shown
     */
    public boolean isShown(Body body) {
        for (int i = 0; i < bodies.length; ++i) {
            if (bodies[i] == body) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void bodyRemoved(World world, Body body) {
        for (int i = 0; i < bodies.length; ++i) {
            if (bodies[i] == body) {
                bodies[i] = null;
                spheres[i].setCullHint(Spatial.CullHint.Always);
                --shown;
                return;
            }
        }
    }
}

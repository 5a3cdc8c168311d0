package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Quad;
import com.jme3.scene.shape.Sphere;

/**
 * Everything drawn for one particle: a lit sphere, its trail, its velocity arrow and a label
 * that follows it. {@link #update} moves them all in place and allocates nothing.
 */
public final class ParticleView {

    /** The label's text height, in sphere radii. */
    private static final float LABEL_SIZE_RADII = 1.9f;
    /** The lowest label row's lift above the sphere, in sphere radii. */
    private static final float LABEL_BASE_RADII = 1.6f;
    /** The height of one label row, in sphere radii: a little more than the text. */
    private static final float LABEL_SLOT_RADII = 2.0f;

    private static final int SPHERE_SAMPLES = 24;
    /** Velocity arrows show this much travel (in seconds). */
    private static final float ARROW_SECONDS = 0.4f;

    private final Node node;
    private final Geometry sphere;
    private final Trail trail;
    private final VelocityArrow arrow;
    private final BitmapText label;
    private final float radius;
    /** The label's height above the sphere (in metres): rows keep labels apart. */
    private final float labelLift;
    /** The label's height above the sphere when its row would put it under the ground. */
    private final float labelLiftAboveGround;

    /**
     * Create the views of one particle.
     *
     * @param assetManager loads the materials (not null)
     * @param font the label font (not null)
     * @param name the particle's label, shown next to it (not null)
     * @param color its colour (not null, not modified)
     * @param radiusMetres the sphere's radius, which also sizes the trail, arrow and label (in
     *     metres, &gt;0)
     * @param trailPoints how many recent positions the trail keeps (&ge;2)
     * @param labelRow which row the label floats in above the sphere (&ge;0), so labels of
     *     particles that meet do not overwrite each other
     */
    public ParticleView(AssetManager assetManager, BitmapFont font, String name,
            ColorRGBA color, float radiusMetres, int trailPoints, int labelRow) {
        this.radius = radiusMetres;
        // Row 0 floats just above the sphere, row 1 hangs below it, row 2 higher above, ...
        // Near the ground a hanging label moves up to a slot of its own: 1.6 + 2·row radii.
        float aboveOffset = LABEL_BASE_RADII + LABEL_SLOT_RADII * labelRow;
        float rowOffset = (labelRow % 2 == 0) ? aboveOffset : -3.4f - 1.6f * labelRow;
        this.labelLift = rowOffset * radiusMetres;
        this.labelLiftAboveGround = aboveOffset * radiusMetres;
        this.node = new Node(name);
        Material lit = new Material(assetManager, "Common/MatDefs/Light/Lighting.j3md");
        lit.setBoolean("UseMaterialColors", true);
        lit.setColor("Diffuse", color);
        lit.setColor("Ambient", color.mult(0.45f));
        lit.setColor("Specular", ColorRGBA.White);
        lit.setFloat("Shininess", 24f);
        sphere = new Geometry(name + " sphere",
                new Sphere(SPHERE_SAMPLES, SPHERE_SAMPLES, radiusMetres));
        sphere.setMaterial(lit);
        node.attachChild(sphere);

        Material unshaded = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        trail = new Trail(name + " trail", trailPoints, 0.5f * radiusMetres, color, unshaded);
        node.attachChild(trail.getGeometry());
        arrow = new VelocityArrow(name + " velocity", 0.4f * radiusMetres, ARROW_SECONDS,
                ColorRGBA.White.clone(), unshaded);
        node.attachChild(arrow.getGeometry());

        label = new BitmapText(font);
        label.setSize(LABEL_SIZE_RADII * radiusMetres);
        label.setColor(color.clone());
        label.setText(name);
        label.setQueueBucket(RenderQueue.Bucket.Transparent);
        node.attachChild(label);
    }

    /**
     * Access the node holding all the views.
     *
     * @return the live node (not null)
     */
    public Node getNode() {
        return node;
    }

    /**
     * Access the trail.
     *
     * @return the live trail (not null)
     */
    public Trail getTrail() {
        return trail;
    }

    /**
     * Access the velocity arrow.
     *
     * @return the live arrow (not null)
     */
    public VelocityArrow getArrow() {
        return arrow;
    }

    /**
     * Access the label.
     *
     * @return the live label (not null)
     */
    public BitmapText getLabel() {
        return label;
    }

    /**
     * Build a labelled post standing on the ground at {@code (x, 0)}, e.g. a gun or a target.
     *
     * @param assetManager loads the material (not null)
     * @param font the label font (not null)
     * @param label the text above the post (not null)
     * @param x where the post stands (in metres)
     * @param heightMetres its height (in metres, &gt;0)
     * @param widthMetres its width (in metres, &gt;0)
     * @param color its colour (not null, not modified)
     * @return a new node (not null)
     */
    public static Node createPost(AssetManager assetManager, BitmapFont font, String label,
            float x, float heightMetres, float widthMetres, ColorRGBA color) {
        Node post = new Node(label);
        Material material = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", color);
        Geometry bar = new Geometry(label + " bar", new Quad(widthMetres, heightMetres));
        bar.setMaterial(material);
        bar.setLocalTranslation(x - widthMetres / 2f, 0f, -0.02f);
        post.attachChild(bar);
        BitmapText text = new BitmapText(font);
        text.setSize(3.5f * widthMetres);
        text.setColor(color.clone());
        text.setText(label);
        text.setQueueBucket(RenderQueue.Bucket.Transparent);
        text.setLocalTranslation(x - text.getLineWidth() / 2f, heightMetres + 4f * widthMetres,
                0f);
        post.attachChild(text);
        return post;
    }

    /**
     * Move the sphere, label and arrow to the particle's state and push the trail to its mesh.
     *
     * @param position the particle's position (in metres, not null, not modified)
     * @param velocity the particle's velocity (in m/s, not null, not modified)
     */
    public void update(Vector3f position, Vector3f velocity) {
        sphere.setLocalTranslation(position.x, position.y, position.z);
        // The label's bottom edge sits at y + lift; it hangs no lower than the ground.
        float lift = position.y + labelLift < 0f ? labelLiftAboveGround : labelLift;
        label.setLocalTranslation(position.x + radius,
                position.y + lift + LABEL_SIZE_RADII * radius, position.z);
        arrow.update(position, velocity);
        trail.refresh();
    }
}

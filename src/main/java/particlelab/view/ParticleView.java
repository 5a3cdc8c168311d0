package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Quad;
import com.jme3.scene.shape.Sphere;

/**
 * Everything drawn for one particle: a lit sphere, its trail (with a dot per step), its
 * velocity arrow and a label
 * that follows it in a free slot beside it ({@link #placeLabel}). {@link #update} moves them in
 * place and allocates nothing.
 */
public final class ParticleView {

    private static final int SPHERE_SAMPLES = 24;
    /** Velocity arrows show this much travel (in seconds); labels keep clear of them. */
    public static final float ARROW_SECONDS = 0.4f;
    /**
     * A label's plate: the scene's background colour, nearly opaque, so a label that has to
     * lie over a trail (no free slot beside its sphere) stays readable.
     */
    private static final ColorRGBA PLATE_COLOR = new ColorRGBA(0.07f, 0.08f, 0.11f, 0.9f);
    /**
     * The plate and the label stand this far in front of the particles' plane (in metres):
     * the plate hides what lies under it, the label is drawn over the plate. Against the
     * camera's distance (tens of metres) the shift on the screen is far below a pixel.
     */
    private static final float PLATE_Z = 0.01f;
    /** A label's depth in front of the particles' plane, over its plate (in metres). */
    public static final float LABEL_Z = 2f * PLATE_Z;
    /**
     * Two spheres whose centres lie closer than this on the screen (in radii) coincide for a
     * viewer: they get one joined label naming both ("ball = slide code"), not two stacked.
     */
    public static final float JOIN_RADII = 0.5f;
    /** The separator between the names of a joined label. */
    public static final String JOIN_SEPARATOR = " = ";
    /** A joined label's colour: neutral, as it names spheres of several colours. */
    private static final ColorRGBA JOINED_COLOR = new ColorRGBA(0.92f, 0.92f, 0.92f, 1f);

    private final Node node;
    private final Geometry sphere;
    private final Trail trail;
    private final VelocityArrow arrow;
    private final HudText label;
    /** The label's plate, shown only while the label lies over a trail. */
    private final Geometry plate;
    private final float radius;
    /** Where the label is on the screen (in pixels), and which slot it took. */
    private final ScreenRect labelRect = new ScreenRect();
    private int labelSlot = -1;
    private boolean labelPlated;
    /** The particle's own colour, its label's unless joined. */
    private final ColorRGBA ownColor;
    /** True while the label names this sphere and those coinciding with it. */
    private boolean labelJoined;

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
     */
    public ParticleView(AssetManager assetManager, BitmapFont font, String name,
            ColorRGBA color, float radiusMetres, int trailPoints) {
        this.radius = radiusMetres;
        this.ownColor = color.clone();
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
        node.attachChild(trail.getDotGeometry());
        arrow = new VelocityArrow(name + " velocity", 0.4f * radiusMetres, ARROW_SECONDS,
                ColorRGBA.White.clone(), unshaded);
        node.attachChild(arrow.getGeometry());

        Material plateMaterial = new Material(assetManager,
                "Common/MatDefs/Misc/Unshaded.j3md");
        plateMaterial.setColor("Color", PLATE_COLOR);
        plateMaterial.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        plate = new Geometry(name + " label plate", new Quad(1f, 1f));
        plate.setMaterial(plateMaterial);
        plate.setQueueBucket(RenderQueue.Bucket.Transparent);
        plate.setCullHint(Spatial.CullHint.Always);
        node.attachChild(plate);

        label = new HudText(font, color);
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
    public HudText getLabel() {
        return label;
    }

    /**
     * Build a post standing on the ground at {@code (x, 0)}, e.g. a gun or a target; its name
     * is a {@link SceneLabel} of the layout's.
     *
     * @param assetManager loads the material (not null)
     * @param name the post's name (not null)
     * @param x where the post stands (in metres)
     * @param heightMetres its height (in metres, &gt;0)
     * @param widthMetres its width (in metres, &gt;0)
     * @param color its colour (not null, not modified)
     * @return a new geometry (not null)
     */
    public static Geometry createPost(AssetManager assetManager, String name, float x,
            float heightMetres, float widthMetres, ColorRGBA color) {
        Material material = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", color);
        Geometry bar = new Geometry(name + " post", new Quad(widthMetres, heightMetres));
        bar.setMaterial(material);
        bar.setLocalTranslation(x - widthMetres / 2f, 0f, -0.02f);
        return bar;
    }

    /**
     * Create a label's plate: a unit square of the scene's background colour, nearly opaque,
     * hidden until placed ({@link #placePlate}), to lay under a text over a trail.
     *
     * @param assetManager loads the material (not null)
     * @param name the geometry's name (not null)
     * @return a new plate (hidden)
     */
    public static Geometry createPlate(AssetManager assetManager, String name) {
        Material material = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", PLATE_COLOR);
        material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        Geometry plate = new Geometry(name, new Quad(1f, 1f));
        plate.setMaterial(material);
        plate.setQueueBucket(RenderQueue.Bucket.Transparent);
        plate.setCullHint(Spatial.CullHint.Always);
        return plate;
    }

    /**
     * Lay a plate ({@link #createPlate}) under a rectangle of the screen, or hide it.
     * Allocates nothing.
     *
     * @param plate the plate (not null, modified)
     * @param view the plane's mapping (not null, not modified)
     * @param where the rectangle (in pixels, not null, not modified)
     * @param shown false to hide the plate
     */
    public static void placePlate(Geometry plate, PlaneView view, ScreenRect where,
            boolean shown) {
        if (!shown) {
            plate.setCullHint(Spatial.CullHint.Always);
            return;
        }
        plate.setLocalTranslation(view.planeX(where.getX()), view.planeY(where.getY()),
                PLATE_Z);
        plate.setLocalScale(where.getWidth() / view.getPixelsPerMetre(),
                where.getHeight() / view.getPixelsPerMetre(), 1f);
        plate.setCullHint(Spatial.CullHint.Inherit);
    }

    /**
     * Return the sphere's radius.
     *
     * @return the radius (in metres)
     */
    public float getRadius() {
        return radius;
    }

    /**
     * Access the label's place on the screen, as last put by {@link #placeLabel}.
     *
     * @return the live rectangle (in pixels, do not modify)
     */
    public ScreenRect getLabelRect() {
        return labelRect;
    }

    /**
     * Return the slot the label last took ({@link LabelSlots}).
     *
     * @return the slot, or -1 before the first placement
     */
    public int getLabelSlot() {
        return labelSlot;
    }

    /**
     * Change the label's text; rewrites its glyphs in place, allocating nothing once the
     * label has held a text this long.
     *
     * @param text the new text, one line (not null, not modified)
     */
    public void setLabelText(CharSequence text) {
        label.setText(text);
    }

    /**
     * Put the label into a rectangle of the screen, through the plane's mapping, with no
     * plate. Allocates nothing.
     *
     * @param view the plane's mapping (not null, not modified)
     * @param size the text size (in pixels, &gt;0)
     * @param slot the slot taken ({@link LabelSlots})
     * @param where the rectangle (in pixels, not null, copied)
     */
    public void placeLabel(PlaneView view, float size, int slot, ScreenRect where) {
        placeLabel(view, size, slot, where, false);
    }

    /**
     * Put the label into a rectangle of the screen, through the plane's mapping, on a plate
     * of the background's colour if asked (a label that lies over a trail: the plate hides
     * the trail there, so the text stays readable). Allocates nothing.
     *
     * @param view the plane's mapping (not null, not modified)
     * @param size the text size (in pixels, &gt;0)
     * @param slot the slot taken ({@link LabelSlots})
     * @param where the rectangle (in pixels, not null, copied)
     * @param plated true to draw the plate under the label
     */
    public void placeLabel(PlaneView view, float size, int slot, ScreenRect where,
            boolean plated) {
        labelRect.set(where);
        labelSlot = slot;
        labelPlated = plated;
        float worldSize = size / view.getPixelsPerMetre();
        if (label.getSize() != worldSize) {
            label.setSize(worldSize);
        }
        label.setLocalTranslation(view.planeX(where.getX()), view.planeY(where.getTop()),
                LABEL_Z);
        label.setCullHint(Spatial.CullHint.Inherit);
        if (plated) {
            plate.setLocalTranslation(view.planeX(where.getX()), view.planeY(where.getY()),
                    PLATE_Z);
            plate.setLocalScale(where.getWidth() / view.getPixelsPerMetre(),
                    where.getHeight() / view.getPixelsPerMetre(), 1f);
            plate.setCullHint(Spatial.CullHint.Inherit);
        } else {
            plate.setCullHint(Spatial.CullHint.Always);
        }
    }

    /**
     * Show the label as a joined one (naming this sphere and those coinciding with it on the
     * screen, {@link #JOIN_RADII}) in a neutral colour, or as this sphere's own in its colour.
     * Allocates nothing; recolours only on a change.
     *
     * @param joined true for a joined label
     */
    public void setLabelJoined(boolean joined) {
        if (joined != labelJoined) {
            labelJoined = joined;
            label.setColor(joined ? JOINED_COLOR : ownColor);
        }
    }

    /**
     * Test whether the label is a joined one ({@link #setLabelJoined}).
     *
     * @return true if joined
     */
    public boolean isLabelJoined() {
        return labelJoined;
    }

    /**
     * Test whether the label was last placed on a plate ({@link #placeLabel}): it lies over a
     * trail, which the plate hides under it.
     *
     * @return true if plated (false while hidden)
     */
    public boolean isLabelPlated() {
        return labelPlated;
    }

    /**
     * Hide the label until the next {@link #placeLabel}: its rectangle becomes empty, so it
     * covers nothing. Allocates nothing.
     */
    public void hideLabel() {
        labelRect.set(0f, 0f, 0f, 0f);
        labelPlated = false;
        label.setCullHint(Spatial.CullHint.Always);
        plate.setCullHint(Spatial.CullHint.Always);
    }

    /**
     * Move the sphere and arrow to the particle's state and push the trail to its mesh; the
     * label is placed by the scene's layout ({@link #placeLabel}).
     *
     * @param position the particle's position (in metres, not null, not modified)
     * @param velocity the particle's velocity (in m/s, not null, not modified)
     */
    public void update(Vector3f position, Vector3f velocity) {
        sphere.setLocalTranslation(position.x, position.y, position.z);
        arrow.update(position, velocity);
        trail.refresh();
    }
}

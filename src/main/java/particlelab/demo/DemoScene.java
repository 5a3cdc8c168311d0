package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.scene.Node;
import java.util.ArrayList;
import java.util.List;
import particlelab.view.CameraFraming;
import particlelab.view.DistanceGrid;
import particlelab.view.ParticleView;

/**
 * What a demo's scene shows and where the camera looks: the region of the x-y plane the camera
 * frames, the distance grid over it, the posts (a gun, a target), the lights, and one view per
 * particle (sphere, label, trail, velocity arrow). A demo declares the region and the posts
 * while it creates its scene ({@link DemoState#setView}, {@link DemoState#addMarker}); the
 * scene is built once, at initialisation; then the views follow the particles each frame,
 * allocating nothing.
 */
final class DemoScene {

    /** How many recent positions each trail keeps: 10 s at 60 steps per second. */
    private static final int TRAIL_POINTS = 600;
    /** The depth of the ground band below y = 0 (in grid spacings). */
    private static final float GROUND_BAND_SPACINGS = 1.5f;
    /** A post's radius (as a fraction of the particles' radius). */
    private static final float POST_RADIUS_FRACTION = 0.6f;

    private final List<DemoParticle> particles;
    private final List<Marker> markers = new ArrayList<>();
    private float xMin = -2f;
    private float xMax = 22f;
    private float yMin = -1.5f;
    private float yMax = 8f;
    private float gridSpacing = 1f;
    private int gridLabelEvery = 5;
    private float sphereRadius = 0.35f;
    private boolean arrowsVisible = true;

    /**
     * Create the scene of one demo, with the default region.
     *
     * @param particles the demo's particles, each given its view by {@link #build} (not null,
     *     live)
     */
    DemoScene(List<DemoParticle> particles) {
        this.particles = particles;
    }

    /**
     * Choose the region of the x-y plane the camera frames, the grid and the sphere size.
     *
     * @param xMin the left edge (in metres)
     * @param xMax the right edge (in metres, &gt;xMin)
     * @param yMax the top edge (in metres, &gt;0); the ground band below y = 0 is added
     * @param gridSpacingMetres the distance between grid lines (in metres, &gt;0)
     * @param labelEvery a distance mark every this many grid lines (&ge;1)
     * @param sphereRadiusMetres the particles' radius as drawn (in metres, &gt;0)
     */
    void setRegion(float xMin, float xMax, float yMax, float gridSpacingMetres, int labelEvery,
            float sphereRadiusMetres) {
        if (!(xMax > xMin && yMax > 0f && gridSpacingMetres > 0f && labelEvery >= 1
                && sphereRadiusMetres > 0f)) {
            throw new IllegalArgumentException("view needs xMin < xMax, yMax > 0, spacing > 0,"
                    + " labelEvery >= 1 and radius > 0, but got x " + xMin + ".." + xMax
                    + ", yMax " + yMax + ", spacing " + gridSpacingMetres + ", labelEvery "
                    + labelEvery + ", radius " + sphereRadiusMetres);
        }
        this.xMin = xMin;
        this.xMax = xMax;
        this.yMax = yMax;
        this.yMin = -GROUND_BAND_SPACINGS * gridSpacingMetres;
        gridSpacing = gridSpacingMetres;
        gridLabelEvery = labelEvery;
        sphereRadius = sphereRadiusMetres;
    }

    /**
     * Add a labelled post standing on the ground.
     *
     * @param label the text above the post (not null)
     * @param x where it stands (in metres)
     * @param heightMetres how tall it is (in metres, finite, &gt;0)
     * @param color its colour (not null, not modified)
     */
    void addMarker(String label, float x, float heightMetres, ColorRGBA color) {
        if (!(heightMetres > 0f) || Float.isInfinite(heightMetres)) {
            throw new IllegalArgumentException(
                    "marker height (m) must be finite and > 0, but was " + heightMetres);
        }
        markers.add(new Marker(label, x, heightMetres, color.clone()));
    }

    /**
     * Build the scene: grid, posts and lights, and a view for each particle, its trail
     * starting at the particle's position. Call once, after the particles were added.
     *
     * @param assets the application's asset manager (not null)
     * @param font the font of labels (not null)
     * @param sceneNode where to attach everything (not null, modified)
     */
    void build(AssetManager assets, BitmapFont font, Node sceneNode) {
        sceneNode.attachChild(new DistanceGrid(assets, font, xMin, xMax, yMin, yMax,
                gridSpacing, gridLabelEvery).getNode());
        for (int i = 0; i < markers.size(); ++i) {
            Marker marker = markers.get(i);
            sceneNode.attachChild(ParticleView.createPost(assets, font, marker.label,
                    marker.x, marker.height, POST_RADIUS_FRACTION * sphereRadius,
                    marker.color));
        }
        DirectionalLight sun = new DirectionalLight(
                new Vector3f(-0.4f, -0.6f, -0.7f).normalizeLocal(), ColorRGBA.White.clone());
        sceneNode.addLight(sun);
        sceneNode.addLight(new AmbientLight(new ColorRGBA(0.45f, 0.45f, 0.5f, 1f)));
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            particle.view = new ParticleView(assets, font, particle.getLabel(),
                    particle.getColor(), sphereRadius, TRAIL_POINTS, i);
            particle.view.getTrail().add(particle.getParticle().position);
            particle.view.getArrow().setVisible(arrowsVisible);
            sceneNode.attachChild(particle.view.getNode());
        }
    }

    /**
     * Move every particle's view (sphere, label, arrow) to its particle. Allocates nothing.
     */
    void updateViews() {
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            particle.view.update(particle.getParticle().position,
                    particle.getParticle().velocity);
        }
    }

    /**
     * Start a particle's trail again at its position; before {@link #build}, do nothing.
     * Allocates nothing.
     *
     * @param particle one of the demo's particles (not null, not modified)
     */
    void restartTrail(DemoParticle particle) {
        if (particle.view != null) {
            particle.view.getTrail().clear();
            particle.view.getTrail().add(particle.getParticle().position);
        }
    }

    /**
     * Show the velocity arrows if hidden, hide them if shown.
     */
    void toggleArrows() {
        arrowsVisible = !arrowsVisible;
        for (int i = 0; i < particles.size(); ++i) {
            particles.get(i).view.getArrow().setVisible(arrowsVisible);
        }
    }

    /**
     * Test whether the velocity arrows are shown.
     *
     * @return true if shown
     */
    boolean areArrowsVisible() {
        return arrowsVisible;
    }

    /**
     * Point the camera at the region.
     *
     * @param camera the application's camera (not null, modified)
     */
    void frame(Camera camera) {
        CameraFraming.frame(camera, xMin, xMax, yMin, yMax);
    }

    /** A post declared by {@link #addMarker}, built by {@link #build}. */
    private static final class Marker {
        final String label;
        final float x;
        final float height;
        final ColorRGBA color;

        Marker(String label, float x, float height, ColorRGBA color) {
            this.label = label;
            this.x = x;
            this.height = height;
            this.color = color;
        }
    }
}

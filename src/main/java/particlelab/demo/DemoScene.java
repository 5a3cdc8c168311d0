package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.light.AmbientLight;
import com.jme3.light.DirectionalLight;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import java.util.ArrayList;
import java.util.List;
import particlelab.view.BodyViews;
import particlelab.view.CameraFraming;
import particlelab.view.DistanceGrid;
import particlelab.view.HudLayout;
import particlelab.view.LabelSlots;
import particlelab.view.MarkThinning;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.SceneLabel;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.view.TextMeasure;
import particlelab.view.Trail;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * What a demo's scene shows and where the camera looks: the region of the x-y plane the camera
 * frames, the distance grid over it, the posts (a gun, a target), the lights, and one view per
 * particle (sphere, label, trail, velocity arrow). A demo declares the region and the posts
 * while it creates its scene ({@link DemoState#setView}, {@link DemoState#addMarker}); the
 * scene is built once, at initialisation; then the views follow the particles each frame,
 * allocating nothing.
 *
 * <p>The layout ({@link #layOut}) fits the region into the screen area the HUD leaves free and
 * places every text in pixels: the posts' names and the distance marks are shifted inside the
 * window or hidden where they would cover the HUD or each other; each frame, every particle's
 * label takes the first slot beside its sphere ({@link LabelSlots}) that covers no HUD text,
 * no other label, no other sphere and no trail as drawn, above the ground line where it can,
 * keeping its slot while that stays free; a particle whose view its demo culled has no label
 * and is no obstacle. A distance mark or a post's name that a sphere covers (the "0 m" mark
 * under a ball at launch) is hidden until the sphere has moved on.
 */
final class DemoScene {

    /** The room left around a reach beyond the declared region (share of its size). */
    private static final float REACH_HEADROOM = 0.08f;
    /** How many recent positions each trail keeps: 10 s at 60 steps per second. */
    private static final int TRAIL_POINTS = 600;
    /** The depth of the ground band below y = 0 (in grid spacings). */
    private static final float GROUND_BAND_SPACINGS = 1.5f;
    /** A post's radius (as a fraction of the particles' radius). */
    private static final float POST_RADIUS_FRACTION = 0.6f;
    /** Slot scores: covering text or leaving the window, covering a sphere, a trail point. */
    private static final int TEXT_PENALTY = 1_000_000;
    private static final int SPHERE_PENALTY = 1_000;
    /**
     * Slot score: reaching below the ground line, into the band of the distance marks and
     * the footer. Worse than a trail under a plate ({@link #TRAIL_PENALTY} with every near
     * point), better than a sphere or a post: aiming's joined label "lecture = discrete"
     * fell beside the footer at 1280x720 when every slot above covered a trail (issue 29 §3).
     */
    private static final int GROUND_PENALTY = 800;
    /**
     * Slot score: lying over a trail as drawn. Taken, on a plate, only where every slot
     * covers a trail or worse: a label over a trail beats no label (issue 29 §3: the
     * linear-drag sphere had none when its trail and its neighbours' hemmed it in).
     */
    private static final int TRAIL_PENALTY = 600;
    /** The most a slot's trail points within the clearance add to its score. */
    private static final int MAX_NEAR_POINTS = 99;
    /** An edge label's arrows: its sphere is beyond the scene's right or left edge. */
    private static final String RIGHT_ARROW = " \u2192";
    private static final String LEFT_ARROW = "\u2190 ";
    /** A stacked joined label's separator: " =" ends a line, the next name starts one. */
    private static final String STACKED_SEPARATOR = " =\n";
    private static final String STACKED_LINE_END = " =";
    /** An edge label's position's decimals (metres). */
    private static final int EDGE_DECIMALS = 1;
    /** How many label heights an edge label moves up, at most, to leave a text free. */
    private static final int EDGE_TRIES = 6;
    /** A post name's plate's name, before the post's index (tests find it by it). */
    static final String POST_PLATE = "post name plate ";
    /** The least ground shown below y = 0, in scene label heights. */
    private static final float GROUND_LABEL_ROOM = 1.8f;
    /** Points sampled along each velocity arrow, which a label avoids like a trail. */
    private static final int ARROW_SAMPLES = 16;
    /** The least room between two distance marks shown (as a fraction of the text size). */
    private static final float MARK_GAP_FRACTION = 1f;
    /**
     * A trail counts as covered this close to a label, beyond the trail's drawn half width
     * (in pixels at HUD scale 1).
     */
    private static final float TRAIL_CLEARANCE = 3f;

    private final List<DemoParticle> particles;
    /** Each particle's view, in the particles' order (empty until {@link #build}). */
    private final List<ParticleView> views = new ArrayList<>();
    private final List<Marker> markers = new ArrayList<>();
    /**
     * Per post: the plate laid under its name while a trail runs under it ("gun" on its
     * shots' trails, "target S = 60 m" under them), named {@link #POST_PLATE} and its index.
     */
    private final List<Geometry> postPlates = new ArrayList<>();
    private float xMin = -2f;
    private float xMax = 22f;
    private float yMin = -1.5f;
    private float yMax = 8f;
    /** The top of what the camera frames (in metres, at most yMax). */
    private float frameTop = 8f;
    private float gridSpacing = 1f;
    private int gridLabelEvery = 5;
    private float sphereRadius = 0.35f;
    private boolean arrowsVisible = true;
    /** The region the demo declared (setRegion): the least the camera frames. */
    private float declaredXMin = xMin;
    private float declaredXMax = xMax;
    private float declaredYMax = yMax;
    private float declaredSpacing = gridSpacing;
    /** Kept from build, to build the grid again for a wider region. */
    private AssetManager assets;
    private BitmapFont font;
    private Node sceneNode;
    /** How many of fixedLabels are posts' names (the grid's marks follow them). */
    private int markerLabels;
    private boolean dotsVisible = true;
    /** The region the grid covers: the framed one widened to the scene area's shape (m). */
    private float gridLeft = xMin;
    private float gridRight = xMax;
    private float gridTop = yMax;
    /** The bottom of the ground band the last layout framed (in metres, &lt;0). */
    private float gridBottom = yMin;
    /** True when the grid's spacing changed since it was built (frameReach). */
    private boolean gridStale;

    private final PlaneView plane = new PlaneView();
    /**
     * Spheres beyond the particles that labels keep off as they keep off the particles'
     * (targets' gun platform, targets, fragments), or null: "shot" lay over the grey
     * platform at tour stop 1 (issue 29 §3).
     */
    private BodyViews obstacleSpheres;
    /** Scratch: an obstacle sphere's centre (in metres). */
    private final Vector3f obstacleCentre = new Vector3f();
    /** The posts' names, then the distance marks: placed once per layout, in this order. */
    private final List<SceneLabel> fixedLabels = new ArrayList<>();
    /** The HUD's text rectangles, which no scene text may cover. */
    private final List<ScreenRect> hudRects = new ArrayList<>();
    /** The window less its margin, above the footer band: where particles' labels stay. */
    private final ScreenRect textArea = new ScreenRect();
    /** The scene's area within the margins: where the fixed labels must stay. */
    private final ScreenRect fixedArea = new ScreenRect();
    private final ScreenRect candidate = new ScreenRect();
    private final ScreenRect chosen = new ScreenRect();
    /** Scratch: a neighbouring ground mark's preferred place (in pixels). */
    private final ScreenRect neighbourMark = new ScreenRect();
    private final ScreenRect reach = new ScreenRect();
    private final Vector3f trailPoint = new Vector3f();
    /** The HUD's side panel and graph slots (live, empty when not asked for). */
    private ScreenRect panelSlot = new ScreenRect();
    private ScreenRect graphSlot = new ScreenRect();
    private TextMeasure measure;
    private DistanceGrid grid;
    private float labelSize = HudLayout.SCENE_LABEL_SIZE;
    private float labelHeight;
    private float trailClearance = TRAIL_CLEARANCE;
    /** How far the trails are drawn on each side of their points (ribbon, dots; pixels). */
    private float trailHalfWidth;
    private boolean laidOut;
    /** Per particle: its label's width (px), and its sphere's centre on the screen (px). */
    private float[] labelWidths = new float[0];
    private float[] sphereX = new float[0];
    private float[] sphereY = new float[0];
    /**
     * Per particle: true while its label stands at the scene's edge, its sphere beyond it
     * (the text then says where: "target (physics) at x = 21.0 m →"), and that text.
     */
    private boolean[] atEdge = new boolean[0];
    private StringBuilder[] edgeTexts = new StringBuilder[0];
    /**
     * Per particle: the particle whose label names it too (itself unless its sphere coincides
     * on the screen with one before it, {@link ParticleView#JOIN_RADII}), and a leader's
     * joined text ("ball = slide code").
     */
    private int[] labelLeader = new int[0];
    private StringBuilder[] joinedTexts = new StringBuilder[0];
    /** The HUD's scene rectangle (live): a sphere beyond its sides gets an edge label. */
    private ScreenRect sceneArea = new ScreenRect();
    /** Scratch: the trail points near the label being placed, on the screen (px). */
    private float[] nearX = new float[0];
    private float[] nearY = new float[0];
    private int nearCount;
    /** How many of the near points, the first ones, are trail points (not arrow samples). */
    private int nearTrailCount;
    /** Where the views draw between the last two physics states (0 to 1; 1: the last). */
    private float drawBlend = 1f;
    /** Scratch: a particle's drawn position (m). */
    private final Vector3f drawn = new Vector3f();
    /**
     * The view's own listener on the demo's world: after each step, every particle the step
     * moved adds its position to its trail. The step itself writes no view.
     */
    private final StepListener trailWriter = new StepListener() {
        @Override
        public void afterStep(World stepping, float stepSeconds) {
            for (int i = 0; i < particles.size(); ++i) {
                DemoParticle particle = particles.get(i);
                if (particle.steppedThisStep && viewOf(particle) != null) {
                    viewOf(particle).getTrail().add(particle.getParticle().position);
                }
            }
        }
    };

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
        this.frameTop = yMax;
        this.yMin = -GROUND_BAND_SPACINGS * gridSpacingMetres;
        gridSpacing = gridSpacingMetres;
        gridLabelEvery = labelEvery;
        sphereRadius = sphereRadiusMetres;
        declaredXMin = xMin;
        declaredXMax = xMax;
        declaredYMax = yMax;
        declaredSpacing = gridSpacingMetres;
        gridLeft = xMin;
        gridRight = xMax;
        gridTop = yMax;
    }

    /**
     * Frame the region the current launches reach, where it goes beyond the declared one: the
     * region becomes the declared one widened to hold the reach with {@value #REACH_HEADROOM}
     * headroom, its grid spacing the declared one times 1, 2 or 5 times a power of ten so the
     * grid keeps about as many lines, and the grid is built again. A reach inside the
     * declared region frames the declared region. Call from the jME thread; it allocates
     * only when the region changes. Takes effect at the next {@link #layOut}.
     *
     * @param reach the reach of the launches (not null, not modified; empty: the declared
     *     region)
     * @return true if the region changed
     */
    boolean frameReach(LaunchReach reach) {
        float left = declaredXMin;
        float right = declaredXMax;
        float top = declaredYMax;
        if (!reach.isEmpty()) {
            float width = reach.getXMax() - reach.getXMin();
            float room = REACH_HEADROOM * Math.max(width, reach.getYMax());
            if (reach.getXMin() < left) {
                left = reach.getXMin() - room;
            }
            if (reach.getXMax() > right) {
                right = reach.getXMax() + room;
            }
            if (reach.getYMax() > top) {
                top = reach.getYMax() + room;
            }
        }
        if (left == xMin && right == xMax && top == yMax) {
            return false;
        }
        float growth = Math.max((right - left) / (declaredXMax - declaredXMin),
                top / declaredYMax);
        gridSpacing = niceSpacing(declaredSpacing * growth);
        xMin = left;
        xMax = right;
        yMax = top;
        frameTop = top;
        yMin = -GROUND_BAND_SPACINGS * gridSpacing;
        // The grid is built again for the new spacing at the next layOut.
        gridStale = true;
        return true;
    }

    /**
     * Choose how high the camera frames, within the region: e.g. the apex of the highest shot
     * in the air. Takes effect at the next {@link #layOut}.
     *
     * @param top the top edge to frame (in metres, &gt;0; more than the region's top frames
     *     the region's top)
     */
    void setFrameTop(float top) {
        if (!(top > 0f) || Float.isInfinite(top)) {
            throw new IllegalArgumentException("frame top (m) must be finite and > 0, but was "
                    + top);
        }
        frameTop = Math.min(top, yMax);
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
        addMarker(label, x, heightMetres, color, false);
    }

    /**
     * Add a labelled post standing on the ground, its name on its top or beside its foot.
     *
     * @param label the post's name (not null)
     * @param x where it stands (in metres)
     * @param heightMetres how tall it is (in metres, finite, &gt;0)
     * @param color its colour (not null, not modified)
     * @param nameAtFoot true for the name right of the post's foot, false for above its top
     */
    void addMarker(String label, float x, float heightMetres, ColorRGBA color,
            boolean nameAtFoot) {
        if (!(heightMetres > 0f) || Float.isInfinite(heightMetres)) {
            throw new IllegalArgumentException(
                    "marker height (m) must be finite and > 0, but was " + heightMetres);
        }
        markers.add(new Marker(label, x, heightMetres, color.clone(), nameAtFoot));
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
        measure = TextMeasure.of(font);
        this.assets = assets;
        this.font = font;
        this.sceneNode = sceneNode;
        for (int i = 0; i < markers.size(); ++i) {
            Marker marker = markers.get(i);
            // The post is a bar this wide, centred on its x: a name at its foot starts at its
            // right side, a gap beyond it.
            float postWidth = POST_RADIUS_FRACTION * sphereRadius;
            sceneNode.attachChild(ParticleView.createPost(assets, marker.label, marker.x,
                    marker.height, postWidth, marker.color));
            SceneLabel name = marker.nameAtFoot
                    ? new SceneLabel(font, marker.label, marker.color,
                            marker.x + postWidth / 2f, 0f, SceneLabel.Anchor.FOOT_RIGHT)
                    : new SceneLabel(font, marker.label, marker.color, marker.x,
                            marker.height, SceneLabel.Anchor.ABOVE);
            fixedLabels.add(name);
            sceneNode.attachChild(name.getText());
            Geometry plate = ParticleView.createPlate(assets, POST_PLATE + i);
            postPlates.add(plate);
            sceneNode.attachChild(plate);
        }
        markerLabels = fixedLabels.size();
        buildGrid();
        DirectionalLight sun = new DirectionalLight(
                new Vector3f(-0.4f, -0.6f, -0.7f).normalizeLocal(), ColorRGBA.White.clone());
        sceneNode.addLight(sun);
        sceneNode.addLight(new AmbientLight(new ColorRGBA(0.45f, 0.45f, 0.5f, 1f)));
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            ParticleView view = new ParticleView(assets, font, particle.getLabel(),
                    particle.getColor(), sphereRadius, TRAIL_POINTS);
            views.add(view);
            view.getTrail().add(particle.getParticle().position);
            view.getArrow().setVisible(arrowsVisible);
            // No arrow crosses the ground band's distance marks into the footer.
            view.getArrow().setFloor(0f);
            view.getTrail().setDotsVisible(dotsVisible);
            sceneNode.attachChild(view.getNode());
        }
        int count = particles.size();
        labelWidths = new float[count];
        sphereX = new float[count];
        sphereY = new float[count];
        atEdge = new boolean[count];
        edgeTexts = new StringBuilder[count];
        labelLeader = new int[count];
        joinedTexts = new StringBuilder[count];
        for (int i = 0; i < count; ++i) {
            edgeTexts[i] = new StringBuilder(64);
            joinedTexts[i] = new StringBuilder(128);
        }
        nearX = new float[count * (TRAIL_POINTS + ARROW_SAMPLES)];
        nearY = new float[count * (TRAIL_POINTS + ARROW_SAMPLES)];
    }

    /**
     * Fit the region into the screen area the HUD leaves free, and place the fixed labels
     * (posts' names, distance marks) and the particles' labels for that layout. Call after
     * {@link #build}, and again whenever the HUD's layout changed.
     *
     * @param hud the HUD's layout (not null, not modified)
     */
    void layOut(HudLayout hud) {
        ScreenRect window = hud.getWindow();
        ScreenRect area = hud.getScene();
        labelSize = hud.getSceneLabelSize();
        labelHeight = measure.lineHeight(labelSize);
        // Frame enough ground below y = 0 for the footer drawn on it and the distance marks
        // above the footer: at least the declared band, and at least the floor and
        // GROUND_LABEL_ROOM label heights on the screen (refined as the scale settles).
        float floor = Math.max(0f, hud.getSceneFloor() - area.getY());
        float bottom = yMin;
        for (int pass = 0; pass < 3; ++pass) {
            plane.fit(xMin, xMax, bottom, frameTop, area, window.getWidth(),
                    window.getHeight());
            bottom = Math.min(yMin, -(GROUND_LABEL_ROOM * labelHeight + floor)
                    / plane.getPixelsPerMetre());
        }
        // Widen the framed region to the area's shape, as a camera with the area's aspect
        // would: wider (about its centre) when the area is wider than the region, higher
        // (above the ground) when it is narrower, so the scene fills the area, no bands.
        float left = xMin;
        float right = xMax;
        float top = frameTop;
        float areaAspect = Math.max(PlaneView.MIN_PIXELS, area.getWidth())
                / Math.max(PlaneView.MIN_PIXELS, area.getHeight());
        if ((right - left) < areaAspect * (top - bottom)) {
            float extra = areaAspect * (top - bottom) - (right - left);
            left -= extra / 2f;
            right += extra / 2f;
        } else {
            top = bottom + (right - left) / areaAspect;
        }
        plane.fit(left, right, bottom, top, area, window.getWidth(), window.getHeight());
        if (grid == null || gridStale || left != gridLeft || right != gridRight
                || top != gridTop) {
            gridStale = false;
            gridLeft = left;
            gridRight = right;
            gridTop = top;
            buildGrid();
        }
        gridBottom = bottom;
        grid.setGroundDepth(-bottom);
        float margin = hud.getMargin();
        // The particles' labels stay inside the margins and above the footer band, which
        // holds the footer's line: "discrete" dropped there at the target's foot (aiming,
        // h = 1/10, issue 29 §3), where the footer band scored better than the post.
        float textBottom = Math.max(margin, hud.getSceneFloor());
        textArea.set(margin, textBottom, window.getWidth() - 2f * margin,
                window.getHeight() - margin - textBottom);
        // The fixed labels stay inside the scene's area (marks above the frame are hidden).
        float fixedBottom = Math.max(area.getY(), margin);
        fixedArea.set(Math.max(area.getX(), margin), fixedBottom,
                Math.min(area.getRight(), window.getWidth() - margin)
                        - Math.max(area.getX(), margin), area.getTop() - fixedBottom);
        // A label keeps clear of a trail as drawn, not of its centre line: the step dots
        // reach 0.35 radii to each side ("undamped spring" ran into its trail at 1920x1080).
        trailHalfWidth = 0f;
        for (int i = 0; i < particles.size(); ++i) {
            trailHalfWidth = Math.max(trailHalfWidth, plane.getPixelsPerMetre()
                    * views.get(i).getTrail().getDrawnHalfWidth());
        }
        trailClearance = trailHalfWidth + TRAIL_CLEARANCE * hud.getScale();
        hudRects.clear();
        hudRects.add(hud.getTitle());
        hudRects.add(hud.getBody());
        hudRects.add(hud.getWarning());
        hudRects.add(hud.getFooter());
        // Presentation mode's readout strip (empty in the full HUD).
        hudRects.add(hud.getReadout());
        // The side panel's and the graph's slots (empty, covering nothing, when not asked for).
        hudRects.add(hud.getSidePanel());
        hudRects.add(hud.getGraph());
        // The energy ledger's strip (empty when not shown): the scene's area stays left of it.
        hudRects.add(hud.getLedger());
        panelSlot = hud.getSidePanel();
        graphSlot = hud.getGraph();
        sceneArea = hud.getScene();
        // The ground's marks thinned to a stride that keeps two shown from touching.
        float widestMark = 0f;
        int marks = grid.countGroundMarks();
        for (int m = 0; m < marks; ++m) {
            widestMark = Math.max(widestMark,
                    measure.width(fixedLabels.get(markerLabels + m).getText().getText(),
                            labelSize));
        }
        int markStride = MarkThinning.stride(grid.getMarkSpacing() * plane.getPixelsPerMetre(),
                widestMark, MARK_GAP_FRACTION * labelSize);
        for (int i = 0; i < fixedLabels.size(); ++i) {
            SceneLabel label = fixedLabels.get(i);
            label.preferredRect(plane, measure, labelSize, candidate);
            // Shift a mark that would stick out of the window ("14 m" at the right edge).
            float preferredX = candidate.getX();
            float x = Math.max(fixedArea.getX(),
                    Math.min(preferredX, fixedArea.getRight() - candidate.getWidth()));
            candidate.set(x, candidate.getY(), candidate.getWidth(), candidate.getHeight());
            int mark = i - markerLabels;
            boolean groundMark = mark >= 0 && mark < marks;
            boolean free = fixedArea.contains(candidate) && !coversHud(candidate)
                    && (!groundMark
                            || MarkThinning.isShown(grid.getGroundMarkIndex(mark), markStride));
            if (free && groundMark && x != preferredX) {
                // Shifted towards its neighbour, the edge's mark goes if it comes within the
                // gap of one shown, rather than the neighbour at its true place.
                free = !nearShownMark(mark, marks, markStride, MARK_GAP_FRACTION * labelSize);
            }
            for (int j = 0; j < i && free; ++j) {
                SceneLabel other = fixedLabels.get(j);
                free = !(other.isPlaced() && other.getRect().intersects(candidate));
            }
            label.apply(plane, labelSize, candidate, free);
        }
        for (int i = 0; i < particles.size(); ++i) {
            labelWidths[i] = measure.width(particles.get(i).getLabel(), labelSize);
        }
        laidOut = true;
        placeParticleLabels(true);
    }

    /**
     * Test whether the candidate rectangle comes within a gap of another ground mark shown at
     * its preferred place.
     *
     * @param self the mark placed (index among the ground marks)
     * @param marks how many ground marks there are
     * @param stride the marks' stride ({@link MarkThinning})
     * @param gap the least room between two marks (in pixels)
     */
    private boolean nearShownMark(int self, int marks, int stride, float gap) {
        for (int m = 0; m < marks; ++m) {
            if (m == self || !MarkThinning.isShown(grid.getGroundMarkIndex(m), stride)) {
                continue;
            }
            fixedLabels.get(markerLabels + m).preferredRect(plane, measure, labelSize,
                    neighbourMark);
            if (neighbourMark.getX() - gap < candidate.getRight()
                    && neighbourMark.getRight() + gap > candidate.getX()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Choose where the views draw the particles between their last two physics states.
     *
     * @param alpha the blend (0: the previous state, 1: the state now)
     */
    void setDrawBlend(float alpha) {
        drawBlend = alpha;
    }

    /**
     * Move every particle's view (sphere, label, arrow) to its particle, or between its last
     * two states ({@link #setDrawBlend}). Allocates nothing.
     */
    void updateViews() {
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            // Drawn between the last two physics states (the replay's blend); the arrow is
            // the physics velocity.
            viewOf(particle).update(particle.getBody().copyDrawnPosition(drawBlend, drawn),
                    particle.getParticle().velocity);
        }
        if (laidOut) {
            placeParticleLabels(false);
            uncoverFixedLabels();
        }
    }

    /** @return the particles' radius as drawn (in metres, &gt;0) */
    float getSphereRadius() {
        return sphereRadius;
    }

    /**
     * Access a particle's view (its sphere, label, trail and arrow).
     *
     * @param particle one of the demo's particles (not null)
     * @return the live view, or null before {@link #build}
     */
    ParticleView viewOf(DemoParticle particle) {
        return views.isEmpty() ? null : views.get(particle.index);
    }

    /**
     * Walk a particle's trail back one step, as a step undone by the replay.
     *
     * @param particle one of the demo's particles (not null)
     */
    void undoTrailStep(DemoParticle particle) {
        if (!views.isEmpty()) {
            viewOf(particle).getTrail().removeNewest();
        }
    }

    /**
     * Walk a particle's trail forward one step, as a step redone by the replay.
     *
     * @param particle one of the demo's particles (not null)
     */
    void redoTrailStep(DemoParticle particle) {
        if (!views.isEmpty()) {
            viewOf(particle).getTrail().add(particle.getParticle().position);
        }
    }

    /**
     * Access the plane's mapping to the window of the last layout.
     *
     * @return the live mapping (not null, do not modify)
     */
    PlaneView getPlaneView() {
        return plane;
    }

    /**
     * Copy the rectangle the scene is drawn into, as the last layout framed it: the grid and
     * the ground band's extent on the screen, within the scene's area (the HUD's backdrop
     * covers the rest).
     *
     * @param area the scene's area the layout was given (not null, not modified)
     * @param storeResult storage for the rectangle (not null, modified)
     * @return storeResult
     */
    ScreenRect copyDrawnRect(ScreenRect area, ScreenRect storeResult) {
        float left = Math.max(area.getX(), plane.screenX(gridLeft));
        float right = Math.min(area.getRight(), plane.screenX(gridRight));
        float bottom = Math.max(area.getY(), plane.screenY(gridBottom));
        float top = Math.min(area.getTop(), plane.screenY(Math.max(yMax, gridTop)));
        storeResult.set(left, bottom, Math.max(0f, right - left), Math.max(0f, top - bottom));
        return storeResult;
    }

    /**
     * Make a demo's own spheres obstacles for the particles' labels, as the particles' spheres
     * are (as bad to cover as a sphere): the views are read each frame, as last drawn.
     *
     * @param spheres the spheres (alias kept; null for none)
     */
    void setObstacleSpheres(BodyViews spheres) {
        obstacleSpheres = spheres;
    }

    /** Test whether a place covers an obstacle sphere shown. Allocates nothing. */
    private boolean coversObstacleSphere(ScreenRect place) {
        if (obstacleSpheres == null) {
            return false;
        }
        float scale = plane.getPixelsPerMetre();
        for (int k = 0; k < obstacleSpheres.capacity(); ++k) {
            float r = obstacleSpheres.getDrawnRadius(k) * scale;
            if (r > 0f) {
                obstacleSpheres.copyDrawnCentre(k, obstacleCentre);
                float x = plane.screenX(obstacleCentre.x);
                float y = plane.screenY(obstacleCentre.y);
                if (x + r > place.getX() && x - r < place.getRight() && y + r > place.getY()
                        && y - r < place.getTop()) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Copy the screen rectangle of every post ({@link #addMarker}), from the ground to its
     * top, into a list, for tests of the layout.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyPostRects(List<ScreenRect> storeResult) {
        float halfWidth = 0.5f * POST_RADIUS_FRACTION * sphereRadius * plane.getPixelsPerMetre();
        for (int i = 0; i < markers.size(); ++i) {
            Marker marker = markers.get(i);
            float ground = plane.screenY(0f);
            storeResult.add(new ScreenRect(plane.screenX(marker.x) - halfWidth, ground,
                    2f * halfWidth, plane.screenY(marker.height) - ground));
        }
        return storeResult;
    }

    /**
     * Copy the screen rectangle of every post's name ({@link #addMarker}), shown or not, into
     * a list, for tests of the layout.
     *
     * @param storeResult where to add them, in the posts' order (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyPostLabelRects(List<ScreenRect> storeResult) {
        for (int i = 0; i < markerLabels; ++i) {
            storeResult.add(new ScreenRect().set(fixedLabels.get(i).getRect()));
        }
        return storeResult;
    }

    /**
     * Copy the screen rectangle of every scene text shown (posts' names, distance marks,
     * particles' labels) into a list, for tests of the layout.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        for (int i = 0; i < fixedLabels.size(); ++i) {
            if (fixedLabels.get(i).isVisible()) {
                storeResult.add(new ScreenRect().set(fixedLabels.get(i).getRect()));
            }
        }
        for (int i = 0; i < particles.size(); ++i) {
            storeResult.add(new ScreenRect().set(viewOf(particles.get(i)).getLabelRect()));
        }
        return storeResult;
    }

    /**
     * Access the listener that writes the trails after each step, for the demo to register on
     * its world once the views are built (and to remove when they go).
     *
     * @return the listener (not null)
     */
    StepListener getTrailWriter() {
        return trailWriter;
    }

    /**
     * Start a particle's trail again at its position; before {@link #build}, do nothing.
     * Allocates nothing.
     *
     * @param particle one of the demo's particles (not null, not modified)
     */
    void restartTrail(DemoParticle particle) {
        if (viewOf(particle) != null) {
            viewOf(particle).getTrail().clear();
            viewOf(particle).getTrail().add(particle.getParticle().position);
        }
    }

    /**
     * Show a particle's new label: its text and, once laid out, its measured width, so the
     * next placement finds it a free slot. Before {@link #build}, do nothing (the view is
     * built with the label).
     *
     * @param particle one of the demo's particles, already relabelled (not null)
     */
    void relabel(DemoParticle particle) {
        if (viewOf(particle) == null) {
            return;
        }
        viewOf(particle).setLabelText(particle.getLabel());
        int index = particles.indexOf(particle);
        if (laidOut && index >= 0) {
            labelWidths[index] = measure.width(particle.getLabel(), labelSize);
        }
    }

    /**
     * Show the velocity arrows if hidden, hide them if shown.
     */
    void toggleArrows() {
        arrowsVisible = !arrowsVisible;
        for (int i = 0; i < particles.size(); ++i) {
            if (viewOf(particles.get(i)) != null) {
                viewOf(particles.get(i)).getArrow().setVisible(arrowsVisible);
            }
        }
    }

    /**
     * Show the trails' step dots if hidden, hide them if shown.
     */
    void toggleDots() {
        dotsVisible = !dotsVisible;
        for (int i = 0; i < particles.size(); ++i) {
            if (viewOf(particles.get(i)) != null) {
                viewOf(particles.get(i)).getTrail().setDotsVisible(dotsVisible);
            }
        }
    }

    /**
     * Test whether the trails' step dots are shown.
     *
     * @return true if shown
     */
    boolean areDotsVisible() {
        return dotsVisible;
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
        CameraFraming.frame(camera, plane);
    }

    /**
     * Build the grid over the region, in place of the one before (and its marks). The new
     * grid is made first: one that cannot be made leaves the old one whole, marks and all.
     */
    private void buildGrid() {
        DistanceGrid built = new DistanceGrid(assets, font, gridLeft, gridRight, yMin,
                Math.max(yMax, gridTop), gridSpacing, gridLabelEvery);
        if (grid != null) {
            grid.getNode().removeFromParent();
            for (int i = fixedLabels.size() - 1; i >= markerLabels; --i) {
                fixedLabels.remove(i);
            }
        }
        grid = built;
        sceneNode.attachChild(grid.getNode());
        fixedLabels.addAll(grid.getLabels());
    }

    /** The smallest of 1, 2, 5 times a power of ten of the declared spacing, at least s. */
    private float niceSpacing(float spacing) {
        float decade = declaredSpacing;
        while (true) {
            if (decade >= spacing) {
                return decade;
            }
            if (2f * decade >= spacing) {
                return 2f * decade;
            }
            if (5f * decade >= spacing) {
                return 5f * decade;
            }
            decade *= 10f;
        }
    }

    /**
     * Give every particle's label the best slot beside its sphere, in the particles' order:
     * keep the slot it has while that stays free (unless a nearer one is free), else take the
     * slot that covers least. Allocates nothing.
     *
     * @param fresh true to choose again from scratch (after a new layout)
     */
    private void placeParticleLabels(boolean fresh) {
        int count = particles.size();
        for (int i = 0; i < count; ++i) {
            Vector3f position = particles.get(i).getParticle().position;
            // A particle its demo hides (culled) covers nothing: NaN meets no slot.
            boolean hidden = isHidden(viewOf(particles.get(i)));
            sphereX[i] = hidden ? Float.NaN : plane.screenX(position.x);
            sphereY[i] = hidden ? Float.NaN : plane.screenY(position.y);
        }
        float radius = sphereRadius * plane.getPixelsPerMetre();
        findLabelLeaders(radius);
        for (int i = 0; i < count; ++i) {
            ParticleView view = viewOf(particles.get(i));
            if (isHidden(view) || labelLeader[i] != i) {
                // Hidden, or named by the joined label of a sphere it coincides with.
                view.hideLabel();
                continue;
            }
            if (placeEdgeLabel(i, view, radius)) {
                continue;
            }
            boolean joined = writeJoinedText(i, false) > 0f;
            if (!joined && view.isLabelJoined()) {
                view.setLabelText(particles.get(i).getLabel());
            }
            view.setLabelJoined(joined);
            // A joined label tries one line first, then its names stacked one per line (the
            // launch of three lanes from one spot) where one line finds no free slot.
            for (int form = 0; form < (joined ? 2 : 1); ++form) {
                float width = labelWidths[i];
                float height = labelHeight;
                if (joined) {
                    width = writeJoinedText(i, form == 1);
                    height = form == 1 ? joinedLines(i) * labelHeight : labelHeight;
                    view.setLabelText(joinedTexts[i]);
                }
                if (placeLabelBeside(i, view, radius, width, height, fresh || form == 1)) {
                    break;
                }
            }
        }
    }

    /**
     * Put particle i's label of this size in the best slot beside its sphere: keep the slot
     * it has while that stays free (unless a nearer one is free), else take the slot that
     * covers least; hide it where every slot covers text, a sphere or a post.
     *
     * @return true if placed, false if hidden
     */
    private boolean placeLabelBeside(int i, ParticleView view, float radius, float width,
            float height, boolean fresh) {
        gatherTrailPoints(sphereX[i], sphereY[i], radius, width, height);
        int current = fresh ? -1 : view.getLabelSlot();
        int best = -1;
        int bestScore = Integer.MAX_VALUE;
        int currentScore = Integer.MAX_VALUE;
        for (int slot = 0; slot < LabelSlots.COUNT; ++slot) {
            slotRect(slot, i, radius, width, height, candidate);
            int score = score(candidate, i, radius);
            if (slot == current) {
                currentScore = score;
            }
            if (score < bestScore) {
                bestScore = score;
                best = slot;
            }
        }
        boolean keep = current >= 0 && currentScore == 0
                && LabelSlots.ring(best) >= LabelSlots.ring(current);
        int slot = keep ? current : best;
        slotRect(slot, i, radius, width, height, chosen);
        if (chosen.intersects(panelSlot) || chosen.intersects(graphSlot)
                || (keep ? currentScore : bestScore) >= SPHERE_PENALTY) {
            // The sphere is under the panel or the graph, or every slot beside it covers
            // text, a sphere or a post, or leaves the window (large text on a crowded
            // scene): the label waits for a free slot.
            view.hideLabel();
            return false;
        }
        // The least bad slot: over a trail only where every slot is, then on a plate
        // that hides the trail under it, so the name stays readable.
        view.placeLabel(plane, labelSize, slot, chosen, coversNearPoint(chosen));
        return true;
    }

    /**
     * Compute particle i's label slot ({@link LabelSlots}), the nearest ring's slots beside the
     * sphere (right and left) raised onto the ground line where the sphere's centre lies
     * within half a label height above it: a landed sphere's side slots would reach into the
     * ground band, and with its top slots over a post (aiming, h = 1/10: both shots down at
     * the target's foot) its label had no free place. Raised by at most half a label height,
     * the slot stays beside the sphere; the farther rings are not raised, so a label does not
     * hop over a neighbouring sphere to the ground beyond it ("lecture" beside "discrete"'s
     * sphere).
     */
    private void slotRect(int slot, int i, float radius, float width, float height,
            ScreenRect storeResult) {
        LabelSlots.rect(slot, sphereX[i], sphereY[i], radius, width, height, storeResult);
        int direction = slot % LabelSlots.DIRECTIONS;
        float ground = plane.screenY(0f);
        if (LabelSlots.ring(slot) == 0 && (direction == 1 || direction == 3)
                && sphereY[i] >= ground
                && storeResult.getY() < ground) {
            storeResult.set(storeResult.getX(), ground, width, height);
        }
    }

    /**
     * Find each particle's label leader: the first particle before it, itself a leader, whose
     * sphere coincides with its own on the screen (centres closer than
     * {@link ParticleView#JOIN_RADII} radii), both shown and inside the scene's sides; else
     * itself. Allocates nothing.
     */
    private void findLabelLeaders(float radius) {
        float join = ParticleView.JOIN_RADII * radius;
        for (int i = 0; i < labelLeader.length; ++i) {
            labelLeader[i] = i;
            if (!isJoinable(i, radius)) {
                continue;
            }
            for (int j = 0; j < i; ++j) {
                float dx = sphereX[j] - sphereX[i];
                float dy = sphereY[j] - sphereY[i];
                if (labelLeader[j] == j && isJoinable(j, radius)
                        && dx * dx + dy * dy < join * join) {
                    labelLeader[i] = j;
                    break;
                }
            }
        }
    }

    /** Test whether a particle's sphere is shown and not beyond the scene's sides. */
    private boolean isJoinable(int i, float radius) {
        // sphereX is NaN for a culled particle: the comparisons fail.
        return sphereX[i] - radius <= sceneArea.getRight()
                && sphereX[i] + radius >= sceneArea.getX();
    }

    /**
     * Write a leader's joined label into {@link #joinedTexts}: its name, then the names of the
     * particles it leads, in order ("ball = slide code"). Allocates nothing once the text has
     * been this long.
     *
     * @param stacked true for one name per line, each but the last ending in " ="
     * @return the text's width (in pixels; 0 if it leads no other, no text written)
     */
    private float writeJoinedText(int leader, boolean stacked) {
        StringBuilder text = joinedTexts[leader];
        text.setLength(0);
        float widest = 0f;
        for (int i = leader + 1; i < labelLeader.length; ++i) {
            if (labelLeader[i] == leader) {
                if (text.length() == 0) {
                    text.append(particles.get(leader).getLabel());
                    widest = labelWidths[leader];
                }
                text.append(stacked ? STACKED_SEPARATOR : ParticleView.JOIN_SEPARATOR)
                        .append(particles.get(i).getLabel());
                widest = Math.max(widest, labelWidths[i]);
            }
        }
        if (text.length() == 0) {
            return 0f;
        }
        // Stacked: the widest name and its " =" bound every line.
        return stacked ? widest + measure.width(STACKED_LINE_END, labelSize)
                : measure.width(text, labelSize);
    }

    /** How many names a leader's joined label holds (itself and those it leads). */
    private int joinedLines(int leader) {
        int lines = 1;
        for (int i = leader + 1; i < labelLeader.length; ++i) {
            if (labelLeader[i] == leader) {
                ++lines;
            }
        }
        return lines;
    }

    /**
     * Give a particle whose sphere lies beyond the scene's left or right side a label at that
     * side, on a plate, at the sphere's height (above the ground line), saying where it is
     * ("target (physics) at x = 21.0 m →"): a body that rolled out of the framed view is not
     * lost from it (issue 29 §3, clip's physics lane). When the sphere is back, its label is
     * its name again. Allocates nothing once the edge text has been this long.
     *
     * @return true if the particle's label was handled here (its sphere is beyond a side)
     */
    private boolean placeEdgeLabel(int i, ParticleView view, float radius) {
        boolean beyondRight = sphereX[i] - radius > sceneArea.getRight();
        boolean beyondLeft = sphereX[i] + radius < sceneArea.getX();
        DemoParticle particle = particles.get(i);
        if (!beyondRight && !beyondLeft) {
            if (atEdge[i]) {
                atEdge[i] = false;
                view.setLabelText(particle.getLabel());
            }
            return false;
        }
        if (particle.getLabel().isEmpty()) {
            // A nameless body parked out of sight (iterate's shots not yet fired, at
            // x = -1000 m) has no label to keep: no "\u2190 at x = -1000.0 m" at the edge.
            view.hideLabel();
            return true;
        }
        StringBuilder text = edgeTexts[i];
        text.setLength(0);
        if (beyondLeft) {
            text.append(LEFT_ARROW);
        }
        text.append(particle.getLabel()).append(" at x = ");
        TextFormat.appendFixed(text, particle.getParticle().position.x, EDGE_DECIMALS)
                .append(" m");
        if (beyondRight) {
            text.append(RIGHT_ARROW);
        }
        atEdge[i] = true;
        view.setLabelJoined(false);
        view.setLabelText(text);
        float width = measure.width(text, labelSize);
        float x = beyondRight ? fixedArea.getRight() - width : fixedArea.getX();
        float lowest = Math.max(fixedArea.getY(), plane.screenY(0f) + 0.15f * labelHeight);
        float highest = fixedArea.getTop() - labelHeight;
        float y = Math.max(lowest, Math.min(highest, sphereY[i] - labelHeight / 2f));
        for (int tries = 0; tries < EDGE_TRIES; ++tries) {
            chosen.set(x, y, width, labelHeight);
            if (isFreeForEdgeLabel(chosen, i, radius)) {
                view.placeLabel(plane, labelSize, -1, chosen, true);
                return true;
            }
            y += labelHeight;
            if (y > highest) {
                break;
            }
        }
        view.hideLabel();
        return true;
    }

    /**
     * Test whether an edge label's place covers no HUD text, no fixed label, no label placed
     * before it and no sphere.
     */
    private boolean isFreeForEdgeLabel(ScreenRect place, int self, float radius) {
        if (!textArea.contains(place) || coversHud(place) || coversObstacleSphere(place)) {
            return false;
        }
        for (int i = 0; i < particles.size(); ++i) {
            // sphereX is NaN for a culled particle: it covers nothing.
            if (i != self && sphereX[i] + radius > place.getX()
                    && sphereX[i] - radius < place.getRight()
                    && sphereY[i] + radius > place.getY()
                    && sphereY[i] - radius < place.getTop()) {
                return false;
            }
        }
        for (int i = 0; i < fixedLabels.size(); ++i) {
            SceneLabel label = fixedLabels.get(i);
            if (label.isPlaced() && label.getRect().intersects(place)) {
                return false;
            }
        }
        for (int i = 0; i < self; ++i) {
            if (viewOf(particles.get(i)).getLabelRect().intersects(place)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Hide each post's name and distance mark while a sphere shown covers it (the "0 m" mark
     * under a ball launched from the ground), and show it again when the sphere has moved on.
     * Allocates nothing.
     */
    private void uncoverFixedLabels() {
        float radius = sphereRadius * plane.getPixelsPerMetre();
        for (int i = 0; i < fixedLabels.size(); ++i) {
            SceneLabel label = fixedLabels.get(i);
            ScreenRect place = label.getRect();
            boolean covered = false;
            for (int p = 0; p < particles.size() && !covered; ++p) {
                // sphereX is NaN for a culled particle: it covers nothing.
                covered = label.isPlaced() && sphereX[p] + radius > place.getX()
                        && sphereX[p] - radius < place.getRight()
                        && sphereY[p] + radius > place.getY()
                        && sphereY[p] - radius < place.getTop();
            }
            label.setCovered(covered);
            if (i < markerLabels) {
                // A post's name over a trail as drawn lies on a plate that hides the trail
                // under it, as a particle's label with no free slot does.
                ParticleView.placePlate(postPlates.get(i), plane, place,
                        label.isVisible() && coversTrail(place));
            }
        }
    }

    /** Test whether a rectangle covers a trail as drawn (ribbon and step dots). */
    private boolean coversTrail(ScreenRect place) {
        for (int i = 0; i < particles.size(); ++i) {
            ParticleView view = viewOf(particles.get(i));
            if (isHidden(view)) {
                continue;
            }
            Trail trail = view.getTrail();
            for (int age = 0; age < trail.size(); ++age) {
                trail.copyPoint(age, trailPoint);
                float x = plane.screenX(trailPoint.x);
                float y = plane.screenY(trailPoint.y);
                if (x >= place.getX() - trailHalfWidth && x <= place.getRight() + trailHalfWidth
                        && y >= place.getY() - trailHalfWidth
                        && y <= place.getTop() + trailHalfWidth) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Test whether the demo hid a particle's view (sphere, trail, label) by culling it. */
    private static boolean isHidden(ParticleView view) {
        return view.getNode().getCullHint() == Spatial.CullHint.Always;
    }

    /** Test whether a rectangle covers a trail, as drawn, at a point gathered last. */
    private boolean coversNearPoint(ScreenRect place) {
        for (int i = 0; i < nearTrailCount; ++i) {
            if (nearX[i] >= place.getX() - trailHalfWidth
                    && nearX[i] <= place.getRight() + trailHalfWidth
                    && nearY[i] >= place.getY() - trailHalfWidth
                    && nearY[i] <= place.getTop() + trailHalfWidth) {
                return true;
            }
        }
        return false;
    }

    /** Collect the trail and arrow points within reach of any slot of a label, on screen. */
    private void gatherTrailPoints(float centreX, float centreY, float radius, float width,
            float height) {
        float far = LabelSlots.extent(radius, width, height);
        reach.set(centreX - far - trailClearance, centreY - far - trailClearance,
                2f * (far + trailClearance), 2f * (far + trailClearance));
        nearCount = 0;
        for (int i = 0; i < particles.size(); ++i) {
            Trail trail = viewOf(particles.get(i)).getTrail();
            for (int age = 0; age < trail.size(); ++age) {
                trail.copyPoint(age, trailPoint);
                float x = plane.screenX(trailPoint.x);
                float y = plane.screenY(trailPoint.y);
                keepIfNear(x, y);
            }
        }
        nearTrailCount = nearCount;
        for (int i = 0; i < particles.size(); ++i) {
            if (arrowsVisible) {
                Vector3f position = particles.get(i).getParticle().position;
                Vector3f velocity = particles.get(i).getParticle().velocity;
                for (int sample = 1; sample <= ARROW_SAMPLES; ++sample) {
                    float along = ParticleView.ARROW_SECONDS * sample / ARROW_SAMPLES;
                    keepIfNear(plane.screenX(position.x + along * velocity.x),
                            plane.screenY(position.y + along * velocity.y));
                }
            }
        }
    }

    private void keepIfNear(float x, float y) {
        if (reach.contains(x, y)) {
            nearX[nearCount] = x;
            nearY[nearCount] = y;
            ++nearCount;
        }
    }

    /** Score a place for particle self's label: 0 when it covers nothing. */
    private int score(ScreenRect place, int self, float radius) {
        int score = 0;
        if (!textArea.contains(place) || coversHud(place)) {
            score += TEXT_PENALTY;
        }
        // A sphere above the ground keeps its label above the ground line where it can: the
        // band below holds the distance marks and the footer ("slide code" lay across the
        // ground line by the "20 m" mark). Where nothing above is free, a plate over a trail
        // comes first, then below, which still beats no label.
        float ground = plane.screenY(0f);
        if (sphereY[self] >= ground && place.getY() < ground) {
            score += GROUND_PENALTY;
        }
        for (int i = 0; i < fixedLabels.size(); ++i) {
            SceneLabel label = fixedLabels.get(i);
            if (label.isPlaced() && label.getRect().intersects(place)) {
                score += TEXT_PENALTY;
            }
        }
        for (int i = 0; i < self; ++i) {
            if (viewOf(particles.get(i)).getLabelRect().intersects(place)) {
                score += TEXT_PENALTY;
            }
        }
        // a post (a target, a gun) standing from the ground to its height, with a margin of
        // its own width on each side: as bad to cover as a sphere
        float postHalfWidth = Math.max(1f, POST_RADIUS_FRACTION * radius);
        for (int i = 0; i < markers.size(); ++i) {
            Marker marker = markers.get(i);
            float postX = plane.screenX(marker.x);
            if (postX + postHalfWidth > place.getX() && postX - postHalfWidth < place.getRight()
                    && plane.screenY(marker.height) > place.getY()
                    && ground < place.getTop()) {
                score += SPHERE_PENALTY;
            }
        }
        for (int i = 0; i < particles.size(); ++i) {
            if (i != self && sphereX[i] + radius > place.getX()
                    && sphereX[i] - radius < place.getRight()
                    && sphereY[i] + radius > place.getY()
                    && sphereY[i] - radius < place.getTop()) {
                score += SPHERE_PENALTY;
            }
        }
        if (coversObstacleSphere(place)) {
            score += SPHERE_PENALTY;
        }
        float left = place.getX() - trailClearance;
        float right = place.getRight() + trailClearance;
        float bottom = place.getY() - trailClearance;
        float top = place.getTop() + trailClearance;
        int near = 0;
        for (int i = 0; i < nearCount; ++i) {
            if (nearX[i] >= left && nearX[i] <= right && nearY[i] >= bottom
                    && nearY[i] <= top) {
                ++near;
            }
        }
        score += Math.min(near, MAX_NEAR_POINTS);
        // Over a trail as drawn: better than below the ground line and than no label.
        if (coversNearPoint(place)) {
            score += TRAIL_PENALTY;
        }
        return score;
    }

    private boolean coversHud(ScreenRect place) {
        for (int i = 0; i < hudRects.size(); ++i) {
            if (hudRects.get(i).intersects(place)) {
                return true;
            }
        }
        return false;
    }

    /** A post declared by {@link #addMarker}, built by {@link #build}. */
    private static final class Marker {
        final String label;
        final float x;
        final float height;
        final ColorRGBA color;
        /** True for the name right of the post's foot, false for above its top. */
        final boolean nameAtFoot;

        Marker(String label, float x, float height, ColorRGBA color, boolean nameAtFoot) {
            this.label = label;
            this.x = x;
            this.height = height;
            this.color = color;
            this.nameAtFoot = nameAtFoot;
        }
    }
}

package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import java.util.List;
import particlelab.reference.ExactPath;
import particlelab.physics.Particle;
import particlelab.view.GhostView;
import particlelab.view.HudLayout;
import particlelab.view.LiveGraph;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.view.Trail;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.World;

/**
 * "Seeing the error" for a demo that asks for it ({@link DemoState#showExactGhosts()}): beside
 * each particle its exact ghost, the continuous path under the same forces from the same
 * launch ({@link ExactPath}: the closed form for gravity and linear drag, RK4 otherwise),
 * drawn faint; the HUD's readouts, Euler against exact; and a live graph of height and speed
 * against time.
 *
 * <p>The ghost starts when its particle takes its first step after a launch or reset, and
 * then moves by the same h as the particle, step for step, so the HUD's distance
 * {@code |P − P_exact|} compares the two at the same time. The ghost's trail gets a point at
 * least every {@link #GHOST_POINT_SECONDS}, so it is smooth even when h is long. When a
 * particle that stops at the ground lands, its ghost flies on to its own landing at once (at
 * most {@link #MAX_FINISH_SECONDS} more), so both flights' readouts are there together and the
 * clock stops as it always did, with the last Euler landing.
 *
 * <p>The HUD ({@link HudWriter}) adds the live distance to each particle's line while it
 * flies; once a particle that stops at the ground has landed together with its ghost, its line
 * becomes its readouts, each "Euler | exact": apex height and time, range (from the launch x)
 * and flight time ("range 20.24 | 20.41 m after a flight of 2.02 | 2.04 s"). So the body
 * keeps its height: a landed particle's position and zero velocity say nothing the range does
 * not. The Euler particle's come from its steps: it moves
 * on a straight segment within each step, so its apex is its highest step point; its landing
 * is where the segment of its last step crosses y = 0, interpolated linearly
 * ({@link DemoParticle#getLandingX()}). The ghost's come from the exact path, found inside the
 * step by bisection.
 *
 * <p>Contacts: the ghost does not model them. In a world with collision rules, a ghost stops
 * for good after the step in which its particle had its first resolved contact (a bounce, a
 * hit), and the particle's line then gives the distance at that moment and says the ghost
 * stopped there; after a bounce there is no single exact path to compare with.
 *
 * <p>A step back (Home, End, the timeline) shows the ghosts as they were at the step shown:
 * their paths, the Euler apexes, the contact stops and the graph's last sample are part of
 * the demo's recorded state ({@link StateRecord}), so the HUD's readouts and the graph's end
 * are those of that step; the ghosts' trails lose the points of the steps undone (a step
 * redone adds the ghost's position), and the graph draws only its samples before the step
 * shown ({@link LiveGraph#showEnd}).
 *
 * <p>Per step and per frame this allocates nothing.
 */
final class ExactGhosts implements StateRecord {

    /**
     * The ints of one particle's ghost in the recorded state: its path, the Euler apex
     * (float, double, boolean), the launch x, the contact flags and distance, the graph's
     * four values, and the trail's count of points and of restarts.
     */
    private static final int GHOST_STATE_INTS = ExactPath.STATE_INTS + 1 + 2 + 1 + 1 + 1 + 1 + 2
            + 4 + 2 + 1;

    /** The ghost's trail gets a point at least this often (in seconds of its flight). */
    static final double GHOST_POINT_SECONDS = 1.0 / 60.0;
    /** How long a ghost may fly on after its particle landed (in seconds). */
    static final double MAX_FINISH_SECONDS = 30.0;
    /** The graph's size at HUD scale 1 (in pixels); the layout may give it less. */
    static final float GRAPH_WIDTH = 560f;
    static final float GRAPH_HEIGHT = 220f;

    private final List<DemoParticle> particles;
    private boolean enabled;
    private boolean ghostsVisible = true;
    private boolean graphVisible;
    private ExactPath[] paths = new ExactPath[0];
    private GhostView[] views = new GhostView[0];
    /** Per particle: whether its ghost may be shown (a hidden comparison lane's is not). */
    private boolean[] ghostShown = new boolean[0];
    /**
     * Per particle: moved by other forces than those its exact path follows (the drag demo's
     * swapped laws), so neither its ghost nor its distance to it means anything.
     */
    private boolean[] otherForces = new boolean[0];
    /** Per particle: the Euler particle's highest step point and when (NaN: none yet). */
    private float[] eulerApexHeight = new float[0];
    private double[] eulerApexSeconds = new double[0];
    /** Per particle: whether the Euler particle is past its apex (falling, or landed). */
    private boolean[] eulerPastApex = new boolean[0];
    private float[] launchX = new float[0];
    /** Per particle: a contact was resolved in this step, and the ghost stopped for it. */
    private boolean[] contactThisStep = new boolean[0];
    private boolean[] stoppedAtContact = new boolean[0];
    private double[] contactError = new double[0];
    private final ContactListener contactListener = new ContactListener() {
        @Override
        public void resolved(Contact contact, World world) {
            noteContact(contact);
        }
    };
    private LiveGraph graph;
    private final Node graphNode = new Node("live graph holder");
    private float graphSeconds;
    /** The graph's flight ({@link LiveGraph#getFlight()}) the state shown belongs to. */
    private int graphFlight;
    /** Per ghost: the points its trail was given, and its restarts, ever (for a step back). */
    private long[] trailPoints = new long[0];
    private int[] trailRestarts = new int[0];
    private float[] eulerHeights = new float[0];
    private float[] eulerSpeeds = new float[0];
    private float[] exactHeights = new float[0];
    private float[] exactSpeeds = new float[0];
    /** The graph rectangle and scale the graph was last laid out for. */
    private final ScreenRect graphRect = new ScreenRect();
    private float graphScale = Float.NaN;
    private final Vector3f point = new Vector3f();

    /**
     * Create the ghosts of one demo; they do nothing until {@link #enable()}.
     *
     * @param particles the demo's particles (not null, live, not modified)
     */
    ExactGhosts(List<DemoParticle> particles) {
        this.particles = particles;
    }

    /** Ask for ghosts, readouts and the graph. Call before {@link #build}. */
    void enable() {
        enabled = true;
    }

    /** @return true if the demo asked for ghosts */
    boolean isEnabled() {
        return enabled;
    }

    /**
     * Build a ghost per particle and the graph, and start them from the particles' states.
     * Does nothing unless enabled. Call once, after the particles' views were built.
     *
     * @param assets the asset manager (not null)
     * @param font the labels' font (not null)
     * @param sceneNode where the ghosts go (not null, modified)
     * @param world the demo's world, whose resolved contacts stop the ghosts (not null,
     *     a listener is added)
     * @param scene the particles' views, built: the ghosts take their size (not null)
     */
    void build(AssetManager assets, BitmapFont font, Node sceneNode, World world,
            DemoScene scene) {
        if (!enabled) {
            return;
        }
        world.addContactListener(contactListener);
        int count = particles.size();
        paths = new ExactPath[count];
        views = new GhostView[count];
        ghostShown = new boolean[count];
        otherForces = new boolean[count];
        for (int i = 0; i < count; ++i) {
            ghostShown[i] = !particles.get(i).isGhostHidden();
        }
        eulerApexHeight = new float[count];
        eulerApexSeconds = new double[count];
        eulerPastApex = new boolean[count];
        launchX = new float[count];
        contactThisStep = new boolean[count];
        stoppedAtContact = new boolean[count];
        contactError = new double[count];
        eulerHeights = new float[count];
        eulerSpeeds = new float[count];
        exactHeights = new float[count];
        exactSpeeds = new float[count];
        trailPoints = new long[count];
        trailRestarts = new int[count];
        ColorRGBA[] colors = new ColorRGBA[count];
        for (int i = 0; i < count; ++i) {
            DemoParticle particle = particles.get(i);
            paths[i] = new ExactPath(particle.getPathIntegrator());
            views[i] = new GhostView(assets, particle.getLabel(), particle.getColor(),
                    scene.viewOf(particle).getRadius(),
                    scene.viewOf(particle).getTrail().getCapacity());
            sceneNode.attachChild(views[i].getNode());
            views[i].setVisible(ghostShown[i]);
            colors[i] = particle.getColor();
        }
        graph = new LiveGraph(assets, font, colors);
        graph.setVisible(graphVisible);
        graphNode.attachChild(graph.getNode());
        for (int i = 0; i < count; ++i) {
            restart(i);
        }
    }

    /**
     * Access the node holding the graph, for the GUI scene.
     *
     * @return the live node (not null; empty unless enabled)
     */
    Node getGraphNode() {
        return graphNode;
    }

    /**
     * Start one particle's ghost again from the particle's state (its launch), and the graph
     * from t = 0. Allocates nothing.
     *
     * @param index the particle's index
     */
    void restart(int index) {
        if (!enabled || paths.length == 0) {
            return;
        }
        DemoParticle demoParticle = particles.get(index);
        Particle particle = demoParticle.getParticle();
        paths[index].start(particle.position, particle.velocity, particle.getMass(),
                demoParticle.stopsAtGround());
        views[index].restart(particle.position);
        trailPoints[index] = 0L;
        ++trailRestarts[index];
        eulerApexHeight[index] = particle.position.y;
        eulerApexSeconds[index] = 0.0;
        eulerPastApex[index] = !(particle.velocity.y > 0f);
        launchX[index] = particle.position.x;
        contactThisStep[index] = false;
        stoppedAtContact[index] = false;
        contactError[index] = Double.NaN;
        graph.clear();
        graphFlight = graph.getFlight();
        graphSeconds = 0f;
        for (int i = 0; i < paths.length; ++i) {
            eulerHeights[i] = Float.NaN;
            eulerSpeeds[i] = Float.NaN;
            exactHeights[i] = Float.NaN;
            exactSpeeds[i] = Float.NaN;
        }
    }

    /**
     * Start every ghost again (a reset).
     */
    void restartAll() {
        for (int i = 0; i < paths.length; ++i) {
            restart(i);
        }
    }

    /**
     * Move each ghost whose particle took this step by the same h, note the Euler apex, and
     * record a graph sample. Call after each world step. Allocates nothing.
     *
     * @param stepSeconds h (in seconds, &gt;0)
     */
    void afterStep(float stepSeconds) {
        if (!enabled || paths.length == 0) {
            return;
        }
        if (graphFlight != graph.getFlight()) {
            // A step from a state shown before the last launch: its flight's samples are
            // gone, so the graph starts again here.
            graph.clear();
            graphFlight = graph.getFlight();
        }
        graphSeconds += stepSeconds;
        for (int i = 0; i < paths.length; ++i) {
            DemoParticle demoParticle = particles.get(i);
            Particle particle = demoParticle.getParticle();
            if (demoParticle.steppedThisStep && !stoppedAtContact[i]) {
                advanceGhost(i, stepSeconds);
                if (contactThisStep[i]) {
                    stoppedAtContact[i] = true;
                    contactError[i] = paths[i].distanceTo(particle.position);
                }
                if (particle.position.y > eulerApexHeight[i] && !eulerPastApex[i]) {
                    eulerApexHeight[i] = particle.position.y;
                    eulerApexSeconds[i] = demoParticle.getFlightSeconds();
                }
                if (!(particle.velocity.y > 0f)) {
                    eulerPastApex[i] = true;
                }
                if (demoParticle.hasLanded()) {
                    finishGhost(i);
                }
            }
            eulerHeights[i] = particle.position.y;
            eulerSpeeds[i] = particle.velocity.length();
            // A ghost flown on ahead of the clock has no value at this time: the graph leaves
            // its curve off from here (it ends at its own landing in the scene and readouts).
            boolean ahead = paths[i].getTimeSeconds() > graphSeconds + 0.5 * stepSeconds;
            exactHeights[i] = ahead ? Float.NaN : (float) paths[i].getPosition(1);
            exactSpeeds[i] = ahead ? Float.NaN : (float) paths[i].getSpeed();
        }
        graph.record(graphSeconds, eulerHeights, eulerSpeeds, exactHeights, exactSpeeds);
    }

    /**
     * Move the ghosts' views to their paths and redraw the graph, laying it out again if the
     * HUD's graph slot moved. Call once a frame. Allocates nothing.
     *
     * @param layout the HUD's layout (not null, not modified)
     * @param helpVisible true while the help overlay covers the scene (the graph hides)
     */
    void updateViews(HudLayout layout, boolean helpVisible) {
        if (!enabled || paths.length == 0) {
            return;
        }
        graph.setVisible(graphVisible && !helpVisible);
        for (int i = 0; i < paths.length; ++i) {
            views[i].update(paths[i].copyPosition(point));
        }
        ScreenRect slot = layout.getGraph();
        if (!sameRect(slot, graphRect) || layout.getScale() != graphScale) {
            graphRect.set(slot);
            graphScale = layout.getScale();
            graph.layOut(slot, layout.getSceneLabelSize());
        }
        graph.refresh();
    }

    /**
     * Count the ints {@link #writeState} writes: a count and the graph's time until the
     * ghosts are built.
     *
     * @return the count (&ge;2)
     */
    @Override
    public int countStateInts() {
        return paths.length == 0 ? 2 : 3 + paths.length * GHOST_STATE_INTS;
    }

    /**
     * Write the ghosts' state: each path, the Euler apex, the contact stop, the graph's last
     * sample and the trail's counts. Allocates nothing.
     *
     * @param slab where to write (not null, modified)
     */
    @Override
    public void writeState(StateSlab slab) {
        slab.putInt(paths.length);
        slab.putFloat(graphSeconds);
        if (paths.length == 0) {
            return;
        }
        slab.putInt(graphFlight);
        for (int i = 0; i < paths.length; ++i) {
            paths[i].writeState(slab);
            slab.putFloat(eulerApexHeight[i]);
            slab.putDouble(eulerApexSeconds[i]);
            slab.putBoolean(eulerPastApex[i]);
            slab.putFloat(launchX[i]);
            slab.putBoolean(contactThisStep[i]);
            slab.putBoolean(stoppedAtContact[i]);
            slab.putDouble(contactError[i]);
            slab.putFloat(eulerHeights[i]);
            slab.putFloat(eulerSpeeds[i]);
            slab.putFloat(exactHeights[i]);
            slab.putFloat(exactSpeeds[i]);
            slab.putLong(trailPoints[i]);
            slab.putInt(trailRestarts[i]);
        }
    }

    /**
     * Put the ghosts' state back: the paths and readouts as they were, the trails walked to
     * the step shown, the graph ending at its sample. A state written before the ghosts were
     * built is skipped. Allocates nothing.
     *
     * @param slab where to read (not null, modified)
     */
    @Override
    public void readState(StateSlab slab) {
        int recorded = slab.getInt();
        float recordedSeconds = slab.getFloat();
        if (recorded != paths.length) {
            for (int i = 0; i < (recorded == 0 ? 0 : 1 + recorded * GHOST_STATE_INTS); ++i) {
                slab.getInt();
            }
            return;
        }
        graphSeconds = recordedSeconds;
        if (paths.length == 0) {
            return;
        }
        graphFlight = slab.getInt();
        for (int i = 0; i < paths.length; ++i) {
            paths[i].readState(slab);
            eulerApexHeight[i] = slab.getFloat();
            eulerApexSeconds[i] = slab.getDouble();
            eulerPastApex[i] = slab.getBoolean();
            launchX[i] = slab.getFloat();
            contactThisStep[i] = slab.getBoolean();
            stoppedAtContact[i] = slab.getBoolean();
            contactError[i] = slab.getDouble();
            eulerHeights[i] = slab.getFloat();
            eulerSpeeds[i] = slab.getFloat();
            exactHeights[i] = slab.getFloat();
            exactSpeeds[i] = slab.getFloat();
            long points = slab.getLong();
            int restarts = slab.getInt();
            walkTrail(i, points, restarts);
        }
        graph.showEnd(graphFlight, graphSeconds, eulerHeights, eulerSpeeds, exactHeights,
                exactSpeeds);
    }

    /**
     * Show or hide the ghosts.
     */
    void toggleGhosts() {
        ghostsVisible = !ghostsVisible;
        for (int i = 0; i < views.length; ++i) {
            views[i].setVisible(ghostsVisible && ghostShown[i]);
        }
    }

    /**
     * Say whether a particle runs other forces than its exact path follows (the drag demo's
     * swapped laws): then its ghost is hidden and the HUD compares nothing with it. Does
     * nothing before the ghosts are built. Allocates nothing.
     *
     * @param index the particle's index
     * @param other true while its forces are not its path's
     */
    void setOtherForces(int index, boolean other) {
        if (index < otherForces.length) {
            otherForces[index] = other;
            setGhostShown(index, !other && !particles.get(index).isGhostHidden());
        }
    }

    /**
     * Let one particle's ghost be shown (with the others, as G has them) or keep it hidden,
     * e.g. the ghost of a comparison lane while the lane is off. Does nothing before the
     * ghosts are built. Allocates nothing.
     *
     * @param index the particle's index
     * @param shown true to show it with the others
     */
    void setGhostShown(int index, boolean shown) {
        if (index >= views.length || ghostShown[index] == shown) {
            return;
        }
        ghostShown[index] = shown;
        views[index].setVisible(ghostsVisible && shown);
    }

    /** @return true if the ghosts are shown */
    boolean areGhostsVisible() {
        return ghostsVisible;
    }

    /**
     * Show or hide the graph, and ask the HUD's layout for its slot or give it back; the
     * caller lays the HUD out again.
     *
     * @param layout the HUD's layout (not null, modified)
     */
    void toggleGraph(HudLayout layout) {
        graphVisible = !graphVisible;
        layout.setGraphSize(graphVisible ? GRAPH_WIDTH : 0f,
                graphVisible ? GRAPH_HEIGHT : 0f);
        if (graph != null) {
            graph.setVisible(graphVisible);
        }
    }

    /** @return true if the graph is shown */
    boolean isGraphVisible() {
        return graphVisible;
    }

    /**
     * Access the graph.
     *
     * @return the live graph (null unless enabled and built)
     */
    LiveGraph getGraph() {
        return graph;
    }

    /**
     * Access one particle's exact path.
     *
     * @param index the particle's index
     * @return the live path (not null once built)
     */
    ExactPath getPath(int index) {
        return paths[index];
    }

    /**
     * Return the Euler particle's apex so far: its highest step point since the launch, up to
     * where it starts to fall.
     *
     * @param index the particle's index
     * @return the height (in metres)
     */
    float getEulerApexHeight(int index) {
        return eulerApexHeight[index];
    }

    /**
     * Return when the Euler particle was at its apex.
     *
     * @param index the particle's index
     * @return the time since the launch (in seconds)
     */
    double getEulerApexSeconds(int index) {
        return eulerApexSeconds[index];
    }

    /**
     * Test whether the Euler particle is past its apex, so its apex readout is final.
     *
     * @param index the particle's index
     * @return true if falling or landed
     */
    boolean isEulerPastApex(int index) {
        return eulerPastApex[index];
    }

    /**
     * Copy the graph's labels' rectangles into a list, when it is shown.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        if (graph != null && graphVisible) {
            graph.copyTextRects(storeResult);
        }
        return storeResult;
    }

    /**
     * Test whether a particle's line is its readout: it stops at the ground, and it and its
     * ghost have landed.
     *
     * @param index the particle's index
     * @return true if {@link #appendReadout} writes its line
     */
    boolean hasReadout(int index) {
        if (!enabled || paths.length == 0) {
            return false;
        }
        DemoParticle particle = particles.get(index);
        return particle.stopsAtGround() && particle.hasLanded() && paths[index].hasLanded()
                && !otherForces[index];
    }

    /**
     * Append a landed particle's readout line: apex height and time, range and flight time,
     * each "Euler | exact". Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param index the particle's index
     */
    void appendReadout(StringBuilder text, int index) {
        DemoParticle particle = particles.get(index);
        ExactPath path = paths[index];
        appendName(text, particle.getLabel()).append(", Euler | exact:  apex ");
        pair(text, eulerApexHeight[index], path.getApexHeight()).append(" m at ");
        pair(text, eulerApexSeconds[index], path.getApexSeconds()).append(" s   range ");
        pair(text, particle.getLandingX() - launchX[index], path.getLandingX() - launchX[index])
                .append(" m after a flight of ");
        pair(text, particle.getLandingSeconds(), path.getLandingSeconds()).append(" s\n");
    }

    /**
     * Append the live distance between a particle and its ghost to the particle's line.
     * Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param index the particle's index
     */
    void appendLiveError(StringBuilder text, int index) {
        if (!enabled || paths.length == 0 || otherForces[index]) {
            return;
        }
        text.append("   |P - P_exact| = ");
        if (stoppedAtContact[index]) {
            TextFormat.appendFixed(text, contactError[index], 3)
                    .append(" m at the first contact, where the ghost stopped");
            return;
        }
        TextFormat.appendFixed(text, paths[index].distanceTo(particles.get(index)
                .getParticle().position), 3).append(" m");
    }

    /**
     * Test whether a particle's ghost stopped at the particle's first contact.
     *
     * @param index the particle's index
     * @return true if stopped there
     */
    boolean isStoppedAtContact(int index) {
        return stoppedAtContact[index];
    }

    /** Mark the particles of a resolved contact: their ghosts stop after this step. */
    private void noteContact(Contact contact) {
        for (int i = 0; i < contactThisStep.length; ++i) {
            Body body = particles.get(i).getBody();
            if (body == contact.getBodyA() || body == contact.getBodyB()) {
                contactThisStep[i] = true;
            }
        }
    }

    /** Advance a ghost by h, in pieces that each leave a trail point. */
    private void advanceGhost(int index, double stepSeconds) {
        ExactPath path = paths[index];
        int pieces = (int) Math.ceil(stepSeconds / GHOST_POINT_SECONDS);
        double piece = stepSeconds / pieces;
        for (int n = 0; n < pieces && !path.hasLanded(); ++n) {
            path.advance(piece);
            addTrailPoint(index);
        }
    }

    /** Give a ghost's trail its path's position now, and count it. */
    private void addTrailPoint(int index) {
        views[index].getTrail().add(paths[index].copyPosition(point));
        ++trailPoints[index];
    }

    /**
     * Walk a ghost's trail to a recorded state's count of points: a step undone takes the
     * points it added off; a step redone adds the ghost's position there (one point, where
     * the step had added one per piece); a state of another launch starts the trail again at
     * the ghost.
     */
    private void walkTrail(int index, long points, int restarts) {
        Trail trail = views[index].getTrail();
        if (restarts != trailRestarts[index]) {
            views[index].restart(paths[index].copyPosition(point));
        } else if (points < trailPoints[index]) {
            for (long n = points; n < trailPoints[index] && trail.size() > 1; ++n) {
                trail.removeNewest();
            }
        } else if (points > trailPoints[index]) {
            trail.add(paths[index].copyPosition(point));
        }
        trailPoints[index] = points;
        trailRestarts[index] = restarts;
    }

    /** Fly a ghost on to its own landing after its particle landed. */
    private void finishGhost(int index) {
        ExactPath path = paths[index];
        double limit = path.getTimeSeconds() + MAX_FINISH_SECONDS;
        while (!path.hasLanded() && path.getTimeSeconds() < limit) {
            path.advance(GHOST_POINT_SECONDS);
            addTrailPoint(index);
        }
    }

    /** A particle's name: its label up to the force law after two spaces, if any. */
    private static StringBuilder appendName(StringBuilder text, String label) {
        int end = label.indexOf("  ");
        return text.append(label, 0, end < 0 ? label.length() : end);
    }

    private static boolean sameRect(ScreenRect a, ScreenRect b) {
        return a.getX() == b.getX() && a.getY() == b.getY() && a.getWidth() == b.getWidth()
                && a.getHeight() == b.getHeight();
    }

    private static StringBuilder pair(StringBuilder text, double euler, double exact) {
        TextFormat.appendFixed(text, euler, 2).append(" | ");
        return TextFormat.appendFixed(text, exact, 2);
    }
}

package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.WhatIfPart;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.CollisionSounds;
import particlelab.view.HudFont;
import particlelab.view.LiveGraph;
import particlelab.view.ScreenRect;
import particlelab.view.SilentSoundPlayer;
import particlelab.view.SoundPlayer;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.Detection;
import particlelab.world.HopCycle;
import particlelab.world.ImpulseResponse;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.SurfaceRule;

/**
 * Demo 7, bounce: two balls of radius R dropped from rest onto the ground side by side, the
 * first collision response of the lecture. Builds upon gravitational pull (the fall is its
 * parabola) and adds one collision rule per lane to the demo's world: the ground
 * {@code y = 0}, resolved by an impulse along the normal, {@code v' = −e·v}, found by the
 * overlap test in the left lane and by the intersection (swept) test in the right one. Both
 * lanes have the same e, threshold and resting fix; the balls never meet.
 *
 * <p>What to watch for:
 * <ul>
 * <li>The restitution law: the ideal ball climbs to {@code h_n = e^{2n}·h0} after its n-th
 * impact, so each apex is e² times the one before, and comes to rest after
 * {@code T = t0(1+e)/(1−e)}, {@code t0 = √(2h0/g)} (a geometric series of flights). The HUD's
 * apex table gives each recorded apex from impact 1 and its ratio to the one before against
 * e²; the graph draws both balls' heights against time and the ideal ball dashed. With the
 * defaults (e = 0.9, no resting fix, Box2D's threshold) the first ratios read e² = 0.81 to
 * within the step's O(h) error, about 0.01 at h = 1/60 s, until the threshold stops the
 * ball.</li>
 * <li>The restitution threshold (none, Cyclone's 0.25 m/s, Box2D's and Jolt's 1 m/s): an impact
 * at or below it is perfectly inelastic. It is no sure cure. Without the resting fix the
 * swept ball's hops end on an orbit that repeats (the rest of an impact's step has no
 * gravity, {@link HopCycle}): hops of K whole steps at the fixed point
 * {@code w* = K·g·h/(1+e)}, or a cycle of several hops mixing K. After this demo's 4 m drop
 * with e = 0.8 it is K = 4 and w* = 0.363 m/s, so Cyclone's 0.25 m/s never stops it and
 * Box2D's 1 m/s does; with e = 0.9 it is a cycle of 64 hops, K 4 to 9, impacts 0.300 to
 * 0.815 m/s. A threshold stops the ball once one impact comes at or below it; while none
 * does, the HUD names the orbit, read from the latest impacts.</li>
 * <li>The resting fix (Cyclone's): the rebound leaves out the velocity gravity added during
 * the step, {@code v' = e·(v − g·h)}, so a ball lying on the ground stays exactly still and
 * no hop can repeat: the only cure that always works. The price is {@code e·g·h} off every
 * rebound (the HUD puts it beside the last impact's speeds), so every apex ratio reads below
 * e² (press F). With the fix off the ball hops on its orbit for ever unless the threshold
 * reaches its slowest impact.</li>
 * <li>Overlap test against intersection (swept) test, lane beside lane: the overlap test finds
 * the ball inside the ground at the step's end and pushes it out, the swept test finds the
 * moment of impact on the step's straight segment. The HUD compares the lanes' apexes, rest
 * times and energies; with e = 1 the overlap lane's apexes sit a constant 0.1045 m below the
 * drop (every bounce repeats the first: the push-out loses the same height each time) and the
 * swept lane's stay at it.</li>
 * <li>The impact sound, as loud as the approach speed (silent without an audio device; the
 * HUD's sound line shows what would play).</li>
 * </ul>
 */
public final class BounceDemo extends DemoState {

    /** The ball's radius R (in metres). */
    public static final float RADIUS = 0.25f;
    /** The ball's lowest point starts this high above the ground, h0 (in metres). */
    public static final float DROP_HEIGHT = 4f;
    /** The ball's mass (in kilograms). */
    public static final float MASS_KG = 1f;
    /**
     * The restitution e at the start: 0.9, whose many fast bounces keep the step's O(h) error
     * of the apex ratios near 0.01 (it grows as 2·g·h over the rebound speed).
     */
    public static final float START_E = 0.9f;
    /** What the Up and Down keys (and the panel's keys) add to e or take from it. */
    static final float E_KEY_STEP = 0.1f;
    /** Decimals of e on the panel and the HUD: any e from 0 to 1 is taken as given. */
    private static final int E_DIGITS = 2;
    /** The threshold presets (in m/s): none, Cyclone's, Box2D's and Jolt's. */
    static final float[] THRESHOLDS = {0f, ImpulseResponse.CYCLONE_THRESHOLD,
        ImpulseResponse.BOX2D_THRESHOLD};
    /** The presets' names, in the order of {@link #THRESHOLDS}. */
    static final String[] THRESHOLD_NAMES = {"none", "Cyclone", "Box2D/Jolt"};
    /** The presets' command-line names, in the order of {@link #THRESHOLDS}. */
    static final String[] THRESHOLD_KEYS = {"none", "cyclone", "box2d"};
    /**
     * The threshold preset at the start: Box2D's 1 m/s, above every hop's fixed point of the
     * 4 m drop with e = 0.9 the ball meets, so it stops the ball after the law has shown.
     */
    static final int START_THRESHOLD = 2;
    /** The index of the overlap test's lane, in the lane arrays and the graph's series. */
    static final int OVERLAP_LANE = 0;
    /** The index of the swept test's lane. */
    static final int SWEPT_LANE = 1;
    /** The lanes' tests, in lane order. */
    private static final Detection[] LANE_TESTS = {Detection.OVERLAP, Detection.SWEPT};
    /** The lanes' labels, beside the balls and at the head of their HUD lines. */
    private static final String[] LANE_NAMES = {"overlap test", "swept test"};
    /** The lanes' names on the HUD's line that compares them. */
    private static final String[] LANE_SHORT_NAMES = {"overlap", "swept"};
    /**
     * Where the lanes stand (x, in metres): left of the scene's middle, since the graph takes
     * the scene's top right corner.
     */
    private static final float[] LANE_X = {-3.5f, -1.5f};
    private static final ColorRGBA[] LANE_COLORS = {new ColorRGBA(0.3f, 0.75f, 1f, 1f),
        ColorRGBA.Orange};
    /** The apex table's latest rows on the HUD. */
    private static final int APEX_ROWS_SHOWN = 4;
    /** Digits of the apex ratios: the step's O(h) error is about 0.01 at h = 1/60 s. */
    private static final int RATIO_DIGITS = 2;
    /** The graph's size at HUD scale 1 (pixels): the live graph's, as for the free flights. */
    private static final float GRAPH_WIDTH = 560f;
    private static final float GRAPH_HEIGHT = 220f;

    /** The ground's response, the same for both lanes (it keeps no state between contacts). */
    private final ImpulseResponse response = new ImpulseResponse(START_E,
            THRESHOLDS[START_THRESHOLD], false);
    private final Body[] balls = new Body[LANE_TESTS.length];
    private final BounceRecorder[] recorders = new BounceRecorder[LANE_TESTS.length];
    /** The lane whose apex table and last impact the HUD shows. */
    private Detection detection = Detection.SWEPT;
    private IdealBounce ideal = new IdealBounce(DROP_HEIGHT, START_E, Gravity.STANDARD_G);
    private CollisionSounds sounds =
            new CollisionSounds(new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE));
    /** The height graph (null without a window). */
    private LiveGraph graph;
    /** Simulated time since the drop, the graph's time axis (in seconds). */
    private float graphSeconds;
    private final float[] graphHeights = new float[LANE_TESTS.length];
    private final float[] graphSpeeds = new float[LANE_TESTS.length];
    private final float[] idealHeights = new float[LANE_TESTS.length];
    /** What-if forks (Insert, Delete, J): as recorded, e = 0.6, h = 1/30 s; lanes 0.4 m apart. */
    private final WhatIfPart whatIf = addPart(new WhatIfPart(BounceDemo::new,
            new String[] {null, "e", "h"}, new float[] {0f, 0.6f, 1f / 30f}, 0.4f));
    private final float[] idealSpeeds = new float[LANE_TESTS.length];
    /** The graph rectangle and HUD scale the graph was last laid out for. */
    private final ScreenRect graphRect = new ScreenRect();
    private float graphScale = Float.NaN;

    /** Create the demo. */
    public BounceDemo() {
        super("Bounce");
        // The slide is about energy: presenting shows the ledger's bars.
        getEnergyPart().showOnSlide();
    }

    /**
     * Access the what-if forks (Insert, Delete, J).
     *
     * @return the live part (not null)
     */
    public WhatIfPart getWhatIf() {
        return whatIf;
    }

    @Override
    protected void createScene() {
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Vector3f start = new Vector3f();
        for (int lane = 0; lane < LANE_TESTS.length; ++lane) {
            start.set(LANE_X[lane], DROP_HEIGHT + RADIUS, 0f);
            DemoParticle demoBall = addParticle(LANE_NAMES[lane], LANE_COLORS[lane], start,
                    Vector3f.ZERO, MASS_KG, gravity);
            Body ball = demoBall.getBody();
            ball.setRadius(RADIUS);
            balls[lane] = ball;
            // Each lane's ground sees its own ball only: the lanes share the world and the
            // clock, and neither ball knows of the other.
            getWorld().addRule(SurfaceRule.ground(response, LANE_TESTS[lane]).limitTo(ball));
            recorders[lane] = new BounceRecorder(ball);
            getWorld().addContactListener(recorders[lane]);
            getWorld().addStepListener(recorders[lane]);
            addStateRecord(recorders[lane]);
        }
        addStateRecord(graphState());
        // The balls hit the ground at 6 m/s and more: their arrows would cross the ground's
        // labels and the footer (the HUD gives V; V shows the arrows).
        hideArrowsAtStart();
        setView(-6f, 6f, DROP_HEIGHT + 2f * RADIUS + 0.5f, 0.5f, 2, RADIUS);
    }

    /** The bounces' sounds, in a window (silent without one). */
    @Override
    protected void buildViews(Application app) {
        sounds = new CollisionSounds(SoundPlayer.forApplication(app));
    }

    @Override
    protected void declareParameters() {
        // Each parameter is one value, put straight into the object that uses it (the shared
        // ground response, the ideal ball, the table's lane); a change drops the balls again,
        // as the keys do. Every other parameter keeps its value: none is written back.
        declareParameter(new DemoParameter("e", "restitution", "", 0f, 1f,
                E_KEY_STEP, START_E, E_DIGITS, DemoParameter.Applies.LIVE, value -> {
                    if (value != response.getRestitution()) {
                        response.setRestitution(value);
                        ideal = new IdealBounce(DROP_HEIGHT, value, Gravity.STANDARD_G);
                        refreshEquations();
                        restart();
                    }
                }));
        // The threshold, the resting fix and the lane in the apex table, as P, F and O do.
        declareParameter(DemoParameter.choice("threshold", "threshold speed", THRESHOLD_KEYS,
                START_THRESHOLD, DemoParameter.Applies.LIVE, value -> {
                    float speed = THRESHOLDS[Math.round(value)];
                    if (speed != response.getThresholdSpeed()) {
                        response.setThresholdSpeed(speed);
                        restart();
                    }
                }));
        declareParameter(DemoParameter.choice("fix", "resting fix", new String[] {"off", "on"},
                response.isRestingFix() ? 1 : 0, DemoParameter.Applies.LIVE, value -> {
                    if ((Math.round(value) == 1) != response.isRestingFix()) {
                        response.setRestingFix(Math.round(value) == 1);
                        restart();
                    }
                }));
        // Both lanes always run; the choice is the lane whose apex table the HUD shows.
        declareParameter(DemoParameter.choice("detection", "table lane",
                new String[] {"swept", "overlap"}, detection == Detection.SWEPT ? 0 : 1,
                DemoParameter.Applies.LIVE, value -> {
                    Detection wanted = Math.round(value) == 0 ? Detection.SWEPT
                            : Detection.OVERLAP;
                    if (wanted != detection) {
                        detection = wanted;
                        restart();
                    }
                }));
    }

    @Override
    protected void declareKeys() {
        bindKey(KeyInput.KEY_UP, "Up", "restitution e + 0.1 (up to 1), drop again",
                () -> changeE(1));
        bindKey(KeyInput.KEY_DOWN, "Down", "restitution e - 0.1 (down to 0), drop again",
                () -> changeE(-1));
        StringBuilder presets = new StringBuilder("threshold preset:");
        for (int i = 0; i < THRESHOLDS.length; ++i) {
            presets.append(i == 0 ? " " : " -> ").append(THRESHOLD_NAMES[i]);
            if (THRESHOLDS[i] > 0f) {
                presets.append(' ');
                TextFormat.appendFixed(presets, THRESHOLDS[i], 2).append(" m/s");
            }
        }
        bindKey(KeyInput.KEY_P, "P", presets.toString(), this::nextThreshold);
        bindKey(KeyInput.KEY_F, "F", "resting fix (Cyclone's) on / off, drop again",
                this::toggleRestingFix);
        bindKey(KeyInput.KEY_O, "O", "apex table: swept lane <-> overlap lane (both always run)",
                this::toggleDetection);
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("fall: V += h g, P += h V;   impact: v_n' = -e v_n (impulse j = -(1+e) m v_n),"
                + " R = ");
        TextFormat.appendFixed(text, RADIUS, 2).append(" m,  m = ");
        TextFormat.appendFixed(text, MASS_KG, 0).append(" kg\n");
    }

    @Override
    protected void afterStep(float stepSeconds) {
        graphSeconds += stepSeconds;
        if (graph == null) {
            return;
        }
        sampleGraph();
        graph.record(graphSeconds, graphHeights, graphSpeeds, idealHeights, idealSpeeds);
    }

    @Override
    protected void afterFrame() {
        sounds.playFrame(getWorld());
        if (graph == null) {
            return;
        }
        graph.setVisible(!getWindow().getHud().isHelpVisible());
        ScreenRect slot = getWindow().getHud().getLayout().getGraph();
        if (!sameRect(slot, graphRect)
                || getWindow().getHud().getLayout().getScale() != graphScale) {
            graphRect.set(slot);
            graphScale = getWindow().getHud().getLayout().getScale();
            graph.layOut(slot, getWindow().getHud().getLayout().getSceneLabelSize());
        }
        graph.refresh();
    }

    @Override
    protected void onRestart() {
        for (int lane = 0; lane < recorders.length; ++lane) {
            recorders[lane].clear();
        }
        graphSeconds = 0f;
        if (graph != null) {
            graph.clear();
        }
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        float e = getRestitution();
        float g = Gravity.STANDARD_G;
        text.append("e = ");
        appendRestitution(text, e).append(", e^2 = ");
        TextFormat.appendFixed(text, e * e, RATIO_DIGITS).append("   threshold ");
        TextFormat.appendFixed(text, response.getThresholdSpeed(), 2).append(" m/s (")
                .append(THRESHOLD_NAMES[thresholdPreset()])
                .append(")   time to rest: T = t0 (1+e)/(1-e) = ");
        if (getRestitution() == 1f) {
            text.append("never (e = 1)\n");
        } else {
            TextFormat.appendFixed(text, ideal.getRestSeconds(), 3).append(" s\n");
        }
        // The law first: on a small window the last lines are the ones hidden.
        appendApexTable(text);
        appendFixCost(text, e, g);
        text.append("apex, energy:");
        for (int lane = 0; lane < balls.length; ++lane) {
            text.append(lane == 0 ? " " : "   ");
            appendLane(text, lane, e);
        }
        text.append('\n');
        if (isOnHop(SWEPT_LANE, e)) {
            appendHopCycle(text, SWEPT_LANE, e);
        }
        if (getRestitution() == 1f) {
            appendDrift(text);
        }
        sounds.getPlayer().getLog().appendLatest(text).append('\n');
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        graph = new LiveGraph(app.getAssetManager(), HudFont.load(app.getAssetManager()),
                LANE_COLORS);
        getWindow().getHud().getLayout().setGraphSize(GRAPH_WIDTH, GRAPH_HEIGHT);
        getDemoHud().layOut(app.getCamera().getWidth(), app.getCamera().getHeight());
        // The graph is a GUI overlay of the demo: it comes and goes with the HUD's node.
        getWindow().getHud().getNode().attachChild(graph.getNode());
    }

    /**
     * Return the restitution now.
     *
     * @return e (0 to 1)
     */
    public float getRestitution() {
        return response.getRestitution();
    }

    /**
     * Return the threshold speed the lanes' ground applies now.
     *
     * @return v_t (in m/s, &ge;0)
     */
    public float getThresholdSpeed() {
        return response.getThresholdSpeed();
    }

    /**
     * Test whether the lanes' ground applies the resting fix now.
     *
     * @return true if it does
     */
    public boolean isRestingFix() {
        return response.isRestingFix();
    }

    /**
     * Return when the ball of the lane in the apex table came to rest, as its HUD line says.
     *
     * @return the time (in seconds of world time), NaN while it bounces
     */
    public double getRestSeconds() {
        return getRecorder().getRestSeconds();
    }

    /**
     * Access the measurements of one lane's ball.
     *
     * @param test the lane's detection test (not null)
     * @return the live recorder (not null after the scene was created)
     */
    BounceRecorder getRecorder(Detection test) {
        getWorld();
        return recorders[laneOf(test)];
    }

    /**
     * Access the measurements of the lane in the apex table.
     *
     * @return the live recorder (not null after the scene was created)
     */
    BounceRecorder getRecorder() {
        return getRecorder(detection);
    }

    /**
     * Access one lane's ball.
     *
     * @param test the lane's detection test (not null)
     * @return the live body (not null after the scene was created)
     */
    Body getBall(Detection test) {
        getWorld();
        return balls[laneOf(test)];
    }

    /**
     * Access the height graph, for tests.
     *
     * @return the live graph (null without a window)
     */
    LiveGraph getGraph() {
        return graph;
    }

    /**
     * Return the lane in the apex table: both lanes run, this one's table is shown.
     *
     * @return its detection (not null)
     */
    public Detection getDetection() {
        return detection;
    }

    /**
     * Set e, the threshold preset, the resting fix and the lane in the apex table, then drop
     * both balls again (what the keys do, for tests and scripts): through the demo's
     * parameters, so the panel, {@code --set} and the keys change the same values.
     *
     * @param restitution e (from 0 to 1)
     * @param preset index into the threshold presets (0 to 2)
     * @param restingFix true for the resting fix
     * @param newDetection the lane in the apex table (not null)
     */
    public void configure(float restitution, int preset, boolean restingFix,
            Detection newDetection) {
        if (!(restitution >= 0f && restitution <= 1f) || preset < 0
                || preset >= THRESHOLDS.length || newDetection == null) {
            throw new IllegalArgumentException("e must be 0 to 1 and preset 0 to "
                    + (THRESHOLDS.length - 1) + ", but were " + restitution + ", " + preset
                    + ", " + newDetection);
        }
        getParameters().set("e", restitution);
        getParameters().set("threshold", preset);
        getParameters().set("fix", restingFix ? 1 : 0);
        getParameters().set("detection", newDetection == Detection.SWEPT ? 0 : 1);
        restart();
    }

    /**
     * The resting fix by name and what it costs per impact: e·g·h off the rebound, beside the
     * table lane's last impact speed and rebound, as the world resolved them.
     */
    private void appendFixCost(StringBuilder text, float e, float g) {
        BounceRecorder table = getRecorder();
        float h = table.getImpactStepSeconds() > 0f ? table.getImpactStepSeconds()
                : getClock().getStepSeconds();
        float cost = e * g * h;
        if (response.isRestingFix()) {
            text.append("resting fix on: rebound e v - e g h, e g h = ");
            TextFormat.appendFixed(text, cost, 3).append(" m/s");
        } else {
            text.append("resting fix off: rebound e v (on: less e g h = ");
            TextFormat.appendFixed(text, cost, 3).append(" m/s)");
        }
        text.append("   last impact ");
        if (table.countImpacts() == 0) {
            text.append("-\n");
            return;
        }
        TextFormat.appendFixed(text, table.getLastImpactSpeed(), 3).append(", rebound ");
        TextFormat.appendFixed(text, table.getLastReboundSpeed(), 3).append(" m/s\n");
    }

    /** One lane's part of the lanes' line: the latest apex, the energy, the rest time. */
    private void appendLane(StringBuilder text, int lane, float e) {
        BounceRecorder recorder = recorders[lane];
        Body ball = balls[lane];
        text.append(LANE_SHORT_NAMES[lane]).append(' ');
        if (recorder.countApexes() == 0) {
            text.append("-");
        } else {
            TextFormat.appendFixed(text, recorder.getApex(recorder.countApexes() - 1), 3)
                    .append(" m");
        }
        Vector3f v = ball.getVelocity();
        float energy = 0.5f * MASS_KG * v.lengthSquared()
                + MASS_KG * Gravity.STANDARD_G * (ball.getPosition().y - RADIUS);
        text.append(", ");
        TextFormat.appendFixed(text, energy, 3).append(" J, ");
        if (recorder.isResting()) {
            text.append("at rest at ");
            TextFormat.appendFixed(text, recorder.getRestSeconds(), 3).append(" s");
        } else if (getRestitution() == 1f) {
            text.append("never at rest (e = 1)");
        } else if (isOnHop(lane, e)) {
            text.append("never at rest");
        } else {
            text.append("still bouncing");
        }
    }

    /**
     * The apex table of the lane chosen, one line: each apex h_n from impact 1 (the latest
     * rows) and its ratio to the one before, h_n/h_(n-1) with h_0 the drop, to hold against
     * the e² of the line above, the law.
     */
    private void appendApexTable(StringBuilder text) {
        BounceRecorder table = getRecorder();
        text.append(laneName(detection)).append(", h_n (h_n/h_(n-1)):");
        int count = table.countApexes();
        if (count == 0) {
            text.append(" no apex yet\n");
            return;
        }
        for (int i = Math.max(0, count - APEX_ROWS_SHOWN); i < count; ++i) {
            float previous = i == 0 ? DROP_HEIGHT : table.getApex(i - 1);
            text.append("  ").append(i + 1).append(": ");
            TextFormat.appendFixed(text, table.getApex(i), 3).append(" (");
            TextFormat.appendFixed(text, table.getApex(i) / previous, RATIO_DIGITS).append(')');
        }
        text.append('\n');
    }

    /**
     * Test whether a lane's ball, without the resting fix, is on an orbit of hops that never
     * ends: its latest impacts repeat a K-step fixed point or a cycle of several K
     * ({@link HopCycle}), every impact of it above the threshold (or it would have stopped).
     * Only the swept test has such orbits.
     */
    private boolean isOnHop(int lane, float e) {
        BounceRecorder recorder = recorders[lane];
        return !response.isRestingFix() && e < 1f && LANE_TESTS[lane] == Detection.SWEPT
                && !recorder.isResting() && recorder.getLastStepSeconds() > 0f
                && recorder.getOrbitHops() > 0;
    }

    /**
     * The orbit a lane's ball on it ({@link #isOnHop}) hops on, from its latest impacts: a
     * K-step fixed point with its w*, or a cycle of n hops with its range of K and of impact
     * speeds, all above the threshold.
     */
    private void appendHopCycle(StringBuilder text, int lane, float e) {
        BounceRecorder recorder = recorders[lane];
        int hops = recorder.getOrbitHops();
        text.append(laneName(LANE_TESTS[lane])).append(" never at rest: ");
        if (hops == 1) {
            int stepsPerHop = recorder.getLastHopSteps();
            double fixedPoint = HopCycle.fixedPointSpeed(stepsPerHop, e, Gravity.STANDARD_G,
                    recorder.getLastStepSeconds());
            text.append("hops of K = ").append(stepsPerHop)
                    .append(" steps, fixed point w* = K g h/(1+e) = ");
            TextFormat.appendFixed(text, fixedPoint, 3).append(" m/s > threshold ");
        } else {
            text.append("a cycle of ").append(hops).append(" hops, K = ")
                    .append(recorder.getHopStepsBound(hops, false)).append(" to ")
                    .append(recorder.getHopStepsBound(hops, true)).append(" steps, impacts ");
            TextFormat.appendFixed(text, recorder.getHopImpactBound(hops, false), 3)
                    .append(" to ");
            TextFormat.appendFixed(text, recorder.getHopImpactBound(hops, true), 3)
                    .append(" m/s, all > threshold ");
        }
        TextFormat.appendFixed(text, response.getThresholdSpeed(), 2).append(" m/s\n");
    }

    private void appendDrift(StringBuilder text) {
        BounceRecorder overlap = recorders[OVERLAP_LANE];
        BounceRecorder swept = recorders[SWEPT_LANE];
        int n = Math.min(overlap.countApexes(), swept.countApexes());
        text.append("e = 1, apex - h0 after ").append(n).append(" bounces:");
        text.append("   overlap test ");
        appendSignedDrift(text, overlap, n);
        text.append("   swept test ");
        appendSignedDrift(text, swept, n);
        text.append('\n');
    }

    private static void appendSignedDrift(StringBuilder text, BounceRecorder from, int n) {
        // none yet, or the lane is so far ahead that its n-th apex has left its ring
        if (n == 0 || n - 1 < from.firstKeptApex()) {
            text.append("-");
            return;
        }
        float drift = from.getApex(n - 1) - DROP_HEIGHT;
        if (drift >= 0f) {
            text.append('+');
        }
        TextFormat.appendFixed(text, drift, 4).append(" m");
    }

    /** e with one decimal on the tenths the keys reach, else two (as the panel shows it). */
    private static StringBuilder appendRestitution(StringBuilder text, float e) {
        return TextFormat.appendFixed(text, e, Math.round(e * 10f) / 10f == e ? 1 : E_DIGITS);
    }

    private static String laneName(Detection test) {
        return test == Detection.SWEPT ? "swept lane" : "overlap lane";
    }

    private static int laneOf(Detection test) {
        return test == Detection.SWEPT ? SWEPT_LANE : OVERLAP_LANE;
    }

    private static boolean sameRect(ScreenRect a, ScreenRect b) {
        return a.getX() == b.getX() && a.getY() == b.getY() && a.getWidth() == b.getWidth()
                && a.getHeight() == b.getHeight();
    }

    /** The Up and Down keys: e ± 0.1, kept to hundredths (0.33 + 0.1 is 0.43) and 0 to 1. */
    private void changeE(int direction) {
        float hundredths = Math.round((getRestitution() + direction * E_KEY_STEP) * 100f);
        getParameters().set("e", Math.max(0f, Math.min(1f, hundredths / 100f)));
    }

    private void nextThreshold() {
        getParameters().set("threshold", (thresholdPreset() + 1) % THRESHOLDS.length);
    }

    private void toggleRestingFix() {
        getParameters().set("fix", response.isRestingFix() ? 0 : 1);
    }

    private void toggleDetection() {
        getParameters().set("detection", detection == Detection.SWEPT ? 1 : 0);
    }

    /** The threshold preset chosen: an index into {@link #THRESHOLDS}. */
    private int thresholdPreset() {
        return Math.round(getParameters().getValue("threshold"));
    }

    /** The slide: the impact law and the apex it predicts; the latest apex ratio. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        float e = getRestitution();
        appendRestitution(slide.formula().append("impact: v_n' = -e v_n,   e = "), e)
                .append(";   apex h_n = e^2n h0");
        StringBuilder readout = slide.readout();
        // the table's lane, the one the HUD's apex table shows
        BounceRecorder recorder = getRecorder();
        int count = recorder.countApexes();
        if (count == 0) {
            TextFormat.appendFixed(readout.append("apex ratio: no bounce yet   (e² = "), e * e, 3)
                    .append(')');
            return;
        }
        float before = count == 1 ? DROP_HEIGHT : recorder.getApex(count - 2);
        if (count == 1) {
            readout.append("apex 1 / h0 = ");
        } else {
            readout.append("apex ").append(count).append(" / apex ").append(count - 1)
                    .append(" = ");
        }
        TextFormat.appendFixed(readout, recorder.getApex(count - 1) / before, 3)
                .append("   (e² = ");
        TextFormat.appendFixed(readout, e * e, 3).append(')');
    }

    /** The graph's sample of the state now: each ball's height and speed, the ideal ball's. */
    private void sampleGraph() {
        for (int lane = 0; lane < balls.length; ++lane) {
            graphHeights[lane] = balls[lane].getPosition().y;
            graphSpeeds[lane] = balls[lane].getVelocity().length();
            // The ideal ball is drawn once, dashed, as the swept lane's exact curve.
            idealHeights[lane] = Float.NaN;
            idealSpeeds[lane] = Float.NaN;
        }
        idealHeights[SWEPT_LANE] = RADIUS + (float) ideal.height(graphSeconds);
        idealSpeeds[SWEPT_LANE] = (float) ideal.speed(graphSeconds);
    }

    /**
     * The graph's clock, for the ring: after a step back the graph ends at the step shown
     * (its later samples are not drawn), and a step from there goes on at that time.
     */
    private StateRecord graphState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putFloat(graphSeconds);
            }

            @Override
            public void readState(StateSlab slab) {
                graphSeconds = slab.getFloat();
                if (graph != null) {
                    sampleGraph();
                    graph.showEnd(graph.getFlight(), graphSeconds, graphHeights, graphSpeeds,
                            idealHeights, idealSpeeds);
                }
            }
        };
    }
}

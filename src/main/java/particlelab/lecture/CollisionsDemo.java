package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.font.BitmapFont;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import java.util.List;
import particlelab.collision.Plane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.Draggable;
import particlelab.demo.Presentation;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.CalloutLayout;
import particlelab.view.HudFont;
import particlelab.view.HudLayout;
import particlelab.view.ImpulseArrows;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.view.TextMeasure;
import particlelab.view.Trail;
import particlelab.view.WallView;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.ContactResponse;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SphereRule;
import particlelab.world.StepListener;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * Demo 8, collisions: spheres against spheres in free flight (no gravity), resolved by the
 * impulse {@code j = −(1+e)·v_rel·n / (1/m1 + 1/m2)} along the contact normal. Builds upon
 * bounce (the same impulse, now with a second finite mass; the swept test finds the moment of
 * impact).
 * Four presets (P):
 * <ol>
 * <li><b>head-on</b>: normal velocities 4 and −2 m/s; masses m1, m2 and e from the keys;</li>
 * <li><b>glancing</b>: ball 2 at rest, hit off-centre (impact parameter r);</li>
 * <li><b>Newton's cradle</b>: one ball into a row of four touching ones, found by the overlap
 * test and resolved worst first (the fastest closing contact, then the next);</li>
 * <li><b>paddle</b>: a kinematic paddle moved by script, {@code P += speed·h·U(t)} with a
 * direction U(t) that turns in time, unaffected by any force or impact, hits three balls at
 * rest.</li>
 * </ol>
 *
 * <p>What to watch for: the total momentum is the same before and after every impact (to
 * float round-off); the kinetic energy drops by {@code ½·μ·(1−e²)·v_n²},
 * {@code μ = m1·m2/(m1+m2)}, nothing at e = 1; equal masses with e = 1 leave a glancing impact
 * at right angles. The cradle passes the momentum down the row. The paddle (infinite mass)
 * sends a ball off at {@code (1+e)·u − e·v} along the normal, u its own speed: the balls'
 * energy grows, since the script does work no force accounts for (kinematics, not dynamics).
 * At every contact between two bodies the arrows show the impulses the world applied, J on
 * one and −J on the other (Newton's third law), held half a second; the paddle's −J is grey,
 * not applied (infinite mass), so the balls' momentum changes by the ΣJ the HUD shows.
 */
public final class CollisionsDemo extends DemoState {

    /** The presets' command-line names, in the order of {@link Preset}. */
    public static final String[] PRESET_NAMES = {"head-on", "glancing", "cradle", "paddle"};

    /** The presets, in the order the P key cycles them. */
    public enum Preset {
        /** Two balls meeting along the line of centres. */
        HEAD_ON("head-on"),
        /** Ball 2 at rest, hit off-centre. */
        GLANCING("glancing"),
        /** One ball into a row of four. */
        CRADLE("Newton's cradle"),
        /** A scripted kinematic paddle into three balls. */
        PADDLE("kinematic paddle");

        private final String label;

        Preset(String label) {
            this.label = label;
        }

        /** @return the name on the HUD (not null) */
        public String getLabel() {
            return label;
        }
    }

    /** Every ball's radius r (in metres). */
    public static final float RADIUS = 0.3f;
    /** The masses the Left and Right keys cycle through (in kilograms). */
    static final float[] MASSES = {1f, 2f, 3f, 0.5f};
    /** The paddle's speed (in m/s). */
    public static final float PADDLE_SPEED = 3f;
    /** How far the paddle's direction swings either side of +x (in radians). */
    public static final float PADDLE_SWING = 0.4f;
    /** How fast it swings (in radians per second). */
    public static final float PADDLE_RATE = 1.5f;
    /** Where the paddle's run ends (in metres): the script stops it there. */
    public static final float PADDLE_END_X = 10.5f;
    /** The left wall's plane (in metres): the box's inside starts there. */
    public static final float X_MIN = -1f;
    /** The right wall's plane (in metres). */
    public static final float X_MAX = 13f;
    /** The top wall's plane (in metres); the ground is y = 0. */
    public static final float Y_MAX = 6f;
    /**
     * An impulse arrow's length per N·s (in m/(N·s)): the paddle's 6 N·s at e = 1 on 1 kg
     * is drawn 1.2 m long,
     * past the ball (its diameter 0.6 m from the contact).
     */
    public static final float METRES_PER_NEWTON_SECOND = 0.2f;
    private static final float PADDLE_START_Y = 2f;
    private static final int BALLS = 5;
    private static final float LANE_Y = 3f;
    /**
     * The rack for the bodies a preset leaves out, held and hidden: on the ground right of
     * the box, out of the framed view (m).
     */
    private static final float RACK_X = X_MAX + 3f;
    /** The distance between two bodies on the rack (m). */
    private static final float RACK_SPACING = 1.5f;
    /**
     * The room framed beyond each side wall (m): more than a ball's diameter past the wall's
     * 0.05 m, so the wall never lands on the window's edge (the panel open at 1280x720).
     */
    private static final float WALL_ROOM = 1f;
    private static final float VIEW_Y_MAX = Y_MAX + 0.6f;
    /** How far in front of the plane the arrows are drawn (in ball radii). */
    private static final float ARROW_LIFT = 1.2f;
    /** The impulse labels' text size, as a share of the scene labels' (the balls' names). */
    private static final float IMPULSE_LABEL_SHARE = 1f;
    /** The lowest an impulse arrow's tip goes (in metres): its shaft's width above ground. */
    private static final float ARROW_FLOOR = 0.25f * RADIUS;
    /** The room between an arrow's tip and its label (as a fraction of the text size). */
    private static final float CALLOUT_GAP = 0.3f;
    /**
     * The most obstacles a frame's callouts meet: the HUD's seven texts, each body's sphere
     * and name (five balls and the paddle), and every arrow's label.
     */
    private static final int CALLOUT_OBSTACLES = 7 + 2 * 6 + 2 * ContactImpulses.CAPACITY;

    private final ImpulseResponse response = new ImpulseResponse(1f, 0f, false);
    /** Decimals of e on the panel, the HUD and the slide: any e from 0 to 1 is taken. */
    private static final int E_DIGITS = 2;
    /**
     * The balls' response: the impulse, then a note of balls 1 and 2's velocities the moment
     * their impact is resolved, before any wall can change them.
     */
    private final ContactResponse ballResponse = new ContactResponse() {
        @Override
        public void resolve(Contact contact, float stepSeconds) {
            response.resolve(contact, stepSeconds);
            recordExit(contact);
        }

        @Override
        public String describe() {
            return response.describe();
        }
    };
    private final SphereRule sweptRule = new SphereRule(ballResponse, Detection.SWEPT);
    private final SphereRule overlapRule = new SphereRule(ballResponse, Detection.OVERLAP);
    private final DemoParticle[] balls = new DemoParticle[BALLS];
    /** Scratch: a dragged ball's start and start velocity (m, m/s). */
    private final Vector3f dragged = new Vector3f();
    private final Vector3f draggedVelocity = new Vector3f();
    private final Vector3f position = new Vector3f();
    private final Vector3f velocity = new Vector3f();
    private final Vector3f momentum = new Vector3f();
    private final Vector3f momentumBefore = new Vector3f();
    private final Vector3f impactMomentumBefore = new Vector3f();
    private final Vector3f impactMomentumAfter = new Vector3f();
    /** Ball 1's velocity just after its first impact with ball 2 (m/s). */
    private final Vector3f exitVelocity1 = new Vector3f();
    /** Ball 2's velocity just after that impact (m/s). */
    private final Vector3f exitVelocity2 = new Vector3f();
    private boolean exitRecorded;
    /** The latest contacts between two bodies, for the impulse arrows (in the state). */
    private final ContactImpulses impulses = new ContactImpulses();
    /** The impulse the paddle gave the balls since the start, ΣJ (in N·s = kg·m/s). */
    private final Vector3f paddleImpulse = new Vector3f();
    /** The impulse the paddle gave a ball at its latest contact (in N·s). */
    private final Vector3f lastPaddleImpulse = new Vector3f();
    /** The impulse the walls gave the balls since the start (in N·s). */
    private final Vector3f wallImpulse = new Vector3f();
    /** Scratch for the arrows: a contact's point (m) and one side's impulse (N·s). */
    private final Vector3f arrowStart = new Vector3f();
    private final Vector3f arrowImpulse = new Vector3f();
    /** Scratch: an arrow's label. */
    private final StringBuilder arrowLabel = new StringBuilder(48);
    /** Where the impulse labels go, clear of each other, the spheres and the texts. */
    private final CalloutLayout callouts = new CalloutLayout(CALLOUT_OBSTACLES);
    /** Scratch: the scene above the ground band (in pixels). */
    private final ScreenRect calloutArea = new ScreenRect();
    /** The trails' points on the screen, which the labels keep off (pixels; grown once). */
    private float[] trailScreenX = new float[0];
    private float[] trailScreenY = new float[0];
    /** Scratch: one trail point (m). */
    private final Vector3f trailPoint = new Vector3f();
    /** Where each arrow's label was put this frame (in pixels; empty: hidden). */
    private final ScreenRect[] impulseLabelRects = new ScreenRect[2 * ContactImpulses.CAPACITY];
    /** The lowest tip of the arrows drawn this frame (in metres; +∞: none drawn). */
    private float lowestArrowTip = Float.POSITIVE_INFINITY;
    /** Measures the labels in pixels (null without a window). */
    private TextMeasure labelMeasure;
    /** Two arrows per kept contact, built with the window (null without one). */
    private ImpulseArrows arrows;
    /** The paddle's contacts since the start. */
    private int paddleContacts;
    /** The script's angle θ(t) of U(t) at the latest step (in radians). */
    private float paddleAngle;
    /** True once the script stopped the paddle at the end of its run. */
    private boolean paddleStopped;
    private DemoParticle paddle;
    private Preset preset = Preset.HEAD_ON;
    private int mass1 = 0;
    private int mass2 = 0;
    private SphereRule rule;
    private float energyBefore;
    private float stepLoss;
    private int stepContacts;
    private int impactSteps;
    private int impactContacts;
    private float impactEnergyBefore;
    private float impactEnergyAfter;
    private float impactPredictedLoss;
    private float impactNormalSpeed;
    private float impactReducedMass;

    /** Create the demo. */
    public CollisionsDemo() {
        super("Collisions");
        // The slide is about energy: presenting shows the ledger's bars.
        getEnergyPart().showOnSlide();
        for (int i = 0; i < impulseLabelRects.length; ++i) {
            impulseLabelRects[i] = new ScreenRect();
        }
    }

    @Override
    protected void createScene() {
        ParticleIntegrator freeFlight = new ParticleIntegrator();
        ColorRGBA[] colors = {ColorRGBA.Orange, new ColorRGBA(0.3f, 0.85f, 1f, 1f),
            new ColorRGBA(1f, 0.4f, 0.8f, 1f), new ColorRGBA(0.6f, 1f, 0.4f, 1f),
            new ColorRGBA(1f, 1f, 0.5f, 1f)};
        for (int i = 0; i < BALLS; ++i) {
            balls[i] = addParticle("ball " + (i + 1), colors[i], new Vector3f(-10f * i, 0f, 0f),
                    Vector3f.ZERO, 1f, freeFlight);
            balls[i].getBody().setRadius(RADIUS);
        }
        paddle = addParticle("paddle", ColorRGBA.White, Vector3f.ZERO, Vector3f.ZERO, 1f,
                freeFlight);
        paddle.getBody().setRadius(RADIUS);
        World world = getWorld();
        world.addStepListener(new StepListener() {
            @Override
            public void beforeStep(World stepping, float stepSeconds) {
                steerPaddle(stepping.getTimeSeconds());
                energyBefore = totals(momentumBefore);
                stepLoss = 0f;
                stepContacts = 0;
            }

            @Override
            public void afterStep(World stepping, float stepSeconds) {
                if (stepContacts > 0) {
                    ++impactSteps;
                    impactContacts = stepContacts;
                    impactEnergyBefore = energyBefore;
                    impactMomentumBefore.set(momentumBefore);
                    impactEnergyAfter = totals(impactMomentumAfter);
                    impactPredictedLoss = stepLoss;
                }
            }
        });
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World stepping) {
                recordContact(contact);
            }
        });
        // The box: four static walls with the same impulse, so no ball leaves the scene.
        Plane[] walls = {Plane.ground(), new Plane(Vector3f.UNIT_X, X_MIN),
            new Plane(new Vector3f(-1f, 0f, 0f), -X_MAX),
            new Plane(new Vector3f(0f, -1f, 0f), -Y_MAX)};
        for (Plane wall : walls) {
            world.addRule(new SurfaceRule("wall", wall, response, Detection.SWEPT));
        }
        // The box, room beside its walls, and room above the top wall for the balls' labels.
        setView(X_MIN - WALL_ROOM, X_MAX + WALL_ROOM, VIEW_Y_MAX, 1f, 2, RADIUS);
        arrange();
        addStateRecord(impactState());
        addStateRecord(impulses);
        addStateRecord(paddleState());
    }

    /** The box's three walls above the ground. */
    @Override
    protected void buildViews(Application app) {
        ColorRGBA grey = new ColorRGBA(0.6f, 0.6f, 0.65f, 1f);
        float t = 0.05f;
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "left", X_MIN - t, 0f, X_MIN, Y_MAX, grey));
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "right", X_MAX, 0f, X_MAX + t, Y_MAX, grey));
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "top", X_MIN - t, Y_MAX, X_MAX + t, Y_MAX + t, grey));
    }

    @Override
    protected void declareParameters() {
        // A new e starts the collision again, as the Up and Down keys do: one value, kept in
        // the response that uses it, any e from 0 to 1 (shown to hundredths).
        declareParameter(new DemoParameter("e", "restitution", "", 0f, 1f, 0.1f,
                response.getRestitution(), E_DIGITS, DemoParameter.Applies.LIVE, value -> {
                    if (value != response.getRestitution()) {
                        response.setRestitution(value);
                        restart();
                    }
                }));
        // The preset, as the P key steps through them.
        declareParameter(DemoParameter.choice("preset", "collision preset", PRESET_NAMES,
                preset.ordinal(), DemoParameter.Applies.LIVE, value -> {
                    if (Math.round(value) != preset.ordinal()) {
                        choose(Preset.values()[Math.round(value)]);
                    }
                }));
    }

    @Override
    protected void declareKeys() {
        bindKey(KeyInput.KEY_P, "P", "preset: head-on, glancing, cradle, paddle",
                () -> choose(Preset.values()[(preset.ordinal() + 1) % Preset.values().length]));
        bindKey(KeyInput.KEY_UP, "Up", "e + 0.1 (up to 1), restart",
                () -> setRestitutionTenths(Math.round(getRestitution() * 10f) + 1));
        bindKey(KeyInput.KEY_DOWN, "Down", "e - 0.1 (down to 0), restart",
                () -> setRestitutionTenths(Math.round(getRestitution() * 10f) - 1));
        StringBuilder masses = new StringBuilder();
        for (int i = 0; i < MASSES.length; ++i) {
            TextFormat.appendFixed(masses, MASSES[i], 1).append(i + 1 < MASSES.length ? " -> "
                    : " kg");
        }
        bindKey(KeyInput.KEY_LEFT, "Left", "m1 of ball 1: " + masses,
                () -> setMasses((mass1 + 1) % MASSES.length, mass2));
        bindKey(KeyInput.KEY_RIGHT, "Right", "m2 of ball 2 and on: " + masses,
                () -> setMasses(mass1, (mass2 + 1) % MASSES.length));
    }

    @Override
    protected void declareDraggables() {
        // A collision of one's own: a ball's start and its start velocity (P, Up, Down and
        // the mass keys arrange the preset again).
        List<DemoParticle> all = List.of(balls);
        declareDraggable(new Draggable("a ball", Draggable.Grip.BODY, Draggable.Effect.LAUNCH,
                all, "its start", Draggable.PAUSED_NOTE, false,
                (ball, point) -> ball.setLaunch(dragged.set(
                        Math.max(X_MIN + RADIUS, Math.min(X_MAX - RADIUS, point.x)),
                        Math.max(RADIUS, Math.min(Y_MAX - RADIUS, point.y)), 0f),
                        ball.copyLaunchVelocity(draggedVelocity))));
        declareDraggable(new Draggable("a ball", Draggable.Grip.ARROW_TIP,
                Draggable.Effect.LAUNCH, all, "start velocity", Draggable.PAUSED_NOTE, false,
                (ball, velocity) -> ball.setLaunch(ball.copyLaunchPosition(dragged),
                        velocity)));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        if (preset == Preset.PADDLE) {
            // The paddle has 1/m = 0: the ball-ball impulse reduces to the paddle-ball rule.
            text.append("paddle-ball (1/m_paddle = 0):  v' = (1+e) u - e v along n,"
                    + "  J = m (v' - v);  balls P += h V, r = ");
        } else {
            text.append("j = -(1+e) v_rel.n / (1/m1 + 1/m2):  V1 += j n/m1,  V2 -= j n/m2;"
                    + "  free flight P += h V, r = ");
        }
        TextFormat.appendFixed(text, RADIUS, 1).append(" m\n");
    }

    @Override
    protected void onRestart() {
        impactSteps = 0;
        impactContacts = 0;
        exitRecorded = false;
        impulses.clear();
        paddleImpulse.zero();
        lastPaddleImpulse.zero();
        wallImpulse.zero();
        paddleContacts = 0;
        paddleStopped = false;
        paddleAngle = 0f;
        for (int i = 0; i < BALLS; ++i) {
            if (balls[i].isParked()) {
                balls[i].setHeld(true);
            }
        }
        if (paddle.isParked()) {
            paddle.setHeld(true);
        }
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        text.append("preset: ").append(preset.getLabel()).append("   e = ");
        TextFormat.appendFixed(text, getRestitution(), eDigits()).append("   m1 = ");
        TextFormat.appendFixed(text, MASSES[mass1], 1).append(" kg   m2 = ");
        TextFormat.appendFixed(text, MASSES[mass2], 1).append(" kg   ")
                .append(preset == Preset.CRADLE ? "overlap test, worst first"
                        : "swept test").append('\n');
        if (preset == Preset.PADDLE) {
            writePaddleLines(text);
        }
        if (impactSteps == 0) {
            text.append("no impact yet\n");
        } else if (preset != Preset.PADDLE) {
            text.append("latest impact step (").append(impactContacts)
                    .append(impactContacts == 1 ? " contact" : " contacts resolved worst first")
                    .append("):  momentum before ");
            TextFormat.appendVector(text, impactMomentumBefore, 3).append(" after ");
            TextFormat.appendVector(text, impactMomentumAfter, 3).append(" kg m/s\n");
        }
        if (impactSteps > 0) {
            text.append("kinetic energy before ");
            TextFormat.appendFixed(text, impactEnergyBefore, 3).append(" J, after ");
            TextFormat.appendFixed(text, impactEnergyAfter, 3).append(" J:  lost ");
            TextFormat.appendFixed(text, impactEnergyBefore - impactEnergyAfter, 3);
            if (preset == Preset.PADDLE) {
                text.append(" J (negative: the paddle's script added energy), now ");
                TextFormat.appendFixed(text, totals(momentum), 3).append(" J\n");
            } else {
                text.append(" J;  ½·μ·(1 − e²)·v_n² = ");
                TextFormat.appendFixed(text, impactPredictedLoss, 3).append(" J  (v_n = ");
                TextFormat.appendFixed(text, impactNormalSpeed, 3).append(" m/s, μ = ");
                TextFormat.appendFixed(text, impactReducedMass, 3).append(" kg)\n");
            }
        }
        if (preset == Preset.GLANCING && exitRecorded) {
            text.append("angle between the exit velocities just after the impact: ");
            TextFormat.appendFixed(text, exitAngleDegrees(), 1)
                    .append(" deg (90 for equal masses and e = 1)\n");
        }
    }

    /**
     * The paddle preset's lines: the script with its live U(t), kinematics against dynamics,
     * and the momentum the paddle gave and did not receive.
     */
    private void writePaddleLines(StringBuilder text) {
        text.append("kinematic paddle: moved by script, infinite mass, no force moves it:"
                + "  P += speed·h·U(t)\n  U(t) = (cos θ, sin θ, 0) = (");
        TextFormat.appendFixed(text, paddleStopped ? 0f : FastMath.cos(paddleAngle), 3)
                .append(", ");
        TextFormat.appendFixed(text, paddleStopped ? 0f : FastMath.sin(paddleAngle), 3)
                .append(", 0),  θ(t) = ");
        TextFormat.appendFixed(text, PADDLE_SWING, 1).append(" sin(");
        TextFormat.appendFixed(text, PADDLE_RATE, 1).append(" t) = ");
        TextFormat.appendFixed(text, paddleAngle, 3).append(" rad")
                .append(paddleStopped ? " (run over)\n" : "\n");
        text.append("dynamic balls: moved by impulses J;  ΣJ from the paddle ");
        TextFormat.appendVector(text, paddleImpulse, 3).append(", at its last contact ");
        TextFormat.appendVector(text, lastPaddleImpulse, 3).append(" kg m/s\n");
        text.append("the paddle's -J is not applied (infinite mass): the balls' momentum is not"
                + " conserved;  walls gave ");
        TextFormat.appendVector(text, wallImpulse, 3).append('\n');
    }

    /**
     * Choose a preset and start it.
     *
     * @param newPreset the preset (not null)
     */
    public void choose(Preset newPreset) {
        if (newPreset == null) {
            throw new IllegalArgumentException("preset must be one of the presets, not null");
        }
        preset = newPreset;
        // The panel and --set show the preset the key or a caller chose.
        getParameters().set("preset", preset.ordinal());
        arrange();
        restart();
        // The formula line is the preset's own.
        refreshEquations();
    }

    /**
     * Set e to a whole number of tenths and start again (what the keys do), through the
     * parameter, so the panel and {@code --set} change the same value.
     *
     * @param tenths e in tenths (clamped to 0..10)
     */
    public void setRestitutionTenths(int tenths) {
        getParameters().set("e", Math.max(0, Math.min(10, tenths)) / 10f);
        restart();
    }

    /**
     * Set the masses and start again.
     *
     * @param index1 m1's index into the mass list (0 to 3)
     * @param index2 m2's index (0 to 3)
     */
    public void setMasses(int index1, int index2) {
        if (index1 < 0 || index1 >= MASSES.length || index2 < 0 || index2 >= MASSES.length) {
            throw new IllegalArgumentException("mass indexes must be 0 to " + (MASSES.length - 1)
                    + ", but were " + index1 + ", " + index2);
        }
        mass1 = index1;
        mass2 = index2;
        choose(preset);
    }

    /** Decimals to show e with: one on the tenths the keys reach, else two (as the panel). */
    private int eDigits() {
        float e = getRestitution();
        return Math.round(e * 10f) / 10f == e ? 1 : E_DIGITS;
    }

    /** @return e (0 to 1), as the response between the balls applies it */
    public float getRestitution() {
        return response.getRestitution();
    }

    /** @return the preset whose bodies are in play (not null) */
    Preset getPreset() {
        return preset;
    }

    /**
     * Return the total momentum of the dynamic balls now.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in kg·m/s)
     */
    public Vector3f copyMomentum(Vector3f storeResult) {
        totals(storeResult);
        return storeResult;
    }

    /** @return the kinetic energy of the dynamic balls now (in joules) */
    public float kineticEnergy() {
        return totals(momentum);
    }

    /** @return the kinetic energy just before the latest impact step (in joules) */
    public float getImpactEnergyBefore() {
        return impactEnergyBefore;
    }

    /** @return the kinetic energy just after it (in joules) */
    public float getImpactEnergyAfter() {
        return impactEnergyAfter;
    }

    /** @return the loss {@code ½·μ·(1−e²)·v_n²} summed over its contacts (in joules) */
    public float getImpactPredictedLoss() {
        return impactPredictedLoss;
    }

    /** @return the count of steps with an impact since the start (&ge;0) */
    public int countImpactSteps() {
        return impactSteps;
    }

    /**
     * Return the angle between balls 1 and 2's velocities just after their first impact since
     * the start, as the impulse left them (later wall bounces do not change it).
     *
     * @return the angle (in degrees, 0 to 180; 0 before that impact or if a ball stopped)
     */
    public float exitAngleDegrees() {
        if (!exitRecorded) {
            return 0f;
        }
        Vector3f v1 = exitVelocity1;
        Vector3f v2 = exitVelocity2;
        float lengths = v1.length() * v2.length();
        if (lengths == 0f) {
            return 0f;
        }
        float cosine = Math.max(-1f, Math.min(1f, v1.dot(v2) / lengths));
        return FastMath.RAD_TO_DEG * (float) Math.acos(cosine);
    }

    /**
     * Return the script's angle at a time: {@code θ(t) = swing·sin(rate·t)}.
     *
     * @param timeSeconds the simulated time (in seconds)
     * @return θ (in radians, within ±{@link #PADDLE_SWING})
     */
    public static float scriptAngle(double timeSeconds) {
        return PADDLE_SWING * (float) Math.sin(PADDLE_RATE * timeSeconds);
    }

    /**
     * Access the latest contacts between two bodies, as the arrows draw them.
     *
     * @return the live record (not null, do not modify)
     */
    public ContactImpulses getImpulses() {
        return impulses;
    }

    /**
     * Copy where each impulse arrow's label was put at the last frame, for tests of the
     * layout: those shown, in pixels.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyImpulseLabelRects(List<ScreenRect> storeResult) {
        for (int i = 0; i < impulseLabelRects.length; ++i) {
            if (!impulseLabelRects[i].isEmpty()) {
                storeResult.add(new ScreenRect().set(impulseLabelRects[i]));
            }
        }
        return storeResult;
    }

    /**
     * Return the lowest tip of the impulse arrows drawn at the last frame.
     *
     * @return its height (in metres; +∞ when none was drawn)
     */
    public float getLowestArrowTip() {
        return lowestArrowTip;
    }

    /**
     * Copy the impulse the paddle gave the balls since the start, ΣJ: the change of their
     * momentum it caused (the paddle, kinematic, took none of the −J back).
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in N·s = kg·m/s)
     */
    public Vector3f copyPaddleImpulse(Vector3f storeResult) {
        return storeResult.set(paddleImpulse);
    }

    /** @return the length of the impulse the paddle gave the balls, |ΣJ| (in N·s) */
    public float paddleImpulseLength() {
        return paddleImpulse.length();
    }

    /**
     * Copy the impulse the paddle gave a ball at its latest contact.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in N·s, zero before the first)
     */
    public Vector3f copyLastPaddleImpulse(Vector3f storeResult) {
        return storeResult.set(lastPaddleImpulse);
    }

    /**
     * Copy the impulse the static walls gave the balls since the start.
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in N·s)
     */
    public Vector3f copyWallImpulse(Vector3f storeResult) {
        return storeResult.set(wallImpulse);
    }

    /** @return how many contacts the paddle had since the start (&ge;0) */
    public int countPaddleContacts() {
        return paddleContacts;
    }

    /** @return the demo's paddle (the kinematic body of the paddle preset; not null) */
    public DemoParticle getPaddle() {
        getWorld();
        return paddle;
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        BitmapFont font = HudFont.load(app.getAssetManager());
        labelMeasure = TextMeasure.of(font);
        arrows = new ImpulseArrows(app.getAssetManager(), font, 2 * ContactImpulses.CAPACITY,
                METRES_PER_NEWTON_SECOND, 0.25f * RADIUS);
        getSceneNode().attachChild(arrows.getNode());
        showImpulses();
    }

    /**
     * Run a frame as every demo does, then draw the impulse arrows: after the views and any
     * new layout the HUD asked for, so their labels keep clear of the balls' names where
     * this frame put them.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    @Override
    public void update(float tpf) {
        hideIdleBodies();
        super.update(tpf);
        showImpulses();
    }


    /** Just after a ball contact's resolution: balls 1 and 2's exit velocities, once. */
    private void recordExit(Contact contact) {
        Body a = contact.getBodyA();
        Body b = contact.getBodyB();
        Body one = balls[0].getBody();
        Body two = balls[1].getBody();
        boolean pair = a == one && b == two || a == two && b == one;
        Contact.Resolution resolution = contact.getResolution();
        if (exitRecorded || !pair || resolution == Contact.Resolution.SEPARATING
                || resolution == Contact.Resolution.NONE) {
            return;
        }
        exitVelocity1.set(balls[0].getParticle().velocity);
        exitVelocity2.set(balls[1].getParticle().velocity);
        exitRecorded = true;
    }

    /**
     * Epilogue: the contact's impulse kept for the arrows and summed by who gave it (the
     * paddle, a wall); the predicted loss of a contact between two dynamic balls.
     */
    private void recordContact(Contact contact) {
        Body a = contact.getBodyA();
        Body b = contact.getBodyB();
        Body paddleBody = paddle.getBody();
        float j = contact.getImpulse();
        if (b == null) {
            // A wall: not a collision between the demo's bodies; its impulse j·n went to A.
            if (a != paddleBody) {
                addAlong(wallImpulse, contact.getNormal(), j);
            }
            return;
        }
        ++stepContacts;
        impulses.record(contact);
        if (a == paddleBody || b == paddleBody) {
            // The ball got j·n if it is A, −j·n if it is B; the paddle the opposite, unused.
            lastPaddleImpulse.zero();
            addAlong(lastPaddleImpulse, contact.getNormal(), b == paddleBody ? j : -j);
            paddleImpulse.addLocal(lastPaddleImpulse);
            ++paddleContacts;
        }
        if (b.getInverseMass() == 0f || a.getInverseMass() == 0f) {
            return;
        }
        float mu = 1f / (contact.getBodyA().getInverseMass() + b.getInverseMass());
        float vn = contact.getApproachSpeed();
        float e = getRestitution();
        stepLoss += 0.5f * mu * (1f - e * e) * vn * vn;
        impactNormalSpeed = vn;
        impactReducedMass = mu;
    }

    /** Sum the dynamic balls' momentum into storeResult; return their kinetic energy. */
    private float totals(Vector3f storeResult) {
        storeResult.zero();
        float energy = 0f;
        for (int i = 0; i < BALLS; ++i) {
            DemoParticle ball = balls[i];
            if (ball.isParked()) {
                continue;
            }
            float m = ball.getParticle().getMass();
            Vector3f v = ball.getParticle().velocity;
            storeResult.x += m * v.x;
            storeResult.y += m * v.y;
            storeResult.z += m * v.z;
            energy += 0.5f * m * v.lengthSquared();
        }
        return energy;
    }

    /**
     * The script: the paddle's velocity {@code speed·U(t)}, {@code U(t) = (cos θ, sin θ, 0)},
     * {@code θ(t) = swing·sin(rate·t)}, set before each step (so {@code P += speed·h·U(t)}).
     */
    private void steerPaddle(double timeSeconds) {
        if (preset != Preset.PADDLE) {
            return;
        }
        if (paddle.getParticle().position.x >= PADDLE_END_X) {
            paddle.getParticle().velocity.zero();
            paddleStopped = true;
            return;
        }
        paddleAngle = scriptAngle(timeSeconds);
        paddle.getParticle().velocity.set(PADDLE_SPEED * FastMath.cos(paddleAngle),
                PADDLE_SPEED * FastMath.sin(paddleAngle), 0f);
    }

    /**
     * Draw each recent contact's impulses, held {@link ContactImpulses#HOLD_SECONDS}: from
     * the contact point, {@code j·n} on A and {@code −j·n} on B (Newton's third law), each
     * shortened only to keep its tip above the ground band; with the magnitude, or a
     * kinematic side's arrow grey and marked not applied. The labels, newest contact first,
     * go where they cover no other label, sphere, ball's name, trail or HUD text
     * ({@link CalloutLayout}), without their unit or note when the full text has no room, or
     * not at all. Allocates nothing.
     */
    private void showImpulses() {
        if (arrows == null) {
            return;
        }
        double now = getWorld().getTimeSeconds();
        PlaneView plane = getWindow().getPlaneView();
        float pixelsPerMetre = Math.max(PlaneView.MIN_PIXELS, plane.getPixelsPerMetre());
        float sizePixels = IMPULSE_LABEL_SHARE
                * getWindow().getHud().getLayout().getSceneLabelSize();
        float size = sizePixels / pixelsPerMetre;
        float height = labelMeasure.lineHeight(sizePixels);
        beginCallouts(plane);
        lowestArrowTip = Float.POSITIVE_INFINITY;
        for (int i = 0; i < ContactImpulses.CAPACITY; ++i) {
            for (int side = 0; side < 2; ++side) {
                impulseLabelRects[2 * i + side].set(0f, 0f, 0f, 0f);
            }
            if (i >= impulses.size() || !impulses.isShown(i, now)) {
                arrows.hide(2 * i);
                arrows.hide(2 * i + 1);
                continue;
            }
            // In front of the spheres (their radius towards the camera), so none hides them.
            impulses.copyPoint(i, arrowStart).z += ARROW_LIFT * RADIUS;
            for (int side = 0; side < 2; ++side) {
                boolean onA = side == 0;
                boolean applied = impulses.isApplied(i, onA);
                impulses.copyImpulse(i, onA, arrowImpulse);
                // The tip kept above the ground band: the arrow drawn shorter, never longer.
                arrowImpulse.multLocal(ImpulseArrows.lengthScale(arrowStart.y, arrowImpulse.y,
                        METRES_PER_NEWTON_SECOND, ARROW_FLOOR));
                int shortLength = writeArrowLabel(i, onA, applied);
                float fullWidth = labelMeasure.width(arrowLabel, sizePixels);
                arrowLabel.setLength(shortLength);
                float shortWidth = labelMeasure.width(arrowLabel, sizePixels);
                writeArrowLabel(i, onA, applied);
                float tipX = arrowStart.x + METRES_PER_NEWTON_SECOND * arrowImpulse.x;
                float tipY = arrowStart.y + METRES_PER_NEWTON_SECOND * arrowImpulse.y;
                lowestArrowTip = Math.min(lowestArrowTip, tipY);
                ScreenRect place = impulseLabelRects[2 * i + side];
                int form = callouts.place(plane.screenX(tipX), plane.screenY(tipY),
                        arrowImpulse.x, arrowImpulse.y, fullWidth, shortWidth, height,
                        CALLOUT_GAP * sizePixels, place);
                if (form == CalloutLayout.SHORT) {
                    arrowLabel.setLength(shortLength);
                } else if (form == CalloutLayout.HIDDEN) {
                    arrowLabel.setLength(0);
                }
                arrows.show(2 * i + side, arrowStart, arrowImpulse, applied, arrowLabel, size,
                        plane.planeX(place.getX()), plane.planeY(place.getTop()));
            }
        }
    }

    /**
     * Start the frame's callouts: inside the scene above the ground band, clear of the
     * spheres, the balls' names, the trails as drawn (issue 29 §3: a label lay over the
     * path its ball came along) and the HUD's texts.
     */
    private void beginCallouts(PlaneView plane) {
        getWindow().copySceneRect(calloutArea);
        float ground = plane.screenY(0f);
        calloutArea.set(calloutArea.getX(), Math.max(calloutArea.getY(), ground),
                calloutArea.getWidth(), Math.max(0f, calloutArea.getTop() - ground));
        callouts.begin(calloutArea);
        HudLayout layout = getWindow().getHud().getLayout();
        callouts.addObstacle(layout.getTitle());
        callouts.addObstacle(layout.getBody());
        callouts.addObstacle(layout.getWarning());
        callouts.addObstacle(layout.getFooter());
        callouts.addObstacle(layout.getReadout());
        callouts.addObstacle(layout.getSidePanel());
        callouts.addObstacle(layout.getGraph());
        List<DemoParticle> shown = getParticles();
        float radius = RADIUS * plane.getPixelsPerMetre();
        for (int p = 0; p < shown.size(); ++p) {
            Vector3f position = shown.get(p).getParticle().position;
            callouts.addObstacle(plane.screenX(position.x) - radius,
                    plane.screenY(position.y) - radius, 2f * radius, 2f * radius);
            callouts.addObstacle(getWindow().getView(shown.get(p)).getLabelRect());
        }
        addTrailPoints(plane, shown);
    }

    /**
     * Give the callouts every shown ball's trail points on the screen, kept off by the
     * trails' drawn half width (ribbon and step dots). The arrays grow at the first frame
     * that needs them, then are reused.
     */
    private void addTrailPoints(PlaneView plane, List<DemoParticle> shown) {
        int capacity = 0;
        for (int p = 0; p < shown.size(); ++p) {
            capacity += getWindow().getView(shown.get(p)).getTrail().getCapacity();
        }
        if (trailScreenX.length < capacity) {
            trailScreenX = new float[capacity];
            trailScreenY = new float[capacity];
        }
        int count = 0;
        float halfWidth = 0f;
        for (int p = 0; p < shown.size(); ++p) {
            ParticleView view = getWindow().getView(shown.get(p));
            if (view.getNode().getCullHint() == Spatial.CullHint.Always) {
                continue;
            }
            Trail trail = view.getTrail();
            halfWidth = Math.max(halfWidth, trail.getDrawnHalfWidth());
            for (int age = 0; age < trail.size(); ++age) {
                trail.copyPoint(age, trailPoint);
                trailScreenX[count] = plane.screenX(trailPoint.x);
                trailScreenY[count] = plane.screenY(trailPoint.y);
                ++count;
            }
        }
        callouts.setTrailPoints(trailScreenX, trailScreenY, count,
                halfWidth * plane.getPixelsPerMetre());
    }

    /**
     * Write one side's arrow label into {@link #arrowLabel}: "J = 5.85 N s" once per contact
     * on the side that took it (A, unless A is the kinematic paddle), "-J" on the other, and
     * "-J not applied (kinematic)" on a kinematic side.
     *
     * @return the length of its short form: without the unit or the note
     */
    private int writeArrowLabel(int contact, boolean onA, boolean applied) {
        boolean magnitude = applied && (onA || !impulses.isApplied(contact, true));
        arrowLabel.setLength(0);
        arrowLabel.append(onA ? "J" : "-J");
        int shortLength = arrowLabel.length();
        if (!applied) {
            arrowLabel.append(" not applied (kinematic)");
        } else if (magnitude) {
            TextFormat.appendFixed(arrowLabel.append(" = "), impulses.getMagnitude(contact), 2);
            shortLength = arrowLabel.length();
            arrowLabel.append(" N s");
        }
        return shortLength;
    }

    /** Add {@code scale·n} to a vector in place. */
    private static void addAlong(Vector3f vector, Vector3f n, float scale) {
        vector.x += scale * n.x;
        vector.y += scale * n.y;
        vector.z += scale * n.z;
    }

    /** Put the preset's bodies at their launch states and park the rest on a rack. */
    private void arrange() {
        int rackSlot = 0;
        int used = usedBalls();
        for (int i = 0; i < BALLS; ++i) {
            if (i >= used) {
                park(balls[i], rackSlot++);
            }
            balls[i].getParticle().setMass(i == 0 ? MASSES[mass1] : MASSES[mass2]);
        }
        if (preset != Preset.PADDLE) {
            park(paddle, rackSlot);
        }
        paddle.getBody().setKinematic(preset == Preset.PADDLE);
        switch (preset) {
            case HEAD_ON:
                place(balls[0], 2f, LANE_Y, 4f, 0f);
                place(balls[1], 8f, LANE_Y, -2f, 0f);
                break;
            case GLANCING:
                place(balls[0], 2f, LANE_Y, 4f, 0f);
                place(balls[1], 7f, LANE_Y + RADIUS, 0f, 0f);
                break;
            case CRADLE:
                place(balls[0], 1f, LANE_Y, 4f, 0f);
                for (int i = 1; i < BALLS; ++i) {
                    place(balls[i], 6f + 2f * RADIUS * i, LANE_Y, 0f, 0f);
                }
                break;
            case PADDLE:
                // On the paddle's path (its direction swings up first), a little off it.
                place(paddle, 1f, PADDLE_START_Y, PADDLE_SPEED, 0f);
                place(balls[0], 4.9f, PADDLE_START_Y + 1f, 0f, 0f);
                place(balls[1], 6.8f, PADDLE_START_Y + 1.7f, 0f, 0f);
                place(balls[2], 8.8f, PADDLE_START_Y + 1.2f, 0f, 0f);
                break;
            default:
                throw new IllegalStateException("unknown preset " + preset);
        }
        Detection detection = preset == Preset.CRADLE ? Detection.OVERLAP : Detection.SWEPT;
        SphereRule wanted = detection == Detection.OVERLAP ? overlapRule : sweptRule;
        if (rule != wanted) {
            if (rule != null) {
                getWorld().removeRule(rule);
            }
            rule = wanted;
            getWorld().addRule(rule);
        }
    }

    /** @return how many balls the preset uses, from ball 1 on */
    private int usedBalls() {
        switch (preset) {
            case HEAD_ON:
            case GLANCING:
                return 2;
            case CRADLE:
                return BALLS;
            default:
                return 3;
        }
    }

    /**
     * Hide the bodies the preset leaves out (sphere, trail, label), show the others; before
     * the scene places the labels. Views exist only in a window; allocates nothing.
     */
    private void hideIdleBodies() {
        for (int i = 0; i < BALLS; ++i) {
            hideIfParked(balls[i]);
        }
        hideIfParked(paddle);
    }

    private void hideIfParked(DemoParticle body) {
        ParticleView view = getWindow().getView(body);
        if (view != null) {
            view.getNode().setCullHint(body.isParked() ? Spatial.CullHint.Always
                    : Spatial.CullHint.Inherit);
        }
    }

    /**
     * A body not in the preset: held on the rack, on the ground right of the box (where no
     * ball goes), out of the view and hidden ({@link #hideIdleBodies}); out of the HUD.
     */
    private void park(DemoParticle body, int slot) {
        position.set(RACK_X + RACK_SPACING * slot, RADIUS, 0f);
        body.setLaunch(position, Vector3f.ZERO);
        body.setParked(true);
        body.setHeld(true);
    }

    private void place(DemoParticle body, float x, float y, float vx, float vy) {
        position.set(x, y, 0f);
        velocity.set(vx, vy, 0f);
        body.setLaunch(position, velocity);
        body.setParked(false);
        body.setHeld(false);
    }

    /** The paddle's readouts, for the ring: its angle and the impulses it and the walls gave. */
    private StateRecord paddleState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 3 * 3 + 1 + 1 + 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putVector(paddleImpulse);
                slab.putVector(lastPaddleImpulse);
                slab.putVector(wallImpulse);
                slab.putInt(paddleContacts);
                slab.putFloat(paddleAngle);
                slab.putBoolean(paddleStopped);
            }

            @Override
            public void readState(StateSlab slab) {
                slab.getVector(paddleImpulse);
                slab.getVector(lastPaddleImpulse);
                slab.getVector(wallImpulse);
                paddleContacts = slab.getInt();
                paddleAngle = slab.getFloat();
                paddleStopped = slab.getBoolean();
            }
        };
    }

    /**
     * The demo's own state, for the ring: the latest impact step's readouts and the exit
     * velocities once recorded.
     */
    private StateRecord impactState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 4 * 3 + 1 + 3 + 2 + 5;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putVector(impactMomentumBefore);
                slab.putVector(impactMomentumAfter);
                slab.putVector(exitVelocity1);
                slab.putVector(exitVelocity2);
                slab.putBoolean(exitRecorded);
                slab.putFloat(energyBefore);
                slab.putFloat(stepLoss);
                slab.putInt(stepContacts);
                slab.putInt(impactSteps);
                slab.putInt(impactContacts);
                slab.putFloat(impactEnergyBefore);
                slab.putFloat(impactEnergyAfter);
                slab.putFloat(impactPredictedLoss);
                slab.putFloat(impactNormalSpeed);
                slab.putFloat(impactReducedMass);
            }

            @Override
            public void readState(StateSlab slab) {
                slab.getVector(impactMomentumBefore);
                slab.getVector(impactMomentumAfter);
                slab.getVector(exitVelocity1);
                slab.getVector(exitVelocity2);
                exitRecorded = slab.getBoolean();
                energyBefore = slab.getFloat();
                stepLoss = slab.getFloat();
                stepContacts = slab.getInt();
                impactSteps = slab.getInt();
                impactContacts = slab.getInt();
                impactEnergyBefore = slab.getFloat();
                impactEnergyAfter = slab.getFloat();
                impactPredictedLoss = slab.getFloat();
                impactNormalSpeed = slab.getFloat();
                impactReducedMass = slab.getFloat();
            }
        };
    }

    /**
     * The slide: the impulse with e and the masses; the latest impact's j. For the paddle:
     * its script and rule, and the momentum it gave the balls.
     */
    @Override
    protected void writePresentation(Presentation slide) {
        if (preset == Preset.PADDLE) {
            StringBuilder script = slide.formula()
                    .append("kinematic paddle: P += speed·h·U(t),  θ = ");
            TextFormat.appendFixed(script, paddleAngle, 3).append(" rad");
            TextFormat.appendFixed(slide.formula()
                    .append("dynamic balls: v' = (1+e) u - e v along n,  e = "),
                    getRestitution(), eDigits());
            StringBuilder readout = slide.readout();
            if (paddleContacts == 0) {
                readout.append("the paddle has not hit a ball yet");
                return;
            }
            TextFormat.appendVector(readout.append("ΣJ from the paddle "), paddleImpulse, 3)
                    .append(" kg m/s, -J not applied");
            return;
        }
        TextFormat.appendFixed(slide.formula()
                .append("j = -(1+e) v_rel·n / (1/m1 + 1/m2),   e = "), getRestitution(),
                eDigits());
        StringBuilder formula = slide.formula().append("V1 += j n/m1,  V2 -= j n/m2,   m1 = ");
        TextFormat.appendFixed(formula, MASSES[mass1], 1).append(" kg,  m2 = ");
        TextFormat.appendFixed(formula, MASSES[mass2], 1).append(" kg");
        StringBuilder readout = slide.readout();
        if (impactSteps == 0) {
            readout.append("no impact yet");
            return;
        }
        // |j| = (1+e)·μ·v_n, from the numbers the HUD's energy line shows.
        readout.append("latest impact:  j = (1+e)·μ·v_n = ");
        TextFormat.appendFixed(readout,
                (1f + getRestitution()) * impactReducedMass * impactNormalSpeed, 3)
                .append(" N s");
    }
}

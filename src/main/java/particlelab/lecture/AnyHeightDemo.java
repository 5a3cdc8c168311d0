package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.aiming.LaunchAngles;
import particlelab.collision.Plane;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.Draggable;
import particlelab.demo.KeyBinding;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.CurveView;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ScriptedResponse;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.StepListener;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * Aim at any height with a fixed launch speed s (Forrest Smith's "Solving Ballistic
 * Trajectories"). Builds upon HelloAiming, where vx was given and the target level: here the
 * speed is fixed and the angle is sought, for a target anywhere. No drag:
 * {@code tan θ = (s² ± √(s⁴ − g·(g·x² + 2·y·s²)))/(g·x)} ({@link LaunchAngles}), two angles
 * (a flat shot and a lob) while the square root is real.
 *
 * <p>What to watch for: move the target (arrows); both solutions are drawn (their continuous
 * parabolas) and fired (stepped by the shared integrator), and each shot stops where it
 * crosses the target's distance, the crossing found by the swept test of its step. The
 * stepped shots arrive about {@code ½·g·h·t} below the parabola, more for the lob, which flies
 * longer. Outside the reachable envelope, the safety parabola
 * {@code y = s²/(2g) − g·x²/(2s²)} (drawn), no angle reaches: the HUD says why and nothing is
 * fired.
 */
public final class AnyHeightDemo extends DemoState {

    /** The fixed launch speed s (in m/s). */
    public static final float LAUNCH_SPEED = 20f;
    /** The height of the gun's muzzle above the ground (in metres). */
    public static final float GUN_HEIGHT = 8f;
    /** The target's radius as drawn, and the tolerance of a hit (in metres). */
    public static final float TARGET_RADIUS = 0.5f;
    /** The target's distance: range and step of the keys (in metres). */
    public static final float MIN_DISTANCE = 4f;
    public static final float MAX_DISTANCE = 50f;
    public static final float DISTANCE_STEP = 2f;
    /** The target's height above the gun: range and step of the keys (in metres). */
    public static final float MIN_HEIGHT = -7f;
    public static final float MAX_HEIGHT = 20f;
    public static final float HEIGHT_STEP = 1f;
    /** Both shots stopped: fire again after this long (in seconds of simulated time). */
    public static final float REFIRE_SECONDS = 1.5f;
    private static final float START_DISTANCE = 30f;
    private static final float START_HEIGHT = 4f;
    private static final float GRAVITY = Gravity.STANDARD_G;
    private static final int CURVE_POINTS = 96;
    private static final float CURVE_WIDTH = 0.18f;
    /** Where a shot not fired waits: out of sight (in metres). */
    private static final float PARK_X = -1000f;
    private static final ColorRGBA LOW_COLOR = new ColorRGBA(0.3f, 0.85f, 1f, 1f);
    private static final ColorRGBA HIGH_COLOR = new ColorRGBA(1f, 0.6f, 0.2f, 1f);
    private static final ColorRGBA TARGET_COLOR = new ColorRGBA(1f, 0.3f, 0.25f, 1f);
    private static final ColorRGBA ENVELOPE_COLOR = new ColorRGBA(0.85f, 0.85f, 0.95f, 0.8f);

    private final ParticleIntegrator falling = new ParticleIntegrator(new Gravity());
    private final ParticleIntegrator still = new ParticleIntegrator();
    private final Shot low = new Shot();
    private final Shot high = new Shot();
    private final Vector3f muzzle = new Vector3f(0f, GUN_HEIGHT, 0f);
    private final Vector3f park = new Vector3f(PARK_X, GUN_HEIGHT, 0f);
    private final Vector3f scratch = new Vector3f();
    private final float[] curveX = new float[CURVE_POINTS];
    private final float[] curveY = new float[CURVE_POINTS];
    private float targetDistance = START_DISTANCE;
    private float targetHeight = START_HEIGHT;
    private LaunchAngles angles;
    /** The target the angles were solved for (in metres). */
    private float solvedDistance = Float.NaN;
    private float solvedHeight = Float.NaN;
    private DemoParticle target;
    private SurfaceRule targetPlane;
    private CurveView envelope;
    /** The step the world is taking (in seconds). */
    private float worldStep = Float.NaN;
    /** Both shots stopped this long ago (in seconds; &lt;0: not both yet). */
    private float stoppedSeconds = -1f;
    /** The shots have rested long enough: fire again at the next step's start. */
    private boolean refireDue;
    private KeyBinding fartherKey;
    private KeyBinding nearerKey;
    private KeyBinding higherKey;
    private KeyBinding lowerKey;

    /** One of the two solutions: its particle, its drawn parabola and where it arrived. */
    private static final class Shot {
        DemoParticle particle;
        CurveView curve;
        String name;
        boolean fired;
        boolean arrived;
        /** Where it crossed the target's distance, above the gun (in metres). */
        float arrivalHeight = Float.NaN;
        double arrivalSeconds = Double.NaN;
        /** The angle its label and parabola show (in radians; NaN: none). */
        double shownRadians = Double.NaN;
        /** The label and parabola must be shown again ({@link #update}). */
        boolean viewChanged = true;
    }

    /** Create the demo. */
    public AnyHeightDemo() {
        super("Aim at any height");
    }

    // ----------------------------------------------------------------------- public API ----

    /**
     * Move the target and fire both solutions at it (none if out of reach).
     *
     * @param distance x, its horizontal distance from the gun (in metres, from
     *     {@link #MIN_DISTANCE} to {@link #MAX_DISTANCE})
     * @param height y, its height above the gun (in metres, from {@link #MIN_HEIGHT} to
     *     {@link #MAX_HEIGHT})
     */
    public void setTarget(float distance, float height) {
        if (!(distance >= MIN_DISTANCE && distance <= MAX_DISTANCE)) {
            throw new IllegalArgumentException("target distance must be from " + MIN_DISTANCE
                    + " to " + MAX_DISTANCE + " m, but was " + distance);
        }
        if (!(height >= MIN_HEIGHT && height <= MAX_HEIGHT)) {
            throw new IllegalArgumentException("target height must be from " + MIN_HEIGHT
                    + " to " + MAX_HEIGHT + " m above the gun, but was " + height);
        }
        targetDistance = distance;
        targetHeight = height;
        placeTarget();
        fire();
    }

    /** @return the target's horizontal distance from the gun (in metres) */
    public float getTargetDistance() {
        return targetDistance;
    }

    /** @return the target's height above the gun (in metres) */
    public float getTargetHeight() {
        return targetHeight;
    }

    /**
     * Return the launch angles for the current target.
     *
     * @return the solution (not null)
     */
    public LaunchAngles getAngles() {
        return angles;
    }

    /**
     * Test whether a shot crossed the target's distance.
     *
     * @param lob true for the high arc, false for the low one
     * @return true once it arrived
     */
    public boolean hasArrived(boolean lob) {
        return (lob ? high : low).arrived;
    }

    /**
     * Return how high above the gun a shot crossed the target's distance.
     *
     * @param lob true for the high arc, false for the low one
     * @return the height (in metres; NaN until it arrived)
     */
    public float getArrivalHeight(boolean lob) {
        return (lob ? high : low).arrivalHeight;
    }

    /**
     * Return a shot's flight time to the target's distance.
     *
     * @param lob true for the high arc, false for the low one
     * @return the time (in seconds; NaN until it arrived)
     */
    public double getArrivalSeconds(boolean lob) {
        return (lob ? high : low).arrivalSeconds;
    }

    /**
     * Test whether a shot was fired this time (not when out of reach).
     *
     * @param lob true for the high arc, false for the low one
     * @return true if fired
     */
    public boolean isFired(boolean lob) {
        return (lob ? high : low).fired;
    }

    /**
     * Fire both solutions at the target, or none when it is out of reach.
     */
    public void fire() {
        stoppedSeconds = -1f;
        refireDue = false;
        if (angles == null || solvedDistance != targetDistance || solvedHeight != targetHeight) {
            // Solved again only when the target moved: firing again allocates nothing.
            angles = LaunchAngles.solve(LAUNCH_SPEED, targetDistance, targetHeight, GRAVITY);
            solvedDistance = targetDistance;
            solvedHeight = targetHeight;
        }
        if (angles.isReachable()) {
            fire(low, angles.getLowRadians());
            fire(high, angles.getHighRadians());
        } else {
            holdOutOfSight(low);
            holdOutOfSight(high);
        }
    }

    // ------------------------------------------------------------- framework overrides ----

    @Override
    protected void createScene() {
        low.name = "low";
        high.name = "high";
        low.particle = addParticle("", LOW_COLOR, park, Vector3f.ZERO, 1f, falling);
        high.particle = addParticle("", HIGH_COLOR, park, Vector3f.ZERO, 1f, falling);
        target = addParticle("target", TARGET_COLOR, park, Vector3f.ZERO, 1f, still);
        target.setParked(true);
        low.particle.setParked(true);
        high.particle.setParked(true);
        // The target never moves by itself and takes part in no contact.
        target.getBody().setKinematic(true);
        World world = getWorld();
        world.addRule(SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT));
        world.addStepListener(new StepListener() {
            @Override
            public void beforeStep(World stepping, float stepSeconds) {
                worldStep = stepSeconds;
            }
        });
        world.addContactListener(new ContactListener() {
            @Override
            public boolean accept(Contact contact, World stepping) {
                arrive(contact);
                return true;
            }
        });
        addMarker("gun", 0f, GUN_HEIGHT, new ColorRGBA(0.6f, 0.9f, 0.6f, 1f));
        // The envelope's apex is s²/(2g) above the gun.
        float top = GUN_HEIGHT + LAUNCH_SPEED * LAUNCH_SPEED / (2f * GRAVITY);
        setView(-3f, MAX_DISTANCE + 3f, Math.max(top, GUN_HEIGHT + MAX_HEIGHT) + 2f, 2f, 5,
                TARGET_RADIUS);
        hideArrowsAtStart();
        addStateRecord(shotState());
        placeTarget();
        fire();
    }

    @Override
    protected void buildViews(Application app) {
        envelope = new CurveView(app.getAssetManager(), "envelope", CURVE_POINTS, CURVE_WIDTH,
                ENVELOPE_COLOR);
        low.curve = new CurveView(app.getAssetManager(), "low parabola", CURVE_POINTS,
                CURVE_WIDTH, LOW_COLOR.clone().setAlpha(0.45f));
        high.curve = new CurveView(app.getAssetManager(), "high parabola", CURVE_POINTS,
                CURVE_WIDTH, HIGH_COLOR.clone().setAlpha(0.45f));
        getSceneNode().attachChild(envelope.getGeometry());
        getSceneNode().attachChild(low.curve.getGeometry());
        getSceneNode().attachChild(high.curve.getGeometry());
        drawEnvelope();
    }

    @Override
    protected void declareKeys() {
        String across = TextFormat.appendFixed(new StringBuilder(), DISTANCE_STEP, 0)
                .append(" m").toString();
        String up = TextFormat.appendFixed(new StringBuilder(), HEIGHT_STEP, 0)
                .append(" m").toString();
        fartherKey = bindKey(KeyInput.KEY_RIGHT, "Right", "target " + across + " farther",
                () -> moveTarget(DISTANCE_STEP, 0f));
        nearerKey = bindKey(KeyInput.KEY_LEFT, "Left", "target " + across + " nearer",
                () -> moveTarget(-DISTANCE_STEP, 0f));
        higherKey = bindKey(KeyInput.KEY_UP, "Up", "target " + up + " higher",
                () -> moveTarget(0f, HEIGHT_STEP));
        lowerKey = bindKey(KeyInput.KEY_DOWN, "Down", "target " + up + " lower",
                () -> moveTarget(0f, -HEIGHT_STEP));
        bindKey(KeyInput.KEY_F, "F", "fire both solutions again", this::fire);
    }

    @Override
    protected void declareDraggables() {
        // The target, as the arrow keys move it but anywhere in their range, to the metre
        // the HUD prints; both solutions fire again at once, so also while running.
        declareDraggable(new Draggable("the target", Draggable.Grip.BODY,
                Draggable.Effect.PLACE, List.of(target), "x and y to the metre, fired at",
                " (also running)", true, (particle, point) -> {
                    float distance = Math.max(MIN_DISTANCE, Math.min(MAX_DISTANCE,
                            Math.round(point.x)));
                    float height = Math.max(MIN_HEIGHT, Math.min(MAX_HEIGHT,
                            Math.round(point.y - GUN_HEIGHT)));
                    if (distance != targetDistance || height != targetHeight) {
                        setTarget(distance, height);
                    }
                }));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("fixed speed s, no drag:  tan θ = (s² ± √(s⁴ − g·(g·x² + 2·y·s²)))/(g·x),"
                + "  reachable below y = s²/(2g) − g·x²/(2s²)\n");
    }

    @Override
    protected void afterStep(float stepSeconds) {
        boolean lowDone = !low.fired || low.particle.isHeld();
        boolean highDone = !high.fired || high.particle.isHeld();
        if (!(low.fired || high.fired) || !(lowDone && highDone)) {
            return;
        }
        stoppedSeconds = stoppedSeconds < 0f ? 0f : stoppedSeconds + stepSeconds;
        refireDue = stoppedSeconds >= REFIRE_SECONDS;
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        if (refireDue) {
            refireDue = false;
            fire();
        }
    }

    /**
     * Show the shots' new angles before the frame: jME rebuilds a text's mesh when its text
     * changes, which allocates, so this happens here, once per change, and not in the
     * allocation-free {@link particlelab.demo.DemoWindow#advance}.
     */
    @Override
    public void update(float tpf) {
        if (low.viewChanged) {
            low.viewChanged = false;
            showAngle(low);
        }
        if (high.viewChanged) {
            high.viewChanged = false;
            showAngle(high);
        }
        super.update(tpf);
    }

    @Override
    protected void onRestart() {
        placeTarget();
        fire();
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        text.append("s = ");
        TextFormat.appendFixed(text, LAUNCH_SPEED, 0).append(" m/s fixed, gun ");
        TextFormat.appendFixed(text, GUN_HEIGHT, 0).append(" m up;  target x = ");
        TextFormat.appendFixed(text, targetDistance, 0).append(" m (")
                .append(nearerKey.getKeyLabel()).append('/').append(fartherKey.getKeyLabel())
                .append("),  y = ");
        TextFormat.appendFixed(text, targetHeight, 0).append(" m above the gun (")
                .append(higherKey.getKeyLabel()).append('/').append(lowerKey.getKeyLabel())
                .append(")\n");
        text.append("Envelope (safety parabola) at this x: y = ");
        TextFormat.appendFixed(text, LaunchAngles.envelopeHeight(LAUNCH_SPEED, targetDistance,
                GRAVITY), 2).append(" m;  range at the gun's height s²/g = ");
        TextFormat.appendFixed(text, LAUNCH_SPEED * LAUNCH_SPEED / GRAVITY, 1).append(" m\n");
        if (!angles.isReachable()) {
            text.append("OUT OF REACH: the target's y = ");
            TextFormat.appendFixed(text, targetHeight, 2).append(" m is above the envelope's ");
            TextFormat.appendFixed(text, LaunchAngles.envelopeHeight(LAUNCH_SPEED,
                    targetDistance, GRAVITY), 2).append(" m, so s⁴ − g·(g·x² + 2·y·s²) < 0:"
                    + " no real angle reaches it at this speed\n");
            return;
        }
        appendShot(text, low, angles.getLowRadians());
        appendShot(text, high, angles.getHighRadians());
    }

    // ---------------------------------------------------------------- private helpers ----

    private void appendShot(StringBuilder text, Shot shot, double radians) {
        text.append(shot == low ? "Low arc   θ = " : "High arc  θ = ");
        TextFormat.appendFixed(text, radians * FastMath.RAD_TO_DEG, 2).append("°:  ");
        if (!shot.arrived) {
            text.append(shot.particle.isHeld() ? "came down before the target" : "in flight");
        } else {
            text.append("crossed x = ");
            TextFormat.appendFixed(text, targetDistance, 0).append(" m at y = ");
            TextFormat.appendFixed(text, shot.arrivalHeight, 3).append(" m after ");
            TextFormat.appendFixed(text, shot.arrivalSeconds, 2).append(" s,  ");
            float miss = shot.arrivalHeight - targetHeight;
            text.append(Math.abs(miss) <= TARGET_RADIUS ? "HIT" : "MISS").append(", off by ");
            TextFormat.appendFixed(text, miss, 3).append(" m  (Euler: ½·g·h·t = ");
            TextFormat.appendFixed(text, 0.5 * GRAVITY * worldStep * shot.arrivalSeconds, 3)
                    .append(" m low)");
        }
        text.append('\n');
    }

    private void moveTarget(float byDistance, float byHeight) {
        setTarget(Math.max(MIN_DISTANCE, Math.min(MAX_DISTANCE, targetDistance + byDistance)),
                Math.max(MIN_HEIGHT, Math.min(MAX_HEIGHT, targetHeight + byHeight)));
    }

    /** Put the target where it is asked for, and the plane that stops the shots through it. */
    private void placeTarget() {
        scratch.set(targetDistance, GUN_HEIGHT + targetHeight, 0f);
        target.setLaunch(scratch, Vector3f.ZERO);
        target.setHeld(true);
        World world = getWorld();
        if (targetPlane != null) {
            world.removeRule(targetPlane);
        }
        // The plane x = target distance, its front facing the gun: a new one per move.
        targetPlane = new SurfaceRule("target distance", new Plane(new Vector3f(-1f, 0f, 0f),
                -targetDistance), ScriptedResponse.stick(), Detection.SWEPT);
        world.addRule(targetPlane);
    }

    private void fire(Shot shot, double radians) {
        scratch.set(LAUNCH_SPEED * (float) Math.cos(radians),
                LAUNCH_SPEED * (float) Math.sin(radians), 0f);
        shot.particle.setLaunch(muzzle, scratch);
        launch(shot.particle, scratch);
        shot.fired = true;
        shot.arrived = false;
        shot.arrivalHeight = Float.NaN;
        shot.arrivalSeconds = Double.NaN;
        if (radians != shot.shownRadians) {
            shot.shownRadians = radians;
            shot.viewChanged = true;
        }
    }

    private void holdOutOfSight(Shot shot) {
        shot.particle.setLaunch(park, Vector3f.ZERO);
        launch(shot.particle, Vector3f.ZERO);
        shot.particle.setHeld(true);
        shot.fired = false;
        shot.arrived = false;
        if (!Double.isNaN(shot.shownRadians)) {
            shot.shownRadians = Double.NaN;
            shot.viewChanged = true;
        }
    }

    /** Show a shot's new angle: its label and its parabola, or neither when not fired. */
    private void showAngle(Shot shot) {
        if (Double.isNaN(shot.shownRadians)) {
            relabel(shot.particle, "");
            if (shot.curve != null) {
                shot.curve.hide();
            }
            return;
        }
        StringBuilder label = new StringBuilder(shot.name).append(' ');
        TextFormat.appendFixed(label, shot.shownRadians * FastMath.RAD_TO_DEG, 1).append('°');
        relabel(shot.particle, label.toString());
        if (shot.curve != null) {
            drawParabola(shot.curve, shot.shownRadians);
        }
    }

    /** The prologue: a shot meeting the target's plane has arrived; note where and when. */
    private void arrive(Contact contact) {
        if (contact.getRule() != targetPlane) {
            return;
        }
        Body body = contact.getBodyA();
        Shot shot = body == low.particle.getBody() ? low
                : body == high.particle.getBody() ? high : null;
        if (shot == null) {
            return;
        }
        shot.arrived = true;
        shot.arrivalHeight = contact.getPoint().y - GUN_HEIGHT;
        // The particle's flight time is counted after the step: here it is the step's start.
        shot.arrivalSeconds = shot.particle.getFlightSeconds()
                + contact.getFraction() * (double) worldStep;
    }

    /**
     * The shots' results and the refire timer, for the ring: after a step back the HUD says
     * where each shot was at that step (in flight, arrived, came down), not where it is live.
     */
    private StateRecord shotState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 2 * (1 + 1 + 1 + 2) + 1 + 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                writeShot(slab, low);
                writeShot(slab, high);
                slab.putFloat(stoppedSeconds);
                slab.putBoolean(refireDue);
            }

            @Override
            public void readState(StateSlab slab) {
                readShot(slab, low);
                readShot(slab, high);
                stoppedSeconds = slab.getFloat();
                refireDue = slab.getBoolean();
            }
        };
    }

    private static void writeShot(StateSlab slab, Shot shot) {
        slab.putBoolean(shot.fired);
        slab.putBoolean(shot.arrived);
        slab.putFloat(shot.arrivalHeight);
        slab.putDouble(shot.arrivalSeconds);
    }

    private static void readShot(StateSlab slab, Shot shot) {
        shot.fired = slab.getBoolean();
        shot.arrived = slab.getBoolean();
        shot.arrivalHeight = slab.getFloat();
        shot.arrivalSeconds = slab.getDouble();
    }

    /** The continuous parabola at an angle, from the muzzle to the target's distance. */
    private void drawParabola(CurveView curve, double radians) {
        double vx = LAUNCH_SPEED * Math.cos(radians);
        double vy = LAUNCH_SPEED * Math.sin(radians);
        double flight = targetDistance / vx;
        for (int i = 0; i < CURVE_POINTS; ++i) {
            double t = flight * i / (CURVE_POINTS - 1);
            curveX[i] = (float) (vx * t);
            curveY[i] = (float) (GUN_HEIGHT + vy * t - 0.5 * GRAVITY * t * t);
        }
        curve.setPoints(curveX, curveY, CURVE_POINTS);
    }

    /** The safety parabola, from the gun to where it meets the ground (or the view's edge). */
    private void drawEnvelope() {
        double reach = LAUNCH_SPEED * (double) LAUNCH_SPEED / GRAVITY;
        // GUN_HEIGHT + s²/(2g) − g·x²/(2s²) = 0  at  x = (s²/g)·√(1 + 2·g·GUN_HEIGHT/s²).
        double end = Math.min(MAX_DISTANCE + 3.0, reach * Math.sqrt(1.0 + 2.0 * GUN_HEIGHT
                / reach));
        for (int i = 0; i < CURVE_POINTS; ++i) {
            double x = end * i / (CURVE_POINTS - 1);
            curveX[i] = (float) x;
            curveY[i] = (float) (GUN_HEIGHT + LaunchAngles.envelopeHeight(LAUNCH_SPEED, x,
                    GRAVITY));
        }
        envelope.setPoints(curveX, curveY, CURVE_POINTS);
    }

    /** The slide: the two angles of the fixed speed; how far each arc is off the target. */
    @Override
    protected void writePresentation(Presentation slide) {
        slide.formula().append("tan θ = (s² ± √(s⁴ − g·(g·x² + 2·y·s²)))/(g·x)");
        StringBuilder formula = slide.formula().append("s = ");
        TextFormat.appendFixed(formula, LAUNCH_SPEED, 0).append(" m/s,  x = ");
        TextFormat.appendFixed(formula, targetDistance, 0).append(" m,  y = ");
        TextFormat.appendFixed(formula, targetHeight, 0).append(" m");
        StringBuilder readout = slide.readout();
        if (!angles.isReachable()) {
            readout.append("OUT OF REACH: above the envelope");
            return;
        }
        for (int i = 0; i < 2; ++i) {
            Shot shot = i == 0 ? low : high;
            readout.append(i == 0 ? "low arc " : ",   high arc ");
            if (!shot.arrived) {
                readout.append(shot.particle.isHeld() ? "came down" : "in flight");
            } else {
                TextFormat.appendFixed(readout.append("off by "),
                        shot.arrivalHeight - targetHeight, 3).append(" m");
            }
        }
    }
}

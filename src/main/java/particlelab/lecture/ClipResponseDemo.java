package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.Clip;
import particlelab.world.ClipReader;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.ContactResponse;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.ScriptedResponse;
import particlelab.world.SphereRule;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * Demo 19, clip: the slide "Collision Resolution: animation based vs physics based". Builds
 * upon collisions (the impulse with restitution e between two spheres) and puts beside it what
 * a game often does instead: an artist's clip played from the contact ("a rocket hits a
 * target", motion capture in a sports game). Two lanes in one world and one clock, the same
 * shot in each: a rocket (a sphere flying straight, its motor holding it level) fired at a
 * target resting on a 2 m ledge.
 * <ul>
 * <li>Physics lane (right): the world's response, an impulse along the normal n with
 * restitution e, {@code j = (1+e)·v_n/(1/m_r + 1/m_t)}: after it, {@code v_r' = v·(m_r −
 * e·m_t)/(m_r + m_t)} and {@code v_t' = v·(1+e)·m_r/(m_r + m_t)} along n for a head-on hit.
 * Then both fall under g (the motor is out, the target off its ledge) and bounce on the
 * ground.</li>
 * <li>Clip lane (left): at the contact both bodies stop and become kinematic
 * ({@link ScriptedResponse#clip()}); a keyframed {@link Clip} read from
 * {@code assets/clips/*.clip} then moves them, each from where it was at the contact, linear
 * between keys: before each step the demo sets a body's V so that {@code P += h·V} lands on
 * the clip's offset at the step's end.</li>
 * </ul>
 *
 * <p>What to watch for: fire at two speeds (Up/Down) or two angles (Left/Right). The clip
 * plays the same motion whatever the impact: its momentum and energy after the hit are the
 * same numbers every shot, while the physics lane's grow with the speed and keep the
 * momentum of the shot. The HUD sets the lanes side by side and the clip's error against what
 * the impact implies (the physics lane's velocities): each body's |Δv|, the momentum it makes
 * up or loses, and the energy it creates or loses against the e chosen; the shots table keeps
 * the last few shots.
 */
public final class ClipResponseDemo extends DemoState {

    /** Every sphere's radius, rocket and target alike (in metres). */
    public static final float RADIUS = 0.25f;
    /** The ledge the target rests on (in metres); the clips drop it this far. */
    public static final float LEDGE_HEIGHT = 2f;
    /** How far the rocket starts from the target's centre, along its flight (in metres). */
    public static final float RUN_UP_METRES = 3.5f;
    /** The clip lane's target stands here (x, in metres): the left half. */
    public static final float CLIP_TARGET_X = -4.5f;
    /** The physics lane's target stands here (x, in metres): the right half. */
    public static final float PHYSICS_TARGET_X = 2.5f;
    /** The clips, by their names on the command line; each is assets/clips/NAME.clip. */
    static final String[] CLIP_NAMES = {"topple", "rebound"};
    /** The speed at the start (in m/s). */
    static final float START_SPEED = 12f;
    /** The speed keys' change (in m/s). */
    static final float SPEED_STEP = 4f;
    /** The slowest shot (in m/s). */
    static final float MIN_SPEED = 4f;
    /** The fastest shot (in m/s). */
    static final float MAX_SPEED = 40f;
    /** The angle keys' change (in degrees). */
    static final float ANGLE_STEP = 10f;
    /** The steepest climb (in degrees); 0 is level. */
    static final float MAX_ANGLE = 30f;
    /** Restitution e of the rocket-target impulse at the start. */
    static final float START_E = 0.5f;
    /** The rocket's mass at the start (in kg). */
    static final float START_ROCKET_KG = 1f;
    /** The target's mass at the start (in kg). */
    static final float START_TARGET_KG = 2f;
    /** The physics lane's ground: e = 0.3 with the resting fix, so the bodies come to rest. */
    private static final float GROUND_E = 0.3f;
    /** The lanes' collision groups: a lane's bodies touch each other, never the other's. */
    private static final int PHYSICS_GROUP = 2;
    /** The clip lane's collision group (a bit). */
    private static final int CLIP_GROUP = 4;
    /** The clips' track names, in body order ({@link #ROCKET}, {@link #TARGET}). */
    private static final String[] TRACKS = {"rocket", "target"};
    /** The shots the HUD's shots line keeps. */
    static final int SHOT_ROWS = 3;
    /** Per shot: speed (m/s), angle (deg), physics KE and clip KE after the impact (J). */
    private static final int SHOT_FIELDS = 4;
    /** The physics lane's index in the body arrays and the lane arguments. */
    public static final int PHYSICS_LANE = 0;
    /** The clip lane's index. */
    public static final int CLIP_LANE = 1;
    /** The rocket's index in a lane. */
    public static final int ROCKET = 0;
    /** The target's index in a lane. */
    public static final int TARGET = 1;
    /** The rockets' colour, both lanes. */
    private static final ColorRGBA ROCKET_COLOR = new ColorRGBA(1f, 0.55f, 0.15f, 1f);
    /** The targets' colour, both lanes. */
    private static final ColorRGBA TARGET_COLOR = new ColorRGBA(0.3f, 0.75f, 1f, 1f);
    /** g while a motor or a ledge holds a body (m/s², never modified). */
    private static final Vector3f NO_GRAVITY = new Vector3f();
    /** g once a physics body is free (m/s², never modified). */
    private static final Vector3f DOWN_G = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    /** The HUD's digits for velocities, momenta and energies. */
    private static final int DIGITS = 2;

    /** The clips, in the order of {@link #CLIP_NAMES}. */
    private final Clip[] clips = new Clip[CLIP_NAMES.length];
    /** [clip][body]: the body's track in the clip. */
    private final int[][] tracks = new int[CLIP_NAMES.length][TRACKS.length];
    /** [lane][body]. */
    private final DemoParticle[][] spheres = new DemoParticle[2][2];
    /** [lane][body]: each body's own g, 0 until it is free (hit), g after in physics. */
    private final Gravity[][] gravities = new Gravity[2][2];
    /** The physics lane's rocket-target impulse. */
    private final ImpulseResponse impulse = new ImpulseResponse(START_E, 0f, false);
    /** The clip lane's contact: both bodies stopped and handed to the clip. */
    private final ContactResponse clipStart = ScriptedResponse.clip();
    /** The rocket-target rule of both lanes. */
    private SphereRule pairRule;
    /** The shot's speed (in m/s). */
    private float speed = START_SPEED;
    /** The shot's climb angle (in degrees). */
    private float angleDegrees;
    /** The clip the clip lane plays (index into {@link #clips}). */
    private int clipIndex;
    /** The rockets' mass (in kg). */
    private float rocketKg = START_ROCKET_KG;
    /** The targets' mass (in kg). */
    private float targetKg = START_TARGET_KG;
    /** The physics lane's rocket has hit (state a step changes, as those below). */
    private boolean physicsHit;
    /** The clip lane's rocket has hit: its clip plays. */
    private boolean clipHit;
    /** This shot's row is in the shots table. */
    private boolean shotRecorded;
    /** The clip lane's contact time (in seconds of the world). */
    private double clipStartSeconds;
    /** [body]: where the clip lane's bodies were at the contact (m). */
    private final Vector3f[] clipOrigins = {new Vector3f(), new Vector3f()};
    /** [body]: the physics lane's velocities right after the impact (m/s). */
    private final Vector3f[] physicsAfter = {new Vector3f(), new Vector3f()};
    /** The shots table, a ring of {@link #SHOT_ROWS} rows. */
    private final float[] shots = new float[SHOT_ROWS * SHOT_FIELDS];
    /** The shots recorded since the demo was created. */
    private int shotCount;
    /** Scratch: a position (m). */
    private final Vector3f scratchPosition = new Vector3f();
    /** Scratch: a velocity (m/s). */
    private final Vector3f scratchVelocity = new Vector3f();
    /** Scratch: a momentum (kg·m/s). */
    private final Vector3f scratchMomentum = new Vector3f();
    /** Scratch: the other side of a difference (m/s or kg·m/s). */
    private final Vector3f scratchOther = new Vector3f();

    /** Create the demo; read its clips (a bad clip file is refused, naming line and value). */
    public ClipResponseDemo() {
        super("Clip vs physics");
        // The slide is about energy: presenting shows the ledger's bars.
        getEnergyPart().showOnSlide();
        for (int i = 0; i < CLIP_NAMES.length; ++i) {
            clips[i] = ClipReader.readResource("clips/" + CLIP_NAMES[i] + ".clip");
            for (int b = 0; b < TRACKS.length; ++b) {
                tracks[i][b] = clips[i].indexOf(TRACKS[b]);
                if (tracks[i][b] < 0) {
                    throw new IllegalArgumentException("clip " + clips[i].getName()
                            + " has no track '" + TRACKS[b] + "' (it needs rocket and target)");
                }
            }
        }
    }

    /**
     * Fire a shot in both lanes (what F does, for tests and scripts): set the speed and the
     * angle, then launch both rockets again, the targets back on their ledges.
     *
     * @param newSpeed the rocket's speed (in m/s, 4 to 40)
     * @param newAngleDegrees its climb angle (in degrees, 0 to 30)
     */
    public void fire(float newSpeed, float newAngleDegrees) {
        getParameters().set("speed", newSpeed);
        getParameters().set("angle", newAngleDegrees);
        restart();
    }

    /**
     * Access a lane's body.
     *
     * @param lane {@link #PHYSICS_LANE} or {@link #CLIP_LANE}
     * @param which {@link #ROCKET} or {@link #TARGET}
     * @return the live body (not null)
     */
    Body body(int lane, int which) {
        return spheres[lane][which].getBody();
    }

    /** @return e of the physics lane's impulse (0 to 1), the response its rule applies */
    float getRestitution() {
        return impulse.getRestitution();
    }

    /**
     * Access the clip the clip lane plays.
     *
     * @return the clip (not null)
     */
    Clip getClip() {
        return clips[clipIndex];
    }

    /**
     * Test whether a lane's impact has happened.
     *
     * @param lane the lane
     * @return true once its rocket hit its target
     */
    public boolean hasHit(int lane) {
        return lane == PHYSICS_LANE ? physicsHit : clipHit;
    }

    /**
     * Copy a body's velocity right after the impact into storeResult: the physics lane's as
     * the impulse left it, the clip lane's as its clip starts (the first key segment's slope).
     *
     * @param lane the lane
     * @param which the body
     * @param storeResult storage (in m/s, not null, modified)
     * @return storeResult
     */
    Vector3f copyVelocityAfter(int lane, int which, Vector3f storeResult) {
        if (lane == PHYSICS_LANE) {
            return storeResult.set(physicsAfter[which]);
        }
        return clips[clipIndex].copyStartVelocity(tracks[clipIndex][which], storeResult);
    }

    /**
     * Copy where a clip-lane body was at the contact into storeResult.
     *
     * @param which the body
     * @param storeResult storage (in metres, not null, modified)
     * @return storeResult
     */
    Vector3f copyClipOrigin(int which, Vector3f storeResult) {
        return storeResult.set(clipOrigins[which]);
    }

    /**
     * Return the clip lane's contact time.
     *
     * @return the time (in seconds of the world; 0 before the impact)
     */
    double getClipStartSeconds() {
        return clipStartSeconds;
    }

    /**
     * Copy the momentum of a lane's two bodies right after the impact into storeResult.
     *
     * @param lane the lane
     * @param storeResult storage (in kg·m/s, not null, modified)
     * @return storeResult
     */
    Vector3f momentumAfter(int lane, Vector3f storeResult) {
        copyVelocityAfter(lane, ROCKET, scratchVelocity).multLocal(rocketKg);
        copyVelocityAfter(lane, TARGET, storeResult).multLocal(targetKg);
        return storeResult.addLocal(scratchVelocity);
    }

    /**
     * Return the kinetic energy of a lane's two bodies right after the impact.
     *
     * @param lane the lane
     * @return {@code ½·m_r·v_r² + ½·m_t·v_t²} (in J)
     */
    public float energyAfter(int lane) {
        float rocket = copyVelocityAfter(lane, ROCKET, scratchVelocity).lengthSquared();
        float target = copyVelocityAfter(lane, TARGET, scratchVelocity).lengthSquared();
        return 0.5f * rocketKg * rocket + 0.5f * targetKg * target;
    }

    /**
     * Return the clip's velocity error of one body: {@code |v_clip − v_physics|}.
     *
     * @param which the body
     * @return the error (in m/s)
     */
    float velocityError(int which) {
        copyVelocityAfter(CLIP_LANE, which, scratchVelocity);
        return scratchVelocity.distance(copyVelocityAfter(PHYSICS_LANE, which, scratchOther));
    }

    /**
     * Return the clip's momentum error: {@code |p_clip − p_physics|}.
     *
     * @return the error (in kg·m/s)
     */
    float momentumError() {
        momentumAfter(CLIP_LANE, scratchMomentum);
        return scratchMomentum.distance(momentumAfter(PHYSICS_LANE, scratchOther));
    }

    /**
     * Return the energy the clip creates (&gt;0) or loses (&lt;0) against what the impact
     * with e implies: {@code KE_clip − KE_physics}.
     *
     * @return the difference (in J)
     */
    float energyError() {
        return energyAfter(CLIP_LANE) - energyAfter(PHYSICS_LANE);
    }

    /**
     * Count the shots recorded.
     *
     * @return the count (&ge;0)
     */
    int countShots() {
        return shotCount;
    }

    @Override
    protected void createScene() {
        String[][] labels = {{"rocket (physics)", "target (physics)"},
            {"rocket (clip)", "target (clip)"}};
        ColorRGBA[] colors = {ROCKET_COLOR, TARGET_COLOR};
        int[] groups = {PHYSICS_GROUP, CLIP_GROUP};
        // The physics lane's bodies also meet the ground (the default group).
        int[] masks = {PHYSICS_GROUP | Body.DEFAULT_GROUP, CLIP_GROUP};
        for (int lane = 0; lane < 2; ++lane) {
            for (int body = 0; body < 2; ++body) {
                // Each body its own g: 0 while the motor or the ledge holds it, g once free.
                gravities[lane][body] = new Gravity(NO_GRAVITY);
                spheres[lane][body] = addParticle(labels[lane][body], colors[body],
                        Vector3f.ZERO, Vector3f.ZERO, body == ROCKET ? rocketKg : targetKg,
                        new ParticleIntegrator(gravities[lane][body]));
                Body b = spheres[lane][body].getBody();
                b.setRadius(RADIUS);
                b.setCollisionFilter(groups[lane], masks[lane]);
            }
        }
        applyLaunch();
        // One sphere rule for both pairs (a pair is one contact a step, whatever the rule):
        // its response hands each lane's contact to that lane's response.
        pairRule = new SphereRule(new LaneResponse(), Detection.SWEPT);
        getWorld().addRule(pairRule);
        getWorld().addRule(SurfaceRule.ground(new ImpulseResponse(GROUND_E, 0f, true),
                Detection.SWEPT).limitTo(body(PHYSICS_LANE, ROCKET))
                .limitTo(body(PHYSICS_LANE, TARGET)));
        getWorld().addContactListener(new Epilogue());
        addStateRecord(new Record());
        // Each ledge's name beside its foot, on the far side from the rocket: its top is
        // where the target rests and its trail starts; the bodies land away from the post.
        addMarkerNamedAtFoot("ledge", PHYSICS_TARGET_X, LEDGE_HEIGHT, ColorRGBA.Gray);
        addMarkerNamedAtFoot("ledge", CLIP_TARGET_X, LEDGE_HEIGHT, ColorRGBA.Gray);
        hideArrowsAtStart();
        setView(-9f, 9f, LEDGE_HEIGHT + 2.5f, 1f, 2, RADIUS);
    }

    @Override
    protected void declareParameters() {
        DemoParameter.Applies next = DemoParameter.Applies.NEXT_LAUNCH;
        declareParameter(new DemoParameter("speed", "rocket speed", "m/s", MIN_SPEED, MAX_SPEED,
                1f, START_SPEED, 0, next, value -> {
                    speed = value;
                    applyLaunch();
                }));
        declareParameter(new DemoParameter("angle", "rocket climb angle", "deg", 0f, MAX_ANGLE,
                5f, 0f, 0, next, value -> {
                    angleDegrees = value;
                    applyLaunch();
                }));
        declareParameter(new DemoParameter("e", "restitution (physics lane)", "", 0f, 1f, 0.1f,
                START_E, 1, next, impulse::setRestitution));
        declareParameter(new DemoParameter("m_rocket", "rocket mass", "kg", 0.5f, 5f, 0.5f,
                START_ROCKET_KG, 1, next, value -> {
                    rocketKg = value;
                    applyLaunch();
                }));
        declareParameter(new DemoParameter("m_target", "target mass", "kg", 0.5f, 10f, 0.5f,
                START_TARGET_KG, 1, next, value -> {
                    targetKg = value;
                    applyLaunch();
                }));
        declareParameter(DemoParameter.choice("clip", "clip (clip lane)", CLIP_NAMES, 0, next,
                value -> clipIndex = Math.round(value)));
    }

    @Override
    protected void declareKeys() {
        bindKey(KeyInput.KEY_UP, "Up", "rocket speed + 4 m/s (up to 40), fire", () -> aim(
                SPEED_STEP, 0f));
        bindKey(KeyInput.KEY_DOWN, "Down", "rocket speed - 4 m/s (down to 4), fire",
                () -> aim(-SPEED_STEP, 0f));
        bindKey(KeyInput.KEY_RIGHT, "Right", "climb angle + 10 deg (up to 30), fire",
                () -> aim(0f, ANGLE_STEP));
        bindKey(KeyInput.KEY_LEFT, "Left", "climb angle - 10 deg (down to 0), fire",
                () -> aim(0f, -ANGLE_STEP));
        bindKey(KeyInput.KEY_P, "P", "the other clip in the clip lane (topple <-> rebound), fire",
                this::nextClip);
        KeyBinding fire = bindKey(KeyInput.KEY_F, "F", "fire the same shot again in both lanes",
                this::restart);
        getKeys().setFireKey(fire);
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        // The shot is the same until the next launch: its line is written once, here.
        text.append("shot: v = ");
        TextFormat.appendFixed(text, speed, 1).append(" m/s at ");
        TextFormat.appendFixed(text, angleDegrees, 0).append(" deg, m_r = ");
        TextFormat.appendFixed(text, rocketKg, 1).append(" kg, m_t = ");
        TextFormat.appendFixed(text, targetKg, 1).append(" kg, e = ");
        TextFormat.appendFixed(text, impulse.getRestitution(), 1)
                .append(";   before: p = ");
        appendXy(text, momentumBefore(new Vector3f())).append(" kg m/s, KE = ");
        TextFormat.appendFixed(text, 0.5f * rocketKg * speed * speed, DIGITS).append(" J\n");
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        if (!clipHit) {
            return;
        }
        // The clip moves its kinematic bodies: V such that P += h·V ends on the key offset.
        Clip clip = clips[clipIndex];
        double clipSeconds = getWorld().getTimeSeconds() + stepSeconds - clipStartSeconds;
        for (int b = 0; b < 2; ++b) {
            Body body = body(CLIP_LANE, b);
            clip.copyOffset(tracks[clipIndex][b], clipSeconds, scratchPosition)
                    .addLocal(clipOrigins[b]);
            body.getVelocity().set(scratchPosition).subtractLocal(body.getPosition())
                    .divideLocal(stepSeconds);
        }
    }

    @Override
    protected void afterStep(float stepSeconds) {
        if (physicsHit && clipHit && !shotRecorded) {
            shotRecorded = true;
            int at = (shotCount % SHOT_ROWS) * SHOT_FIELDS;
            shots[at] = speed;
            shots[at + 1] = angleDegrees;
            shots[at + 2] = energyAfter(PHYSICS_LANE);
            shots[at + 3] = energyAfter(CLIP_LANE);
            ++shotCount;
        }
    }

    @Override
    protected void onRestart() {
        for (int lane = 0; lane < 2; ++lane) {
            for (int b = 0; b < 2; ++b) {
                body(lane, b).setKinematic(false);
            }
        }
        physicsHit = false;
        clipHit = false;
        shotRecorded = false;
        clipStartSeconds = 0.0;
        applyGravity();
        refreshEquations();
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        appendLane(text, PHYSICS_LANE);
        appendLane(text, CLIP_LANE);
        if (physicsHit && clipHit) {
            // The clip's error against what the impact implies, on the clip lane's line.
            text.append(";  error |dv_r| ");
            TextFormat.appendFixed(text, velocityError(ROCKET), DIGITS).append(", |dv_t| ");
            TextFormat.appendFixed(text, velocityError(TARGET), DIGITS).append(", |dp| ");
            TextFormat.appendFixed(text, momentumError(), DIGITS).append(", KE ");
            float energy = energyError();
            text.append(energy >= 0f ? "created +" : "lost ");
            TextFormat.appendFixed(text, Math.abs(energy), DIGITS);
        }
        text.append('\n');
        // The latest shots on one line, the oldest first.
        text.append("shots, KE after (J, physics | clip):");
        if (shotCount == 0) {
            text.append(" none yet (Up/Down: another speed, Left/Right: another angle)");
        }
        for (int i = Math.max(0, shotCount - SHOT_ROWS); i < shotCount; ++i) {
            int at = (i % SHOT_ROWS) * SHOT_FIELDS;
            text.append(i == Math.max(0, shotCount - SHOT_ROWS) ? "  " : ";  ");
            TextFormat.appendFixed(text, shots[at], 0).append(" m/s ");
            TextFormat.appendFixed(text, shots[at + 1], 0).append(" deg: ");
            TextFormat.appendFixed(text, shots[at + 2], 1).append(" | ");
            TextFormat.appendFixed(text, shots[at + 3], 1);
        }
        text.append('\n');
    }

    /** The slide: the impulse law against the clip; the energy each lane leaves. */
    @Override
    protected void writePresentation(Presentation slide) {
        TextFormat.appendFixed(slide.formula().append("physics: j = (1+e) v_n / (1/m_r + 1/m_t),"
                + "  e = "), impulse.getRestitution(), 1);
        slide.formula().append("clip: P = P_contact + key(t - t_contact), whatever the impact");
        StringBuilder readout = slide.readout();
        if (!physicsHit || !clipHit) {
            TextFormat.appendFixed(readout.append("before the impact: KE = "),
                    0.5f * rocketKg * speed * speed, DIGITS).append(" J");
            return;
        }
        readout.append("KE after: physics ");
        TextFormat.appendFixed(readout, energyAfter(PHYSICS_LANE), DIGITS).append(" J,  clip ");
        TextFormat.appendFixed(readout, energyAfter(CLIP_LANE), DIGITS).append(" J");
    }

    /**
     * One lane's line, without its newline: each body's velocity after the impact (m/s), the
     * momentum (kg·m/s), the energy (J).
     */
    private void appendLane(StringBuilder text, int lane) {
        if (lane == PHYSICS_LANE) {
            text.append("physics (j = (1+e) v_n/(1/m_r+1/m_t)): ");
        } else {
            text.append("clip (").append(clips[clipIndex].getName()).append("): ");
        }
        if (!hasHit(lane)) {
            text.append("- (no impact yet)");
        } else {
            text.append("v_r ");
            appendXy(text, copyVelocityAfter(lane, ROCKET, scratchVelocity)).append(", v_t ");
            appendXy(text, copyVelocityAfter(lane, TARGET, scratchVelocity)).append(", p ");
            appendXy(text, momentumAfter(lane, scratchMomentum)).append(", KE ");
            TextFormat.appendFixed(text, energyAfter(lane), DIGITS);
        }
        if (lane == PHYSICS_LANE) {
            text.append("   (after; m/s, kg m/s, J)\n");
        }
    }

    private static StringBuilder appendXy(StringBuilder text, Vector3f v) {
        text.append('(');
        TextFormat.appendFixed(text, v.x, DIGITS).append(", ");
        return TextFormat.appendFixed(text, v.y, DIGITS).append(')');
    }

    private Vector3f momentumBefore(Vector3f storeResult) {
        return direction(storeResult).multLocal(rocketKg * speed);
    }

    /** The rocket's flight direction: {@code (cos θ, sin θ, 0)}. */
    private Vector3f direction(Vector3f storeResult) {
        float theta = angleDegrees * FastMath.DEG_TO_RAD;
        return storeResult.set((float) Math.cos(theta), (float) Math.sin(theta), 0f);
    }

    /**
     * Put the shot into both lanes' launch states: the target at rest on its ledge, the rocket
     * the run-up before it along the flight, at the speed; and the masses.
     */
    private void applyLaunch() {
        if (spheres[0][0] == null) {
            return;
        }
        float[] targetX = {PHYSICS_TARGET_X, CLIP_TARGET_X};
        Vector3f d = direction(new Vector3f());
        for (int lane = 0; lane < 2; ++lane) {
            Vector3f target = new Vector3f(targetX[lane], LEDGE_HEIGHT + RADIUS, 0f);
            spheres[lane][TARGET].setLaunch(target, Vector3f.ZERO);
            spheres[lane][ROCKET].setLaunch(target.subtract(d.mult(RUN_UP_METRES)),
                    d.mult(speed));
            spheres[lane][ROCKET].getParticle().setMass(rocketKg);
            spheres[lane][TARGET].getParticle().setMass(targetKg);
        }
    }

    /** Each body's g: the physics lane's bodies fall once hit; the clip's never. */
    private void applyGravity() {
        for (int b = 0; b < 2; ++b) {
            gravities[PHYSICS_LANE][b].setAcceleration(physicsHit ? DOWN_G : NO_GRAVITY);
            gravities[CLIP_LANE][b].setAcceleration(NO_GRAVITY);
        }
    }

    private void aim(float speedChange, float angleChange) {
        float newSpeed = Math.max(MIN_SPEED, Math.min(MAX_SPEED, speed + speedChange));
        float newAngle = Math.max(0f, Math.min(MAX_ANGLE, angleDegrees + angleChange));
        fire(newSpeed, newAngle);
    }

    private void nextClip() {
        getParameters().set("clip", (clipIndex + 1) % CLIP_NAMES.length);
        restart();
    }

    private boolean inClipLane(Contact contact) {
        return contact.getBodyA().getGroup() == CLIP_GROUP;
    }

    /** The collision phase of the rocket-target pairs: impulse or clip, by lane. */
    private final class LaneResponse implements ContactResponse {
        @Override
        public void resolve(Contact contact, float stepSeconds) {
            (inClipLane(contact) ? clipStart : impulse).resolve(contact, stepSeconds);
        }

        @Override
        public String describe() {
            return "physics lane " + impulse.describe() + "; clip lane " + clipStart.describe();
        }
    }

    /** The epilogue of the first rocket-target contact of each lane. */
    private final class Epilogue implements ContactListener {
        @Override
        public void resolved(Contact contact, World world) {
            if (contact.getRule() != pairRule) {
                return;
            }
            if (inClipLane(contact)) {
                if (!clipHit) {
                    clipHit = true;
                    clipStartSeconds = contact.getTimeSeconds();
                    for (int b = 0; b < 2; ++b) {
                        clipOrigins[b].set(body(CLIP_LANE, b).getPosition());
                    }
                }
            } else if (!physicsHit) {
                physicsHit = true;
                for (int b = 0; b < 2; ++b) {
                    physicsAfter[b].set(body(PHYSICS_LANE, b).getVelocity());
                }
                // The motor is out and the target off its ledge: both fall from now on.
                applyGravity();
            }
        }
    }

    /** The demo's own state a step changes: the impacts, the clip's start, the shots. */
    private final class Record implements StateRecord {
        @Override
        public int countStateInts() {
            return 3 + 2 + 4 * 3 + shots.length + 1;
        }

        @Override
        public void writeState(StateSlab slab) {
            slab.putBoolean(physicsHit);
            slab.putBoolean(clipHit);
            slab.putBoolean(shotRecorded);
            slab.putDouble(clipStartSeconds);
            for (int b = 0; b < 2; ++b) {
                slab.putVector(clipOrigins[b]);
                slab.putVector(physicsAfter[b]);
            }
            for (int i = 0; i < shots.length; ++i) {
                slab.putFloat(shots[i]);
            }
            slab.putInt(shotCount);
        }

        @Override
        public void readState(StateSlab slab) {
            physicsHit = slab.getBoolean();
            clipHit = slab.getBoolean();
            shotRecorded = slab.getBoolean();
            clipStartSeconds = slab.getDouble();
            for (int b = 0; b < 2; ++b) {
                slab.getVector(clipOrigins[b]);
                slab.getVector(physicsAfter[b]);
            }
            for (int i = 0; i < shots.length; ++i) {
                shots[i] = slab.getFloat();
            }
            shotCount = slab.getInt();
            applyGravity();
        }
    }
}

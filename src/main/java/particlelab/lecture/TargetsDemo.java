package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;
import particlelab.collision.Plane;
import particlelab.collision.ThinWall;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.BodyViews;
import particlelab.view.CollisionSounds;
import particlelab.view.SilentSoundPlayer;
import particlelab.view.SoundPlayer;
import particlelab.view.TextFormat;
import particlelab.view.WallView;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SphereRule;
import particlelab.world.SurfaceRule;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.World;

/**
 * Demo 10, targets: the lecture's three phases of a collision response, each visible. A gun
 * on a platform fires a shot (F) at three targets; the HUD shows what each phase decided for
 * the latest contact. Builds upon bounce (the ground), collisions (spheres) and tunnelling
 * (the swept test, so no shot passes through a target).
 * <ol>
 * <li><b>Prologue</b> (should the contact be ignored? effects at the moment of impact): the
 * shot touches the gun's own platform at every step as it leaves, and the prologue ignores it
 * (friendly); the pane between gun and targets is a ghost (G toggles it solid), so its
 * contacts are ignored too. An accepted contact flashes at the contact point.</li>
 * <li><b>Collision</b> (resolution): an impulse with restitution bounces the shot off the
 * ground, the far wall, the solid pane and the targets.</li>
 * <li><b>Epilogue</b> (propagate): a hit target is destroyed (its body, sphere and every
 * reference to it go), six fragments are spawned that fall and bounce under their own
 * gravity, the score goes up and the destroy sound plays. The world queues the destruction
 * until the step's contacts are all handled, so nothing is corrupted mid-step.</li>
 * </ol>
 * What to watch for: the ignored contacts never reach resolution or epilogue; fragments
 * leave after {@link #FRAGMENT_SECONDS} s; when every target is gone they come back.
 */
public final class TargetsDemo extends DemoState {

    /** The shot's radius (in metres). */
    public static final float SHOT_RADIUS = 0.15f;
    /** The targets' radius (in metres). */
    public static final float TARGET_RADIUS = 0.6f;
    /** The fragments' radius (in metres). */
    public static final float FRAGMENT_RADIUS = 0.12f;
    /** Fragments spawned by one destroyed target. */
    public static final int FRAGMENTS_PER_TARGET = 6;
    /** How long a fragment lives (in seconds). */
    public static final float FRAGMENT_SECONDS = 2.5f;
    /** How long a flash shows (in seconds). */
    public static final float FLASH_SECONDS = 0.15f;
    /** The shot's launch speed (in m/s). */
    public static final float SHOT_SPEED = 18f;
    /** The restitution of every contact. */
    public static final float RESTITUTION = 0.6f;
    private static final float[] TARGET_X = {14f, 20f, 26f};
    private static final float[] TARGET_Y = {3f, 5.5f, 2f};
    /** The number of targets. */
    public static final int TARGETS = TARGET_X.length;
    private static final int MAX_FRAGMENTS = 4 * FRAGMENTS_PER_TARGET;
    /** The gun's height: the shot leaves from {@code (0, GUN_Y)} (in metres). */
    public static final float GUN_Y = 1.2f;
    private static final float PLATFORM_RADIUS = 0.5f;
    /** The pane's centre x (in metres). */
    public static final float PANE_X = 8f;
    /** The pane's thickness (in metres). */
    public static final float PANE_THICKNESS = 0.1f;
    /** The far wall's x (in metres). */
    public static final float WALL_X = 30f;
    /** The near wall's x (in metres). */
    public static final float X_MIN = -2f;
    /** The ceiling's height (in metres). */
    public static final float Y_MAX = 8f;
    private static final float ANGLE_STEP_DEGREES = 2.5f;
    /** The lowest aim the keys give (in degrees above the horizontal). */
    private static final float MIN_AIM_DEGREES = 5f;
    /** The highest aim the keys give (in degrees above the horizontal). */
    private static final float MAX_AIM_DEGREES = 85f;
    private static final int FRAGMENT_GROUP = 4;
    private static final ColorRGBA TARGET_COLOR = new ColorRGBA(1f, 0.3f, 0.3f, 1f);
    private static final ColorRGBA FRAGMENT_COLOR = new ColorRGBA(1f, 0.7f, 0.3f, 1f);
    private static final ColorRGBA PANE_SOLID = new ColorRGBA(0.7f, 0.8f, 1f, 0.9f);
    private static final ColorRGBA PANE_GHOST = new ColorRGBA(0.7f, 0.8f, 1f, 0.25f);
    /** Every text the three phases' HUD lines show, so a state record names one by place. */
    private static final String[] STEP_TEXTS = {"none yet",
        "ignored: friendly (the gun's own platform)", "ignored: the pane is a ghost (G)",
        "accepted: the shot hits target", "accepted: the shot hits a surface",
        "impulse off the solid pane", "impulse off the ground, a wall or the ceiling",
        "impulse off the target", "destroyed target"};

    private final ParticleIntegrator still = new ParticleIntegrator();
    private final ParticleIntegrator falling = new ParticleIntegrator(new Gravity());
    private final ImpulseResponse bounce = new ImpulseResponse(RESTITUTION);
    private final Body[] targets = new Body[TARGETS];
    private final Body[] fragments = new Body[MAX_FRAGMENTS];
    private final double[] fragmentBorn = new double[MAX_FRAGMENTS];
    private final Vector3f scratch = new Vector3f();
    private final Vector3f aim = new Vector3f();
    private final Vector3f flashPoint = new Vector3f();
    private SurfaceRule paneRule;
    private Body platform;
    private DemoParticle shot;
    private BodyViews views;
    private CollisionSounds sounds;
    private Geometry paneView;
    private Geometry flash;
    private boolean paneGhost = true;
    private float angleDegrees = 35f;
    private int score;
    private long destroyed;
    private long spawned;
    private double flashUntil = -1.0;
    private String prologue = "none yet";
    private int prologueTarget = -1;
    private String resolution = "none yet";
    private float resolutionImpulse;
    private String epilogue = "none yet";
    private int epilogueTarget = -1;
    /** What the shot's first resolved contact since its launch was, or -1 (not yet). */
    private int firstContact = -1;

    /** Create the demo. */
    public TargetsDemo() {
        super("Targets");
    }

    @Override
    protected void createScene() {
        shot = addParticle("shot", ColorRGBA.Orange, new Vector3f(0f, GUN_Y, 0f),
                launchVelocity(new Vector3f()), 1f, falling);
        shot.getBody().setRadius(SHOT_RADIUS);
        World world = getWorld();
        platform = world.addBody(still, new Vector3f(0f, GUN_Y - PLATFORM_RADIUS, 0f),
                Vector3f.ZERO, 1f, PLATFORM_RADIUS);
        platform.setKinematic(true);
        world.addRule(new SphereRule(bounce, Detection.SWEPT));
        world.addRule(SurfaceRule.ground(bounce, Detection.SWEPT));
        world.addRule(new SurfaceRule("far wall", new Plane(new Vector3f(-1f, 0f, 0f), -WALL_X),
                bounce, Detection.SWEPT));
        world.addRule(new SurfaceRule("near wall", new Plane(Vector3f.UNIT_X, X_MIN), bounce,
                Detection.SWEPT));
        world.addRule(new SurfaceRule("ceiling", new Plane(new Vector3f(0f, -1f, 0f), -Y_MAX),
                bounce, Detection.SWEPT));
        paneRule = new SurfaceRule("pane", new ThinWall(Vector3f.UNIT_X, PANE_X, PANE_THICKNESS),
                bounce,
                Detection.SWEPT);
        world.addRule(paneRule);
        world.addContactListener(new ContactListener() {
            @Override
            public boolean accept(Contact contact, World stepping) {
                return prologue(contact);
            }

            @Override
            public void resolved(Contact contact, World stepping) {
                epilogue(contact, stepping);
            }
        });
        // Silent until a window's buildViews gives the sounds a player.
        sounds = new CollisionSounds(new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE));
        sounds.attach(world);
        spawnTargets();
        addStateRecord(targetState());
        setView(X_MIN, WALL_X + 1f, Y_MAX, 2f, 2, SHOT_RADIUS);
    }

    /**
     * The bodies beyond the particles (the platform, the targets, later the fragments), the
     * pane, the far wall, the flash, and the impacts' sounds.
     */
    @Override
    protected void buildViews(Application app) {
        World world = getWorld();
        sounds.detach(world);
        sounds = new CollisionSounds(SoundPlayer.forApplication(app));
        sounds.attach(world);
        views = new BodyViews(app.getAssetManager(), TARGETS + MAX_FRAGMENTS + 1);
        world.addBodyListener(views);
        getSceneNode().attachChild(views.getNode());
        views.show(platform, ColorRGBA.Gray);
        // The particles' labels keep off these spheres ("shot" lay over the platform).
        getWindow().setLabelObstacles(views);
        for (int i = 0; i < TARGETS; ++i) {
            if (targets[i] != null) {
                views.show(targets[i], TARGET_COLOR);
            }
        }
        paneView = WallView.create(app.getAssetManager(), "pane",
                PANE_X - 0.05f, 0f, PANE_X + 0.05f, Y_MAX, PANE_GHOST);
        getSceneNode().attachChild(paneView);
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "far", WALL_X, 0f, WALL_X + 0.1f, Y_MAX, ColorRGBA.Gray));
        flash = WallView.create(app.getAssetManager(), "flash", -0.3f, -0.3f,
                0.3f, 0.3f, ColorRGBA.Yellow);
        flash.setCullHint(Spatial.CullHint.Always);
        getSceneNode().attachChild(flash);
    }

    @Override
    protected void declareParameters() {
        // The aim, as the Up and Down keys change it; the pane, as G switches it.
        declareParameter(new DemoParameter("angle", "aim above the horizontal", "deg",
                MIN_AIM_DEGREES, MAX_AIM_DEGREES, ANGLE_STEP_DEGREES, angleDegrees, 1,
                DemoParameter.Applies.LIVE, value -> {
                    if (value != angleDegrees) {
                        angleDegrees = value;
                        fire();
                    }
                }));
        String[] panes = {"ghost", "solid"};
        declareParameter(DemoParameter.choice("pane", "the pane", panes, paneGhost ? 0 : 1,
                DemoParameter.Applies.LIVE, value -> {
                    if ((Math.round(value) == 0) != paneGhost) {
                        togglePane();
                    }
                }));
    }

    @Override
    protected void declareKeys() {
        bindKey(KeyInput.KEY_F, "F", "fire the shot again", this::fire);
        StringBuilder up = new StringBuilder("aim ");
        TextFormat.appendFixed(up, ANGLE_STEP_DEGREES, 1).append(" deg higher");
        bindKey(KeyInput.KEY_UP, "Up", up.toString(), () -> aimBy(ANGLE_STEP_DEGREES));
        StringBuilder down = new StringBuilder("aim ");
        TextFormat.appendFixed(down, ANGLE_STEP_DEGREES, 1).append(" deg lower");
        bindKey(KeyInput.KEY_DOWN, "Down", down.toString(), () -> aimBy(-ANGLE_STEP_DEGREES));
        bindKey(KeyInput.KEY_G, "G", "the pane: ghost (ignored by the prologue) <-> solid",
                this::togglePane);
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("prologue: ignore friendly / ghost, flash;  collision: impulse, e = ");
        TextFormat.appendFixed(text, RESTITUTION, 1).append(";  epilogue: destroy, ")
                .append(FRAGMENTS_PER_TARGET).append(" fragments, score, sound\n");
    }

    @Override
    protected void afterFrame() {
        World world = getWorld();
        double now = world.getTimeSeconds();
        if (world.getImpacts().size() > 0 && flash != null) {
            flash.setLocalTranslation(flashPoint);
            flash.setCullHint(Spatial.CullHint.Inherit);
            flashUntil = now + FLASH_SECONDS;
        }
        if (flash != null && now > flashUntil) {
            // Hidden, not detached: attaching copies the scene node's child list.
            flash.setCullHint(Spatial.CullHint.Always);
        }
        sounds.playFrame(world);
        for (int i = 0; i < MAX_FRAGMENTS; ++i) {
            if (fragments[i] != null && now - fragmentBorn[i] > FRAGMENT_SECONDS) {
                world.destroy(fragments[i]);
                fragments[i] = null;
            }
        }
        if (countTargetsAlive() == 0 && countFragments() == 0) {
            spawnTargets();
        }
        if (views != null) {
            views.update(getWindow().getDrawBlend());
        }
    }

    @Override
    protected void onRestart() {
        World world = getWorld();
        for (int i = 0; i < MAX_FRAGMENTS; ++i) {
            if (fragments[i] != null) {
                world.destroy(fragments[i]);
                fragments[i] = null;
            }
        }
        spawnTargets();
        score = 0;
        flashUntil = -1.0;
        prologue = "none yet";
        prologueTarget = -1;
        resolution = "none yet";
        resolutionImpulse = 0f;
        epilogue = "none yet";
        epilogueTarget = -1;
        firstContact = -1;
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        text.append("aim ");
        TextFormat.appendFixed(text, angleDegrees, 1).append(" deg at ");
        TextFormat.appendFixed(text, SHOT_SPEED, 0).append(" m/s   pane: ")
                .append(paneGhost ? "ghost" : "solid").append("   score ").append(score)
                .append("   targets left ").append(countTargetsAlive()).append("   fragments ")
                .append(countFragments()).append('\n');
        text.append("1 prologue:   ").append(prologue);
        appendTarget(text, prologueTarget).append('\n');
        text.append("2 collision:  ").append(resolution);
        if (resolutionImpulse != 0f) {
            text.append(", j = ");
            TextFormat.appendFixed(text, resolutionImpulse, 2).append(" N s");
        }
        text.append('\n');
        text.append("3 epilogue:   ").append(epilogue);
        appendTarget(text, epilogueTarget);
        if (epilogueTarget >= 0) {
            text.append(": spawned ").append(FRAGMENTS_PER_TARGET)
                    .append(" fragments, score + 1, destroy sound");
        }
        text.append('\n');
        sounds.getPlayer().getLog().appendLatest(text).append('\n');
    }

    /**
     * Fire the shot straight at a live target, aimed for the continuous parabola (the
     * stepped one drops a little more, far less than the target's radius).
     *
     * @param index the target (0 to 2)
     * @return true if that target is alive and was aimed at
     */
    public boolean fireAt(int index) {
        Body target = targets[index];
        if (target == null) {
            return false;
        }
        scratch.set(target.getPosition()).subtractLocal(0f, GUN_Y, 0f);
        float seconds = scratch.length() / SHOT_SPEED;
        aim.set(scratch).divideLocal(seconds);
        aim.y += 0.5f * Gravity.STANDARD_G * seconds;
        launch(shot, aim);
        firstContact = -1;
        return true;
    }

    /**
     * Fire the shot from the gun at an angle (what the keys do, without their limits).
     *
     * @param degrees the angle above the horizontal (in degrees, -90 to 90; -90 fires
     *     straight down into the gun's own platform)
     */
    public void fireAtAngle(float degrees) {
        if (!(degrees >= -90f && degrees <= 90f)) {
            throw new IllegalArgumentException(
                    "angle must be from -90 to 90 degrees, but was " + degrees);
        }
        angleDegrees = degrees;
        fire();
    }

    /** @return the score: targets destroyed since the start or reset */
    public int getScore() {
        return score;
    }

    /** @return true if the pane lets shots through (a ghost), false if they bounce off it */
    boolean isPaneGhost() {
        return paneGhost;
    }

    /** @return the count of targets destroyed since the demo was created */
    public long countDestroyed() {
        return destroyed;
    }

    /** @return the count of fragments spawned since the demo was created */
    public long countSpawned() {
        return spawned;
    }

    /** @return the count of live targets (0 to 3) */
    public int countTargetsAlive() {
        int count = 0;
        for (int i = 0; i < TARGETS; ++i) {
            if (targets[i] != null) {
                ++count;
            }
        }
        return count;
    }

    /** @return the count of live fragments */
    public int countFragments() {
        int count = 0;
        for (int i = 0; i < MAX_FRAGMENTS; ++i) {
            if (fragments[i] != null) {
                ++count;
            }
        }
        return count;
    }

    /**
     * Access the spheres of the targets, fragments and platform.
     *
     * @return the views (null without an application)
     */
    public BodyViews getBodyViews() {
        return views;
    }

    /** The prologue: friendly and ghost contacts are ignored; accepted ones flash. */
    private boolean prologue(Contact contact) {
        Body a = contact.getBodyA();
        Body b = contact.getBodyB();
        boolean withShot = a == shot.getBody() || b == shot.getBody();
        if (a == platform || b == platform) {
            if (withShot) {
                prologue = "ignored: friendly (the gun's own platform)";
                prologueTarget = -1;
            }
            return false;
        }
        if (contact.getRule() == paneRule && paneGhost) {
            prologue = "ignored: the pane is a ghost (G)";
            prologueTarget = -1;
            return false;
        }
        if (withShot) {
            int target = targetIndex(a == shot.getBody() ? b : a);
            prologue = target >= 0 ? "accepted: the shot hits target" : "accepted: the shot"
                    + " hits a surface";
            prologueTarget = target;
            flashPoint.set(contact.getPoint());
            flashPoint.z = 0.05f;
        }
        return true;
    }

    /** The epilogue: record the resolution; destroy a hit target and spawn its fragments. */
    private void epilogue(Contact contact, World world) {
        Body a = contact.getBodyA();
        Body b = contact.getBodyB();
        boolean withShot = a == shot.getBody() || b == shot.getBody();
        if (!withShot) {
            return;
        }
        resolution = contact.getRule() == paneRule ? "impulse off the solid pane"
                : b == null ? "impulse off the ground, a wall or the ceiling"
                : "impulse off the target";
        resolutionImpulse = contact.getImpulse();
        int index = targetIndex(a == shot.getBody() ? b : a);
        if (firstContact < 0) {
            firstContact = index >= 0 ? index : TARGETS;
        }
        if (index < 0) {
            return;
        }
        Body target = targets[index];
        targets[index] = null;
        spawnFragments(world, target.getPosition());
        world.destroy(target);
        ++score;
        ++destroyed;
        epilogue = "destroyed target";
        epilogueTarget = index;
    }

    private void spawnFragments(World world, Vector3f at) {
        int made = 0;
        for (int i = 0; i < MAX_FRAGMENTS && made < FRAGMENTS_PER_TARGET; ++i) {
            if (fragments[i] != null) {
                continue;
            }
            float angle = FastMath.TWO_PI * made / FRAGMENTS_PER_TARGET;
            scratch.set(3f * FastMath.cos(angle), 3f * FastMath.sin(angle) + 2f, 0f);
            Body fragment = world.addBody(falling, at, scratch, 0.2f, FRAGMENT_RADIUS);
            fragment.setCollisionFilter(FRAGMENT_GROUP, Body.DEFAULT_GROUP);
            fragments[i] = fragment;
            fragmentBorn[i] = world.getTimeSeconds();
            if (views != null) {
                views.show(fragment, FRAGMENT_COLOR);
            }
            ++made;
            ++spawned;
        }
    }

    private void spawnTargets() {
        for (int i = 0; i < TARGETS; ++i) {
            if (targets[i] == null) {
                copyTargetCentre(i, scratch);
                targets[i] = getWorld().addBody(still, scratch, Vector3f.ZERO, 1f,
                        TARGET_RADIUS);
                targets[i].setKinematic(true);
                if (views != null) {
                    views.show(targets[i], TARGET_COLOR);
                }
            }
        }
    }

    private int targetIndex(Body body) {
        for (int i = 0; i < TARGETS; ++i) {
            if (body != null && targets[i] == body) {
                return i;
            }
        }
        return -1;
    }

    private static StringBuilder appendTarget(StringBuilder text, int index) {
        if (index >= 0) {
            text.append(' ').append(index + 1);
        }
        return text;
    }

    private Vector3f launchVelocity(Vector3f storeResult) {
        return launchVelocity(angleDegrees, storeResult);
    }

    /**
     * The shot's launch velocity at an aim, as F fires it.
     *
     * @param degrees the aim above the horizontal (in degrees)
     * @param storeResult storage for the velocity (in m/s, not null, modified)
     * @return storeResult
     */
    public static Vector3f launchVelocity(float degrees, Vector3f storeResult) {
        float radians = degrees * FastMath.DEG_TO_RAD;
        return storeResult.set(SHOT_SPEED * FastMath.cos(radians),
                SHOT_SPEED * FastMath.sin(radians), 0f);
    }

    /**
     * Copy a target's centre, where it stands at the start and after a reset.
     *
     * @param index the target (0 to {@link #TARGETS} − 1)
     * @param storeResult storage for the centre (in metres, not null, modified)
     * @return storeResult
     */
    public static Vector3f copyTargetCentre(int index, Vector3f storeResult) {
        return storeResult.set(TARGET_X[index], TARGET_Y[index], 0f);
    }

    /**
     * Return what the shot's first resolved contact since its launch was: the collision
     * phase's first impulse on it (contacts the prologue ignored do not count).
     *
     * @return the target it hit (0 to {@link #TARGETS} − 1), {@link #TARGETS} for a surface
     *     (the ground, a wall, the ceiling, the solid pane), or -1 while it has hit nothing
     */
    public int getFirstContact() {
        return firstContact;
    }

    private void fire() {
        launch(shot, launchVelocity(aim));
        firstContact = -1;
    }

    private void aimBy(float degrees) {
        angleDegrees = Math.max(MIN_AIM_DEGREES, Math.min(MAX_AIM_DEGREES,
                angleDegrees + degrees));
        getParameters().set("angle", angleDegrees);
        fire();
    }

    private void togglePane() {
        paneGhost = !paneGhost;
        getParameters().set("pane", paneGhost ? 0 : 1);
        if (paneView != null) {
            WallView.setColor(paneView, paneGhost ? PANE_GHOST : PANE_SOLID);
        }
    }

    /**
     * The demo's own state, for the ring: which bodies are the targets and the fragments (by
     * their place in the world's pool), when each fragment was born, the score and counts.
     * Read back after the world's, which already brought the bodies back or took them away:
     * the spheres follow.
     */
    private StateRecord targetState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return TARGETS + 3 * MAX_FRAGMENTS + 1 + 2 + 2 + 2 + 6 + 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                World world = getWorld();
                for (int i = 0; i < TARGETS; ++i) {
                    slab.putInt(targets[i] == null ? -1 : world.getPoolIndex(targets[i]));
                }
                for (int i = 0; i < MAX_FRAGMENTS; ++i) {
                    slab.putInt(fragments[i] == null ? -1 : world.getPoolIndex(fragments[i]));
                    slab.putDouble(fragmentBorn[i]);
                }
                slab.putInt(score);
                slab.putLong(destroyed);
                slab.putLong(spawned);
                slab.putDouble(flashUntil);
                slab.putInt(indexOfText(prologue));
                slab.putInt(prologueTarget);
                slab.putInt(indexOfText(resolution));
                slab.putFloat(resolutionImpulse);
                slab.putInt(indexOfText(epilogue));
                slab.putInt(epilogueTarget);
                slab.putInt(firstContact);
            }

            @Override
            public void readState(StateSlab slab) {
                World world = getWorld();
                for (int i = 0; i < TARGETS; ++i) {
                    targets[i] = pooled(world, slab.getInt(), TARGET_COLOR);
                }
                for (int i = 0; i < MAX_FRAGMENTS; ++i) {
                    fragments[i] = pooled(world, slab.getInt(), FRAGMENT_COLOR);
                    fragmentBorn[i] = slab.getDouble();
                }
                score = slab.getInt();
                destroyed = slab.getLong();
                spawned = slab.getLong();
                flashUntil = slab.getDouble();
                prologue = STEP_TEXTS[slab.getInt()];
                prologueTarget = slab.getInt();
                resolution = STEP_TEXTS[slab.getInt()];
                resolutionImpulse = slab.getFloat();
                epilogue = STEP_TEXTS[slab.getInt()];
                epilogueTarget = slab.getInt();
                firstContact = slab.getInt();
            }
        };
    }

    /** A body of the world's pool by its place, shown in a colour; null for -1. */
    private Body pooled(World world, int index, ColorRGBA color) {
        if (index < 0) {
            return null;
        }
        Body body = world.getPooledBody(index);
        if (views != null && !views.isShown(body)) {
            views.show(body, color);
        }
        return body;
    }

    /** The place of a phase's text in {@link #STEP_TEXTS}. */
    private static int indexOfText(String text) {
        for (int i = 0; i < STEP_TEXTS.length; ++i) {
            if (STEP_TEXTS[i].equals(text)) {
                return i;
            }
        }
        throw new IllegalStateException("a phase text missing from STEP_TEXTS: " + text);
    }

    /** The slide: the three stages of a contact; the score and the last impulse. */
    @Override
    protected void writePresentation(Presentation slide) {
        // A phase a line's end never splits: the impulse and its e on the first line.
        TextFormat.appendFixed(slide.formula()
                .append("1 prologue: ignore or flash   2 collision: impulse j, e = "),
                RESTITUTION, 1);
        slide.formula().append("3 epilogue: destroy, fragments, score");
        StringBuilder readout = slide.readout().append("score ").append(score)
                .append("   last collision ");
        if (resolutionImpulse == 0f) {
            readout.append("none yet");
        } else {
            TextFormat.appendFixed(readout.append("j = "), resolutionImpulse, 2).append(" N s");
        }
    }
}

package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;
import particlelab.reference.CostMeter;
import particlelab.aiming.CheatFrontier;
import particlelab.aiming.Hitscan;
import particlelab.collision.Plane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;
import particlelab.view.WallView;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ScriptedResponse;
import particlelab.world.StepListener;
import particlelab.world.SurfaceRule;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.World;

/**
 * Fast bullets, the lecture's cheat: "if the bullet speed is high, consider it travel along a
 * straight line; adjust its position if necessary". Builds upon HelloAiming (the stepped
 * bullet) and tunnelling (the swept test). The gun on its tower fires level at the centre of a
 * target disc of radius r at distance d, twice: a straight-line ray (hitscan: no travel time,
 * no drop; it always hits the centre) and a projectile stepped by the shared integrator under
 * gravity.
 *
 * <p>The projectile takes {@code t = d/v} to get there and falls {@code ½·g·t²} meanwhile, the
 * drop the straight line ignores; the stepped bullet falls about {@code ½·g·h·t} more. The
 * cheat is right while the drop stays within r, i.e. for {@code d < v·√(2r/g)}: raise the
 * speed (Up) from 35 m/s to 900 m/s and watch the projectile's impact climb onto the disc.
 *
 * <p>"Adjust its position": at 900 m/s one step carries the bullet 15 m, and the disc is
 * thin. The projectile is not looked at only at the ends of its steps (it would be found past
 * the disc, or never on it): the world sweeps each step's straight segment against the disc's
 * plane and puts the bullet at the first point where it crosses, the impact drawn there. The
 * prologue accepts the contact only within r of the centre; a miss flies on to the ground.
 *
 * <p>The frontier (L, {@code --set shot=...}): four ways to shoot at the same disc
 * ({@link CheatFrontier}): the instant ray, a straight-line bullet with travel time (a cyan
 * square along the ray), the drop-corrected straight line (a green square along the aim raised
 * by {@code ½·g·(d/v)²}) and the stepped projectile. The HUD gives each one's miss (where a
 * real bullet aimed as that way says crosses {@code x = d}: the exact parabola for the three
 * straight-line ways, the stepped bullet itself for the fourth), its hit time and its cost
 * per shot, timed in process once when the demo starts (on this machine, rough: a short
 * timing). L shows all four or one alone.
 */
public final class FastBulletsDemo extends DemoState {

    /** The distance from the gun to the target d (in metres). */
    public static final float DISTANCE = 50f;
    /** The target disc's radius r (in metres). */
    public static final float TARGET_RADIUS = 0.5f;
    /** The height of the gun's muzzle and of the target's centre (in metres). */
    public static final float GUN_HEIGHT = 12f;
    /** The speeds the keys step through (in m/s). */
    public static final float[] SPEEDS = {35f, 50f, 70f, 100f, 150f, 200f, 300f, 450f, 600f,
        900f};
    /** A stopped bullet is fired again after this long (in seconds of simulated time). */
    public static final float REFIRE_SECONDS = 1.5f;
    private static final float GRAVITY = Gravity.STANDARD_G;
    /** The drawn disc's thickness, and the impact mark's size (in metres). */
    private static final float DISC_THICKNESS = 0.3f;
    private static final float MARK_SIZE = 0.5f;
    private static final float RAY_WIDTH = 0.08f;
    private static final ColorRGBA TARGET_COLOR = new ColorRGBA(1f, 0.3f, 0.25f, 1f);
    private static final ColorRGBA RAY_COLOR = new ColorRGBA(0.4f, 0.9f, 1f, 0.7f);
    private static final ColorRGBA IMPACT_COLOR = new ColorRGBA(1f, 1f, 0.3f, 1f);
    private static final ColorRGBA STRAIGHT_COLOR = new ColorRGBA(0.3f, 0.85f, 1f, 1f);
    private static final ColorRGBA CORRECTED_COLOR = new ColorRGBA(0.4f, 1f, 0.45f, 1f);
    /** The {@code shot} parameter's names: all four ways, or one by its way's ordinal + 1. */
    private static final String[] SHOT_NAMES = {"all", "ray", "line", "raised",
        "stepped"};
    /** Each way's HUD name, by ordinal. */
    private static final String[] WAY_NAMES = {"ray", "straight line", "drop-corrected",
        "stepped"};
    /** Shots per timed call: enough for microseconds, so the clock's grain does not show. */
    private static final int SHOTS_PER_CALL = 32;
    /** The ways in ordinal order, without the copy {@code values()} makes. */
    private static final CheatFrontier.Way[] WAYS = CheatFrontier.Way.values();

    private final ParticleIntegrator falling = new ParticleIntegrator(new Gravity());
    /** The disc's plane x = d, its front facing the gun. */
    private final Plane discPlane = new Plane(new Vector3f(-1f, 0f, 0f), -DISTANCE);
    private final Vector3f muzzle = new Vector3f(0f, GUN_HEIGHT, 0f);
    private final Vector3f launchVelocity = new Vector3f();
    private final Vector3f impact = new Vector3f();
    private SurfaceRule discRule;
    private DemoParticle bullet;
    private Geometry impactMark;
    private int speedIndex;
    /** The projectile's arrival at the disc's plane, this shot. */
    private boolean reached;
    private boolean hit;
    private double arrivalSeconds = Double.NaN;
    /** The step the projectile flew with (in seconds). */
    private float shotStep = Float.NaN;
    /** The step the world is taking (in seconds). */
    private float worldStep = Float.NaN;
    /** The bullet stopped (on the disc or on the ground) this long ago (in seconds; <0: no). */
    private float stoppedSeconds = -1f;
    /** The shots have rested long enough: fire again at the next step's start. */
    private boolean refireDue;
    private KeyBinding fasterKey;
    private KeyBinding slowerKey;
    private KeyBinding shotKey;
    /** Which ways are shown: 0 for all, else a way's ordinal + 1 (the {@code shot} value). */
    private int shown;
    /** The four ways for the shot's speed and step, made again only when they change. */
    private CheatFrontier frontier;
    /** Each way's measured time per step, or per shot for the ray (ns; NaN: not measured). */
    private final double[] nanosPerStep = {Double.NaN, Double.NaN, Double.NaN, Double.NaN};
    /** The time since this shot was fired (in seconds of simulated time). */
    private float shotSeconds;
    /** The straight-line bullets' squares (null without a window), by way ordinal. */
    private final Geometry[] lineMarks = new Geometry[WAYS.length];

    /** Create the demo. */
    public FastBulletsDemo() {
        super("Fast bullets: the cheat");
    }

    // ----------------------------------------------------------------------- public API ----

    /**
     * Return the projectile's launch speed.
     *
     * @return v (in m/s)
     */
    public float getSpeed() {
        return SPEEDS[speedIndex];
    }

    /**
     * Choose the launch speed among {@link #SPEEDS} and fire again.
     *
     * @param index 0 for the slowest
     */
    public void setSpeedIndex(int index) {
        if (index < 0 || index >= SPEEDS.length) {
            throw new IllegalArgumentException("speed index must be in 0.." + (SPEEDS.length - 1)
                    + ", but was " + index);
        }
        speedIndex = index;
        // The panel and --set show the speed the keys or a caller chose.
        getParameters().set("speed", index);
        fire();
    }

    /**
     * Fire the projectile from the muzzle, level, at the target's centre.
     */
    public void fire() {
        // The bullet exists once the scene does (a caller may fire before any frame).
        getWorld();
        refireDue = false;
        launchVelocity.set(getSpeed(), 0f, 0f);
        bullet.setLaunch(muzzle, launchVelocity);
        launch(bullet, launchVelocity);
        reached = false;
        hit = false;
        arrivalSeconds = Double.NaN;
        stoppedSeconds = -1f;
        shotStep = getClock().getCurrentStepSeconds();
        shotSeconds = 0f;
        if (frontier == null) {
            frontier = new CheatFrontier(GRAVITY, DISTANCE, TARGET_RADIUS, getSpeed(), shotStep);
        } else if (frontier.getSpeed() != getSpeed() || frontier.getStepSeconds() != shotStep) {
            // At the raw tpf h changes from frame to frame: worked out again in place, so a
            // refire allocates nothing.
            frontier.reset(getSpeed(), shotStep);
        }
        if (impactMark != null) {
            impactMark.setCullHint(Spatial.CullHint.Always);
        }
    }

    /**
     * Test whether this shot's projectile reached the disc's plane.
     *
     * @return true once it crossed x = d
     */
    public boolean isReached() {
        return reached;
    }

    /**
     * Test whether this shot's projectile hit the disc: crossed its plane within r of the
     * centre.
     *
     * @return true on a hit
     */
    public boolean isHit() {
        return hit;
    }

    /**
     * Copy where the projectile crossed the disc's plane, inside its step.
     *
     * @param storeResult storage for the point (in metres, not null, modified)
     * @return storeResult (NaN until reached)
     */
    public Vector3f copyImpact(Vector3f storeResult) {
        return storeResult.set(impact);
    }

    /**
     * Return how far below the centre the projectile crossed the disc's plane.
     *
     * @return the drop (in metres; NaN until reached)
     */
    public double getSteppedDrop() {
        return reached ? GUN_HEIGHT - impact.y : Double.NaN;
    }

    /**
     * Return the projectile's flight time to the disc's plane, inside the step.
     *
     * @return the time (in seconds; NaN until reached)
     */
    public double getArrivalSeconds() {
        return arrivalSeconds;
    }

    /**
     * Access the projectile.
     *
     * @return the live particle (not null after creation)
     */
    public DemoParticle getBullet() {
        return bullet;
    }

    /**
     * Access the four ways for the shot in the air (its speed and step).
     *
     * @return the frontier (not null once the demo has started)
     */
    public CheatFrontier getFrontier() {
        return frontier;
    }

    /**
     * Return which ways are shown.
     *
     * @return 0 for all four, else a way's ordinal + 1
     */
    public int getShown() {
        return shown;
    }

    /**
     * Time each way's shot once, in process, with the report's timing loop (its shortest
     * budget: a rough figure for this machine), at the shot's speed and step; kept as time
     * per step (per shot for the ray), so the HUD's cost per shot follows the speed and h.
     * Allocates; called once when the demo starts in an application.
     */
    public void measureCosts() {
        CostMeter meter = new CostMeter(CostMeter.Budget.TINY);
        for (int w = 0; w < WAYS.length; ++w) {
            CheatFrontier.Way way = WAYS[w];
            CheatFrontier timed = frontier;
            CostMeter.Workload shots = units -> {
                double sum = 0.0;
                for (int i = 0; i < units; ++i) {
                    sum += timed.shoot(way);
                }
                return sum;
            };
            // Twice, the first as a longer warm-up for the JIT; the second is kept.
            meter.measure(shots, SHOTS_PER_CALL);
            double nanosPerShot = meter.measure(shots, SHOTS_PER_CALL).nanosPerUnit();
            nanosPerStep[w] = nanosPerShot / Math.max(1, timed.getSteps(way));
        }
    }

    /**
     * Return one way's cost per shot at the shot's speed and step, from {@link #measureCosts}.
     *
     * @param way the way (not null)
     * @return the time (in nanoseconds; NaN until measured)
     */
    public double getCostNanos(CheatFrontier.Way way) {
        return nanosPerStep[way.ordinal()] * Math.max(1, frontier.getSteps(way));
    }

    // ------------------------------------------------------------- framework overrides ----

    @Override
    protected void createScene() {
        bullet = addParticle("projectile", IMPACT_COLOR, muzzle, Vector3f.ZERO, 1f, falling);
        World world = getWorld();
        discRule = new SurfaceRule("target disc", discPlane, ScriptedResponse.stick(),
                Detection.SWEPT);
        world.addRule(discRule);
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
                return prologue(contact);
            }
        });
        addMarker("gun", 0f, GUN_HEIGHT, new ColorRGBA(0.6f, 0.9f, 0.6f, 1f));
        addMarker("target  r = " + TARGET_RADIUS + " m", DISTANCE, GUN_HEIGHT + TARGET_RADIUS,
                TARGET_COLOR);
        impact.set(Float.NaN, Float.NaN, 0f);
        addStateRecord(shotState());
        setView(-3f, DISTANCE + 12f, GUN_HEIGHT + 4f, 2f, 5, 0.3f);
        hideArrowsAtStart();
        fire();
    }

    /** The ray, the target's disc, and the marks of the impact and the lines' crossings. */
    @Override
    protected void buildViews(Application app) {
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "ray", 0f, GUN_HEIGHT - RAY_WIDTH / 2f, DISTANCE, GUN_HEIGHT
                        + RAY_WIDTH / 2f, RAY_COLOR));
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "disc", DISTANCE, GUN_HEIGHT - TARGET_RADIUS, DISTANCE + DISC_THICKNESS,
                GUN_HEIGHT + TARGET_RADIUS, TARGET_COLOR));
        impactMark = WallView.create(app.getAssetManager(), "impact",
                -MARK_SIZE / 2f, -MARK_SIZE / 2f, MARK_SIZE / 2f, MARK_SIZE / 2f,
                IMPACT_COLOR);
        impactMark.setCullHint(Spatial.CullHint.Always);
        getSceneNode().attachChild(impactMark);
        ColorRGBA[] colors = {null, STRAIGHT_COLOR, CORRECTED_COLOR, null};
        for (int w = 0; w < WAYS.length; ++w) {
            if (colors[w] != null) {
                lineMarks[w] = WallView.create(app.getAssetManager(),
                        WAY_NAMES[w], -MARK_SIZE / 2f, -MARK_SIZE / 2f, MARK_SIZE / 2f,
                        MARK_SIZE / 2f, colors[w]);
                getSceneNode().attachChild(lineMarks[w]);
            }
        }
    }

    @Override
    protected void declareParameters() {
        // The speeds the Up and Down keys step through, named by their value in m/s.
        String[] names = new String[SPEEDS.length];
        for (int i = 0; i < SPEEDS.length; ++i) {
            names[i] = Integer.toString(Math.round(SPEEDS[i]));
        }
        declareParameter(DemoParameter.choice("speed", "launch speed, m/s", names, speedIndex,
                DemoParameter.Applies.LIVE, value -> {
                    if (Math.round(value) != speedIndex) {
                        setSpeedIndex(Math.round(value));
                    }
                }));
        declareParameter(DemoParameter.choice("shot", "ways shown", SHOT_NAMES, shown,
                DemoParameter.Applies.LIVE, value -> {
                    shown = Math.round(value);
                    showWays();
                }));
    }

    @Override
    protected void declareKeys() {
        StringBuilder up = new StringBuilder("faster (up to ");
        TextFormat.appendFixed(up, SPEEDS[SPEEDS.length - 1], 0).append(" m/s), fire");
        fasterKey = bindKey(KeyInput.KEY_UP, "Up", up.toString(),
                () -> setSpeedIndex(Math.min(SPEEDS.length - 1, speedIndex + 1)));
        StringBuilder down = new StringBuilder("slower (down to ");
        TextFormat.appendFixed(down, SPEEDS[0], 0).append(" m/s), fire");
        slowerKey = bindKey(KeyInput.KEY_DOWN, "Down", down.toString(),
                () -> setSpeedIndex(Math.max(0, speedIndex - 1)));
        bindKey(KeyInput.KEY_F, "F", "fire again", this::fire);
        shotKey = bindKey(KeyInput.KEY_L, "L",
                "ways shown: all four -> ray -> straight line -> drop-corrected -> stepped",
                () -> getParameters().set("shot", (shown + 1) % SHOT_NAMES.length));
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        measureCosts();
        showWays();
    }

    @Override
    protected void afterFrame() {
        // The straight-line bullets at the shot's time, each along its line, stopped at x = d.
        for (int w = 0; w < WAYS.length; ++w) {
            Geometry mark = lineMarks[w];
            if (mark == null) {
                continue;
            }
            double slope = WAYS[w] == CheatFrontier.Way.CORRECTED
                    ? frontier.getDrop() / DISTANCE : 0.0;
            double along = getSpeed() * (double) shotSeconds / Math.sqrt(1.0 + slope * slope);
            float x = (float) Math.min(DISTANCE, along);
            mark.setLocalTranslation(x, GUN_HEIGHT + (float) (x * slope), 0.02f);
        }
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("ray: no time, no drop;  projectile: V += h·g,  P += h·V, swept against"
                + " x = d = ");
        TextFormat.appendFixed(text, DISTANCE, 0).append(" m\n");
    }

    @Override
    protected void afterStep(float stepSeconds) {
        shotSeconds += stepSeconds;
        if (bullet.isHeld()) {
            if (stoppedSeconds < 0f) {
                stoppedSeconds = 0f;
            } else {
                stoppedSeconds += stepSeconds;
            }
            refireDue = stoppedSeconds >= REFIRE_SECONDS;
        }
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        if (refireDue) {
            refireDue = false;
            fire();
        }
    }

    @Override
    protected void onRestart() {
        fire();
    }

    /**
     * A new h: the cheat frontier and the shot's stepped drop were for the old one, so the
     * gun fires again with the new h (at the start, the h {@code --set} chose).
     */
    @Override
    protected void onStepChanged(float stepSeconds) {
        if (getClock().getMode() == SimulationClock.Mode.FIXED_STEP && stepSeconds != shotStep) {
            fire();
        }
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        // Five lines of its own, the most the HUD holds at 1280x720 with the panel open and
        // the panel's text still legible (ProjectorTextHeadlessTest).
        float v = getSpeed();
        double drop = Hitscan.formulaDrop(GRAVITY, DISTANCE, v);
        text.append("v = ");
        TextFormat.appendFixed(text, v, 0).append(" m/s (").append(fasterKey.getKeyLabel())
                .append('/').append(slowerKey.getKeyLabel()).append("):  ½·g·(d/v)² = ");
        TextFormat.appendFixed(text, drop, 3).append(" m   against the radius r = ");
        TextFormat.appendFixed(text, TARGET_RADIUS, 2).append(" m\nSo the cheat ")
                .append(drop <= TARGET_RADIUS ? "is" : "is NOT")
                .append(" good enough here: it is for d < v·√(2r/g) = ");
        TextFormat.appendFixed(text, Hitscan.cheatDistance(v, TARGET_RADIUS, GRAVITY), 1)
                .append(" m\n");
        writeFrontier(text);
    }

    // ---------------------------------------------------------------- private helpers ----

    /**
     * The frontier: the key and the four ways in two lines, each with its miss, hit time and
     * cost per shot (the way shown alone in brackets); the stepped way, the projectile
     * itself, ends with its verdict and how far below the centre it crossed x = d.
     */
    private void writeFrontier(StringBuilder text) {
        text.append("Ways (").append(shotKey.getKeyLabel()).append(": ")
                .append(SHOT_NAMES[shown]).append("):  ");
        for (int w = 0; w < WAYS.length; ++w) {
            CheatFrontier.Way way = WAYS[w];
            boolean marked = shown == w + 1;
            text.append(marked ? "[" : "").append(SHOT_NAMES[w + 1]).append(marked ? "] " : " ");
            TextFormat.appendFixed(text, frontier.getMiss(way), 3).append(" m ");
            TextFormat.appendFixed(text, frontier.getHitSeconds(way), 2).append(" s ");
            double nanos = getCostNanos(way);
            if (Double.isNaN(nanos)) {
                text.append("not timed");
            } else if (nanos < 1e3) {
                TextFormat.appendFixed(text, nanos, 0).append(" ns");
            } else {
                TextFormat.appendFixed(text, nanos / 1e3, 1).append(" µs");
            }
            text.append(w == 1 ? "\n" : w == WAYS.length - 1 ? "" : ";  ");
        }
        text.append(":  projectile ");
        if (!reached) {
            text.append(bullet.isHeld() ? "came down before the disc" : "in flight");
        } else {
            text.append(hit ? "HIT" : "MISS").append(", ");
            TextFormat.appendFixed(text, getSteppedDrop(), 3).append(" m low");
        }
    }

    /** Show the ways chosen: the straight-line squares and the stepped projectile. */
    private void showWays() {
        for (int w = 0; w < WAYS.length; ++w) {
            boolean visible = shown == 0 || shown == w + 1;
            if (lineMarks[w] != null) {
                lineMarks[w].setCullHint(visible ? Spatial.CullHint.Inherit
                        : Spatial.CullHint.Always);
            }
            if (WAYS[w] == CheatFrontier.Way.STEPPED && bullet != null
                    && getWindow().getView(bullet) != null) {
                getWindow().getView(bullet).getNode().setCullHint(visible ? Spatial.CullHint.Inherit
                        : Spatial.CullHint.Always);
            }
        }
    }

    /**
     * The prologue: the disc's plane is crossed at the contact point, the first point of the
     * step's segment on it; a hit only within r of the centre. The ground always stops the
     * bullet.
     */
    private boolean prologue(Contact contact) {
        // The particle's flight time is counted after the step: here it is the step's start.
        if (contact.getRule() != discRule) {
            showImpact(contact.getPoint());
            return true;
        }
        if (reached) {
            // Behind the plane already (a miss flies on): only the first crossing counts.
            return false;
        }
        Vector3f point = contact.getPoint();
        impact.set(point);
        reached = true;
        hit = Math.abs(point.y - GUN_HEIGHT) <= TARGET_RADIUS;
        arrivalSeconds = bullet.getFlightSeconds() + contact.getFraction() * (double) worldStep;
        if (hit) {
            showImpact(point);
        }
        return hit;
    }

    private void showImpact(Vector3f point) {
        if (impactMark != null) {
            impactMark.setLocalTranslation(point.x, point.y, 0.01f);
            impactMark.setCullHint(Spatial.CullHint.Inherit);
        }
    }

    /**
     * The shot's own state, for the ring: where and when it reached the disc's plane, the h
     * it was fired and stepped with, how long it has been stopped and whether it refires.
     */
    private StateRecord shotState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 3 + 2 + 2 + 1 + 1 + 1 + 1 + 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putVector(impact);
                slab.putBoolean(reached);
                slab.putBoolean(hit);
                slab.putDouble(arrivalSeconds);
                slab.putFloat(shotStep);
                slab.putFloat(worldStep);
                slab.putFloat(stoppedSeconds);
                slab.putBoolean(refireDue);
                slab.putFloat(shotSeconds);
            }

            @Override
            public void readState(StateSlab slab) {
                slab.getVector(impact);
                reached = slab.getBoolean();
                hit = slab.getBoolean();
                arrivalSeconds = slab.getDouble();
                shotStep = slab.getFloat();
                worldStep = slab.getFloat();
                stoppedSeconds = slab.getFloat();
                refireDue = slab.getBoolean();
                shotSeconds = slab.getFloat();
                if (impactMark != null) {
                    impactMark.setCullHint(reached && hit ? Spatial.CullHint.Inherit
                            : Spatial.CullHint.Always);
                    impactMark.setLocalTranslation(impact.x, impact.y, 0.01f);
                }
            }
        };
    }

    /** The slide: the drop the straight line ignores, against r; the projectile's result. */
    @Override
    protected void writePresentation(Presentation slide) {
        slide.formula().append("ray: straight, no drop;   projectile: V += h·g,  P += h·V");
        StringBuilder formula = slide.formula().append("drop ½·g·(d/v)² = ");
        TextFormat.appendFixed(formula, Hitscan.formulaDrop(GRAVITY, DISTANCE, getSpeed()), 3)
                .append(" m  against r = ");
        TextFormat.appendFixed(formula, TARGET_RADIUS, 2).append(" m");
        StringBuilder readout = slide.readout().append("projectile: ");
        if (!reached) {
            readout.append(bullet.isHeld() ? "came down before the disc" : "in flight");
        } else {
            readout.append(hit ? "HIT" : "MISS").append(", ");
            TextFormat.appendFixed(readout, getSteppedDrop(), 3).append(" m low at x = d");
        }
    }
}

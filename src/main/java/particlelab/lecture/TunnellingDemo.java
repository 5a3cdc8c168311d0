package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.collision.ThinWall;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.Presentation;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.TextFormat;
import particlelab.view.WallView;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.StepRandom;
import particlelab.world.World;

/**
 * Demo 9, tunnelling: the overlap test against the intersection test. The same fast ball is
 * fired at a thin wall twice, side by side, in free flight (no forces: {@code P += h·V}): the
 * upper lane's wall is checked by the overlap test at the end of each step, the lower lane's
 * by the swept (intersection) test over each step's straight segment. Each shot starts at a
 * random phase, a uniformly random fraction of one step's travel {@code v·h} before the start
 * line, the same for both lanes. Builds upon bounce (its two tests) and collisions (the same
 * impulse, here with e = 1 against a static wall).
 *
 * <p>What to watch for: a ball of radius r meets a wall of thickness d only if some step ends
 * with its centre inside the band of width {@code 2r + d}. When a step carries it further than
 * that ({@code v·h > 2r + d}) the overlap test misses with probability
 * {@code max(0, 1 − (2r+d)/(v·h))}, and the ball flies on through the wall; the HUD counts the
 * misses of each lane against that prediction. The swept test never misses. Raise the speed
 * until {@code v·h} passes {@code 2r + d} and the upper lane starts to leak.
 */
public final class TunnellingDemo extends DemoState {

    /** The balls' radius r (in metres). */
    public static final float RADIUS = 0.1f;
    /** The wall's thickness d (in metres). */
    public static final float THICKNESS = 0.1f;
    /** Where the wall's centre plane stands (in metres). */
    public static final float WALL_X = 8f;
    /** The speed at the start (in m/s). */
    public static final float START_SPEED = 40f;
    /** What the speed keys add or take (in m/s). */
    public static final float SPEED_STEP = 10f;
    /** The slowest and fastest speed the keys allow (in m/s). */
    public static final float MIN_SPEED = 10f;
    /** The fastest speed the keys allow (in m/s). */
    public static final float MAX_SPEED = 200f;
    /** The seed of the phases, so a run is repeatable. */
    public static final long SEED = 20261201L;
    private static final float OVERLAP_LANE_Y = 3f;
    private static final float SWEPT_LANE_Y = 1.5f;
    private static final int OVERLAP_GROUP = 2;
    private static final int SWEPT_GROUP = 4;

    private final ThinWall wall = new ThinWall(new Vector3f(-1f, 0f, 0f), -WALL_X, THICKNESS);
    private final StepRandom phases = new StepRandom(SEED);
    private final Lane overlap = new Lane();
    private final Lane swept = new Lane();
    private final Vector3f launchPosition = new Vector3f();
    private final Vector3f launchVelocity = new Vector3f();
    private float speed = START_SPEED;
    private float lastStepSeconds;
    /** Both lanes' shots are through: fire the next pair at the next step's start. */
    private boolean nextShotDue;

    /** One lane's ball and counts. */
    private static final class Lane {
        DemoParticle ball;
        float laneY;
        int shots;
        int hits;
        boolean done;
        /** True if the lane's last ball whose result is known went through the wall. */
        boolean lastPassed;
    }

    /** Create the demo. */
    public TunnellingDemo() {
        super("Tunnelling");
    }

    @Override
    protected void createScene() {
        ParticleIntegrator freeFlight = new ParticleIntegrator();
        overlap.ball = addParticle("overlap test", ColorRGBA.Orange,
                new Vector3f(0f, OVERLAP_LANE_Y, 0f), new Vector3f(speed, 0f, 0f), 1f,
                freeFlight);
        swept.ball = addParticle("swept test", new ColorRGBA(0.3f, 0.85f, 1f, 1f),
                new Vector3f(0f, SWEPT_LANE_Y, 0f), new Vector3f(speed, 0f, 0f), 1f,
                freeFlight);
        overlap.laneY = OVERLAP_LANE_Y;
        swept.laneY = SWEPT_LANE_Y;
        setUp(overlap, OVERLAP_GROUP);
        setUp(swept, SWEPT_GROUP);
        ImpulseResponse bounceBack = new ImpulseResponse(1f);
        World world = getWorld();
        world.addRule(new SurfaceRule("wall (overlap)", wall, bounceBack, Detection.OVERLAP)
                .setCollisionFilter(OVERLAP_GROUP, OVERLAP_GROUP));
        world.addRule(new SurfaceRule("wall (swept)", wall, bounceBack, Detection.SWEPT)
                .setCollisionFilter(SWEPT_GROUP, SWEPT_GROUP));
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World stepping) {
                hit(contact.getBodyA());
            }
        });
        setView(-1f, 12f, 4.5f, 1f, 2, RADIUS);
        hideArrowsAtStart();
        addStateRecord(laneState());
        fire();
    }

    /** The thin wall. */
    @Override
    protected void buildViews(Application app) {
        getSceneNode().attachChild(WallView.create(app.getAssetManager(),
                "thin", WALL_X - THICKNESS / 2f, 0f, WALL_X + THICKNESS / 2f, 4f,
                new ColorRGBA(0.8f, 0.8f, 0.85f, 1f)));
    }

    @Override
    protected void declareKeys() {
        StringBuilder up = new StringBuilder("speed + ");
        TextFormat.appendFixed(up, SPEED_STEP, 0).append(" m/s (up to ");
        TextFormat.appendFixed(up, MAX_SPEED, 0).append("), counts from zero");
        bindKey(KeyInput.KEY_UP, "Up", up.toString(), () -> setSpeed(speed + SPEED_STEP));
        StringBuilder down = new StringBuilder("speed - ");
        TextFormat.appendFixed(down, SPEED_STEP, 0).append(" m/s (down to ");
        TextFormat.appendFixed(down, MIN_SPEED, 0).append("), counts from zero");
        bindKey(KeyInput.KEY_DOWN, "Down", down.toString(), () -> setSpeed(speed - SPEED_STEP));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("free flight P += h V;  thin wall d = ");
        TextFormat.appendFixed(text, THICKNESS, 2).append(" m at x = ");
        TextFormat.appendFixed(text, WALL_X, 1).append(" m, balls r = ");
        TextFormat.appendFixed(text, RADIUS, 2).append(" m, bounce back with e = 1\n");
    }

    @Override
    protected void afterStep(float stepSeconds) {
        lastStepSeconds = stepSeconds;
        passed(overlap);
        passed(swept);
        nextShotDue = overlap.done && swept.done;
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        if (nextShotDue) {
            nextShotDue = false;
            fire();
        }
    }

    @Override
    protected void onRestart() {
        overlap.shots = 0;
        overlap.hits = 0;
        swept.shots = 0;
        swept.hits = 0;
        phases.setSeed(SEED);
        fire();
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        float h = stepSeconds();
        float travel = speed * h;
        text.append("v = ");
        TextFormat.appendFixed(text, speed, 0).append(" m/s:  v h = ");
        TextFormat.appendFixed(text, travel, 3).append(" m  against 2r + d = ");
        TextFormat.appendFixed(text, 2f * RADIUS + THICKNESS, 3).append(" m   predicted miss"
                + " probability max(0, 1 - (2r+d)/(v h)) = ");
        TextFormat.appendFixed(text, wall.overlapMissProbability(RADIUS, speed, h), 3)
                .append('\n');
        appendLane(text, "overlap test", overlap);
        appendLane(text, "swept test  ", swept);
    }

    /**
     * Return the speed of the shots.
     *
     * @return v (in m/s)
     */
    public float getSpeed() {
        return speed;
    }

    /**
     * Set the speed of the shots and count from zero (what the keys do).
     *
     * @param newSpeed v (in m/s, from {@link #MIN_SPEED} to {@link #MAX_SPEED})
     */
    public void setSpeed(float newSpeed) {
        speed = Math.max(MIN_SPEED, Math.min(MAX_SPEED, newSpeed));
        restart();
    }

    /**
     * Count the shots of a lane whose result is known.
     *
     * @param sweptLane true for the swept lane, false for the overlap lane
     * @return the count (&ge;0)
     */
    public int countShots(boolean sweptLane) {
        return (sweptLane ? swept : overlap).shots;
    }

    /**
     * Count the shots of a lane that hit the wall.
     *
     * @param sweptLane true for the swept lane, false for the overlap lane
     * @return the count (&ge;0)
     */
    public int countHits(boolean sweptLane) {
        return (sweptLane ? swept : overlap).hits;
    }

    /**
     * Return the overlap test's predicted miss probability at the current speed and step.
     *
     * @return the probability (0 to 1)
     */
    public double predictedMissProbability() {
        return wall.overlapMissProbability(RADIUS, speed, stepSeconds());
    }

    private float stepSeconds() {
        return lastStepSeconds > 0f ? lastStepSeconds : getClock().getStepSeconds();
    }

    private static void appendLane(StringBuilder text, String name, Lane lane) {
        int misses = lane.shots - lane.hits;
        text.append(name).append(":  shots ").append(lane.shots).append("   hits ")
                .append(lane.hits).append("   misses ").append(misses).append("   miss rate ");
        TextFormat.appendFixed(text, lane.shots == 0 ? 0.0 : (double) misses / lane.shots, 3)
                .append('\n');
    }

    private void setUp(Lane lane, int group) {
        lane.ball.getBody().setRadius(RADIUS);
        lane.ball.getBody().setCollisionFilter(group, group);
    }

    /** Epilogue: a ball that met the wall counts a hit and is done. */
    private void hit(Body body) {
        Lane lane = body == overlap.ball.getBody() ? overlap : swept;
        if (!lane.done) {
            lane.done = true;
            ++lane.shots;
            ++lane.hits;
            lane.lastPassed = false;
        }
    }

    /** A ball beyond the wall's far face went through it: a miss. */
    private void passed(Lane lane) {
        if (!lane.done && lane.ball.getParticle().position.x
                > WALL_X + THICKNESS / 2f + RADIUS) {
            lane.done = true;
            ++lane.shots;
            lane.lastPassed = true;
        }
    }

    /** Both lanes again, from the same random phase before the start line. */
    private void fire() {
        nextShotDue = false;
        float h = stepSeconds();
        float start = -phases.nextFloat() * speed * h;
        launchVelocity.set(speed, 0f, 0f);
        launch(overlap, start);
        launch(swept, start);
    }

    private void launch(Lane lane, float x) {
        launchPosition.set(x, lane.laneY, 0f);
        lane.ball.setLaunch(launchPosition, launchVelocity);
        launch(lane.ball, launchVelocity);
        lane.done = false;
    }

    /**
     * The demo's own state, for the ring: the random phase's sequence, the lanes' counts
     * and whether the next shot is due.
     */
    private StateRecord laneState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 2 + 1 + 1 + 2 * 3;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putLong(phases.getState());
                slab.putFloat(lastStepSeconds);
                slab.putBoolean(nextShotDue);
                writeLane(slab, overlap);
                writeLane(slab, swept);
            }

            @Override
            public void readState(StateSlab slab) {
                phases.setState(slab.getLong());
                lastStepSeconds = slab.getFloat();
                nextShotDue = slab.getBoolean();
                readLane(slab, overlap);
                readLane(slab, swept);
            }
        };
    }

    private static void writeLane(StateSlab slab, Lane lane) {
        slab.putInt(lane.shots);
        slab.putInt(lane.hits);
        slab.putBoolean(lane.done);
    }

    private static void readLane(StateSlab slab, Lane lane) {
        lane.shots = slab.getInt();
        lane.hits = slab.getInt();
        lane.done = slab.getBoolean();
    }

    /** The slide: one step's travel against the wall; whether the last ball went through. */
    @Override
    protected void writePresentation(Presentation slide) {
        float h = stepSeconds();
        StringBuilder formula = slide.formula().append("overlap test misses when v h > 2r + d:"
                + "   v h = ");
        TextFormat.appendFixed(formula, speed * h, 3).append(" m");
        StringBuilder second = slide.formula().append("2r + d = ");
        TextFormat.appendFixed(second, 2f * RADIUS + THICKNESS, 3).append(" m,   miss"
                + " probability ");
        TextFormat.appendFixed(second, wall.overlapMissProbability(RADIUS, speed, h), 3);
        StringBuilder readout = slide.readout().append("overlap test, ball passed through the"
                + " wall: ");
        if (overlap.shots == 0) {
            readout.append("not yet");
        } else {
            readout.append(overlap.lastPassed ? "yes" : "no");
        }
    }
}

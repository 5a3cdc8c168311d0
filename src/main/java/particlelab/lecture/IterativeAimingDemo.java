package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.aiming.AimResult;
import particlelab.aiming.AimStrategy;
import particlelab.aiming.Duel;
import particlelab.aiming.Flight;
import particlelab.aiming.IterativeAim;
import particlelab.aiming.LevelAim;
import particlelab.aiming.PredictorMismatch;
import particlelab.aiming.ShotLog;
import particlelab.aiming.ShotSimulator;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.Presentation;
import particlelab.demo.StepTable;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ScriptedResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.World;

/**
 * Iterative aiming, the lecture's computer-science approach: "shoot at will, see where it
 * lands; if undershot increase power, if overshot decrease power". Builds upon HelloAiming
 * (the same level target, vx fixed) and drag: with drag on, the closed form
 * {@code vy = g·S/(2·vx)} falls short, and no formula replaces it, so the gun fires, looks and
 * adjusts vy.
 *
 * <p>The aimer is {@link IterativeAim} with the shared integrator and this scene's forces.
 * Its search is deterministic, so the demo asks it once per round for its shots
 * ({@link ShotLog}) and then flies them in the scene one after another, each where the
 * player sees it: the n-th flown shot lands where the search's n-th shot did (unless the
 * predictor is stepped differently, below). The last {@value #VISIBLE_SHOTS} trails stay,
 * the older ones fainter, each labelled with its vy and its miss; the HUD lists the attempts.
 *
 * <p>What to watch for:
 * <ul>
 * <li>the strategies (G): the lecture's rule creeps in with a change halved at each sign
 * change of the miss; bisection halves a bracket; the secant closes in fastest; the
 * "believable" player always misses its first shot and then moves a seeded random
 * 30–170 % of the way to the answer, as an artillery-game opponent a person believes;</li>
 * <li>"what will the user think?" (I): the instant mode does the same search invisibly,
 * within one frame, and fires only the final shot; the HUD says how many shots the player
 * would otherwise have watched;</li>
 * <li>the predictor mismatch (P): the aimer predicts with a step of {@value #PREDICT_STEP_MS}
 * ms while the shots fly at the demo's h; a shot it believes lands at S flies about
 * {@code vx·|h_predict − h_fly|} further (the Worms "CPU shot misprediction").</li>
 * </ul>
 *
 * <p>The duel ({@code --set duel=on}, issue 34 §3): a student aims at the same target against
 * the believable player, with an angle (Up/Down) and a speed (Left/Right) of their own, F
 * firing their shot (cyan, "you"); the HUD keeps both players' shots to a hit, worst miss and
 * time ({@link Duel}). Once the student hits, Y or B answers "felt fair?" (yes / no), which
 * closes the round and starts the next with the next seed; every closed round is a row of
 * {@value #DUEL_TABLE}.csv in the export (E).
 */
public final class IterativeAimingDemo extends DemoState {

    /** The distance to the target S (in metres). */
    public static final float TARGET_DISTANCE = 60f;
    /** The fixed horizontal launch speed vx (in m/s). */
    public static final float HORIZONTAL_SPEED = 20f;
    /** The bullet's mass m (in kilograms). */
    public static final float MASS_KG = 1f;
    /** The linear drag coefficient b (in kg/s): b/m = 0.1 /s. */
    public static final float LINEAR_DRAG = 0.1f;
    /** The quadratic drag coefficient c (in kg/m): c/m = 0.01 /m. */
    public static final float QUADRATIC_DRAG = 0.01f;
    /** A shot hits when it lands this close to S: the target's half-width (in metres). */
    public static final float TOLERANCE_METRES = 0.25f;
    /** The step the mismatched predictor uses (in milliseconds). */
    public static final int PREDICT_STEP_MS = 50;
    /** How many shots' trails stay visible. */
    public static final int VISIBLE_SHOTS = 4;
    /** The most shots a round may take. */
    public static final int MAX_SHOTS = 40;
    /** The export's table of the round's shots (file name without .csv). */
    public static final String SHOTS_TABLE = "shots";
    /** Its header: one row per attempt, as planned and as flown. */
    public static final String SHOTS_HEADER = "shot,vx_m_per_s,vy_m_per_s,predicted_landing_x_m,"
            + "predicted_flight_s,predicted_miss_m,flown_landing_x_m";
    /** The believable player's seed at the start. */
    public static final long DEFAULT_SEED = 1L;
    /** The export's table of the duel's closed rounds (file name without .csv). */
    public static final String DUEL_TABLE = "duel";
    /** The human's aim at the start of a duel (in degrees above the horizontal). */
    public static final float DUEL_START_DEGREES = 45f;
    /** The human's launch speed at the start of a duel (in m/s). */
    public static final float DUEL_START_SPEED = 25f;
    /** How much Up and Down change the human's aim (in degrees). */
    public static final float DUEL_ANGLE_STEP = 0.5f;
    /** How much Right and Left change the human's launch speed (in m/s). */
    public static final float DUEL_SPEED_STEP = 0.1f;
    /** The human's sphere: a cyan none of the computer's shots has. */
    private static final ColorRGBA HUMAN_COLOR = new ColorRGBA(0.3f, 0.9f, 1f, 1f);
    /** The names of a switch's two states, off first. */
    private static final String[] OFF_ON = {"off", "on"};
    /** The strategies the G key cycles through, in order. */
    private static final AimStrategy[] STRATEGIES = {AimStrategy.LECTURE,
        AimStrategy.BISECTION, AimStrategy.SECANT, AimStrategy.BELIEVABLE};
    /** The mismatched predictor's step (in seconds). */
    private static final float PREDICT_STEP = PREDICT_STEP_MS / 1000f;
    /** How many attempts the HUD table lists: the latest ones, one column each. */
    private static final int TABLE_COLUMNS = 8;
    /** The width of a column (in characters; the font's digits are all one width). */
    private static final int CELL_CHARACTERS = 10;
    /** A shot still in the air after this long never lands (in seconds). */
    private static final float MAX_FLIGHT_SECONDS = 60f;
    private static final float GRAVITY = Gravity.STANDARD_G;
    /** Where a shot not in use waits, held: out of sight, above the ground (in metres). */
    private static final float PARK_X = -1000f;
    private static final float PARK_Y = 5f;
    /** The opacity of each trail by age: the newest shot first. */
    private static final float[] TRAIL_OPACITY = {1f, 0.55f, 0.3f, 0.15f};
    /** The view frames at least this high, and the grid reaches this high (in metres). */
    private static final float MIN_VIEW_TOP = 16f;
    private static final float MAX_VIEW_TOP = 60f;
    /** Room kept above the highest apex, as a fraction of it. */
    private static final float HEADROOM = 0.1f;
    private static final ColorRGBA SHOT_COLOR = new ColorRGBA(1f, 0.85f, 0.2f, 1f);

    /** Which drag law the scene's bullets feel. */
    public enum Drag {
        /** {@code F = −b·V}. */
        LINEAR,
        /** {@code F = −c·|V|·V}. */
        QUADRATIC
    }

    private final Gravity gravity = new Gravity();
    private final LinearDrag linearDrag = new LinearDrag(LINEAR_DRAG);
    private final QuadraticDrag quadraticDrag = new QuadraticDrag(0f);
    /** The scene's bullets' forces. */
    private final ParticleIntegrator integrator =
            new ParticleIntegrator(gravity, linearDrag, quadraticDrag);
    /** The aimer's own integrator, with the same forces: its shots are in its head. */
    private final ParticleIntegrator aimerIntegrator =
            new ParticleIntegrator(gravity, linearDrag, quadraticDrag);
    private final ShotLog plan = new ShotLog(MAX_SHOTS);
    /** Where each attempt of the round landed in the scene (in metres; NaN: not yet). */
    private final double[] flownLanding = new double[MAX_SHOTS];
    private final DemoParticle[] slots = new DemoParticle[VISIBLE_SHOTS];
    /** The attempt each slot flies, or -1. */
    private final int[] slotShot = new int[VISIBLE_SHOTS];
    /** One tint object per age (see {@link particlelab.view.Trail#setTint}). */
    private final ColorRGBA[] tints = new ColorRGBA[TRAIL_OPACITY.length];
    private final Vector3f gun = new Vector3f();
    private final Vector3f park = new Vector3f(PARK_X, PARK_Y, 0f);
    /** Per slot: its label and its trail's tint must be shown again ({@link #update}). */
    private final boolean[] labelChanged = new boolean[VISIBLE_SHOTS];
    private boolean tintsChanged;
    private SurfaceRule groundRule;
    /** Where the shot in the air came down in this step (in metres; NaN: not yet). */
    private float pendingLandingX = Float.NaN;
    /** The last shot landed and the plan has more: fire the next at the next step's start. */
    private boolean nextShotDue;
    private final Vector3f launchVelocity = new Vector3f();
    /** A shot flown up to its apex, to frame it. */
    private final Particle apexProbe = new Particle();
    /** Flies the apex probe with the aimer's integrator. */
    private final Flight apexFlight = new Flight(aimerIntegrator);
    private AimStrategy strategy = AimStrategy.LECTURE;
    private Drag drag = Drag.LINEAR;
    private boolean instant;
    private boolean mismatch;
    private long seed = DEFAULT_SEED;
    private AimResult result;
    /** The steps of the round: the shots fly with flyStep, the aimer predicted with the other. */
    private float flyStep = Float.NaN;
    private float predictStep = Float.NaN;
    /** The first attempt flown in the scene (the last one in instant mode). */
    private int firstFlown;
    /** Attempts launched, and attempts landed, in the scene (counting the skipped ones). */
    private int fired;
    private int landed;
    /** The total flight time of the round's attempts (in seconds). */
    private double watchSeconds;
    private ShotSimulator flySimulator;
    private ShotSimulator predictSimulator;
    private KeyBinding strategyKey;
    private KeyBinding dragKey;
    private KeyBinding instantKey;
    private KeyBinding mismatchKey;
    private KeyBinding seedKey;
    private KeyBinding roundKey;
    /**
     * The duel: the human's shots against the believable player's ({@link Duel}); its
     * simulator is the flight's own from the first round on (this one steps no shot).
     */
    private final Duel duel = new Duel(new ShotSimulator(aimerIntegrator, MASS_KG,
            SimulationClock.DEFAULT_STEP_SECONDS, MAX_FLIGHT_SECONDS), GRAVITY,
            TARGET_DISTANCE, HORIZONTAL_SPEED, TOLERANCE_METRES, MAX_SHOTS);
    private boolean duelOn;
    private float duelDegrees = DUEL_START_DEGREES;
    private float duelSpeed = DUEL_START_SPEED;
    /** The human's sphere (parked while the duel is off). */
    private DemoParticle human;
    /** The human's shot is flying in the scene. */
    private boolean humanInAir;
    /** The human's shot came down in this step. */
    private boolean humanLandedPending;
    /** The human's shots whose landing the scene has shown. */
    private int humanShown;
    private boolean humanLabelChanged;
    /** The simulated time the round started at (in seconds). */
    private double roundStartSeconds;

    /** Create the demo. */
    public IterativeAimingDemo() {
        super("Iterative aiming");
        for (int i = 0; i < tints.length; ++i) {
            tints[i] = new ColorRGBA(1f, 1f, 1f, TRAIL_OPACITY[i]);
        }
    }

    // ----------------------------------------------------------------------- public API ----

    /**
     * Return the strategy that adjusts vy.
     *
     * @return the strategy (not null)
     */
    public AimStrategy getStrategy() {
        return strategy;
    }

    /**
     * Choose the strategy and start a new round.
     *
     * @param newStrategy lecture, bisection, secant or believable (not null)
     */
    public void setStrategy(AimStrategy newStrategy) {
        if (indexOfStrategy(newStrategy) < 0) {
            throw new IllegalArgumentException("strategy must be lecture, bisection, secant or"
                    + " believable, but was " + newStrategy);
        }
        strategy = newStrategy;
        getParameters().set("strategy", indexOfStrategy(strategy));
        restart();
    }

    /**
     * Return the drag law.
     *
     * @return the law (not null)
     */
    public Drag getDrag() {
        return drag;
    }

    /**
     * Choose the drag law and start a new round.
     *
     * @param newDrag linear or quadratic (not null)
     */
    public void setDrag(Drag newDrag) {
        if (newDrag == null) {
            throw new IllegalArgumentException("drag must be LINEAR or QUADRATIC, but was null");
        }
        drag = newDrag;
        getParameters().set("drag", drag.ordinal());
        linearDrag.setCoefficient(drag == Drag.LINEAR ? LINEAR_DRAG : 0f);
        quadraticDrag.setCoefficient(drag == Drag.QUADRATIC ? QUADRATIC_DRAG : 0f);
        refreshEquations();
        restart();
    }

    /**
     * Test whether the instant mode is on.
     *
     * @return true if the search is invisible and only the final shot flies
     */
    public boolean isInstant() {
        return instant;
    }

    /**
     * Switch the instant mode and start a new round.
     *
     * @param newInstant true to search invisibly and fly only the final shot
     */
    public void setInstant(boolean newInstant) {
        instant = newInstant;
        getParameters().set("instant", instant ? 1 : 0);
        restart();
    }

    /**
     * Test whether the aimer predicts with another step than the shots fly with.
     *
     * @return true if it predicts with {@value #PREDICT_STEP_MS} ms
     */
    public boolean isMismatch() {
        return mismatch;
    }

    /**
     * Make the aimer predict with {@value #PREDICT_STEP_MS} ms or with the flight's own step,
     * and start a new round.
     *
     * @param newMismatch true for the mismatched predictor
     */
    public void setMismatch(boolean newMismatch) {
        mismatch = newMismatch;
        getParameters().set("predictor", mismatch ? 1 : 0);
        restart();
    }

    /**
     * Return the believable player's seed.
     *
     * @return the seed
     */
    public long getSeed() {
        return seed;
    }

    /**
     * Choose the believable player's seed and start a new round.
     *
     * @param newSeed any value; the same seed gives the same shots
     */
    public void setSeed(long newSeed) {
        seed = newSeed;
        restart();
    }

    /**
     * Access the aimer's attempts of this round, as it predicted them.
     *
     * @return the live log (not null, do not modify)
     */
    public ShotLog getPlan() {
        return plan;
    }

    /**
     * Return the aimer's answer for this round.
     *
     * @return the result (not null once the demo is initialised)
     */
    public AimResult getResult() {
        return result;
    }

    /**
     * Return the attempts flown in the scene this round: all of them, or in instant mode
     * only the final one.
     *
     * @return the first attempt flown (0 for the first shot)
     */
    public int getFirstFlownShot() {
        return firstFlown;
    }

    /**
     * Count the round's attempts that have landed, in the scene or (in instant mode) in the
     * aimer's head.
     *
     * @return the count (0 to the plan's size)
     */
    public int countLanded() {
        return landed;
    }

    /**
     * Return where an attempt landed in the scene.
     *
     * @param shot 0 for the first attempt
     * @return x (in metres; NaN if it was not flown or has not landed yet)
     */
    public double getFlownLandingX(int shot) {
        if (shot < 0 || shot >= plan.size()) {
            throw new IllegalArgumentException("shot must be in 0.." + (plan.size() - 1)
                    + ", but was " + shot);
        }
        return flownLanding[shot];
    }

    /**
     * Return the total flight time of the round's attempts: what a player watching every
     * shot would sit through.
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getWatchSeconds() {
        return watchSeconds;
    }

    /**
     * Return the miss the predictor mismatch should cause, drag aside:
     * {@code vx·|h_predict − h_fly|} ({@link PredictorMismatch#expectedMiss}).
     *
     * @return the miss (in metres, &ge;0; 0 without the mismatch)
     */
    public double getExpectedMismatchMiss() {
        if (!mismatch || Float.isNaN(flyStep)) {
            return 0.0;
        }
        return Math.abs(PredictorMismatch.expectedMiss(HORIZONTAL_SPEED, predictStep, flyStep));
    }

    /**
     * Access the shots drawn in the scene (the slots the attempts take in turn).
     *
     * @param slot 0 to {@link #VISIBLE_SHOTS} − 1
     * @return the slot's particle (not null)
     */
    public DemoParticle getShotSlot(int slot) {
        return slots[slot];
    }

    /**
     * Test whether the duel is on: the human aims against the believable player.
     *
     * @return true while it is
     */
    public boolean isDuelOn() {
        return duelOn;
    }

    /**
     * Start or end the duel. On, the round is the believable player's with the flight's own
     * predictor and every shot visible (another strategy, instant or the mismatch ends the
     * duel again); a new round starts either way.
     *
     * @param on true to duel
     */
    public void setDuel(boolean on) {
        duelOn = on;
        getParameters().set("duel", on ? 1 : 0);
        if (on) {
            strategy = AimStrategy.BELIEVABLE;
            getParameters().set("strategy", indexOfStrategy(strategy));
            instant = false;
            getParameters().set("instant", 0);
            mismatch = false;
            getParameters().set("predictor", 0);
        }
        restart();
    }

    /**
     * Access the duel: the human's shots and the closed rounds.
     *
     * @return the live duel (not null, do not modify)
     */
    public Duel getDuel() {
        return duel;
    }

    /**
     * Access the human's sphere in the scene.
     *
     * @return the demo particle (null before the scene is declared)
     */
    public DemoParticle getHumanSphere() {
        return human;
    }

    /** @return true while the human's shot flies in the scene */
    public boolean isHumanInAir() {
        return humanInAir;
    }

    /** @return the human's aim (in degrees above the horizontal) */
    public float getDuelDegrees() {
        return duelDegrees;
    }

    /** @return the human's launch speed (in m/s) */
    public float getDuelSpeed() {
        return duelSpeed;
    }

    /**
     * Change the human's aim, as the arrow keys do, within {@link Duel}'s limits.
     *
     * @param degrees added to the aim (in degrees)
     * @param speed added to the launch speed (in m/s)
     */
    public void aimBy(float degrees, float speed) {
        if (!duelOn) {
            getDemoHud().showNotice("the duel is off: --set duel=on, or the panel (F2)");
            return;
        }
        // Whole tenths: a key pressed a hundred times leaves no float drift in the aim.
        duelDegrees = Math.round(10f * Math.max(Duel.MIN_ANGLE_DEGREES,
                Math.min(Duel.MAX_ANGLE_DEGREES, duelDegrees + degrees))) / 10f;
        duelSpeed = Math.round(10f * Math.max(Duel.MIN_SPEED,
                Math.min(Duel.MAX_SPEED, duelSpeed + speed))) / 10f;
    }

    /**
     * Fire the human's shot with their aim (F in the duel): refused with a notice while the
     * last one flies or once the round is over.
     *
     * @return true if it was fired
     */
    public boolean fireHuman() {
        if (!duelOn) {
            getDemoHud().showNotice("the duel is off: --set duel=on, or the panel (F2)");
            return false;
        }
        if (duel.isRoundOver()) {
            getDemoHud().showNotice("round over: felt fair? Y yes, B no");
            return false;
        }
        if (humanInAir) {
            getDemoHud().showNotice("your shot is still in the air");
            return false;
        }
        if (duel.fire(duelDegrees, duelSpeed, getClock().getSimulatedSeconds()
                - roundStartSeconds) < 0) {
            return false;
        }
        launchVelocity.set(Duel.launchX(duelDegrees, duelSpeed),
                Duel.launchY(duelDegrees, duelSpeed), 0f);
        human.setLaunch(gun, launchVelocity);
        launch(human, launchVelocity);
        human.setHeld(false);
        humanInAir = true;
        humanLabelChanged = true;
        // Room for the human's apex too: without drag it is vy²/(2g), with drag lower.
        float top = launchVelocity.y * launchVelocity.y / (2f * GRAVITY);
        for (int i = firstFlown; i < plan.size(); ++i) {
            top = Math.max(top, plan.getVerticalSpeed(i) * plan.getVerticalSpeed(i)
                    / (2f * GRAVITY));
        }
        getWindow().setViewTop(Math.min(MAX_VIEW_TOP,
                Math.max(MIN_VIEW_TOP, (1f + HEADROOM) * top)));
        return true;
    }

    /**
     * Answer "felt fair?" (Y or B in the duel): once the human hit (or ran out of shots), the
     * round is closed, logged, and the next starts with the next seed.
     *
     * @param fair true if it felt fair
     * @return true if the round was closed
     */
    public boolean poll(boolean fair) {
        if (!duelOn) {
            getDemoHud().showNotice("the duel is off: --set duel=on, or the panel (F2)");
            return false;
        }
        if (!duel.isRoundOver() || humanInAir) {
            getDemoHud().showNotice("the round is not over: hit the target first (F fires)");
            return false;
        }
        duel.closeRound(fair);
        getDemoHud().showNotice("round " + duel.countClosedRounds() + " logged (felt fair: "
                + (fair ? "yes" : "no") + "); E exports " + DUEL_TABLE + ".csv");
        setSeed(seed + 1L);
        return true;
    }

    // ------------------------------------------------------------- framework overrides ----

    /**
     * Add the round's shots to an export ({@value #SHOTS_TABLE}.csv): each attempt's launch
     * velocity, where and when the aimer predicted it lands, its predicted miss, and where it
     * landed in the scene (NaN while it has not). The shots fly parked between attempts, so
     * their trajectories are not what the round is about.
     *
     * @param storeResult where to add the table (not null, modified)
     */
    @Override
    public void collectExportTables(List<StepTable> storeResult) {
        StepTable shots = new StepTable(SHOTS_TABLE, SHOTS_HEADER, MAX_SHOTS);
        for (int i = 0; i < plan.size(); ++i) {
            shots.startRow().put(i + 1).put(plan.getHorizontalSpeed(i))
                    .put(plan.getVerticalSpeed(i)).put(plan.getLandingX(i))
                    .put(plan.getFlightSeconds(i)).put(plan.getMiss(i)).put(flownLanding[i]);
        }
        storeResult.add(shots);
        if (duelOn || duel.countClosedRounds() > 0) {
            StepTable rounds = new StepTable(DUEL_TABLE, Duel.CSV_HEADER,
                    Math.max(1, duel.countClosedRounds()));
            for (int i = 0; i < duel.countClosedRounds(); ++i) {
                rounds.startRow();
                double[] row = duel.copyClosedRound(i);
                for (double value : row) {
                    rounds.put(value);
                }
            }
            storeResult.add(rounds);
        }
    }

    @Override
    protected void createScene() {
        for (int i = 0; i < VISIBLE_SHOTS; ++i) {
            slots[i] = addParticle("", SHOT_COLOR, park, Vector3f.ZERO, MASS_KG, integrator);
            slots[i].setParked(true);
        }
        human = addParticle("", HUMAN_COLOR, park, Vector3f.ZERO, MASS_KG, integrator);
        human.setParked(true);
        // The ground stops a shot where its step's segment crosses y = 0 and holds it there.
        groundRule = SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT);
        getWorld().addRule(groundRule);
        getWorld().addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World stepping) {
                landed(contact);
                if (contact.getRule() == groundRule && contact.getBodyA() == human.getBody()
                        && humanInAir) {
                    humanLandedPending = true;
                }
            }
        });
        addMarker("gun", 0f, 2f, new ColorRGBA(0.6f, 0.9f, 0.6f, 1f));
        addMarker("target  S = " + Math.round(TARGET_DISTANCE) + " m", TARGET_DISTANCE, 4f,
                new ColorRGBA(1f, 0.3f, 0.25f, 1f));
        // The grid reaches the highest apex a round may need; the camera frames the round's.
        setView(-4f, TARGET_DISTANCE + 14f, MAX_VIEW_TOP, 4f, 5, 0.7f);
        hideArrowsAtStart();
        addStateRecord(roundState());
        startRound();
    }

    @Override
    protected void declareParameters() {
        // The states the G, L, I and P keys switch; each setter mirrors into its parameter.
        String[] strategies = new String[STRATEGIES.length];
        for (int i = 0; i < STRATEGIES.length; ++i) {
            strategies[i] = STRATEGIES[i].cliName();
        }
        declareParameter(DemoParameter.choice("strategy", "aiming strategy", strategies,
                indexOfStrategy(strategy), DemoParameter.Applies.LIVE, value -> {
                    if (Math.round(value) != indexOfStrategy(strategy)) {
                        setStrategy(STRATEGIES[Math.round(value)]);
                    }
                }));
        String[] laws = {"linear", "quadratic"};
        declareParameter(DemoParameter.choice("drag", "drag law", laws, drag.ordinal(),
                DemoParameter.Applies.LIVE, value -> {
                    if (Math.round(value) != drag.ordinal()) {
                        setDrag(Drag.values()[Math.round(value)]);
                    }
                }));
        declareParameter(DemoParameter.choice("instant", "instant mode", OFF_ON, instant ? 1 : 0,
                DemoParameter.Applies.LIVE, value -> {
                    if ((Math.round(value) == 1) != instant) {
                        setInstant(Math.round(value) == 1);
                    }
                }));
        declareParameter(DemoParameter.choice("predictor", "predictor's step",
                new String[] {"own", "mismatch"}, mismatch ? 1 : 0, DemoParameter.Applies.LIVE,
                value -> {
                    if ((Math.round(value) == 1) != mismatch) {
                        setMismatch(Math.round(value) == 1);
                    }
                }));
        declareParameter(DemoParameter.choice("duel", "you against the believable player",
                OFF_ON, duelOn ? 1 : 0, DemoParameter.Applies.LIVE, value -> {
                    if ((Math.round(value) == 1) != duelOn) {
                        setDuel(Math.round(value) == 1);
                    }
                }));
    }

    @Override
    protected void declareKeys() {
        StringBuilder names = new StringBuilder("aiming strategy: ");
        for (int i = 0; i < STRATEGIES.length; ++i) {
            names.append(i == 0 ? "" : " -> ").append(STRATEGIES[i].cliName());
        }
        strategyKey = bindKey(KeyInput.KEY_G, "G", names.toString(),
                () -> setStrategy(STRATEGIES[(indexOfStrategy(strategy) + 1)
                        % STRATEGIES.length]));
        dragKey = bindKey(KeyInput.KEY_L, "L", "drag: linear <-> quadratic",
                () -> setDrag(drag == Drag.LINEAR ? Drag.QUADRATIC : Drag.LINEAR));
        instantKey = bindKey(KeyInput.KEY_I, "I",
                "instant: search invisibly in one frame, fly only the final shot",
                () -> setInstant(!instant));
        mismatchKey = bindKey(KeyInput.KEY_P, "P", "predictor: the flight's own h <-> "
                + PREDICT_STEP_MS + " ms (mismatch)", () -> setMismatch(!mismatch));
        roundKey = bindKey(KeyInput.KEY_F, "F", "fire a new round (duel: your shot)", () -> {
                    if (duelOn) {
                        fireHuman();
                    } else {
                        restart();
                    }
                });
        seedKey = bindKey(KeyInput.KEY_J, "J", "believable player: next random seed",
                () -> setSeed(seed + 1L));
        // One help row for the four arrows: the help stays legible at 1280x720.
        StringBuilder arrows = new StringBuilder("duel: aim (Up/Down) ");
        TextFormat.appendFixed(arrows, DUEL_ANGLE_STEP, 1).append(" deg, speed (Right/Left) ");
        TextFormat.appendFixed(arrows, DUEL_SPEED_STEP, 1).append(" m/s");
        getKeys().bindKeys(new KeyBinding(new int[] {KeyInput.KEY_UP, KeyInput.KEY_DOWN,
            KeyInput.KEY_RIGHT, KeyInput.KEY_LEFT}, new String[] {"Up", "Down", "Right", "Left"},
                arrows.toString(), null, key -> aimBy(
                        key == 0 ? DUEL_ANGLE_STEP : key == 1 ? -DUEL_ANGLE_STEP : 0f,
                        key == 2 ? DUEL_SPEED_STEP : key == 3 ? -DUEL_SPEED_STEP : 0f))
                .withKeyLabel("arrows"));
        getKeys().bindKeys(new KeyBinding(new int[] {KeyInput.KEY_Y, KeyInput.KEY_B},
                new String[] {"Y", "B"}, "duel: felt fair? yes/no (ends the round)", null,
                key -> poll(key == 0)));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        if (drag == Drag.LINEAR) {
            text.append("V += h·(g − (b/m)·V),  P += h·V,   b/m = ");
            TextFormat.appendFixed(text, LINEAR_DRAG / MASS_KG, 2).append(" /s");
        } else {
            text.append("V += h·(g − (c/m)·|V|·V),  P += h·V,   c/m = ");
            TextFormat.appendFixed(text, QUADRATIC_DRAG / MASS_KG, 2).append(" /m");
        }
        text.append(";   S = ");
        TextFormat.appendFixed(text, TARGET_DISTANCE, 0).append(" m,  vx = ");
        TextFormat.appendFixed(text, HORIZONTAL_SPEED, 0).append(" m/s,  first guess"
                + " g·S/(2·vx) = ");
        TextFormat.appendFixed(text, LevelAim.lectureVy(GRAVITY, TARGET_DISTANCE,
                HORIZONTAL_SPEED), 2).append(" m/s (no drag)\n");
    }

    @Override
    protected void afterStep(float stepSeconds) {
        if (humanLandedPending) {
            humanLandedPending = false;
            humanInAir = false;
            humanShown = duel.countHumanShots();
            humanLabelChanged = true;
        }
        if (Float.isNaN(pendingLandingX)) {
            return;
        }
        int shot = fired - 1;
        flownLanding[shot] = pendingLandingX;
        pendingLandingX = Float.NaN;
        landed = fired;
        labelChanged[shot % VISIBLE_SHOTS] = true;
        nextShotDue = fired < plan.size();
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        if (nextShotDue) {
            nextShotDue = false;
            fireNext();
        }
    }

    /**
     * Show the labels and trail tints that changed, before the frame: once per change, here
     * rather than in {@link particlelab.demo.DemoWindow#advance}, which only steps and moves
     * the views.
     */
    @Override
    public void update(float tpf) {
        if (humanLabelChanged) {
            humanLabelChanged = false;
            relabel(human, humanLabel());
        }
        for (int i = 0; i < VISIBLE_SHOTS; ++i) {
            if (labelChanged[i]) {
                labelChanged[i] = false;
                int shot = slotShot[i];
                relabel(slots[i], shot < 0 ? "" : shotLabel(shot, shot < landed));
            }
        }
        if (tintsChanged) {
            tintsChanged = false;
            for (int i = 0; i < VISIBLE_SHOTS; ++i) {
                if (slotShot[i] >= 0 && getWindow().getView(slots[i]) != null) {
                    int age = Math.min(fired - 1 - slotShot[i], tints.length - 1);
                    getWindow().getView(slots[i]).getTrail().setTint(tints[age]);
                }
            }
        }
        super.update(tpf);
    }

    /**
     * Test whether the round is over: every attempt flown has landed.
     *
     * @return true once the final shot landed
     */
    public boolean isRoundOver() {
        return plan.size() > 0 && landed == plan.size();
    }

    @Override
    protected void onRestart() {
        startRound();
    }

    /**
     * A new h: the round in the air was planned (and its shots aimed) for the old one, so a
     * new round is planned and fired for the new h, as F does. At the scene's start this is
     * the h {@code --set} chose.
     */
    @Override
    protected void onStepChanged(float stepSeconds) {
        if (getClock().getMode() == SimulationClock.Mode.FIXED_STEP && stepSeconds != flyStep) {
            restart();
        }
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        text.append("Strategy ").append(strategy.cliName()).append(" (")
                .append(strategyKey.getKeyLabel()).append(")");
        if (strategy == AimStrategy.BELIEVABLE) {
            text.append(", seed ").append(seed).append(" (").append(seedKey.getKeyLabel())
                    .append(')');
        }
        text.append(",  drag ").append(drag == Drag.LINEAR ? "linear" : "quadratic")
                .append(" (").append(dragKey.getKeyLabel()).append("),  ")
                .append(instant ? "instant" : "visible shots").append(" (")
                .append(instantKey.getKeyLabel()).append("),  predictor h ");
        TextFormat.appendFixed(text, predictStep * 1000f, 1).append(" ms, flight h ");
        TextFormat.appendFixed(text, flyStep * 1000f, 1).append(" ms (")
                .append(mismatchKey.getKeyLabel()).append(")\n");
        if (duelOn) {
            // The duel's lines say what the summary would, for both players; before the
            // table, which a small window hides first.
            appendDuel(text);
            appendTable(text);
        } else {
            appendTable(text);
            appendSummary(text);
        }
    }

    // ---------------------------------------------------------------- private helpers ----

    /** A new round: every slot out of sight, the aimer asked, the first shot fired. */
    private void startRound() {
        for (int i = 0; i < VISIBLE_SHOTS; ++i) {
            slots[i].setLaunch(park, Vector3f.ZERO);
            launch(slots[i], Vector3f.ZERO);
            slots[i].setHeld(true);
            slotShot[i] = -1;
            labelChanged[i] = true;
        }
        pendingLandingX = Float.NaN;
        nextShotDue = false;
        flyStep = getClock().getCurrentStepSeconds();
        predictStep = mismatch ? PREDICT_STEP : flyStep;
        if (flySimulator == null || flySimulator.getStepSeconds() != flyStep) {
            flySimulator = new ShotSimulator(aimerIntegrator, MASS_KG, flyStep,
                    MAX_FLIGHT_SECONDS);
        }
        if (predictSimulator == null || predictSimulator.getStepSeconds() != PREDICT_STEP) {
            predictSimulator = new ShotSimulator(aimerIntegrator, MASS_KG, PREDICT_STEP,
                    MAX_FLIGHT_SECONDS);
        }
        startDuelRound();
        IterativeAim aimer = new IterativeAim(mismatch ? predictSimulator : flySimulator,
                GRAVITY, TOLERANCE_METRES, MAX_SHOTS, strategy, seed);
        // The whole search, within this frame: the instant mode shows only its last shot.
        result = aimer.aim(TARGET_DISTANCE, HORIZONTAL_SPEED, plan);
        watchSeconds = 0.0;
        for (int i = 0; i < plan.size(); ++i) {
            flownLanding[i] = Double.NaN;
            if (!Double.isNaN(plan.getFlightSeconds(i))) {
                watchSeconds += plan.getFlightSeconds(i);
            }
        }
        firstFlown = instant ? Math.max(0, plan.size() - 1) : 0;
        frameShots();
        fired = firstFlown;
        landed = firstFlown;
        if (plan.size() > 0) {
            fireNext();
        }
    }

    /**
     * Frame the round's highest shot: each shot to be flown is stepped, in the aimer's head,
     * up to its apex (where vy stops being positive).
     */
    private void frameShots() {
        float highest = 0f;
        apexProbe.setMass(MASS_KG);
        for (int i = firstFlown; i < plan.size(); ++i) {
            apexProbe.position.zero();
            apexProbe.velocity.set(plan.getHorizontalSpeed(i), plan.getVerticalSpeed(i), 0f);
            // A shot still climbing after a flight's limit is far above MAX_VIEW_TOP.
            apexFlight.climb(apexProbe, flyStep, (int) Math.ceil(MAX_FLIGHT_SECONDS / flyStep));
            highest = Math.max(highest, apexProbe.position.y);
        }
        getWindow().setViewTop(Math.min(MAX_VIEW_TOP,
                Math.max(MIN_VIEW_TOP, (1f + HEADROOM) * highest)));
    }

    /** Fire the next attempt from the gun in the next slot; fade the older trails. */
    private void fireNext() {
        nextShotDue = false;
        int shot = fired;
        int slot = shot % VISIBLE_SHOTS;
        DemoParticle bullet = slots[slot];
        launchVelocity.set(plan.getHorizontalSpeed(shot), plan.getVerticalSpeed(shot), 0f);
        bullet.setLaunch(gun, launchVelocity);
        launch(bullet, launchVelocity);
        slotShot[slot] = shot;
        ++fired;
        labelChanged[slot] = true;
        tintsChanged = true;
    }

    /** The epilogue of a ground contact: the shot in the air came down there. */
    private void landed(Contact contact) {
        if (contact.getRule() != groundRule || fired == 0 || landed == fired
                || contact.getBodyA() != slots[(fired - 1) % VISIBLE_SHOTS].getBody()) {
            return;
        }
        pendingLandingX = contact.getPoint().x;
    }

    /** A shot's label: its number, vy, and once landed its miss. */
    private String shotLabel(int shot, boolean hasLanded) {
        StringBuilder label = new StringBuilder(40);
        label.append(shot + 1).append(": vy ");
        TextFormat.appendFixed(label, plan.getVerticalSpeed(shot), 1);
        if (hasLanded) {
            label.append(", miss ");
            TextFormat.appendFixed(label, flownLanding[shot] - TARGET_DISTANCE, 1);
        }
        return label.toString();
    }

    /**
     * The attempts table, one column per attempt (the latest {@link #TABLE_COLUMNS} known so
     * far), one row per quantity: shot, vy, landing, miss, and with the mismatch what the
     * aimer predicted.
     */
    private void appendTable(StringBuilder text) {
        // In instant mode every attempt is known at once; else those fired so far.
        int known = instant ? plan.size() : fired;
        int first = Math.max(0, known - TABLE_COLUMNS);
        text.append("shot          ");
        for (int shot = first; shot < known; ++shot) {
            int start = text.length();
            text.append(shot + 1);
            pad(text, start);
        }
        if (first > 0) {
            text.append("     (").append(first).append(" earlier not listed)");
        }
        text.append("\nvy (m/s)      ");
        for (int shot = first; shot < known; ++shot) {
            int start = text.length();
            TextFormat.appendFixed(text, plan.getVerticalSpeed(shot), 2);
            pad(text, start);
        }
        text.append("\nlanding (m)  ");
        for (int shot = first; shot < known; ++shot) {
            appendLanding(text, shot, false);
        }
        text.append("\nmiss (m)       ");
        for (int shot = first; shot < known; ++shot) {
            appendLanding(text, shot, true);
        }
        if (mismatch) {
            text.append("\naimer saw (m)");
            for (int shot = first; shot < known; ++shot) {
                int start = text.length();
                TextFormat.appendFixed(text, plan.getLandingX(shot), 2);
                pad(text, start);
            }
        }
        text.append('\n');
    }

    /** One cell: where an attempt landed or its miss; "air" while in flight. */
    private void appendLanding(StringBuilder text, int shot, boolean miss) {
        int start = text.length();
        double landingX = shot < firstFlown ? plan.getLandingX(shot) : flownLanding[shot];
        if (Double.isNaN(landingX)) {
            text.append(shot < landed ? "never" : "air");
        } else {
            TextFormat.appendFixed(text, miss ? landingX - TARGET_DISTANCE : landingX, 2);
        }
        pad(text, start);
    }

    /** Right-align the cell that starts at start to {@link #CELL_CHARACTERS}. */
    private static void pad(StringBuilder text, int start) {
        for (int i = text.length() - start; i < CELL_CHARACTERS; ++i) {
            text.insert(start, ' ');
        }
    }

    /** Shots used, the instant mode's count, and the mismatch's expected miss. */
    /** Append "1 flown shot" or "3 flown shots": a count, a word before the noun, the noun. */
    private static StringBuilder appendShots(StringBuilder text, int count, String adjective) {
        return text.append(count).append(adjective).append(count == 1 ? " shot" : " shots");
    }

    private void appendSummary(StringBuilder text) {
        int attempts = plan.size();
        if (isRoundOver()) {
            appendShots(text.append("Round over after "), plan.size() - firstFlown, " flown")
                    .append(" (").append(roundKey.getKeyLabel()).append(" fires a new round)\n");
        }
        if (!result.isHit()) {
            text.append("No hit: ").append(result.getExplanation()).append('\n');
        } else if (instant) {
            appendShots(text.append("Instant: "), attempts, "")
                    .append(" in one invisible frame, the last flown; the player would have"
                            + " watched ");
            appendShots(text, attempts, "").append(", ");
            TextFormat.appendFixed(text, watchSeconds, 1).append(" s of flight\n");
        } else {
            text.append("Shots used: ").append(fired).append(" of ").append(attempts)
                    .append(landed == attempts ? " (hit: |miss| ≤ " : " (aim: |miss| ≤ ");
            TextFormat.appendFixed(text, TOLERANCE_METRES, 2).append(" m)\n");
        }
        if (mismatch) {
            text.append("Predictor mismatch: expected miss vx·|h_predict − h_fly| = ");
            TextFormat.appendFixed(text, HORIZONTAL_SPEED, 0).append(" m/s · ");
            TextFormat.appendFixed(text, Math.abs(predictStep - flyStep), 4).append(" s = ");
            TextFormat.appendFixed(text, getExpectedMismatchMiss(), 3).append(" m");
            int last = attempts - 1;
            if (last >= 0 && landed == attempts && !Double.isNaN(flownLanding[last])) {
                text.append(";  the final shot flew ");
                TextFormat.appendFixed(text, flownLanding[last] - plan.getLandingX(last), 3)
                        .append(" m past where the aimer saw it, missing by ");
                TextFormat.appendFixed(text, flownLanding[last] - TARGET_DISTANCE, 3)
                        .append(" m");
            }
            text.append('\n');
        }
    }

    /**
     * The duel's part of a new round: the human's sphere parked, the duel's computer worked
     * out for this seed and step; the duel ends if the round is not the believable player's.
     */
    private void startDuelRound() {
        human.setLaunch(park, Vector3f.ZERO);
        launch(human, Vector3f.ZERO);
        human.setHeld(true);
        humanInAir = false;
        humanLandedPending = false;
        humanShown = 0;
        humanLabelChanged = true;
        roundStartSeconds = getClock().getSimulatedSeconds();
        if (duelOn && (strategy != AimStrategy.BELIEVABLE || instant || mismatch)) {
            duelOn = false;
            getParameters().set("duel", 0);
            getDemoHud().showNotice("the duel is off: it plays the believable player, every"
                    + " shot visible, with the flight's own predictor");
        }
        if (duelOn) {
            duel.setSimulator(flySimulator);
            duel.startRound(seed);
        }
    }

    /** The human's label: their shot's number and aim, once landed its miss. */
    private String humanLabel() {
        int shots = duel.countHumanShots();
        if (!duelOn || shots == 0) {
            return "";
        }
        StringBuilder label = new StringBuilder(40).append("you ").append(shots);
        if (humanShown < shots) {
            TextFormat.appendFixed(label.append(": "), duelDegrees, 1).append("°, ");
            TextFormat.appendFixed(label, duelSpeed, 1).append(" m/s");
        } else {
            TextFormat.appendFixed(label.append(": miss "), duel.getHumanMiss(shots - 1), 1);
        }
        return label.toString();
    }

    /**
     * The duel's lines: the human's aim and shots, the computer's once its round is over, and
     * the poll once the human's is.
     */
    private void appendDuel(StringBuilder text) {
        text.append("Duel, round ").append(duel.getRound()).append(" (seed ").append(seed)
                .append("): your aim ");
        TextFormat.appendFixed(text, duelDegrees, 1).append("° (Up/Down) at ");
        TextFormat.appendFixed(text, duelSpeed, 1).append(" m/s (Left/Right), F fires\n");
        appendHumanShots(text);
        if (duel.isRoundOver() && !humanInAir) {
            text.append(";  felt fair? Y yes, B no");
        }
        appendComputerShots(text.append("\nthe believable player: ")).append('\n');
    }

    /** The computer's round: its shot in the air, or once over its shots, worst and time. */
    private StringBuilder appendComputerShots(StringBuilder text) {
        if (!isRoundOver()) {
            return text.append("shot ").append(fired).append(" in the air");
        }
        appendShots(text, plan.size(), "").append(" to the hit, worst miss ");
        TextFormat.appendFixed(text, duel.worstComputerMiss(), 2).append(" m, ");
        return TextFormat.appendFixed(text, duel.computerSeconds(), 1).append(" s");
    }

    /** The human's shots so far: count, last miss once shown, worst, the hit's time. */
    private void appendHumanShots(StringBuilder text) {
        // A step back may show fewer shots landed than fired, never more.
        int shown = Math.min(humanShown, duel.countHumanShots());
        appendShots(text.append("you: "), duel.countHumanShots(), "");
        if (shown == 0) {
            return;
        }
        double worst = 0.0;
        for (int i = 0; i < shown; ++i) {
            worst = Math.max(worst, Math.abs(duel.getHumanMiss(i)));
        }
        TextFormat.appendFixed(text.append(", last miss "), duel.getHumanMiss(shown - 1), 2);
        TextFormat.appendFixed(text.append(" m, worst "), worst, 2).append(" m");
        if (duel.hasHumanHit() && shown == duel.countHumanShots()) {
            TextFormat.appendFixed(text.append(", hit at "),
                    duel.getHumanLandingSeconds(shown - 1), 1).append(" s");
        }
    }

    private static int indexOfStrategy(AimStrategy wanted) {
        for (int i = 0; i < STRATEGIES.length; ++i) {
            if (STRATEGIES[i] == wanted) {
                return i;
            }
        }
        return -1;
    }

    /**
     * The round's own state, for the ring: the shots fired and landed, each shot's flown
     * landing, which shot each slot shows and what the next step does. The plan is the
     * aimer's, made at the round's start, and not changed by a step.
     */
    private StateRecord roundState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 1 + 1 + 1 + 1 + 2 * MAX_SHOTS + VISIBLE_SHOTS + 3;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putFloat(pendingLandingX);
                slab.putBoolean(nextShotDue);
                slab.putInt(fired);
                slab.putInt(landed);
                for (int i = 0; i < MAX_SHOTS; ++i) {
                    slab.putDouble(flownLanding[i]);
                }
                for (int i = 0; i < VISIBLE_SHOTS; ++i) {
                    slab.putInt(slotShot[i]);
                }
                slab.putBoolean(humanInAir);
                slab.putBoolean(humanLandedPending);
                slab.putInt(humanShown);
            }

            @Override
            public void readState(StateSlab slab) {
                pendingLandingX = slab.getFloat();
                nextShotDue = slab.getBoolean();
                fired = slab.getInt();
                landed = slab.getInt();
                for (int i = 0; i < MAX_SHOTS; ++i) {
                    flownLanding[i] = slab.getDouble();
                }
                for (int i = 0; i < VISIBLE_SHOTS; ++i) {
                    slotShot[i] = slab.getInt();
                    labelChanged[i] = true;
                }
                humanInAir = slab.getBoolean();
                humanLandedPending = slab.getBoolean();
                humanShown = slab.getInt();
                humanLabelChanged = true;
                tintsChanged = true;
            }
        };
    }

    /** The slide: the drag law the aimer steps; the latest shot's miss. */
    @Override
    protected void writePresentation(Presentation slide) {
        StringBuilder formula = slide.formula();
        if (drag == Drag.LINEAR) {
            TextFormat.appendFixed(formula.append("V += h·(g − (b/m)·V),   b/m = "),
                    LINEAR_DRAG / MASS_KG, 2).append(" /s");
        } else {
            TextFormat.appendFixed(formula.append("V += h·(g − (c/m)·|V|·V),   c/m = "),
                    QUADRATIC_DRAG / MASS_KG, 2).append(" /m");
        }
        if (duelOn) {
            // One formula line: each call of slide.formula() starts another.
            StringBuilder aimLine = slide.formula().append("your aim ");
            TextFormat.appendFixed(aimLine, duelDegrees, 1).append("° (Up/Down) at ");
            TextFormat.appendFixed(aimLine, duelSpeed, 1).append(" m/s (Left/Right), F fires");
        } else {
            TextFormat.appendFixed(slide.formula().append("first guess g·S/(2·vx) = "),
                    LevelAim.lectureVy(GRAVITY, TARGET_DISTANCE, HORIZONTAL_SPEED), 2)
                    .append(" m/s, then the aimer's search");
        }
        StringBuilder readout = slide.readout();
        if (duelOn) {
            // The duel's score, short: the slide's type is large.
            int shown = Math.min(humanShown, duel.countHumanShots());
            appendShots(readout.append("you: "), duel.countHumanShots(), "");
            if (shown > 0) {
                TextFormat.appendFixed(readout.append(", last "),
                        duel.getHumanMiss(shown - 1), 2).append(" m");
            }
            readout.append(";  computer: ");
            if (isRoundOver()) {
                appendShots(readout, plan.size(), "");
                TextFormat.appendFixed(readout.append(", worst "), duel.worstComputerMiss(), 1)
                        .append(" m");
            } else {
                readout.append("shot ").append(fired);
            }
            if (duel.isRoundOver() && !humanInAir) {
                readout.append(";  fair? Y / B");
            }
            return;
        }
        if (landed == 0) {
            readout.append("shot 1 in the air");
            return;
        }
        int shot = landed - 1;
        double landingX = shot < firstFlown ? plan.getLandingX(shot) : flownLanding[shot];
        readout.append("shot ").append(shot + 1).append(" of ").append(plan.size());
        if (Double.isNaN(landingX)) {
            readout.append(":  never landed");
        } else {
            TextFormat.appendFixed(readout.append(":  miss "), landingX - TARGET_DISTANCE, 2)
                    .append(" m");
        }
    }
}

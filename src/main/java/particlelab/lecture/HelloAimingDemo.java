package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;
import particlelab.aiming.Landing;
import particlelab.aiming.LevelAim;
import particlelab.aiming.ShotSimulator;
import particlelab.aiming.Flight;
import particlelab.aiming.SlideCodeBullet;
import particlelab.coursework.StudentRunner;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.LaunchControl;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.ParticleView;
import particlelab.view.TextFormat;
import particlelab.view.WallView;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * Demo 5, HelloAiming: a gun at the origin, a target on the same level at {@code S = 100} m,
 * the horizontal speed {@code vx} given (20 m/s to start). Builds upon gravitational pull.
 *
 * <p>The lecture's formula: the flight time is {@code T = S/vx}, and a level shot needs
 * {@code vy = g·T/2 = g·S/(2·vx)}. That is exact for the continuous parabola, but the bullet
 * the game flies is stepped by the Euler method: its samples lie on the parabola launched with
 * {@code vy − g·h/2}, so it lands {@code vx·h} short (a third of a metre at 20 m/s and
 * 60 steps per second). The cure aims for the stepped bullet:
 * {@code vy = g·(S/vx + h)/2} ({@link LevelAim#discreteVy}). With raw tpf the step changes
 * from frame to frame and so does the landing: aim for the h you will actually step with.
 * A new h ({@code --set h=1/10}, the panel) fires the shot in the air again, aimed for it.
 *
 * <p>What to watch for: the gun fires two shots at once, with the same vx, the same step and
 * the same world: the lecture's aim (yellow) and the discrete correction (cyan), each
 * labelled. The HUD predicts each one's landing under the current stepping (a simulated shot
 * with the same integrator) and shows, side by side, where each actually landed and its miss:
 * the lecture's lands {@code vx·h} short, the correction on the target. At 20 m/s and h = 1/60
 * the two arcs are a few centimetres apart, inside one sphere: a longer h (F2's panel) pulls
 * them apart. F fires; L chooses what the next F fires: both, the lecture's aim alone or the
 * correction alone. The bullets stop at the ground, as in the lecture. {@code t} is the
 * flight time of the shots in the air: firing starts it again from 0, and it stops when they
 * land. The shot lines name the shot they describe: while shot N flies, they show shot N in
 * the air and where shot N−1 landed.
 *
 * <p>The slide's own code (J, {@code --set code=both}): a third bullet, a magenta square,
 * moved by the HelloAiming slide's update transcribed literally ({@link SlideCodeBullet}:
 * allocating {@code Vector3f} calls, the step's {@code tpf}, the {@code if (y >= 0)} test),
 * from the same launch as the first recipe bullet. The HUD lists the slide's lines with live
 * comments: in flight its floats are the recipe's, bit for bit; at the end its test lets it
 * step once below the ground, and the HUD gives how far below and how far past the recipe's
 * interpolated crossing it stopped. {@code code=slide} hides the recipe's bullets (they still
 * fly, for the comparison). The lane allocates {@value SlideCodeBullet#VECTORS_PER_STEP}
 * vectors a step by design, so it is off by default (the rest of the frame allocates
 * nothing).
 *
 * <p>The student's aim ({@code --set aim=student}, the last of L's choices): both aims and a
 * third bullet, green, launched with the {@code discreteVy} of exercise 3's class (found by
 * name, as the comparison lane's student recipe is: {@code particlelab.exercises.Aiming}
 * under {@code gradle run}, the reference solution's under {@code -Psolutions}), called once
 * per shot on a worker thread ({@link StudentRunner}). An aim that throws, gives NaN or has
 * not returned within a second fires no student bullet, and one HUD line says why.
 */
public final class HelloAimingDemo extends DemoState {

    /** The distance to the target (m). */
    public static final float TARGET_DISTANCE = 100f;
    /** The starting horizontal speed (m/s). */
    public static final float DEFAULT_VX = 20f;
    /** The horizontal speed's range and step for the keys (m/s). */
    public static final float MIN_VX = 12f;
    public static final float MAX_VX = 60f;
    private static final float VX_STEP = 1f;
    /**
     * The longest step a shot can be aimed for (s): the hitch key's frame, taken as one raw
     * step; the clock caps other frames at less.
     */
    private static final float LONGEST_STEP = Math.max(DemoState.HITCH_SECONDS,
            SimulationClock.DEFAULT_MAX_FRAME_SECONDS);
    /** Room kept above the apex, as a fraction of it. */
    private static final float HEADROOM = 0.12f;
    /** The view never frames less than this height (m): the target and the gun stay clear. */
    private static final float MIN_VIEW_TOP = 20f;
    /** Shots in the air longer than this count as lost (s). */
    private static final float MAX_FLIGHT_SECONDS = 60f;
    private static final float GRAVITY = Gravity.STANDARD_G;
    /** The value of {@link #getFiring()} that fires both aims at once. */
    public static final int BOTH = 2;
    /** The value of {@link #getFiring()} that fires both aims and the student's. */
    public static final int WITH_STUDENT = 3;
    /**
     * The {@code aim} parameter's names: one aim alone, by {@link Aim} ordinal, both, or both
     * with the student's.
     */
    private static final String[] FIRING_NAMES = {"lecture", "discrete", "both", "student"};
    /**
     * What L fires next, by {@link #FIRING_NAMES} index: from the default (both) the lecture's
     * alone, the correction alone, then the student's beside both, and back to both.
     */
    private static final int[] NEXT_FIRING = {1, 3, 0, 2};
    /** The student bullet's colour: the comparison lane's green. */
    private static final ColorRGBA STUDENT_COLOR = new ColorRGBA(0.45f, 1f, 0.35f, 1f);
    /** Each aim's HUD line start, by {@link Aim} ordinal. */
    private static final String[] FORMULAS = {"lecture   vy = g·S/(2·vx) = ",
        "discrete  vy = g·(S/vx + h)/2 = "};
    /** Each aim's bullet colour, by {@link Aim} ordinal. */
    private static final ColorRGBA[] COLORS = {ColorRGBA.Yellow,
        new ColorRGBA(0.3f, 0.85f, 1f, 1f)};

    /** Which formula aims a shot. */
    public enum Aim {
        /** The lecture's {@code vy = g·S/(2·vx)}: lands {@code vx·h} short when stepped. */
        LECTURE,
        /** Corrected for the stepped bullet: {@code vy = g·(S/vx + h)/2}. */
        DISCRETE
    }

    /** The aims in ordinal order, without the copy {@code values()} makes. */
    private static final Aim[] AIMS = Aim.values();
    /** The {@code code} parameter's names: the shared recipe alone, the slide's alone, both. */
    private static final String[] CODE_NAMES = {"recipe", "slide", "both"};
    /** {@link #getCode()}: the shared recipe's bullets alone (the default). */
    public static final int RECIPE_CODE = 0;
    /** {@link #getCode()}: the slide's bullet drawn alone (the recipe's fly hidden). */
    public static final int SLIDE_CODE = 1;
    /** {@link #getCode()}: the slide's bullet beside the recipe's. */
    public static final int BOTH_CODES = 2;
    /** The slide bullet's colour. */
    private static final ColorRGBA SLIDE_COLOR = new ColorRGBA(1f, 0.35f, 0.95f, 1f);
    /**
     * How close {@code S/(vx·h)} must be to a whole number to count as whole: the float h =
     * 1/60 s gives 299.99998 at 20 m/s; a thousandth of a step puts the sample within
     * {@code 0.001·h·|vy|} (under half a millimetre here) of the ground.
     */
    private static final double WHOLE_TOLERANCE = 1e-3;
    /** The slide bullet's square's side (m): larger than the spheres, so it shows around them. */
    /** The fault of this demo, by {@code --set fault=} name, and what it is. */
    static final String Y_LOOP = "y-loop";
    private static final String[] FAULTS = {Y_LOOP};
    private static final String[] FAULT_TITLES = {"the slide's if (y >= 0) loop"};
    private static final String[] FAULT_LABELS = {"y >= 0 loop"};
    private static final float SLIDE_MARK_SIZE = 1.6f;

    private final Gravity gravity = new Gravity();
    private final ParticleIntegrator integrator = new ParticleIntegrator(gravity);
    /** Scratch: g as a vector (m/s²). */
    private final Vector3f gravityVector = new Vector3f();
    /** g, pointing down (m/s²): a parameter. */
    private float g = GRAVITY;
    private float predictedG = Float.NaN;
    /** Each aim's predicted landing, by ordinal. */
    private final Landing[] predicted = {new Landing(), new Landing()};
    private final Vector3f launchVelocity = new Vector3f();
    /** Each aim's bullet, by ordinal: both fly every shot (see {@link #fire()}). */
    private final DemoParticle[] bullets = new DemoParticle[AIMS.length];
    /** What F fires: an aim's ordinal for that aim alone, or {@link #BOTH}. */
    private int firing = BOTH;
    private float vx = DEFAULT_VX;
    private ShotSimulator simulator;
    /** The step and vx the predictions were made for. */
    private float predictedStep = Float.NaN;
    private float predictedVx = Float.NaN;
    /** The number of the shot in the air, or of the last one fired (1 for the first). */
    private int shots;
    /** Per aim: whether the shot in the air fired it, and whether its landing is recorded. */
    private final boolean[] inShot = new boolean[AIMS.length];
    private final boolean[] landingRecorded = new boolean[AIMS.length];
    /** Per aim: the last shot that landed with it: its number (0 if none), where and when. */
    private final int[] landedShot = new int[AIMS.length];
    private final float[] lastLandingX = {Float.NaN, Float.NaN};
    private final double[] lastFlightSeconds = {Double.NaN, Double.NaN};
    /** What the shot in the air fired: an aim's ordinal, or {@link #BOTH}. */
    private int shotFiring = BOTH;
    /** The vx of the last shot that landed, and of the shot in the air (m/s). */
    private float lastShotVx;
    private float shotVx;
    /** The highest vy of the shot in the air (m/s), for the framing. */
    private float shotVy;
    /** The step h the shot in the air was aimed for (s). */
    private float shotStep = Float.NaN;
    /** The demo's keys, named in the HUD. */
    private KeyBinding fireKey;
    private KeyBinding fasterKey;
    private KeyBinding slowerKey;
    private KeyBinding aimKey;
    /** Which code moves the next shot's bullets: {@link #RECIPE_CODE}, ... */
    private int code = RECIPE_CODE;
    /** ... and the shot in the air's. */
    private int shotCode = RECIPE_CODE;
    /** The slide's bullet, flying the first recipe bullet's launch when the shot has it. */
    private final SlideCodeBullet slideBullet = new SlideCodeBullet();
    /** The slide's {@code gravity} vector (m/s²), as its listing holds it. */
    private final Vector3f slideGravity = new Vector3f(0f, -GRAVITY, 0f);
    /** The slide bullet's square in the scene (null without a window). */
    private Geometry slideMark;
    private KeyBinding codeKey;
    /**
     * The bug hunt's switch: {@code fault=y-loop} flies the slide's bullet, its
     * {@code if (y >= 0)} loop, in every shot (an alias of {@code code=both} that the HUD
     * calls a fault); {@code random} hides it until B.
     */
    private final FaultHunt faults = new FaultHunt(FAULTS, FAULT_TITLES, FAULT_LABELS);
    private final StringBuilder consequence = new StringBuilder();
    /** The shot the consequence was flown for: vx, vy, h (NaN: to be flown). */
    private float consequenceVx = Float.NaN;
    private float consequenceVy = Float.NaN;
    private float consequenceStep = Float.NaN;
    /** Where the listing's loop stops the shot: after how many steps, at which x (m). */
    private int faultStopStep;
    private float faultStopX = Float.NaN;
    /** Where the recipe's bullet crosses the ground, interpolated (m). */
    private double crossingX = Double.NaN;
    /** Scratch for the crossing flown ahead. */
    private final Particle flown = new Particle();
    private Flight crossingFlight;
    /** The student's bullet: flies in the shots fired {@link #WITH_STUDENT}. */
    private DemoParticle studentBullet;
    /** The student's aim (null until a shot first asks it). */
    private StudentAim studentAim;
    /** The class it runs (null: exercise 3's, in the package the app was started in). */
    private String studentClass;
    private long studentLimitNanos = StudentRunner.DEFAULT_LIMIT_NANOS;
    /** The shot in the air's student vy (m/s; NaN when it has no student bullet). */
    private float studentVy = Float.NaN;
    private boolean studentInShot;
    private boolean studentLandingRecorded;
    /** The last shot that landed with the student's bullet: its number (0 if none), x. */
    private int studentLandedShot;
    private float studentLandingX = Float.NaN;
    /** The target's distance as printed, e.g. "S = 100 m". */
    private final String distanceText = "S = " + Math.round(TARGET_DISTANCE) + " m";

    /** Create the demo. */
    public HelloAimingDemo() {
        super("HelloAiming");
    }

    /**
     * Return what F fires.
     *
     * @return {@link Aim#ordinal()} of the aim fired alone, or {@link #BOTH}
     */
    public int getFiring() {
        return firing;
    }

    /**
     * Fire one formula alone from the next shot on (the panel's and L's {@code aim}).
     *
     * @param newAim the aim (not null)
     */
    public void setAim(Aim newAim) {
        if (newAim == null) {
            throw new IllegalArgumentException("aim must be LECTURE or DISCRETE, but was null");
        }
        getParameters().set("aim", newAim.ordinal());
    }

    /** Fire both formulas at once from the next shot on: the default. */
    public void setBothAims() {
        getParameters().set("aim", BOTH);
    }

    /**
     * Test whether the next shot fires one aim (alone or beside the other).
     *
     * @param aim the aim (not null)
     * @return true if F fires it
     */
    public boolean firesAim(Aim aim) {
        return firing >= BOTH || firing == aim.ordinal();
    }

    /**
     * Choose the class the student's bullet is aimed by, and how long its call may take: by
     * default {@code Aiming} in the package the app was started with ({@link
     * StudentRunner#className}) and {@link StudentRunner#DEFAULT_LIMIT_NANOS}. Applies from
     * the next shot.
     *
     * @param className an {@link particlelab.coursework.AimingExercise}'s binary name (not
     *     null)
     * @param limitNanos how long one call may take (in ns, &gt;0)
     */
    public void useStudentClass(String className, long limitNanos) {
        if (className == null || className.isEmpty() || limitNanos <= 0L) {
            throw new IllegalArgumentException("the student's aim needs a class name and a"
                    + " time limit > 0 ns, but got " + className + " and " + limitNanos);
        }
        studentClass = className;
        studentLimitNanos = limitNanos;
        studentAim = null;
    }

    /**
     * Access the student's bullet.
     *
     * @return the live particle (not null)
     */
    public DemoParticle getStudentBullet() {
        getWorld();
        return studentBullet;
    }

    /**
     * Return the vy the student's aim gave the shot in the air.
     *
     * @return vy (in m/s; NaN when the shot has no student bullet)
     */
    public float getStudentVy() {
        return studentVy;
    }

    /**
     * Return what kept the shot in the air (or the last one) from the student's aim, in one
     * line.
     *
     * @return the line ("not written yet", "threw ...", ...), or null when the shot had the
     *     student's bullet or did not fire the student's aim
     */
    public String getStudentProblem() {
        // the first shot is fired with the scene; a shot without the student's aim asked
        // nothing of it
        getWorld();
        return studentAim == null || shotFiring != WITH_STUDENT ? null
                : studentAim.getProblem();
    }

    /**
     * Return where the student's bullet of the last shot that fired it landed.
     *
     * @return x (in metres; NaN until such a shot lands)
     */
    public float getStudentLandingX() {
        return studentLandingX;
    }

    /**
     * Return the horizontal speed the gun fires with.
     *
     * @return vx (in m/s)
     */
    public float getHorizontalSpeed() {
        return vx;
    }

    /**
     * Return the vertical speed one formula gives for the current step.
     *
     * @param aim the formula (not null)
     * @return vy (in m/s)
     */
    public float getVerticalSpeed(Aim aim) {
        if (aim == Aim.LECTURE) {
            return (float) LevelAim.lectureVy(g, TARGET_DISTANCE, vx);
        }
        return (float) LevelAim.discreteVy(g, TARGET_DISTANCE, vx,
                getClock().getCurrentStepSeconds());
    }

    /**
     * Return where one aim's bullet of the last shot that fired it landed.
     *
     * @param aim the aim (not null)
     * @return x (in metres; NaN until such a shot lands)
     */
    public float getLastLandingX(Aim aim) {
        return lastLandingX[aim.ordinal()];
    }

    /**
     * Return one aim's predicted landing for the next shot under the current step: a shot
     * simulated with the demo's integrator, g, vx and h.
     *
     * @param aim the aim (not null)
     * @return x (in metres; NaN if it never lands)
     */
    public double getPredictedLandingX(Aim aim) {
        updatePrediction(getClock().getCurrentStepSeconds());
        Landing landing = predicted[aim.ordinal()];
        return landing.hasLanded() ? landing.getX() : Double.NaN;
    }

    /**
     * Access one aim's bullet.
     *
     * @param aim the aim (not null)
     * @return the live particle (not null)
     */
    public DemoParticle getBullet(Aim aim) {
        getWorld();
        return bullets[aim.ordinal()];
    }

    /**
     * Return the number of the shot in the air, or of the last one fired.
     *
     * @return the number (&ge;1 once the demo has started)
     */
    public int getShotNumber() {
        return shots;
    }

    /**
     * Return the number of the last shot that landed with one aim.
     *
     * @param aim the aim (not null)
     * @return the number (0 until such a shot lands)
     */
    public int getLandedShotNumber(Aim aim) {
        return landedShot[aim.ordinal()];
    }

    /**
     * Return the number of the last shot that landed, whichever aims it fired.
     *
     * @return the number (0 until a shot lands)
     */
    public int getLandedShotNumber() {
        return Math.max(landedShot[0], landedShot[1]);
    }

    /**
     * Return the flight time of one aim's bullet of the last shot that fired it, its ground
     * crossing interpolated inside the step.
     *
     * @param aim the aim (not null)
     * @return the time (in seconds; NaN until such a shot lands)
     */
    public double getLastFlightSeconds(Aim aim) {
        return lastFlightSeconds[aim.ordinal()];
    }

    /**
     * Return which code moves the next shot's bullets.
     *
     * @return {@link #RECIPE_CODE}, {@link #SLIDE_CODE} or {@link #BOTH_CODES}
     */
    public int getCode() {
        return code;
    }

    /**
     * Choose which code moves the bullets from the next shot on (the panel's and J's
     * {@code code}).
     *
     * @param newCode {@link #RECIPE_CODE}, {@link #SLIDE_CODE} or {@link #BOTH_CODES}
     */
    public void setCode(int newCode) {
        if (newCode < RECIPE_CODE || newCode > BOTH_CODES) {
            throw new IllegalArgumentException("code must be 0 (recipe), 1 (slide) or 2 (both),"
                    + " but was " + newCode);
        }
        getParameters().set("code", newCode);
    }

    /**
     * Test whether the shot in the air has the slide's bullet.
     *
     * @return true if the slide's code moves a bullet in this shot
     */
    public boolean isSlideInShot() {
        return shotCode != RECIPE_CODE;
    }

    /**
     * Access the slide's bullet (it flies only in shots with {@link #isSlideInShot()}).
     *
     * @return the live bullet (not null)
     */
    public SlideCodeBullet getSlideBullet() {
        return slideBullet;
    }

    /**
     * Return how far past the recipe bullet's interpolated ground crossing the slide's bullet
     * stopped, along x: the slide's last step below the ground.
     *
     * @return the distance (in metres; NaN unless both have landed in this shot)
     */
    public float getSlideOvershootX() {
        if (!isSlideInShot() || !slideBullet.isStopped() || !bullets[0].hasLanded()) {
            return Float.NaN;
        }
        return slideBullet.position.x - bullets[0].getLandingX();
    }

    /**
     * Fire a shot from the gun with the current vx, and start {@code t} again: the HUD's time
     * is this shot's flight time. Both bullets always fly, from the same gun with the same vx
     * and step: each with its own formula when both are fired; when one aim is fired alone,
     * the other bullet flies the same shot, hidden and left out of the HUD.
     */
    public void fire() {
        // The bullets exist once the scene does (a test may fire before any frame).
        getWorld();
        int alone = firing >= BOTH ? -1 : firing;
        shotVy = 0f;
        for (int a = 0; a < AIMS.length; ++a) {
            boolean fired = alone < 0 || alone == a;
            float vy = getVerticalSpeed(AIMS[fired ? a : alone]);
            launchVelocity.set(vx, vy, 0f);
            launch(bullets[a], launchVelocity);
            bullets[a].setParked(!fired);
            inShot[a] = fired;
            landingRecorded[a] = false;
            shotVy = Math.max(shotVy, vy);
        }
        shotFiring = firing;
        fireStudent();
        launchSlide();
        showFiredBullets();
        getClock().reset();
        shotVx = vx;
        shotStep = getClock().getCurrentStepSeconds();
        frameArcs();
        ++shots;
    }

    /**
     * A new h: the discrete aim and the predictions are for it (they read the clock). The
     * shot in the air was aimed for the old h, so it is fired again: aimed for the new h,
     * with the same number if it had not flown yet (a {@code --set h}), as the next shot if
     * it was in flight. A shot that has landed stays as it landed.
     */
    @Override
    protected void onStepChanged(float stepSeconds) {
        if (getClock().getMode() != SimulationClock.Mode.FIXED_STEP
                || stepSeconds == shotStep) {
            return;
        }
        if (bullets[0].getFlightSeconds() == 0.0) {
            reaimUnflown();
        } else if (getLandedShotNumber() != shots) {
            fire();
        }
    }

    @Override
    protected void createScene() {
        // The gun fires once as the demo starts: the first shot, both aims, is in the air at
        // t = 0. The discrete aim is for the clock's step.
        float step = getClock().getCurrentStepSeconds();
        for (int a = 0; a < AIMS.length; ++a) {
            float vy = (float) (AIMS[a] == Aim.LECTURE
                    ? LevelAim.lectureVy(GRAVITY, TARGET_DISTANCE, vx)
                    : LevelAim.discreteVy(GRAVITY, TARGET_DISTANCE, vx, step));
            launchVelocity.set(vx, vy, 0f);
            bullets[a] = addParticle(FIRING_NAMES[a], COLORS[a], Vector3f.ZERO, launchVelocity,
                    1f, integrator).stopAtGround();
            inShot[a] = true;
            shotVy = Math.max(shotVy, vy);
        }
        // The student's bullet flies the first shot's discrete aim, parked and hidden, and
        // stays where it lands until a shot fires the student's aim.
        launchVelocity.set(vx, bullets[Aim.DISCRETE.ordinal()].copyLaunchVelocity(
                new Vector3f()).y, 0f);
        studentBullet = addParticle("student's aim", STUDENT_COLOR, Vector3f.ZERO,
                launchVelocity, 1f, integrator).stopAtGround();
        studentBullet.setParked(true);
        shots = 1;
        shotVx = vx;
        shotStep = step;
        launchSlide();
        // The slide's code runs in the world's steps, after the world has moved the recipe's
        // bullets: both see the same h (the raw tpf in raw mode).
        getRun().addSimulation(this::stepSlide);
        addMarker("gun", 0f, 3f, new ColorRGBA(0.6f, 0.9f, 0.6f, 1f));
        addMarker("target  S = 100 m", TARGET_DISTANCE, 6f, new ColorRGBA(1f, 0.3f, 0.25f, 1f));
        // The grid reaches the highest arc the keys and the panel allow: the slowest vx and
        // the largest g, aimed for the longest step (a level shot's apex g*S^2/(8*vx^2)
        // grows with g). The camera frames only as high as the arcs in play (frameArcs).
        float highestVy = (float) LevelAim.discreteVy(LaunchControl.MAX_G, TARGET_DISTANCE,
                MIN_VX, LONGEST_STEP);
        setView(-6f, 116f, (1f + HEADROOM) * highestVy * highestVy
                / (2f * LaunchControl.MAX_G), 5f, 2, 1.1f);
        showExactGhosts();
        frameArcs();
        addStateRecord(shotState());
    }

    /** The slide code's bullet, a square mark. */
    @Override
    protected void buildViews(Application app) {
        slideMark = WallView.create(app.getAssetManager(), "slide code",
                -SLIDE_MARK_SIZE / 2f, -SLIDE_MARK_SIZE / 2f, SLIDE_MARK_SIZE / 2f,
                SLIDE_MARK_SIZE / 2f, SLIDE_COLOR);
        getSceneNode().attachChild(slideMark);
    }

    @Override
    protected void declareParameters() {
        // The launch is vx; the formula gives vy, so the angle follows from the aim. Both
        // apply to the next shot (the one the HUD predicts), at once, and so does which aims
        // the gun fires.
        declareParameter(new DemoParameter("vx", "launch vx (next shot)",
                "m/s", MIN_VX, MAX_VX, VX_STEP, DEFAULT_VX, 1, DemoParameter.Applies.LIVE,
                this::applyVx));
        declareParameter(new DemoParameter("g", "gravity", "m/s²",
                LaunchControl.MIN_G, LaunchControl.MAX_G, 0.1f, GRAVITY, 2,
                DemoParameter.Applies.LIVE, this::setGravity));
        declareParameter(DemoParameter.choice("aim", "aims fired (next shot)", FIRING_NAMES,
                firing, DemoParameter.Applies.LIVE, this::applyFiring));
        declareParameter(DemoParameter.choice("code", "bullets' code (next shot)", CODE_NAMES,
                code, DemoParameter.Applies.LIVE, this::applyCode));
        declareParameter(faults.switchParameter(this::reaimUnflown));
        declareParameter(faults.seedParameter(this::reaimUnflown));
    }

    @Override
    protected void declareKeys() {
        fireKey = bindKey(KeyInput.KEY_F, "F", "fire", this::fire);
        getKeys().setFireKey(fireKey);
        String step = Math.round(VX_STEP) + " m/s";
        fasterKey = bindKey(KeyInput.KEY_UP, "Up", "vx + " + step, () -> changeVx(VX_STEP));
        slowerKey = bindKey(KeyInput.KEY_DOWN, "Down", "vx - " + step,
                () -> changeVx(-VX_STEP));
        aimKey = bindKey(KeyInput.KEY_L, "L",
                // One help line: wrapped, it pushed the help below 16 px at 1280x720.
                "next shot fires: both aims -> lecture's -> correction -> both + student's",
                () -> getParameters().set("aim", NEXT_FIRING[firing]));
        codeKey = bindKey(KeyInput.KEY_J, "J",
                "next shot's code: shared recipe -> slide's listing -> both",
                () -> getParameters().set("code", (code + 1) % CODE_NAMES.length));
        bindKey(KeyInput.KEY_B, "B", FaultHunt.REVEAL_DESCRIPTION,
                faults::reveal);
    }

    /**
     * Return the fault that runs now.
     *
     * @return its {@code --set fault=} name, or "none"
     */
    public String getActiveFault() {
        return faults.activeName();
    }

    /**
     * Return the seed of "spot the fault" ({@code --set seed=N}), as its pick uses it.
     *
     * @return the seed
     */
    public float getFaultSeed() {
        return faults.getSeed();
    }

    /**
     * Return after how many steps the listing's {@code if (y >= 0)} loop stops the shot in
     * the air, flown ahead in float as the listing computes it (its first sample below
     * {@code y = 0}).
     *
     * @return the step count (0 without the fault)
     */
    public int getFaultStopStep() {
        refreshConsequence();
        return faultStopStep;
    }

    /** Reveal the hidden fault (key B). */
    void revealFault() {
        faults.reveal();
    }

    @Override
    protected void onRestart() {
        shots = 0;
        for (int a = 0; a < AIMS.length; ++a) {
            landedShot[a] = 0;
            lastLandingX[a] = Float.NaN;
            lastFlightSeconds[a] = Double.NaN;
        }
        studentLandedShot = 0;
        studentLandingX = Float.NaN;
        fire();
    }

    @Override
    protected void afterStep(float stepSeconds) {
        for (int a = 0; a < AIMS.length; ++a) {
            DemoParticle bullet = bullets[a];
            if (inShot[a] && bullet.hasLanded() && !landingRecorded[a]) {
                landingRecorded[a] = true;
                landedShot[a] = shots;
                lastLandingX[a] = bullet.getLandingX();
                lastFlightSeconds[a] = bullet.getLandingSeconds();
                lastShotVx = shotVx;
            }
        }
        if (studentInShot && studentBullet.hasLanded() && !studentLandingRecorded) {
            studentLandingRecorded = true;
            studentLandedShot = shots;
            studentLandingX = studentBullet.getLandingX();
        }
    }

    @Override
    protected void initialize(Application app) {
        super.initialize(app);
        showFiredBullets();
    }

    @Override
    protected void afterFrame() {
        if (slideMark != null) {
            slideMark.setLocalTranslation(slideBullet.position.x, slideBullet.position.y, 0.02f);
        }
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("Level target: T = S/vx,  lecture vy = g·S/(2·vx);  Euler lands vx·h short;"
                + "  discrete vy = g·(S/vx + h)/2\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        float step = getClock().getCurrentStepSeconds();
        updatePrediction(step);
        refreshConsequence();
        faults.appendHudLine(text, "B", consequence);
        // Few lines: two aims' numbers share the HUD with two ghost readouts.
        text.append("Next shot (").append(aimKey.getKeyLabel()).append("): ")
                .append(firing == BOTH ? "both aims" : firing == WITH_STUDENT
                        ? "both aims and the student's" : FIRING_NAMES[firing])
                .append(firing >= BOTH ? "" : " alone").append(",  ")
                .append(fireKey.getKeyLabel()).append(" fires;  ").append(distanceText)
                .append(",  vx = ");
        TextFormat.appendFixed(text, vx, 1).append(" m/s (").append(fasterKey.getKeyLabel())
                .append('/').append(slowerKey.getKeyLabel()).append("),  S/vx = ");
        TextFormat.appendFixed(text, TARGET_DISTANCE / vx, 3).append(" s,  vx·h = ");
        TextFormat.appendFixed(text, vx * step, 3).append(" m at h = ");
        TextFormat.appendFixed(text, step * 1000f, 1).append(" ms\n");
        for (int a = 0; a < AIMS.length; ++a) {
            text.append(FORMULAS[a]);
            TextFormat.appendFixed(text, getVerticalSpeed(AIMS[a]), 3)
                    .append(" m/s:  predicted x = ");
            if (predicted[a].hasLanded()) {
                TextFormat.appendFixed(text, predicted[a].getX(), 3).append(" m,  miss ");
                TextFormat.appendFixed(text, predicted[a].getX() - TARGET_DISTANCE, 3)
                        .append(" m\n");
            } else {
                text.append("never lands\n");
            }
        }
        if (firing == WITH_STUDENT || studentInShot || getStudentProblem() != null) {
            writeStudentLine(text);
        }
        if (code != RECIPE_CODE || isSlideInShot() || faults.active() != 0) {
            writeSlideLines(text, step);
        }
        if (getLandedShotNumber() != shots) {
            text.append("Shot ").append(shots).append(": in the air for ");
            DemoParticle flying = bullets[shotFiring >= BOTH ? 0 : shotFiring];
            TextFormat.appendFixed(text, flying.getFlightSeconds(), 2).append(" s  (")
                    .append(FIRING_NAMES[shotFiring]).append(", vx ");
            TextFormat.appendFixed(text, shotVx, 1).append(" m/s)\n");
        }
        // The last shot that landed, its aims' misses side by side.
        int landed = getLandedShotNumber();
        if (landed == 0) {
            return;
        }
        text.append("Shot ").append(landed).append(" landed (vx ");
        TextFormat.appendFixed(text, lastShotVx, 1).append(" m/s):");
        char separator = ' ';
        for (int a = 0; a < AIMS.length; ++a) {
            if (landedShot[a] != landed) {
                continue;
            }
            text.append(separator).append(' ').append(FIRING_NAMES[a]).append(" x = ");
            TextFormat.appendFixed(text, lastLandingX[a], 3).append(" m, miss ");
            TextFormat.appendFixed(text, lastLandingX[a] - TARGET_DISTANCE, 3).append(" m");
            separator = ';';
        }
        if (studentLandedShot == landed) {
            text.append("; student x = ");
            TextFormat.appendFixed(text, studentLandingX, 3).append(" m, miss ");
            TextFormat.appendFixed(text, studentLandingX - TARGET_DISTANCE, 3).append(" m");
        }
        text.append('\n');
    }

    /**
     * The student's aim in one line: the vy it gave the shot beside the lecture's discrete
     * one, or what kept the shot from it.
     */
    private void writeStudentLine(StringBuilder text) {
        text.append("Student's aim (exercise 3), green:  ");
        String problem = getStudentProblem();
        if (problem != null) {
            text.append(problem);
            if (StudentRunner.NOT_WRITTEN.equals(problem)) {
                text.append(": write ").append(studentAim.getClassName())
                        .append(" (docs/exercises.md)");
            }
            text.append('\n');
            return;
        }
        if (!studentInShot) {
            text.append("fires with the next shot\n");
            return;
        }
        TextFormat.appendFixed(text.append("discreteVy = "), studentVy, 3)
                .append(" m/s (the lecture's ");
        TextFormat.appendFixed(text, getVerticalSpeed(Aim.DISCRETE), 3).append(" m/s)\n");
    }

    /**
     * Launch the student's bullet with the student's discrete aim if the shot fires it and
     * the aim returns a number; otherwise park and hide it where it is.
     */
    private void fireStudent() {
        studentInShot = false;
        studentLandingRecorded = false;
        studentVy = Float.NaN;
        float vy = Float.NaN;
        if (firing == WITH_STUDENT) {
            if (studentAim == null) {
                // once per class: a user's choice, not a step, so it may allocate
                studentAim = new StudentAim(studentClass != null ? studentClass
                        : StudentRunner.className(StudentAim.SIMPLE_NAME), studentLimitNanos);
            }
            vy = studentAim.discreteVy(vx, TARGET_DISTANCE, g,
                    getClock().getCurrentStepSeconds());
        }
        studentInShot = !Float.isNaN(vy);
        studentBullet.setParked(!studentInShot);
        if (!studentInShot) {
            // Not launched: a launch keeps the shot before it (F2's kept shots) and marks the
            // replay, which a hidden bullet must not do.
            return;
        }
        studentVy = vy;
        shotVy = Math.max(shotVy, vy);
        launchVelocity.set(vx, vy, 0f);
        launch(studentBullet, launchVelocity);
    }

    /**
     * The slide's listing, one HUD line per code line, with live comments: the step, whether
     * its floats are the recipe's, and where its test let it stop. At most three lines.
     */
    private void writeSlideLines(StringBuilder text, float step) {
        String[] listing = SlideCodeBullet.LISTING;
        text.append("Slide code (").append(codeKey.getKeyLabel()).append(": next ")
                .append(CODE_NAMES[code]).append("), magenta");
        if (faults.active() != 0) {
            text.append(" [FAULT: ").append(faults.isHidden() ? "?" : FAULT_LABELS[0])
                    .append(']');
        }
        text.append(":  ").append(listing[0]);
        if (!isSlideInShot()) {
            text.append("   // not in this shot: fires with the next\n");
            return;
        }
        text.append("   // tpf = ");
        TextFormat.appendFixed(text, step * 1000f, 1).append(" ms a step, ")
                .append(SlideCodeBullet.VECTORS_PER_STEP).append(" new Vector3f each\n");
        text.append(listing[1]).append("   // step ").append(slideBullet.getSteps());
        DemoParticle recipe = bullets[0];
        if (!slideBullet.isStopped()) {
            text.append(", y = ");
            TextFormat.appendFixed(text, slideBullet.position.y, 3).append(" m: ")
                    .append(recipe.hasLanded() ? "the recipe has stopped at the ground"
                            : sameBits(slideBullet.position, recipe.getParticle().position)
                            ? "the recipe's floats, bit for bit" : "NOT the recipe's floats");
        } else {
            text.append(": stopped ");
            TextFormat.appendFixed(text, -slideBullet.position.y, 3)
                    .append(" m below the ground at x = ");
            TextFormat.appendFixed(text, slideBullet.position.x, 3).append(" m");
            float past = getSlideOvershootX();
            if (!Float.isNaN(past)) {
                text.append(", ");
                TextFormat.appendFixed(text, past, 3)
                        .append(" m past the recipe's interpolated crossing");
            }
        }
        text.append('\n').append(listing[2]);
        if (slideBullet.isStopped()) {
            appendSampleNote(text);
        }
        text.append('\n');
    }

    /**
     * Say why the slide's bullet stopped as far below as it did. A level shot's samples lie
     * on a parabola that meets the ground at step {@code S/(vx·h) − 1} (the lecture's aim)
     * or {@code S/(vx·h)} (the discrete one): when {@code S/(vx·h)} is whole a sample lies
     * on {@code y = 0}, and float rounding decides whether {@code y >= 0} stops there (0 m
     * below) or takes one more step; otherwise the first sample below is up to a step past.
     */
    private void appendSampleNote(StringBuilder text) {
        double stepsToTarget = TARGET_DISTANCE / ((double) shotVx * shotStep);
        double whole = Math.rint(stepsToTarget);
        text.append("   // S/(vx·h) = ");
        if (Math.abs(stepsToTarget - whole) < WHOLE_TOLERANCE) {
            text.append((long) whole).append(" is whole: a sample on y = 0, rounding decides");
        } else {
            TextFormat.appendFixed(text, stepsToTarget, 3).append(": no sample on y = 0");
        }
    }

    /**
     * Choose the horizontal speed of the next shot; the camera frames its arc.
     *
     * @param newVx the speed (in m/s, from {@link #MIN_VX} to {@link #MAX_VX})
     */
    public void setHorizontalSpeed(float newVx) {
        if (!(newVx >= MIN_VX && newVx <= MAX_VX)) {
            throw new IllegalArgumentException("vx must be from " + MIN_VX + " to " + MAX_VX
                    + " m/s, but was " + newVx);
        }
        // Through the parameter, so the panel shows it; its setter applies it.
        getParameters().set("vx", newVx);
    }

    /** The vx parameter's setter: the next shot's horizontal speed (m/s). */
    private void applyVx(float newVx) {
        vx = newVx;
        frameArcs();
        reaimUnflown();
    }

    /**
     * The code parameter's setter: from the next shot on, and for the shot in the air too if
     * it has not flown yet (a {@code --set} before the first frame).
     */
    private void applyCode(float value) {
        code = Math.round(value);
        reaimUnflown();
    }

    /** The aim parameter's setter: like {@link #applyCode}. */
    private void applyFiring(float value) {
        firing = Math.round(value);
        reaimUnflown();
    }

    /**
     * Fire the shot in the air again, with the same number, if it has not flown a step yet:
     * the scene fired it before the parameters applied, so a {@code --set} of h, vx, g, aim
     * or code (or a change while paused at its start) would otherwise fly, and the HUD
     * describe, a shot aimed with the old values.
     */
    private void reaimUnflown() {
        if (shots > 0 && bullets[0] != null && bullets[0].getFlightSeconds() == 0.0) {
            --shots;
            fire();
        }
    }

    private void changeVx(float delta) {
        // Through the parameter, so the panel shows what the keys did.
        setHorizontalSpeed(Math.max(MIN_VX, Math.min(MAX_VX, vx + delta)));
    }

    /**
     * Set g for the flight, the aim and the prediction.
     *
     * @param newG g, pointing down (in m/s², &gt;0)
     */
    private void setGravity(float newG) {
        g = newG;
        gravity.setAcceleration(gravityVector.set(0f, -newG, 0f));
        slideGravity.set(0f, -newG, 0f);
        frameArcs();
        reaimUnflown();
    }

    /**
     * Frame both the shot in the air and the one the gun would fire now, apex and all.
     */
    private void frameArcs() {
        // The discrete aim is the higher of the two (for h > 0): it bounds the next shot.
        float highest = Math.max(apex(shotVy), apex(getVerticalSpeed(Aim.DISCRETE)));
        getWindow().setViewTop(Math.max(MIN_VIEW_TOP, (1f + HEADROOM) * highest));
    }

    /**
     * Return the apex of a level shot's continuous parabola, {@code vy²/(2g)}: the stepped
     * shot's samples lie on the parabola launched with {@code vy − g·h/2}, just below it.
     *
     * @param vy the launch's vertical speed (in m/s)
     * @return the height (in metres)
     */
    private float apex(float vy) {
        return vy * vy / (2f * g);
    }

    /**
     * Simulate the shots each formula would fire now, with the current step; only when the
     * step, vx or g changed (a new simulator is made only when the step changed).
     */
    private void updatePrediction(float step) {
        if (step == predictedStep && vx == predictedVx && g == predictedG) {
            return;
        }
        if (simulator == null || simulator.getStepSeconds() != step) {
            simulator = new ShotSimulator(integrator, 1f, step, MAX_FLIGHT_SECONDS);
        }
        for (int a = 0; a < AIMS.length; ++a) {
            simulator.fire(vx, getVerticalSpeed(AIMS[a]), predicted[a]);
        }
        predictedStep = step;
        predictedVx = vx;
        predictedG = g;
    }

    /**
     * Launch the slide's bullet with the first recipe bullet's launch, if the shot has it
     * (the {@code code} chosen for it).
     */
    private void launchSlide() {
        // the fault flies the slide's bullet beside the recipe's, whatever code says
        shotCode = code == RECIPE_CODE && faults.active() != 0 ? BOTH_CODES : code;
        Particle recipe = bullets[0].getParticle();
        slideBullet.launch(recipe.position, recipe.velocity);
    }

    /**
     * The slide's update, one step: the clock's h, the raw tpf in raw mode. Only in a shot
     * that has it: it allocates.
     *
     * @param stepSeconds the step (in seconds, &gt;0)
     */
    private void stepSlide(float stepSeconds) {
        if (isSlideInShot()) {
            slideBullet.update(slideGravity, stepSeconds);
        }
    }

    /**
     * Fly the shot in the air ahead with the listing's loop and with the recipe, and write
     * the fault's consequence, if the shot changed since. Allocates nothing once the flight
     * is made (at the first call).
     */
    private void refreshConsequence() {
        if (faults.active() == 0 || bullets[0] == null) {
            faultStopStep = 0;
            faultStopX = Float.NaN;
            consequence.setLength(0);
            consequenceVx = Float.NaN;
            return;
        }
        float launchVy = bullets[0].copyLaunchVelocity(flown.velocity).y;
        if (shotVx == consequenceVx && launchVy == consequenceVy
                && shotStep == consequenceStep) {
            return;
        }
        consequenceVx = shotVx;
        consequenceVy = launchVy;
        consequenceStep = shotStep;
        // The listing in float, in its order: V = V + g·tpf, then P = P + V·tpf, while y >= 0.
        float gy = slideGravity.y;
        float x = 0f;
        float y = 0f;
        float vxNow = shotVx;
        float vy = launchVy;
        faultStopStep = 0;
        while (y >= 0f && faultStopStep < FaultConsequence.MAX_FLIGHT_STEPS) {
            vy = vy + gy * shotStep;
            x = x + vxNow * shotStep;
            y = y + vy * shotStep;
            ++faultStopStep;
        }
        faultStopX = x;
        if (crossingFlight == null) {
            crossingFlight = new Flight(integrator);
        }
        flown.copyFrom(bullets[0].getParticle());
        bullets[0].copyLaunchPosition(flown.position);
        bullets[0].copyLaunchVelocity(flown.velocity);
        crossingX = Double.NaN;
        for (int n = 1; n <= FaultConsequence.MAX_FLIGHT_STEPS; ++n) {
            double landing = crossingFlight.step(flown, shotStep);
            if (landing != Flight.NO_LANDING) {
                crossingX = crossingFlight.crossingX(landing);
                break;
            }
        }
        consequence.setLength(0);
        consequence.append("stops after step ").append(faultStopStep).append(" at x = ");
        TextFormat.appendFixed(consequence, faultStopX, 2).append(" m, ");
        TextFormat.appendFixed(consequence, faultStopX - crossingX, 2)
                .append(" m past the crossing at ");
        TextFormat.appendFixed(consequence, crossingX, 2).append(" m (vx·h = ");
        TextFormat.appendFixed(consequence, (double) shotVx * shotStep, 2).append(" m)");
    }

    /** Whether two vectors hold the same floats, bit for bit. */
    private static boolean sameBits(Vector3f a, Vector3f b) {
        return Float.floatToIntBits(a.x) == Float.floatToIntBits(b.x)
                && Float.floatToIntBits(a.y) == Float.floatToIntBits(b.y)
                && Float.floatToIntBits(a.z) == Float.floatToIntBits(b.z);
    }

    /**
     * Hide the bullet of an aim the shot in the air did not fire (it flies the fired one's
     * shot, so its sphere, trail and label would only cover the other's; its exact ghost is
     * the fired one's path, drawn twice); show the others. Views exist only in a window.
     */
    private void showFiredBullets() {
        for (int a = 0; a < AIMS.length; ++a) {
            ParticleView view = getWindow().getView(bullets[a]);
            if (view != null) {
                view.getNode().setCullHint(inShot[a] && shotCode != SLIDE_CODE
                        ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
            }
        }
        ParticleView student = getWindow().getView(studentBullet);
        if (student != null) {
            student.getNode().setCullHint(studentInShot && shotCode != SLIDE_CODE
                    ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
        }
        if (slideMark != null) {
            slideMark.setCullHint(isSlideInShot() ? Spatial.CullHint.Inherit
                    : Spatial.CullHint.Always);
        }
    }

    /** The demo's own state, for the ring: the shot in the air and the last ones landed. */
    private StateRecord shotState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 1 + 4 * AIMS.length + 2 * AIMS.length + 1 + 1 + 1 + 1 + 1
                        + 1 + 3 + 3 + 1 + 5;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putInt(shots);
                for (int a = 0; a < AIMS.length; ++a) {
                    slab.putBoolean(inShot[a]);
                    slab.putBoolean(landingRecorded[a]);
                    slab.putInt(landedShot[a]);
                    slab.putFloat(lastLandingX[a]);
                    slab.putDouble(lastFlightSeconds[a]);
                }
                slab.putInt(shotFiring);
                slab.putFloat(lastShotVx);
                slab.putFloat(shotVx);
                slab.putFloat(shotVy);
                slab.putFloat(shotStep);
                slab.putInt(shotCode);
                slab.putVector(slideBullet.position);
                slab.putVector(slideBullet.velocity);
                slab.putInt(slideBullet.getSteps());
                slab.putBoolean(studentInShot);
                slab.putBoolean(studentLandingRecorded);
                slab.putInt(studentLandedShot);
                slab.putFloat(studentLandingX);
                slab.putFloat(studentVy);
            }

            @Override
            public void readState(StateSlab slab) {
                shots = slab.getInt();
                for (int a = 0; a < AIMS.length; ++a) {
                    inShot[a] = slab.getBoolean();
                    landingRecorded[a] = slab.getBoolean();
                    landedShot[a] = slab.getInt();
                    lastLandingX[a] = slab.getFloat();
                    lastFlightSeconds[a] = slab.getDouble();
                }
                shotFiring = slab.getInt();
                lastShotVx = slab.getFloat();
                shotVx = slab.getFloat();
                shotVy = slab.getFloat();
                shotStep = slab.getFloat();
                shotCode = slab.getInt();
                slab.getVector(slideBullet.position);
                slab.getVector(slideBullet.velocity);
                slideBullet.setSteps(slab.getInt());
                studentInShot = slab.getBoolean();
                studentLandingRecorded = slab.getBoolean();
                studentLandedShot = slab.getInt();
                studentLandingX = slab.getFloat();
                studentVy = slab.getFloat();
                showFiredBullets();
            }
        };
    }

    /** The slide: the two aims' vy; the last landed shot's misses side by side. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        for (int a = 0; a < AIMS.length; ++a) {
            StringBuilder formula = slide.formula().append(FORMULAS[a]);
            TextFormat.appendFixed(formula, getVerticalSpeed(AIMS[a]), 3).append(" m/s");
        }
        StringBuilder readout = slide.readout();
        int landed = getLandedShotNumber();
        if (landed == 0) {
            readout.append("shot ").append(getShotNumber()).append(" in the air");
            return;
        }
        readout.append("shot ").append(landed).append(":");
        char separator = ' ';
        for (int a = 0; a < AIMS.length; ++a) {
            if (landedShot[a] != landed) {
                continue;
            }
            readout.append(separator).append(' ').append(FIRING_NAMES[a]).append(" miss ");
            TextFormat.appendFixed(readout, lastLandingX[a] - TARGET_DISTANCE, 3).append(" m");
            separator = ';';
        }
    }
}

package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.aiming.Landing;
import particlelab.aiming.LevelAim;
import particlelab.aiming.ShotSimulator;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.LaunchControl;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

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
 *
 * <p>What to watch for: the HUD predicts the landing under the current stepping (a simulated
 * shot with the same integrator) and shows where the shot actually landed; press L to switch
 * formulas and F to fire. The bullet stops at the ground, as in the lecture. {@code t} is the
 * flight time of the shot in the air: firing starts it again from 0, and it stops when the
 * shot lands. The shot line names the shot it describes: while shot N flies, it shows shot N
 * in the air and where shot N−1 landed.
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

    /** Which formula aims the gun. */
    public enum Aim {
        /** The lecture's {@code vy = g·S/(2·vx)}: lands {@code vx·h} short when stepped. */
        LECTURE,
        /** Corrected for the stepped bullet: {@code vy = g·(S/vx + h)/2}. */
        DISCRETE
    }

    private final Gravity gravity = new Gravity();
    private final ParticleIntegrator integrator = new ParticleIntegrator(gravity);
    /** Scratch: g as a vector (m/s²). */
    private final Vector3f gravityVector = new Vector3f();
    /** g, pointing down (m/s²): a parameter. */
    private float g = GRAVITY;
    private float predictedG = Float.NaN;
    private final Landing predicted = new Landing();
    private final Vector3f launchVelocity = new Vector3f();
    private DemoParticle bullet;
    private Aim aim = Aim.LECTURE;
    private float vx = DEFAULT_VX;
    private ShotSimulator simulator;
    /** The step, vx and aim the prediction was made for. */
    private float predictedStep = Float.NaN;
    private float predictedVx = Float.NaN;
    private Aim predictedAim;
    /** The number of the shot in the air, or of the last one fired (1 for the first). */
    private int shots;
    private boolean landingRecorded;
    /** The last shot that landed: its number (0 if none yet), where, when, vx and formula. */
    private int landedShot;
    private float lastLandingX = Float.NaN;
    private double lastFlightSeconds = Double.NaN;
    private float lastShotVx;
    private Aim lastShotAim = Aim.LECTURE;
    /** The vx and formula of the shot in the air. */
    private float shotVx;
    private float shotVy;
    private Aim shotAim = Aim.LECTURE;
    /** The demo's keys, named in the HUD. */
    private KeyBinding fireKey;
    private KeyBinding fasterKey;
    private KeyBinding slowerKey;
    private KeyBinding aimKey;
    /** The target's distance as printed, e.g. "S = 100 m". */
    private final String distanceText = "S = " + Math.round(TARGET_DISTANCE) + " m";

    /** Create the demo. */
    public HelloAimingDemo() {
        super("HelloAiming");
    }

    /**
     * Return the formula in use.
     *
     * @return the aim (not null)
     */
    public Aim getAim() {
        return aim;
    }

    /**
     * Choose the formula; the next shot uses it.
     *
     * @param newAim the aim (not null)
     */
    public void setAim(Aim newAim) {
        if (newAim == null) {
            throw new IllegalArgumentException("aim must be LECTURE or DISCRETE, but was null");
        }
        aim = newAim;
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
     * Return the vertical speed the current formula gives for the current step.
     *
     * @return vy (in m/s)
     */
    public float getVerticalSpeed() {
        if (aim == Aim.LECTURE) {
            return (float) LevelAim.lectureVy(g, TARGET_DISTANCE, vx);
        }
        return (float) LevelAim.discreteVy(g, TARGET_DISTANCE, vx,
                getClock().getCurrentStepSeconds());
    }

    /**
     * Return where the last shot landed.
     *
     * @return x (in metres; NaN until a shot lands)
     */
    public float getLastLandingX() {
        return lastLandingX;
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
     * Return the number of the last shot that landed.
     *
     * @return the number (0 until a shot lands)
     */
    public int getLandedShotNumber() {
        return landedShot;
    }

    /**
     * Return the flight time of the last shot that landed, its ground crossing interpolated
     * inside the step.
     *
     * @return the time (in seconds; NaN until a shot lands)
     */
    public double getLastFlightSeconds() {
        return lastFlightSeconds;
    }

    /**
     * Fire a shot from the gun with the current vx and formula, and start {@code t} again:
     * the HUD's time is this shot's flight time.
     */
    public void fire() {
        launchVelocity.set(vx, getVerticalSpeed(), 0f);
        launch(bullet, launchVelocity);
        getClock().reset();
        shotVx = vx;
        shotVy = launchVelocity.y;
        shotAim = aim;
        frameArcs();
        landingRecorded = false;
        ++shots;
    }

    @Override
    protected void createScene() {
        launchVelocity.set(vx, (float) LevelAim.lectureVy(GRAVITY, TARGET_DISTANCE, vx), 0f);
        // The gun fires once as the demo starts: the first shot is in the air at t = 0.
        bullet = addParticle("bullet", ColorRGBA.Yellow, Vector3f.ZERO, launchVelocity, 1f,
                integrator).stopAtGround();
        shots = 1;
        shotVx = vx;
        shotVy = launchVelocity.y;
        shotAim = aim;
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
    }

    @Override
    protected void declareParameters() {
        // The launch is vx; the formula gives vy, so the angle follows from the aim. Both
        // apply to the next shot (the one the HUD predicts), at once.
        declareParameter(new DemoParameter("vx", "launch vx (next shot)",
                "m/s", MIN_VX, MAX_VX, VX_STEP, DEFAULT_VX, 1, DemoParameter.Applies.LIVE,
                this::applyVx));
        declareParameter(new DemoParameter("g", "gravity", "m/s²",
                LaunchControl.MIN_G, LaunchControl.MAX_G, 0.1f, GRAVITY, 2,
                DemoParameter.Applies.LIVE, this::setGravity));
    }

    @Override
    protected void declareKeys() {
        fireKey = bindKey(KeyInput.KEY_F, "F", "fire", this::fire);
        setFireKey(fireKey);
        String step = Math.round(VX_STEP) + " m/s";
        fasterKey = bindKey(KeyInput.KEY_UP, "Up", "vx + " + step, () -> changeVx(VX_STEP));
        slowerKey = bindKey(KeyInput.KEY_DOWN, "Down", "vx - " + step,
                () -> changeVx(-VX_STEP));
        aimKey = bindKey(KeyInput.KEY_L, "L", "aim: lecture formula <-> discrete correction",
                () -> setAim(aim == Aim.LECTURE ? Aim.DISCRETE : Aim.LECTURE));
    }

    @Override
    protected void onRestart() {
        shots = 0;
        landedShot = 0;
        lastLandingX = Float.NaN;
        lastFlightSeconds = Double.NaN;
        fire();
    }

    @Override
    protected void afterStep(float stepSeconds) {
        if (bullet.hasLanded() && !landingRecorded) {
            landingRecorded = true;
            landedShot = shots;
            lastLandingX = bullet.getLandingX();
            lastFlightSeconds = bullet.getLandingSeconds();
            lastShotVx = shotVx;
            lastShotAim = shotAim;
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
        text.append(aim == Aim.LECTURE ? "Aim: LECTURE vy = g·S/(2·vx)"
                : "Aim: DISCRETE vy = g·(S/vx + h)/2");
        text.append("   (").append(aimKey.getKeyLabel()).append(" switches, ")
                .append(fireKey.getKeyLabel()).append(" fires, ")
                .append(fasterKey.getKeyLabel()).append('/').append(slowerKey.getKeyLabel())
                .append(" change vx)\n");
        text.append(distanceText).append(",  vx = ");
        TextFormat.appendFixed(text, vx, 1).append(" m/s,  vy = ");
        TextFormat.appendFixed(text, getVerticalSpeed(), 3).append(" m/s,  flight S/vx = ");
        TextFormat.appendFixed(text, TARGET_DISTANCE / vx, 3).append(" s\n");
        text.append("Predicted landing with h = ");
        TextFormat.appendFixed(text, step * 1000f, 1).append(" ms:  x = ");
        if (predicted.hasLanded()) {
            TextFormat.appendFixed(text, predicted.getX(), 3).append(" m,  miss ");
            TextFormat.appendFixed(text, predicted.getX() - TARGET_DISTANCE, 3);
            text.append(" m   (vx·h = ");
            TextFormat.appendFixed(text, vx * step, 3).append(" m)\n");
        } else {
            text.append("never lands\n");
        }
        if (landedShot != shots) {
            text.append("Shot ").append(shots).append(": in the air for ");
            TextFormat.appendFixed(text, bullet.getFlightSeconds(), 2).append(" s  (");
            appendShot(text, shotAim, shotVx).append(")\n");
        }
        if (landedShot > 0) {
            text.append("Shot ").append(landedShot).append(": landed at x = ");
            TextFormat.appendFixed(text, lastLandingX, 3).append(" m after ");
            TextFormat.appendFixed(text, lastFlightSeconds, 3).append(" s,  miss ");
            TextFormat.appendFixed(text, lastLandingX - TARGET_DISTANCE, 3).append(" m  (");
            appendShot(text, lastShotAim, lastShotVx).append(")\n");
        }
    }

    private static StringBuilder appendShot(StringBuilder text, Aim shotAim, float shotVx) {
        text.append(shotAim == Aim.LECTURE ? "lecture" : "discrete").append(", vx ");
        return TextFormat.appendFixed(text, shotVx, 1).append(" m/s");
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
        frameArcs();
    }

    /**
     * Frame both the shot in the air and the one the gun would fire now, apex and all.
     */
    private void frameArcs() {
        float highest = Math.max(apex(shotVy), apex(getVerticalSpeed()));
        setViewTop(Math.max(MIN_VIEW_TOP, (1f + HEADROOM) * highest));
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
     * Simulate the shot the gun would fire now, with the current step; only when the step, vx
     * or the formula changed (a new simulator is made only when the step changed).
     */
    private void updatePrediction(float step) {
        if (step == predictedStep && vx == predictedVx && aim == predictedAim
                && g == predictedG) {
            return;
        }
        if (simulator == null || simulator.getStepSeconds() != step) {
            simulator = new ShotSimulator(integrator, 1f, step, MAX_FLIGHT_SECONDS);
        }
        simulator.fire(vx, getVerticalSpeed(), predicted);
        predictedStep = step;
        predictedVx = vx;
        predictedAim = aim;
        predictedG = g;
    }

    /** The slide: the aim formula with its vx and vy; the last shot's miss. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        StringBuilder formula = slide.formula().append(getAim() == Aim.LECTURE
                ? "lecture  vy = g·S/(2·vx) = " : "discrete  vy = g·(S/vx + h)/2 = ");
        TextFormat.appendFixed(formula, getVerticalSpeed(), 3).append(" m/s,   vx = ");
        TextFormat.appendFixed(formula, getHorizontalSpeed(), 1).append(" m/s");
        StringBuilder readout = slide.readout();
        if (getLandedShotNumber() == 0) {
            readout.append("shot ").append(getShotNumber()).append(" in the air");
        } else {
            readout.append("shot ").append(getLandedShotNumber()).append(":  miss ");
            TextFormat.appendFixed(readout, getLastLandingX() - TARGET_DISTANCE, 3)
                    .append(" m");
        }
    }
}

package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.CollisionSounds;
import particlelab.view.SilentSoundPlayer;
import particlelab.view.SoundPlayer;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.Detection;
import particlelab.world.HopCycle;
import particlelab.world.ImpulseResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * Demo 7, bounce: a ball of radius R dropped from rest onto the ground, the first collision
 * response of the lecture. Builds upon gravitational pull (the fall is its parabola) and adds
 * one collision rule to the demo's world: the ground {@code y = 0}, resolved by an impulse
 * along the normal, {@code v' = −e·v}.
 *
 * <p>What to watch for:
 * <ul>
 * <li>The ideal ball climbs to {@code e^{2n}·h0} after its n-th impact and comes to rest after
 * {@code T = t0(1+e)/(1−e)}, {@code t0 = √(2h0/g)} (a geometric series of flights); the HUD
 * puts the stepped ball's apexes and rest time next to these.</li>
 * <li>The restitution threshold (none, Cyclone's 0.25 m/s, Box2D's and Jolt's 1 m/s): an impact
 * at or below it is perfectly inelastic. It is no sure cure. Without the resting fix the
 * swept ball settles on hops of K whole steps (the rest of an impact's step has no gravity)
 * whose impact speed is the fixed point {@code w* = K·g·h/(1+e)} of
 * {@link HopCycle}: after this demo's 4 m drop with e = 0.8, K = 4 and w* = 0.363 m/s, so
 * Cyclone's 0.25 m/s never stops it (the HUD says so and shows w*) and Box2D's 1 m/s does.
 * A threshold stops a ball on its hop only when {@code w* ≤ v_t}.</li>
 * <li>The resting fix (Cyclone's): the rebound leaves out the velocity gravity added during
 * the step, {@code v' = e·(v − g·h)}, so a ball lying on the ground stays exactly still and
 * no hop can repeat: the only cure that always works. The price is a slightly lower apex
 * after every impact (press F and compare the apexes with {@code e^{2n}·h0}). With the fix
 * off the ball hops at w* for ever unless the threshold is at or above it.</li>
 * <li>Overlap test against intersection (swept) test: with e = 1 the overlap test finds the
 * ball inside the ground and pushes it out, and its apexes drift; the swept test finds the
 * moment of impact on the step's straight segment. A hidden second world runs the other test
 * with the same ball, so the HUD shows both drifts.</li>
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
    /** The restitution e at the start, in tenths. */
    public static final int START_E_TENTHS = 8;
    /** The threshold presets (in m/s): none, Cyclone's, Box2D's and Jolt's. */
    static final float[] THRESHOLDS = {0f, ImpulseResponse.CYCLONE_THRESHOLD,
        ImpulseResponse.BOX2D_THRESHOLD};
    /** The presets' names, in the order of {@link #THRESHOLDS}. */
    static final String[] THRESHOLD_NAMES = {"none", "Cyclone", "Box2D/Jolt"};
    /** The presets' command-line names, in the order of {@link #THRESHOLDS}. */
    static final String[] THRESHOLD_KEYS = {"none", "cyclone", "box2d"};
    /** Apexes shown on the HUD, the latest ones. */
    private static final int APEXES_SHOWN = 4;
    /**
     * The hop counts as settled (the HUD names its fixed point) once the latest impact speed
     * is this close to w*, relatively: the speeds approach it by a factor e a hop, so a ball
     * still wandering between hop lengths is not taken for one on its hop.
     */
    private static final double SETTLED_FRACTION = 0.05;

    private final ImpulseResponse response = new ImpulseResponse(START_E_TENTHS / 10f);
    private final ImpulseResponse otherResponse = new ImpulseResponse(START_E_TENTHS / 10f);
    private final World other = new World();
    private int eTenths = START_E_TENTHS;
    private int thresholdPreset;
    private Detection detection = Detection.SWEPT;
    private SurfaceRule ground;
    private SurfaceRule otherGround;
    private Body ball;
    private BounceRecorder recorder;
    private BounceRecorder otherRecorder;
    private CollisionSounds sounds;

    /** Create the demo. */
    public BounceDemo() {
        super("Bounce");
    }

    @Override
    protected void createScene() {
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Vector3f start = new Vector3f(0f, DROP_HEIGHT + RADIUS, 0f);
        DemoParticle demoBall = addParticle("ball", ColorRGBA.Orange, start, Vector3f.ZERO,
                MASS_KG, gravity);
        ball = demoBall.getBody();
        ball.setRadius(RADIUS);
        recorder = new BounceRecorder(ball);
        getWorld().addContactListener(recorder);
        getWorld().addStepListener(recorder);
        Body otherBall = other.addBody(gravity, start, Vector3f.ZERO, MASS_KG, RADIUS);
        otherRecorder = new BounceRecorder(otherBall);
        other.addContactListener(otherRecorder);
        other.addStepListener(otherRecorder);
        // The other detection's lane is a second world beside this one, on the same clock.
        addSimulation(other);
        applyRules();
        sounds = new CollisionSounds(getApplication() == null
                ? new SilentSoundPlayer(SoundPlayer.NO_AUDIO_DEVICE)
                : SoundPlayer.forApplication(getApplication()));
        setView(-4f, 4f, DROP_HEIGHT + 2f * RADIUS + 0.5f, 0.5f, 2, RADIUS);
    }

    @Override
    protected void declareParameters() {
        // A new e drops the ball again, as the Up and Down keys do.
        declareParameter(new DemoParameter("e", "restitution", "", 0f, 1f,
                0.1f, START_E_TENTHS / 10f, 1, DemoParameter.Applies.LIVE, value -> {
                    int tenths = Math.round(value * 10f);
                    if (tenths != eTenths) {
                        configure(tenths, thresholdPreset, response.isRestingFix(), detection);
                    }
                }));
        // The threshold, the resting fix and the detection test, as P, F and O switch them.
        declareParameter(DemoParameter.choice("threshold", "threshold speed", THRESHOLD_KEYS,
                thresholdPreset, DemoParameter.Applies.LIVE, value -> {
                    if (Math.round(value) != thresholdPreset) {
                        configure(eTenths, Math.round(value), response.isRestingFix(),
                                detection);
                    }
                }));
        declareParameter(DemoParameter.choice("fix", "resting fix", new String[] {"off", "on"},
                response.isRestingFix() ? 1 : 0, DemoParameter.Applies.LIVE, value -> {
                    if ((Math.round(value) == 1) != response.isRestingFix()) {
                        configure(eTenths, thresholdPreset, Math.round(value) == 1, detection);
                    }
                }));
        declareParameter(DemoParameter.choice("detection", "ground test",
                new String[] {"swept", "overlap"}, detection == Detection.SWEPT ? 0 : 1,
                DemoParameter.Applies.LIVE, value -> {
                    Detection wanted = Math.round(value) == 0 ? Detection.SWEPT
                            : Detection.OVERLAP;
                    if (wanted != detection) {
                        configure(eTenths, thresholdPreset, response.isRestingFix(), wanted);
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
        bindKey(KeyInput.KEY_O, "O", "detection: swept (intersection test) <-> overlap test",
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
    protected void afterFrame() {
        sounds.playFrame(getWorld());
    }

    @Override
    protected void onRestart() {
        other.restart();
        recorder.clear();
        otherRecorder.clear();
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        float e = getRestitution();
        text.append("e = ");
        TextFormat.appendFixed(text, e, 1).append("   threshold ");
        TextFormat.appendFixed(text, THRESHOLDS[thresholdPreset], 2).append(" m/s (")
                .append(THRESHOLD_NAMES[thresholdPreset]).append(")   resting fix ")
                .append(response.isRestingFix() ? "on" : "off").append("   detection: ")
                .append(detection == Detection.SWEPT ? "swept (intersection test)"
                        : "overlap test")
                .append('\n');
        float g = Gravity.STANDARD_G;
        float t0 = (float) Math.sqrt(2.0 * DROP_HEIGHT / g);
        text.append("h0 = ");
        TextFormat.appendFixed(text, DROP_HEIGHT, 2).append(" m   t0 = sqrt(2 h0/g) = ");
        TextFormat.appendFixed(text, t0, 3).append(" s   impacts: ")
                .append(recorder.countImpacts()).append("   last impact speed ");
        TextFormat.appendFixed(text, recorder.getLastImpactSpeed(), 2).append(" m/s\n");
        appendApexes(text, e);
        text.append("time to rest: T = t0 (1+e)/(1-e) = ");
        if (eTenths == 10) {
            text.append("never (e = 1)");
        } else {
            TextFormat.appendFixed(text, t0 * (1f + e) / (1f - e), 3).append(" s");
        }
        text.append(",  measured ");
        if (recorder.isResting()) {
            TextFormat.appendFixed(text, recorder.getRestSeconds(), 3).append(" s\n");
        } else {
            text.append("still bouncing\n");
            appendHopCycle(text, e);
        }
        Vector3f v = ball.getVelocity();
        float energy = 0.5f * MASS_KG * v.lengthSquared()
                + MASS_KG * g * (ball.getPosition().y - RADIUS);
        text.append("energy E = m v²/2 + m g (y − R) = ");
        TextFormat.appendFixed(text, energy, 3).append(" J   at the drop m g h0 = ");
        TextFormat.appendFixed(text, MASS_KG * g * DROP_HEIGHT, 3).append(" J\n");
        if (eTenths == 10) {
            appendDrift(text);
        }
        sounds.getPlayer().getLog().appendLatest(text).append('\n');
    }

    /**
     * Return the restitution now.
     *
     * @return e (0 to 1)
     */
    public float getRestitution() {
        return eTenths / 10f;
    }

    /**
     * Access the measurements of the ball on screen.
     *
     * @return the live recorder (not null after initialisation)
     */
    BounceRecorder getRecorder() {
        return recorder;
    }

    /**
     * Access the measurements of the hidden ball that runs the other test.
     *
     * @return the live recorder (not null after initialisation)
     */
    BounceRecorder getOtherRecorder() {
        return otherRecorder;
    }

    /**
     * Return the detection of the ball on screen.
     *
     * @return the detection (not null)
     */
    public Detection getDetection() {
        return detection;
    }

    /**
     * Set e, the threshold preset, the resting fix and the detection, then drop again (what
     * the keys do, for tests and scripts).
     *
     * @param newETenths e in tenths (0 to 10)
     * @param preset index into the threshold presets (0 to 2)
     * @param restingFix true for the resting fix
     * @param newDetection the ball's detection (not null)
     */
    public void configure(int newETenths, int preset, boolean restingFix,
            Detection newDetection) {
        if (newETenths < 0 || newETenths > 10 || preset < 0 || preset >= THRESHOLDS.length
                || newDetection == null) {
            throw new IllegalArgumentException("e tenths must be 0 to 10 and preset 0 to "
                    + (THRESHOLDS.length - 1) + ", but were " + newETenths + ", " + preset
                    + ", " + newDetection);
        }
        eTenths = newETenths;
        thresholdPreset = preset;
        response.setRestingFix(restingFix);
        detection = newDetection;
        applyRules();
        refreshEquations();
        // The panel shows the e the keys or a caller chose.
        getParameters().set("e", eTenths / 10f);
        getParameters().set("threshold", thresholdPreset);
        getParameters().set("fix", restingFix ? 1 : 0);
        getParameters().set("detection", detection == Detection.SWEPT ? 0 : 1);
        restart();
    }

    private void appendApexes(StringBuilder text, float e) {
        text.append("apex after impact n, measured / ideal e^2n h0:");
        int count = recorder.countApexes();
        if (count == 0) {
            text.append(" none yet");
        }
        for (int i = Math.max(0, count - APEXES_SHOWN); i < count; ++i) {
            int n = i + 1;
            text.append("   ").append(n).append(": ");
            TextFormat.appendFixed(text, recorder.getApex(i), 3).append(" / ");
            TextFormat.appendFixed(text, DROP_HEIGHT * Math.pow(e, 2.0 * n), 3);
        }
        text.append(" m\n");
    }

    /**
     * When the ball, without the resting fix, has settled on a hop of K whole steps (the last
     * two hops that long, the impact speed near w*) whose fixed-point impact speed w* is
     * above the threshold: the reason it never rests.
     */
    private void appendHopCycle(StringBuilder text, float e) {
        int stepsPerHop = recorder.getLastHopSteps();
        float h = recorder.getLastStepSeconds();
        if (response.isRestingFix() || eTenths == 10 || detection != Detection.SWEPT
                || !recorder.isHopRepeating() || !(h > 0f)) {
            return;
        }
        float threshold = THRESHOLDS[thresholdPreset];
        float g = Gravity.STANDARD_G;
        double fixedPoint = HopCycle.fixedPointSpeed(stepsPerHop, e, g, h);
        if (HopCycle.thresholdStops(threshold, stepsPerHop, e, g, h) || Math.abs(
                recorder.getLastImpactSpeed() - fixedPoint) > SETTLED_FRACTION * fixedPoint) {
            return;
        }
        text.append("never at rest: hops of K = ").append(stepsPerHop)
                .append(" steps, fixed point w* = K g h/(1+e) = ");
        TextFormat.appendFixed(text, fixedPoint, 3).append(" m/s > threshold ");
        TextFormat.appendFixed(text, threshold, 2).append(" m/s\n");
    }

    private void appendDrift(StringBuilder text) {
        int n = Math.min(recorder.countApexes(), otherRecorder.countApexes());
        text.append("e = 1, apex drift (apex - h0) after ").append(n).append(" bounces:");
        BounceRecorder overlap = detection == Detection.OVERLAP ? recorder : otherRecorder;
        BounceRecorder swept = detection == Detection.OVERLAP ? otherRecorder : recorder;
        text.append("   overlap test ");
        appendSignedDrift(text, overlap, n);
        text.append("   swept test ");
        appendSignedDrift(text, swept, n);
        text.append('\n');
    }

    private static void appendSignedDrift(StringBuilder text, BounceRecorder from, int n) {
        if (n == 0) {
            text.append("-");
            return;
        }
        float drift = from.getApex(n - 1) - DROP_HEIGHT;
        if (drift >= 0f) {
            text.append('+');
        }
        TextFormat.appendFixed(text, drift, 4).append(" m");
    }

    private void changeE(int tenths) {
        configure(Math.max(0, Math.min(10, eTenths + tenths)), thresholdPreset,
                response.isRestingFix(), detection);
    }

    private void nextThreshold() {
        configure(eTenths, (thresholdPreset + 1) % THRESHOLDS.length, response.isRestingFix(),
                detection);
    }

    private void toggleRestingFix() {
        configure(eTenths, thresholdPreset, !response.isRestingFix(), detection);
    }

    private void toggleDetection() {
        configure(eTenths, thresholdPreset, response.isRestingFix(),
                detection == Detection.SWEPT ? Detection.OVERLAP : Detection.SWEPT);
    }

    /** Put the ground rules in both worlds: this test here, the other test in the other. */
    private void applyRules() {
        float e = getRestitution();
        for (ImpulseResponse each : new ImpulseResponse[] {response, otherResponse}) {
            each.setRestitution(e);
            each.setThresholdSpeed(THRESHOLDS[thresholdPreset]);
            each.setRestingFix(response.isRestingFix());
        }
        if (ground != null) {
            getWorld().removeRule(ground);
            other.removeRule(otherGround);
        }
        Detection otherDetection = detection == Detection.SWEPT ? Detection.OVERLAP
                : Detection.SWEPT;
        ground = SurfaceRule.ground(response, detection);
        otherGround = SurfaceRule.ground(otherResponse, otherDetection);
        getWorld().addRule(ground);
        other.addRule(otherGround);
    }

    /** The slide: the impact law and the apex it predicts; the latest apex ratio. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        float e = getRestitution();
        TextFormat.appendFixed(slide.formula().append("impact: v_n' = -e v_n,   e = "), e, 1)
                .append(";   apex h_n = e^2n h0");
        StringBuilder readout = slide.readout();
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
}

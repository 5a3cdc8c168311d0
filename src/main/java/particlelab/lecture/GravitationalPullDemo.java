package particlelab.lecture;

import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import particlelab.reference.SlideCode;
import particlelab.aiming.Flight;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.demo.LensPart;
import particlelab.demo.RateLanes;
import particlelab.demo.WhatIfPart;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.view.TextFormat;

/**
 * Demo 2, gravitational pull: the lecture's example launch {@code V0 = (10, 10, 0)} m/s under
 * {@code g = (0, −9.8, 0)} m/s². Builds upon uniform motion by adding the one field force.
 *
 * <p>The Euler step: {@code V ← V + h·g}, then {@code P ← P + h·V}. What to watch for: the
 * trail is a parabola; {@code Vx} never changes while {@code Vy} falls by 9.8 m/s every
 * second; the sphere lands near {@code x = 2·Vx·Vy/g ≈ 20.4} m after {@code 2·Vy/g ≈ 2.04} s
 * (from a launch point raised to {@code y0}, after {@code T = (Vy + √(Vy² + 2·g·y0))/g}).
 * The stepped flight lands a little short of the continuous parabola (by {@code Vx·h}, about
 * 0.17 m at 60 steps per second): the samples lie on the parabola launched with
 * {@code Vy − g·h/2}. Press T and K to see what one long raw frame does to the path.
 *
 * <p>Newton's first law: g goes down to 0 ({@code --set g=0}), and then no force acts: V stays
 * as launched and the path is the straight line {@code P = P0 + V0·t}, stepped exactly as
 * uniform motion is. With nothing to bring it down the ball starts over when it leaves the
 * view.
 *
 * <p>Bug hunt ({@code --set fault=p-before-v}): a twin of the ball, launched with it, runs
 * another book's order, P updated before V ({@link LectureFaults.PositionBeforeVelocity},
 * forward Euler): it lands about {@code Vx·h} <em>beyond</em> the continuous parabola's
 * landing where the ball lands {@code Vx·h} short of it, a whole {@code 2·Vx·h} past the
 * ball; {@code fault=random} hides it ({@code --set seed=N}) until B reveals it.
 */
public final class GravitationalPullDemo extends DemoState {

    /** The lecture's launch velocity (m/s). */
    private static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);
    /** The launch speed's largest value and key step (m/s). */
    private static final float MAX_SPEED = 30f;
    private static final float SPEED_STEP = 0.5f;
    private static final float MASS_KG = 1f;
    /** The view's right edge and top (m): without gravity the ball starts over past them. */
    private static final float RIGHT_EDGE = 24f;
    private static final float TOP_EDGE = 7f;
    /** The spheres' drawn radius (m). */
    private static final float SPHERE_RADIUS = 0.35f;
    /** The fault of this demo, by {@code --set fault=} name, and what it is. */
    static final String P_BEFORE_V = "p-before-v";
    private static final String[] FAULTS = {P_BEFORE_V};
    private static final String[] FAULT_TITLES = {"P updated before V (forward Euler)"};
    private static final String[] FAULT_LABELS = {"P before V"};
    /** The twin's own label, before its fault's. */
    private static final String TWIN_LABEL = "twin";

    /** The launch, mass and g, declared as parameters. */
    private final LaunchControl launch = new LaunchControl(LAUNCH_VELOCITY);
    /** Scratch: the launch velocity as printed (m/s). */
    private final Vector3f shownVelocity = new Vector3f();
    /** Scratch: the launch position now (m). */
    private final Vector3f scratchPosition = new Vector3f();
    /** The launch position the equations were written for (m). */
    private final Vector3f shownPosition = new Vector3f();
    /** Scratch: g as the force has it now (m/s²). */
    private final Vector3f gravityNow = new Vector3f();
    private final Gravity gravity = new Gravity();
    /** The comparison lane beside the ball: off, the slide's code, a report stepper. */
    private final ComparisonLane lane = addPart(new ComparisonLane(
            () -> SlideCode.pull(gravity), SPHERE_RADIUS));
    /** The derivative lens on the followed sphere (key O, {@code --set lens=on}). */
    private final LensPart lens = addPart(new LensPart(SPHERE_RADIUS));
    /** What-if forks (Insert, Delete, J): as recorded, h = 1/30 s, h = 1/10 s. */
    private final WhatIfPart whatIf = addPart(new WhatIfPart(GravitationalPullDemo::new,
            new String[] {null, "h", "h"}, new float[] {0f, 1f / 30f, 1f / 10f}, 0f));
    /** The lecture's loop at 30, 60, 144 and 240 Hz beside the ball ({@code rates=on}). */
    private final RateLanes rates = addPart(new RateLanes(SPHERE_RADIUS));
    private DemoParticle ball;
    /** The bug hunt's switch: the twin runs P before V. */
    private final FaultHunt faults = new FaultHunt(FAULTS, FAULT_TITLES, FAULT_LABELS);
    /** The fault's stepper: the world moves the twin's P (forceless), this then its V. */
    private final LectureFaults.PositionBeforeVelocity pBeforeV =
            new LectureFaults.PositionBeforeVelocity(gravity);
    /**
     * The ball's twin: with the fault on, moved by the fault's order; off, hidden and out of
     * the HUD, it flies the lecture's order, the ball's very floats, and lands with it.
     */
    private DemoParticle twin;
    /** The twin's V update comes after its P update (the fault) or before it (off). */
    private boolean positionFirst;
    /** The consequence: the twin's landing x and the ball's, flown ahead (m). */
    private final FaultConsequence consequence = new FaultConsequence(faults, getClock(),
            "the twin", "the lecture order");
    /** Scratch for the flights ahead: a particle and a flight with the ball's forces. */
    private final Particle flown = new Particle();
    private final Flight correctFlight = new Flight(new ParticleIntegrator(gravity));
    private final Flight twinFlight = new Flight(new ParticleIntegrator());

    /** Create the demo. */
    public GravitationalPullDemo() {
        super("Gravitational pull");
    }

    /**
     * Access the comparison lane ({@code --set lane=...}, key L).
     *
     * @return the live lane (not null)
     */
    public ComparisonLane getLane() {
        return lane;
    }

    /**
     * Access the derivative lens ({@code --set lens=on}, key O).
     *
     * @return the live lens part (not null)
     */
    public LensPart getLens() {
        return lens;
    }

    /**
     * Access the rate lanes ({@code --set rates=on}).
     *
     * @return the live part (not null)
     */
    public RateLanes getRates() {
        return rates;
    }

    /**
     * Access the what-if forks (Insert, Delete, J).
     *
     * @return the live part (not null)
     */
    public WhatIfPart getWhatIf() {
        return whatIf;
    }

    @Override
    protected void createScene() {
        ball = launch.add(addParticle("ball", ColorRGBA.Orange, Vector3f.ZERO,
                LAUNCH_VELOCITY, MASS_KG, new ParticleIntegrator(launch.add(gravity))));
        ball.stopAtGround();
        // The bug hunt's twin: no forces in its integrator, so the world's step is just
        // P += h·V with the V it has; V += h·g comes after it (afterStep: the fault) or, with
        // the fault off, before it (beforeStep: the lecture's order, the ball's floats).
        twin = launch.add(addParticle(faults.label(TWIN_LABEL), new ColorRGBA(1f, 0.3f, 0.3f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG, new ParticleIntegrator()));
        twin.stopAtGround();
        // its exact path is the ball's (its forces, not its forceless integrator's), whose
        // ghost the ball draws already
        twin.setPathIntegrator(ball.getIntegrator());
        twin.hideGhost();
        consequence.setFlight(new FaultConsequence.AheadFlight() {
            @Override
            public double landingX(int fault, float stepSeconds) {
                return fault == 0 ? correctLandingX(stepSeconds) : faultyLandingX(stepSeconds);
            }

            @Override
            public void appendAfter(StringBuilder text, float stepSeconds) {
                double vxh = twin.copyLaunchVelocity(scratchPosition).x * (double) stepSeconds;
                TextFormat.appendFixed(text.append(" (2·Vx·h = "), 2.0 * vxh, 2).append(" m)");
            }
        });
        applyFault();
        lane.follow(launch, ball);
        lens.follow(ball);
        rates.follow(ball);
        setView(-2f, RIGHT_EDGE, TOP_EDGE, 1f, 5, SPHERE_RADIUS);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        // Gravity alone: every mass falls alike (try it with the mass). g from 0: no force.
        declareParameter(launch.speedParameter(MAX_SPEED, SPEED_STEP));
        declareParameter(launch.angleParameter());
        declareParameter(launch.massParameter(MASS_KG));
        declareParameter(launch.gravityParameter(0f));
        declareParameter(faults.switchParameter(this::faultChanged));
        declareParameter(faults.seedParameter(this::faultChanged));
    }

    @Override
    protected void declareKeys() {
        bindKey(KeyInput.KEY_B, "B", FaultHunt.REVEAL_DESCRIPTION,
                this::revealFault);
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
     * Tell the order the twin steps in now.
     *
     * @return true for the fault's (P before V), false for the lecture's (V first)
     */
    public boolean isTwinPositionFirst() {
        return positionFirst;
    }

    /**
     * Access the bug hunt's twin: the ball's launch stepped P before V while the fault is on;
     * while it is off, hidden, it steps the lecture's order with the ball.
     *
     * @return the twin (not null: asking makes the scene)
     */
    public DemoParticle getFaultTwin() {
        getParticles();
        return twin;
    }

    /**
     * Access the fault's consequence: where the twin lands, flown ahead from the launch with
     * the fault's order, and where the ball lands, flown with the lecture's recipe.
     *
     * @return the live consequence (not null)
     */
    FaultConsequence getFaultConsequence() {
        return consequence;
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        consequence.appendHudLine(text, "B");
    }

    @Override
    protected void beforeStep(float stepSeconds) {
        // Fault off: V += h·g before the world's P += h·V, the lecture's order.
        if (!positionFirst && !twin.isHeld()) {
            pBeforeV.updateVelocity(twin.getParticle(), stepSeconds);
        }
    }

    @Override
    protected void afterStep(float stepSeconds) {
        // The fault's second half, V += h·g after P moved with the old V (it did not land).
        if (positionFirst && twin.wasSteppedThisStep() && !twin.hasLanded()) {
            pBeforeV.updateVelocity(twin.getParticle(), stepSeconds);
        }
        // No gravity, no landing: start over past the view's edge, as uniform motion does.
        Vector3f position = ball.getParticle().position;
        if (gravity.copyAcceleration(gravityNow).y == 0f
                && (position.x > RIGHT_EDGE || position.y > TOP_EDGE)) {
            restart();
        }
    }

    @Override
    protected void declareDraggables() {
        // The mouse moves the launch (paused): the sphere P0, its arrow's tip V0.
        declareDraggable(launch.dragPosition("the ball"));
        declareDraggable(launch.dragVelocity("the ball", getParameters()));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        float g = getParameters().getValue("g");
        launch.copyVelocity(shownVelocity);
        if (g == 0f) {
            text.append("No force (g = 0):  a = 0,  V += h·0 stays,  P += h·V:  Newton's first"
                    + " law\nLaunch V0 = (");
            DemoParameter.appendShort(text, shownVelocity.x, 2).append(", ");
            DemoParameter.appendShort(text, shownVelocity.y, 2)
                    .append(", 0) m/s:  the straight line P = P0 + V0·t, never a parabola\n");
            return;
        }
        text.append("Pull:  a = g = (0, -");
        DemoParameter.appendShort(text, g, 2).append(", 0) m/s²,   V += h·g,   P += h·V\n");
        text.append("Launch V0 = (");
        DemoParameter.appendShort(text, shownVelocity.x, 2).append(", ");
        DemoParameter.appendShort(text, shownVelocity.y, 2).append(", 0) m/s:  lands Vx·T = ");
        // The continuous parabola from the launch shown, at its height y0 (a drag can raise
        // it) and any angle: it comes down at T = (Vy + √(Vy² + 2·g·y0))/g, which is 2·Vy/g
        // from the ground, and Vx·T downrange. The launch stays at or above the ground (y0 ≥ 0).
        ball.copyLaunchPosition(shownPosition);
        double vy = shownVelocity.y;
        double flightSeconds = (vy + Math.sqrt(vy * vy + 2.0 * g * Math.max(0f,
                shownPosition.y))) / g;
        TextFormat.appendFixed(text, shownVelocity.x * flightSeconds, 2)
                .append(" m downrange at T = ");
        TextFormat.appendFixed(text, flightSeconds, 2)
                .append(" s (continuous; T = (Vy + √(Vy² + 2·g·y0))/g)\n");
    }

    /** A reset after a drag of the launch point: the landing line follows the new y0. */
    @Override
    protected void onRestart() {
        applyFault();
        if (!ball.copyLaunchPosition(scratchPosition).equals(shownPosition)) {
            refreshEquations();
        }
    }

    /** Hide the twin while the fault is off. Allocates nothing. */
    @Override
    protected void afterFrame() {
        particlelab.view.ParticleView view = getWindow().getView(twin);
        if (view != null) {
            view.getNode().setCullHint(faults.active() == 0 ? Spatial.CullHint.Always
                    : Spatial.CullHint.Inherit);
        }
    }

    /** The fault or the seed changed: the twin's label, and whether it flies. */
    private void faultChanged() {
        consequence.markStale();
        if (twin != null) {
            applyFault();
            relabel(twin, faults.label(TWIN_LABEL));
        }
    }

    /**
     * Let the twin fly the fault's order in sight with the fault on, the lecture's hidden and
     * out of the HUD if off. At every launch: allocates nothing.
     */
    private void applyFault() {
        boolean on = faults.active() != 0;
        positionFirst = on;
        twin.setParked(!on);
        consequence.markStale();
    }

    /** Reveal the hidden fault (key B): the label and the HUD name it. */
    void revealFault() {
        if (faults.isHidden()) {
            faults.reveal();
            relabel(twin, faults.label(TWIN_LABEL));
        }
    }

    /** The twin flown from its launch with the fault's order; NaN if it does not land. */
    private double faultyLandingX(float h) {
        flown.copyFrom(twin.getParticle());
        twin.copyLaunchPosition(flown.position);
        twin.copyLaunchVelocity(flown.velocity);
        for (int n = 1; n <= FaultConsequence.MAX_FLIGHT_STEPS; ++n) {
            // as in the scene: a forceless step moves P with the old V, swept against the
            // ground; then the fault's V += h·g
            double landing = twinFlight.step(flown, h);
            if (landing != Flight.NO_LANDING) {
                return twinFlight.crossingX(landing);
            }
            pBeforeV.updateVelocity(flown, h);
        }
        return Double.NaN;
    }

    /** The ball flown from its launch with the lecture's recipe; NaN if it does not land. */
    private double correctLandingX(float h) {
        flown.copyFrom(ball.getParticle());
        ball.copyLaunchPosition(flown.position);
        ball.copyLaunchVelocity(flown.velocity);
        for (int n = 1; n <= FaultConsequence.MAX_FLIGHT_STEPS; ++n) {
            double landing = correctFlight.step(flown, h);
            if (landing != Flight.NO_LANDING) {
                return correctFlight.crossingX(landing);
            }
        }
        return Double.NaN;
    }

    /** The slide: g alone changes V, only its y; the ball's V now, or where it landed. */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        particlelab.demo.DemoParticle ball = getParticles().get(0);
        DemoParameter.appendShort(slide.formula().append("a = g:  V += h·g,  P += h·V,   g = "),
                getParameters().getValue("g"), 2).append(" m/s²");
        StringBuilder readout = slide.readout();
        if (ball.hasLanded()) {
            TextFormat.appendFixed(readout.append("landed at x = "), ball.getLandingX(), 2)
                    .append(" m after ");
            TextFormat.appendFixed(readout, ball.getLandingSeconds(), 2).append(" s");
            return;
        }
        TextFormat.appendVector(readout.append("V = "), ball.getParticle().velocity, 2)
                .append(" m/s   at t = ");
        TextFormat.appendFixed(readout, getClock().getSimulatedSeconds(), 2).append(" s");
    }
}

package particlelab.lecture;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.reference.SlideCode;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.demo.LensPart;
import particlelab.demo.RateLanes;
import particlelab.demo.WhatIfPart;
import particlelab.physics.Gravity;
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
    /** The lecture's loop at 30, 60, 144 and 240 Hz beside the sphere ({@code rates=on}). */
    private final RateLanes rates = addPart(new RateLanes());
    /** What-if forks (Insert, Delete, J): as recorded, h = 1/30 s, h = 1/10 s. */
    private final WhatIfPart whatIf = addPart(new WhatIfPart(GravitationalPullDemo::new,
            new String[] {null, "h", "h"}, new float[] {0f, 1f / 30f, 1f / 10f}, 0f));
    private DemoParticle ball;

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
        lane.follow(launch, ball);
        rates.follow(ball);
        lens.follow(ball);
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
    }

    @Override
    protected void afterStep(float stepSeconds) {
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
        if (!ball.copyLaunchPosition(scratchPosition).equals(shownPosition)) {
            refreshEquations();
        }
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

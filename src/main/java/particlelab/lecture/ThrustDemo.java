package particlelab.lecture;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.reference.SlideCode;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.demo.LensPart;
import particlelab.demo.Presentation;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Thrust;

/**
 * Demo 4, thrust: two spheres launched together with {@code V0 = (10, 10, 0)} m/s: pull + drag
 * (the linear-drag sphere of demo 3), and pull + drag + thrust {@code F = k·V/|V|} with
 * {@code k = 2} N along the sphere's <em>own</em> velocity. Builds upon the drag demo.
 *
 * <p>The original lecture code pushed one sphere along the other sphere's velocity; here each
 * motor pushes where its own sphere flies. What to watch for: the thruster keeps its speed
 * longer and flies farther, and its thrust turns with it as gravity bends the path down.
 * Without gravity it would settle at the terminal speed {@code k/b ≈ 2.2} m/s.
 */
public final class ThrustDemo extends DemoState {

    /** The lecture's thrust (N). */
    public static final float THRUST_K = 2f;
    /** The lecture's linear drag coefficient b (N·s/m). */
    public static final float LINEAR_B = 0.9f;
    /** The common launch velocity (m/s). */
    private static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);
    private static final float MASS_KG = 1f;
    /** The launch speed's largest value and key step (m/s). */
    private static final float MAX_SPEED = 30f;
    private static final float SPEED_STEP = 0.5f;
    /** The largest drag coefficient (N·s/m) and thrust (N) offered. */
    private static final float MAX_B = 5f;
    private static final float MAX_K = 20f;
    /** The spheres' drawn radius (m). */
    private static final float SPHERE_RADIUS = 0.18f;

    /** The launch, mass and g, declared as parameters. */
    private final LaunchControl launch = new LaunchControl(LAUNCH_VELOCITY);
    /** Both spheres feel the same drag; only the second one thrusts. */
    private final LinearDrag drag = new LinearDrag(LINEAR_B);
    private final LinearDrag thrusterDrag = new LinearDrag(LINEAR_B);
    private final Thrust thrust = new Thrust(THRUST_K);
    /** The thruster's gravity, which the lane's slide code reads too. */
    private final Gravity thrusterGravity = new Gravity();
    /** The comparison lane beside the thruster. */
    private final ComparisonLane lane = addPart(new ComparisonLane(
            () -> SlideCode.thrust(thrusterGravity, thrusterDrag, thrust), SPHERE_RADIUS));
    /** The derivative lens on the followed sphere (key O, {@code --set lens=on}). */
    private final LensPart lens = addPart(new LensPart(SPHERE_RADIUS));

    /** Create the demo. */
    public ThrustDemo() {
        super("Thrust");
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

    @Override
    protected void createScene() {
        launch.add(addParticle("pull + drag", new ColorRGBA(0.3f, 0.85f, 1f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(new Gravity()), drag))).stopAtGround();
        DemoParticle thruster = launch.add(addParticle("pull + drag + thrust k",
                new ColorRGBA(1f, 0.75f, 0.2f, 1f), Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(thrusterGravity), thrusterDrag, thrust)));
        thruster.stopAtGround();
        lane.follow(launch, thruster);
        lens.follow(thruster);
        setView(-1f, 14f, 4.5f, 0.5f, 4, SPHERE_RADIUS);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        launch.projectileParameters(MAX_SPEED, SPEED_STEP, MASS_KG).forEach(this::declareParameter);
        declareParameter(new DemoParameter("b", "linear drag", "N s/m", 0f, MAX_B,
                0.05f, LINEAR_B, 2, DemoParameter.Applies.LIVE, value -> {
                    drag.setCoefficient(value);
                    thrusterDrag.setCoefficient(value);
                }));
        declareParameter(new DemoParameter("k", "thrust", "N", 0f, MAX_K, 0.25f,
                THRUST_K, 2, DemoParameter.Applies.LIVE, thrust::setMagnitude));
    }

    @Override
    protected void declareDraggables() {
        // The mouse moves the launch (paused): the sphere P0, its arrow's tip V0.
        declareDraggable(launch.dragPosition("a sphere"));
        declareDraggable(launch.dragVelocity("a sphere", getParameters()));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        launch.appendLaunch(text.append("a = g + F/m,  "), getParameters()).append('\n');
        text.append("drag F = -b V, b = ");
        DemoParameter.appendShort(text, drag.getCoefficient(), 2).append(" N s/m;   thrust"
                + " F = k V/|V|, k = ");
        DemoParameter.appendShort(text, thrust.getMagnitude(), 2)
                .append(" N along the sphere's OWN velocity\n");
    }

    /** The slide: thrust along its own velocity against drag; both speeds (or landings). */
    @Override
    protected void writePresentation(Presentation slide) {
        StringBuilder formula = slide.formula().append("a = g - (b/m)V + (k/m)V/|V|,   b = ");
        DemoParameter.appendShort(formula, drag.getCoefficient(), 2).append(" N s/m,  k = ");
        DemoParameter.appendShort(formula, thrust.getMagnitude(), 2).append(" N");
        List<DemoParticle> spheres = getParticles();
        StringBuilder readout = slide.readout().append("pull + drag ");
        Presentation.appendSpeedOrLanding(readout, spheres.get(0)).append(",  with thrust ");
        Presentation.appendSpeedOrLanding(readout, spheres.get(1));
    }
}

package particlelab.lecture;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoState;
import particlelab.demo.LaunchControl;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;

/**
 * Demo 3, drag: three spheres launched together with the same {@code V0 = (10, 10, 0)} m/s and
 * mass {@code m = 1} kg. Builds upon gravitational pull; each sphere has its own integrator
 * holding its own forces:
 * <ol>
 * <li>gravity only (the parabola of demo 2);</li>
 * <li>gravity + linear drag {@code F = −b·V} with the lecture's {@code b = 0.9} N·s/m;</li>
 * <li>gravity + quadratic drag {@code F = −c·|V|·V}.</li>
 * </ol>
 *
 * <p>What to watch for: with drag the path is no longer a parabola: it climbs less, bends down
 * steeper and lands shorter. Linear drag pulls every velocity toward the terminal velocity
 * {@code m·g/b ≈ 10.9} m/s straight down; quadratic drag bites hardest at the start, when the
 * sphere is fastest. The HUD's stability line names the sphere whose stability limit is the
 * smallest at its current state ({@code 2m/b} for linear drag, {@code m/(c·|V|)} for quadratic
 * drag, which grows as the sphere slows); press T (raw tpf) and K (a long hitch, longer still
 * at a raised time scale) to see a long step pass a limit and the warning name the sphere.
 */
public final class DragDemo extends DemoState {

    /** The lecture's linear drag coefficient b (N·s/m). */
    public static final float LINEAR_B = 0.9f;
    /** The quadratic drag coefficient c (kg/m), chosen to bite as hard as b at launch. */
    public static final float QUADRATIC_C = 0.064f;
    /** The common launch velocity (m/s). */
    private static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);
    private static final float MASS_KG = 1f;
    /** The launch speed's largest value and key step (m/s). */
    private static final float MAX_SPEED = 30f;
    private static final float SPEED_STEP = 0.5f;
    /** The drag coefficients' largest values (N·s/m and kg/m). */
    private static final float MAX_B = 5f;
    private static final float MAX_C = 0.5f;

    /** The launch, mass and g, declared as parameters. */
    private final LaunchControl launch = new LaunchControl(LAUNCH_VELOCITY);
    private final LinearDrag linearDrag = new LinearDrag(LINEAR_B);
    private final QuadraticDrag quadraticDrag = new QuadraticDrag(QUADRATIC_C);

    /** Create the demo. */
    public DragDemo() {
        super("Drag");
    }

    @Override
    protected void createScene() {
        // Same launch for all three; only the forces differ.
        // The labels name the forces, not their numbers: the panel changes b and c.
        launch.add(addParticle("gravity only", ColorRGBA.Orange, Vector3f.ZERO,
                LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(new Gravity())))).stopAtGround();
        launch.add(addParticle("linear drag  F = -b V", new ColorRGBA(0.3f, 0.85f, 1f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(new Gravity()), linearDrag))).stopAtGround();
        launch.add(addParticle("quadratic drag  F = -c |V|V", new ColorRGBA(1f, 0.4f, 0.8f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(launch.add(new Gravity()), quadraticDrag)))
                .stopAtGround();
        setView(-2f, 24f, 7f, 1f, 5, 0.3f);
        showExactGhosts();
    }

    @Override
    protected void declareParameters() {
        launch.projectileParameters(MAX_SPEED, SPEED_STEP, MASS_KG).forEach(this::declareParameter);
        // The coefficients change the forces at once, in the middle of a flight.
        declareParameter(new DemoParameter("b", "linear drag", "N s/m", 0f, MAX_B,
                0.05f, LINEAR_B, 2, DemoParameter.Applies.LIVE, linearDrag::setCoefficient));
        declareParameter(new DemoParameter("c", "quadratic drag", "kg/m", 0f,
                MAX_C, 0.004f, QUADRATIC_C, 3, DemoParameter.Applies.LIVE,
                quadraticDrag::setCoefficient));
    }

    @Override
    protected void declareDraggables() {
        // The mouse moves the launch (paused): the sphere P0, its arrow's tip V0.
        declareDraggable(launch.dragPosition("a sphere"));
        declareDraggable(launch.dragVelocity("a sphere", getParameters()));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        launch.appendLaunch(text.append("a = g + F/m,  "), getParameters());
        text.append(";   linear: F = -b V, b = ");
        DemoParameter.appendShort(text, linearDrag.getCoefficient(), 2)
                .append(" N s/m;   quadratic: F = -c |V| V, c = ");
        DemoParameter.appendShort(text, quadraticDrag.getCoefficient(), 3).append(" kg/m\n");
    }

    /** The slide: the two drag laws with b/m and c/m; the three speeds (or landings). */
    @Override
    protected void writePresentation(particlelab.demo.Presentation slide) {
        java.util.List<particlelab.demo.DemoParticle> balls = getParticles();
        float mass = balls.get(1).getParticle().getMass();
        particlelab.view.TextFormat.appendFixed(slide.formula()
                .append("linear:  a = g - (b/m)V,   b/m = "),
                linearDrag.getCoefficient() / mass, 2).append(" /s");
        particlelab.view.TextFormat.appendFixed(slide.formula()
                .append("quadratic:  a = g - (c/m)|V|V,   c/m = "),
                quadraticDrag.getCoefficient() / mass, 3).append(" /m");
        StringBuilder readout = slide.readout().append("gravity only ");
        appendSpeedOrLanding(readout, balls.get(0)).append(",  linear ");
        appendSpeedOrLanding(readout, balls.get(1)).append(",  quadratic ");
        appendSpeedOrLanding(readout, balls.get(2));
    }
}

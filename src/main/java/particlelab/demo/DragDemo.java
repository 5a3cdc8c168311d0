package particlelab.demo;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
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

    /** Create the demo. */
    public DragDemo() {
        super("Drag");
    }

    @Override
    protected void createScene() {
        // Same launch for all three; only the forces differ.
        addParticle("gravity only", ColorRGBA.Orange, Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(new Gravity())).stopAtGround();
        addParticle("linear drag  F = -0.9 V", new ColorRGBA(0.3f, 0.85f, 1f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(new Gravity(), new LinearDrag(LINEAR_B))).stopAtGround();
        addParticle("quadratic drag  F = -0.064 |V|V", new ColorRGBA(1f, 0.4f, 0.8f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, MASS_KG,
                new ParticleIntegrator(new Gravity(), new QuadraticDrag(QUADRATIC_C)))
                .stopAtGround();
        setView(-2f, 24f, 7f, 1f, 5, 0.3f);
        showExactGhosts();
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("a = g + F/m,  m = 1 kg,  V0 = (10, 10, 0) m/s;   linear: F = -b V, b = 0.9"
                + " N s/m;   quadratic: F = -c |V| V, c = 0.064 kg/m\n");
    }
}

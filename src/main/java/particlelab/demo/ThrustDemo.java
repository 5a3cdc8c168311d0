package particlelab.demo;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
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

    /** Create the demo. */
    public ThrustDemo() {
        super("Thrust");
    }

    @Override
    protected void createScene() {
        addParticle("pull + drag", new ColorRGBA(0.3f, 0.85f, 1f, 1f), Vector3f.ZERO,
                LAUNCH_VELOCITY, 1f,
                new ParticleIntegrator(new Gravity(), new LinearDrag(LINEAR_B)))
                .stopAtGround();
        addParticle("pull + drag + thrust 2 N", new ColorRGBA(1f, 0.75f, 0.2f, 1f),
                Vector3f.ZERO, LAUNCH_VELOCITY, 1f, new ParticleIntegrator(new Gravity(),
                        new LinearDrag(LINEAR_B), new Thrust(THRUST_K))).stopAtGround();
        setView(-1f, 14f, 4.5f, 0.5f, 4, 0.18f);
        showExactGhosts();
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        text.append("a = g + F/m,  m = 1 kg,  V0 = (10, 10, 0) m/s\n");
        text.append("drag F = -b V, b = 0.9 N s/m;   thrust F = k V/|V|, k = 2 N"
                + " along the sphere's OWN velocity\n");
    }
}

package particlelab.solutions;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import particlelab.demo.DemoState;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * Exercise 8, solved: a demo of one's own (the student guide's worked example): one ball in
 * still air, one in a wind {@code F = b·(W − V)}.
 */
public final class OwnDemo extends DemoState {

    /** The wind's velocity W (in m/s). */
    public static final Vector3f WIND = new Vector3f(-6f, 0f, 0f);
    /** The wind's drag coefficient b (in N·s/m). */
    public static final float WIND_B = 0.3f;
    /** Both balls' launch velocity (in m/s). */
    public static final Vector3f LAUNCH = new Vector3f(10f, 10f, 0f);
    /** Both balls' mass (in kg). */
    public static final float MASS_KG = 1f;

    /** The wind force {@code F = b·(W − V)}, added in place. */
    private static final class Wind implements Force {
        @Override
        public void addForce(Particle particle, Vector3f netForce) {
            netForce.scaleAdd(WIND_B, WIND, netForce);
            netForce.scaleAdd(-WIND_B, particle.velocity, netForce);
        }

        @Override
        public float dampingRate(Particle particle) {
            return WIND_B / particle.getMass();
        }

        @Override
        public String describe() {
            return "F = b·(W - V)";
        }
    }

    /** A demo titled for the menu. */
    public OwnDemo() {
        super("Own demo (exercise 8)");
    }

    @Override
    protected void createScene() {
        addParticle("still air", ColorRGBA.Orange, Vector3f.ZERO, LAUNCH, MASS_KG,
                new ParticleIntegrator(new Gravity())).stopAtGround();
        addParticle("in the wind", ColorRGBA.Green, Vector3f.ZERO, LAUNCH, MASS_KG,
                new ParticleIntegrator(new Gravity(), new Wind())).stopAtGround();
        setView(-2f, 24f, 7f, 1f, 5, 0.35f);
    }
}

package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.aiming.Landing;
import particlelab.aiming.ShotSimulator;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

/**
 * The lecture's "stop at the ground", built from world parts (a point body, the ground plane,
 * the swept test and the stick response), lands where {@link ShotSimulator} says: the same
 * crossing of the same straight segment. The world places the body in float ({@code P + f·h·V}
 * with f a float) where the simulator interpolates in double, so they agree to float round-off
 * of the 100 m landing, a few times 1e-5 m.
 */
class GroundStopTest {

    private static final float H = 1f / 60f;

    @Test
    void stickingToTheGroundLandsWhereTheShotSimulatorDoes() {
        // HelloAiming: S = 100 m, vx = 20 m/s, the lecture's vy = g·S/(2·vx) = 24.5 m/s
        // lands vx·h = 0.33 m short when stepped.
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Landing landing = new Landing();
        assertTrue(new ShotSimulator(gravity, 1f, H, 60f).fire(20f, 24.5f, landing));

        World world = new World();
        Body shot = world.addBody(gravity, Vector3f.ZERO, new Vector3f(20f, 24.5f, 0f), 1f, 0f);
        world.addRule(SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT));
        for (int i = 0; i < 600 && !shot.isHeld(); ++i) {
            world.step(H);
        }
        assertTrue(shot.isHeld());
        assertEquals(landing.getX(), shot.getPosition().x, 5e-5);
        assertEquals(0f, shot.getPosition().y, 1e-5f);
        assertEquals(landing.getTimeSeconds(), shot.getScriptedSinceSeconds(), 1e-6);
        assertEquals(100.0 - 20.0 * H, landing.getX(), 1e-3, "vx·h short");
    }
}

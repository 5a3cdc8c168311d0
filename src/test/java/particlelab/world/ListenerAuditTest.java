package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

/** The world's audit of its rule "after-step listeners observe; they move nothing". */
class ListenerAuditTest {

    private static final float H = 1f / 60f;

    @Test
    void aListenerThatMovesABodyAfterTheStepIsCaught() {
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()), Vector3f.ZERO,
                new Vector3f(1f, 5f, 0f), 1f, 0f);
        world.addStepListener(new StepListener() {
            @Override
            public void afterStep(World stepping, float stepSeconds) {
                if (stepping.getStepCount() == 3) {
                    ball.getParticle().position.y = 0f; // a hand-made "ground stop"
                }
            }
        });
        world.setAuditingListeners(true);
        world.step(H);
        world.step(H);
        IllegalStateException caught = assertThrows(IllegalStateException.class,
                () -> world.step(H));
        assertTrue(caught.getMessage().contains("moved"), caught.getMessage());
    }

    @Test
    void listenersThatOnlyReadPassAndBeforeStepMayMove() {
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()), Vector3f.ZERO,
                new Vector3f(1f, 5f, 0f), 1f, 0f);
        float[] apex = {0f};
        world.addStepListener(new StepListener() {
            @Override
            public void beforeStep(World stepping, float stepSeconds) {
                ball.getParticle().velocity.x = 2f; // a script's kinematic push: allowed
            }

            @Override
            public void afterStep(World stepping, float stepSeconds) {
                apex[0] = Math.max(apex[0], ball.getParticle().position.y);
            }
        });
        world.setAuditingListeners(true);
        for (int i = 0; i < 60; ++i) {
            world.step(H);
        }
        assertEquals(60L, world.getStepCount());
        assertTrue(apex[0] > 1f, "the listener saw the flight: apex " + apex[0]);
    }
}

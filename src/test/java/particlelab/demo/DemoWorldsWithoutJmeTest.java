package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import particlelab.app.DemoCatalog;
import particlelab.physics.Particle;
import particlelab.rigid.RigidBody;
import particlelab.world.Body;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * A demo's physics needs no jME application: every catalogued demo, made with {@code new}, has
 * its simulation (its world and what steps beside it) stepped here in plain JUnit (no
 * application, no asset manager, no scene graph), and its bodies move. The views (trails,
 * dots, labels) are the view's business, written after the step by listeners the view
 * registers when it is built.
 */
class DemoWorldsWithoutJmeTest {

    /** Two seconds of the clock's default step. */
    private static final int STEPS = 120;
    private static final float STEP_SECONDS = 1f / 60f;

    static Stream<String> demoNames() {
        return DemoCatalog.names().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("demoNames")
    void theDemosWorldStepsWithoutAnApplication(String name) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
        String hudBefore = demo.getWindow().formatHud(new StringBuilder()).toString();
        float[] before = positions(demo);
        for (int i = 0; i < STEPS; ++i) {
            // The frame's physics: the world and the simulations beside it, by the clock.
            demo.getRun().advancePhysics(STEP_SECONDS);
        }
        assertTrue(demo.getWorld().getStepCount() > 0, name + ": the world never stepped");
        float[] after = positions(demo);
        if (before.length > 0) {
            boolean moved = false;
            for (int i = 0; i < before.length && i < after.length; ++i) {
                moved |= before[i] != after[i];
            }
            assertTrue(moved, name + ": no body moved in " + STEPS + " steps");
        } else {
            // Demos whose bodies live outside the world's list (the rotation demo's matrices,
            // the fountain's packed particles) show the steps in their numbers.
            String hudAfter = demo.getWindow().formatHud(new StringBuilder()).toString();
            assertNotEquals(hudBefore, hudAfter, name + ": the HUD's numbers did not change");
        }
    }

    /**
     * The rule the world's listeners keep: they observe, they move nothing. Twenty seconds of
     * every demo (shots land and are fired again, rounds go on) with the world checking,
     * after each step, that its after-step listeners (the demo's hook among them) left every
     * body as the step did.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("demoNames")
    void noAfterStepHookMovesABody(String name) {
        DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
        demo.getWorld().setAuditingListeners(true);
        long[] steps = {0L};
        demo.getWorld().addStepListener(new StepListener() {
            @Override
            public void afterStep(World stepping, float stepSeconds) {
                ++steps[0];
            }
        });
        for (int i = 0; i < 20 * 60; ++i) {
            demo.getRun().advancePhysics(STEP_SECONDS);
        }
        // Each frame of 1/60 s is one step of the default h, each checked by the audit, until
        // a demo whose shots have all landed stops stepping (its scene is over).
        assertTrue(steps[0] > 60, name + ": " + steps[0] + " steps");
        if (!demo.getRun().isSceneOver()) {
            assertEquals(20 * 60, steps[0], name);
        }
    }

    /** Every body's position, and the orientation of those that turn. */
    private static float[] positions(DemoState demo) {
        int count = demo.getWorld().countBodies();
        float[] state = new float[12 * count];
        for (int i = 0; i < count; ++i) {
            Body body = demo.getWorld().getBody(i);
            Particle particle = body.getParticle();
            state[12 * i] = particle.position.x;
            state[12 * i + 1] = particle.position.y;
            state[12 * i + 2] = particle.position.z;
            RigidBody rigid = body.getRigidBody();
            for (int k = 0; k < 9 && rigid != null; ++k) {
                state[12 * i + 3 + k] = rigid.orientation.get(k / 3, k % 3);
            }
        }
        return state;
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import particlelab.app.DemoCatalog;
import particlelab.physics.Particle;
import particlelab.rigid.RigidBody;
import particlelab.world.Body;

/**
 * A demo's physics needs no jME application: every catalogued demo, made with {@code new}, has
 * its world stepped here in plain JUnit (no application, no asset manager, no scene graph), and
 * its particles move. The views (trails, dots, labels) are the view's business, written after
 * the step by listeners the view registers when it is built.
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
        String hudBefore = demo.formatHud(new StringBuilder()).toString();
        float[] before = positions(demo);
        for (int i = 0; i < STEPS; ++i) {
            demo.getWorld().step(STEP_SECONDS);
        }
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
            String hudAfter = demo.formatHud(new StringBuilder()).toString();
            assertNotEquals(hudBefore, hudAfter, name + ": the HUD's numbers did not change");
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

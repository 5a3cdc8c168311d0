package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParticle;
import particlelab.view.TextFormat;

/**
 * The pull demo's landing line is the continuous landing of the launch shown, from its own
 * height and at any angle (it said 2·Vx·Vy/g, a launch from the ground, after a drag raised
 * the launch point; a negative angle gave a negative range). Plain JUnit.
 */
class PullLandingLineTest {

    private static final double G = 9.8;

    @Test
    void theLandingLineIsTheParabolasCrossingFromTheLaunchShown() {
        float[][] launches = {{0f, 0f}, {5f, 0f}, {5f, -20f}};
        for (float[] launch : launches) {
            GravitationalPullDemo pull = new GravitationalPullDemo();
            pull.getParameters().set("angle", launch[1]);
            DemoParticle ball = pull.getParticles().get(0);
            Vector3f velocity = ball.copyLaunchVelocity(new Vector3f());
            ball.setLaunch(new Vector3f(0f, launch[0], 0f), velocity);
            pull.restart();
            StringBuilder equations = new StringBuilder();
            pull.describeEquations(equations);
            // The crossing of y0 + vy·t − g·t²/2 = 0 after the launch, found by bisection
            // (60 halvings of [0, 10 s]: far below the 0.005 the two decimals keep).
            double low = 0.0;
            double high = 10.0;
            for (int i = 0; i < 60; ++i) {
                double mid = 0.5 * (low + high);
                double y = launch[0] + velocity.y * mid - 0.5 * G * mid * mid;
                if (y > 0.0 || mid < 1e-9) {
                    low = mid;
                } else {
                    high = mid;
                }
            }
            StringBuilder line = new StringBuilder("lands Vx·T = ");
            TextFormat.appendFixed(line, velocity.x * low, 2).append(" m downrange at T = ");
            TextFormat.appendFixed(line, low, 2).append(" s");
            assertTrue(equations.toString().contains(line), line + " in\n" + equations);
        }
    }
}

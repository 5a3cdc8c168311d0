package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParticle;
import particlelab.physics.Particle;

/**
 * Demo 2 with g = 0: Newton's first law, no force and a straight line, stepped in plain JUnit.
 */
class GravitationalPullDemoTest {

    private static final float H = 1f / 60f;

    @Test
    void withoutGravityTheBallMovesOnTheStraightLineOfItsLaunch() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        pull.getParameters().set("g", 0f);
        int frames = 36;
        for (int frame = 0; frame < frames; ++frame) {
            pull.getRun().advancePhysics(H);
        }
        DemoParticle ball = pull.getParticles().get(0);
        Particle state = ball.getParticle();
        double t = pull.getClock().getSimulatedSeconds();
        // a = 0: V += h·0 changes no bit of V, so V is the launch (10, 10, 0) exactly.
        assertEquals(10f, state.velocity.x, 0f);
        assertEquals(10f, state.velocity.y, 0f);
        // x and y take the same float additions of h·10, so they are equal to the bit: the
        // samples lie exactly on the launch's line y = x, never on a parabola.
        assertEquals(state.position.x, state.position.y, 0f);
        // The closed form P = P0 + V0·t. Each of the n float additions rounds by at most half
        // an ulp of |P| ≤ 6 m (2^-22 relative at most) and h·10 once by 2^-24 relative: the
        // sum stays within n·2^-22·6 m ≈ 5e-5 m.
        double tolerance = frames * Math.scalb(1.0, -22) * 6.0;
        assertEquals(10.0 * t, state.position.x, tolerance);
        assertEquals(frames * H, t, 1e-6);
        assertFalse(ball.hasLanded());
    }

    @Test
    void withoutGravityTheBallStartsOverPastTheViewsEdge() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        pull.getParameters().set("g", 0f);
        // At 10 m/s up it passes the top (7 m) after 0.7 s: then it starts over from P0,
        // with the clock, so 1 s of frames leaves it about 0.3 s into its second flight.
        float highest = 0f;
        for (int frame = 0; frame < 60; ++frame) {
            pull.getRun().advancePhysics(H);
            highest = Math.max(highest, pull.getParticles().get(0).getParticle().position.y);
        }
        assertTrue(highest > 6.5f, "highest " + highest);
        float y = pull.getParticles().get(0).getParticle().position.y;
        assertTrue(y < 4f, "started over, y = " + y);
        assertTrue(pull.getClock().getSimulatedSeconds() < 0.5, "the clock started over");
    }

    @Test
    void gZeroIsAllowedAndANegativeGIsRefusedWithTheRange() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        DemoParameter g = pull.getParameters().get(pull.getParameters().indexOf("g"));
        assertEquals(0f, g.getMin(), 0f);
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> pull.getParameters().set("g", -1f));
        assertTrue(refused.getMessage().contains("g (gravity) from 0.00 m/s^2 to 30.00 m/s^2"),
                refused.getMessage());
    }
}

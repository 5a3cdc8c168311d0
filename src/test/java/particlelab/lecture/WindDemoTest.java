package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.physics.Particle;

/**
 * The student's worked example, tested the way "Write your own demo" says: its physics in
 * plain JUnit, no jME application. {@code new WindDemo()} builds its scene when first asked,
 * and {@link particlelab.demo.DemoRun#advancePhysics} runs a frame's steps with a fixed frame time.
 */
class WindDemoTest {

    private static final float H = 1f / 60f;
    private static final float G = 9.8f;
    private final WindDemo wind = new WindDemo();

    @Test
    void ballInTheWindFollowsTheEulerStepsClosedForm() {
        int frames = 30;
        for (int frame = 0; frame < frames; ++frame) {
            wind.getRun().advancePhysics(H);
        }
        Particle ball = wind.getParticles().get(1).getParticle();
        float[] state = {ball.velocity.x, ball.velocity.y,
            (float) wind.getClock().getSimulatedSeconds()};
        // One fixed step per frame of exactly h.
        assertEquals(frames * H, state[2], 1e-6f);
        // Wind is linear drag relative to the air: with k = b/m and r = 1 − k·h, the lecture's
        // step gives V_n = V* + (V0 − V*)·rⁿ with the terminal velocity V* = W + g/k
        // (docs/numerics.md, "Linear drag", with the air moving at W).
        double k = WindDemo.WIND_B / 1.0;
        double r = 1.0 - k * H;
        double decay = Math.pow(r, frames);
        double terminalX = -6.0;
        double terminalY = -G / k;
        double expectedVx = terminalX + (10.0 - terminalX) * decay;
        double expectedVy = terminalY + (10.0 - terminalY) * decay;
        // 30 float steps, each rounding |V| ≲ 33 m/s at 6e-8 relative: under 1e-4 m/s.
        assertEquals(expectedVx, state[0], 1e-4);
        assertEquals(expectedVy, state[1], 1e-4);
    }

    @Test
    void headwindShortensTheFlightAndStillAirLandsVxHShortOfTheParabola() {
        for (int frame = 0; frame < 300; ++frame) {
            wind.getRun().advancePhysics(H);
        }
        float[] landings = {wind.getParticles().get(0).getLandingX(),
            wind.getParticles().get(1).getLandingX()};
        // Still air is demo 2's shot: the stepped parabola lands exactly vx·h short of
        // 2·vx·vy/g (docs/numerics.md); the interpolated crossing adds under 1 mm here.
        assertEquals(2.0 * 10 * 10 / G - 10.0 * H, landings[0], 2e-3);
        // A 6 m/s headwind with b = 0.3 takes metres off a 20 m shot.
        assertTrue(landings[1] < landings[0] - 3f, "headwind landing " + landings[1]);
    }

    @Test
    void windInStillAirIsLinearDrag() {
        WindDemo.Wind calm = new WindDemo.Wind(new Vector3f(), 0.3f);
        Particle ball = new Particle(new Vector3f(), new Vector3f(3f, -4f, 0f), 2f);
        Vector3f force = new Vector3f();
        calm.addForce(ball, force);
        // F = b·(0 − V) = −b·V: one float product each, within an ulp of −0.9 and 1.2.
        assertEquals(-0.9f, force.x, 1e-6f);
        assertEquals(1.2f, force.y, 1e-6f);
        assertEquals(0f, force.z, 0f);
        assertEquals(0.15f, calm.dampingRate(ball), 0f);
    }

    @Test
    void theDemoDeclaresTheWindKeys() {
        // The help overlay is generated from these declarations.
        boolean left = false;
        boolean right = false;
        for (KeyBinding binding : wind.getKeys().getBindings()) {
            left |= binding.getKeyLabel().equals("Left");
            right |= binding.getKeyLabel().equals("Right");
        }
        assertTrue(left && right, "the wind keys Left and Right");
    }
}

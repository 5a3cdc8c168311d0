package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import particlelab.app.HeadlessHarness;

/** HelloAiming and the student's wind demo, attached to a headless app. */
class HelloAimingDemoTest {

    private static final float H = 1f / 60f;
    private static HelloAimingDemo aiming;
    private static WindDemo wind;
    private static HeadlessHarness harness;

    @BeforeAll
    static void startApp() throws Exception {
        aiming = new HelloAimingDemo();
        wind = new WindDemo();
        harness = HeadlessHarness.start(List.of(aiming, wind));
    }

    @AfterAll
    static void stopApp() {
        harness.close();
    }

    @Test
    void lectureFormulaLandsVxTimesHShortAndTheCorrectionHits() throws Exception {
        float lecture = fireAndLand(HelloAimingDemo.Aim.LECTURE);
        // NUMERICS.md: the stepped shot lands exactly vx·h = 20/60 m short; float rounding
        // over 300 steps moves the interpolated crossing by well under 1 mm.
        assertEquals(100.0 - 20.0 / 60.0, lecture, 1e-3);
        float discrete = fireAndLand(HelloAimingDemo.Aim.DISCRETE);
        assertEquals(100.0, discrete, 1e-3);
        String hud = harness.call(() -> aiming.formatHud(new StringBuilder()).toString());
        assertTrue(hud.contains("Predicted landing with h = 16.7 ms:  x = 100.000 m"), hud);
        assertTrue(hud.contains("last landed at x = 100.000 m"), hud);
    }

    @Test
    void windBlowsTheBallBackAndStillAirMatchesThePull() throws Exception {
        float[] landings = harness.call(() -> {
            wind.restart();
            for (int frame = 0; frame < 300; ++frame) {
                wind.advance(H);
            }
            return new float[] {wind.getParticles().get(0).getLandingX(),
                wind.getParticles().get(1).getLandingX()};
        });
        // Still air: the stepped parabola of demo 2, about vx·h/2 short of 20.41 m.
        assertEquals(2 * 10 * 10 / 9.8, landings[0], 0.2);
        assertTrue(landings[1] < landings[0] - 3f, "headwind: " + landings[1]);

        // In still air (W = 0) the wind force is linear drag: F = b·(0 − V) = −b·V.
        WindDemo.Wind calm = new WindDemo.Wind(new Vector3f(), 0.3f);
        particlelab.physics.Particle ball = new particlelab.physics.Particle(new Vector3f(),
                new Vector3f(3f, -4f, 0f), 2f);
        Vector3f force = new Vector3f();
        calm.addForce(ball, force);
        // One float product each: within an ulp or two of the exact −0.9 and 1.2.
        assertEquals(-0.9f, force.x, 1e-6f);
        assertEquals(1.2f, force.y, 1e-6f);
        assertEquals(0f, force.z, 0f);
        assertEquals(0.15f, calm.dampingRate(ball), 0f);
    }

    private float fireAndLand(HelloAimingDemo.Aim aim) throws Exception {
        return harness.call(() -> {
            aiming.setAim(aim);
            aiming.fire();
            for (int frame = 0; frame < 400; ++frame) {
                aiming.advance(H);
            }
            return aiming.getLastLandingX();
        });
    }
}

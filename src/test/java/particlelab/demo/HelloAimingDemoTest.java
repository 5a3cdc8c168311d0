package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import particlelab.app.HeadlessHarness;

/** HelloAiming attached to a headless app: the lecture formula's miss and its cure. */
class HelloAimingDemoTest {

    private static final float H = 1f / 60f;
    private static HelloAimingDemo aiming;
    private static HeadlessHarness harness;

    @BeforeAll
    static void startApp() throws Exception {
        aiming = new HelloAimingDemo();
        harness = HeadlessHarness.start(List.of(aiming));
    }

    @AfterAll
    static void stopApp() {
        harness.close();
    }

    @Test
    void lectureFormulaLandsVxTimesHShortAndTheCorrectionHits() throws Exception {
        float lecture = fireAndLand(HelloAimingDemo.Aim.LECTURE);
        // docs/numerics.md: the stepped shot lands exactly vx·h = 20/60 m short; float rounding
        // over 300 steps moves the interpolated crossing by well under 1 mm.
        assertEquals(100.0 - 20.0 / 60.0, lecture, 1e-3);
        float discrete = fireAndLand(HelloAimingDemo.Aim.DISCRETE);
        assertEquals(100.0, discrete, 1e-3);
        String hud = harness.call(() -> aiming.formatHud(new StringBuilder()).toString());
        assertTrue(hud.contains("Predicted landing with h = 16.7 ms:  x = 100.000 m"), hud);
        assertTrue(hud.contains("last landed at x = 100.000 m"), hud);
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

package particlelab.lecture;

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
        int shot = harness.call(aiming::getShotNumber);
        assertTrue(hud.contains("Shot " + shot + ": landed at x = 100.000 m after "), hud);
    }

    @Test
    void tAndTheShotLinesDescribeTheShotInTheAir() throws Exception {
        Object[] inTheAir = harness.call(() -> {
            aiming.restart(); // shot 1 in the air at t = 0
            aiming.setAim(HelloAimingDemo.Aim.LECTURE);
            for (int frame = 0; frame < 400; ++frame) {
                aiming.advance(H);
            }
            double landedAt = aiming.getClock().getSimulatedSeconds();
            aiming.fire(); // shot 2
            for (int frame = 0; frame < 60; ++frame) {
                aiming.advance(H);
            }
            return new Object[] {landedAt, aiming.getClock().getSimulatedSeconds(),
                aiming.getShotNumber(), aiming.getLandedShotNumber(),
                aiming.getLastFlightSeconds(),
                aiming.formatHud(new StringBuilder()).toString()};
        });
        double flight = (Double) inTheAir[4];
        // Shot 1 flew about S/vx − h = 4.983 s (the stepped parabola lands a step early), and
        // t stopped within a step of its landing.
        assertEquals(100.0 / 20.0 - H, flight, 1e-3);
        assertEquals(flight, (Double) inTheAir[0], H);
        // Firing shot 2 started t again: 60 frames of h.
        assertEquals(60.0 * H, (Double) inTheAir[1], 1e-9);
        assertEquals(2, inTheAir[2]);
        assertEquals(1, inTheAir[3]);
        String hud = (String) inTheAir[5];
        assertTrue(hud.contains("t = 1.00 s"), hud);
        assertTrue(hud.contains("Shot 2: in the air for 1.00 s  (lecture, vx 20.0 m/s)"), hud);
        assertTrue(hud.contains("Shot 1: landed at x = 99.667 m after 4.983 s,  miss -0.333 m"),
                hud);
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

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.scene.Spatial;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.demo.DemoParticle;

/** HelloAiming attached to a headless app: the lecture formula's miss and its cure, at once. */
class HelloAimingDemoTest {

    private static final float H = 1f / 60f;
    private static final HelloAimingDemo aiming = new HelloAimingDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(aiming));

    @Test
    void bothAimsLandAndTheHiddenBulletOfAnAimFiredAloneIsNotDrawn() throws Exception {
        Object[] measured = harness.call(() -> {
            aiming.setBothAims();
            aiming.fire();
            for (int frame = 0; frame < 400; ++frame) {
                aiming.advance(H);
            }
            float lecture = aiming.getLastLandingX(HelloAimingDemo.Aim.LECTURE);
            float discrete = aiming.getLastLandingX(HelloAimingDemo.Aim.DISCRETE);
            boolean bothDrawn = drawn(HelloAimingDemo.Aim.LECTURE)
                    && drawn(HelloAimingDemo.Aim.DISCRETE);
            aiming.setAim(HelloAimingDemo.Aim.DISCRETE);
            aiming.fire();
            aiming.advance(H);
            boolean[] alone = {drawn(HelloAimingDemo.Aim.LECTURE),
                drawn(HelloAimingDemo.Aim.DISCRETE)};
            aiming.setBothAims();
            aiming.fire();
            return new Object[] {lecture, discrete, bothDrawn, alone[0], alone[1],
                drawn(HelloAimingDemo.Aim.LECTURE)};
        });
        // docs/numerics.md: the stepped shot lands exactly vx·h = 20/60 m short; float rounding
        // over 300 steps moves the interpolated crossing by well under 1 mm.
        assertEquals(100.0 - 20.0 / 60.0, (Float) measured[0], 1e-3);
        assertEquals(100.0, (Float) measured[1], 1e-3);
        assertEquals(true, measured[2]);
        // The discrete aim alone: the lecture's bullet flies the same shot, hidden.
        assertEquals(false, measured[3]);
        assertEquals(true, measured[4]);
        assertEquals(true, measured[5]);
    }

    @Test
    void tAndTheShotLinesDescribeTheShotInTheAir() throws Exception {
        boolean[] tooSmall = {true};
        Object[] inTheAir = harness.call(() -> {
            aiming.setBothAims();
            aiming.restart(); // shot 1 in the air at t = 0
            for (int frame = 0; frame < 400; ++frame) {
                aiming.advance(H);
            }
            double landedAt = aiming.getClock().getSimulatedSeconds();
            aiming.fire(); // shot 2
            aiming.getDemoHud().layOut(1280, 720);
            for (int frame = 0; frame < 60; ++frame) {
                aiming.update(H);
            }
            tooSmall[0] = aiming.getHud().getLayout().isTooSmall();
            return new Object[] {landedAt, aiming.getClock().getSimulatedSeconds(),
                aiming.getShotNumber(), aiming.getLandedShotNumber(),
                aiming.getLastFlightSeconds(HelloAimingDemo.Aim.DISCRETE),
                aiming.formatHud(new StringBuilder()).toString()};
        });
        double flight = (Double) inTheAir[4];
        // The corrected shot 1 flew about S/vx = 5 s (the lecture's lands a step early), and
        // t stopped within a step of the later landing.
        assertEquals(100.0 / 20.0, flight, 1e-3);
        assertEquals(flight, (Double) inTheAir[0], H);
        // Firing shot 2 started t again: 60 frames of h.
        assertEquals(60.0 * H, (Double) inTheAir[1], 1e-9);
        assertEquals(2, inTheAir[2]);
        assertEquals(1, inTheAir[3]);
        String hud = (String) inTheAir[5];
        // Its most lines (two ghost readouts, both aims, the shot in the air and the one
        // that landed) all show at 1280x720, the footer's keys too.
        assertFalse(tooSmall[0], hud);
        assertTrue(hud.contains("t = 1.00 s"), hud);
        assertTrue(hud.contains("Shot 2: in the air for 1.00 s  (both, vx 20.0 m/s)"), hud);
        assertTrue(hud.contains("Shot 1 landed (vx 20.0 m/s):  lecture x = 99.667 m, miss -0.333"
                + " m; discrete x = 100.000 m, miss 0.000 m"), hud);
    }

    /** Whether an aim's bullet is drawn: its view's node is not culled. */
    private static boolean drawn(HelloAimingDemo.Aim aim) {
        DemoParticle bullet = aiming.getBullet(aim);
        return aiming.getView(bullet).getNode().getCullHint() != Spatial.CullHint.Always;
    }
}

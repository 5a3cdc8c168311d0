package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.lecture.HelloAimingDemo.Aim;

/**
 * Issue 19 §8: HelloAiming fires the lecture's aim and the discrete correction at once, from
 * the same gun with the same vx and step. Plain JUnit: the demo's physics and HUD text run
 * without jME.
 */
class HelloAimingTwoShotsTest {

    /** The demo's fixed step (s). */
    private static final float H = 1f / 60f;
    /** Frames of H that see a 20 m/s shot land: S/vx = 5 s is 300. */
    private static final int FRAMES = 400;

    @Test
    void bothAimsFlyAtOnceAndEachLandsWhereItsAimFiredAloneLands() {
        HelloAimingDemo both = run(new HelloAimingDemo());
        assertEquals(HelloAimingDemo.BOTH, both.getFiring());
        for (Aim aim : Aim.values()) {
            assertEquals(1, both.getLandedShotNumber(aim), aim.toString());
            // The same aim fired alone, by the single-aim path (L, then F): the bullets share
            // the world but nothing acts between them, so the same floats give the same
            // landing, bit for bit.
            HelloAimingDemo alone = new HelloAimingDemo();
            alone.setAim(aim);
            alone.fire();
            run(alone);
            // Shot 1 is the one the gun fires at the start; F fired shot 2.
            assertEquals(2, alone.getLandedShotNumber(aim), aim.toString());
            assertEquals(alone.getLastLandingX(aim), both.getLastLandingX(aim), 0f,
                    aim.toString());
            assertEquals(alone.getLastFlightSeconds(aim), both.getLastFlightSeconds(aim), 0.0,
                    aim.toString());
        }
        // docs/numerics.md: the stepped lecture shot lands exactly vx·h = 20/60 m short, the
        // corrected one on the target; float rounding over 300 steps moves the interpolated
        // crossing by well under 1 mm.
        assertEquals(100.0 - 20.0 / 60.0, both.getLastLandingX(Aim.LECTURE), 1e-3);
        assertEquals(100.0, both.getLastLandingX(Aim.DISCRETE), 1e-3);
        String hud = both.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("Next shot (L): both aims,  F fires;  S = 100 m,  vx = 20.0 m/s"
                + " (Up/Down),  S/vx = 5.000 s,  vx·h = 0.333 m at h = 16.7 ms"), hud);
        assertTrue(hud.contains("lecture   vy = g·S/(2·vx) = 24.500 m/s:  predicted x = 99.667 m,"
                + "  miss -0.333 m"), hud);
        assertTrue(hud.contains("discrete  vy = g·(S/vx + h)/2 = 24.582 m/s:  predicted"
                + " x = 100.000 m,  miss 0.000 m"), hud);
        assertTrue(hud.contains("Shot 1 landed (vx 20.0 m/s):  lecture x = 99.667 m, miss -0.333"
                + " m; discrete x = 100.000 m, miss 0.000 m"), hud);
        assertFalse(hud.contains("NaN"), hud);
    }

    @Test
    void eachLandingMatchesItsPredictedShot() {
        HelloAimingDemo both = run(new HelloAimingDemo());
        for (Aim aim : Aim.values()) {
            // The prediction flies the same integrator, g, vx and h in its own simulator and
            // interpolates the ground crossing in double: the two agree far inside a 0.1 mm.
            assertEquals(both.getPredictedLandingX(aim), both.getLastLandingX(aim), 1e-4,
                    aim.toString());
        }
    }

    @Test
    void theLKeyFiresOneAimAloneAndItsLineAloneReportsTheShot() {
        HelloAimingDemo aiming = run(new HelloAimingDemo());
        aiming.setAim(Aim.LECTURE);
        assertTrue(aiming.firesAim(Aim.LECTURE));
        assertFalse(aiming.firesAim(Aim.DISCRETE));
        aiming.fire();
        // The other bullet flies the same shot, parked: out of the HUD and out of the count.
        assertTrue(aiming.getBullet(Aim.DISCRETE).isParked());
        assertFalse(aiming.getBullet(Aim.LECTURE).isParked());
        run(aiming);
        assertEquals(2, aiming.getLandedShotNumber(Aim.LECTURE));
        assertEquals(1, aiming.getLandedShotNumber(Aim.DISCRETE));
        String hud = aiming.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("Next shot (L): lecture alone,"), hud);
        assertTrue(hud.contains("Shot 2 landed (vx 20.0 m/s):  lecture x = 99.667 m, miss -0.333"
                + " m\n"), hud);
        assertFalse(hud.contains("discrete x ="), hud);
        assertFalse(hud.contains("Shot 1"), hud);
        aiming.setBothAims();
        aiming.fire();
        assertFalse(aiming.getBullet(Aim.DISCRETE).isParked());
    }

    private static HelloAimingDemo run(HelloAimingDemo aiming) {
        for (int frame = 0; frame < FRAMES; ++frame) {
            aiming.getRun().advancePhysics(H);
        }
        return aiming;
    }
}

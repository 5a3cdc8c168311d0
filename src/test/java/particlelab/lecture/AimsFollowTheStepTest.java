package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.aiming.LevelAim;
import particlelab.physics.Gravity;

/**
 * Every value the aiming demos derive from the step h follows a new h, set before the scene
 * starts ({@code --set h=1/10}, applied after the scene fired its first shot) or changed live:
 * HelloAiming's discrete aim of the shot in the air, the iterative aimer's planned round and
 * the flight h it shows. Plain JUnit: the demos' worlds need no application.
 */
class AimsFollowTheStepTest {

    /** The step docs/demos/aiming.md recommends for showing the correction (s). */
    private static final float LONG_STEP = 0.1f;
    private static final float DEFAULT_STEP = 1f / 60f;
    /** Frames enough for any shot of these demos to land (s of flight at the long step). */
    private static final int FRAMES = 2000;

    @Test
    void helloAimingFiresItsFirstShotForTheStepSetBeforeTheStart() {
        HelloAimingDemo aiming = new HelloAimingDemo();
        aiming.getParameters().set("h", LONG_STEP);
        aiming.getWorld();
        float vy = aiming.getBullet(HelloAimingDemo.Aim.DISCRETE).getParticle().velocity.y;
        // The launch is the formula's float, nothing stepped yet: exact.
        assertEquals((float) LevelAim.discreteVy(Gravity.STANDARD_G,
                HelloAimingDemo.TARGET_DISTANCE, HelloAimingDemo.DEFAULT_VX, LONG_STEP), vy);
        assertEquals(1, aiming.getShotNumber());
        flyToLanding(aiming, LONG_STEP);
        assertLandsOnTarget(aiming);
        String hud = aiming.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("vx·h = 2.000 m at h = 100.0 ms"), hud);
        assertTrue(hud.contains("Shot 1 landed (vx 20.0 m/s):  lecture x = 98.000 m, miss"
                + " -2.000 m; discrete x = 100.000 m, miss 0.000 m"), hud);
    }

    @Test
    void helloAimingFiresTheShotInTheAirAgainForANewStep() {
        HelloAimingDemo aiming = new HelloAimingDemo();
        for (int frame = 0; frame < 60; ++frame) {
            aiming.getRun().advancePhysics(DEFAULT_STEP);
        }
        assertEquals(1, aiming.getShotNumber());
        aiming.getParameters().set("h", LONG_STEP);
        // Shot 1 was in flight, aimed for 1/60 s: the new h fires shot 2, aimed for it.
        assertEquals(2, aiming.getShotNumber());
        assertEquals((float) LevelAim.discreteVy(Gravity.STANDARD_G,
                HelloAimingDemo.TARGET_DISTANCE, HelloAimingDemo.DEFAULT_VX, LONG_STEP),
                aiming.getBullet(HelloAimingDemo.Aim.DISCRETE).getParticle().velocity.y);
        flyToLanding(aiming, LONG_STEP);
        assertEquals(2, aiming.getLandedShotNumber());
        assertLandsOnTarget(aiming);
    }

    @Test
    void helloAimingFiresItsFirstShotWithTheSpeedSetBeforeTheStart() {
        // The tour's slide-code stop sets vx = 21 before the scene starts.
        HelloAimingDemo aiming = new HelloAimingDemo();
        aiming.getParameters().set("vx", 21f);
        aiming.getWorld();
        assertEquals(21f, aiming.getBullet(HelloAimingDemo.Aim.LECTURE).getParticle().velocity.x);
        assertEquals((float) LevelAim.lectureVy(Gravity.STANDARD_G,
                HelloAimingDemo.TARGET_DISTANCE, 21f),
                aiming.getBullet(HelloAimingDemo.Aim.LECTURE).getParticle().velocity.y);
        assertEquals(1, aiming.getShotNumber());
    }

    @Test
    void theCheatFrontierIsForTheStepTheBulletFlies() {
        FastBulletsDemo cheat = new FastBulletsDemo();
        cheat.getParameters().set("h", LONG_STEP);
        cheat.getWorld();
        assertEquals(LONG_STEP, cheat.getFrontier().getStepSeconds());
        cheat.getParameters().set("h", DEFAULT_STEP);
        assertEquals(DEFAULT_STEP, cheat.getFrontier().getStepSeconds());
    }

    @Test
    void iterativeAimingPlansItsRoundForTheStepSetBeforeTheStart() {
        IterativeAimingDemo iterate = new IterativeAimingDemo();
        iterate.getParameters().set("h", LONG_STEP);
        iterate.getWorld();
        String hud = iterate.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("predictor h 100.0 ms, flight h 100.0 ms"), hud);
        assertFlownAsPlanned(iterate, LONG_STEP);
    }

    @Test
    void iterativeAimingPlansANewRoundForALiveStep() {
        IterativeAimingDemo iterate = new IterativeAimingDemo();
        for (int frame = 0; frame < 30; ++frame) {
            iterate.getRun().advancePhysics(DEFAULT_STEP);
        }
        iterate.getParameters().set("h", LONG_STEP);
        assertEquals(0, iterate.countLanded());
        String hud = iterate.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("flight h 100.0 ms"), hud);
        assertFlownAsPlanned(iterate, LONG_STEP);
    }

    /** Step until the shot in the air has landed with both aims (the discrete one last). */
    private static void flyToLanding(HelloAimingDemo aiming, float step) {
        HelloAimingDemo.Aim last = HelloAimingDemo.Aim.DISCRETE;
        for (int frame = 0; frame < FRAMES
                && aiming.getLandedShotNumber(last) != aiming.getShotNumber(); ++frame) {
            aiming.getRun().advancePhysics(step);
        }
        assertEquals(aiming.getShotNumber(), aiming.getLandedShotNumber(last));
    }

    private static void assertLandsOnTarget(HelloAimingDemo aiming) {
        // S/(vx·h) = 50 steps is whole, so the discrete aim's stepped samples hit y = 0 at
        // x = S exactly (docs/numerics.md); float32 rounding over 50 steps moves the crossing
        // by well under 1 mm. The lecture's lands vx·h = 2 m short.
        assertEquals(HelloAimingDemo.TARGET_DISTANCE,
                aiming.getLastLandingX(HelloAimingDemo.Aim.DISCRETE), 1e-3);
        assertEquals(HelloAimingDemo.TARGET_DISTANCE - HelloAimingDemo.DEFAULT_VX * LONG_STEP,
                aiming.getLastLandingX(HelloAimingDemo.Aim.LECTURE), 1e-3);
    }

    /** Fly the whole round: each shot lands where the aimer, stepping h, predicted. */
    private static void assertFlownAsPlanned(IterativeAimingDemo iterate, float step) {
        for (int frame = 0; frame < 20 * FRAMES && !iterate.isRoundOver(); ++frame) {
            iterate.getRun().advancePhysics(step);
        }
        assertTrue(iterate.isRoundOver());
        for (int shot = 0; shot < iterate.getPlan().size(); ++shot) {
            // The aimer steps the same Euler step in the same float order, with the h the
            // shots fly: the flown landing is the planned one to float rounding (1 mm).
            assertEquals(iterate.getPlan().getLandingX(shot), iterate.getFlownLandingX(shot),
                    1e-3, "shot " + (shot + 1));
        }
        int last = iterate.getPlan().size() - 1;
        assertEquals(IterativeAimingDemo.TARGET_DISTANCE, iterate.getFlownLandingX(last),
                IterativeAimingDemo.TOLERANCE_METRES);
    }
}

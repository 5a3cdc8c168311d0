package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.aiming.LevelAim;
import particlelab.aiming.SlideCodeBullet;
import particlelab.demo.DemoParticle;
import particlelab.view.TextFormat;

/**
 * HelloAiming's slide-code lane, in plain JUnit: the slide's bullet beside the recipe's, the
 * same floats in flight, one step below the ground at the end, the HUD saying so.
 */
class HelloAimingSlideCodeTest {

    private static final float H = 1f / 60f;
    /** A vx whose flight S/vx is far from a whole number of steps (260.87 at h = 1/60). */
    private static final float VX = 23f;

    /**
     * While the recipe's lecture bullet flies, the slide bullet's position has its bits at
     * every step (no tolerance: see {@code SlideCodeBulletTest}); the step the recipe lands in
     * is the slide's last, {@code N = floor(T/h)} with {@code T = S/vx} (its samples meet
     * the ground at step {@code T/h − 1}, not whole here); the slide stops
     * there below the ground, past the recipe's interpolated crossing by less than one step
     * {@code vx·h}.
     */
    @Test
    void theSlideBulletFliesTheRecipesFloatsAndStopsOneStepBelowTheGround() {
        HelloAimingDemo demo = new HelloAimingDemo();
        demo.getParameters().set("code", HelloAimingDemo.BOTH_CODES);
        demo.setHorizontalSpeed(VX);
        demo.fire();
        assertTrue(demo.isSlideInShot());
        DemoParticle recipe = demo.getBullet(HelloAimingDemo.Aim.LECTURE);
        SlideCodeBullet slide = demo.getSlideBullet();
        int steps = 0;
        while (!recipe.hasLanded() && steps < 1000) {
            demo.getRun().advancePhysics(H);
            ++steps;
            if (!recipe.hasLanded()) {
                Vector3f p = recipe.getParticle().position;
                assertEquals(Float.floatToIntBits(p.x), Float.floatToIntBits(slide.position.x),
                        "x at step " + steps);
                assertEquals(Float.floatToIntBits(p.y), Float.floatToIntBits(slide.position.y),
                        "y at step " + steps);
            }
        }
        int expected = (int) Math.floor(HelloAimingDemo.TARGET_DISTANCE / VX / H);
        assertEquals(expected, steps);
        assertEquals(expected, slide.getSteps());
        assertTrue(slide.isStopped());
        assertTrue(slide.position.y < 0f);
        float past = demo.getSlideOvershootX();
        assertTrue(past > 0f && past < VX * H, "past the crossing by " + past);
        // More steps leave it where its test stopped it.
        Vector3f end = slide.position.clone();
        demo.getRun().advancePhysics(H);
        assertEquals(end, slide.position);
        assertEquals(expected, slide.getSteps());

        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        for (String line : SlideCodeBullet.LISTING) {
            assertTrue(hud.contains(line), line + " in\n" + hud);
        }
        assertTrue(hud.contains(" m past the recipe's interpolated crossing"), hud);
        StringBuilder below = new StringBuilder("stopped ");
        TextFormat.appendFixed(below, -slide.position.y, 3);
        assertTrue(hud.contains(below), below + " in\n" + hud);
    }

    /**
     * The lane is off by default (it allocates): no slide bullet in the shot, no listing in
     * the HUD; J's value applies from the next shot.
     */
    @Test
    void theLaneIsOffByDefaultAndAppliesFromTheNextShot() {
        HelloAimingDemo demo = new HelloAimingDemo();
        demo.getRun().advancePhysics(H);
        assertEquals(HelloAimingDemo.RECIPE_CODE, demo.getCode());
        assertFalse(demo.isSlideInShot());
        assertEquals(0, demo.getSlideBullet().getSteps());
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        assertFalse(hud.contains(SlideCodeBullet.LISTING[1]), hud);
        demo.setCode(HelloAimingDemo.SLIDE_CODE);
        demo.getRun().advancePhysics(H);
        assertFalse(demo.isSlideInShot());
        demo.fire();
        demo.getRun().advancePhysics(H);
        assertTrue(demo.isSlideInShot());
        assertEquals(1, demo.getSlideBullet().getSteps());
        // g changes the slide's gravity vector too: it flies the recipe's g.
        demo.getParameters().set("g", 5f);
        demo.fire();
        float vy = (float) LevelAim.lectureVy(5f, HelloAimingDemo.TARGET_DISTANCE,
                demo.getHorizontalSpeed());
        demo.getRun().advancePhysics(H);
        // One step: vy − g·h in float, a rounding or two of about 1e-6 m/s.
        assertEquals(vy - 5f * H, demo.getSlideBullet().velocity.y, 1e-5);
    }

    /**
     * The HUD says why the slide's bullet stops where it does: at the tour's vx = 21 m/s,
     * {@code S/(vx·h)} = 285.714 is not whole and it stops at step floor(285.714) = 285, a
     * visible overrun; at the lecture's 20 m/s, 300 is whole, sample 299 lies on the ground and
     * float rounding puts it just below, so the listing stops there, 0.000 m below.
     */
    @Test
    void theHudSaysWhetherASampleLiesOnTheGround() {
        String[] expected = {"step 285: stopped 0.111 m below the ground at x = 99.750 m",
            "   // S/(vx·h) = 285.714: no sample on y = 0\n",
            "step 299: stopped 0.000 m below the ground at x = 99.667 m",
            "   // S/(vx·h) = 300 is whole: a sample on y = 0, rounding decides\n"};
        float[] speeds = {21f, 20f};
        for (int i = 0; i < speeds.length; ++i) {
            HelloAimingDemo demo = new HelloAimingDemo();
            demo.getParameters().set("code", HelloAimingDemo.BOTH_CODES);
            demo.getParameters().set("vx", speeds[i]);
            for (int frame = 0; frame < 400; ++frame) {
                demo.getRun().advancePhysics(H);
            }
            assertTrue(demo.getSlideBullet().isStopped());
            String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
            assertTrue(hud.contains(expected[2 * i]), expected[2 * i] + " in\n" + hud);
            assertTrue(hud.contains(expected[2 * i + 1]), expected[2 * i + 1] + " in\n" + hud);
        }
        // The 0.111 m is the closed form's: the lecture aim's samples lie at
        // y_n = n·h·vy − g·h²·n(n+1)/2 with vy = g·S/(2·vx); at vx = 21, h = 1/60, g = 9.8:
        // y_285 = −0.110833 m exactly, which the HUD's three decimals show as 0.111.
        double g = particlelab.physics.Gravity.STANDARD_G;
        double vy = g * HelloAimingDemo.TARGET_DISTANCE / (2.0 * 21.0);
        double h = 1.0 / 60.0;
        int n = 285;
        assertEquals(-0.110833, n * h * vy - g * h * h * n * (n + 1) / 2.0, 1e-6);
    }
}

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
     * is the slide's last, {@code N = ceil(T/h − 1)} with {@code T = S/vx}; the slide stops
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
            demo.advancePhysics(H);
            ++steps;
            if (!recipe.hasLanded()) {
                Vector3f p = recipe.getParticle().position;
                assertEquals(Float.floatToIntBits(p.x), Float.floatToIntBits(slide.position.x),
                        "x at step " + steps);
                assertEquals(Float.floatToIntBits(p.y), Float.floatToIntBits(slide.position.y),
                        "y at step " + steps);
            }
        }
        int expected = (int) Math.ceil(HelloAimingDemo.TARGET_DISTANCE / VX / H - 1.0);
        assertEquals(expected, steps);
        assertEquals(expected, slide.getSteps());
        assertTrue(slide.isStopped());
        assertTrue(slide.position.y < 0f);
        float past = demo.getSlideOvershootX();
        assertTrue(past > 0f && past < VX * H, "past the crossing by " + past);
        // More steps leave it where its test stopped it.
        Vector3f end = slide.position.clone();
        demo.advancePhysics(H);
        assertEquals(end, slide.position);
        assertEquals(expected, slide.getSteps());

        String hud = demo.formatHud(new StringBuilder()).toString();
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
        demo.advancePhysics(H);
        assertEquals(HelloAimingDemo.RECIPE_CODE, demo.getCode());
        assertFalse(demo.isSlideInShot());
        assertEquals(0, demo.getSlideBullet().getSteps());
        String hud = demo.formatHud(new StringBuilder()).toString();
        assertFalse(hud.contains(SlideCodeBullet.LISTING[1]), hud);
        demo.setCode(HelloAimingDemo.SLIDE_CODE);
        demo.advancePhysics(H);
        assertFalse(demo.isSlideInShot());
        demo.fire();
        demo.advancePhysics(H);
        assertTrue(demo.isSlideInShot());
        assertEquals(1, demo.getSlideBullet().getSteps());
        // g changes the slide's gravity vector too: it flies the recipe's g.
        demo.getParameters().set("g", 5f);
        demo.fire();
        float vy = (float) LevelAim.lectureVy(5f, HelloAimingDemo.TARGET_DISTANCE,
                demo.getHorizontalSpeed());
        demo.advancePhysics(H);
        // One step: vy − g·h in float, a rounding or two of about 1e-6 m/s.
        assertEquals(vy - 5f * H, demo.getSlideBullet().velocity.y, 1e-5);
    }
}

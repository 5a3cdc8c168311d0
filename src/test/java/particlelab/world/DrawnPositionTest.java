package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Random;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

/**
 * The view's interpolation: a body is drawn on the segment between its last two physics
 * states, at the fraction α of the way ({@code P_prev + α·(P − P_prev)}); α = 1 is the
 * physics state itself, bit for bit.
 */
class DrawnPositionTest {

    private static final int TRIALS = 10_000;

    @Test
    void theBlendLiesOnTheSegmentAtAlpha() {
        Random random = new Random(21L);
        Vector3f from = new Vector3f();
        Vector3f to = new Vector3f();
        Vector3f drawn = new Vector3f();
        for (int i = 0; i < TRIALS; ++i) {
            from.set(next(random), next(random), next(random));
            to.set(next(random), next(random), next(random));
            float alpha = random.nextFloat();
            Body.blend(from, to, alpha, drawn);
            float length = from.distance(to);
            // On the segment: the two parts add up to the whole, to float round-off (a few
            // ulps of coordinates up to 100 m: 1e-4 m is far above that, far below a pixel).
            assertEquals(length, from.distance(drawn) + drawn.distance(to), 1e-4f);
            // At the fraction α of the way, to the same round-off.
            assertEquals(alpha * length, from.distance(drawn), 1e-4f);
        }
        from.set(1f, 2f, 3f);
        to.set(-4f, 5.5f, 0.1f);
        assertEquals(to, Body.blend(from, to, 1f, drawn));
        assertEquals(from, Body.blend(from, to, 0f, drawn));
        assertEquals(to, Body.blend(from, to, Float.NaN, drawn), "NaN draws the physics state");
    }

    @Test
    void aBodyIsDrawnBetweenItsLastTwoSteps() {
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()), new Vector3f(0f, 5f, 0f),
                new Vector3f(3f, 4f, 0f), 1f, 0f);
        float h = 1f / 60f;
        world.step(h);
        Vector3f before = new Vector3f(ball.getPosition());
        world.step(h);
        Vector3f after = new Vector3f(ball.getPosition());
        Vector3f drawn = ball.copyDrawnPosition(0.25f, new Vector3f());
        assertEquals(before.distance(after), before.distance(drawn) + drawn.distance(after),
                1e-6f);
        assertEquals(0.25f * before.distance(after), before.distance(drawn), 1e-6f);
        assertEquals(after, ball.copyDrawnPosition(1f, drawn));
        ball.settle();
        assertEquals(after, ball.copyDrawnPosition(0f, drawn), "settled: no last step");
        assertTrue(before.distance(after) > 0f);
    }

    private static float next(Random random) {
        return 200f * random.nextFloat() - 100f;
    }
}

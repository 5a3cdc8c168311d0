package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Random;
import org.junit.jupiter.api.Test;
import particlelab.collision.ThinWall;
import particlelab.physics.ParticleIntegrator;

/**
 * A fast ball against a thin wall: the swept test never misses; the overlap test misses at
 * the rate {@code max(0, 1 − (2r + D)/(v·h))} predicts for a uniformly random phase.
 *
 * <p>Binomial tolerance: N shots each missing with probability p give a miss count with mean
 * {@code N·p} and standard deviation {@code σ = √(N·p·(1−p))}; the tests allow 4σ (a fair
 * run strays that far once in about 16 000; the seeds are fixed, so the runs repeat).
 */
class TunnellingTest {

    private static final double SIGMAS = 4.0;

    @Test
    void sweptTestNeverMissesOverRandomPhasesSpeedsAndSizes() {
        Random random = new Random(42);
        float[] steps = {1f / 30f, 1f / 60f, 1f / 120f};
        int shots = 3000;
        int misses = 0;
        for (int i = 0; i < shots; ++i) {
            float speed = 1f + 2000f * random.nextFloat();
            float radius = 0.005f + 0.2f * random.nextFloat();
            float thickness = 0.005f + 0.2f * random.nextFloat();
            float step = steps[i % steps.length];
            if (!hits(speed, radius, thickness, step, random.nextFloat(), Detection.SWEPT)) {
                ++misses;
            }
        }
        assertEquals(0, misses);
    }

    @Test
    void overlapTestMissesAtThePredictedRate() {
        // v·h = 2·(2r + D) and 5·(2r + D): p = 0.5 and 0.8.
        float radius = 0.1f;
        float thickness = 0.2f;
        float step = 1f / 60f;
        float band = 2f * radius + thickness;
        Random random = new Random(7);
        int shots = 4000;
        for (float multiple : new float[] {2f, 5f}) {
            float speed = multiple * band / step;
            double p = new ThinWall(Vector3f.UNIT_X, 0f, thickness)
                    .overlapMissProbability(radius, speed, step);
            assertEquals(1.0 - 1.0 / multiple, p, 1e-6);
            int misses = 0;
            for (int i = 0; i < shots; ++i) {
                if (!hits(speed, radius, thickness, step, random.nextFloat(),
                        Detection.OVERLAP)) {
                    ++misses;
                }
            }
            double sigma = Math.sqrt(shots * p * (1.0 - p));
            assertEquals(shots * p, misses, SIGMAS * sigma, "v·h = " + multiple + "·(2r+D)");
        }
    }

    @Test
    void overlapTestNeverMissesWhileAStepIsShorterThanTheBand() {
        Random random = new Random(3);
        for (int i = 0; i < 1000; ++i) {
            // v·h = 0.4 m·(0.1 .. 0.99) < 2r + D = 0.4 m.
            float speed = (0.1f + 0.89f * random.nextFloat()) * 0.4f * 60f;
            assertTrue(hits(speed, 0.1f, 0.2f, 1f / 60f, random.nextFloat(), Detection.OVERLAP));
        }
    }

    /** Fire one shot along +x at the wall |x| <= D/2 from (1 + phase) steps' travel away. */
    private static boolean hits(float speed, float radius, float thickness, float step,
            float phase, Detection detection) {
        World world = new World(4);
        float reach = radius + 0.5f * thickness;
        float travel = speed * step;
        Body shot = world.addBody(new ParticleIntegrator(),
                new Vector3f(-reach - (1f + phase) * travel, 0f, 0f),
                new Vector3f(speed, 0f, 0f), 1f, radius);
        world.addRule(new SurfaceRule("wall", new ThinWall(Vector3f.UNIT_X, 0f, thickness),
                new ImpulseResponse(1f, 0f, false), detection));
        while (shot.getPosition().x <= reach + travel && world.getLog().size() == 0) {
            world.step(step);
        }
        boolean hit = world.getLog().size() > 0;
        if (hit && detection == Detection.SWEPT) {
            // The overlap test pushes a ball out of the nearer face: one caught more than
            // half-way through leaves by the far side, seen but not stopped.
            assertTrue(shot.getVelocity().x < 0f, "bounced back");
        }
        return hit;
    }
}

package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.Allocations;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * The packed ground against the world's: the same particles dropped on the same ground, one
 * world body each ({@code SurfaceRule.ground} with an {@code ImpulseResponse}, overlap test)
 * and one packed loop for all, must stay at the same bits step after step, bounces and rest
 * included. Both run the same float operations in the same order (the batch step is
 * bit-identical to the per-particle step, and the contact is the same formula), so the
 * tolerance is zero.
 */
class GroundBounceTest {

    private static final float H = 1f / 60f;
    private static final float MASS = 0.5f;
    private static final float DRAG_B = 0.1f;
    private static final float RADIUS = 0.25f;
    /** 10 s: several bounces, and with e &lt; 1 the particles come to rest. */
    private static final int STEPS = 600;

    @ParameterizedTest(name = "e = {0}, threshold {1} m/s, resting fix {2}")
    @CsvSource({"0.5, 0, true", "0.8, 0.25, true", "0.5, 0, false", "1, 1, false",
        "0, 0, true"})
    void packedBouncesAgreeWithTheWorldsResponseToTheBit(float e, float threshold,
            boolean fix) {
        float[][] launches = {{0f, 3f, 0f, 1.3f, 0f, 0.2f}, {2f, RADIUS, 1f, -0.7f, 0f, 0f},
            {-1f, 0.9f, 0f, 0f, 6f, 0f}};
        int count = launches.length;
        ParticleIntegrator worldIntegrator =
                new ParticleIntegrator(new Gravity(), new LinearDrag(DRAG_B));
        World world = new World();
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e, threshold, fix),
                Detection.OVERLAP));
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        for (int i = 0; i < count; ++i) {
            float[] l = launches[i];
            world.addBody(worldIntegrator, new Vector3f(l[0], l[1], l[2]),
                    new Vector3f(l[3], l[4], l[5]), MASS, RADIUS);
            for (int axis = 0; axis < 3; ++axis) {
                positions[axis * count + i] = l[axis];
                velocities[axis * count + i] = l[3 + axis];
            }
        }
        ParticleIntegrator packedIntegrator =
                new ParticleIntegrator(new Gravity(), new LinearDrag(DRAG_B));
        GroundBounce ground = new GroundBounce(RADIUS, e, threshold, fix);
        float[] before = new float[count];
        int[] touched = new int[count];
        int contacts = 0;
        int reversals = 0;
        for (int step = 1; step <= STEPS; ++step) {
            System.arraycopy(velocities, count, before, 0, count);
            world.step(H);
            packedIntegrator.batch().stepPacked(positions, velocities, count, MASS, H);
            float[] velocityYAfterStep = java.util.Arrays.copyOfRange(velocities, count,
                    2 * count);
            contacts += ground.resolve(positions, velocities, before, count, touched);
            for (int i = 0; i < count; ++i) {
                Particle body = world.getBody(i).getParticle();
                String where = "particle " + i + " step " + step;
                for (int axis = 0; axis < 3; ++axis) {
                    assertEquals(body.position.get(axis), positions[axis * count + i], 0f,
                            where + " P" + axis);
                    assertEquals(body.velocity.get(axis), velocities[axis * count + i], 0f,
                            where + " V" + axis);
                }
                if (velocityYAfterStep[i] < 0f && velocities[count + i] > 0f) {
                    ++reversals;
                }
            }
        }
        assertTrue(contacts > 0, "the particles touched the ground");
        if (e > 0f) {
            assertTrue(reversals >= count, "each particle bounced: " + reversals);
        }
    }

    /**
     * The first count particles of a layout with a larger stride bounce to the same bits, and
     * give the same contacts, as the same particles packed alone; the slots beyond count are
     * not touched.
     */
    @Test
    void aStrideResolvesTheFirstParticlesAloneToTheSameBits() {
        int count = 200;
        int stride = 233;
        java.util.SplittableRandom random = new java.util.SplittableRandom(5);
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        float[] before = new float[count];
        for (int i = 0; i < 3 * count; ++i) {
            // heights from 0 to 2r: about half in contact; velocities of both signs
            positions[i] = (float) (2.0 * RADIUS * random.nextDouble());
            velocities[i] = (float) (4.0 * random.nextDouble() - 2.0);
        }
        for (int i = 0; i < count; ++i) {
            before[i] = velocities[count + i] + 0.1f;
        }
        float[] widePositions = new float[3 * stride];
        float[] wideVelocities = new float[3 * stride];
        java.util.Arrays.fill(widePositions, -1f);
        for (int axis = 0; axis < 3; ++axis) {
            System.arraycopy(positions, axis * count, widePositions, axis * stride, count);
            System.arraycopy(velocities, axis * count, wideVelocities, axis * stride, count);
        }
        GroundBounce ground = new GroundBounce(RADIUS, 0.7f, 0.2f, true);
        int[] touched = new int[count];
        int[] wideTouched = new int[count];
        int contacts = ground.resolve(positions, velocities, before, count, touched);
        int wideContacts = ground.resolve(widePositions, wideVelocities, before, stride, count,
                wideTouched);
        assertTrue(contacts > count / 4 && contacts < count, "contacts " + contacts);
        assertEquals(contacts, wideContacts, "contacts");
        for (int c = 0; c < contacts; ++c) {
            assertEquals(touched[c], wideTouched[c], "contact " + c);
        }
        for (int axis = 0; axis < 3; ++axis) {
            for (int i = 0; i < stride; ++i) {
                if (i < count) {
                    assertEquals(positions[axis * count + i], widePositions[axis * stride + i],
                            0f, "P" + axis + " of " + i);
                    assertEquals(velocities[axis * count + i],
                            wideVelocities[axis * stride + i], 0f, "V" + axis + " of " + i);
                } else {
                    // below the ground, so in contact if it were looked at
                    assertEquals(-1f, widePositions[axis * stride + i], 0f, "slot " + i);
                    assertEquals(0f, wideVelocities[axis * stride + i], 0f, "slot " + i);
                }
            }
        }
    }

    @Test
    void aParticleAtRestStaysExactlyAtRestWithTheRestingFix() {
        // Dormant fountain slots rely on this: V = 0 at y = r; the step gives it −g·h, the
        // ground takes exactly that back (v_s' = max(0, e·g·h − e·g·h) = 0) and lifts it by
        // the g·h² it sank, an exact float subtraction (Sterbenz: y within a factor 2 of r).
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(), new LinearDrag(DRAG_B));
        GroundBounce ground = new GroundBounce(RADIUS, 0.7f, 0f, true);
        float[] positions = {1f, RADIUS, 2f};
        float[] velocities = {0f, 0f, 0f};
        float[] before = new float[1];
        int[] touched = new int[1];
        for (int step = 0; step < 10_000; ++step) {
            before[0] = velocities[1];
            integrator.batch().stepPacked(positions, velocities, 1, MASS, H);
            ground.resolve(positions, velocities, before, 1, touched);
        }
        assertEquals(RADIUS, positions[1], 0f);
        assertEquals(0f, velocities[0], 0f);
        assertEquals(0f, velocities[1], 0f);
        assertEquals(0f, velocities[2], 0f);
        assertEquals(1, ground.resolve(positions, velocities, before, 1, touched));
        assertEquals(0, touched[0]);
    }

    /**
     * The contact test by groups finds exactly the particles one test each finds, in
     * increasing order: contacts at a group's first and last place, a lone one, a run of
     * them, y exactly r, −0 and a count that ends inside a group, for every count from 0 to
     * 40 and a stride wider than the count.
     */
    @Test
    void theGroupedContactTestFindsWhatOneTestPerParticleFinds() {
        float radius = 0.05f;
        float[] ys = new float[40];
        for (int i = 0; i < ys.length; ++i) {
            ys[i] = 0.05f + 0.37f * (i % 5) + 0.001f; // in the air, just above r for some
        }
        for (int i : new int[] {0, 7, 8, 15, 19, 20, 21, 22, 39}) {
            ys[i] = -0.02f * (i % 3); // 0, -0.02, -0.04: touching or below the ground
        }
        ys[30] = radius; // exactly r: d = 0, a contact
        ys[31] = -0f;
        ys[33] = Math.nextUp(radius); // a hair above r: none
        GroundBounce ground = new GroundBounce(radius, 0.5f, 0f, true);
        for (int count = 0; count <= ys.length; ++count) {
            int stride = count + 3;
            float[] positions = new float[3 * stride];
            float[] velocities = new float[3 * stride];
            System.arraycopy(ys, 0, positions, stride, count);
            int[] expected = new int[count];
            int expectedCount = 0;
            for (int i = 0; i < count; ++i) {
                if (ys[i] <= radius) {
                    expected[expectedCount++] = i;
                }
            }
            int[] contacts = new int[count];
            int found = ground.resolve(positions, velocities, new float[count], stride, count,
                    contacts);
            assertEquals(expectedCount, found, "contacts among " + count);
            for (int c = 0; c < found; ++c) {
                assertEquals(expected[c], contacts[c], "contact " + c + " among " + count);
            }
        }
    }

    @Test
    void resolvingAllocatesNothing() {
        int count = 10_000;
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        float[] before = new float[count];
        int[] touched = new int[count];
        for (int i = 0; i < count; ++i) {
            positions[count + i] = -0.01f * (i % 7);
            velocities[count + i] = -3f + 0.001f * i;
        }
        GroundBounce ground = new GroundBounce(0.05f, 0.5f, 0f, true);
        Allocations.assertAllocatesNothing("10_000 ground contacts",
                () -> ground.resolve(positions, velocities, before, count, touched));
    }

    @Test
    void badRestitutionOrRadiusIsRefusedWithTheValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new GroundBounce(0.1f, 1.5f, 0f, true));
        assertTrue(e.getMessage().contains("restitution e must be from 0 to 1, but was 1.5"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> new GroundBounce(Float.NaN, 0.5f, 0f, true));
        assertTrue(e.getMessage().contains("particle radius r (m)"), e.getMessage());
    }
}

package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.lang.reflect.Field;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link ParticleBatch#stepPackedFindingFloor}: the same floats as
 * {@link ParticleBatch#stepPacked} with a stride, the same particles as a plain
 * {@code y <= floor} over the stepped y (and as {@link HeightScan#findAtOrBelow}), each with
 * its vy before the step, in every form of the batch: by axes with either scalar check and
 * on the Vector API where this JVM has it, by speed (quadratic drag) and one by one (a
 * spring); and it refuses a non-finite y by itself, since the floor's marks stand in for
 * y's finiteness check there. Exact equality throughout: both sides run the same float
 * operations, so any difference is a defect, not round-off.
 */
class StepFindingFloorTest {

    private static final float STEP = 1f / 60f;
    private static final float MASS = 0.001f;
    private static final float FLOOR = 0.05f;
    /** Block edges of the batch (1024) and of the scalar scan's groups (8), and beyond. */
    private static final int[] COUNTS = {0, 1, 7, 8, 9, 1023, 1024, 1025, 3000};

    @Test
    void everyFormStepsAsStepPackedAndFindsWhatAPlainTestFinds() throws Exception {
        for (String form : new String[] {"tree", "fused", "vector", "speed", "one-by-one"}) {
            if (form.equals("vector") && !ParticleBatch.isVectorApiAvailable()) {
                continue;
            }
            for (int count : COUNTS) {
                for (int stride : new int[] {count, count + 5}) {
                    compare(form, true, count, stride, FLOOR);
                }
            }
            for (boolean gravity : new boolean[] {true, false}) {
                compare(form, gravity, 2100, 2100, FLOOR);
                compare(form, gravity, 2100, 2100, 0f);
                compare(form, gravity, 2100, 2100, -3.5f);
            }
        }
    }

    @Test
    void aNonFinitePositionIsRefusedAsStepPackedRefusesIt() throws Exception {
        for (String form : new String[] {"tree", "fused"}) {
            for (int axis = 0; axis < 3; ++axis) {
                for (float bad : new float[] {Float.NaN, Float.POSITIVE_INFINITY,
                    Float.NEGATIVE_INFINITY}) {
                    String where = form + ", axis " + axis + " = " + bad;
                    String plain = refusal(form, axis, bad, false, where);
                    assertTrue(plain.contains("packed particle 2048 of 2500"), plain);
                    assertEquals(plain, refusal(form, axis, bad, true, where), where);
                }
            }
        }
    }

    @Test
    void aZeroStepMovesNothingAndFindsThoseAtOrBelowAlready() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new LinearDrag(0.0002f));
        float[] positions = {0f, 0f, 0f, 1f, FLOOR, -2f, 0f, 0f, 0f};
        float[] velocities = {0f, 0f, 0f, 4f, 5f, 6f, 0f, 0f, 0f};
        float[] before = positions.clone();
        int[] below = new int[3];
        float[] velocityYBefore = new float[3];
        int found = integrator.batch().stepPackedFindingFloor(positions, velocities, 3, 3, MASS, 0f,
                FLOOR, below, velocityYBefore);
        assertArrayEquals(before, positions);
        assertEquals(2, found);
        assertArrayEquals(new int[] {1, 2}, Arrays.copyOf(below, found));
        assertArrayEquals(new float[] {5f, 6f}, Arrays.copyOf(velocityYBefore, found));
    }

    @Test
    void storesTooShortAreRefusedByName() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        float[] positions = new float[30];
        float[] velocities = new float[30];
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPackedFindingFloor(positions, velocities, 10, 10, MASS,
                        STEP, FLOOR, new int[9], new float[10]));
        assertEquals("the stores of the particles found and of their vy before the step must"
                + " each hold count = 10 values, but held 9 and 10", bad.getMessage());
        IllegalArgumentException nan = assertThrows(IllegalArgumentException.class,
                () -> integrator.batch().stepPackedFindingFloor(positions, velocities, 10, 10, MASS,
                        STEP, Float.NaN, new int[10], new float[10]));
        assertTrue(nan.getMessage().contains("floor (m)"), nan.getMessage());
    }

    /**
     * The message of the refusal of 2500 particles, one with a bad position on one axis
     * (only P is bad: in the floor form the floor's marks are the batch's only check of P),
     * by stepPacked or by the floor form.
     */
    private static String refusal(String form, int axis, float bad, boolean floorForm,
            String where) throws Exception {
        int count = 2500;
        ParticleIntegrator integrator = integrator(form, true);
        float[] positions = new float[3 * count];
        float[] velocities = new float[3 * count];
        Arrays.fill(positions, count, 2 * count, 2f);
        positions[axis * count + 2048] = bad;
        NonFiniteStepException thrown = assertThrows(NonFiniteStepException.class, () -> {
            if (floorForm) {
                integrator.batch().stepPackedFindingFloor(positions, velocities, count, count, MASS,
                        STEP, FLOOR, new int[count], new float[count]);
            } else {
                integrator.batch().stepPacked(positions, velocities, count, count, MASS, STEP);
            }
        }, where);
        return thrown.getMessage();
    }

    /**
     * One case: the floor form against stepPacked and a plain test on a copy. Without
     * gravity a particle with vy = 0 keeps its height to the bit, so the heights on the
     * floor and the floats either side of it are still there after the step, where
     * {@code y <= floor} turns.
     */
    private static void compare(String form, boolean gravity, int count, int stride,
            float floor) throws Exception {
        String where = form + (gravity ? "" : " without gravity") + ", count " + count
                + ", stride " + stride + ", floor " + floor;
        float[] positions = new float[3 * stride];
        float[] velocities = new float[3 * stride];
        fill(positions, velocities, stride, count, floor, new Random(count * 31L + stride));
        float[] expectedPositions = positions.clone();
        float[] expectedVelocities = velocities.clone();
        float[] velocityY = Arrays.copyOfRange(velocities, stride, stride + count);

        integrator(form, gravity).batch().stepPacked(expectedPositions, expectedVelocities,
                stride, count, MASS, STEP);
        int[] below = new int[count];
        float[] velocityYBefore = new float[count];
        int found = integrator(form, gravity).batch().stepPackedFindingFloor(positions,
                velocities, stride, count, MASS, STEP, floor, below, velocityYBefore);

        assertArrayEquals(expectedPositions, positions, where);
        assertArrayEquals(expectedVelocities, velocities, where);
        int[] plain = new int[count];
        int expected = 0;
        for (int i = 0; i < count; ++i) {
            if (positions[stride + i] <= floor) {
                plain[expected++] = i;
            }
        }
        assertEquals(expected, found, where);
        assertArrayEquals(Arrays.copyOf(plain, expected), Arrays.copyOf(below, found), where);
        int[] scanned = new int[count];
        assertEquals(expected, HeightScan.findAtOrBelow(positions, stride, count, floor, 0,
                scanned, 0), where);
        assertArrayEquals(Arrays.copyOf(plain, expected), Arrays.copyOf(scanned, expected),
                where);
        for (int c = 0; c < found; ++c) {
            assertEquals(velocityY[below[c]], velocityYBefore[c], where + ", found " + c);
        }
        // handed on block by block (or all at once), the same particles in the same order
        float[] again = new float[3 * stride];
        float[] againVelocities = new float[3 * stride];
        fill(again, againVelocities, stride, count, floor, new Random(count * 31L + stride));
        int[] handedIndices = new int[count];
        float[] handedVelocities = new float[count];
        int[] handed = {0};
        int[] ends = {0};
        int foundAgain = integrator(form, gravity).batch().stepPackedFindingFloor(again,
                againVelocities, stride, count, MASS, STEP, floor, new int[count],
                new float[count], (indices, before, from, to) -> {
                    assertEquals(ends[0], from, "blocks follow on");
                    ends[0] = to;
                    for (int c = from; c < to; ++c) {
                        handedIndices[handed[0]] = indices[c];
                        handedVelocities[handed[0]++] = before[c];
                    }
                });
        assertEquals(found, foundAgain, where);
        assertEquals(found, handed[0], where + ": every one found is handed on once");
        assertArrayEquals(Arrays.copyOf(below, found), Arrays.copyOf(handedIndices, found),
                where);
        assertArrayEquals(Arrays.copyOf(velocityYBefore, found),
                Arrays.copyOf(handedVelocities, found), where);
        if (count > 100) {
            assertTrue(found > count / 20, where + ": the case must have contacts, " + found);
        }
        if (!gravity && !form.equals("one-by-one")) {
            int onFloor = 0;
            int justAbove = 0;
            for (int i = 0; i < count; ++i) {
                onFloor += positions[stride + i] == floor ? 1 : 0;
                justAbove += positions[stride + i] == Math.nextUp(floor) ? 1 : 0;
            }
            assertTrue(onFloor > 10 && justAbove > 10, where + ": the edge must be covered, "
                    + onFloor + " on the floor, " + justAbove + " just above");
        }
    }

    /**
     * States whose step ends near the floor: heights at the floor, the floats either side of
     * it (exactly where {@code y <= floor} turns), ±0 and well above and below, a few in
     * each group of 8.
     */
    private static void fill(float[] positions, float[] velocities, int stride, int count,
            float floor, Random random) {
        for (int i = 0; i < count; ++i) {
            positions[i] = random.nextFloat() * 10f - 5f;
            positions[2 * stride + i] = random.nextFloat() * 10f - 5f;
            velocities[i] = random.nextFloat() * 4f - 2f;
            velocities[2 * stride + i] = random.nextFloat() * 4f - 2f;
            float y;
            switch (random.nextInt(8)) {
                case 0:
                    y = floor;
                    break;
                case 1:
                    y = Math.nextUp(floor);
                    break;
                case 2:
                    y = Math.nextDown(floor);
                    break;
                case 3:
                    y = random.nextBoolean() ? 0f : -0f;
                    break;
                default:
                    y = floor + random.nextFloat() * 20f - 2f;
                    break;
            }
            // vy 0 keeps most near-floor heights where they are after the step (h·vy and
            // h²·g move them by less than their spacing only sometimes: both sides occur)
            float vy = random.nextInt(3) == 0 ? 0f : random.nextFloat() * 30f - 15f;
            positions[stride + i] = y;
            velocities[stride + i] = vy;
        }
    }

    /** An integrator whose batch runs the given form, with or without gravity. */
    private static ParticleIntegrator integrator(String form, boolean withGravity)
            throws Exception {
        Gravity gravity = withGravity ? new Gravity() : new Gravity(Vector3f.ZERO);
        ParticleIntegrator integrator;
        switch (form) {
            case "speed":
                integrator = new ParticleIntegrator(gravity, new QuadraticDrag(0.0001f));
                break;
            case "one-by-one":
                integrator = new ParticleIntegrator(gravity,
                        new Spring(new Vector3f(0f, 3f, 0f), 1f, 0.02f));
                break;
            default:
                integrator = new ParticleIntegrator(gravity, new LinearDrag(0.0002f));
                break;
        }
        boolean vector = form.equals("vector");
        if (ParticleBatch.isVectorApiAvailable() || !vector) {
            integrator.batch().setVectorBatch(vector);
        }
        Field packed = ParticleBatch.class.getDeclaredField("packed");
        packed.setAccessible(true);
        ((PackedStep) packed.get(integrator.batch())).setFusedCheck(form.equals("fused"));
        return integrator;
    }
}

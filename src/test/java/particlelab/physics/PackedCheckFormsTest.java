package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import org.junit.jupiter.api.Test;

/**
 * The batch's two scalar finiteness checks, the tree of sums and the fused AND, give the
 * same verdict on every kind of float, and a step checked by either refuses the same
 * particles. Both forms are plain Java, so each is tested on whichever JDK runs the tests,
 * whatever form that JDK chose for the app.
 */
class PackedCheckFormsTest {

    /** Not a multiple of the tree's sixteen, so the tail loop is covered too. */
    private static final int LENGTH = 37;
    private static final float[] NON_FINITE = {Float.NaN, Float.POSITIVE_INFINITY,
        Float.NEGATIVE_INFINITY, Float.intBitsToFloat(0x7fc12345)};
    private static final float[] FINITE = {0f, -0f, Float.MIN_VALUE, -Float.MIN_VALUE,
        Float.MIN_NORMAL / 3f, 1f, -2.5f, 1e30f, -1e30f, Float.MAX_VALUE, -Float.MAX_VALUE};
    private static final float STEP = 1f / 60f;

    @Test
    void bothFormsRejectEveryNonFiniteValueAtEveryPlace() {
        for (float bad : NON_FINITE) {
            for (int at = 0; at < LENGTH; ++at) {
                float[] values = filled(LENGTH, 3.25f);
                values[at] = bad;
                String where = bad + " at " + at;
                assertFalse(PackedStep.isSumFinite(values, 0, LENGTH), "tree, " + where);
                assertFalse(PackedStep.isFusedFinite(values, 0, LENGTH), "fused, " + where);
            }
        }
    }

    @Test
    void bothFormsAcceptEveryFiniteValueWhoseSumStaysFinite() {
        for (float good : FINITE) {
            float[] values = filled(LENGTH, 0f);
            values[LENGTH / 2] = good;
            assertTrue(PackedStep.isSumFinite(values, 0, LENGTH), "tree, " + good);
            assertTrue(PackedStep.isFusedFinite(values, 0, LENGTH), "fused, " + good);
        }
    }

    @Test
    void fusedFormHasNoFalseAlarmWhereTheTreesSumOverflows() {
        // every value finite, their sum beyond the float range: the tree says "maybe not"
        // (the step then searches and finds nothing), the fused form says finite at once
        float[] values = filled(LENGTH, Float.MAX_VALUE);
        assertFalse(PackedStep.isSumFinite(values, 0, LENGTH));
        assertTrue(PackedStep.isFusedFinite(values, 0, LENGTH));
    }

    @Test
    void bothFormsLookOnlyAtTheirRange() {
        float[] values = filled(LENGTH, 1f);
        values[0] = Float.NaN;
        values[LENGTH - 1] = Float.POSITIVE_INFINITY;
        assertTrue(PackedStep.isSumFinite(values, 1, LENGTH - 2));
        assertTrue(PackedStep.isFusedFinite(values, 1, LENGTH - 2));
        assertTrue(PackedStep.isFusedFinite(values, 5, 0), "an empty range is finite");
    }

    @Test
    void stepsCheckedByEitherFormRefuseTheSameOverflow() throws Exception {
        // 3000 particles: three blocks of the step by axes, the bad one in the last block;
        // its velocity overflows to infinity in the step (|V|·r + h·g beyond Float.MAX_VALUE)
        int count = 3000;
        String[] messages = new String[2];
        for (int form = 0; form < 2; ++form) {
            ParticleIntegrator integrator = linearDrag(form == 1);
            float[] positions = new float[3 * count];
            float[] velocities = new float[3 * count];
            velocities[count + 2500] = Float.MAX_VALUE;
            positions[count + 2500] = Float.MAX_VALUE;
            NonFiniteStepException thrown = assertThrows(NonFiniteStepException.class,
                    () -> integrator.batch().stepPacked(positions, velocities, count, 1f, STEP));
            messages[form] = thrown.getMessage();
        }
        assertTrue(messages[0].contains("packed particle 2500 of 3000"), messages[0]);
        assertEquals(messages[0], messages[1]);
    }

    @Test
    void stepsCheckedByEitherFormRefuseAStateThatWasAlreadyNaN() throws Exception {
        int count = 1500;
        for (int form = 0; form < 2; ++form) {
            ParticleIntegrator integrator = linearDrag(form == 1);
            float[] positions = new float[3 * count];
            float[] velocities = new float[3 * count];
            positions[2 * count + 7] = Float.NaN;
            NonFiniteStepException thrown = assertThrows(NonFiniteStepException.class,
                    () -> integrator.batch().stepPacked(positions, velocities, count, 1f, STEP));
            assertTrue(thrown.getMessage().contains("packed particle 7 of 1500"),
                    thrown.getMessage());
        }
    }

    @Test
    void stepsCheckedByEitherFormAcceptLargeFiniteStatesAndGiveTheSameFloats()
            throws Exception {
        int count = 2100;
        float[][] results = new float[2][];
        for (int form = 0; form < 2; ++form) {
            ParticleIntegrator integrator = linearDrag(form == 1);
            float[] positions = new float[3 * count];
            float[] velocities = new float[3 * count];
            for (int i = 0; i < count; ++i) {
                // positions near the float range (the tree's sums overflow), a few subnormal
                positions[i] = i % 2 == 0 ? 3e38f : -3e38f;
                positions[count + i] = 3e38f;
                velocities[2 * count + i] = i % 3 == 0 ? Float.MIN_VALUE : 1f;
            }
            integrator.batch().stepPacked(positions, velocities, count, 1f, STEP);
            results[form] = positions;
        }
        assertArrayEquals(results[0], results[1]);
    }

    /**
     * The step by speed (quadratic drag, thrust) checks its blocks by the same two forms:
     * both step every particle to the same floats, slow ones (no thrust term below
     * {@link Thrust#MIN_SPEED}) and those of a partial last block included, and both name
     * the same first non-finite particle.
     */
    @Test
    void stepsBySpeedCheckedByEitherFormGiveTheSameFloatsAndRefuseTheSameParticle()
            throws Exception {
        // 2500 particles: two blocks of 1024 and a partial one; the bad one in the third
        int count = 2500;
        float[][] results = new float[4][];
        String[] messages = new String[2];
        for (int form = 0; form < 2; ++form) {
            ParticleIntegrator integrator = checkedBy(form == 1, new Gravity(),
                    new QuadraticDrag(0.02f), new Thrust(3f));
            float[] positions = new float[3 * count];
            float[] velocities = new float[3 * count];
            for (int i = 0; i < count; ++i) {
                positions[i] = i;
                velocities[i] = i % 7 == 0 ? 0f : 20f - i % 11;
                velocities[count + i] = i % 7 == 0 ? 1e-7f : 30f - i % 5;
                velocities[2 * count + i] = i % 3 - 1f;
            }
            for (int n = 0; n < 30; ++n) {
                integrator.batch().stepPacked(positions, velocities, count, 2f, STEP);
            }
            results[2 * form] = positions;
            results[2 * form + 1] = velocities;
            velocities[2 * count + 2100] = Float.NaN;
            NonFiniteStepException thrown = assertThrows(NonFiniteStepException.class,
                    () -> integrator.batch().stepPacked(positions, velocities, count, 2f, STEP));
            messages[form] = thrown.getMessage();
        }
        assertArrayEquals(results[0], results[2]);
        assertArrayEquals(results[1], results[3]);
        assertTrue(messages[0].contains("packed particle 2100 of 2500"), messages[0]);
        assertEquals(messages[0], messages[1]);
    }

    @Test
    void theFormIsChosenByTheJdkUnlessThePropertySays() {
        assertFalse(PackedStep.chooseFusedCheck(null, 17), "JDK 17 keeps the tree");
        assertEquals(PackedStep.FUSED_CHECK_FROM_JDK <= 25,
                PackedStep.chooseFusedCheck(null, 25));
        assertEquals(PackedStep.FUSED_CHECK_FROM_JDK <= 25,
                PackedStep.chooseFusedCheck("", 25));
        assertFalse(PackedStep.chooseFusedCheck("tree", 25));
        assertTrue(PackedStep.chooseFusedCheck("fused", 17));
        assertEquals(PackedStep.chooseFusedCheck(System.getProperty("particlelab.check"),
                Runtime.version().feature()), PackedStep.FUSED_CHECK);
    }

    @Test
    void aBadPropertyIsNamedWithWhatIsAllowed() {
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> PackedStep.chooseFusedCheck("sum", 17));
        assertEquals("-Dparticlelab.check must be tree or fused, but was sum",
                bad.getMessage());
    }

    /** An integrator under gravity and linear drag whose batch checks by the given form. */
    private static ParticleIntegrator linearDrag(boolean fused) throws Exception {
        ParticleIntegrator integrator = checkedBy(fused, new Gravity(), new LinearDrag(0.5f));
        integrator.batch().setVectorBatch(false);
        return integrator;
    }

    /** An integrator of the forces given whose batch checks by the given form. */
    private static ParticleIntegrator checkedBy(boolean fused, Force... forces)
            throws Exception {
        ParticleIntegrator integrator = new ParticleIntegrator(forces);
        Field packed = ParticleBatch.class.getDeclaredField("packed");
        packed.setAccessible(true);
        PackedStep step = (PackedStep) packed.get(integrator.batch());
        step.setFusedCheck(fused);
        assertEquals(fused, step.isFusedCheck());
        return integrator;
    }

    private static float[] filled(int length, float value) {
        float[] values = new float[length];
        java.util.Arrays.fill(values, value);
        return values;
    }
}

package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static particlelab.VectorAssert.assertVectorEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link LinearDrag}: {@code F = −b·V}.
 */
class LinearDragTest {

    /** A velocity with a whole length (13 m/s) and no two components alike. */
    private static final Vector3f VELOCITY = new Vector3f(3f, -4f, 12f);

    @ParameterizedTest
    @ValueSource(floats = {-1f, -Float.MIN_VALUE, Float.NaN, Float.POSITIVE_INFINITY,
        Float.NEGATIVE_INFINITY})
    void rejectsCoefficientThatIsNegativeOrNotFinite(float bad) {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new LinearDrag(bad));

        String message = thrown.getMessage();
        assertTrue(message.contains("linear drag b"), message);
        assertTrue(message.contains(String.valueOf(bad)), message);
        assertTrue(message.contains(">= 0") && message.contains("finite"), message);
    }

    @Test
    void setCoefficientRejectsNaNAndKeepsTheOldValue() {
        LinearDrag drag = new LinearDrag(0.5f);

        assertThrows(IllegalArgumentException.class, () -> drag.setCoefficient(Float.NaN));

        assertEquals(0.5f, drag.getCoefficient(), 0f);
    }

    @Test
    void forceIsMinusCoefficientTimesVelocity() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 2f);
        Vector3f force = new Vector3f();

        new LinearDrag(0.5f).addForce(particle, force);

        // Products of small dyadic numbers: exact in float.
        assertVectorEquals(new Vector3f(-1.5f, 2f, -6f), force, 0f);
    }

    @Test
    void forceAddsToTheNetForceAndLeavesTheParticleAlone() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 2f);
        Vector3f force = new Vector3f(10f, 20f, 30f);

        new LinearDrag(0.5f).addForce(particle, force);

        assertVectorEquals(new Vector3f(8.5f, 22f, 24f), force, 0f);
        assertVectorEquals(VELOCITY, particle.velocity, 0f);
    }

    @Test
    void zeroCoefficientGivesNoForce() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 1f);
        Vector3f force = new Vector3f();

        new LinearDrag(0f).addForce(particle, force);

        assertVectorEquals(Vector3f.ZERO, force, 0f);
    }

    @Test
    void addsNoFieldAcceleration() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 1f);
        Vector3f field = new Vector3f();

        new LinearDrag(0.5f).addFieldAcceleration(particle, field);

        assertVectorEquals(Vector3f.ZERO, field, 0f);
    }

    @Test
    void dampingRateIsCoefficientOverMassWhateverTheSpeed() {
        LinearDrag drag = new LinearDrag(3f);
        Particle slow = new Particle(Vector3f.ZERO, new Vector3f(0.001f, 0f, 0f), 1.5f);
        Particle fast = new Particle(Vector3f.ZERO, new Vector3f(0f, 1000f, 0f), 1.5f);

        assertEquals(2f, drag.dampingRate(slow), 0f);
        assertEquals(2f, drag.dampingRate(fast), 0f);
    }

    @Test
    void describeGivesTheEquationWithItsCoefficient() {
        assertEquals("F = -0.9·V", new LinearDrag(0.9f).describe());
    }
}

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
 * {@link Gravity}: a field acceleration {@code g}, the same for every mass.
 */
class GravityTest {

    private static final Vector3f DOWN = new Vector3f(0f, -Gravity.STANDARD_G, 0f);

    @Test
    void defaultIsStandardGravityDownTheYAxis() {
        assertVectorEquals(DOWN, new Gravity().copyAcceleration(new Vector3f()), 0f);
        assertEquals(9.8f, Gravity.STANDARD_G, 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsNonFiniteAccelerationNamingItAndTheValue(float bad) {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new Gravity(new Vector3f(bad, -9.8f, 0f)));

        String message = thrown.getMessage();
        assertTrue(message.contains("gravity g"), message);
        assertTrue(message.contains(String.valueOf(bad)), message);
        assertTrue(message.contains("finite"), message);
    }

    @Test
    void rejectsNullAndKeepsTheOldAcceleration() {
        Gravity gravity = new Gravity();

        assertThrows(IllegalArgumentException.class, () -> gravity.setAcceleration(null));

        assertVectorEquals(DOWN, gravity.copyAcceleration(new Vector3f()), 0f);
    }

    @Test
    void copiesTheAccelerationItIsGiven() {
        Vector3f given = new Vector3f(1f, -2f, 3f);
        Gravity gravity = new Gravity(given);

        given.set(0f, 0f, 0f);

        assertVectorEquals(new Vector3f(1f, -2f, 3f), gravity.copyAcceleration(new Vector3f()),
                0f);
    }

    @Test
    void isAFieldAccelerationNotAPush() {
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(1f, 2f, 3f), 4f);
        Vector3f force = new Vector3f();
        Vector3f field = new Vector3f(0.5f, 0f, 0f);
        Gravity gravity = new Gravity();

        gravity.addForce(particle, force);
        gravity.addFieldAcceleration(particle, field);

        assertVectorEquals(Vector3f.ZERO, force, 0f);
        assertVectorEquals(new Vector3f(0.5f, -9.8f, 0f), field, 0f);
        assertEquals(0f, gravity.dampingRate(particle), 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {1e-3f, 1f, 75f, 1e6f})
    void givesTheSameAccelerationToEveryMass(float massKg) {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(5f, 0f, 0f), massKg);

        Vector3f acceleration = integrator.acceleration(particle, new Vector3f());

        // g enters a = g + F/m as it is, never multiplied and divided by m: exact.
        assertVectorEquals(DOWN, acceleration, 0f);
    }
}

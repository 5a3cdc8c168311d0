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
 * {@link QuadraticDrag}: {@code F = −c·|V|·V}, of magnitude {@code c·|V|²}.
 */
class QuadraticDragTest {

    /** A velocity with a whole length (13 m/s) and no two components alike. */
    private static final Vector3f VELOCITY = new Vector3f(3f, -4f, 12f);
    private static final float SPEED = 13f;
    /** Float round-off of a few operations on numbers of order one, relative. */
    private static final float RELATIVE_ROUND_OFF = 1e-6f;

    @ParameterizedTest
    @ValueSource(floats = {-0.5f, Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsCoefficientThatIsNegativeOrNotFinite(float bad) {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new QuadraticDrag(bad));

        String message = thrown.getMessage();
        assertTrue(message.contains("quadratic drag c"), message);
        assertTrue(message.contains(String.valueOf(bad)), message);
        assertTrue(message.contains(">= 0") && message.contains("finite"), message);
    }

    @Test
    void setCoefficientRejectsInfinityAndKeepsTheOldValue() {
        QuadraticDrag drag = new QuadraticDrag(0.2f);

        assertThrows(IllegalArgumentException.class,
                () -> drag.setCoefficient(Float.POSITIVE_INFINITY));

        assertEquals(0.2f, drag.getCoefficient(), 0f);
    }

    @Test
    void forceOpposesVelocityWithMagnitudeCoefficientTimesSpeedSquared() {
        float c = 0.25f;
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 2f);
        Vector3f force = new Vector3f();

        new QuadraticDrag(c).addForce(particle, force);

        // |V| = 13 exactly (sqrt of 169); c·|V| = 3.25; all products exact in float.
        assertVectorEquals(VELOCITY.mult(-c * SPEED), force, 0f);
        assertEquals(c * SPEED * SPEED, force.length(), c * SPEED * SPEED * RELATIVE_ROUND_OFF);
        assertEquals(-1f, force.normalize().dot(VELOCITY.normalize()), RELATIVE_ROUND_OFF);
    }

    @Test
    void forceGrowsWithTheSquareNotTheCubeOfSpeed() {
        QuadraticDrag drag = new QuadraticDrag(0.1f);
        Particle slow = new Particle(Vector3f.ZERO, VELOCITY, 1f);
        Particle fast = new Particle(Vector3f.ZERO, VELOCITY.mult(10f), 1f);
        Vector3f slowForce = new Vector3f();
        Vector3f fastForce = new Vector3f();

        drag.addForce(slow, slowForce);
        drag.addForce(fast, fastForce);

        // Ten times the speed, a hundred times the force (the slide's −c|V|²V would give 1000).
        assertEquals(100f, fastForce.length() / slowForce.length(), 100f * RELATIVE_ROUND_OFF);
    }

    @Test
    void forceAtRestIsZeroNotNaN() {
        Particle particle = new Particle();
        Vector3f force = new Vector3f();

        new QuadraticDrag(5f).addForce(particle, force);

        assertVectorEquals(Vector3f.ZERO, force, 0f);
    }

    @Test
    void addsNoFieldAcceleration() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 1f);
        Vector3f field = new Vector3f();

        new QuadraticDrag(0.5f).addFieldAcceleration(particle, field);

        assertVectorEquals(Vector3f.ZERO, field, 0f);
    }

    @Test
    void dampingRateIsTwiceCoefficientTimesSpeedOverMass() {
        // d(c·v²)/dv = 2c·v: the rate at which a small change of speed decays.
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 2f);

        assertEquals(2f * 0.25f * SPEED / 2f, new QuadraticDrag(0.25f).dampingRate(particle),
                0f);
    }

    @Test
    void dampingRateOfAHugeCoefficientIsZeroAtRestAndFiniteWhenFast() {
        // In float 2c overflows for c = 3e38, and Infinity·0 would be NaN: a NaN rate made
        // every stability comparison false and silenced the warnings.
        QuadraticDrag drag = new QuadraticDrag(3e38f);
        Particle atRest = new Particle(Vector3f.ZERO, Vector3f.ZERO, 1f);
        Particle fast = new Particle(Vector3f.ZERO, VELOCITY, 1f);

        assertEquals(0f, drag.dampingRate(atRest), 0f);
        assertEquals(Float.MAX_VALUE, drag.dampingRate(fast), 0f);
        assertEquals(Float.POSITIVE_INFINITY,
                new ParticleIntegrator(drag).maxStableStep(atRest));
        assertTrue(new ParticleIntegrator(drag).maxStableStep(fast) < 1e-37f);
    }

    @Test
    void describeGivesTheEquationWithItsCoefficient() {
        assertEquals("F = -0.5·|V|·V", new QuadraticDrag(0.5f).describe());
    }
}

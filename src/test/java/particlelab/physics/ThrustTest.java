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
 * {@link Thrust}: {@code F = k·V/|V|} along the particle's own velocity, zero at rest.
 */
class ThrustTest {

    /** A velocity with a whole length (13 m/s) and no two components alike. */
    private static final Vector3f VELOCITY = new Vector3f(3f, -4f, 12f);
    /** Float round-off of a few operations on numbers of order one, relative. */
    private static final float RELATIVE_ROUND_OFF = 1e-6f;

    @ParameterizedTest
    @ValueSource(floats = {-2f, Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsMagnitudeThatIsNegativeOrNotFinite(float bad) {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new Thrust(bad));

        String message = thrown.getMessage();
        assertTrue(message.contains("thrust k"), message);
        assertTrue(message.contains(String.valueOf(bad)), message);
        assertTrue(message.contains(">= 0") && message.contains("finite"), message);
    }

    @Test
    void setMagnitudeRejectsNegativeAndKeepsTheOldValue() {
        Thrust thrust = new Thrust(4f);

        assertThrows(IllegalArgumentException.class, () -> thrust.setMagnitude(-4f));

        assertEquals(4f, thrust.getMagnitude(), 0f);
    }

    @Test
    void forcePushesAlongTheParticlesOwnVelocityWithMagnitudeK() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 5f);
        Vector3f force = new Vector3f();

        new Thrust(26f).addForce(particle, force);

        // k/|V| = 26/13 = 2: F = 2·V.
        assertVectorEquals(VELOCITY.mult(2f), force, 26f * RELATIVE_ROUND_OFF);
    }

    @ParameterizedTest
    @ValueSource(floats = {1e-4f, 0.01f, 1f, 100f, 1e4f})
    void forceMagnitudeIsKWhateverTheSpeed(float speedScale) {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY.mult(speedScale), 1f);
        Vector3f force = new Vector3f();

        new Thrust(7f).addForce(particle, force);

        assertEquals(7f, force.length(), 7f * RELATIVE_ROUND_OFF);
        assertEquals(1f, force.normalize().dot(VELOCITY.normalize()), RELATIVE_ROUND_OFF);
    }

    @Test
    void forceAtRestIsZeroNotNaN() {
        Particle particle = new Particle();
        Vector3f force = new Vector3f(1f, 2f, 3f);

        new Thrust(10f).addForce(particle, force);

        assertVectorEquals(new Vector3f(1f, 2f, 3f), force, 0f);
    }

    @Test
    void forceBelowTheMinimumSpeedIsZero() {
        Vector3f crawl = new Vector3f(Thrust.MIN_SPEED / 2f, 0f, 0f);
        Particle particle = new Particle(Vector3f.ZERO, crawl, 1f);
        Vector3f force = new Vector3f();

        new Thrust(10f).addForce(particle, force);

        assertVectorEquals(Vector3f.ZERO, force, 0f);
    }

    @Test
    void forceAtSubnormalSpeedIsZeroNotNaN() {
        // Squaring underflows here, so |V| computes as 0 although V is not the zero vector.
        Vector3f subnormal = new Vector3f(Float.MIN_VALUE, -Float.MIN_VALUE, Float.MIN_VALUE);
        Particle particle = new Particle(Vector3f.ZERO, subnormal, 1f);
        Vector3f force = new Vector3f();

        new Thrust(10f).addForce(particle, force);

        assertVectorEquals(Vector3f.ZERO, force, 0f);
    }

    @Test
    void neitherAddsFieldAccelerationNorDamps() {
        Particle particle = new Particle(Vector3f.ZERO, VELOCITY, 1f);
        Vector3f field = new Vector3f();
        Thrust thrust = new Thrust(3f);

        thrust.addFieldAcceleration(particle, field);

        assertVectorEquals(Vector3f.ZERO, field, 0f);
        assertEquals(0f, thrust.dampingRate(particle), 0f);
    }
}

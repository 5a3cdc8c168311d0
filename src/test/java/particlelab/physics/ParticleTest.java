package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static particlelab.VectorAssert.assertVectorEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link Particle}: its state, and the validation at its boundary.
 */
class ParticleTest {

    private static final Vector3f POSITION = new Vector3f(1f, 2f, 3f);
    private static final Vector3f VELOCITY = new Vector3f(-4f, 5f, -6f);

    @Test
    void defaultParticleIsOneKilogramAtRestAtTheOrigin() {
        Particle particle = new Particle();

        assertEquals(1f, particle.getMass(), 0f);
        assertVectorEquals(Vector3f.ZERO, particle.position, 0f);
        assertVectorEquals(Vector3f.ZERO, particle.velocity, 0f);
    }

    @Test
    void constructorCopiesTheVectorsItIsGiven() {
        Vector3f position = POSITION.clone();
        Vector3f velocity = VELOCITY.clone();

        Particle particle = new Particle(position, velocity, 2.5f);
        position.set(9f, 9f, 9f);
        velocity.set(9f, 9f, 9f);

        assertVectorEquals(POSITION, particle.position, 0f);
        assertVectorEquals(VELOCITY, particle.velocity, 0f);
        assertNotSame(position, particle.position);
        assertEquals(2.5f, particle.getMass(), 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {0f, -0f, -1f, -Float.MIN_VALUE, Float.NaN,
        Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsMassThatIsNotFiniteAndPositive(float badMass) {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new Particle(POSITION, VELOCITY, badMass));

        String message = thrown.getMessage();
        assertTrue(message.contains("mass"), message);
        assertTrue(message.contains(String.valueOf(badMass)), message);
        assertTrue(message.contains("> 0") && message.contains("finite"), message);
    }

    @ParameterizedTest
    @ValueSource(floats = {0f, -3f, Float.NaN, Float.POSITIVE_INFINITY})
    void setMassRejectsBadMassAndKeepsTheOldOne(float badMass) {
        Particle particle = new Particle(POSITION, VELOCITY, 2f);

        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> particle.setMass(badMass));

        assertTrue(thrown.getMessage().contains("mass"), thrown.getMessage());
        assertEquals(2f, particle.getMass(), 0f);
    }

    @Test
    void acceptsTinyAndHugeFiniteMasses() {
        Particle particle = new Particle();

        // The smallest mass whose 1/m is a finite float (Float.MIN_VALUE's is not).
        particle.setMass(Particle.MIN_MASS_KG);
        assertEquals(Particle.MIN_MASS_KG, particle.getMass(), 0f);
        particle.setMass(Float.MAX_VALUE);
        assertEquals(Float.MAX_VALUE, particle.getMass(), 0f);
    }

    @ParameterizedTest
    @ValueSource(floats = {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsNonFinitePositionNamingFieldValueAndRange(float bad) {
        Vector3f badPosition = new Vector3f(0f, bad, 0f);

        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new Particle(badPosition, VELOCITY, 1f));

        String message = thrown.getMessage();
        assertTrue(message.contains("position"), message);
        assertTrue(message.contains(String.valueOf(bad)), message);
        assertTrue(message.contains("finite"), message);
    }

    @ParameterizedTest
    @ValueSource(floats = {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY})
    void rejectsNonFiniteVelocityNamingFieldValueAndRange(float bad) {
        Vector3f badVelocity = new Vector3f(0f, 0f, bad);

        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new Particle(POSITION, badVelocity, 1f));

        String message = thrown.getMessage();
        assertTrue(message.contains("velocity"), message);
        assertTrue(message.contains(String.valueOf(bad)), message);
        assertTrue(message.contains("finite"), message);
    }

    @Test
    void rejectsNullVectors() {
        assertThrows(IllegalArgumentException.class, () -> new Particle(null, VELOCITY, 1f));
        assertThrows(IllegalArgumentException.class, () -> new Particle(POSITION, null, 1f));
    }

    @Test
    void setStateWithABadVelocityChangesNothing() {
        Particle particle = new Particle(POSITION, VELOCITY, 1f);

        assertThrows(IllegalArgumentException.class, () -> particle.setState(
                new Vector3f(7f, 7f, 7f), new Vector3f(Float.NaN, 0f, 0f)));

        assertVectorEquals(POSITION, particle.position, 0f);
        assertVectorEquals(VELOCITY, particle.velocity, 0f);
    }

    @Test
    void copyFromCopiesPositionVelocityAndMassButNotTheVectorObjects() {
        Particle source = new Particle(POSITION, VELOCITY, 3f);
        Particle copy = new Particle();

        copy.copyFrom(source);
        source.position.set(0f, 0f, 0f);

        assertVectorEquals(POSITION, copy.position, 0f);
        assertVectorEquals(VELOCITY, copy.velocity, 0f);
        assertEquals(3f, copy.getMass(), 0f);
    }

    /** The step reads 1/m from the particle: every way the mass is set must set it too. */
    @Test
    void theInverseMassIsOneOverTheMassAfterEveryWayTheMassIsSet() {
        Particle particle = new Particle();
        assertInverseBits(particle, "default particle");
        particle = new Particle(POSITION, VELOCITY, 3f);
        assertInverseBits(particle, "constructor");
        particle.setMass(0.7f);
        assertInverseBits(particle, "setMass");
        assertThrows(IllegalArgumentException.class, () -> new Particle().setMass(-1f));
        Particle refused = new Particle(POSITION, VELOCITY, 0.3f);
        assertThrows(IllegalArgumentException.class, () -> refused.setMass(Float.NaN));
        assertInverseBits(refused, "a refused setMass");
        Particle copy = new Particle();
        copy.copyFrom(particle);
        assertInverseBits(copy, "copyFrom");
        particle.setMass(Particle.MIN_MASS_KG);
        assertInverseBits(particle, "the smallest mass");
        assertTrue(Float.isFinite(particle.inverseMass()));
    }

    @Test
    void isFiniteTurnsFalseWhenAComponentIsWrittenNonFinite() {
        Particle particle = new Particle(POSITION, VELOCITY, 1f);
        assertTrue(particle.isFinite());

        particle.velocity.x = Float.POSITIVE_INFINITY;
        assertFalse(particle.isFinite());

        particle.velocity.x = 0f;
        particle.position.z = Float.NaN;
        assertFalse(particle.isFinite());
    }

    /** Below the smallest normal float, 1/m overflows and every step failed later. */
    @Test
    void aMassWhoseInverseIsNotAFiniteFloatIsRefused() {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class,
                () -> new Particle(POSITION, VELOCITY, 3e-39f));
        assertTrue(thrown.getMessage().contains(String.valueOf(Particle.MIN_MASS_KG)),
                thrown.getMessage());
        Particle lightest = new Particle(POSITION, VELOCITY, Particle.MIN_MASS_KG);
        assertTrue(Float.isFinite(1f / lightest.getMass()));
    }

    private static void assertInverseBits(Particle particle, String where) {
        // 1f/m exactly, the float the step's σ has always been computed with
        assertEquals(Float.floatToIntBits(1f / particle.getMass()),
                Float.floatToIntBits(particle.inverseMass()), where);
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Boundary checks shared by the physics and aiming code: each failure is an
 * {@link IllegalArgumentException} that names the parameter, the bad value and what is allowed.
 * A null object is refused the same way, never with a {@link NullPointerException}:
 * {@code "particle must not be null"}. This is the convention of every public method of
 * {@code particlelab.physics} and {@code particlelab.aiming} that takes an object.
 */
public final class Validate {

    private Validate() {
    }

    /**
     * Require an object.
     *
     * @param <T> the object's type
     * @param object the object to check
     * @param name the parameter's name, for the message
     * @return object
     */
    public static <T> T notNull(T object, String name) {
        if (object == null) {
            throw new IllegalArgumentException(name + " must not be null");
        }
        return object;
    }

    /**
     * Require a finite value.
     *
     * @param value the value to check
     * @param name the parameter's name, for the message
     * @return value
     */
    public static float finite(float value, String name) {
        if (!Float.isFinite(value)) {
            throw new IllegalArgumentException(
                    name + " must be a finite number, but was " + value);
        }
        return value;
    }

    /**
     * Require a finite value greater than zero.
     *
     * @param value the value to check
     * @param name the parameter's name, for the message
     * @return value
     */
    public static float positive(float value, String name) {
        if (!Float.isFinite(value) || value <= 0f) {
            throw new IllegalArgumentException(
                    name + " must be finite and > 0, but was " + value);
        }
        return value;
    }

    /**
     * Require a finite value of at least zero.
     *
     * @param value the value to check
     * @param name the parameter's name, for the message
     * @return value
     */
    public static float nonNegative(float value, String name) {
        if (!Float.isFinite(value) || value < 0f) {
            throw new IllegalArgumentException(
                    name + " must be finite and >= 0, but was " + value);
        }
        return value;
    }

    /**
     * Require a finite value of at least zero (double precision).
     *
     * @param value the value to check
     * @param name the parameter's name, for the message
     * @return value
     */
    public static double nonNegative(double value, String name) {
        if (!Double.isFinite(value) || value < 0.0) {
            throw new IllegalArgumentException(
                    name + " must be finite and >= 0, but was " + value);
        }
        return value;
    }

    /**
     * Require a finite value greater than zero (double precision).
     *
     * @param value the value to check
     * @param name the parameter's name, for the message
     * @return value
     */
    public static double positive(double value, String name) {
        if (!Double.isFinite(value) || value <= 0.0) {
            throw new IllegalArgumentException(
                    name + " must be finite and > 0, but was " + value);
        }
        return value;
    }

    /**
     * Require a finite value (double precision).
     *
     * @param value the value to check
     * @param name the parameter's name, for the message
     * @return value
     */
    public static double finite(double value, String name) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(
                    name + " must be a finite number, but was " + value);
        }
        return value;
    }

    /**
     * Require a non-null vector with three finite components.
     *
     * @param vector the vector to check (not modified)
     * @param name the parameter's name, for the message
     * @return vector
     */
    public static Vector3f finite(Vector3f vector, String name) {
        if (vector == null) {
            throw new IllegalArgumentException(name + " must be a vector, but was null");
        }
        if (!isFinite(vector)) {
            throw new IllegalArgumentException(
                    name + " must have finite components, but was " + vector);
        }
        return vector;
    }

    /**
     * Test whether all three components are finite.
     *
     * @param vector the vector to test (not null, not modified)
     * @return true if no component is NaN or infinite
     */
    public static boolean isFinite(Vector3f vector) {
        notNull(vector, "vector");
        return Float.isFinite(vector.x) && Float.isFinite(vector.y) && Float.isFinite(vector.z);
    }
}

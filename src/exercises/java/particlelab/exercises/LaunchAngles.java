package particlelab.exercises;

import particlelab.coursework.LaunchAnglesExercise;

/**
 * Exercise 4. Slide: "Aim at any height".
 *
 * <p>At a fixed launch speed s, find both angles that pass through the target {@code (x, y)}
 * (no drag): put {@code t = x/(s·cos θ)} into {@code y = s·sin θ·t − g·t²/2}, use
 * {@code 1/cos²θ = 1 + tan²θ} and solve the quadratic in {@code tan θ}. Store the low angle in
 * {@code storeAngles[0]}, the high one in {@code [1]}; return false when the discriminant is
 * negative (out of reach).
 *
 * <p>Hint: compute in double; {@code Math.atan} gives the angle.
 */
public final class LaunchAngles implements LaunchAnglesExercise {

    @Override
    public boolean angles(float speed, float x, float y, float gravity, float[] storeAngles) {
        throw new UnsupportedOperationException("not written yet");
    }
}

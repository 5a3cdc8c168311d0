package particlelab.exercises;

import particlelab.coursework.AimingExercise;

/**
 * Exercise 3. Slide: "HelloAiming".
 *
 * <p>{@code continuousVy}: the lecture's {@code vy = g·S/(2·vx)}, which hits a level target at
 * distance S when the flight is the exact parabola.
 *
 * <p>{@code discreteVy}: the launch speed that hits exactly when the shot is stepped with the
 * lecture's Euler step of h. Step the recipe on paper: after n steps
 * {@code y_n = n·h·vy − g·h²·n(n+1)/2} and {@code x_n = n·h·vx}. Ask for {@code y = 0} at
 * {@code x = S}.
 *
 * <p>Hint: the answer is the lecture's formula plus a term that vanishes as h goes to 0.
 */
public final class Aiming implements AimingExercise {

    @Override
    public float continuousVy(float vx, float rangeM, float gravity) {
        throw new UnsupportedOperationException("not written yet");
    }

    @Override
    public float discreteVy(float vx, float rangeM, float gravity, float stepSeconds) {
        throw new UnsupportedOperationException("not written yet");
    }
}

package particlelab.solutions;

import particlelab.coursework.AimingExercise;

/** Exercise 3, solved: the lecture's aim and its discrete correction {@code + g·h/2}. */
public final class Aiming implements AimingExercise {

    @Override
    public float continuousVy(float vx, float rangeM, float gravity) {
        return gravity * rangeM / (2f * vx);
    }

    @Override
    public float discreteVy(float vx, float rangeM, float gravity, float stepSeconds) {
        // The stepped shot flies the parabola launched with vy − g·h/2: give it g·h/2 more.
        return continuousVy(vx, rangeM, gravity) + 0.5f * gravity * stepSeconds;
    }
}

package particlelab.coursework;

/** Exercise 3, the "HelloAiming" slide: the vertical launch speed that hits a level target. */
public interface AimingExercise {

    /**
     * The lecture's formula for the continuous flight: {@code vy = g·S/(2·vx)}.
     *
     * @param vx the horizontal launch speed (in m/s, &gt;0)
     * @param rangeM the distance S to the target at launch height (in metres, &gt;0)
     * @param gravity g (in m/s², &gt;0)
     * @return the vertical launch speed (in m/s)
     */
    float continuousVy(float vx, float rangeM, float gravity);

    /**
     * The launch speed whose flight, stepped with the lecture's Euler step of {@code h}, passes
     * exactly through the target.
     *
     * @param vx the horizontal launch speed (in m/s, &gt;0)
     * @param rangeM the distance S (in metres, &gt;0)
     * @param gravity g (in m/s², &gt;0)
     * @param stepSeconds the step h (in seconds, &gt;0)
     * @return the vertical launch speed (in m/s)
     */
    float discreteVy(float vx, float rangeM, float gravity, float stepSeconds);
}

package particlelab.aiming;

/**
 * Where a stepped shot came down: mutable storage, reused from shot to shot.
 */
public final class Landing {

    /**
     * Test whether a step from height {@code previousY} to {@code y} came down through the
     * ground plane {@code y = 0}: the last position with {@code y ≥ 0}, the first with
     * {@code y < 0}. (Testing {@code y ≤ 0} instead would stop a whole step early whenever a
     * sample lands on the ground to round-off, as the lecture's own shot at S = 100 m,
     * vx = 20 m/s, h = 1/60 s does.)
     *
     * @param previousY the height before the step (in metres)
     * @param y the height after the step (in metres)
     * @return true if the step crossed the ground going down
     */
    public static boolean crossesGround(float previousY, float y) {
        return y < 0f && previousY >= 0f;
    }

    /**
     * Return where inside a step the straight line from {@code previousY} to {@code y}
     * crosses {@code y = 0}, for a step where {@link #crossesGround} is true.
     *
     * @param previousY the height before the step (in metres, &ge;0)
     * @param y the height after the step (in metres, &lt;0)
     * @return the fraction of the step (&ge;0, &lt;1)
     */
    public static double crossingFraction(float previousY, float y) {
        return previousY / ((double) previousY - y);
    }

    private boolean landed;
    private double x;
    private double timeSeconds;
    private int steps;

    /**
     * Test whether the shot crossed the ground going down before its time ran out.
     *
     * @return true if it landed
     */
    public boolean hasLanded() {
        return landed;
    }

    /**
     * Return the landing x, interpolated linearly between the last step with {@code y ≥ 0}
     * and the first with {@code y < 0}.
     *
     * @return x (in metres; NaN if the shot did not land)
     */
    public double getX() {
        return x;
    }

    /**
     * Return the time of the crossing, interpolated like x.
     *
     * @return the flight time (in seconds; NaN if the shot did not land)
     */
    public double getTimeSeconds() {
        return timeSeconds;
    }

    /**
     * Return the number of steps simulated, including the first step below ground.
     *
     * @return the count (&ge;0)
     */
    public int getSteps() {
        return steps;
    }

    void set(boolean newLanded, double newX, double newTimeSeconds, int newSteps) {
        landed = newLanded;
        x = newX;
        timeSeconds = newTimeSeconds;
        steps = newSteps;
    }
}

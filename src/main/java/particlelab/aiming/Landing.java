package particlelab.aiming;

/**
 * Where a stepped shot came down: mutable storage, reused from shot to shot (a
 * {@link Flight} fills it).
 */
public final class Landing {

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

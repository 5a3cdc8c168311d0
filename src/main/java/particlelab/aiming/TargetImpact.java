package particlelab.aiming;

/**
 * Where a projectile met its target: mutable storage, reused from shot to shot, filled by
 * {@link Hitscan}.
 */
public final class TargetImpact {

    private boolean reached;
    private boolean hit;
    private double x;
    private double y;
    private double timeSeconds;
    private int steps;

    /**
     * Test whether the projectile reached the target: crossed the disc's plane, or touched
     * the sphere.
     *
     * @return true if it did, within the steps allowed
     */
    public boolean isReached() {
        return reached;
    }

    /**
     * Test whether it hit: for a disc, crossed its plane within the radius of the centre; for
     * a sphere, touched it.
     *
     * @return true on a hit
     */
    public boolean isHit() {
        return hit;
    }

    /**
     * Return x where the projectile met the target's plane or surface, inside the step.
     *
     * @return x (in metres; NaN if not reached)
     */
    public double getX() {
        return x;
    }

    /**
     * Return y where the projectile met the target's plane or surface, inside the step.
     *
     * @return y (in metres, the target's centre at 0; NaN if not reached)
     */
    public double getY() {
        return y;
    }

    /**
     * Return how far below the target's centre the projectile arrived: {@code −y}.
     *
     * @return the drop (in metres; NaN if not reached)
     */
    public double getDrop() {
        return -y;
    }

    /**
     * Return the time of the impact, inside the step.
     *
     * @return the flight time (in seconds; NaN if not reached)
     */
    public double getTimeSeconds() {
        return timeSeconds;
    }

    /**
     * Return the number of steps taken, including the one in which it met the target.
     *
     * @return the count (&ge;0)
     */
    public int getSteps() {
        return steps;
    }

    void set(boolean newReached, boolean newHit, double newX, double newY,
            double newTimeSeconds, int newSteps) {
        reached = newReached;
        hit = newHit;
        x = newX;
        y = newY;
        timeSeconds = newTimeSeconds;
        steps = newSteps;
    }
}

package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * The attempts of one aiming search, in the order they were fired: shot number, vy as fired,
 * where it landed and the miss. What a demo draws (one trail per attempt, a HUD table of
 * shot, vy, landing, miss) and what {@code aim --shots-csv} prints. Fixed capacity, filled by
 * {@link IterativeAim#aim(double, double, ShotLog)}: recording allocates nothing.
 */
public final class ShotLog {

    private final float[] verticalSpeeds;
    private final double[] landingXs;
    private final double[] flightSeconds;
    private final double[] misses;
    private final float[] horizontalSpeeds;
    private int size;

    /**
     * Create an empty log.
     *
     * @param capacity the most attempts it keeps (&ge;1); later attempts are counted by the
     *     search but not kept
     */
    public ShotLog(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("shot log capacity must be >= 1, but was "
                    + capacity);
        }
        verticalSpeeds = new float[capacity];
        horizontalSpeeds = new float[capacity];
        landingXs = new double[capacity];
        flightSeconds = new double[capacity];
        misses = new double[capacity];
    }

    /** Forget every attempt. */
    public void clear() {
        size = 0;
    }

    /**
     * Return the number of attempts kept.
     *
     * @return the count (0 to the capacity)
     */
    public int size() {
        return size;
    }

    /**
     * Return the number of attempts the log can keep.
     *
     * @return the capacity (&ge;1)
     */
    public int capacity() {
        return misses.length;
    }

    /**
     * Return an attempt's vx.
     *
     * @param index 0 for the first shot
     * @return vx as fired (in m/s)
     */
    public float getHorizontalSpeed(int index) {
        return horizontalSpeeds[check(index)];
    }

    /**
     * Return an attempt's vy.
     *
     * @param index 0 for the first shot
     * @return vy as fired, a float (in m/s)
     */
    public float getVerticalSpeed(int index) {
        return verticalSpeeds[check(index)];
    }

    /**
     * Return where an attempt crossed the ground.
     *
     * @param index 0 for the first shot
     * @return x at the interpolated crossing (in metres; NaN if it never came down)
     */
    public double getLandingX(int index) {
        return landingXs[check(index)];
    }

    /**
     * Return an attempt's flight time.
     *
     * @param index 0 for the first shot
     * @return the time of the interpolated crossing (in seconds; NaN if it never came down)
     */
    public double getFlightSeconds(int index) {
        return flightSeconds[check(index)];
    }

    /**
     * Return an attempt's miss.
     *
     * @param index 0 for the first shot
     * @return {@code landing − S} (in metres; negative: short; NaN if it never came down)
     */
    public double getMiss(int index) {
        return misses[check(index)];
    }

    /**
     * Append an attempt, if there is room.
     *
     * @param horizontalSpeed vx as fired (in m/s)
     * @param verticalSpeed vy as fired (in m/s)
     * @param landing where it came down (not null, not modified)
     * @param distance S (in metres)
     */
    void record(float horizontalSpeed, float verticalSpeed, Landing landing, double distance) {
        Validate.notNull(landing, "landing");
        if (size == misses.length) {
            return;
        }
        horizontalSpeeds[size] = horizontalSpeed;
        verticalSpeeds[size] = verticalSpeed;
        landingXs[size] = landing.getX();
        flightSeconds[size] = landing.getTimeSeconds();
        misses[size] = landing.getX() - distance;
        ++size;
    }

    private int check(int index) {
        if (index < 0 || index >= size) {
            throw new IllegalArgumentException("shot index must be in 0.." + (size - 1)
                    + ", but was " + index);
        }
        return index;
    }
}

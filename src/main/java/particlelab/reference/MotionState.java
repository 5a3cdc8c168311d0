package particlelab.reference;

/**
 * A point's position and velocity in double precision, for the reference steppers. The arrays
 * are {@code public final}: steppers update them in place and allocate nothing.
 */
public final class MotionState {

    /** Position P (in metres; 3 components, live, modified in place by steppers). */
    public final double[] position = new double[3];
    /** Velocity V (in m/s; 3 components, live, modified in place by steppers). */
    public final double[] velocity = new double[3];

    /**
     * Create a state at rest at the origin.
     */
    public MotionState() {
    }

    /**
     * Create a state in the x-y plane.
     *
     * @param x P.x (in metres)
     * @param y P.y (in metres)
     * @param vx V.x (in m/s)
     * @param vy V.y (in m/s)
     */
    public MotionState(double x, double y, double vx, double vy) {
        position[0] = x;
        position[1] = y;
        velocity[0] = vx;
        velocity[1] = vy;
    }

    /**
     * Copy another state into this one.
     *
     * @param source the state to copy (not null, not modified)
     * @return this
     */
    public MotionState set(MotionState source) {
        System.arraycopy(source.position, 0, position, 0, 3);
        System.arraycopy(source.velocity, 0, velocity, 0, 3);
        return this;
    }

    /**
     * Return the distance between this position and another.
     *
     * @param other the other state (not null, not modified)
     * @return |P − P_other| (in metres)
     */
    public double positionDistance(MotionState other) {
        double dx = position[0] - other.position[0];
        double dy = position[1] - other.position[1];
        double dz = position[2] - other.position[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Test whether every component is finite.
     *
     * @return true if no component is NaN or infinite
     */
    public boolean isFinite() {
        for (int i = 0; i < 3; ++i) {
            if (!Double.isFinite(position[i]) || !Double.isFinite(velocity[i])) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        return "MotionState[P=(" + position[0] + ", " + position[1] + ", " + position[2]
                + "), V=(" + velocity[0] + ", " + velocity[1] + ", " + velocity[2] + ")]";
    }
}

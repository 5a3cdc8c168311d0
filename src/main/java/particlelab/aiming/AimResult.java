package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * The outcome of aiming: the launch chosen, where the stepped shot landed, and how many shots
 * it took. Immutable.
 */
public final class AimResult {

    private final String method;
    private final boolean hit;
    private final double horizontalSpeed;
    private final double verticalSpeed;
    private final double flightSeconds;
    private final double landingX;
    private final double targetDistance;
    private final int shots;
    private final String explanation;

    /**
     * Create a result.
     *
     * @param method the aiming method's name, e.g. "lecture" (not null)
     * @param hit true if the shot landed within the tolerance asked for
     * @param horizontalSpeed vx (in m/s)
     * @param verticalSpeed vy (in m/s; NaN if none was found)
     * @param flightSeconds the flight time of the final shot (in seconds; NaN if it never
     *     landed)
     * @param landingX where the final shot crossed the ground (in metres; NaN if it never
     *     landed)
     * @param targetDistance S (in metres)
     * @param shots the number of simulated shots (&ge;0)
     * @param explanation "hit", or why there is no hit (not null)
     */
    public AimResult(String method, boolean hit, double horizontalSpeed, double verticalSpeed,
            double flightSeconds, double landingX, double targetDistance, int shots,
            String explanation) {
        this.method = Validate.notNull(method, "method");
        this.hit = hit;
        this.horizontalSpeed = horizontalSpeed;
        this.verticalSpeed = verticalSpeed;
        this.flightSeconds = flightSeconds;
        this.landingX = landingX;
        this.targetDistance = targetDistance;
        this.shots = shots;
        this.explanation = Validate.notNull(explanation, "explanation");
    }

    /** @return the aiming method's name (not null) */
    public String getMethod() {
        return method;
    }

    /** @return true if the final shot landed within the tolerance */
    public boolean isHit() {
        return hit;
    }

    /** @return vx (in m/s) */
    public double getHorizontalSpeed() {
        return horizontalSpeed;
    }

    /** @return vy (in m/s; NaN if none was found) */
    public double getVerticalSpeed() {
        return verticalSpeed;
    }

    /** @return the final shot's flight time (in seconds; NaN if it never landed) */
    public double getFlightSeconds() {
        return flightSeconds;
    }

    /** @return where the final shot landed (in metres; NaN if it never landed) */
    public double getLandingX() {
        return landingX;
    }

    /** @return S (in metres) */
    public double getTargetDistance() {
        return targetDistance;
    }

    /** @return the miss {@code landingX − S} (in metres; negative = short) */
    public double getMiss() {
        return landingX - targetDistance;
    }

    /** @return the number of simulated shots */
    public int getShots() {
        return shots;
    }

    /** @return "hit", or a one-line reason there is no hit (not null) */
    public String getExplanation() {
        return explanation;
    }

    @Override
    public String toString() {
        return method + ": vy=" + verticalSpeed + " m/s, landed at " + landingX + " m (miss "
                + getMiss() + " m) after " + shots + " shot(s): " + explanation;
    }
}

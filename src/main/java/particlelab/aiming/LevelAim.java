package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * Closed forms for a level target: gun and target at the same height, distance S apart, the
 * horizontal speed vx given, gravity g, no drag.
 *
 * <p>The lecture's formula {@code vy = g·S/(2·vx)} is exact for the continuous parabola. The
 * bullet the game actually flies is stepped by the semi-implicit Euler method at a step h, and
 * its samples lie on the parabola launched with {@code vy − g·h/2}: it lands {@code vx·h}
 * short. {@link #discreteVy} gives the vy that makes the stepped bullet land at S.
 */
public final class LevelAim {

    private LevelAim() {
    }

    /**
     * The lecture's vertical launch speed: {@code vy = g·S/(2·vx)}.
     *
     * @param gravity g (in m/s², finite, &gt;0)
     * @param distance S (in metres, finite, &gt;0)
     * @param horizontalSpeed vx (in m/s, finite, &gt;0)
     * @return vy (in m/s, finite, &gt;0)
     * @throws IllegalArgumentException if an input is not finite and positive, or vy is out
     *     of the double range
     */
    public static double lectureVy(double gravity, double distance, double horizontalSpeed) {
        check(gravity, distance, horizontalSpeed);
        double vy = gravity * distance / (2.0 * horizontalSpeed);
        if (Double.isInfinite(vy)) {
            // g·S alone may overflow where the quotient does not.
            vy = gravity / (2.0 * horizontalSpeed) * distance;
        }
        return inRange(vy, "vy = g*S/(2*vx)", gravity, distance, horizontalSpeed);
    }

    /**
     * The lecture's flight time {@code T = S/vx}.
     *
     * @param distance S (in metres, finite, &gt;0)
     * @param horizontalSpeed vx (in m/s, finite, &gt;0)
     * @return T (in seconds, finite, &gt;0)
     * @throws IllegalArgumentException if an input is not finite and positive, or T is out
     *     of the double range
     */
    public static double flightTime(double distance, double horizontalSpeed) {
        Validate.positive(distance, "distance S (m)");
        Validate.positive(horizontalSpeed, "horizontal speed vx (m/s)");
        double time = distance / horizontalSpeed;
        if (!(Double.isFinite(time) && time > 0.0)) {
            throw new IllegalArgumentException("flight time S/vx is out of the double range"
                    + " for S = " + distance + " m, vx = " + horizontalSpeed + " m/s: " + time);
        }
        return time;
    }

    /**
     * The vertical launch speed that makes the bullet, stepped by the semi-implicit Euler
     * method at a fixed step h, land at S, its landing read as the linearly interpolated ground
     * crossing between steps.
     *
     * <p>With {@code N = S/(vx·h)} steps of flight, {@code n = floor(N)} and {@code f = N − n},
     * the samples are {@code y_i = i·h·vy − g·h²·i(i+1)/2}; setting the interpolated height
     * {@code (1−f)·y_n + f·y_{n+1}} to zero gives {@code vy = g·h·(n+1)(n+2f)/(2N)}. When N is
     * whole this is the lecture's correction {@code vy = g·(S/vx + h)/2}.
     *
     * @param gravity g (in m/s², finite, &gt;0)
     * @param distance S (in metres, finite, &gt;0)
     * @param horizontalSpeed vx (in m/s, finite, &gt;0)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @return vy (in m/s, finite, &gt;0)
     * @throws IllegalArgumentException if an input is not finite and positive, or vy is out
     *     of the double range
     */
    public static double discreteVy(double gravity, double distance, double horizontalSpeed,
            double stepSeconds) {
        check(gravity, distance, horizontalSpeed);
        Validate.positive(stepSeconds, "step h (s)");
        double steps = distance / (horizontalSpeed * stepSeconds);
        double whole = Math.floor(steps);
        double fraction = steps - whole;
        double vy;
        if (fraction < 1e-9 * steps) {
            // N whole (to round-off): vy = g·(S/vx + h)/2 exactly.
            vy = gravity * (distance / horizontalSpeed + stepSeconds) / 2.0;
        } else {
            vy = gravity * stepSeconds * (whole + 1.0) * (whole + 2.0 * fraction) / (2.0 * steps);
        }
        return inRange(vy, "the discrete vy", gravity, distance, horizontalSpeed);
    }

    /**
     * Refuse a result that overflowed (or underflowed to 0) in double arithmetic.
     *
     * @return vy, finite and &gt;0
     */
    private static double inRange(double vy, String what, double gravity, double distance,
            double horizontalSpeed) {
        if (!(Double.isFinite(vy) && vy > 0.0)) {
            throw new IllegalArgumentException(what + " is out of the double range for g = "
                    + gravity + " m/s^2, S = " + distance + " m, vx = " + horizontalSpeed
                    + " m/s: " + vy);
        }
        return vy;
    }

    private static void check(double gravity, double distance, double horizontalSpeed) {
        Validate.positive(gravity, "gravity g (m/s^2)");
        Validate.positive(distance, "distance S (m)");
        Validate.positive(horizontalSpeed, "horizontal speed vx (m/s)");
    }
}

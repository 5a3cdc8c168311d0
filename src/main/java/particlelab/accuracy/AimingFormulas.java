package particlelab.accuracy;

/**
 * The two level-shot formulas the report compares, written here until the aiming package
 * ({@code particlelab.aiming}) lands; the report should then call that package instead.
 * Gun and target level, distance S, horizontal speed vx given, gravity g, no drag.
 */
public final class AimingFormulas {

    private AimingFormulas() {
    }

    /**
     * The lecture's formula: {@code vy = g·S/(2·vx)}, exact for continuous motion. Stepped by
     * the semi-implicit Euler method at a fixed h, the shot lands {@code vx·h} short.
     *
     * @param gDown the pull of gravity (in m/s², &gt;0)
     * @param distance S (in metres, &gt;0)
     * @param vx the horizontal speed (in m/s, &gt;0)
     * @return vy (in m/s)
     */
    public static double lectureVy(double gDown, double distance, double vx) {
        return gDown * distance / (2.0 * vx);
    }

    /**
     * The discrete correction for the semi-implicit Euler step at a fixed h:
     * {@code vy = g·S/(2·vx) + g·h/2}, which lands exactly when {@code S/(vx·h)} is whole.
     *
     * @param gDown the pull of gravity (in m/s², &gt;0)
     * @param distance S (in metres, &gt;0)
     * @param vx the horizontal speed (in m/s, &gt;0)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return vy (in m/s)
     */
    public static double discreteVy(double gDown, double distance, double vx,
            double stepSeconds) {
        return lectureVy(gDown, distance, vx) + gDown * stepSeconds / 2.0;
    }
}

package particlelab.lecture;

/**
 * The ideal bouncing ball of the lecture, in closed form: dropped from rest at height h0 (of
 * its lowest point) under gravity g alone, each impact instantaneous with {@code v' = e·v}.
 * Bounce's graph draws it dashed beside the stepped balls.
 *
 * <pre>
 *   t0 = √(2·h0/g)                       the fall; the first impact at t0, at speed g·t0
 *   flight n (n ≥ 1): leaves at u_n = eⁿ·g·t0, lasts 2·eⁿ·t0, apex e^{2n}·h0
 *   impact n + 1 at t0·(1 + 2·(e + e² + … + eⁿ))
 *   at rest from T = t0·(1+e)/(1−e) (e &lt; 1; e = 0 rests at t0; e = 1 never rests)
 * </pre>
 * Allocates nothing.
 */
final class IdealBounce {

    /** Flights shorter than this are taken for rest (in seconds): far below any step. */
    private static final double SHORTEST_FLIGHT_SECONDS = 1e-9;

    private final double dropMetres;
    private final double restitution;
    private final double gravity;
    private final double fallSeconds;

    /**
     * Describe an ideal ball.
     *
     * @param dropMetres h0, the drop height of the lowest point (in metres, finite, &gt;0)
     * @param restitution e (from 0 to 1)
     * @param gravity g, the magnitude of gravity (in m/s², finite, &gt;0)
     */
    IdealBounce(double dropMetres, double restitution, double gravity) {
        if (!(dropMetres > 0.0) || Double.isInfinite(dropMetres) || !(restitution >= 0.0)
                || restitution > 1.0 || !(gravity > 0.0) || Double.isInfinite(gravity)) {
            throw new IllegalArgumentException("h0 (m) and g (m/s^2) must be finite and > 0,"
                    + " e from 0 to 1, but were " + dropMetres + ", " + gravity + ", "
                    + restitution);
        }
        this.dropMetres = dropMetres;
        this.restitution = restitution;
        this.gravity = gravity;
        this.fallSeconds = Math.sqrt(2.0 * dropMetres / gravity);
    }

    /** @return t0 = √(2·h0/g), the time of the first impact (in seconds) */
    double getFallSeconds() {
        return fallSeconds;
    }

    /**
     * Return the time the ideal ball comes to rest, {@code T = t0·(1+e)/(1−e)}.
     *
     * @return T (in seconds; infinite for e = 1)
     */
    double getRestSeconds() {
        return restitution == 1.0 ? Double.POSITIVE_INFINITY
                : fallSeconds * (1.0 + restitution) / (1.0 - restitution);
    }

    /**
     * Return the height of the lowest point at a time.
     *
     * @param seconds the time since the drop (in seconds, &ge;0)
     * @return the height (in metres, &ge;0)
     */
    double height(double seconds) {
        return evaluate(seconds, false);
    }

    /**
     * Return the speed |V| at a time (before an impact's instant: the approach speed).
     *
     * @param seconds the time since the drop (in seconds, &ge;0)
     * @return the speed (in m/s, &ge;0)
     */
    double speed(double seconds) {
        return evaluate(seconds, true);
    }

    /** The fall, then flight after flight until the one holding the time. */
    private double evaluate(double seconds, boolean wantSpeed) {
        if (seconds < fallSeconds) {
            return wantSpeed ? gravity * seconds : dropMetres - 0.5 * gravity * seconds * seconds;
        }
        double start = fallSeconds;
        double launch = gravity * fallSeconds;
        while (true) {
            launch *= restitution;
            double flight = 2.0 * launch / gravity;
            if (!(flight > SHORTEST_FLIGHT_SECONDS)) {
                return 0.0;
            }
            double since = seconds - start;
            if (since < flight) {
                return wantSpeed ? Math.abs(launch - gravity * since)
                        : launch * since - 0.5 * gravity * since * since;
            }
            start += flight;
        }
    }
}

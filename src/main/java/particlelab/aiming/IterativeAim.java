package particlelab.aiming;

import particlelab.physics.Validate;

/**
 * The lecture's "shoot, see where it lands, adjust the power", for a level target at distance
 * S with vx fixed: each shot is simulated by a {@link ShotSimulator} (the shared integrator and
 * the scene's own forces, drag included), and vy is adjusted until the landing is within a
 * tolerance of S.
 *
 * <p>The search first brackets the target: starting from the drag-free guess
 * {@code g·S/(2·vx)}, it doubles vy while the shot falls short and the reach still grows. Then
 * it narrows the bracket with regula falsi (Illinois variant: a secant step that cannot stall
 * on one side), which needs about six shots to reach millimetres. The landing point is
 * interpolated inside the last step, so it varies smoothly with vy and the search converges.
 *
 * <p>With drag the reach at fixed vx has a maximum (linear drag: no launch passes
 * {@code vx·m/b}). When the reach stops growing while still short, or the bullet stops coming
 * down within the allowed flight time, the answer is "out of reach" with the farthest shot
 * found. When the shots run out first, the answer is "no hit" with the closest shot found:
 * a tolerance finer than the float round-off of the stepped shot (vy is fired as a float, one
 * ulp of vy moves a 100 m shot by about 1e-5 m) cannot be met. Of the two arcs that may hit
 * with drag, the search finds the low one.
 */
public final class IterativeAim {

    /** Method name used in results. */
    public static final String METHOD = "iterative";
    /** Doubling vy stops once the reach grows by less than this fraction of the tolerance. */
    private static final double STALL_FRACTION = 0.01;
    /** The golden-section ratio {@code (√5 − 1)/2}. */
    private static final double GOLDEN = 0.6180339887498949;
    /** The peak search stops when its vy interval is this fraction of vy. */
    private static final double PEAK_RESOLUTION = 1e-6;

    private final ShotSimulator simulator;
    private final double gravity;
    private final double toleranceMetres;
    private final int maxShots;
    private final Landing landing = new Landing();
    /** Shots fired so far in the current search. */
    private int shots;
    /** The farthest shot so far in the current search: its vy and miss. */
    private double bestVy;
    private double bestMiss;
    /** The shot so far that landed closest to S: its vy and miss. */
    private double closestVy;
    private double closestMiss;
    /** The miss of the shot before the current low end of the bracket. */
    private double lastShortfall;

    /**
     * Create an aimer.
     *
     * @param simulator fires the shots (not null)
     * @param gravity the magnitude of g, used only for the first guess (in m/s², finite, &gt;0)
     * @param toleranceMetres stop once {@code |landing − S|} is at most this (in metres,
     *     finite, &gt;0)
     * @param maxShots the most shots to simulate (&ge;2)
     */
    public IterativeAim(ShotSimulator simulator, double gravity, double toleranceMetres,
            int maxShots) {
        Validate.notNull(simulator, "simulator");
        if (maxShots < 2) {
            throw new IllegalArgumentException("max shots must be >= 2, but was " + maxShots);
        }
        this.simulator = simulator;
        this.gravity = Validate.positive(gravity, "gravity g (m/s^2)");
        this.toleranceMetres = Validate.positive(toleranceMetres, "tolerance (m)");
        this.maxShots = maxShots;
    }

    /**
     * Find vy that lands the shot at S.
     *
     * @param distance S (in metres, finite, &gt;0)
     * @param horizontalSpeed vx (in m/s, finite, &gt;0)
     * @return the result (not null): a hit; or no hit, either out of reach (with the farthest
     *     shot) or out of shots (with the closest shot), as its explanation says
     */
    public AimResult aim(double distance, double horizontalSpeed) {
        Validate.positive(distance, "distance S (m)");
        Validate.positive(horizontalSpeed, "horizontal speed vx (m/s)");
        try {
            return search(distance, horizontalSpeed);
        } catch (OutOfReach reason) {
            double landingX = Double.isInfinite(bestMiss) ? Double.NaN : distance + bestMiss;
            return new AimResult(METHOD, false, horizontalSpeed, bestVy, Double.NaN, landingX,
                    distance, shots, "target at S=" + distance + " m is out of reach at vx="
                            + horizontalSpeed + " m/s: " + reason.getMessage());
        } catch (ShotsRanOut reason) {
            // Not out of reach: the search did not converge. Report the closest shot.
            return new AimResult(METHOD, false, horizontalSpeed, closestVy, Double.NaN,
                    distance + closestMiss, distance, shots, "no hit within " + maxShots
                            + " shots at tolerance " + toleranceMetres + " m; the closest landed "
                            + (float) closestMiss + " m from S with vy=" + (float) closestVy
                            + " m/s (a larger tolerance may help)");
        }
    }

    private AimResult search(double distance, double horizontalSpeed) {
        shots = 0;
        bestVy = Double.NaN;
        bestMiss = Double.NEGATIVE_INFINITY;
        closestVy = Double.NaN;
        closestMiss = Double.POSITIVE_INFINITY;
        lastShortfall = -distance;

        // Bracket: lowVy falls short on the rising branch of the reach, highVy overshoots.
        double lowVy = 0.0;
        double lowMiss = -distance;
        double beforeLowVy = 0.0;
        double vy = LevelAim.lectureVy(gravity, distance, horizontalSpeed);
        double miss;
        while (true) {
            miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= toleranceMetres) {
                return hit(horizontalSpeed, vy, distance);
            }
            if (miss > 0.0) {
                break;
            }
            if (miss <= lowMiss + STALL_FRACTION * toleranceMetres) {
                // The reach stopped growing: its peak lies between beforeLowVy and vy.
                vy = searchPeak(horizontalSpeed, distance, beforeLowVy, vy);
                miss = landing.getX() - distance;
                if (Math.abs(miss) <= toleranceMetres) {
                    return hit(horizontalSpeed, vy, distance);
                }
                lowVy = beforeLowVy;
                lowMiss = lastShortfall;
                break;
            }
            beforeLowVy = lowVy;
            lastShortfall = lowMiss;
            lowVy = vy;
            lowMiss = miss;
            vy *= 2.0;
        }
        // Narrow: regula falsi, Illinois variant.
        double highVy = vy;
        double highMiss = miss;
        int side = 0;
        while (true) {
            vy = highVy - highMiss * (highVy - lowVy) / (highMiss - lowMiss);
            miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= toleranceMetres) {
                return hit(horizontalSpeed, vy, distance);
            }
            if (miss < 0.0) {
                lowVy = vy;
                lowMiss = miss;
                if (side == -1) {
                    highMiss /= 2.0;
                }
                side = -1;
            } else {
                highVy = vy;
                highMiss = miss;
                if (side == 1) {
                    lowMiss /= 2.0;
                }
                side = 1;
            }
        }
    }

    /**
     * Maximise the reach over vy in [lowVy, highVy] by golden-section search, stopping early
     * at the first shot that reaches S.
     *
     * @return the vy of the last shot fired, whose landing is in {@link #landing}
     */
    private double searchPeak(double horizontalSpeed, double distance, double lowVy,
            double highVy) {
        double a = lowVy;
        double b = highVy;
        double c = b - GOLDEN * (b - a);
        double d = a + GOLDEN * (b - a);
        double missC = shoot(horizontalSpeed, c, distance);
        if (missC >= -toleranceMetres) {
            return c;
        }
        double missD = shoot(horizontalSpeed, d, distance);
        while (missD < -toleranceMetres) {
            if (b - a <= PEAK_RESOLUTION * b) {
                throw new OutOfReach("the reach peaks at about " + (float) (distance + bestMiss)
                        + " m near vy=" + (float) bestVy + " m/s, short of S");
            }
            if (missC > missD) {
                b = d;
                d = c;
                missD = missC;
                c = b - GOLDEN * (b - a);
                missC = shoot(horizontalSpeed, c, distance);
                if (missC >= -toleranceMetres) {
                    return c;
                }
            } else {
                a = c;
                c = d;
                missC = missD;
                d = a + GOLDEN * (b - a);
                missD = shoot(horizontalSpeed, d, distance);
            }
        }
        return d;
    }

    /**
     * Fire one shot, counting it and remembering the farthest and the closest.
     *
     * @return the miss {@code landing − S} (in metres)
     * @throws ShotsRanOut if the shots run out
     * @throws OutOfReach if the shot does not come down in time
     */
    private double shoot(double horizontalSpeed, double vy, double distance) {
        if (shots == maxShots) {
            throw new ShotsRanOut();
        }
        if (Float.isInfinite((float) vy)) {
            throw new OutOfReach("the search needs vy=" + vy + " m/s, beyond the float range"
                    + " the shots are fired in");
        }
        ++shots;
        if (!simulator.fire((float) horizontalSpeed, (float) vy, landing)) {
            throw new OutOfReach("a shot with vy=" + (float) vy
                    + " m/s did not come down within the flight time allowed");
        }
        double miss = landing.getX() - distance;
        if (miss > bestMiss) {
            bestMiss = miss;
            bestVy = vy;
        }
        if (Math.abs(miss) < Math.abs(closestMiss)) {
            closestMiss = miss;
            closestVy = vy;
        }
        return miss;
    }

    private AimResult hit(double horizontalSpeed, double vy, double distance) {
        return new AimResult(METHOD, true, horizontalSpeed, vy, landing.getTimeSeconds(),
                landing.getX(), distance, shots, "hit");
    }

    /** Ends a search that used up its shots without a hit; caught in {@link #aim}. */
    private static final class ShotsRanOut extends RuntimeException {
        private static final long serialVersionUID = 1L;

        ShotsRanOut() {
            super(null, null, false, false);
        }
    }

    /** Ends a search that cannot hit; caught in {@link #aim}. */
    private static final class OutOfReach extends RuntimeException {
        private static final long serialVersionUID = 1L;

        OutOfReach(String reason) {
            super(reason, null, false, false);
        }
    }
}

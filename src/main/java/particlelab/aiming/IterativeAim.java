package particlelab.aiming;

import java.util.Random;
import particlelab.physics.Validate;

/**
 * The lecture's "shoot, see where it lands, adjust the power", for a level target at distance
 * S with vx fixed: each shot is simulated by a {@link ShotSimulator} (the shared integrator and
 * the scene's own forces, drag included), and vy is adjusted until the landing is within a
 * tolerance of S. How vy is adjusted is the {@link AimStrategy}; the default,
 * {@link AimStrategy#ILLINOIS}, is described here.
 *
 * <p>The search first brackets the target: starting from the drag-free guess
 * {@code g·S/(2·vx)}, it doubles vy while the shot falls short and the reach still grows. Then
 * it narrows the bracket with regula falsi (Illinois variant: a secant step that cannot stall
 * on one side), which needs about six shots to reach millimetres. The landing point is
 * interpolated inside the last step, so it varies smoothly with vy and the search converges.
 * {@link AimStrategy#BISECTION} and {@link AimStrategy#SECANT} bracket the same way and narrow
 * differently; {@link AimStrategy#LECTURE} climbs by a fixed change instead of doubling.
 *
 * <p>A shot fired slower upward than {@code g·h} is under the ground after its first step and
 * lands at the gun: every such vy reaches 0 m. That is not a peak: the search goes on doubling
 * vy until a shot flies. With drag the reach at fixed vx has a maximum (linear drag: no launch
 * passes {@code vx·m/b}). When the reach of shots that flew stops growing while still short,
 * or the bullet stops coming
 * down within the allowed flight time, the answer is "out of reach" with the farthest shot
 * found. When the shots run out first, the answer is "no hit" with the closest shot found:
 * a tolerance finer than the float round-off of the stepped shot (vy is fired as a float, one
 * ulp of vy moves a 100 m shot by about 1e-5 m) cannot be met. Of the two arcs that may hit
 * with drag, the search finds the low one.
 *
 * <p>{@link #aim(double, double, ShotLog)} also records every shot the player would watch, for
 * a demo to draw or a command to print. The believable player's invisible search is not
 * recorded, and not counted in {@link AimResult#getShots()}.
 */
public final class IterativeAim {

    /** Method name used in results. */
    public static final String METHOD = "iterative";
    /** The lecture rule's first change of vy, as a fraction of the first guess. */
    public static final double LECTURE_FIRST_CHANGE = 0.5;
    /** The believable player's least move toward the right vy, as a fraction of the way. */
    public static final double BELIEVABLE_MIN_MOVE = 0.3;
    /** The believable player's largest move toward the right vy, as a fraction of the way. */
    public static final double BELIEVABLE_MAX_MOVE = 1.7;
    /** The believable player's first shot is off the right vy by at least this fraction. */
    public static final double BELIEVABLE_FIRST_MIN_ERROR = 0.15;
    /** The believable player's first shot is off the right vy by at most this fraction. */
    public static final double BELIEVABLE_FIRST_MAX_ERROR = 0.35;
    /** Doubling vy stops once the reach grows by less than this fraction of the tolerance. */
    private static final double STALL_FRACTION = 0.01;
    /** The golden-section ratio {@code (√5 − 1)/2}. */
    private static final double GOLDEN = 0.6180339887498949;
    /** The peak search stops when its vy interval is this fraction of vy. */
    private static final double PEAK_RESOLUTION = 1e-6;
    /** The believable player halves a first shot that would hit at most this often. */
    private static final int MAX_FIRST_SHOT_RETRIES = 60;
    /** {@link #mixSeed}: 2⁶⁴ divided by the golden ratio, odd. */
    private static final long SEED_GAMMA = 0x9E3779B97F4A7C15L;
    /** {@link #mixSeed}: the multiplier of the first mixing round. */
    private static final long SEED_MIX_1 = 0xBF58476D1CE4E5B9L;
    /** {@link #mixSeed}: the multiplier of the second mixing round. */
    private static final long SEED_MIX_2 = 0x94D049BB133111EBL;

    private final ShotSimulator simulator;
    private final double gravity;
    private final double toleranceMetres;
    private final int maxShots;
    private final AimStrategy strategy;
    private final long seed;
    private final Random random = new Random();
    private final Landing landing = new Landing();
    /** Where the current search records the shots the player watches; null: nowhere. */
    private ShotLog log;
    /** The tolerance of the current search: the believable player's invisible one is finer. */
    private double searchTolerance;
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
     * Create an aimer with the {@link AimStrategy#ILLINOIS} search.
     *
     * @param simulator fires the shots (not null)
     * @param gravity the magnitude of g, used only for the first guess (in m/s², finite, &gt;0)
     * @param toleranceMetres stop once {@code |landing − S|} is at most this (in metres,
     *     finite, &gt;0)
     * @param maxShots the most shots to simulate (&ge;2)
     */
    public IterativeAim(ShotSimulator simulator, double gravity, double toleranceMetres,
            int maxShots) {
        this(simulator, gravity, toleranceMetres, maxShots, AimStrategy.ILLINOIS, 0L);
    }

    /**
     * Create an aimer.
     *
     * @param simulator fires the shots (not null)
     * @param gravity the magnitude of g, used only for the first guess (in m/s², finite, &gt;0)
     * @param toleranceMetres stop once {@code |landing − S|} is at most this (in metres,
     *     finite, &gt;0)
     * @param maxShots the most shots to simulate (&ge;2), for the believable player both for
     *     its invisible search and for the shots it fires
     * @param strategy how vy is adjusted (not null)
     * @param seed the believable player's random seed; every search starts from it, so the
     *     same seed gives the same shots (any value; ignored by the other strategies)
     */
    public IterativeAim(ShotSimulator simulator, double gravity, double toleranceMetres,
            int maxShots, AimStrategy strategy, long seed) {
        Validate.notNull(simulator, "simulator");
        if (maxShots < 2) {
            throw new IllegalArgumentException("max shots must be >= 2, but was " + maxShots);
        }
        this.simulator = simulator;
        this.gravity = Validate.positive(gravity, "gravity g (m/s^2)");
        this.toleranceMetres = Validate.positive(toleranceMetres, "tolerance (m)");
        this.maxShots = maxShots;
        this.strategy = Validate.notNull(strategy, "strategy");
        this.seed = seed;
    }

    /**
     * Return the strategy.
     *
     * @return how vy is adjusted (not null)
     */
    public AimStrategy getStrategy() {
        return strategy;
    }

    /**
     * Return the simulator that fires the shots: the aimer's predictor.
     *
     * @return the simulator (not null)
     */
    public ShotSimulator getSimulator() {
        return simulator;
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
        return aim(distance, horizontalSpeed, null);
    }

    /**
     * Find vy that lands the shot at S, recording every shot the player would watch.
     *
     * @param distance S (in metres, finite, &gt;0)
     * @param horizontalSpeed vx (in m/s, finite, &gt;0)
     * @param storeShots storage for the shots fired, in order (cleared first, then modified;
     *     may be null)
     * @return the result (not null): a hit; or no hit, either out of reach (with the farthest
     *     shot) or out of shots (with the closest shot), as its explanation says
     */
    public AimResult aim(double distance, double horizontalSpeed, ShotLog storeShots) {
        Validate.positive(distance, "distance S (m)");
        Validate.positive(horizontalSpeed, "horizontal speed vx (m/s)");
        if (storeShots != null) {
            storeShots.clear();
        }
        log = storeShots;
        searchTolerance = toleranceMetres;
        try {
            if (strategy == AimStrategy.BELIEVABLE) {
                return believable(distance, horizontalSpeed);
            }
            return search(distance, horizontalSpeed, strategy);
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
        } finally {
            log = null;
        }
    }

    private void resetSearch(double distance) {
        shots = 0;
        bestVy = Double.NaN;
        bestMiss = Double.NEGATIVE_INFINITY;
        closestVy = Double.NaN;
        closestMiss = Double.POSITIVE_INFINITY;
        lastShortfall = -distance;
    }

    /**
     * Bracket the target while the shots fall short (doubling vy, or for the lecture rule
     * adding a fixed change), then narrow the bracket as the strategy says.
     */
    private AimResult search(double distance, double horizontalSpeed, AimStrategy how) {
        resetSearch(distance);
        // Bracket: lowVy falls short on the rising branch of the reach, highVy overshoots.
        double lowVy = 0.0;
        double lowMiss = -distance;
        double beforeLowVy = 0.0;
        double vy = LevelAim.lectureVy(gravity, distance, horizontalSpeed);
        double lectureChange = LECTURE_FIRST_CHANGE * vy;
        double miss;
        while (true) {
            miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= searchTolerance) {
                return hit(horizontalSpeed, vy, distance);
            }
            if (miss > 0.0) {
                break;
            }
            // A shot whose vy is below g·h is under the ground after its first step and lands
            // at the gun (x = 0): its reach is flat in vy, but not because of a peak.
            boolean flew = landing.getX() > 0.0;
            if (flew && miss <= lowMiss + STALL_FRACTION * searchTolerance) {
                // The reach stopped growing: its peak lies between beforeLowVy and vy.
                vy = searchPeak(horizontalSpeed, distance, beforeLowVy, vy);
                miss = landing.getX() - distance;
                if (Math.abs(miss) <= searchTolerance) {
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
            vy = how == AimStrategy.LECTURE ? vy + lectureChange : vy * 2.0;
        }
        switch (how) {
            case LECTURE:
                // Short before this overshoot: that was a sign change.
                return lectureRule(horizontalSpeed, distance, vy, shots > 1, lectureChange);
            case BISECTION:
                return bisect(horizontalSpeed, distance, lowVy, vy);
            case SECANT:
                return secant(horizontalSpeed, distance, lowVy, lowMiss, vy, miss);
            default:
                return illinois(horizontalSpeed, distance, lowVy, lowMiss, vy, miss);
        }
    }

    /** Narrow the bracket by regula falsi, Illinois variant. */
    private AimResult illinois(double horizontalSpeed, double distance, double lowVy,
            double lowMiss, double highVy, double highMiss) {
        double low = lowVy;
        double lowSide = lowMiss;
        double high = highVy;
        double highSide = highMiss;
        int side = 0;
        while (true) {
            double vy = high - highSide * (high - low) / (highSide - lowSide);
            double miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= searchTolerance) {
                return hit(horizontalSpeed, vy, distance);
            }
            if (miss < 0.0) {
                low = vy;
                lowSide = miss;
                if (side == -1) {
                    highSide /= 2.0;
                }
                side = -1;
            } else {
                high = vy;
                highSide = miss;
                if (side == 1) {
                    lowSide /= 2.0;
                }
                side = 1;
            }
        }
    }

    /** Halve the bracket at every shot. */
    private AimResult bisect(double horizontalSpeed, double distance, double lowVy,
            double highVy) {
        double low = lowVy;
        double high = highVy;
        while (true) {
            double vy = 0.5 * (low + high);
            double miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= searchTolerance) {
                return hit(horizontalSpeed, vy, distance);
            }
            if (miss < 0.0) {
                low = vy;
            } else {
                high = vy;
            }
        }
    }

    /**
     * The secant through the last two shots, starting from the bracket's ends; a step that
     * would leave the bracket bisects it instead.
     */
    private AimResult secant(double horizontalSpeed, double distance, double lowVy,
            double lowMiss, double highVy, double highMiss) {
        double low = lowVy;
        double high = highVy;
        double olderVy = lowVy;
        double olderMiss = lowMiss;
        double newerVy = highVy;
        double newerMiss = highMiss;
        while (true) {
            double vy = newerVy - newerMiss * (newerVy - olderVy) / (newerMiss - olderMiss);
            if (!(vy > low && vy < high)) {
                vy = 0.5 * (low + high);
            }
            double miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= searchTolerance) {
                return hit(horizontalSpeed, vy, distance);
            }
            if (miss < 0.0) {
                low = vy;
            } else {
                high = vy;
            }
            olderVy = newerVy;
            olderMiss = newerMiss;
            newerVy = vy;
            newerMiss = miss;
        }
    }

    /**
     * The lecture's rule from an overshoot: less power while overshot, more while short, the
     * change halved whenever the miss changes sign. vy never goes to 0 or below: a change that
     * would take it there is halved first.
     *
     * @param overshotVy the vy of the overshoot just fired
     * @param afterShortShot true if the shot before it fell short (a sign change)
     * @param change the change of vy so far (in m/s, &gt;0)
     */
    private AimResult lectureRule(double horizontalSpeed, double distance, double overshotVy,
            boolean afterShortShot, double change) {
        double vy = overshotVy;
        double step = change;
        int sign = 1;
        int previousSign = afterShortShot ? -1 : 1;
        while (true) {
            if (sign != previousSign) {
                step /= 2.0;
            }
            double next = vy - sign * step;
            while (!(next > 0.0)) {
                step /= 2.0;
                next = vy - sign * step;
            }
            vy = next;
            double miss = shoot(horizontalSpeed, vy, distance);
            if (Math.abs(miss) <= searchTolerance) {
                return hit(horizontalSpeed, vy, distance);
            }
            previousSign = sign;
            sign = miss > 0.0 ? 1 : -1;
        }
    }

    /**
     * The believable player: the right vy found invisibly, then shots that close in on it.
     */
    private AimResult believable(double distance, double horizontalSpeed) {
        ShotLog watched = log;
        log = null;
        // The right answer, to half the tolerance so that a shot near it still hits; a
        // tolerance that fine may be beyond round-off, then the tolerance itself.
        searchTolerance = 0.5 * toleranceMetres;
        double right;
        try {
            right = search(distance, horizontalSpeed, AimStrategy.ILLINOIS).getVerticalSpeed();
        } catch (ShotsRanOut fineTolerance) {
            searchTolerance = toleranceMetres;
            right = search(distance, horizontalSpeed, AimStrategy.ILLINOIS).getVerticalSpeed();
        }
        // Random.setSeed only flips a few bits of the seed, so nearby seeds would start from
        // nearby states and fire nearly the same first shot (every seed 1..20 once missed by
        // 29.6 %): mix the seed first.
        random.setSeed(mixSeed(seed));
        double error = BELIEVABLE_FIRST_MIN_ERROR + (BELIEVABLE_FIRST_MAX_ERROR
                - BELIEVABLE_FIRST_MIN_ERROR) * random.nextDouble();
        double firstGuess = random.nextBoolean() ? right * (1.0 + error)
                : right * (1.0 - error);
        // The first shot must miss: a first guess that would hit is shortened, in the head.
        // Only a tolerance of about S leaves no shot that misses: then the first guess hits.
        double vy = firstGuess;
        boolean misses = false;
        for (int retry = 0; retry < MAX_FIRST_SHOT_RETRIES && !misses; ++retry) {
            misses = !simulator.fire((float) horizontalSpeed, (float) vy, landing)
                    || Math.abs(landing.getX() - distance) > toleranceMetres;
            if (!misses) {
                vy *= 0.5;
            }
        }
        if (!misses) {
            vy = firstGuess;
        }
        resetSearch(distance);
        searchTolerance = toleranceMetres;
        log = watched;
        double miss = shoot(horizontalSpeed, vy, distance);
        while (Math.abs(miss) > searchTolerance) {
            double move = BELIEVABLE_MIN_MOVE
                    + (BELIEVABLE_MAX_MOVE - BELIEVABLE_MIN_MOVE) * random.nextDouble();
            vy += move * (right - vy);
            miss = shoot(horizontalSpeed, vy, distance);
        }
        return hit(horizontalSpeed, vy, distance);
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
        if (missC >= -searchTolerance) {
            return c;
        }
        double missD = shoot(horizontalSpeed, d, distance);
        while (missD < -searchTolerance) {
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
                if (missC >= -searchTolerance) {
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
        boolean landed = simulator.fire((float) horizontalSpeed, (float) vy, landing);
        if (log != null) {
            log.record((float) horizontalSpeed, (float) vy, landing, distance);
        }
        if (!landed) {
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

    /**
     * Scramble a seed so that every bit of it affects every bit of the result: SplitMix64's
     * step (add the golden-ratio increment, then two xor-shift-multiply rounds and a final
     * xor-shift), the mixing {@link java.util.SplittableRandom} applies to its seeds.
     *
     * @param seed any value
     * @return the mixed seed (the same for the same seed)
     */
    static long mixSeed(long seed) {
        long z = seed + SEED_GAMMA;
        z = (z ^ (z >>> 30)) * SEED_MIX_1;
        z = (z ^ (z >>> 27)) * SEED_MIX_2;
        return z ^ (z >>> 31);
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

package particlelab.aiming;

import java.util.ArrayList;
import java.util.List;
import particlelab.physics.Validate;

/**
 * A human against the believable player (issue 34 §3): both aim at the same level target at
 * distance S, the computer with {@link AimStrategy#BELIEVABLE}'s seeded shots (exactly what
 * {@code aim --method iterative --strategy believable --seed N} prints for the same scene),
 * the human with an angle and a speed of their own, each shot stepped by the same
 * {@link ShotSimulator}. A round is over once the human hits (or runs out of shots); a
 * one-key poll, "felt fair?", closes it and makes its row of the log ({@link #CSV_HEADER}). No jME:
 * a test plays a scripted human without a window.
 *
 * <p>What each player's row says: the shots up to and including the first hit, the worst
 * {@code |miss|} among them, and the time to the hit (in seconds of the round's simulated
 * time, at the hit's landing). The computer fires each shot as the one before lands, so its
 * time is the sum of its shots' flight times; the human's runs from the round's start, their
 * thinking included.
 */
public final class Duel {

    /** The log's header, one row per closed round; never change it (an interface). */
    public static final String CSV_HEADER = "round,seed,human_shots,human_hit,"
            + "human_worst_miss_m,human_time_s,computer_shots,computer_worst_miss_m,"
            + "computer_time_s,felt_fair";
    /** The human's lowest and highest aim (in degrees above the horizontal). */
    public static final float MIN_ANGLE_DEGREES = 5f;
    /** The human's highest aim (in degrees above the horizontal). */
    public static final float MAX_ANGLE_DEGREES = 85f;
    /** The human's slowest launch (in m/s). */
    public static final float MIN_SPEED = 5f;
    /** The human's fastest launch (in m/s). */
    public static final float MAX_SPEED = 40f;

    private ShotSimulator simulator;
    private final double gravity;
    private final double distance;
    private final double horizontalSpeed;
    private final double toleranceMetres;
    private final int maxShots;
    private final ShotLog computer;
    private final Landing landing = new Landing();
    /** The human's shots this round: vx and vy as fired, miss, landing time (round s). */
    private final float[] humanVx;
    private final float[] humanVy;
    private final double[] humanMiss;
    private final double[] humanLandedAt;
    private final List<double[]> closed = new ArrayList<>();
    private AimResult computerResult;
    private int round = 1;
    private long seed;
    private int humanShots;
    /** The human's first hit (from 0), or -1. */
    private int humanHit = -1;

    /**
     * Set up a duel.
     *
     * @param simulator steps every shot, the human's and the computer's (not null)
     * @param gravity the magnitude of g, for the computer's first guess (in m/s², &gt;0)
     * @param distance S (in metres, finite, &gt;0)
     * @param horizontalSpeed the computer's fixed vx (in m/s, finite, &gt;0)
     * @param toleranceMetres a hit lands within this of S (in metres, finite, &gt;0, &lt;S)
     * @param maxShots the most shots each player fires in a round (&ge;2)
     */
    public Duel(ShotSimulator simulator, double gravity, double distance,
            double horizontalSpeed, double toleranceMetres, int maxShots) {
        this.simulator = Validate.notNull(simulator, "simulator");
        this.gravity = Validate.positive(gravity, "gravity g (m/s^2)");
        this.distance = Validate.positive(distance, "distance S (m)");
        this.horizontalSpeed = Validate.positive(horizontalSpeed, "horizontal speed vx (m/s)");
        this.toleranceMetres = Validate.positive(toleranceMetres, "tolerance (m)");
        if (toleranceMetres >= distance) {
            throw new IllegalArgumentException("tolerance (m) must be less than S = "
                    + distance + " m, so that a shot can miss, but was " + toleranceMetres);
        }
        if (maxShots < 2) {
            throw new IllegalArgumentException("max shots must be >= 2, but was " + maxShots);
        }
        this.maxShots = maxShots;
        computer = new ShotLog(maxShots);
        humanVx = new float[maxShots];
        humanVy = new float[maxShots];
        humanMiss = new double[maxShots];
        humanLandedAt = new double[maxShots];
    }

    /**
     * Step the next round's shots with another simulator (a window's new h), from the next
     * {@link #startRound}.
     *
     * @param newSimulator steps every shot (not null)
     */
    public void setSimulator(ShotSimulator newSimulator) {
        simulator = Validate.notNull(newSimulator, "simulator");
    }

    /**
     * Start the round again with a seed: the computer's shots are worked out (its whole
     * search, as the aim command's), the human's forgotten. The round's number stays until
     * the poll closes it.
     *
     * @param newSeed the believable player's seed (any value)
     */
    public void startRound(long newSeed) {
        seed = newSeed;
        computerResult = new IterativeAim(simulator, gravity, toleranceMetres, maxShots,
                AimStrategy.BELIEVABLE, seed).aim(distance, horizontalSpeed, computer);
        humanShots = 0;
        humanHit = -1;
    }

    /** @return the round's number (from 1): rounds closed so far, plus one */
    public int getRound() {
        return round;
    }

    /** @return the believable player's seed this round */
    public long getSeed() {
        return seed;
    }

    /** @return the computer's shots this round, in order (not null, live: do not modify) */
    public ShotLog getComputerShots() {
        return computer;
    }

    /** @return the computer's search result this round (null before the first round) */
    public AimResult getComputerResult() {
        return computerResult;
    }

    /**
     * Fire the human's shot, unless the round is over or their last shot is still in the air.
     *
     * @param angleDegrees the aim above the horizontal (in degrees, {@link #MIN_ANGLE_DEGREES}
     *     to {@link #MAX_ANGLE_DEGREES})
     * @param speed the launch speed (in m/s, {@link #MIN_SPEED} to {@link #MAX_SPEED})
     * @param roundSeconds the round's simulated time now (in seconds, &ge;0)
     * @return the shot's index (from 0), or -1 if it was not fired
     */
    public int fire(float angleDegrees, float speed, double roundSeconds) {
        if (!(angleDegrees >= MIN_ANGLE_DEGREES && angleDegrees <= MAX_ANGLE_DEGREES)) {
            throw new IllegalArgumentException("aim must be " + MIN_ANGLE_DEGREES + " to "
                    + MAX_ANGLE_DEGREES + " degrees, but was " + angleDegrees);
        }
        if (!(speed >= MIN_SPEED && speed <= MAX_SPEED)) {
            throw new IllegalArgumentException("launch speed must be " + MIN_SPEED + " to "
                    + MAX_SPEED + " m/s, but was " + speed);
        }
        Validate.finite(roundSeconds, "round time (s)");
        if (isRoundOver() || isHumanInAir(roundSeconds)) {
            return -1;
        }
        int shot = humanShots;
        humanVx[shot] = launchX(angleDegrees, speed);
        humanVy[shot] = launchY(angleDegrees, speed);
        if (simulator.fire(humanVx[shot], humanVy[shot], landing)) {
            humanMiss[shot] = landing.getX() - distance;
            humanLandedAt[shot] = roundSeconds + landing.getTimeSeconds();
        } else {
            // Still up when the simulator gave up: a miss as wide as it gets, never a hit.
            humanMiss[shot] = Double.POSITIVE_INFINITY;
            humanLandedAt[shot] = Double.POSITIVE_INFINITY;
        }
        ++humanShots;
        if (Math.abs(humanMiss[shot]) <= toleranceMetres) {
            humanHit = shot;
        }
        return shot;
    }

    /**
     * The launch's vx, as {@link #fire} fires it and a window launches the human's sphere.
     *
     * @param angleDegrees the aim (in degrees)
     * @param speed the launch speed (in m/s)
     * @return {@code speed·cos θ} as a float (in m/s)
     */
    public static float launchX(float angleDegrees, float speed) {
        return (float) (speed * Math.cos(Math.toRadians(angleDegrees)));
    }

    /**
     * The launch's vy, as {@link #fire} fires it.
     *
     * @param angleDegrees the aim (in degrees)
     * @param speed the launch speed (in m/s)
     * @return {@code speed·sin θ} as a float (in m/s)
     */
    public static float launchY(float angleDegrees, float speed) {
        return (float) (speed * Math.sin(Math.toRadians(angleDegrees)));
    }

    /**
     * Test whether the human's last shot is still in the air.
     *
     * @param roundSeconds the round's simulated time now (in seconds)
     * @return true before its landing time
     */
    public boolean isHumanInAir(double roundSeconds) {
        return humanShots > 0 && roundSeconds < humanLandedAt[humanShots - 1];
    }

    /** @return the human's shots this round (0 to the most shots) */
    public int countHumanShots() {
        return humanShots;
    }

    /**
     * Return a human shot's miss.
     *
     * @param shot from 0, less than {@link #countHumanShots()}
     * @return {@code landing − S} (in metres; +∞ if it never came down)
     */
    public double getHumanMiss(int shot) {
        checkShot(shot);
        return humanMiss[shot];
    }

    /**
     * Return when a human shot landed.
     *
     * @param shot from 0, less than {@link #countHumanShots()}
     * @return the round's time at its landing (in seconds; +∞ if it never came down)
     */
    public double getHumanLandingSeconds(int shot) {
        checkShot(shot);
        return humanLandedAt[shot];
    }

    /** @return true once a human shot landed within the tolerance */
    public boolean hasHumanHit() {
        return humanHit >= 0;
    }

    /** @return true once the human hit or fired every shot of the round */
    public boolean isRoundOver() {
        return humanHit >= 0 || humanShots == maxShots;
    }

    /**
     * Close the round with the room's answer to "felt fair?": its row is logged, the round's
     * number goes up. Start the next with {@link #startRound}.
     *
     * @param fair true if the round felt fair
     * @return the row, in the order of {@link #CSV_HEADER} (a new array)
     * @throws IllegalStateException if the round is not over yet
     */
    public double[] closeRound(boolean fair) {
        if (!isRoundOver()) {
            throw new IllegalStateException("round " + round + " is not over: the human has"
                    + " not hit yet (" + humanShots + " of " + maxShots + " shots)");
        }
        int counted = humanHit >= 0 ? humanHit + 1 : humanShots;
        double worst = 0.0;
        for (int i = 0; i < counted; ++i) {
            worst = Math.max(worst, Math.abs(humanMiss[i]));
        }
        double[] row = {round, seed, counted, humanHit >= 0 ? 1 : 0, worst,
            humanHit >= 0 ? humanLandedAt[humanHit] : Double.NaN, computer.size(),
            worstComputerMiss(), computerSeconds(), fair ? 1 : 0};
        closed.add(row);
        ++round;
        return row.clone();
    }

    /** @return the rounds closed so far (&ge;0) */
    public int countClosedRounds() {
        return closed.size();
    }

    /**
     * Copy a closed round's row, in the order of {@link #CSV_HEADER}.
     *
     * @param index from 0, less than {@link #countClosedRounds()}
     * @return a new array (not null)
     */
    public double[] copyClosedRound(int index) {
        return closed.get(index).clone();
    }

    /** @return the computer's worst {@code |miss|} this round (in metres) */
    public double worstComputerMiss() {
        double worst = 0.0;
        for (int i = 0; i < computer.size(); ++i) {
            worst = Math.max(worst, Math.abs(computer.getMiss(i)));
        }
        return worst;
    }

    /** @return the sum of the computer's flight times this round (in seconds) */
    public double computerSeconds() {
        double seconds = 0.0;
        for (int i = 0; i < computer.size(); ++i) {
            seconds += computer.getFlightSeconds(i);
        }
        return seconds;
    }

    private void checkShot(int shot) {
        if (shot < 0 || shot >= humanShots) {
            throw new IllegalArgumentException("shot must be in 0.." + (humanShots - 1)
                    + ", but was " + shot);
        }
    }
}

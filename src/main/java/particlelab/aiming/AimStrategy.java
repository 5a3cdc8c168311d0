package particlelab.aiming;

/**
 * How {@link IterativeAim} adjusts vy from one simulated shot to the next. Every strategy fires
 * its first shot at the lecture's {@code vy = g·S/(2·vx)}, stops once a shot lands within the
 * tolerance, and reports "out of reach" by the same test: while the shots fall short and vy
 * grows, a reach that stops growing is searched for its peak (golden section), and a peak
 * short of S is out of reach. A shot that lands at the gun (vy below g·h: under the ground
 * after one step) did not fly, so its flat reach of 0 m is not taken for a peak.
 */
public enum AimStrategy {
    /**
     * The search {@code aim --method iterative} has always used: double vy until the shot
     * overshoots, then regula falsi (Illinois variant) inside the bracket. About six shots to
     * millimetres.
     */
    ILLINOIS("illinois"),
    /**
     * The lecture's own rule: undershot → more power, overshot → less. vy changes by a fixed
     * amount, half the first guess, and the change is halved at each sign change of the miss.
     * Linear convergence: a couple of shots per halving.
     */
    LECTURE("lecture"),
    /** Double vy until the shot overshoots, then halve the bracket at every shot. */
    BISECTION("bisection"),
    /**
     * Double vy until the shot overshoots, then the secant through the last two shots, kept
     * inside the bracket (a step that would leave it bisects instead). Superlinear on a smooth
     * reach: no more shots than bisection.
     */
    SECANT("secant"),
    /**
     * A computer player a person believes: it works out the right vy first, invisibly (the
     * Illinois search to half the tolerance), then fires a first shot that always misses and
     * moves a seeded random 30–170 % of the way toward the right vy at each later shot. Its
     * error shrinks by a factor of at most 0.7 per shot. (A tolerance so large that even a shot
     * landing at the gun is within it leaves no shot that misses.)
     */
    BELIEVABLE("believable");

    private final String cliName;

    AimStrategy(String cliName) {
        this.cliName = cliName;
    }

    /**
     * Return the name the command line and the HUD use.
     *
     * @return e.g. "secant" (not null)
     */
    public String cliName() {
        return cliName;
    }

    /**
     * Find a strategy by its command-line name.
     *
     * @param name e.g. "bisection" (not null)
     * @return the strategy
     * @throws IllegalArgumentException if no strategy has that name
     */
    public static AimStrategy fromCliName(String name) {
        for (AimStrategy strategy : values()) {
            if (strategy.cliName.equals(name)) {
                return strategy;
            }
        }
        throw new IllegalArgumentException("aim strategy must be one of illinois, lecture,"
                + " bisection, secant, believable, but was " + name);
    }
}

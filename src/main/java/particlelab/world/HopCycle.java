package particlelab.world;

/**
 * The hop a stepped ball settles into on the ground when restitution applies to every impact
 * (the resting fix off, a threshold below the impact speeds): the fixed point of its impact
 * speed. The one place these formulas live; the bounce demo's HUD, the {@code bounce}
 * command's help and the tests call it.
 *
 * <p>Setting: the lecture's semi-implicit Euler step {@code V += h·g, P += h·V} with gravity
 * g alone, the ground met by the swept test of a {@link World} ({@link Detection#SWEPT}) and
 * resolved by {@code v' = e·w} ({@link ImpulseResponse} with the resting fix off). The swept
 * test puts the ball at the impact, a fraction f into step, and sends it on at the rebound
 * speed for the rest of that step <em>with no gravity</em>: the step's gravity was spent
 * before the impact. So a hop that leaves at {@code e·w} gets the kick {@code −g·h} in each of
 * the K whole steps that follow, the last of which holds the next impact, and arrives at
 * <pre>
 *   w' = K·g·h − e·w                                 (K ≥ 1 whole steps of gravity)
 * </pre>
 * With the same K every hop, {@code w = w'} gives the fixed point and, from the hop's height
 * gain {@code h·(K·e·w − g·h·K(K−1)/2 − f·K·g·h) = 0}, the fraction of the step where it is
 * met:
 * <pre>
 *   w*(K) = K·g·h/(1+e)            f*(K) = 1/2 − K·(1−e)/(2·(1+e))
 * </pre>
 * f* must lie in [0, 1/2], so {@code 1 ≤ K ≤ (1+e)/(1−e)}. Linearised about it, the impact
 * speed and fraction map to themselves with both eigenvalues −e: the hop is attracting, and
 * the impact speeds converge to w* alternating about it, off by a factor e per hop. Which K
 * the ball ends on is decided by its drop, not by e, g and h alone: with e = 0.8 and h = 1/60
 * a drop of 4 m ends on K = 4 (w* = 0.36296 m/s), one of 1 m on K = 6, and some drops wander
 * between K values for a long time before one holds. e = 1 has no fixed point: no energy is
 * lost, so the hops keep their height.
 *
 * <p>A restitution threshold v_t (e = 0 for impacts at or below it) therefore stops the ball
 * at its first impact at or below v_t, and a ball on its K-hop gets one exactly when
 * {@code w*(K) ≤ v_t} (the speeds alternate about w*, so one falls at or below it); while
 * {@code w*(K) > v_t} every impact stays above v_t and the ball hops for ever. To stay at rest
 * afterwards it also needs {@code g·h ≤ v_t}, the speed each step of resting contact closes
 * at. A threshold at or above {@code w*(K_max)}, {@code K_max = ⌊(1+e)/(1−e)⌋}, leaves no hop
 * to settle on. With the resting fix the rebound is {@code e·(w − g·h)} and the same algebra
 * gives {@code f* = −(K−1)·(1−e)/(2·(1+e)) < 0} for every K &gt; 1: no hop exists but rest.
 */
public final class HopCycle {

    private HopCycle() {
    }

    /**
     * Return the impact speed of the K-step hop, {@code w* = K·g·h/(1+e)}.
     *
     * @param stepsPerHop K, the whole steps of gravity in one hop (&ge;1)
     * @param restitution e (from 0 to 1)
     * @param gravity g, the magnitude of gravity (in m/s², finite, &gt;0)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @return w* (in m/s, &gt;0)
     */
    public static double fixedPointSpeed(int stepsPerHop, float restitution, float gravity,
            float stepSeconds) {
        check(stepsPerHop, restitution, gravity, stepSeconds);
        return stepsPerHop * (double) gravity * stepSeconds / (1.0 + restitution);
    }

    /**
     * Return where in its step the K-step hop's impact falls,
     * {@code f* = 1/2 − K·(1−e)/(2·(1+e))}.
     *
     * @param stepsPerHop K (&ge;1)
     * @param restitution e (from 0 to 1)
     * @return f* (a fraction of the step; negative when K is too long for e: no such hop)
     */
    public static double impactFraction(int stepsPerHop, float restitution) {
        check(stepsPerHop, restitution, 1f, 1f);
        return 0.5 - stepsPerHop * (1.0 - restitution) / (2.0 * (1.0 + restitution));
    }

    /**
     * Return the longest hop that can repeat, {@code K_max = ⌊(1+e)/(1−e)⌋}.
     *
     * @param restitution e (from 0 to 1)
     * @return K_max (&ge;1; {@link Integer#MAX_VALUE} for e = 1)
     */
    public static int maxStepsPerHop(float restitution) {
        check(1, restitution, 1f, 1f);
        if (restitution == 1f) {
            return Integer.MAX_VALUE;
        }
        int longest = 1;
        while (impactFraction(longest + 1, restitution) >= 0.0) {
            ++longest;
        }
        return longest;
    }

    /**
     * Test whether a restitution threshold stops a ball that hops K steps: whether
     * {@code w*(K) ≤ v_t}.
     *
     * @param thresholdSpeed v_t (in m/s, &ge;0)
     * @param stepsPerHop K (&ge;1)
     * @param restitution e (from 0 to 1)
     * @param gravity g (in m/s², finite, &gt;0)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @return true if its impacts come at or below the threshold
     */
    public static boolean thresholdStops(float thresholdSpeed, int stepsPerHop,
            float restitution, float gravity, float stepSeconds) {
        if (!(thresholdSpeed >= 0f)) {
            throw new IllegalArgumentException(
                    "threshold (m/s) must be >= 0, but was " + thresholdSpeed);
        }
        return fixedPointSpeed(stepsPerHop, restitution, gravity, stepSeconds)
                <= thresholdSpeed;
    }

    private static void check(int stepsPerHop, float restitution, float gravity,
            float stepSeconds) {
        ImpulseResponse.checkRestitution(restitution);
        if (stepsPerHop < 1 || !(gravity > 0f) || gravity == Float.POSITIVE_INFINITY
                || !(stepSeconds > 0f) || stepSeconds == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("steps per hop K must be >= 1, g (m/s^2) and"
                    + " h (s) finite and > 0, but were " + stepsPerHop + ", " + gravity + ", "
                    + stepSeconds);
        }
    }
}

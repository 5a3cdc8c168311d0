package particlelab.world;

/**
 * The hops a stepped ball settles into on the ground when restitution applies to every impact
 * (the resting fix off, a threshold below the impact speeds): the fixed point of its impact
 * speed for hops of K whole steps, or a cycle of hops of several K. The one place these
 * formulas live; the bounce demo's HUD, the {@code bounce} command's help and the tests
 * call it.
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
 * the impact speeds converge to w* alternating about it, off by a factor e per hop.
 *
 * <p>These fixed points are not the only attracting orbits. The map also has cycles of n hops
 * that mix several K, and a drop may end on one of them instead: with h = 1/60 s and R =
 * 0.25 m, 14 of 46 drops from 0.5 to 5 m (0.1 m apart, 300 s each) end at e = 0.8 on a cycle
 * of 12 hops with K from 2 to 4 and impact speeds 0.132 to 0.405 m/s, the rest on fixed
 * points (K = 1 to 6); at e = 0.9, the bounce demo's default, its own 4 m drop ends on a
 * cycle of 64 hops, K from 4 to 9, impact speeds 0.300 to 0.815 m/s (HopCycleTest steps the
 * world and checks these). Which orbit holds is decided by the drop, not by e, g and h alone;
 * {@link #findOrbitHops} tells from the latest impacts which one a ball is on. e = 1 has no
 * fixed point: no energy is lost, so the hops keep their height.
 *
 * <p>A restitution threshold v_t (e = 0 for impacts at or below it) stops the ball at its
 * first impact at or below v_t, on the way to an orbit or on it. A ball on a K-step fixed
 * point gets one exactly when {@code w*(K) ≤ v_t} (the speeds alternate about w*, so one falls
 * at or below it); a ball on a cycle gets one when v_t reaches the cycle's slowest impact,
 * which can lie far below the fastest (Cyclone's 0.25 m/s stops the 0.5 m drop at e = 0.8,
 * whose cycle's slowest impact is 0.132 m/s).
 * While every impact of the orbit stays above v_t the ball hops for ever. To stay at rest
 * afterwards it also needs {@code g·h ≤ v_t}, the speed each step of resting contact closes
 * at. With the resting fix the rebound is {@code e·(w − g·h)} and the same algebra gives
 * {@code f* = −(K−1)·(1−e)/(2·(1+e)) < 0} for every K &gt; 1: no hop exists but rest.
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
     * Test whether a restitution threshold stops a ball on the K-step fixed point: whether
     * {@code w*(K) ≤ v_t}. (A ball on a cycle is stopped when v_t reaches the cycle's slowest
     * impact instead.)
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

    /**
     * Find the orbit the latest hops repeat: the smallest n such that each of the last n hops
     * took as many whole steps as the hop n before it and met the ground at the same speed,
     * to a relative tolerance (the orbit attracts, so the speeds close in on it). n = 1 is a
     * K-step fixed point, n &gt; 1 a cycle of n hops mixing several K. The arrays are rings
     * of the same length: hop number m (from 0, in order) is at index {@code m % length}.
     * Allocates nothing.
     *
     * @param hopSteps each hop's whole steps K (not null)
     * @param impactSpeeds the impact speed that ended each hop (in m/s, not null, as long)
     * @param hopCount how many hops have been written (&ge;0; the ring keeps the latest)
     * @param maxHops the longest orbit to look for (&ge;1; 2·maxHops hops must fit the ring)
     * @param relativeTolerance how close repeated speeds must be, relatively (&ge;0)
     * @return n, the hops in one round of the orbit, or 0 if the latest hops repeat none
     */
    public static int findOrbitHops(int[] hopSteps, float[] impactSpeeds, int hopCount,
            int maxHops, double relativeTolerance) {
        int length = hopSteps.length;
        if (impactSpeeds.length != length || hopCount < 0 || maxHops < 1
                || 2 * maxHops > length || !(relativeTolerance >= 0.0)) {
            throw new IllegalArgumentException("rings of one length >= 2 maxHops, hop count"
                    + " >= 0, maxHops >= 1 and tolerance >= 0 needed, but were " + length
                    + ", " + impactSpeeds.length + ", " + hopCount + ", " + maxHops + ", "
                    + relativeTolerance);
        }
        for (int hops = 1; hops <= maxHops && 2 * hops <= hopCount; ++hops) {
            boolean repeats = true;
            for (int back = 0; back < hops && repeats; ++back) {
                int latest = (hopCount - 1 - back) % length;
                int before = (hopCount - 1 - back - hops) % length;
                float speed = impactSpeeds[latest];
                repeats = hopSteps[latest] == hopSteps[before]
                        && Math.abs(speed - impactSpeeds[before]) <= relativeTolerance * speed;
            }
            if (repeats) {
                return hops;
            }
        }
        return 0;
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

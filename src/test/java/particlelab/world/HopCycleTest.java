package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

/**
 * The stepped ball's hop against {@link HopCycle}'s fixed point {@code w* = K·g·h/(1+e)}: a
 * ball dropped 4 m in a world with the swept ground, the resting fix off, stepped for 60 s.
 */
class HopCycleTest {

    private static final float G = Gravity.STANDARD_G;
    private static final float H = 1f / 60f;
    private static final float DROP_METRES = 4f;
    private static final int STEPS_IN_60_S = 3600;
    private static final int STEPS_IN_300_S = 18_000;
    /** The bounce demo's ball radius R (in metres). */
    private static final float DEMO_RADIUS = 0.25f;
    /** The hops the bounce demo's recorder keeps for the detector. */
    private static final int RING = 256;

    /** Every impact: the step it came in, its fraction, its speed and the rebound. */
    private static final class Impacts implements ContactListener {
        final List<Long> steps = new ArrayList<>();
        final List<Float> fractions = new ArrayList<>();
        final List<Float> speeds = new ArrayList<>();
        final List<Float> rebounds = new ArrayList<>();

        @Override
        public void resolved(Contact contact, World world) {
            steps.add(world.getStepCount());
            fractions.add(contact.getFraction());
            speeds.add(contact.getApproachSpeed());
            rebounds.add(contact.getBodyA().getVelocity().y);
        }

        int count() {
            return steps.size();
        }

        long hopSteps(int fromEnd) {
            int i = count() - fromEnd;
            return steps.get(i) - steps.get(i - 1);
        }
    }

    @ParameterizedTest(name = "e = {0}: K = {1}")
    @CsvSource({"0.8, 4", "0.6, 3"})
    void impactSpeedsConvergeToTheFormulasFixedPoint(float e, int stepsPerHop) {
        Impacts impacts = drop(e, 0f);
        double fixedPoint = HopCycle.fixedPointSpeed(stepsPerHop, e, G, H);
        assertTrue(impacts.count() > 500, "impacts: " + impacts.count());
        for (int k = 1; k <= 50; ++k) {
            int i = impacts.count() - k;
            assertEquals(stepsPerHop, impacts.hopSteps(k), "hop " + i + " in steps");
            // After hundreds of hops the transient (a factor e a hop) is gone; what is left is
            // float round-off: a hop does about K + 2 float operations on speeds below 1 m/s
            // (ulp 6e-8), and the map contracts by e, so the error stays within
            // (K + 2)·6e-8/(1 − e) ≤ 2e-6 m/s (measured: 2e-7).
            assertEquals(fixedPoint, impacts.speeds.get(i), 2e-6, "impact " + i);
            // The fraction is a ratio of gaps of about w*·h·f ≈ 2e-3 m, each rounded to half an
            // ulp of the centre height (≈ 1e-8 m at y ≈ 0): 1e-4 covers it many times.
            assertEquals(HopCycle.impactFraction(stepsPerHop, e), impacts.fractions.get(i),
                    1e-4, "fraction of impact " + i);
        }
        assertTrue(stepsPerHop <= HopCycle.maxStepsPerHop(e));
    }

    @ParameterizedTest(name = "e = {0}")
    @CsvSource({"0.8, 4", "0.6, 3"})
    void cyclonesThresholdBelowTheFixedPointNeverStopsTheBall(float e, int stepsPerHop) {
        float threshold = ImpulseResponse.CYCLONE_THRESHOLD;
        Impacts impacts = drop(e, threshold);
        assertFalse(HopCycle.thresholdStops(threshold, stepsPerHop, e, G, H));
        long lastStep = impacts.steps.get(impacts.count() - 1);
        // Still hopping after 60 s: an impact within the last hop, and it bounced back.
        assertTrue(lastStep >= STEPS_IN_60_S - 1 - stepsPerHop, "last impact at step "
                + lastStep);
        assertTrue(impacts.rebounds.get(impacts.count() - 1) > 0f);
        for (int k = 1; k <= 50; ++k) {
            float speed = impacts.speeds.get(impacts.count() - k);
            assertTrue(speed > threshold, "impact " + k + " from the end: " + speed);
        }
    }

    @Test
    void aThresholdAboveTheFixedPointStopsTheBall() {
        float e = 0.8f;
        // Just above w*(4) = 0.36296 m/s, the hop a 4 m drop settles on.
        float threshold = 0.37f;
        assertTrue(HopCycle.thresholdStops(threshold, 4, e, G, H));
        Impacts impacts = drop(e, threshold);
        int last = impacts.count() - 1;
        assertEquals(0f, impacts.rebounds.get(last), "the last impact is inelastic");
        assertTrue(impacts.speeds.get(last) <= threshold);
        // At rest: each resting step closes at g·h < v_t and gets e = 0, a rebound of 0.
        for (int i = 0; i < impacts.count(); ++i) {
            if (impacts.speeds.get(i) <= threshold) {
                assertEquals(0f, impacts.rebounds.get(i), "impact " + i);
            }
        }
        assertTrue(impacts.steps.get(last) == STEPS_IN_60_S - 1, "resting contact every step");
    }

    @Test
    void theLongestHopAndItsFractionFollowTheFormula() {
        // (1+e)/(1−e): 9 for e = 0.8, 4 for 0.6, 1.86 for 0.3; f*(K_max) = 0 when it is whole.
        assertEquals(9, HopCycle.maxStepsPerHop(0.8f));
        assertEquals(4, HopCycle.maxStepsPerHop(0.6f));
        assertEquals(1, HopCycle.maxStepsPerHop(0.3f));
        assertEquals(1, HopCycle.maxStepsPerHop(0f));
        assertEquals(Integer.MAX_VALUE, HopCycle.maxStepsPerHop(1f));
        // 4·9.8/60/1.8 = 0.362962..., the figure; to double round-off of float inputs.
        assertEquals(4.0 * 9.8 / 60.0 / 1.8, HopCycle.fixedPointSpeed(4, 0.8f, G, H), 1e-7);
        assertEquals(0.5 - 4 * 0.2 / 3.6, HopCycle.impactFraction(4, 0.8f), 1e-7);
        assertThrows(IllegalArgumentException.class, () -> HopCycle.fixedPointSpeed(0, 0.8f,
                G, H));
        assertThrows(IllegalArgumentException.class, () -> HopCycle.fixedPointSpeed(4,
                Float.NaN, G, H));
    }

    @Test
    void withTheRestingFixTheSameDropComesToRest() {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, DROP_METRES, 0f), Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.8f, 0f, true), Detection.SWEPT));
        for (int n = 0; n < STEPS_IN_60_S; ++n) {
            world.step(H);
        }
        Body ball = world.getBody(0);
        assertEquals(0f, ball.getVelocity().y);
        assertEquals(0f, ball.getPosition().y);
    }

    /**
     * The orbits drops from 0.5 to 5 m end on, as the bounce demo drops its ball (R = 0.25 m,
     * lowest point at the drop height, the swept ground, no fix, no threshold), 300 s each.
     * The reference is the exact one of float arithmetic: the stepped world's own impacts,
     * whose (K, impact speed bits) sequence ends periodic; its exact period P is found by
     * equality of bits. The detector, given only the last 256 hops as the demo's recorder
     * keeps them, must name an orbit of n hops that divides P and spans the same K and speeds
     * (exactly: the same floats), and n = 1 exactly when every hop of the orbit has one K.
     */
    @ParameterizedTest(name = "e = {0}")
    @CsvSource({"0.8", "0.9"})
    void theDetectorNamesTheOrbitEachDropEndsOn(float e) {
        int cycles = 0;
        for (int tenths = 5; tenths <= 50; tenths += 5) {
            Impacts impacts = dropDemoBall(tenths / 10f, e, 0f, STEPS_IN_300_S);
            int exact = exactPeriod(impacts);
            assertTrue(exact > 0, "drop " + tenths + ": no exact period in the tail");
            int hops = orbitHops(impacts);
            assertTrue(hops > 0 && exact % hops == 0, "drop " + tenths + ": n = " + hops
                    + ", exact period " + exact);
            String[] orbit = range(impacts, exact).split(" ");
            String[] named = range(impacts, hops).split(" ");
            assertEquals(orbit[1], named[1], "drop " + tenths + ": K");
            // The speeds one round apart agree to the detector's tolerance, 1e-3 relatively
            // (a fixed point's float orbit may alternate between two floats an ulp apart).
            for (int end = 0; end < 2; ++end) {
                double speed = Double.parseDouble(orbit[3].split("\\.\\.\\.")[end]);
                assertEquals(speed, Double.parseDouble(named[3].split("\\.\\.\\.")[end]),
                        1e-3 * speed, "drop " + tenths + ": impact speeds");
            }
            boolean oneK = orbit[1].equals(impacts.hopSteps(1) + "..." + impacts.hopSteps(1));
            assertEquals(oneK, hops == 1, "drop " + tenths + ": " + range(impacts, exact));
            if (hops > 1) {
                ++cycles;
            }
        }
        // Both values of e have drops ending on cycles: K alone does not say where they end.
        assertTrue(cycles > 0, "cycles: " + cycles);
    }

    /**
     * The audit's figures, re-measured: the demo's own 4 m drop at e = 0.9 ends on a cycle of
     * 64 hops, K 4 to 9, impacts 0.300 to 0.815 m/s; at e = 0.8 the 0.5 m drop ends on a cycle
     * of 12 hops, K 2 to 4, impacts 0.132 to 0.405 m/s, and the 4 m drop on the fixed point
     * K = 4, w* = 0.36296 m/s. Cyclone's 0.25 m/s is below w*(4) but above the 0.5 m drop's
     * slowest impact on its cycle: it stops that drop and not the 4 m one.
     */
    @Test
    void theDemosDropsEndOnTheOrbitsTheTheoryNames() {
        Impacts cycle = dropDemoBall(4f, 0.9f, 0f, STEPS_IN_300_S);
        assertEquals(64, orbitHops(cycle));
        // Speeds printed to three decimals: half a unit of the last digit.
        assertEquals("K 4...9 v 0.300...0.815", rounded(cycle, 64));
        Impacts small = dropDemoBall(0.5f, 0.8f, 0f, STEPS_IN_300_S);
        assertEquals(12, orbitHops(small));
        assertEquals("K 2...4 v 0.132...0.405", rounded(small, 12));
        Impacts fixed = dropDemoBall(4f, 0.8f, 0f, STEPS_IN_300_S);
        assertEquals(1, orbitHops(fixed));
        assertEquals(4L, fixed.hopSteps(1));
        // the fixed point to float round-off, as in impactSpeedsConvergeToTheFormulasFixedPoint
        assertEquals(HopCycle.fixedPointSpeed(4, 0.8f, G, H),
                fixed.speeds.get(fixed.count() - 1), 2e-6);
        float cyclone = ImpulseResponse.CYCLONE_THRESHOLD;
        Impacts stopped = dropDemoBall(0.5f, 0.8f, cyclone, STEPS_IN_60_S);
        int last = stopped.count() - 1;
        assertEquals(STEPS_IN_60_S - 1, (long) stopped.steps.get(last), "rests to the end");
        assertEquals(0f, stopped.rebounds.get(last));
        Impacts hopping = dropDemoBall(4f, 0.8f, cyclone, STEPS_IN_60_S);
        assertTrue(hopping.rebounds.get(hopping.count() - 1) > 0f, "still hopping");
    }

    /** The orbit the detector names from the last 256 hops of a run. */
    private static int orbitHops(Impacts impacts) {
        int count = impacts.count();
        int hopCount = count - 1;
        int[] ringSteps = new int[RING];
        float[] ringSpeeds = new float[RING];
        for (int m = hopCount - RING; m < hopCount; ++m) {
            ringSteps[m % RING] = (int) (impacts.steps.get(m + 1) - impacts.steps.get(m));
            ringSpeeds[m % RING] = impacts.speeds.get(m + 1);
        }
        return HopCycle.findOrbitHops(ringSteps, ringSpeeds, hopCount, RING / 2, 1e-3);
    }

    /** The range of K and the exact impact speeds of the last n hops. */
    private static String range(Impacts impacts, int hops) {
        long fewest = Long.MAX_VALUE;
        long most = 0L;
        float slowest = Float.POSITIVE_INFINITY;
        float fastest = 0f;
        for (int k = 1; k <= hops; ++k) {
            fewest = Math.min(fewest, impacts.hopSteps(k));
            most = Math.max(most, impacts.hopSteps(k));
            slowest = Math.min(slowest, impacts.speeds.get(impacts.count() - k));
            fastest = Math.max(fastest, impacts.speeds.get(impacts.count() - k));
        }
        return "K " + fewest + "..." + most + " v " + slowest + "..." + fastest;
    }

    private static String rounded(Impacts impacts, int hops) {
        String[] parts = range(impacts, hops).split(" ");
        String[] speeds = parts[3].split("\\.\\.\\.");
        return parts[0] + " " + parts[1] + " v " + String.format(java.util.Locale.ROOT,
                "%.3f...%.3f", Float.parseFloat(speeds[0]), Float.parseFloat(speeds[1]));
    }

    /**
     * The exact period of the tail: the smallest P such that the last 2P impacts repeat with
     * period P in hop steps and in the bits of the impact speed; 0 if none up to 256.
     */
    private static int exactPeriod(Impacts impacts) {
        int count = impacts.count();
        for (int p = 1; p <= RING; ++p) {
            boolean repeats = true;
            for (int k = 1; k <= 2 * p && repeats; ++k) {
                int i = count - k;
                repeats = impacts.hopSteps(k) == impacts.hopSteps(k + p)
                        && Float.floatToIntBits(impacts.speeds.get(i))
                        == Float.floatToIntBits(impacts.speeds.get(i - p));
            }
            if (repeats) {
                return p;
            }
        }
        return 0;
    }

    /** Drop a ball of the demo's radius with its lowest point at a height and step. */
    private static Impacts dropDemoBall(float dropMetres, float e, float threshold,
            int steps) {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, dropMetres + DEMO_RADIUS, 0f), Vector3f.ZERO, 1f, DEMO_RADIUS);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e, threshold, false),
                Detection.SWEPT));
        Impacts impacts = new Impacts();
        world.addContactListener(impacts);
        for (int n = 0; n < steps; ++n) {
            world.step(H);
        }
        return impacts;
    }

    /** Drop the ball 4 m with the resting fix off and step 60 s. */
    private static Impacts drop(float e, float threshold) {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, DROP_METRES, 0f), Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e, threshold, false),
                Detection.SWEPT));
        Impacts impacts = new Impacts();
        world.addContactListener(impacts);
        for (int n = 0; n < STEPS_IN_60_S; ++n) {
            world.step(H);
        }
        return impacts;
    }
}

package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;

class AimStrategyTest {

    private static final double G = 9.8;
    private static final float VX = 20f;
    private static final float H = 1f / 60f;
    private static final float MAX_FLIGHT_SECONDS = 600f;
    private static final int MAX_SHOTS = 100;
    private static final double TOLERANCE = 1e-3;
    private static final long SEED = 7L;

    private static Force[] gravityOnly() {
        return new Force[] {new Gravity()};
    }

    /** Linear drag b/m = 0.1 /s: the reach at vx = 20 is below vx·m/b = 200 m. */
    private static Force[] linear() {
        return new Force[] {new Gravity(), new LinearDrag(0.1f)};
    }

    /** Quadratic drag c/m = 0.01 /m: the reach at vx = 20 peaks near 67.2 m. */
    private static Force[] quadratic() {
        return new Force[] {new Gravity(), new QuadraticDrag(0.01f)};
    }

    private static IterativeAim aimer(AimStrategy strategy, long seed, double tolerance,
            Force... forces) {
        ShotSimulator simulator = new ShotSimulator(new ParticleIntegrator(forces), 1f, H,
                MAX_FLIGHT_SECONDS);
        return new IterativeAim(simulator, G, tolerance, MAX_SHOTS, strategy, seed);
    }

    private static AimResult aim(AimStrategy strategy, double distance, ShotLog log,
            Force... forces) {
        return aimer(strategy, SEED, TOLERANCE, forces).aim(distance, VX, log);
    }

    /**
     * Each strategy hits within the tolerance with either drag, and its log holds every shot it
     * counted, the last one being the result. Shots measured: Illinois and secant 6, bisection
     * 14 to 16, the lecture rule 20 to 22, the believable player 9 and 8; the bounds leave room but
     * would catch a search that wanders.
     */
    @Test
    void everyStrategyHitsWithLinearAndQuadraticDrag() {
        int[] bound = {12, 40, 30, 12, 40};
        for (AimStrategy strategy : AimStrategy.values()) {
            for (Force[] forces : new Force[][] {linear(), quadratic()}) {
                double distance = forces[1] instanceof LinearDrag ? 100.0 : 50.0;
                ShotLog log = new ShotLog(MAX_SHOTS);
                AimResult result = aim(strategy, distance, log, forces);
                String what = strategy + " " + result;
                assertTrue(result.isHit(), what);
                assertEquals("hit", result.getExplanation(), what);
                assertTrue(Math.abs(result.getMiss()) <= TOLERANCE, what);
                assertTrue(result.getShots() <= bound[strategy.ordinal()], what);
                assertEquals(result.getShots(), log.size(), what);
                int last = log.size() - 1;
                assertEquals((float) result.getVerticalSpeed(), log.getVerticalSpeed(last), what);
                assertEquals(result.getLandingX(), log.getLandingX(last), 0.0, what);
                assertEquals(result.getMiss(), log.getMiss(last), 1e-12, what);
                for (int i = 0; i < last; ++i) {
                    assertTrue(Math.abs(log.getMiss(i)) > TOLERANCE, "only the last hits");
                }
            }
        }
    }

    /**
     * Out of reach, whatever the strategy: linear drag b/m = 0.1 lets no shot pass 200 m (the
     * stepped bullet 199.67 m); quadratic c/m = 0.01 peaks at about 67.21 m at vx = 20. Each
     * finds out before its shots run out and reports the farthest shot.
     */
    @Test
    void everyStrategyReportsOutOfReach() {
        for (AimStrategy strategy : AimStrategy.values()) {
            for (double distance : new double[] {250.0, 199.9}) {
                AimResult result = aim(strategy, distance, null, linear());
                String what = strategy + " " + result;
                assertFalse(result.isHit(), what);
                assertTrue(result.getExplanation().startsWith("target at S=" + distance
                        + " m is out of reach at vx=20.0 m/s"), what);
                assertTrue(result.getLandingX() < 199.67, what);
                assertTrue(result.getShots() < MAX_SHOTS, what);
            }
            AimResult result = aim(strategy, 100.0, null, quadratic());
            String what = strategy + " " + result;
            assertFalse(result.isHit(), what);
            assertTrue(result.getExplanation().contains("the reach peaks at about 67.21"), what);
            assertEquals(67.21, result.getLandingX(), 0.01, what);
            assertTrue(result.getShots() < MAX_SHOTS, what);
        }
    }

    /**
     * The lecture's rule, read back from the shots: while short, vy grows by half the first
     * guess; after that each change is against the last miss, the same size as the one before,
     * or half of it when the last two misses differ in sign. The log holds vy as fired
     * (floats), so each change carries up to one ulp of round-off from its two ends, and the
     * expected half another: 2·ulp(vy) in all.
     */
    @Test
    void lectureRuleHalvesItsChangeAtEachSignChange() {
        ShotLog log = new ShotLog(MAX_SHOTS);
        AimResult result = aim(AimStrategy.LECTURE, 97.3, log, gravityOnly());
        assertTrue(result.isHit(), result.toString());
        double firstGuess = LevelAim.lectureVy(G, 97.3, VX);
        int signChanges = 0;
        double change = IterativeAim.LECTURE_FIRST_CHANGE * firstGuess;
        for (int k = 1; k < log.size(); ++k) {
            double roundOff = 2.0 * Math.ulp(log.getVerticalSpeed(k));
            double actual = (double) log.getVerticalSpeed(k) - log.getVerticalSpeed(k - 1);
            boolean short1 = log.getMiss(k - 1) < 0.0;
            if (k >= 2 && short1 != log.getMiss(k - 2) < 0.0) {
                change /= 2.0;
                ++signChanges;
            }
            assertEquals(short1 ? change : -change, actual, roundOff, "shot " + (k + 1));
        }
        assertTrue(signChanges >= 5, "the search narrowed by halving: " + signChanges);
        assertEquals((float) firstGuess, log.getVerticalSpeed(0), 0f, "the lecture's guess");
    }

    /**
     * The believable player: the same seed gives the same shots; another seed other shots;
     * the first shot always misses, even at a tolerance (20 m) its first guess would meet;
     * and it converges within a stated number of shots. Its error shrinks by |1 − u| &le; 0.7
     * per shot (u uniform in 0.3..1.7) from at most 35 % of the right vy, and a shot within
     * half the tolerance, through the landing slope 1.655 m per m/s (IterativeAimTest), of
     * the right vy (itself within half the tolerance) hits: at most
     * {@code 1 + ceil(ln(0.35·vy·1.655/(tol/2))/ln(1/0.7))} = 31 shots. Measured over the
     * seeds 0 to 19: 5 to 13.
     */
    @Test
    void believablePlayerIsReproducibleMissesFirstAndConverges() {
        double rightVy = 38.0708;
        int bound = 1 + (int) Math.ceil(Math.log(0.35 * rightVy * 1.655 / (TOLERANCE / 2.0))
                / Math.log(1.0 / 0.7));
        assertEquals(31, bound);
        ShotLog first = new ShotLog(MAX_SHOTS);
        ShotLog again = new ShotLog(MAX_SHOTS);
        for (long seed = 0; seed < 20; ++seed) {
            AimResult result = aimer(AimStrategy.BELIEVABLE, seed, TOLERANCE, linear())
                    .aim(100.0, VX, first);
            assertTrue(result.isHit(), result.toString());
            assertTrue(result.getShots() >= 2 && result.getShots() <= bound, result.toString());
            assertTrue(Math.abs(first.getMiss(0)) > TOLERANCE, "first shot misses");
            aimer(AimStrategy.BELIEVABLE, seed, TOLERANCE, linear()).aim(100.0, VX, again);
            assertEquals(first.size(), again.size());
            for (int i = 0; i < first.size(); ++i) {
                assertEquals(first.getVerticalSpeed(i), again.getVerticalSpeed(i), 0f);
                assertEquals(first.getMiss(i), again.getMiss(i), 0.0);
            }
        }
        aimer(AimStrategy.BELIEVABLE, 1L, TOLERANCE, linear()).aim(100.0, VX, again);
        assertNotEquals(first.getVerticalSpeed(0), again.getVerticalSpeed(0), "seed 19 vs 1");

        double loose = 20.0;
        AimResult result = aimer(AimStrategy.BELIEVABLE, SEED, loose, linear())
                .aim(100.0, VX, first);
        assertTrue(result.isHit(), result.toString());
        assertTrue(Math.abs(first.getMiss(0)) > loose, "first shot misses: " + first.getMiss(0));
    }

    /**
     * Issue 17: {@code Random.setSeed} barely scrambles its seed, so the first
     * {@code nextDouble()} of nearby seeds was nearly the same and every seed 1 to 20 fired a
     * first shot 29.6 % ± 0.05 % off (J, seed + 1, always gave the same miss). With the seed
     * mixed, the first shot's offset from the right vy, {@code e = vy₁/vy − 1} (vy the hit,
     * within 6e-4 m/s of the right vy: negligible here), is drawn afresh per seed from
     * ±(15–35 %). Over seeds 1 to 50, independent draws would cover the range: the chance that
     * all 50 miss the lowest or the highest tenth of it is 2·0.9⁵⁰ = 1 %, and we ask less (the
     * extremes beyond 18 % and 32 %); both signs occur (chance of one sign only: 2·0.5⁵⁰);
     * and consecutive seeds differ by 0.067 on average for independent uniform draws over a
     * width of 0.2, against 0.0005 before: we ask for at least 0.03. The seeds are fixed, so
     * this is deterministic; the odds only say the thresholds are not tuned to the draws.
     */
    @Test
    void firstShotsOfNearbySeedsSpreadOverTheWholeRange() {
        ShotLog log = new ShotLog(MAX_SHOTS);
        double smallest = Double.POSITIVE_INFINITY;
        double largest = 0.0;
        int longShots = 0;
        double previous = Double.NaN;
        double sumOfSteps = 0.0;
        int seeds = 50;
        for (long seed = 1; seed <= seeds; ++seed) {
            AimResult result = aimer(AimStrategy.BELIEVABLE, seed, TOLERANCE, linear())
                    .aim(100.0, VX, log);
            assertTrue(result.isHit(), result.toString());
            double offset = log.getVerticalSpeed(0) / result.getVerticalSpeed() - 1.0;
            double size = Math.abs(offset);
            // The draw's range, ±1e-4 for the hit's distance from the right vy and float vy.
            assertTrue(size >= IterativeAim.BELIEVABLE_FIRST_MIN_ERROR - 1e-4
                    && size <= IterativeAim.BELIEVABLE_FIRST_MAX_ERROR + 1e-4,
                    "seed " + seed + ": first shot " + offset);
            smallest = Math.min(smallest, size);
            largest = Math.max(largest, size);
            longShots += offset > 0.0 ? 1 : 0;
            if (seed > 1) {
                sumOfSteps += Math.abs(offset - previous);
            }
            previous = offset;
        }
        assertTrue(smallest < 0.18 && largest > 0.32, smallest + " to " + largest);
        assertTrue(longShots > 0 && longShots < seeds,
                longShots + " of " + seeds + " first shots long");
        double meanStep = sumOfSteps / (seeds - 1);
        assertTrue(meanStep > 0.03, "consecutive seeds differ by " + meanStep + " on average");
    }

    /**
     * On smooth cases (no drag, linear drag, quadratic drag on the rising side of the reach)
     * the secant never needs more shots than bisection: measured 3 against 13, 6 against 16,
     * 6 against 14, 5 against 17.
     */
    @Test
    void secantTakesNoMoreShotsThanBisection() {
        Object[][] cases = {
            {97.3, gravityOnly()}, {100.0, linear()}, {50.0, quadratic()},
            {100.0, new Force[] {new Gravity(), new QuadraticDrag(0.001f)}},
        };
        for (Object[] c : cases) {
            double distance = (Double) c[0];
            Force[] forces = (Force[]) c[1];
            AimResult secant = aim(AimStrategy.SECANT, distance, null, forces);
            AimResult bisection = aim(AimStrategy.BISECTION, distance, null, forces);
            assertTrue(secant.isHit() && bisection.isHit(), secant + " / " + bisection);
            assertTrue(secant.getShots() <= bisection.getShots(), secant + " / " + bisection);
        }
    }

    /** The default strategy is the search aim has always used: Illinois. */
    @Test
    void defaultStrategyIsIllinois() {
        ShotSimulator simulator = new ShotSimulator(new ParticleIntegrator(linear()), 1f, H,
                MAX_FLIGHT_SECONDS);
        IterativeAim plain = new IterativeAim(simulator, G, TOLERANCE, MAX_SHOTS);
        assertEquals(AimStrategy.ILLINOIS, plain.getStrategy());
        AimResult a = plain.aim(100.0, VX);
        AimResult b = aim(AimStrategy.ILLINOIS, 100.0, null, linear());
        assertEquals(a.getVerticalSpeed(), b.getVerticalSpeed(), 0.0);
        assertEquals(6, a.getShots());
    }

    @Test
    void strategiesAreFoundByTheirCommandLineNames() {
        for (AimStrategy strategy : AimStrategy.values()) {
            assertEquals(strategy, AimStrategy.fromCliName(strategy.cliName()));
        }
        IllegalArgumentException bad = org.junit.jupiter.api.Assertions.assertThrows(
                IllegalArgumentException.class, () -> AimStrategy.fromCliName("guess"));
        assertTrue(bad.getMessage().contains("guess"), bad.getMessage());
    }

    /** Recording a shot into the log allocates nothing. */
    @Test
    void recordingShotsAllocatesNothing() {
        ShotLog log = new ShotLog(10);
        Landing landing = new Landing();
        landing.set(true, 99.5, 4.9, 300);
        log.record(20f, 24.5f, landing, 100.0);
        Allocations.assertAllocatesNothing("10000 records", () -> {
            for (int i = 0; i < 10_000; ++i) {
                if (log.size() == log.capacity()) {
                    log.clear();
                }
                log.record(20f, 24.5f, landing, 100.0);
            }
        });
        assertEquals(-0.5, log.getMiss(0), 1e-12);
    }
}

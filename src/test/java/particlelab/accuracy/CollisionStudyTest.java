package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import particlelab.app.TunnelCommand;
import particlelab.physics.Gravity;
import particlelab.world.Detection;

/** The collision study's tunnelling and bounce parts against their closed forms. */
class CollisionStudyTest {

    /** Shots per speed: enough for a binomial σ of at most 0.5/√2000 ≈ 0.011. */
    private static final int SHOTS = 2_000;
    /**
     * Binomial tolerance in standard deviations: the run is seeded, and a fair count strays
     * further than 4σ with probability 6e-5 per speed.
     */
    private static final double SIGMAS = 4.0;
    /**
     * Extra tolerance for the world's overlap slop (1e-4 m): a shot whose only step end in the
     * wall lies within it of the far face, moving out, needs no work and is not resolved, so
     * the band resolved is 2r + D − 1e-4 m. Against v·h ≥ 0.1 m that adds at most 1e-3 to the
     * miss rate (5e-4 at v·h = 2r + D).
     */
    private static final double SLOP_RATE = 1e-3;
    /**
     * Tolerance of the fitted bounce orders around 1. Where in its step each impact falls
     * changes with h, which moves single errors up or down by up to about 3× (the table in
     * the report); over the 2.1 decades of h from 1/15 to 1/1920 s the least-squares slope
     * moves by about 0.1. Twice that, so the test fails for order 0.8 or 1.2 and beyond.
     */
    private static final double ORDER_TOLERANCE = 0.2;

    private static CollisionStudy tunnels;
    private static CollisionStudy bounces;

    @BeforeAll
    static void runStudies() {
        tunnels = new CollisionStudy(CollisionStudy.bounceSteps());
        tunnels.runTunnelling(SHOTS);
        bounces = new CollisionStudy(CollisionStudy.bounceSteps());
        bounces.runBounces();
    }

    @Test
    void overlapMissRateFollowsTheFormulaWithinItsBinomialTolerance() {
        assertEquals(CollisionStudy.TRAVEL_RATIOS.length, tunnels.tunnels.size());
        for (CollisionStudy.Tunnel t : tunnels.tunnels) {
            double formula = Math.max(0.0, 1.0 - 1.0 / t.travelRatio);
            // the float speed makes v·h/(2r+D) off the nominal ratio by round-off only
            assertEquals(formula, t.predicted, 1e-6, "ratio " + t.travelRatio);
            double tolerance = SIGMAS * Math.sqrt(formula * (1 - formula) / SHOTS) + SLOP_RATE;
            assertEquals(formula, t.overlapRate(), tolerance, "ratio " + t.travelRatio + ": "
                    + t.overlapMisses + " of " + t.shots + " missed");
        }
        // the fast end really tunnels: at v·h = 10·(2r+D), nine shots in ten pass
        CollisionStudy.Tunnel fastest = tunnels.tunnels.get(tunnels.tunnels.size() - 1);
        assertTrue(fastest.overlapRate() > 0.85, "rate " + fastest.overlapRate());
    }

    @Test
    void sweptTestNeverMisses() {
        for (CollisionStudy.Tunnel t : tunnels.tunnels) {
            assertEquals(0, t.sweptMisses, "ratio " + t.travelRatio);
        }
    }

    @Test
    void wilsonIntervalHoldsTheRateAndEndsAtZeroWithoutMisses() {
        for (CollisionStudy.Tunnel t : tunnels.tunnels) {
            double[] interval = t.overlapInterval();
            assertTrue(interval[0] <= t.overlapRate() && t.overlapRate() <= interval[1],
                    "ratio " + t.travelRatio);
            if (t.overlapMisses == 0) {
                assertEquals(0.0, interval[0]);
                // no misses in N: the upper end is z²/(N + z²)
                double z2 = CollisionStudy.Z95 * CollisionStudy.Z95;
                assertEquals(z2 / (SHOTS + z2), interval[1], 1e-12);
            }
        }
    }

    @Test
    void countsAreThoseOfTheTunnelCommand() {
        int[] rows = {4, 8};
        for (int row : rows) {
            CollisionStudy.Tunnel t = tunnels.tunnels.get(row);
            assertEquals(t.overlapMisses, tunnelMisses(t, "overlap", row), "row " + row);
            assertEquals(t.sweptMisses, tunnelMisses(t, "swept", row), "row " + row);
        }
    }

    @Test
    void bounceErrorFallsWithTheStepAtFirstOrder() {
        assertEquals(2, bounces.bounceOrders.size());
        for (CollisionStudy.BounceOrder o : bounces.bounceOrders) {
            assertEquals(1.0, o.timeOrder, ORDER_TOLERANCE, o.detection + " impact times");
            assertEquals(1.0, o.apexOrder, ORDER_TOLERANCE, o.detection + " apexes");
        }
        for (Detection detection : new Detection[] {Detection.OVERLAP, Detection.SWEPT}) {
            java.util.List<CollisionStudy.BounceError> line =
                    CollisionSection.errors(bounces, detection);
            assertEquals(CollisionStudy.bounceSteps().length, line.size());
            CollisionStudy.BounceError coarse = line.get(0);
            CollisionStudy.BounceError fine = line.get(line.size() - 1);
            // 128 times smaller h: first order means about 128 times smaller errors; at least 50
            assertTrue(fine.worstApexError < coarse.worstApexError / 50,
                    detection + ": " + fine.worstApexError + " against " + coarse.worstApexError);
            assertTrue(fine.worstTimeError < coarse.worstTimeError / 50,
                    detection + ": " + fine.worstTimeError + " against " + coarse.worstTimeError);
        }
    }

    @Test
    void firstImpactOfTheSweptBallIsHalfAStepEarly() {
        // the stepped fall lies on the parabola launched at −g·h/2: impact at t0 − h/2
        double t0 = Math.sqrt(2.0 * CollisionStudy.BOUNCE_HEIGHT_METRES / Gravity.STANDARD_G);
        for (CollisionStudy.Impact i : bounces.impacts) {
            if (i.detection == Detection.SWEPT && i.number == 1) {
                assertEquals(t0, i.idealTimeSeconds, 1e-12);
                // within the chord's sag g·h²/8 over the speed v0 (below h/100), and float
                // round-off: each of the t0/h steps rounds y (at most h0) within half an ulp,
                // which moves the impact by at most that over v0
                double v0 = Gravity.STANDARD_G * t0;
                double roundOff = (t0 / i.stepSeconds)
                        * Math.ulp(CollisionStudy.BOUNCE_HEIGHT_METRES) / 2 / v0;
                assertEquals(-i.stepSeconds / 2, i.timeError(), 0.01 * i.stepSeconds + roundOff,
                        "h = " + i.stepSeconds);
            }
        }
    }

    @Test
    void fittedOrderIsTheSlopeOfAPowerLaw() {
        double[] h = {0.1, 0.05, 0.025, 0.0125};
        double[] error = new double[h.length];
        for (int i = 0; i < h.length; ++i) {
            // a zigzag symmetric about the middle of the range leaves the slope at 1
            error[i] = 3.0 * h[i] * (i == 0 || i == h.length - 1 ? 2.0 : 0.5);
        }
        assertEquals(1.0, CollisionStudy.fittedOrder(h, error), 1e-12);
        for (int i = 0; i < h.length; ++i) {
            error[i] = 7.0 * h[i] * h[i];
        }
        assertEquals(2.0, CollisionStudy.fittedOrder(h, error), 1e-12);
    }

    private static int tunnelMisses(CollisionStudy.Tunnel t, String detection, int row) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = TunnelCommand.run(new String[] {"--speed", Float.toString(t.speed),
            "--radius", Float.toString(CollisionStudy.SHOT_RADIUS_METRES), "--thickness",
            Float.toString(CollisionStudy.WALL_THICKNESS_METRES), "--tpf",
            Float.toString(CollisionStudy.STEP_SECONDS), "--detection", detection,
            "--shots", Integer.toString(t.shots), "--seed",
            Integer.toString(CollisionStudy.SEED + row)},
                new PrintStream(out, true), new PrintStream(err, true));
        assertEquals(0, status, err.toString());
        String[] lines = out.toString(StandardCharsets.UTF_8).trim().split("\\R");
        assertEquals(TunnelCommand.HEADER, lines[0]);
        return Integer.parseInt(lines[1].split(",")[2]);
    }
}

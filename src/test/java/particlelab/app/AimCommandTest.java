package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class AimCommandTest {

    private static final double G = 9.8f;
    private static final double H = 1f / 60f;
    private static final double VX = 20.0;

    /** One parsed CSV row of {@code aim --csv}. */
    private static final class Row {
        final String method;
        final double vy;
        final double flightTime;
        final double landingX;
        final double miss;
        final int shots;

        Row(String line) {
            String[] cells = line.split(",");
            assertEquals(7, cells.length, line);
            method = cells[0];
            vy = Double.parseDouble(cells[2]);
            flightTime = Double.parseDouble(cells[3]);
            landingX = Double.parseDouble(cells[4]);
            miss = Double.parseDouble(cells[5]);
            shots = Integer.parseInt(cells[6]);
        }
    }

    private static Row csv(String... args) {
        String[] full = new String[args.length + 2];
        full[0] = "aim";
        full[1] = "--csv";
        System.arraycopy(args, 0, full, 2, args.length);
        CommandRun run = CommandRun.of(full);
        assertEquals(0, run.code, run.toString());
        List<String> lines = run.outLines();
        assertEquals(2, lines.size(), run.toString());
        assertEquals("method,vx,vy,flight_time,landing_x,miss,shots", lines.get(0));
        return new Row(lines.get(1));
    }

    /** N·ulp(S): the float round-off of N steps of position (see LevelAimTest). */
    private static double roundOff(double distance) {
        return distance / (VX * H) * Math.ulp((float) distance);
    }

    /**
     * The lecture's vy lands vx·h short of S, and a little more: the crossing is read off the
     * chord between two samples, which moves it short by at most g·h²·vx/(8·vy'), with
     * vy' = vy − g·h/2 the slope of the samples' parabola (LevelAimTest explains).
     */
    @Test
    void lectureLandsVxHShort() {
        // The command reads S as a float: 97.3 becomes 97.30000305.
        for (double distance : new double[] {100.0, 97.3f}) {
            Row row = csv("--distance", String.valueOf((float) distance), "--vx", "20");
            assertEquals("lecture", row.method);
            assertEquals(1, row.shots);
            double vySamples = row.vy - G * H / 2.0;
            double sag = G * H * H * VX / (8.0 * vySamples);
            assertTrue(row.miss <= -VX * H + roundOff(distance)
                    && row.miss >= -VX * H - sag - roundOff(distance), "miss " + row.miss);
            assertEquals(row.landingX - distance, row.miss, 1e-12);
        }
    }

    /**
     * Issue 17: each of these command lines once said "out of reach ... the reach peaks at
     * about 0.0 m", because the first shot (vy = g·S/(2·vx) below g·h) lands at the gun,
     * while {@code trajectory} shows shots that reach S (vx = 50, vy = 0.2 lands at 1.07 m at
     * h = 1/60). Each must now hit within the default tolerance, 1 mm.
     */
    @Test
    void iterativeHitsShortTargetsWhoseFirstShotLandsAtTheGun() {
        String[][] lines = {{"--distance", "1.2"}, {"--distance", "1.5"},
            {"--distance", "7", "--tpf", "0.1"}, {"--distance", "30", "--tpf", "0.5"},
            {"--distance", "40", "--tpf", "0.5"}, {"--distance", "510", "--tpf", "10"},
            {"--distance", "600", "--tpf", "10"}};
        for (String[] line : lines) {
            String[] args = new String[line.length + 4];
            System.arraycopy(line, 0, args, 0, line.length);
            System.arraycopy(new String[] {"--vx", "50", "--method", "iterative"}, 0, args,
                    line.length, 4);
            Row row = csv(args);
            assertTrue(Math.abs(row.miss) <= 1e-3, String.join(" ", line) + ": " + row.miss);
        }
    }

    /**
     * The discrete correction lands at S up to the float round-off of the stepped position,
     * about N·ulp(S) for N = S/(vx·h) steps (measured 1.3e-4 m at S = 100, bound 2.3e-3 m).
     */
    @Test
    void discreteLandsAtSToRoundOff() {
        for (double distance : new double[] {100.0, 97.3f}) {
            Row row = csv("--distance", String.valueOf((float) distance), "--vx", "20", "--method",
                    "discrete");
            assertEquals("discrete", row.method);
            assertEquals(0.0, row.miss, roundOff(distance), "miss at S = " + distance);
        }
    }

    /**
     * The flight time of a closed form is the stepped shot's interpolated crossing, as the
     * help says: with no drag x moves at vx exactly, so landing_x = vx·flight_time up to the
     * float round-off of x.
     */
    @Test
    void closedFormFlightTimeIsTheSteppedShots() {
        Row row = csv("--distance", "100", "--vx", "20");
        assertEquals(row.landingX / VX, row.flightTime, roundOff(100.0) / VX);
        assertTrue(row.flightTime < 100.0 / VX, "shorter than the formula's S/vx");
    }

    @Test
    void iterativeHitsWithinToleranceWithLinearAndQuadraticDrag() {
        Row linear = csv("--distance", "100", "--vx", "20", "--method", "iterative",
                "--linear-drag", "0.1", "--tolerance", "0.001");
        assertEquals("iterative", linear.method);
        assertTrue(Math.abs(linear.miss) <= 0.001, "miss " + linear.miss);
        assertTrue(linear.shots >= 2 && linear.shots <= 12, "shots " + linear.shots);
        Row quadratic = csv("--distance", "50", "--vx", "20", "--method", "iterative",
                "--quadratic-drag", "0.01", "--tolerance", "0.01", "--mass", "2");
        assertTrue(Math.abs(quadratic.miss) <= 0.01, "miss " + quadratic.miss);
        assertTrue(quadratic.shots <= 12, "shots " + quadratic.shots);
    }

    @Test
    void closedFormWithDragStillFliesWithDragAndShowsTheMiss() {
        Row row = csv("--distance", "100", "--vx", "20", "--linear-drag", "0.1");
        assertTrue(row.miss < -10.0, "drag makes the lecture's shot fall far short: " + row.miss);
        CommandRun text = CommandRun.of("aim", "--distance", "100", "--vx", "20",
                "--linear-drag", "0.1");
        assertTrue(text.out.contains("ignores drag"), text.out);
    }

    @Test
    void linearDragTargetAtOrBeyondVxMOverBIsOutOfReach() {
        for (String method : new String[] {"lecture", "iterative"}) {
            // vx·m/b = 20·1/0.1 = 200 m.
            CommandRun run = CommandRun.of("aim", "--distance", "200", "--vx", "20",
                    "--linear-drag", "0.1", "--method", method);
            assertEquals(2, run.code);
            assertEquals("", run.out);
            assertEquals(List.of("particle-lab aim: --distance: the target at S=200.0 m is out"
                    + " of reach at vx=20.0 m/s with linear drag b=0.1 and mass m=1.0: no launch"
                    + " passes vx*m/b = 200.0 m"), run.errLines());
        }
    }

    @Test
    void iterativeReportsATargetBeyondThePeakReachAsOutOfReach() {
        CommandRun run = CommandRun.of("aim", "--distance", "100", "--vx", "20", "--method",
                "iterative", "--quadratic-drag", "0.01");
        assertEquals(2, run.code);
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.startsWith("particle-lab aim: --distance: target at S=100.0 m is out"
                + " of reach at vx=20.0 m/s: the reach peaks at about 67.2"), run.err);
    }

    @Test
    void readableOutputNamesMethodVyFlightLandingMissAndShots() {
        CommandRun run = CommandRun.of("aim", "--distance", "100", "--vx", "20");
        assertEquals(0, run.code);
        String[] labels = {"method:", "launch:", "flight time:", "predicted landing:", "miss:",
                "shots simulated:"};
        List<String> lines = run.outLines();
        for (int i = 0; i < labels.length; ++i) {
            assertTrue(lines.get(i).startsWith(labels[i]), lines.get(i));
        }
        assertTrue(lines.get(1).contains("vy = 24.5 m/s"), lines.get(1));
        assertTrue(lines.get(4).endsWith("(short)"), lines.get(4));
        // What a person reads: 4 decimals (the CSV keeps every digit). The stepped shot's
        // landing 99.66678946... m and miss -0.33321053... m.
        assertEquals("flight time:       4.9833 s (stepped shot); formula S/vx = 5 s",
                lines.get(2));
        assertEquals("predicted landing: 99.6668 m (target S = 100 m)", lines.get(3));
        assertEquals("miss:              -0.3332 m (short)", lines.get(4));
    }

    @Test
    void readableNumbersHaveFourDecimalsOrThreeSignificantDigits() {
        assertEquals("24.5", AimCommand.readable(24.5));
        assertEquals("5", AimCommand.readable(5.0));
        assertEquals("-0.3332", AimCommand.readable(-0.3332105352385639));
        assertEquals("0.000127", AimCommand.readable(1.2658293799461262E-4));
        assertEquals("2.50e+38", AimCommand.readable(2.4999999E38));
        assertEquals("0", AimCommand.readable(-0.0));
    }

    @Test
    void helpStatesTheSameLimitsAsTrajectoryAndTheWarning() {
        CommandRun run = CommandRun.of("aim", "--help");
        String help = run.out.replaceAll("\\s+", " ");
        assertTrue(help.contains(CommandSupport.STABILITY_NOTE), help);
    }
}

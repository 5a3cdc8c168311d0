package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.aiming.Hitscan;

/**
 * {@code aim --strategy/--seed/--shots-csv/--predict-tpf} and {@code hitscan}, through the
 * real entry point.
 */
class AimingCommandsTest {

    private static final double G = 9.8;
    private static final double H = 1f / 60f;
    private static final double TOLERANCE = 0.001;
    private static final String[] STRATEGIES = {"lecture", "bisection", "secant", "believable"};

    private static List<String> run(String... args) {
        CommandRun run = CommandRun.of(args);
        assertEquals(0, run.code, run.toString());
        assertEquals("", run.err, run.toString());
        return run.outLines();
    }

    private static String[] concat(String[] first, String... second) {
        String[] all = new String[first.length + second.length];
        System.arraycopy(first, 0, all, 0, first.length);
        System.arraycopy(second, 0, all, first.length, second.length);
        return all;
    }

    /**
     * One row per shot under the exact header; shots numbered from 1; miss = landing_x − S;
     * only the last shot within the tolerance; and the same last shot as {@code --csv}'s
     * summary row, shot count included.
     */
    @Test
    void shotsCsvPrintsEveryShotOfEveryStrategyWithBothDrags() {
        for (String strategy : STRATEGIES) {
            for (String[] drag : new String[][] {{"--distance", "100", "--linear-drag", "0.1"},
                    {"--distance", "50", "--quadratic-drag", "0.01"}}) {
                String[] base = concat(new String[] {"aim", "--vx", "20", "--method",
                    "iterative", "--strategy", strategy}, drag);
                List<String> lines = run(concat(base, "--shots-csv"));
                assertEquals("shot,vy,landing_x,miss", lines.get(0));
                double distance = Double.parseDouble(drag[1]);
                for (int i = 1; i < lines.size(); ++i) {
                    String[] cells = lines.get(i).split(",");
                    assertEquals(4, cells.length, lines.get(i));
                    assertEquals(i, Integer.parseInt(cells[0]));
                    double miss = Double.parseDouble(cells[3]);
                    assertEquals(Double.parseDouble(cells[2]) - distance, miss, 1e-9);
                    assertEquals(i == lines.size() - 1, Math.abs(miss) <= TOLERANCE,
                            strategy + " " + lines.get(i));
                }
                String[] summary = run(concat(base, "--csv")).get(1).split(",");
                String[] last = lines.get(lines.size() - 1).split(",");
                assertEquals(summary[2], last[1], "vy");
                assertEquals(summary[4], last[2], "landing_x");
                assertEquals(Integer.parseInt(summary[6]), lines.size() - 1, "shots");
            }
        }
    }

    @Test
    void everyStrategyReportsOutOfReachAsOneLineAndExitTwo() {
        for (String strategy : STRATEGIES) {
            CommandRun run = CommandRun.of("aim", "--distance", "100", "--vx", "20",
                    "--method", "iterative", "--quadratic-drag", "0.01", "--strategy", strategy,
                    "--shots-csv");
            assertEquals(2, run.code, run.toString());
            assertEquals("", run.out, run.toString());
            assertEquals(1, run.errLines().size(), run.toString());
            assertTrue(run.err.contains("--distance: target at S=100.0 m is out of reach"),
                    run.toString());
        }
    }

    @Test
    void believableSeedIsReproducibleAndTheFirstShotMisses() {
        String[] args = {"aim", "--distance", "100", "--vx", "20", "--method", "iterative",
            "--linear-drag", "0.1", "--strategy", "believable", "--shots-csv", "--seed"};
        List<String> three = run(concat(args, "3"));
        assertEquals(three, run(concat(args, "3")));
        assertFalse(three.equals(run(concat(args, "4"))));
        String[] noSeed = new String[args.length - 1];
        System.arraycopy(args, 0, noSeed, 0, noSeed.length);
        assertEquals(run(concat(args, "1")), run(noSeed), "the default seed is 1");
        assertTrue(Math.abs(Double.parseDouble(three.get(1).split(",")[3])) > TOLERANCE);
    }

    /**
     * Predicting at 1/30 s a shot flown at 1/60 s lands long by about vx·(1/30 − 1/60) =
     * 0.333 m (drag-free; the bound, tolerance plus the chord sag of both steps, is derived in
     * aiming.PredictorMismatchTest). The last shots-csv row is the flown shot; the text says
     * the expected miss.
     */
    @Test
    void predictTpfMissesByAboutVxTimesTheStepDifference() {
        double expected = 20.0 * (1f / 30f - H);
        double bound = TOLERANCE + 1.7 * G / 8.0 * (1.0 / 900.0 + H * H);
        for (String method : new String[] {"iterative", "discrete"}) {
            String[] row = run("aim", "--distance", "100", "--vx", "20", "--method", method,
                    "--predict-tpf", "1/30", "--csv").get(1).split(",");
            assertEquals(expected, Double.parseDouble(row[5]), bound, method);
        }
        List<String> shots = run("aim", "--distance", "100", "--vx", "20", "--method",
                "iterative", "--predict-tpf", "1/30", "--shots-csv");
        String[] predicted = shots.get(shots.size() - 2).split(",");
        String[] flown = shots.get(shots.size() - 1).split(",");
        assertEquals(predicted[1], flown[1], "the same vy, flown at another step");
        assertTrue(Math.abs(Double.parseDouble(predicted[3])) <= TOLERANCE);
        assertEquals(expected, Double.parseDouble(flown[3]), bound);
        String text = String.join("\n", run("aim", "--distance", "100", "--vx", "20",
                "--method", "iterative", "--predict-tpf", "1/30"));
        assertTrue(text.contains("expected miss about vx*(h_predict - h) = 0.3333 m"), text);
    }

    /**
     * The hitscan row: the formula's drop exactly (the typed decimals), the stepped drop as
     * the SIE's closed form {@code ½g·h²(n+1)(n+2f)} to float round-off (2·N·(ulp(drop) +
     * ulp(d)), see aiming.HitscanTest), the flight time d/v, and whether the stepped drop is
     * within the radius.
     */
    @Test
    void hitscanRowMatchesTheFormulaAndTheSteppedClosedForm() {
        double[][] cases = {{100, 900, 0.5}, {100, 35, 0.5}, {100, 300, 0.25}, {287, 900, 0.5}};
        for (double[] c : cases) {
            List<String> lines = run("hitscan", "--distance", String.valueOf(c[0]), "--speed",
                    String.valueOf(c[1]), "--target-radius", String.valueOf(c[2]));
            assertEquals(2, lines.size());
            assertEquals("speed,distance,flight_time,drop_formula,drop_stepped,projectile_hits",
                    lines.get(0));
            String[] row = lines.get(1).split(",");
            assertEquals(6, row.length);
            double stepped = Hitscan.steppedDrop(9.8f, c[0], c[1], H);
            double steps = Math.ceil(c[0] / (c[1] * H));
            double roundOff = 2.0 * steps * (Math.ulp((float) stepped) + Math.ulp((float) c[0]));

            assertEquals(c[1], Double.parseDouble(row[0]), 0.0);
            assertEquals(c[0], Double.parseDouble(row[1]), 0.0);
            assertEquals(c[0] / c[1], Double.parseDouble(row[2]), roundOff / c[1] + 1e-9);
            assertEquals(0.5 * G * (c[0] / c[1]) * (c[0] / c[1]), Double.parseDouble(row[3]),
                    1e-12 * Double.parseDouble(row[3]));
            double drop = Double.parseDouble(row[4]);
            assertEquals(stepped, drop, roundOff, lines.get(1));
            assertEquals(String.valueOf(drop <= c[2]), row[5]);
        }
        // 900 m/s, r = 0.5 m: the cheat is good to 900*sqrt(1/9.8) = 287.5 m by the formula,
        // but the stepped projectile falls a half step more: it misses at 287 m.
        assertEquals("false", run("hitscan", "--distance", "287", "--speed", "900").get(1)
                .split(",")[5]);
        assertEquals("true", run("hitscan", "--distance", "250", "--speed", "900").get(1)
                .split(",")[5]);
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "--strategy   | aim --distance 100 --vx 20 --method iterative --strategy magic",
        "--strategy   | aim --distance 100 --vx 20 --strategy secant",
        "--seed       | aim --distance 100 --vx 20 --method iterative --seed 3",
        "--seed       | aim --distance 100 --vx 20 --method iterative --strategy believable"
                + " --seed -1",
        "--seed       | aim --distance 100 --vx 20 --method iterative --strategy believable"
                + " --seed 1.5",
        "--shots-csv  | aim --distance 100 --vx 20 --shots-csv",
        "--shots-csv  | aim --distance 100 --vx 20 --method iterative --csv --shots-csv",
        "--predict-tpf| aim --distance 100 --vx 20 --predict-tpf 1/30",
        "--predict-tpf| aim --distance 100 --vx 20 --method iterative --predict-tpf 0",
        "--predict-tpf| aim --distance 100 --vx 20 --method iterative --predict-tpf 1e-9",
        "--predict-tpf| aim --distance 100 --vx 20 --method iterative --predict-tpf 3e38",
        "--tolerance  | aim --distance 100 --vx 20 --method iterative --strategy believable"
                + " --tolerance 100",
        "--distance   | hitscan --speed 900",
        "--speed      | hitscan --distance 100",
        "--speed      | hitscan --distance 100 --speed -1",
        "--g          | hitscan --distance 100 --speed 900 --g 0",
        "--target-radius| hitscan --distance 100 --speed 900 --target-radius NaN",
        "--tpf        | hitscan --distance 100 --speed 900 --tpf 0",
        "--tpf        | hitscan --distance 1e30 --speed 1e-30",
        "--tpf        | hitscan --distance 3e38 --speed 1 --tpf 3e38",
        "--vx         | hitscan --distance 100 --vx 20",
    })
    void badCommandLineIsOneLineNamingTheProblemAndExitTwo(String line) {
        String[] parts = line.split("\\|");
        CommandRun run = CommandRun.of(parts[1].trim().split(" +"));
        assertEquals(2, run.code, run.toString());
        assertEquals("", run.out, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains(parts[0].trim()), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertTrue(run.err.startsWith("particle-lab"), run.toString());
    }

    @Test
    void helpStatesTheNewOptionsAndDefaults() {
        String aim = CommandRun.of("aim", "--help").out.replaceAll("\\s+", " ");
        for (String fact : new String[] {"--strategy NAME", "Default illinois", "--seed N",
                "Default 1.", "--shots-csv", "shot,vy,landing_x,miss", "--predict-tpf H",
                "30-170%"}) {
            assertTrue(aim.contains(fact), fact + " in\n" + aim);
        }
        CommandRun hitscan = CommandRun.of("help", "hitscan");
        assertEquals(0, hitscan.code);
        String words = hitscan.out.replaceAll("\\s+", " ");
        for (String fact : new String[] {"Default 0.5.", "Default 9.8.", "Default 1/60.",
                "d < v*sqrt(2r/g)", "speed,distance,flight_time,drop_formula,drop_stepped,"
                        + "projectile_hits"}) {
            assertTrue(words.contains(fact), fact + " in\n" + hitscan.out);
        }
        for (String line : hitscan.out.split("\\R")) {
            assertTrue(line.length() <= 80, line);
        }
        assertTrue(CommandRun.of("--help").out.contains("\n  hitscan "));
    }
}

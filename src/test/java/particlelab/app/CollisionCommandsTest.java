package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code bounce}, {@code collide} and {@code tunnel} through the real entry point. */
class CollisionCommandsTest {

    private static final float G = 9.8f;
    private static final float H = 1f / 60f;

    private static CommandRun ok(String... args) {
        CommandRun run = CommandRun.of(args);
        assertEquals(0, run.code, run.toString());
        assertEquals("", run.err, run.toString());
        return run;
    }

    private static String[] cells(String line) {
        return line.split(",", -1);
    }

    @Test
    void bounceRowsFollowTheIdealSequenceAndStopOnceTheBallRests() {
        // h0 = 1 m, e = 0.5, resting fix on: the ball rests within t0·(1+e)/(1-e) = 1.4 s
        // (plus a few steps), so 10 s end with a last row of rebound 0 and nothing after.
        List<String> lines = ok("bounce", "--height", "1", "--restitution", "0.5").outLines();
        assertEquals(BounceCommand.HEADER, lines.get(0));
        assertEquals("impact,t,impact_speed,rebound_speed,apex_after", lines.get(0));
        int rows = lines.size() - 1;
        assertTrue(rows >= 3 && rows < 20, lines.toString());
        double t0 = Math.sqrt(2.0 / G);
        String[] first = cells(lines.get(1));
        assertEquals("1", first[0]);
        // Impact at t0 - h/2 to within g·h²/(4·v0) (BounceTest derives it).
        assertEquals(t0 - H / 2.0, Float.parseFloat(first[1]), 1e-4);
        float speed = Float.parseFloat(first[2]);
        assertEquals(Math.sqrt(2.0 * G), speed, G * H);
        // The resting fix takes e·g·h off the rebound: e·(v - g·h).
        assertEquals(0.5f * (speed - G * H), Float.parseFloat(first[3]), 1e-5f);
        // Apex after the first impact: e²·h0 = 0.25 m within (k+1)·v·h (BounceTest).
        assertEquals(0.25, Float.parseFloat(first[4]), 2.0 * 0.5 * speed * H);
        double previous = 0.0;
        for (int i = 1; i <= rows; ++i) {
            String[] row = cells(lines.get(i));
            assertEquals(String.valueOf(i), row[0]);
            double t = Double.parseDouble(row[1]);
            assertTrue(t > previous, "time order");
            previous = t;
            assertEquals(i == rows, row[4].isEmpty(), "apex empty only for the last");
        }
        assertEquals("0.0", cells(lines.get(rows))[3], "the last impact leaves it at rest");
        assertTrue(previous < t0 * 3.0 + 0.5, "rests near T = t0(1+e)/(1-e): " + previous);
    }

    @Test
    void bounceThresholdMakesTheSlowImpactPerfectlyInelastic() {
        // h0 = 2 m, e = 0.5, no resting fix, threshold 1 m/s: ideal speeds 6.26, 3.13, 1.57,
        // 0.78 m/s; the fourth is the last row, with rebound 0; rebounds before are e·v.
        List<String> lines = ok("bounce", "--height", "2", "--restitution", "0.5",
                "--threshold", "1", "--resting-fix", "off", "--tpf", "1/240").outLines();
        assertEquals(5, lines.size(), lines.toString());
        for (int i = 1; i <= 3; ++i) {
            String[] row = cells(lines.get(i));
            float speed = Float.parseFloat(row[2]);
            assertTrue(speed > 1f);
            assertEquals(0.5f * speed, Float.parseFloat(row[3]), 1e-6f * speed);
        }
        String[] last = cells(lines.get(4));
        assertTrue(Float.parseFloat(last[2]) <= 1f);
        assertEquals("0.0", last[3]);
    }

    @ParameterizedTest
    @ValueSource(strings = {"overlap", "swept"})
    void bounceWithNeitherCureNeverRests(String detection) {
        // Every step closes at g·h and bounces back e·g·h: rows until the duration ends.
        List<String> lines = ok("bounce", "--height", "0.5", "--restitution", "0.5",
                "--resting-fix", "off", "--detection", detection, "--duration", "5").outLines();
        assertTrue(lines.size() > 100, lines.size() + " rows");
    }

    @Test
    void bounceRadiusRaisesTheTouchingHeight() {
        // Centre from 1.2 m, r = 0.2: it falls 1 m, as from 1 m with a point.
        String withRadius = cells(ok("bounce", "--height", "1.2", "--radius", "0.2",
                "--restitution", "0.5").outLines().get(1))[2];
        String point = cells(ok("bounce", "--height", "1", "--restitution", "0.5")
                .outLines().get(1))[2];
        assertEquals(Float.parseFloat(point), Float.parseFloat(withRadius), G * H);
    }

    @ParameterizedTest
    @ValueSource(strings = {"overlap", "swept"})
    void collideWorkedExample(String detection) {
        // m = 2 and 1 kg, 3 and -1 m/s, e = 0.5: 1 and 3 m/s, momentum 5, KE 9.5 -> 5.5 J.
        List<String> lines = ok("collide", "--m1", "2", "--m2", "1", "--p1", "0,0,0", "--p2",
                "1,0,0", "--v1", "3,0,0", "--v2", "-1,0,0", "--r1", "0.25", "--r2", "0.25",
                "--restitution", "0.5", "--detection", detection).outLines();
        assertEquals(2, lines.size());
        assertEquals("t_impact,v1x,v1y,v1z,v2x,v2y,v2z,px_before,py_before,pz_before,"
                + "px_after,py_after,pz_after,ke_before,ke_after", lines.get(0));
        String[] row = cells(lines.get(1));
        assertEquals(15, row.length);
        double[] expected = {Double.NaN, 1, 0, 0, 3, 0, 0, 5, 0, 0, 5, 0, 0, 9.5, 5.5};
        for (int i = 1; i < 15; ++i) {
            // Float velocities: a few ulp of 3 m/s; sums of them likewise.
            assertEquals(expected[i], Double.parseDouble(row[i]), 1e-5, "column " + i);
        }
        // Touch after closing 0.5 m at 4 m/s: 0.125 s swept; the overlap test sees it at the
        // end of the step that contains it.
        double t = Double.parseDouble(row[0]);
        if ("swept".equals(detection)) {
            assertEquals(0.125, t, 1e-6);
        } else {
            assertEquals(Math.ceil(0.125 / H) * H, t, 1e-6);
        }
    }

    @Test
    void collideGlancingElasticEqualMassesLeaveAtRightAngles() {
        List<String> lines = ok("collide", "--m1", "1", "--m2", "1", "--p1", "0,0,0", "--p2",
                "3,0.5,0", "--v1", "6,0,0", "--v2", "0,0,0", "--r1", "0.5", "--r2", "0.5",
                "--restitution", "1").outLines();
        String[] row = cells(lines.get(1));
        double dot = 0.0;
        for (int i = 1; i <= 3; ++i) {
            dot += Double.parseDouble(row[i]) * Double.parseDouble(row[i + 3]);
        }
        assertEquals(0.0, dot, 1e-5);
        assertEquals(Double.parseDouble(row[13]), Double.parseDouble(row[14]), 1e-5, "e = 1");
    }

    @Test
    void collideReportsSpheresThatNeverMeetAndOverlapTestsThatStepPast() {
        CommandRun never = CommandRun.of("collide", "--m1", "1", "--m2", "1", "--p1", "0,0,0",
                "--p2", "3,2,0", "--v1", "1,0,0", "--v2", "0,0,0", "--r1", "0.5", "--r2", "0.5",
                "--restitution", "1");
        assertEquals(2, never.code, never.toString());
        assertEquals(1, never.errLines().size());
        assertTrue(never.err.contains("never meet"), never.err);
        // 600 m/s against each other, 0.2 m reach, h = 1/60: 20 m a step, far past.
        CommandRun tunnelled = CommandRun.of("collide", "--m1", "1", "--m2", "1", "--p1",
                "0,0,0", "--p2", "5.1,0,0", "--v1", "300,0,0", "--v2", "-300,0,0", "--r1",
                "0.1", "--r2", "0.1", "--restitution", "1", "--detection", "overlap");
        assertEquals(2, tunnelled.code, tunnelled.toString());
        assertTrue(tunnelled.err.contains("tunnelling"), tunnelled.err);
        ok("collide", "--m1", "1", "--m2", "1", "--p1", "0,0,0", "--p2", "5.1,0,0", "--v1",
                "300,0,0", "--v2", "-300,0,0", "--r1", "0.1", "--r2", "0.1", "--restitution",
                "1");
    }

    @Test
    void tunnelSweptNeverMissesAndOverlapMissesAsPredicted() {
        List<String> swept = ok("tunnel", "--speed", "100", "--radius", "0.1", "--thickness",
                "0.2", "--detection", "swept", "--shots", "2000").outLines();
        assertEquals("shots,hits,misses,predicted_miss_probability", swept.get(0));
        assertEquals("2000,2000,0,0.0", swept.get(1));
        String[] overlap = cells(ok("tunnel", "--speed", "100", "--radius", "0.1",
                "--thickness", "0.2", "--detection", "overlap", "--shots", "2000", "--seed",
                "5").outLines().get(1));
        // p = 1 - 0.4/(100/60) = 0.76; binomial σ = √(2000·0.76·0.24) = 19; 4σ allowed.
        double p = Double.parseDouble(overlap[3]);
        assertEquals(0.76, p, 1e-6);
        int misses = Integer.parseInt(overlap[2]);
        assertEquals(2000 * p, misses, 4.0 * Math.sqrt(2000 * p * (1.0 - p)));
        assertEquals(2000, misses + Integer.parseInt(overlap[1]));
        // Same seed, same phases, same counts.
        assertEquals(String.join(",", overlap), ok("tunnel", "--speed", "100", "--radius",
                "0.1", "--thickness", "0.2", "--detection", "overlap", "--shots", "2000",
                "--seed", "5").outLines().get(1));
    }

    @ParameterizedTest(name = "{1}")
    @CsvSource(delimiter = '|', value = {
        "--restitution | bounce --height 1 --restitution 1.5",
        "--restitution | bounce --height 1 --restitution -0.1",
        "--restitution | bounce --height 1 --restitution NaN",
        "--restitution | bounce --height 1",
        "--height      | bounce --restitution 0.5",
        "--height      | bounce --height 0.1 --radius 0.2 --restitution 0.5",
        "--radius      | bounce --height 1 --radius -1 --restitution 0.5",
        "--threshold   | bounce --height 1 --restitution 0.5 --threshold -1",
        "--resting-fix | bounce --height 1 --restitution 0.5 --resting-fix maybe",
        "--detection   | bounce --height 1 --restitution 0.5 --detection psychic",
        "--g           | bounce --height 1 --restitution 0.5 --g 0",
        "--tpf         | bounce --height 1 --restitution 0.5 --tpf Infinity",
        "--duration    | bounce --height 1 --restitution 0.5 --duration 1e9",
        "--m1          | collide --m1 0 --m2 1 --p1 0,0,0 --p2 3,0,0 --v1 1,0,0 --v2 0,0,0"
            + " --r1 1 --r2 1 --restitution 1",
        "--m2          | collide --m1 1 --m2 -2 --p1 0,0,0 --p2 3,0,0 --v1 1,0,0 --v2 0,0,0"
            + " --r1 1 --r2 1 --restitution 1",
        "--r1          | collide --m1 1 --m2 1 --p1 0,0,0 --p2 3,0,0 --v1 1,0,0 --v2 0,0,0"
            + " --r1 0 --r2 1 --restitution 1",
        "--p1          | collide --m1 1 --m2 1 --p1 0,0,0 --p2 1,0,0 --v1 1,0,0 --v2 0,0,0"
            + " --r1 1 --r2 1 --restitution 1",
        "--v2          | collide --m1 1 --m2 1 --p1 0,0,0 --p2 3,0,0 --v1 1,0,0 --v2 0,NaN,0"
            + " --r1 1 --r2 1 --restitution 1",
        "--v1          | collide --m1 1 --m2 1 --p1 0,0,0 --p2 3,0,0 --r1 1 --r2 1"
            + " --restitution 1",
        "--restitution | collide --m1 1 --m2 1 --p1 0,0,0 --p2 3,0,0 --v1 1,0,0 --v2 0,0,0"
            + " --r1 1 --r2 1 --restitution 2",
        "--thickness   | tunnel --speed 100 --radius 0.1 --thickness 0 --detection swept"
            + " --shots 10",
        "--radius      | tunnel --speed 100 --radius -0.1 --thickness 0.2 --detection swept"
            + " --shots 10",
        "--speed       | tunnel --speed NaN --radius 0.1 --thickness 0.2 --detection swept"
            + " --shots 10",
        "--detection   | tunnel --speed 100 --radius 0.1 --thickness 0.2 --shots 10",
        "--shots       | tunnel --speed 100 --radius 0.1 --thickness 0.2 --detection swept",
        "--shots       | tunnel --speed 100 --radius 0.1 --thickness 0.2 --detection swept"
            + " --shots 0",
        "--seed        | tunnel --speed 100 --radius 0.1 --thickness 0.2 --detection swept"
            + " --shots 1 --seed x",
    })
    void badCommandLineIsOneLineNamingTheProblemAndExitTwo(String named, String commandLine) {
        CommandRun run = CommandRun.of(commandLine.trim().split(" +"));
        assertEquals(2, run.code, run.toString());
        assertEquals("", run.out, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains(named.trim()), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertTrue(run.err.startsWith("particle-lab "), run.toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"bounce", "collide", "tunnel"})
    void helpListsEveryOptionAndFitsEightyColumns(String command) {
        CommandRun run = ok(command, "--help");
        Options declared = "bounce".equals(command) ? BounceCommand.options()
                : "collide".equals(command) ? CollideCommand.options() : TunnelCommand.options();
        for (String option : declared.names()) {
            assertTrue(run.out.contains("\n  " + option + " ")
                    || run.out.contains("\n  " + option + "\n"), option + " in\n" + run.out);
        }
        for (String line : run.out.split("\\R")) {
            assertTrue(line.length() <= 80, "fits 80 columns: " + line);
        }
        assertTrue(ok("--help").out.contains("\n  " + command + " "));
    }
}

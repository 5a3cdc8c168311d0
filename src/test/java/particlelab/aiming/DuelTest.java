package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import particlelab.app.AimCommand;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;

/**
 * Issue 34 §3, a human against the believable player, without a window: a scripted human
 * round checked shot by shot against the lecture's step in closed form, the computer's shots
 * against what {@code aim --strategy believable --seed N} prints, and the log's fixed header.
 * The scene is the iterate demo's: S = 60 m, vx = 20 m/s, b/m = 0.1 /s, h = 1/60 s.
 */
class DuelTest {

    private static final double S = 60.0;
    private static final float VX = 20f;
    private static final float B = 0.1f;
    private static final float H = 1f / 60f;
    private static final double TOLERANCE = 0.25;
    private static final int MAX_SHOTS = 40;
    /**
     * A closed-form landing (exact arithmetic) against the float32 stepped one: about 220
     * steps at up to 60 m, each rounding by at most half an ulp (1.9e-6 m), stray by less
     * than 4.2e-4 m; 1e-3 m is still 250 times finer than a hit's 0.25 m.
     */
    private static final double ROUND_OFF_METRES = 1e-3;
    /** The scripted human: angle (deg) and speed (m/s) as the keys leave them, in order. */
    private static final float[][] SCRIPT = {{45f, 20f}, {45f, 30f}, {45f, 27f}, {45f, 27.4f}};
    /** When the human presses F for each shot (s of the round): after the last one landed. */
    private static final double[] PRESSED_AT = {0.5, 4.0, 9.0, 14.0};

    @Test
    void aScriptedHumanRoundIsCountedShotByShot() {
        Duel duel = newDuel();
        duel.startRound(1L);
        assertEquals(1, duel.getRound());
        assertFalse(duel.isRoundOver());
        assertThrows(IllegalStateException.class, () -> duel.closeRound(true),
                "no poll before the human hits");
        double worst = 0.0;
        for (int i = 0; i < SCRIPT.length; ++i) {
            int shot = duel.fire(SCRIPT[i][0], SCRIPT[i][1], PRESSED_AT[i]);
            assertEquals(i, shot);
            double miss = closedFormLanding(SCRIPT[i][0], SCRIPT[i][1]) - S;
            assertEquals(miss, duel.getHumanMiss(i), ROUND_OFF_METRES, "shot " + (i + 1));
            worst = Math.max(worst, Math.abs(miss));
            if (i == 0) {
                // Still in the air half a second later: F does nothing.
                assertEquals(-1, duel.fire(45f, 25f, PRESSED_AT[0] + 0.5));
                assertTrue(duel.isHumanInAir(PRESSED_AT[0] + 0.5));
            }
            assertFalse(duel.isHumanInAir(PRESSED_AT[i] + 5.0), "every shot lands within 5 s");
        }
        // 20 m/s lands 26 m short, 30 m/s 10 m long, 27 m/s 1.7 m short, 27.4 m/s within
        // 0.25 m: the fourth shot hits, far inside the tolerance (0.10 m off).
        assertTrue(Math.abs(duel.getHumanMiss(2)) > 1.0);
        assertTrue(Math.abs(duel.getHumanMiss(3)) < 0.5 * TOLERANCE);
        assertTrue(duel.hasHumanHit());
        assertTrue(duel.isRoundOver());
        assertEquals(-1, duel.fire(45f, 27.4f, 30.0), "no shot after the hit");
        double hitSeconds = duel.getHumanLandingSeconds(3);
        double flight = hitSeconds - PRESSED_AT[3];
        // The flight is about 3.7 s: the shot lands within the step after the crossing.
        assertTrue(flight > 3.5 && flight < 3.9, "flight " + flight);

        double[] row = duel.closeRound(false);
        ShotLog computer = duel.getComputerShots();
        double computerWorst = 0.0;
        double computerSeconds = 0.0;
        for (int i = 0; i < computer.size(); ++i) {
            computerWorst = Math.max(computerWorst, Math.abs(computer.getMiss(i)));
            computerSeconds += computer.getFlightSeconds(i);
        }
        assertArrayEquals(new double[] {1, 1, 4, 1, worst, hitSeconds, computer.size(),
            computerWorst, computerSeconds, 0}, row, ROUND_OFF_METRES);
        assertEquals(2, duel.getRound());
        assertEquals(1, duel.countClosedRounds());
        // The next round starts with no human shots and keeps the closed row.
        duel.startRound(2L);
        assertEquals(0, duel.countHumanShots());
        assertArrayEquals(row, duel.copyClosedRound(0));
    }

    /**
     * The believable player's shots in the duel are the aim command's for the same scene and
     * seed, shot by shot: vy as fired and the landing, to the printed digit.
     */
    @Test
    void theComputersShotsAreTheAimCommandsForTheSeed() {
        Duel duel = newDuel();
        for (int seed = 1; seed <= 5; ++seed) {
            duel.startRound(seed);
            ShotLog log = duel.getComputerShots();
            String[] lines = aimCommand(seed).split("\n");
            assertEquals(AimCommand.SHOTS_HEADER, lines[0]);
            assertEquals(lines.length - 1, log.size(), "seed " + seed);
            assertTrue(log.size() >= 2, "the believable player misses first");
            for (int i = 0; i < log.size(); ++i) {
                assertEquals((i + 1) + "," + log.getVerticalSpeed(i) + "," + log.getLandingX(i)
                        + "," + log.getMiss(i), lines[i + 1], "seed " + seed);
            }
            assertTrue(Math.abs(log.getMiss(0)) > TOLERANCE);
            assertTrue(Math.abs(log.getMiss(log.size() - 1)) <= TOLERANCE);
        }
    }

    /** The log's header is an interface: a spreadsheet's columns are read by name. */
    @Test
    void theLogHasItsFixedHeader() {
        assertEquals("round,seed,human_shots,human_hit,human_worst_miss_m,human_time_s,"
                + "computer_shots,computer_worst_miss_m,computer_time_s,felt_fair",
                Duel.CSV_HEADER);
    }

    @Test
    void aBadAimIsRefusedNamingTheValue() {
        Duel duel = newDuel();
        duel.startRound(1L);
        IllegalArgumentException angle = assertThrows(IllegalArgumentException.class,
                () -> duel.fire(90f, 20f, 0.0));
        assertTrue(angle.getMessage().contains("90.0"), angle.getMessage());
        assertThrows(IllegalArgumentException.class, () -> duel.fire(45f, Float.NaN, 0.0));
        assertThrows(IllegalArgumentException.class,
                () -> new Duel(simulator(), 9.8, S, VX, S, MAX_SHOTS));
    }

    private static Duel newDuel() {
        return new Duel(simulator(), Gravity.STANDARD_G, S, VX, TOLERANCE, MAX_SHOTS);
    }

    private static ShotSimulator simulator() {
        return new ShotSimulator(new ParticleIntegrator(new Gravity(), new LinearDrag(B)), 1f,
                H, 60f);
    }

    /** {@code aim ... --strategy believable --seed N --shots-csv} for the iterate scene. */
    private static String aimCommand(int seed) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = AimCommand.run(new String[] {"--distance", "60", "--vx", "20", "--method",
            "iterative", "--linear-drag", "0.1", "--tolerance", "0.25", "--strategy",
            "believable", "--seed", Integer.toString(seed), "--shots-csv"},
                new PrintStream(out, true), new PrintStream(err, true));
        assertEquals(0, code, err.toString(StandardCharsets.UTF_8));
        return out.toString(StandardCharsets.UTF_8).replace("\r", "");
    }

    /**
     * The lecture's step with linear drag in closed form (NUMERICS.md): with {@code r = 1 −
     * k·h}, {@code V_n = V* + (V0 − V*)·rⁿ} ({@code V*} = 0 across, {@code −g/k} down), and
     * {@code P_n = h·Σ V_i}; the landing interpolated between the last two samples.
     */
    private static double closedFormLanding(float angleDegrees, float speed) {
        double k = B;
        double h = H;
        double g = Gravity.STANDARD_G;
        double r = 1.0 - k * h;
        double vx0 = Duel.launchX(angleDegrees, speed);
        double vy0 = Duel.launchY(angleDegrees, speed);
        double terminal = -g / k;
        double previousX = 0.0;
        double previousY = 0.0;
        for (int n = 1; n < 100_000; ++n) {
            double sum = r * (1.0 - Math.pow(r, n)) / (1.0 - r);
            double x = h * vx0 * sum;
            double y = h * (n * terminal + (vy0 - terminal) * sum);
            if (y < 0.0) {
                return previousX + (x - previousX) * previousY / (previousY - y);
            }
            previousX = x;
            previousY = y;
        }
        throw new AssertionError("never landed");
    }
}

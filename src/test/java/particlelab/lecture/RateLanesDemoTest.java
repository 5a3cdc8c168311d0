package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.Allocations;
import particlelab.aiming.FrameJitter;
import particlelab.aiming.FrameRateRun;
import particlelab.aiming.FrameRateRunTest;
import particlelab.aiming.JitterHistogram;
import particlelab.app.Main;
import particlelab.app.TrajectoryCommand;
import particlelab.demo.DemoParticle;
import particlelab.demo.RateLanes;
import particlelab.demo.StateHash;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;

/**
 * The rate lanes ({@code --set rates=on}, issue 33 §1) in the gravitational-pull demo, stepped
 * in plain JUnit: off, the demo is what it was without them, bit for bit; on, each lane
 * flies its monitor's raw-tpf frames in step with the demo's time, lands where
 * {@code trajectory --tpf 1/f} lands, and the scene ends when all four have landed.
 */
class RateLanesDemoTest {

    private static final float H = 1f / 60f;
    private static final int FRAMES = 600;
    /**
     * Recorded on main at 1ef4ec7, before the rate lanes came back, with {@link #run}: the
     * hashes of the state after each of 600 frames of 1/60 s folded (fold·31 + hash), the
     * frame whose step ended the scene, the bodies and particles, the world's time at the
     * end and a ring entry's size (ints).
     */
    private static final long MAIN_STATE_FOLD = 0x1e96237f777fbe9bL;
    private static final int MAIN_SCENE_OVER_FRAME = 121;
    private static final int MAIN_BODIES = 3;
    private static final int MAIN_PARTICLES = 3;
    private static final double MAIN_END_SECONDS = 2.0333334393799305;
    private static final int MAIN_ENTRY_INTS = 281;
    /**
     * SHA-256 of {@code demo pull --frames 200 --export DIR}'s ball table at 1ef4ec7, the
     * energy table's header, and its parameters.csv's lines, which gain only the two new
     * parameters' rows.
     */
    private static final String MAIN_BALL_CSV =
            "1ebe83e81acbf6de47baeb1b1080236dea825cc2a025a9ad8eaa0bc2ac5a7ba8";
    private static final String MAIN_ENERGY_HEADER =
            "t,kinetic_J,potential_J,impact_loss_J,numerical_J";
    private static final String MAIN_PARAMETERS_CSV = "name,value,unit\nh,0.016666668,s\n"
            + "speed,14.142136,m/s\nangle,45.0,deg\nmass,1.0,kg\ng,9.8,m/s²\nfault,none,\n"
            + "seed,1.0,\nenergy,off,\nlane,off,\nlens,off,\n";

    /** The frame-rate section of docs/lecturing.md. */
    private static final String SECTION = "## The lecture's loop at your monitor's rate";

    @TempDir
    Path folder;

    @Test
    void lanesOffArePullAsItWasBitForBit() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        Run run = run(pull);
        assertEquals(MAIN_STATE_FOLD, run.fold, "every step's state hash");
        assertEquals(MAIN_SCENE_OVER_FRAME, run.sceneOverFrame, "the scene's end");
        assertEquals(MAIN_BODIES, pull.getWorld().countBodies());
        assertEquals(MAIN_PARTICLES, pull.getParticles().size());
        assertEquals(MAIN_END_SECONDS, pull.getWorld().getTimeSeconds(), 0.0);
        assertEquals(MAIN_ENTRY_INTS, run.entryInts, "a ring entry's size");
        assertFalse(pull.getRates().isOn());
        assertFalse(pull.getWindow().formatHud(new StringBuilder()).toString().contains("Raw tpf"));
        // lanes switched on and off again (at the next launch, as the panel does)
        GravitationalPullDemo toggled = new GravitationalPullDemo();
        toggled.getParameters().set(RateLanes.PARAMETER, 2f);
        toggled.getRun().advancePhysics(H);
        toggled.getParameters().set(RateLanes.PARAMETER, 0f);
        toggled.restart();
        assertEquals(MAIN_STATE_FOLD, run(toggled).fold, "after rates=uniform, then off");
    }

    @Test
    void lanesOffExportWhatPullExported() throws IOException {
        Path out = folder.resolve("pull");
        assertEquals(0, main("demo", "pull", "--frames", "200", "--export", out.toString()));
        assertEquals(MAIN_BALL_CSV, sha256(out.resolve("ball.csv")));
        // The energy ledger's table: its header and a row for each of the ball's steps. Not
        // its bytes: once in about ten runs of this class beside TourQuestionsTest on a
        // loaded machine its file came out longer than main's (SHA-256 d55570a5...) while the
        // ball's table was identical (rates=off: the lanes run no code); not reproduced in
        // eight runs since, and the CLI's export gives main's bytes.
        List<String> energy = Files.readAllLines(out.resolve("energy.csv"));
        List<String> ball = Files.readAllLines(out.resolve("ball.csv"));
        assertEquals(MAIN_ENERGY_HEADER, energy.get(0));
        assertEquals(ball.size(), energy.size(), "a ledger row per exported step");
        for (int row = 1; row < ball.size(); ++row) {
            assertEquals(Float.parseFloat(ball.get(row).split(",")[0]),
                    Float.parseFloat(energy.get(row).split(",")[0]), 0f, "t of row " + row);
        }
        assertEquals(MAIN_PARAMETERS_CSV + "rates,off,\njitter_ms,2.0,ms\n",
                Files.readString(out.resolve("parameters.csv")).replace("\r\n", "\n"));
        List<String> files = new ArrayList<>();
        try (Stream<Path> listed = Files.list(out)) {
            listed.sorted(Comparator.naturalOrder())
                    .forEach(file -> files.add(file.getFileName().toString()));
        }
        assertEquals(List.of("ball.csv", "energy.csv", "parameters.csv"), files);
    }

    @Test
    void eachLaneLandsWhereTrajectoryAtItsRateLands() {
        GravitationalPullDemo pull = lanesOn(1f);
        run(pull);
        RateLanes rates = pull.getRates();
        DemoParticle ball = pull.getParticles().get(0);
        Particle launch = new Particle(ball.copyLaunchPosition(new Vector3f()),
                ball.copyLaunchVelocity(new Vector3f()), ball.getParticle().getMass());
        for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
            float rate = RateLanes.RATES_HZ[i];
            float tpf = FrameRateRun.frameSeconds(rate);
            // the run flown alone, row by row, is trajectory --tpf 1/f byte for byte
            FrameRateRun alone = new FrameRateRun(ball.getIntegrator());
            alone.start(launch, rate, SimulationClock.Mode.RAW_TPF, H);
            StringBuilder csv = new StringBuilder(TrajectoryCommand.HEADER).append('\n');
            FrameRateRunTest.appendRow(csv, 0, tpf, alone.getParticle());
            while (!alone.hasLanded()) {
                alone.frame(tpf);
                FrameRateRunTest.appendRow(csv, alone.getSteps(), tpf, alone.getParticle());
            }
            assertEquals(FrameRateRunTest.trajectory("--v0", "10,10,0", "--g", "0,-9.8,0", "--tpf",
                    "1/" + (int) rate, "--until-ground"), csv.toString(), rate + " Hz");
            // and the lane in the demo took the same frames: the same bits
            FrameRateRun lane = rates.getRun(i);
            assertTrue(lane.hasLanded(), rate + " Hz landed");
            assertEquals(alone.getSteps(), lane.getSteps(), rate + " Hz frames");
            assertEquals(alone.getParticle().position, lane.getParticle().position);
            assertEquals(alone.getParticle().velocity, lane.getParticle().velocity);
            assertEquals(alone.getLanding().getX(), lane.getLanding().getX(), 0.0);
        }
        // the fixed step's run is the ball itself, to the float the world keeps its landing in
        assertEquals(ball.getLandingX(), rates.getFixedRun().getLanding().getX(),
                Math.ulp(ball.getLandingX()));
        // the vx·h law: lane i lands vx·(1/f_{i-1} − 1/f_i) beyond the slower lane; 1 mm is
        // far above float round-off of a 20 m landing (about 1e-5 m) and far below the
        // smallest gap (0.03 m, 144 to 240 Hz); the chord's sag inside the last step moves
        // each landing by at most g·h²/8·vx/|vy| (0.7 mm at 30 Hz), well within it
        double vx = launch.velocity.x;
        for (int i = 1; i < RateLanes.RATES_HZ.length; ++i) {
            double gap = vx * (1.0 / RateLanes.RATES_HZ[i - 1] - 1.0 / RateLanes.RATES_HZ[i]);
            assertEquals(gap, rates.getRun(i).getLanding().getX()
                    - rates.getRun(i - 1).getLanding().getX(), 1e-3, "lane " + i);
        }
        String hud = pull.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("Raw tpf lands (vs fixed):  30 Hz 20.07 m (-0.17)  60 Hz 20.24 m"
                + " (+0.00)  144 Hz 20.34 m (+0.10)  240 Hz 20.37 m (+0.13)\n"), hud);
        assertTrue(hud.contains("Fixed step h = 16.67 ms (the cure): 20.24 m at every rate,"
                + " bit for bit\n"), hud);
    }

    @Test
    void sceneEndsWhenEveryLaneHasLanded() {
        GravitationalPullDemo pull = lanesOn(1f);
        RateLanes rates = pull.getRates();
        int steps = 31;
        for (int frame = 0; frame < steps; ++frame) {
            pull.getRun().advancePhysics(H);
        }
        // after 31 steps of 1/60 s, a monitor at f Hz has shown floor(31·f/60) frames
        for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
            int expected = (int) Math.floor(steps * RateLanes.RATES_HZ[i] / 60.0 + 1e-9);
            assertEquals(expected, rates.getRun(i).getSteps(), RateLanes.RATES_HZ[i] + " Hz");
        }
        DemoParticle ball = pull.getParticles().get(0);
        int frame = steps;
        while (!ball.hasLanded()) {
            pull.getRun().advancePhysics(H);
            ++frame;
        }
        // the ball lands at the 122nd step (as without lanes), the 144 and 240 Hz lanes later
        // (their shorter steps land nearer the parabola's 2.04 s): the scene goes on for them
        assertEquals(MAIN_SCENE_OVER_FRAME + 1, frame);
        assertTrue(rates.isFlying());
        assertFalse(pull.getRun().isSceneOver());
        while (!pull.getRun().isSceneOver() && frame < FRAMES) {
            pull.getRun().advancePhysics(H);
            ++frame;
        }
        for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
            assertTrue(rates.getRun(i).hasLanded(), RateLanes.RATES_HZ[i] + " Hz landed");
        }
        assertFalse(rates.isFlying());
        // the 240 Hz lane lands at about 2.04 − 1/240 s, inside the demo's step to 2.05 s
        assertEquals(MAIN_SCENE_OVER_FRAME + 2, frame, "over one step after the ball");
        assertEquals(123L, pull.getWorld().getStepCount());
        // and a reset starts them again
        pull.restart();
        pull.getRun().advancePhysics(H);
        assertEquals(4, rates.getRun(3).getSteps(), "240 Hz: 4 frames in the first step");
    }

    @Test
    void histogramIsTheSameSeedsSimulatedAgain() {
        GravitationalPullDemo pull = lanesOn(3f);
        pull.getParameters().set(RateLanes.JITTER_WIDTH, 3f);
        pull.getRun().advancePhysics(H);
        RateLanes rates = pull.getRates();
        assertEquals(FrameJitter.Distribution.NORMAL, rates.getJitter());
        JitterHistogram histogram = rates.getHistogram();
        assertEquals(JitterHistogram.DEFAULT_RUNS, histogram.getRuns());
        // the same computation, written out: run i of seed 33 + i, normal, 3 ms, 60 Hz
        JitterHistogram again = new JitterHistogram(pull.getParticles().get(0).getIntegrator(),
                JitterHistogram.DEFAULT_RUNS);
        Particle launch = new Particle(new Vector3f(), new Vector3f(10f, 10f, 0f), 1f);
        again.compute(launch, 60f, FrameJitter.Distribution.NORMAL, 0.003f, RateLanes.SEED,
                JitterHistogram.DEFAULT_RUNS, H);
        for (int i = 0; i < JitterHistogram.DEFAULT_RUNS; ++i) {
            assertEquals(again.getLandingX(i), histogram.getLandingX(i), 0.0, "run " + i);
        }
        for (int bin = 0; bin < JitterHistogram.BINS; ++bin) {
            assertEquals(again.getCount(bin), histogram.getCount(bin), "bin " + bin);
        }
        // the fixed step's single bar is where every run of it lands: the ball's landing
        assertEquals(rates.getFixedRun().getLanding().getX(), histogram.getFixedX(), 0.0);
        String hud = pull.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("Jitter normal 3.0 ms at 60 Hz, 1000 runs land "), hud);
        assertTrue(hud.contains("   fixed step: all 1000 runs in one bar at "), hud);
    }

    /**
     * docs/lecturing.md's frame-rate section shows the lanes' HUD lines after 200 frames of
     * {@code demo pull --set rates=uniform}: they are these, as the demo writes them.
     */
    @Test
    void lecturingPageShowsTheLanesHudLinesAsPrinted() throws IOException {
        GravitationalPullDemo pull = lanesOn(2f);
        for (int frame = 0; frame < 200; ++frame) {
            pull.getRun().advancePhysics(H);
        }
        String hud = pull.getWindow().formatHud(new StringBuilder()).toString();
        // the lanes' four lines: landings, the fixed step, the histogram and its bar
        String[] shown = hud.substring(hud.indexOf("Raw tpf lands")).split("\n");
        String printed = String.join("\n", shown[0], shown[1], shown[2], shown[3]);
        List<String> page = Files.readAllLines(Path.of("docs/lecturing.md"));
        int heading = page.indexOf(SECTION);
        assertTrue(heading >= 0, "docs/lecturing.md has the section " + SECTION);
        int first = heading;
        while (!page.get(first).startsWith("Raw tpf lands")) {
            ++first;
        }
        int end = first;
        while (!page.get(end).equals("```")) {
            ++end;
        }
        assertEquals(printed, String.join("\n", page.subList(first, end)));
    }

    @Test
    void stepsAndFramesWithLanesAllocateNothing() {
        GravitationalPullDemo pull = lanesOn(2f);
        // the launch's step computes the histogram, in preallocated arrays; then a flight
        pull.getRun().advancePhysics(H);
        StringBuilder hud = new StringBuilder(4096);
        Allocations.assertAllocatesNothing("60 frames of pull with the rate lanes", () -> {
            for (int frame = 0; frame < 60; ++frame) {
                pull.getWindow().advance(H);
                hud.setLength(0);
                pull.getWindow().formatHud(hud);
            }
        });
        Allocations.assertAllocatesNothing("a reset and its launch's histogram", () -> {
            pull.restart();
            pull.getRun().advancePhysics(H);
        });
    }

    @Test
    void stepBackPutsTheLanesWhereTheyWere() {
        GravitationalPullDemo pull = lanesOn(1f);
        for (int frame = 0; frame < 60; ++frame) {
            pull.getRun().advancePhysics(H);
        }
        RateLanes rates = pull.getRates();
        Vector3f at240 = rates.getRun(3).getParticle().position.clone();
        long hash = StateHash.of(pull);
        for (int frame = 0; frame < 30; ++frame) {
            pull.getRun().advancePhysics(H);
        }
        for (int step = 0; step < 30; ++step) {
            assertTrue(pull.getReplayControls().stepBack());
        }
        assertEquals(hash, StateHash.of(pull));
        assertEquals(at240, rates.getRun(3).getParticle().position);
    }

    private static GravitationalPullDemo lanesOn(float mode) {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        pull.getParameters().set(RateLanes.PARAMETER, mode);
        return pull;
    }

    /** What a run of 600 frames of 1/60 s gives: the state hashes folded, the scene's end. */
    private static Run run(GravitationalPullDemo pull) {
        Run run = new Run();
        for (int frame = 0; frame < FRAMES; ++frame) {
            pull.getRun().advancePhysics(H);
            run.fold = run.fold * 31 + StateHash.of(pull);
            if (run.sceneOverFrame < 0 && pull.getRun().isSceneOver()) {
                run.sceneOverFrame = frame;
            }
        }
        run.entryInts = pull.getRun().getStateRing().copyEntry(
                pull.getRun().getShownStep()).length;
        return run;
    }

    /** A run's figures. */
    private static final class Run {
        long fold;
        int sceneOverFrame = -1;
        int entryInts;
    }

    private static int main(String... args) {
        ByteArrayOutputStream sink = new ByteArrayOutputStream();
        return Main.run(args, new PrintStream(sink, true, StandardCharsets.UTF_8),
                new PrintStream(sink, true, StandardCharsets.UTF_8));
    }

    private static String sha256(Path file) throws IOException {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                    .digest(Files.readAllBytes(file)));
        } catch (NoSuchAlgorithmException missing) {
            throw new AssertionError(missing);
        }
    }
}

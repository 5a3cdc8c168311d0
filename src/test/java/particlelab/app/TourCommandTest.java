package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.lecture.IterativeAimingDemo;
import particlelab.view.TextFormat;

/**
 * Issue 19, part 3: {@code particle-lab tour}. The stops are one list ({@link LectureTour});
 * {@code tour --list} prints each, every stop's settings are accepted by its demo, and its
 * "what to watch for" is written from the demo's live numbers, allocating nothing. Plain
 * JUnit: the demos' physics and HUD text need no jME ({@link TourHeadlessTest} opens them).
 */
class TourCommandTest {

    /** The frame time the demos are fed (in seconds): the CI's fixed tpf. */
    private static final float TPF = 1f / 60f;
    /** Frames from the stop's start to the second reading: 4 s, long enough for a landing. */
    private static final int FRAMES = 240;

    @Test
    void listPrintsEveryStopInOrderWithItsDemoAndSettings() {
        CommandRun run = CommandRun.of("tour", "--list");
        assertEquals(Program.OK, run.code, run.toString());
        List<LectureTour.Stop> stops = LectureTour.stops();
        List<String> lines = run.outLines();
        assertEquals(stops.size(), lines.size(), run.toString());
        for (int i = 0; i < stops.size(); ++i) {
            LectureTour.Stop stop = stops.get(i);
            String line = lines.get(i);
            assertTrue(line.startsWith((i + 1) + " "), line);
            assertTrue(line.contains(" " + stop.getSlide() + ": " + stop.getDemo()), line);
            for (String setting : stop.getSettings()) {
                assertTrue(line.contains("--set " + setting), line);
            }
        }
        assertEquals("", run.err);
    }

    @Test
    void theLectureSlidesComeInTheLecturesOrder() {
        String[] slides = {"Collision Response", "Collision Response", "Collision Resolution",
            "Collision Resolution", "Collision Resolution: animation based vs physics based",
            "Kinematics vs dynamics", "Discrete particle motion", "Example: gravitational pull",
            "Example: pull + drag", "Example: pull + drag", "Example: pull + drag + thrust",
            "Simulation recipe: gravity, drag, thrust, spring pull", "Rotation", "Rotation",
            "Rotation", "Accuracy of simulation", "Accuracy of simulation",
            "Targeting problem", "HelloAiming",
            "Euler steps: advantages and disadvantages",
            "Euler steps: advantages and disadvantages", "If accuracy matters: cheat",
            "Computer science approach: iterations"};
        // The three-phase slide opens on the demo of its three phases (issue 29).
        assertEquals("targets", LectureTour.stops().get(0).getDemo());
        assertEquals(slides.length, LectureTour.stops().size());
        List<LectureTour.Stop> stops = LectureTour.stops();
        for (int i = 0; i < slides.length; ++i) {
            assertEquals(slides[i], stops.get(i).getSlide(), "stop " + (i + 1));
        }
    }

    @Test
    void everyStopsDemoExistsAndAcceptsItsSettings() {
        for (LectureTour.Stop stop : LectureTour.stops()) {
            int index = DemoCatalog.indexOf(stop.getDemo());
            assertTrue(index >= 0, stop.getSlide() + ": no demo " + stop.getDemo());
            DemoState demo = DemoCatalog.createAll().get(index);
            // Throws a UsageException naming the setting if the demo refuses it.
            DemoCommand.applySettings(demo, stop.getSettings());
        }
    }

    @Test
    void watchLinesFollowTheDemosLiveNumbers() {
        List<LectureTour.Stop> stops = LectureTour.stops();
        for (int i = 0; i < stops.size(); ++i) {
            LectureTour.Stop stop = stops.get(i);
            DemoState demo = DemoCatalog.createAll().get(DemoCatalog.indexOf(stop.getDemo()));
            DemoCommand.applySettings(demo, stop.getSettings());
            demo.getRun().advancePhysics(TPF);
            String early = watch(stop, demo);
            for (int frame = 0; frame < FRAMES; ++frame) {
                demo.getRun().advancePhysics(TPF);
            }
            String later = watch(stop, demo);
            assertTrue(early.startsWith(LectureTour.WATCH) && early.endsWith("\n"), early);
            assertTrue(later.matches("(?s).*\\d.*"), stop.getSlide() + ": no number in "
                    + later);
            // The same text after 4 s would be a typed figure, not the demo's own.
            assertNotEquals(early, later, stop.getSlide() + ": the watch line did not move");
        }
    }

    /**
     * Issue 29: after the landing, stops 6, 7 and 8 said "vy is 0.00 m/s now, falling by g·h
     * each step; vx stays 0.00 m/s" of the ball at rest. Once every ball of a falling stop
     * has landed, its watch line gives each landing x, as the demo computed it.
     */
    @Test
    void watchLinesSayWhereTheFlightEndedOnceItIsOver() {
        for (LectureTour.Stop stop : LectureTour.stops()) {
            if (!List.of("pull", "drag", "thrust").contains(stop.getDemo())) {
                continue;
            }
            DemoState demo = DemoCatalog.createAll().get(DemoCatalog.indexOf(stop.getDemo()));
            DemoCommand.applySettings(demo, stop.getSettings());
            for (int frame = 0; frame < FRAMES; ++frame) {
                demo.getRun().advancePhysics(TPF);
            }
            String line = watch(stop, demo);
            // The balls the watch line is about: pull's one, drag's three, thrust's two.
            int balls = stop.getDemo().equals("pull") ? 1 : stop.getDemo().equals("drag") ? 3 : 2;
            for (int i = 0; i < balls; ++i) {
                DemoParticle ball = demo.getParticles().get(i);
                assertTrue(ball.hasLanded(), stop.getSlide() + ": ball " + i + " not landed");
                String x = TextFormat.appendFixed(new StringBuilder("landed at x = "),
                        ball.getLandingX(), 2).toString();
                assertTrue(line.contains(x), stop.getSlide() + ": no " + x + " in " + line);
            }
            assertFalse(line.contains("m/s now"), line);
        }
    }

    /** Issue 29: the iterations stop counted "1 shots landed so far". */
    @Test
    void theIterationsStopCountsOneShotInTheSingular() {
        LectureTour.Stop stop = null;
        for (LectureTour.Stop candidate : LectureTour.stops()) {
            if (candidate.getDemo().equals("iterate")) {
                stop = candidate;
            }
        }
        assertNotNull(stop, "no iterate stop");
        IterativeAimingDemo demo = (IterativeAimingDemo) DemoCatalog.createAll().get(
                DemoCatalog.indexOf("iterate"));
        DemoCommand.applySettings(demo, stop.getSettings());
        boolean sawOne = false;
        for (int frame = 0; frame < 3000 && demo.countLanded() < 2; ++frame) {
            demo.getRun().advancePhysics(TPF);
            String line = watch(stop, demo);
            if (demo.countLanded() == 1) {
                sawOne = true;
                assertTrue(line.contains(": 1 shot landed so far"), line);
            }
            assertFalse(line.contains(" 1 shots"), line);
        }
        assertTrue(sawOne, "the round never had exactly one shot landed");
    }

    @Test
    void watchLinesAllocateNothing() {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        StringBuilder text = new StringBuilder(1024);
        for (LectureTour.Stop stop : LectureTour.stops()) {
            DemoState demo = DemoCatalog.createAll().get(DemoCatalog.indexOf(stop.getDemo()));
            DemoCommand.applySettings(demo, stop.getSettings());
            demo.getRun().advancePhysics(TPF);
            for (int i = 0; i < 200; ++i) {
                text.setLength(0);
                stop.getWatch().append(demo, text);
            }
            // The least of five windows of 200 calls: a watch line that allocates does so in
            // every call, so at least 200 objects in every window; the JVM under load has been
            // seen to charge this thread 80 or 128 bytes in one window of code that allocates
            // nothing (its own compilation and safepoint work), never in all five.
            long least = Long.MAX_VALUE;
            for (int window = 0; window < 5 && least > 0; ++window) {
                long before = threads.getCurrentThreadAllocatedBytes();
                for (int i = 0; i < 200; ++i) {
                    text.setLength(0);
                    stop.getWatch().append(demo, text);
                }
                least = Math.min(least, threads.getCurrentThreadAllocatedBytes() - before);
            }
            assertEquals(0L, least, stop.getSlide() + ": the watch lines allocated");
        }
    }

    @Test
    void aStopOutOfRangeIsOneLineAndExitTwo() {
        int count = LectureTour.stops().size();
        for (String bad : new String[] {"0", Integer.toString(count + 1), "two"}) {
            CommandRun run = CommandRun.of("tour", "--stop", bad);
            assertEquals(Program.USAGE, run.code, run.toString());
            assertEquals(1, run.errLines().size(), run.toString());
            assertTrue(run.err.startsWith("particle-lab tour: --stop"), run.toString());
            assertTrue(run.err.contains(Integer.toString(count)), run.toString());
        }
    }

    @Test
    void theCommandPagesExampleRefusalIsTheOneTheCommandPrints() throws IOException {
        // docs/cli.md quotes `tour --stop 99`'s line inline (no transcript TranscriptTest
        // runs): it said "from 1 to 16" after the tour had grown to 22 stops
        CommandRun run = CommandRun.of("tour", "--stop", "99");
        String page = new String(Files.readAllBytes(Paths.get("docs", "cli.md")),
                StandardCharsets.UTF_8).replaceAll("\\s+", " ");
        String line = run.err.trim();
        assertTrue(page.contains("`" + line + "`"), "docs/cli.md should quote: " + line);
    }

    @Test
    void aScreenshotNeedsFrames() {
        CommandRun run = CommandRun.of("tour", "--stop", "2", "--screenshot", "x.png");
        assertEquals(Program.USAGE, run.code, run.toString());
        assertTrue(run.err.contains("--screenshot: needs --frames N"), run.toString());
    }

    @Test
    void helpNamesTheKeysAndOptions() {
        CommandRun run = CommandRun.of("tour", "--help");
        assertEquals(Program.OK, run.code, run.toString());
        for (String option : new String[] {"--list", "--stop", "--frames", "--fixed-tpf",
            "--screenshot", "--window", "--ui-scale", "--present", "--force", "PageDown",
            "PageUp"}) {
            assertTrue(run.out.contains(option), option + " in " + run.out);
        }
    }

    private static String watch(LectureTour.Stop stop, DemoState demo) {
        StringBuilder text = new StringBuilder();
        stop.getWatch().append(demo, text);
        return text.toString();
    }
}

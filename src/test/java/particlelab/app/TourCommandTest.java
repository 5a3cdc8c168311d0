package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;

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
        assertEquals(DemoCommand.OK, run.code, run.toString());
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
        String[] slides = {"Collision Response", "Collision Resolution",
            "Collision Resolution: animation based vs physics based", "Kinematics vs dynamics",
            "Discrete particle motion", "Example: gravitational pull", "Example: pull + drag",
            "Example: pull + drag + thrust",
            "Simulation recipe: gravity, drag, thrust, spring pull", "Rotation",
            "Accuracy of simulation", "Targeting problem", "HelloAiming",
            "Euler steps: advantages and disadvantages", "If accuracy matters: cheat",
            "Computer science approach: iterations"};
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
            demo.advancePhysics(TPF);
            String early = watch(stop, demo);
            for (int frame = 0; frame < FRAMES; ++frame) {
                demo.advancePhysics(TPF);
            }
            String later = watch(stop, demo);
            assertTrue(early.startsWith(LectureTour.WATCH) && early.endsWith("\n"), early);
            assertTrue(later.matches("(?s).*\\d.*"), stop.getSlide() + ": no number in "
                    + later);
            // The same text after 4 s would be a typed figure, not the demo's own.
            assertNotEquals(early, later, stop.getSlide() + ": the watch line did not move");
        }
    }

    @Test
    void watchLinesAllocateNothing() {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        StringBuilder text = new StringBuilder(1024);
        for (LectureTour.Stop stop : LectureTour.stops()) {
            DemoState demo = DemoCatalog.createAll().get(DemoCatalog.indexOf(stop.getDemo()));
            DemoCommand.applySettings(demo, stop.getSettings());
            demo.advancePhysics(TPF);
            for (int i = 0; i < 200; ++i) {
                text.setLength(0);
                stop.getWatch().append(demo, text);
            }
            long before = threads.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < 200; ++i) {
                text.setLength(0);
                stop.getWatch().append(demo, text);
            }
            long bytes = threads.getCurrentThreadAllocatedBytes() - before;
            assertEquals(0L, bytes, stop.getSlide() + ": the watch lines allocated");
        }
    }

    @Test
    void aStopOutOfRangeIsOneLineAndExitTwo() {
        int count = LectureTour.stops().size();
        for (String bad : new String[] {"0", Integer.toString(count + 1), "two"}) {
            CommandRun run = CommandRun.of("tour", "--stop", bad);
            assertEquals(DemoCommand.USAGE, run.code, run.toString());
            assertEquals(1, run.errLines().size(), run.toString());
            assertTrue(run.err.startsWith("particle-lab tour: --stop"), run.toString());
            assertTrue(run.err.contains(Integer.toString(count)), run.toString());
        }
    }

    @Test
    void aScreenshotNeedsFrames() {
        CommandRun run = CommandRun.of("tour", "--stop", "2", "--screenshot", "x.png");
        assertEquals(DemoCommand.USAGE, run.code, run.toString());
        assertTrue(run.err.contains("--screenshot: needs --frames N"), run.toString());
    }

    @Test
    void helpNamesTheKeysAndOptions() {
        CommandRun run = CommandRun.of("tour", "--help");
        assertEquals(DemoCommand.OK, run.code, run.toString());
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

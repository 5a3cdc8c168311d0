package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import particlelab.physics.SimulationClock;
import particlelab.world.Fountain;

/**
 * The fountain's physics and HUD text, in plain JUnit (no jME application): the clock drives
 * its packed steps, and the HUD's numbers are the fountain's own. Its points' size and a
 * frame with its mesh buffers are checked in {@link LectureFramesHeadlessTest}.
 */
class FountainDemoTest {

    private static final float H = 1f / 60f;
    private static final int PARTICLES = 20_000;
    /** The HUD's line of the frame's shares, its numbers measured. */
    private static final Pattern SHARE_LINE = Pattern.compile("physics \\d+\\.\\d\\d ms/frame"
            + " = \\d+% of a 16\\.7 ms frame;  mesh \\d+\\.\\d\\d \\+ render \\d+\\.\\d\\d ms;"
            + "  frame \\d+\\.\\d ms \\(\\d+ fps\\)\n");
    private final FountainDemo demo = new FountainDemo();

    FountainDemoTest() {
        demo.setParticleCount(PARTICLES);
    }

    @Test
    void theClockDrivesTheFountainsSteps() throws Exception {
        double[] times = measure(() -> {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.getClock().setPaused(false);
            demo.restart();
            for (int frame = 0; frame < 90; ++frame) {
                demo.getRun().advancePhysics(H);
            }
            double running = demo.getFountain().getTimeSeconds();
            demo.getClock().setPaused(true);
            for (int frame = 0; frame < 30; ++frame) {
                demo.getRun().advancePhysics(H);
            }
            double paused = demo.getFountain().getTimeSeconds();
            demo.getClock().setPaused(false);
            return new double[] {running, paused, demo.getClock().getSimulatedSeconds()};
        });
        // 90 fixed steps of h, then none while paused; the clock and the fountain agree
        assertEquals(90 * H, times[0], 1e-4);
        assertEquals(times[0], times[1], 0.0);
        assertEquals(times[2], times[1], 1e-6);
    }

    @Test
    void theHudCountsWhatTheFountainHolds() throws Exception {
        String[] texts = measure(() -> {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < 300; ++frame) {
                demo.getRun().advancePhysics(H);
            }
            Fountain fountain = demo.getFountain();
            String expected = "particles: " + fountain.countLive() + " in flight (stepped) of "
                    + PARTICLES + ": water " + fountain.countLive(Fountain.WATER);
            return new String[] {demo.getWindow().formatHud(new StringBuilder()).toString(),
                    expected};
        });
        assertTrue(texts[0].contains(texts[1]), texts[0]);
        assertTrue(SHARE_LINE.matcher(texts[0]).find(), texts[0]);
        assertEquals(PARTICLES, demo.getRun().countSimulatedParticles());
    }

    /**
     * The share line at 10^6 with the figures of a run (docs/speed.md): 2.6 ms of physics is
     * 16 % of a 16.7 ms frame; the percentage is rounded to a whole one.
     */
    @Test
    void theShareLineGivesThePhysicsShareOfTheFrame() {
        StringBuilder text = new StringBuilder();
        FountainDemo.appendShareLine(text, 2.6, 1.1, 0.4, 1000.0 / 60.0);
        assertEquals("physics 2.60 ms/frame = 16% of a 16.7 ms frame;  mesh 1.10 + render 0.40"
                + " ms;  frame 16.7 ms (60 fps)\n", text.toString());
        text.setLength(0);
        // a frame not timed yet shows 0 fps, no division by zero
        FountainDemo.appendShareLine(text, 4.2, 0.0, 0.0, 0.0);
        assertEquals("physics 4.20 ms/frame = 25% of a 16.7 ms frame;  mesh 0.00 + render 0.00"
                + " ms;  frame 0.0 ms (0 fps)\n", text.toString());
    }

    /** Run one block of a test and hand back what it measured. */
    private static <T> T measure(Callable<T> block) throws Exception {
        return block.call();
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.renderer.Camera;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.Allocations;
import particlelab.app.HeadlessHarness;
import particlelab.physics.SimulationClock;
import particlelab.world.Fountain;

/**
 * The fountain in a real headless jME application: the clock drives its packed steps, a frame
 * (steps, mesh buffers, HUD text) allocates nothing once running, and the HUD's numbers are
 * the fountain's own.
 */
class FountainDemoTest {

    private static final float H = 1f / 60f;
    private static final int PARTICLES = 20_000;
    /** The HUD's line of the frame's shares, its numbers measured. */
    private static final Pattern SHARE_LINE = Pattern.compile("physics \\d+\\.\\d\\d ms/frame"
            + " = \\d+% of a 16\\.7 ms frame;  mesh \\d+\\.\\d\\d \\+ render \\d+\\.\\d\\d ms;"
            + "  frame \\d+\\.\\d ms \\(\\d+ fps\\)\n");
    private static final FountainDemo demo = new FountainDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> {
        demo.setParticleCount(PARTICLES);
        return List.of(demo);
    });

    @Test
    void theClockDrivesTheFountainsSteps() throws Exception {
        double[] times = harness.call(() -> {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.getClock().setPaused(false);
            demo.restart();
            for (int frame = 0; frame < 90; ++frame) {
                demo.advance(H);
            }
            double running = demo.getFountain().getTimeSeconds();
            demo.getClock().setPaused(true);
            for (int frame = 0; frame < 30; ++frame) {
                demo.advance(H);
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

    /** Points keep their share of the picture in a larger window: 2 px up to 720p, 6 at 4K. */
    @Test
    void pointsGrowWithTheWindowBeyond720p() throws Exception {
        assertEquals(FountainDemo.POINT_SIZE_PIXELS, FountainDemo.pointSizeFor(360), 0f);
        assertEquals(FountainDemo.POINT_SIZE_PIXELS, FountainDemo.pointSizeFor(720), 0f);
        assertEquals(3f * FountainDemo.POINT_SIZE_PIXELS, FountainDemo.pointSizeFor(2160), 0f);
        float[] drawn = harness.call(() -> {
            Camera camera = demo.getApplication().getCamera();
            int width = camera.getWidth();
            int height = camera.getHeight();
            camera.resize(3840, 2160, true);
            demo.advance(H);
            float large = demo.drawnPointSize();
            camera.resize(width, height, true);
            demo.advance(H);
            return new float[] {large, demo.drawnPointSize(), height};
        });
        assertEquals(FountainDemo.pointSizeFor(2160), drawn[0], 0f, "at 3840x2160");
        assertEquals(FountainDemo.pointSizeFor((int) drawn[2]), drawn[1], 0f,
                "back at " + drawn[2] + " px high");
    }

    /**
     * The fountain's own part of a frame: its steps, mesh buffers and HUD text. The whole
     * frame, with the text handed to the screen, the scene graph and the render pass, is
     * measured for every demo by {@code particlelab.app.FrameAllocationHeadlessTest}.
     */
    @Test
    void aRunningFrameAllocatesNothing() throws Exception {
        StringBuilder hud = new StringBuilder(4096);
        Runnable frames = () -> {
            for (int frame = 0; frame < 30; ++frame) {
                demo.advance(H);
                demo.formatHud(hud);
            }
        };
        long bytes = harness.call(() -> {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < 600; ++frame) {
                demo.advance(H); // the pool fills, shells burst
            }
            return Allocations.warmBytesAllocatedBy(frames);
        });
        assertEquals(0L, bytes, "30 fountain frames with the HUD text allocated");
    }

    @Test
    void theHudCountsWhatTheFountainHolds() throws Exception {
        String[] texts = harness.call(() -> {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < 300; ++frame) {
                demo.advance(H);
            }
            Fountain fountain = demo.getFountain();
            String expected = "particles: " + fountain.countLive() + " in flight (stepped) of "
                    + PARTICLES + ": water " + fountain.countLive(Fountain.WATER);
            return new String[] {demo.formatHud(new StringBuilder()).toString(), expected};
        });
        assertTrue(texts[0].contains(texts[1]), texts[0]);
        assertTrue(SHARE_LINE.matcher(texts[0]).find(), texts[0]);
        assertEquals(PARTICLES, demo.countSimulatedParticles());
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
}

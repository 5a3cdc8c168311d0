package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
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
    private static FountainDemo demo;
    private static HeadlessHarness harness;

    @BeforeAll
    static void startApp() throws Exception {
        demo = new FountainDemo();
        demo.setParticleCount(PARTICLES);
        harness = HeadlessHarness.start(List.of(demo));
    }

    @AfterAll
    static void stopApp() {
        harness.close();
    }

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
        assertTrue(texts[0].contains("ms/frame"), texts[0]);
        assertTrue(texts[0].contains("% of 16.7 ms"), texts[0]);
        assertEquals(PARTICLES, demo.countSimulatedParticles());
    }
}

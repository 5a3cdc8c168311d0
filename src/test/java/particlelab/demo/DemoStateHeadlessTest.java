package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * Every catalogue demo attached to a real headless jME application and driven with a fixed
 * tpf on the jME thread.
 */
class DemoStateHeadlessTest {

    private static final float H = 1f / 60f;
    /** The catalogue and a demo too stiff for its step. */
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> {
        List<DemoState> demos = new ArrayList<>(DemoCatalog.createAll());
        demos.add(new StiffDemo());
        return demos;
    });

    @Test
    void pauseFreezesTheSimulationAndSingleStepTakesOneStep() throws Exception {
        DemoState drag = demos().get(DemoCatalog.indexOf("drag"));
        double[] times = harness.call(() -> {
            drag.restart();
            drag.getClock().setPaused(true);
            for (int frame = 0; frame < 10; ++frame) {
                drag.advance(H);
            }
            double paused = drag.getClock().getSimulatedSeconds();
            drag.getClock().requestSingleStep();
            drag.advance(H);
            drag.advance(H);
            double stepped = drag.getClock().getSimulatedSeconds();
            drag.getClock().setPaused(false);
            return new double[] {paused, stepped};
        });
        assertEquals(0.0, times[0]);
        assertEquals(drag.getClock().getStepSeconds(), times[1], 1e-9);
    }

    /**
     * Issue 19: with the HUD rebuilt at 10 Hz, {@code demo tunnelling --frames 1200} showed
     * P = (3.56, 3.00) m while the ball was drawn at x = 6.9 m. Rebuilt every frame (the
     * default), the HUD's P of each ball is its sphere's drawn position after every one of
     * the 1200 frames, to the 2 decimals it prints, when the raw steps are drawn
     * (F6; issue 21: interpolated, the sphere is between the last two states, below).
     */
    @Test
    void theHudsPositionIsWhereTheBallIsDrawnAfterEveryFrame() throws Exception {
        DemoState tunnelling = demos().get(DemoCatalog.indexOf("tunnelling"));
        String mismatch = harness.call(() -> {
            tunnelling.getReplayControls().setInterpolating(false);
            tunnelling.restart();
            StringBuilder expected = new StringBuilder();
            for (int frame = 1; frame <= 1200; ++frame) {
                tunnelling.update(H);
                String shown = tunnelling.getHud().getBodyText();
                for (DemoParticle ball : tunnelling.getParticles()) {
                    Spatial sphere = tunnelling.getView(ball).getNode()
                            .getChild(ball.getLabel() + " sphere");
                    expected.setLength(0);
                    expected.append('\n').append(ball.getLabel()).append(":  P = ");
                    TextFormat.appendVector(expected, sphere.getLocalTranslation(), 2);
                    if (!shown.contains(expected)) {
                        return "frame " + frame + ": drawn at" + expected + ", HUD:\n" + shown;
                    }
                }
            }
            tunnelling.getReplayControls().setInterpolating(true);
            return "";
        });
        assertEquals("", mismatch);
    }

    /**
     * Issue 21: interpolated, each ball is drawn on the segment between its last two physics
     * states at α = leftover / h, the HUD's P is the physics state, and the HUD says what is
     * drawn, with α.
     */
    @Test
    void theInterpolatedBallIsDrawnBetweenItsLastTwoStates() throws Exception {
        DemoState tunnelling = demos().get(DemoCatalog.indexOf("tunnelling"));
        String mismatch = harness.call(() -> {
            tunnelling.getReplayControls().setInterpolating(true);
            tunnelling.restart();
            StringBuilder expected = new StringBuilder();
            Vector3f drawn = new Vector3f();
            for (int frame = 1; frame <= 300; ++frame) {
                // 1.5 h a frame: the leftover is 0 or h/2, so α is 0 or 0.5.
                tunnelling.update(1.5f * H);
                String shown = tunnelling.getHud().getBodyText();
                float alpha = tunnelling.getDrawBlend();
                double leftover = tunnelling.getClock().getLeftoverSeconds()
                        / tunnelling.getClock().getStepSeconds();
                if (Math.abs(alpha - leftover) > 1e-6) {
                    return "frame " + frame + ": α " + alpha + ", leftover/h " + leftover;
                }
                expected.setLength(0);
                expected.append("drawn: interpolated (α = ");
                TextFormat.appendFixed(expected, alpha, 2);
                if (!shown.contains(expected)) {
                    return "frame " + frame + ": no " + expected + " in the HUD:\n" + shown;
                }
                for (DemoParticle ball : tunnelling.getParticles()) {
                    Spatial sphere = tunnelling.getView(ball).getNode()
                            .getChild(ball.getLabel() + " sphere");
                    ball.getBody().copyDrawnPosition(alpha, drawn);
                    if (!sphere.getLocalTranslation().equals(drawn)) {
                        return "frame " + frame + ": " + sphere.getLocalTranslation()
                                + " drawn, the blend is " + drawn;
                    }
                    expected.setLength(0);
                    expected.append('\n').append(ball.getLabel()).append(":  P = ");
                    TextFormat.appendVector(expected, ball.getParticle().position, 2);
                    if (!shown.contains(expected)) {
                        return "frame " + frame + ": physics at" + expected + ", HUD:\n"
                                + shown;
                    }
                }
            }
            return "";
        });
        assertEquals("", mismatch);
    }

    @Test
    void switchingDemosOffAndOnLeavesNothingBehind() throws Exception {
        ParticleLabApp app = harness.app();
        int[] before = harness.call(() -> HeadlessHarness.countLeftovers(app));
        DemoState selected = harness.call(() -> app.getSwitcher().getSelected());
        for (int i = 0; i < 10; ++i) {
            harness.call(() -> {
                selected.setEnabled(false);
                selected.setEnabled(true);
                return true;
            });
        }
        assertArrayEquals(before, harness.call(() -> HeadlessHarness.countLeftovers(app)));

        // Through the switcher, round every demo and back to the first.
        int count = demos().size();
        for (int i = 1; i <= count; ++i) {
            int index = i % count;
            harness.call(() -> {
                app.getSwitcher().select(index);
                return true;
            });
            harness.awaitFrames(2);
            assertTrue(harness.call(() -> demos().get(index).isEnabled()));
            int enabled = harness.call(() -> {
                int n = 0;
                for (DemoState demo : demos()) {
                    n += demo.isEnabled() ? 1 : 0;
                }
                return n;
            });
            assertEquals(1, enabled);
        }
        assertArrayEquals(before, harness.call(() -> HeadlessHarness.countLeftovers(app)));
    }

    @Test
    void helpOverlayListsEveryDeclaredBinding() throws Exception {
        List<KeyBinding> appKeys = harness.app().getSwitcher().getBindings();
        for (DemoState demo : demos()) {
            String help = demo.getKeys().getHelpText();
            List<KeyBinding> keys = demo.getBindings();
            keys.addAll(appKeys);
            assertTrue(keys.size() > 10, demo.getTitle());
            for (KeyBinding key : keys) {
                String line = key.getKeyLabel() + "  -  " + key.getDescription();
                assertTrue(help.contains(line), demo.getTitle() + " help lacks: " + line);
            }
            assertEquals(help, harness.call(() -> demo.getHud().getHelpText()));
        }
    }

    /**
     * Bytes allocated on the jME thread, measured in ten windows of 100 frames each after a
     * warm-up. A per-frame allocation would show in every window. What shows instead, now and
     * then, is a one-off of a few hundred bytes in a single window, at random demos and
     * windows, even when nothing in the scene changes (the JVM's own doing on this thread,
     * e.g. around JIT transitions); so most windows, not all, must be exactly zero.
     */
    @Test
    void simulationTrailsArrowsAndHudTextAllocateNothingPerFrame() throws Exception {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        StringBuilder hudText = new StringBuilder(4096);
        int windows = 10;
        for (DemoState demo : demos()) {
            // A collision scene allocates while it warms up: the world's contact pools grow
            // until the scene has met its largest number of contacts, and rarely taken
            // contact branches are compiled late. Measured: zero per frame after 6000 frames
            // of Collisions, a few windows with 72..1528 bytes after 400.
            int warmUp = demo.getWorld().countRules() > 0 ? 3000 : 400;
            long[][] allocated = harness.call(() -> {
                demo.restart();
                for (int frame = 0; frame < warmUp; ++frame) {
                    demo.advance(H);
                    demo.formatHud(hudText);
                }
                long[][] bytes = new long[2][windows];
                for (int window = 0; window < windows; ++window) {
                    long start = threads.getCurrentThreadAllocatedBytes();
                    for (int frame = 0; frame < 100; ++frame) {
                        demo.advance(H);
                    }
                    long middle = threads.getCurrentThreadAllocatedBytes();
                    for (int frame = 0; frame < 10; ++frame) {
                        demo.formatHud(hudText);
                    }
                    bytes[0][window] = middle - start;
                    bytes[1][window] = threads.getCurrentThreadAllocatedBytes() - middle;
                }
                return bytes;
            });
            assertTrue(countZeros(allocated[0]) >= windows - 2, demo.getTitle()
                    + ": simulation + trails + arrows " + Arrays.toString(allocated[0]));
            assertTrue(countZeros(allocated[1]) >= windows - 2, demo.getTitle()
                    + ": HUD text formatting " + Arrays.toString(allocated[1]));
        }
    }

    @Test
    void atTheSlowRefreshTheHudHandsTextToJmeAtMostTenTimesASecond() throws Exception {
        DemoState demo = demos().get(DemoCatalog.indexOf("aiming"));
        int changes = harness.call(() -> {
            demo.getDemoHud().setRefreshSeconds(DemoState.SLOW_HUD_REFRESH_SECONDS);
            try {
                demo.restart(); // a shot in the air: the HUD has something to follow
                int before = demo.getHud().countTextChanges();
                for (int frame = 0; frame < 600; ++frame) {
                    demo.update(H);
                }
                return demo.getHud().countTextChanges() - before;
            } finally {
                demo.getDemoHud().setRefreshSeconds(DemoState.HUD_REFRESH_SECONDS);
            }
        });
        // 10 s at 60 frames per second: at most 101 refreshes, each setting body and warning.
        assertTrue(changes <= 2 * 101, "text changes: " + changes);
        assertTrue(changes > 10, "the HUD must follow the simulation: " + changes);
    }

    @Test
    void aStepThatBlowsUpResetsTheSceneAndWarns() throws Exception {
        DemoState stiff = demos().get(demos().size() - 1);
        String warning = harness.call(() -> {
            stiff.restart();
            stiff.getClock().setMode(SimulationClock.Mode.RAW_TPF);
            // h = 32/60 s with b/m = 10 per second: each step multiplies V by 1 − 5.3.
            stiff.getClock().setTimeScale(32f);
            for (int frame = 0; frame < 200 && stiff.getRun().countBlowUps() == 0; ++frame) {
                stiff.update(H);
            }
            stiff.getClock().setTimeScale(1f);
            stiff.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            stiff.update(H);
            return stiff.getHud().getWarningText();
        });
        assertEquals(1, stiff.getRun().countBlowUps());
        assertTrue(warning.contains("blew up"), warning);
        for (DemoParticle particle : stiff.getParticles()) {
            assertTrue(particle.getParticle().isFinite(), particle.getLabel());
        }
    }

    @Test
    void aStepBeyondTheStabilityLimitIsWarnedAbout() throws Exception {
        DemoState stiff = demos().get(demos().size() - 1);
        String warning = harness.call(() -> {
            stiff.restart();
            stiff.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            stiff.getClock().setStepSeconds(0.25f); // beyond 2m/b = 0.2 s
            for (int frame = 0; frame < 20; ++frame) {
                stiff.update(H);
            }
            stiff.getClock().setStepSeconds(SimulationClock.DEFAULT_STEP_SECONDS);
            return stiff.getHud().getWarningText();
        });
        assertTrue(warning.startsWith("UNSTABLE: h = 250.0 ms"), warning);
        // Linear drag b/m = 10 /s: sigma = lambda, and h > 2/sigma grows the speed.
        assertTrue(warning.contains("2/σ = 200.0 ms of 'stiff': drag makes the speed grow"),
                warning);
    }

    @ParameterizedTest(name = "time x{0}")
    @ValueSource(floats = {1f, 8f})
    void afterUniformMotionLoopsItsClockAgreesWithItsPosition(float scale) throws Exception {
        // Demo 1 restarts itself from afterStep when the sphere passes x = 30 m. The restart
        // waits for the end of the frame's steps, so t and P describe the same motion after
        // the loop: P.x = 4 m/s · t (uniform motion from x = 0), and t = the flight time.
        DemoState uniform = demos().get(DemoCatalog.indexOf("uniform"));
        double[] result = harness.call(() -> {
            uniform.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            uniform.restart();
            uniform.getClock().setTimeScale(scale);
            double firstLoop = Double.NaN;
            double previous = 0.0;
            // 7.5 s to the edge; run 12 s of simulated time, through at least one loop.
            for (int frame = 0; frame < Math.round(12f / scale / H); ++frame) {
                uniform.advance(H);
                double t = uniform.getClock().getSimulatedSeconds();
                if (t < previous && Double.isNaN(firstLoop)) {
                    firstLoop = t;
                }
                previous = t;
            }
            uniform.getClock().setTimeScale(1f);
            DemoParticle sphere = uniform.getParticles().get(0);
            return new double[] {firstLoop, uniform.getClock().getSimulatedSeconds(),
                sphere.getFlightSeconds(), sphere.getParticle().position.x,
                uniform.getClock().getLeftoverSeconds()};
        });
        assertFalse(Double.isNaN(result[0]), "the demo never looped");
        // The frame that looped ends at t = 0: no step is counted before the restart.
        assertEquals(0.0, result[0], 0.0);
        // Both sums of the same float h in double: equal to round-off.
        assertEquals(result[2], result[1], 1e-9);
        // x = n·h·4 in float: ~300 additions of 0.067 m, rounding well below 1e-3 m.
        assertEquals(4.0 * result[1], result[3], 1e-3);
        assertTrue(result[4] >= -1e-4 * H, "leftover " + result[4]);
    }

    @Test
    void whenEveryParticleHasLandedTheClockStopsAndTheHudSaysSo() throws Exception {
        DemoState drag = demos().get(DemoCatalog.indexOf("drag"));
        Object[] result = harness.call(() -> {
            drag.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            drag.restart();
            // The three spheres land within 2.1 s (gravity only: 2.04 s).
            for (int frame = 0; frame < 200; ++frame) {
                drag.advance(H);
            }
            double t = drag.getClock().getSimulatedSeconds();
            for (int frame = 0; frame < 100; ++frame) {
                drag.advance(H);
            }
            double latest = 0.0;
            for (DemoParticle particle : drag.getParticles()) {
                latest = Math.max(latest, particle.getLandingSeconds());
            }
            return new Object[] {drag.getRun().isSceneOver(), t,
                drag.getClock().getSimulatedSeconds(), latest,
                drag.formatHud(new StringBuilder()).toString()};
        });
        assertTrue((Boolean) result[0]);
        assertEquals((Double) result[1], (Double) result[2], 0.0);
        // t stopped at the end of the step in which the last sphere landed.
        assertEquals((Double) result[3], (Double) result[2], H);
        String hud = (String) result[4];
        assertTrue(hud.contains("stopped: every particle has landed (R launches again)"), hud);
        assertEquals(3, hud.split(" m after ", -1).length - 1, hud);
    }

    @Test
    void timeKeysDoubleHalveAndGoBackToRealTimeWithinTheLimits() throws Exception {
        DemoState demo = demos().get(DemoCatalog.indexOf("pull"));
        float[] scales = harness.call(() -> {
            KeyBinding faster = binding(demo, "time scale x2");
            KeyBinding slower = binding(demo, "time scale /2");
            KeyBinding realTime = binding(demo, "time scale back to x1");
            for (int i = 0; i < 10; ++i) {
                faster.press(i % 2); // both keys: + and the keypad's +
            }
            float top = demo.getClock().getTimeScale();
            realTime.press(0);
            float back = demo.getClock().getTimeScale();
            for (int i = 0; i < 10; ++i) {
                slower.press(i % 2);
            }
            float bottom = demo.getClock().getTimeScale();
            realTime.press(0);
            return new float[] {top, back, bottom};
        });
        assertArrayEquals(new float[] {SimulationClock.MAX_TIME_SCALE, 1f,
            SimulationClock.MIN_TIME_SCALE}, scales, 0f);
    }

    private static KeyBinding binding(DemoState demo, String descriptionStart) {
        for (KeyBinding key : demo.getBindings()) {
            if (key.getDescription().startsWith(descriptionStart)) {
                return key;
            }
        }
        throw new AssertionError("no key for " + descriptionStart);
    }

    private static int countZeros(long[] values) {
        int zeros = 0;
        for (long value : values) {
            zeros += value == 0L ? 1 : 0;
        }
        return zeros;
    }

    private static List<DemoState> demos() {
        return harness.app().getSwitcher().getDemos();
    }

    /** A test-only demo whose drag is strong enough to blow up at long steps. */
    static final class StiffDemo extends DemoState {
        StiffDemo() {
            super("Stiff drag (test)");
        }

        @Override
        protected void createScene() {
            addParticle("stiff", ColorRGBA.Red, new Vector3f(0f, 5f, 0f),
                    new Vector3f(10f, 0f, 0f), 1f,
                    new ParticleIntegrator(new LinearDrag(10f)));
        }
    }
}

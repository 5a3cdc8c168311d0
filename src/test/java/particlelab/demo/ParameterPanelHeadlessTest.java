package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.Allocations;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.DragDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.HelloAimingDemo;
import particlelab.lecture.ThrustDemo;
import particlelab.lecture.UniformMotionDemo;
import particlelab.lecture.WindDemo;
import particlelab.physics.SimulationClock;
import particlelab.view.ParameterPanel;

/**
 * The parameter panel and the kept shots in every catalogue demo, in a real headless jME
 * application driven with a fixed tpf: the panel lists exactly the declared parameters, a
 * LIVE change acts at once, a launch change at the next reset, the mouse's buttons and
 * sliders go through the same model, and the kept shots stay bounded and labelled.
 */
class ParameterPanelHeadlessTest {

    private static final float H = 1f / 60f;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    private static List<DemoState> demos() {
        return harness.app().getSwitcher().getDemos();
    }

    private static <T extends DemoState> T demo(Class<T> type) {
        for (DemoState demo : demos()) {
            if (type.isInstance(demo)) {
                return type.cast(demo);
            }
        }
        throw new IllegalStateException("no " + type.getSimpleName() + " in the catalogue");
    }

    @Test
    void panelListsExactlyTheDeclaredParametersOfEveryDemo() throws Exception {
        for (DemoState demo : demos()) {
            List<String> problems = harness.call(() -> {
                List<String> found = new ArrayList<>();
                DemoParameters parameters = demo.getParameters();
                ParameterPanel panel = demo.getParameterControls().getPanel();
                panel.refresh();
                if (panel.countRows() != parameters.size()) {
                    found.add(demo.getTitle() + ": " + panel.countRows() + " rows for "
                            + parameters.size() + " parameters");
                }
                for (int i = 0; i < parameters.size(); ++i) {
                    String expected = parameters.formatRow(i, new StringBuilder()).toString();
                    if (!expected.equals(panel.getRowText(i))
                            || !expected.contains(parameters.get(i).getName() + " = ")) {
                        found.add(demo.getTitle() + " row " + i + ": " + panel.getRowText(i));
                    }
                }
                // Every demo has the shared step h first; the help names the panel's keys.
                if (!"h".equals(parameters.get(0).getName())
                        || !demo.getKeys().getHelpText().contains("parameter panel")) {
                    found.add(demo.getTitle() + ": no h or no panel keys in the help");
                }
                return found;
            });
            assertTrue(problems.isEmpty(), problems.toString());
        }
    }

    @Test
    void firstDemosDeclareTheirLaunchMassGravityAndCoefficients() throws Exception {
        // Each demo's own, then its parts': the energy ledger's switch (every demo's first
        // part, issue 32), and the free-flight demos' comparison lane, then their derivative
        // lens (issue 32 §2), last. Pull, drag, thrust and aiming: the bug hunt's switch and
        // seed (issue 34); pull: the rate lanes (issue 33), after the lens.
        assertNames(UniformMotionDemo.class, "h", "speed", "angle", "energy", "lane", "lens");
        assertNames(GravitationalPullDemo.class, "h", "speed", "angle", "mass", "g", "fault",
                "seed", "energy", "lane", "lens", "rates", "jitter_ms");
        assertNames(DragDemo.class, "h", "speed", "angle", "mass", "g", "b", "c", "law",
                "drag", "fault", "seed", "energy", "lane", "lens", "method");
        assertNames(ThrustDemo.class, "h", "speed", "angle", "mass", "g", "b", "k", "fault",
                "seed", "energy", "lane", "lens");
        assertNames(HelloAimingDemo.class, "h", "vx", "g", "aim", "code", "fault", "seed",
                "energy");
        assertNames(BounceDemo.class, "h", "e", "threshold", "fix", "detection", "energy");
        assertNames(CollisionsDemo.class, "h", "e", "preset", "energy");
        assertNames(WindDemo.class, "h", "w", "energy");
    }

    private static void assertNames(Class<? extends DemoState> type, String... names)
            throws Exception {
        DemoParameters parameters = harness.call(() -> demo(type).getParameters());
        List<String> declared = new ArrayList<>();
        for (int i = 0; i < parameters.size(); ++i) {
            declared.add(parameters.get(i).getName());
        }
        assertEquals(List.of(names), declared, type.getSimpleName());
    }

    @Test
    void defaultLaunchIsTheLectureOneExactly() throws Exception {
        Vector3f launch = harness.call(() -> demo(DragDemo.class).getParticles().get(0)
                .copyLaunchVelocity(new Vector3f()));
        // speed = |(10, 10)| and 45 degrees give back (10, 10) to the bit, as before.
        assertEquals(new Vector3f(10f, 10f, 0f), launch);
    }

    @Test
    void liveDragCoefficientActsAtOnce() throws Exception {
        float[] result = harness.call(() -> {
            DragDemo drag = demo(DragDemo.class);
            drag.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            drag.restart();
            drag.getWindow().advance(H);
            DemoParticle linear = drag.getParticles().get(1);
            drag.getParameters().set("b", 0f);
            Vector3f before = new Vector3f(linear.getParticle().velocity);
            drag.getWindow().advance(H);
            Vector3f after = linear.getParticle().velocity;
            drag.getParameters().set("b", DragDemo.LINEAR_B);
            return new float[] {after.x - before.x, after.y - before.y};
        });
        // With b = 0 from this step on, the step is V += h*g: vx does not change, and vy
        // changes by -9.8 h (to float round-off of a difference of numbers near 10 m/s).
        assertEquals(0f, result[0], 0f);
        assertEquals(-9.8f * H, result[1], 2e-6f);
    }

    @Test
    void launchSpeedChangesTheNextLaunchOnly() throws Exception {
        float[] speeds = harness.call(() -> {
            GravitationalPullDemo pull = demo(GravitationalPullDemo.class);
            pull.restart();
            pull.getParameters().set("speed", 20f);
            pull.getParameters().set("angle", 30f);
            float waiting = pull.getParticles().get(0).getParticle().velocity.length();
            pull.restart();
            Vector3f launched = pull.getParticles().get(0).getParticle().velocity;
            float[] out = {waiting, launched.length(),
                (float) Math.toDegrees(Math.atan2(launched.y, launched.x))};
            pull.getParameters().set("speed", pull.getParameters().get(1).getDefault());
            pull.getParameters().set("angle", pull.getParameters().get(2).getDefault());
            pull.restart();
            return out;
        });
        assertEquals((float) Math.hypot(10, 10), speeds[0], 1e-5f);
        // 20·(cos 30°, sin 30°) in float: |V| and the angle to float round-off.
        assertEquals(20f, speeds[1], 1e-5f);
        assertEquals(30f, speeds[2], 1e-4f);
    }

    @Test
    void panelButtonsAndSlidersGoThroughTheSameModel() throws Exception {
        Object[] seen = harness.call(() -> {
            DragDemo drag = demo(DragDemo.class);
            ParameterPanel panel = ((DemoState) drag).getParameterControls().getPanel();
            DemoParameters parameters = drag.getParameters();
            int b = parameters.indexOf("b");
            panel.drag(b, 0.5f);
            panel.refresh();
            float dragged = parameters.getValue(b);
            boolean selected = parameters.getSelected() == b;
            panel.click("Pause");
            boolean paused = drag.getClock().isPaused();
            panel.click("Pause");
            parameters.set("speed", 20f);
            panel.click("Reset");
            float launched = drag.getParticles().get(0).getParticle().velocity.length();
            parameters.set(b, DragDemo.LINEAR_B);
            parameters.set("speed", parameters.get(1).getDefault());
            drag.restart();
            panel.refresh();
            return new Object[] {dragged, selected, paused, launched};
        });
        // Half-way along b's slider, from 0 to 5 N s/m in steps of 0.05: 2.5 N s/m.
        assertEquals(2.5f, (float) seen[0], 1e-5f);
        assertEquals(true, seen[1]);
        assertEquals(true, seen[2]);
        assertEquals(20f, (float) seen[3], 1e-5f);
    }

    @Test
    void nextDemoButtonChoosesTheNextDemo() throws Exception {
        DemoState first = harness.call(() -> harness.app().getSwitcher().getSelected());
        harness.call(() -> {
            first.getParameterControls().getPanel().click("Next demo");
            return true;
        });
        harness.awaitFrames(3);
        DemoState second = harness.call(() -> harness.app().getSwitcher().getSelected());
        harness.call(() -> {
            harness.app().getSwitcher().select(demos().indexOf(first));
            return true;
        });
        harness.awaitFrames(3);
        assertEquals(demos().indexOf(first) + 1, demos().indexOf(second));
    }

    @Test
    void exportButtonAsksForTheExportTheEKeyAsksFor() throws Exception {
        boolean asked = harness.call(() -> {
            DemoState demo = harness.app().getSwitcher().getSelected();
            // The application's export state takes requests at the end of a frame; on this
            // thread, between frames, the request is still there to be taken.
            demo.getParameterControls().getPanel().click("Export");
            return demo.getKeys().takeExportRequest();
        });
        assertTrue(asked, "the Export button did not ask for an export");
    }

    @Test
    void keptShotsAreBoundedAndLabelledWithWhatDiffered() throws Exception {
        String legend = harness.call(() -> {
            DragDemo drag = demo(DragDemo.class);
            drag.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            drag.getClock().setPaused(false);
            ParameterControls controls = ((DemoState) drag).getParameterControls();
            controls.getKeptShots().clear();
            drag.restart();
            for (int shot = 0; shot < KeptShots.SHOTS + 2; ++shot) {
                drag.getParameters().set("b", 0.1f * (shot + 1));
                drag.restart();
                for (int frame = 0; frame < 30; ++frame) {
                    drag.getWindow().advance(H);
                }
            }
            drag.getParameters().set("b", 0.9f);
            drag.restart();
            controls.update(drag.getWindow().getHud().getLayout());
            controls.getPanel().refresh();
            int kept = controls.getKeptShots().size();
            String text = controls.getPanel().getLegendText();
            controls.getKeptShots().clear();
            return kept + "\n" + text;
        });
        String[] lines = legend.split("\n");
        assertEquals(String.valueOf(KeptShots.SHOTS), lines[0], legend);
        assertEquals(KeptShots.SHOTS + 2, lines.length, legend);
        // The newest kept shot flew with b = 0.7 (the 7th launch); now b = 0.9.
        assertEquals("1.  b = 0.70 N s/m vs 0.90 N s/m", lines[2], legend);
        assertEquals("5.  b = 0.30 N s/m vs 0.90 N s/m", lines[6], legend);
    }

    @Test
    void perFrameWorkWithKeptShotsAndPanelAllocatesNothing() throws Exception {
        long[] bytes = harness.call(() -> {
            DragDemo drag = demo(DragDemo.class);
            drag.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            drag.getClock().setPaused(false);
            ParameterControls controls = ((DemoState) drag).getParameterControls();
            HeadlessHarness.press(drag, "F2");
            boolean shown = controls.isPanelVisible()
                    && !drag.getWindow().getHud().getLayout().getSidePanel().isEmpty();
            drag.restart();
            for (int frame = 0; frame < 20; ++frame) {
                drag.getWindow().advance(H);
            }
            drag.restart();
            controls.update(drag.getWindow().getHud().getLayout());
            long frames = Allocations.warmBytesAllocatedBy(() -> {
                drag.getWindow().advance(H);
                controls.update(drag.getWindow().getHud().getLayout());
            });
            // Keeping a shot (copying the trails, fading the older ones) at a reset.
            long keep = Allocations.warmBytesAllocatedBy(() -> {
                drag.getWindow().advance(H);
                drag.restart();
            });
            controls.getKeptShots().clear();
            drag.restart();
            HeadlessHarness.press(drag, "F2");
            return new long[] {frames, keep, shown ? 1L : 0L};
        });
        assertEquals(1L, bytes[2], "F2 shows the panel in the side slot");
        assertEquals(0L, bytes[0], "a frame with the panel and kept shots");
        assertEquals(0L, bytes[1], "a reset that keeps a shot");
    }
}

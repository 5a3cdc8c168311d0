package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.view.EnergyBars;
import particlelab.view.HudLayout;
import particlelab.view.ScreenRect;

/**
 * The parts of demos in a real headless application: the hooks a window calls, the student
 * lane's recipe that fails, and issue 32's bar graph. The bar graph: with
 * {@code --set energy=on} the drag, bounce and spring demos draw the ledger's bars in the HUD's ledger strip at every
 * window from 200x150 to 3840x2160, presenting and not: the strip inside the window, of no
 * negative size, clear of the HUD's texts, the side panel and the graph, the scene left of
 * it, every GUI spatial placed by finite numbers; its labels at least 14 px at 1280x720;
 * its scale the same from frame to frame while the energy stays under it; its last bar the
 * ledger's numerical column. Presenting, bounce shows the bars without being switched on
 * (its slide is about energy) and drag does not.
 */
class DemoPartsHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{200, 150}, {640, 360}, {1280, 720},
        {3840, 2160}};
    /** Frames after each change: the strip is asked for, then laid out and drawn. */
    private static final int FRAMES = 4;
    /** Frames watched for a steady scale: a second of the bounce's fall and rebound. */
    private static final int STEADY_FRAMES = 60;
    /** The least label size a back row reads at 1280x720 (pixels), issue 32. */
    private static final float BACK_ROW_PIXELS = 14f;
    private static final List<String> SHOWN = List.of("drag", "bounce", "spring");
    /** Whole frames after the student lane stopped: a second of flight. */
    private static final int LANE_FRAMES = 60;
    /** What the recording demo's parts log (live, appended to on the jME thread). */
    private static final List<String> partsLog = new ArrayList<>();
    private static final DemoPartTest.RecordingDemo recording =
            new DemoPartTest.RecordingDemo(partsLog);
    private static final GravitationalPullDemo studentPull = new GravitationalPullDemo();
    /** The catalogue, then a demo with recording parts and a pull for the student lane. */
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> {
        List<DemoState> demos = new ArrayList<>(DemoCatalog.createAll());
        demos.add(recording);
        demos.add(studentPull);
        return demos;
    });

    @Test
    void theBarsKeepToTheirStripAtEveryWindowPresentingAndNot() throws Exception {
        List<String> problems = new ArrayList<>();
        ParticleLabApp app = harness.app();
        for (String name : SHOWN) {
            int index = DemoCatalog.names().indexOf(name);
            DemoState demo = app.getSwitcher().getDemos().get(index);
            harness.call(() -> {
                app.getSwitcher().select(index);
                demo.getParameters().set(demo.getParameters().indexOf(EnergyPart.PARAMETER), 1);
                frames(app, FRAMES);
                return true;
            });
            for (boolean presenting : new boolean[] {false, true}) {
                for (int[] window : WINDOWS) {
                    problems.add(harness.call(() -> {
                        app.getWindowControls().setPresenting(presenting);
                        app.reshape(window[0], window[1]);
                        frames(app, FRAMES);
                        return check(demo, window, presenting);
                    }));
                }
            }
            harness.call(() -> {
                demo.getParameters().set(demo.getParameters().indexOf(EnergyPart.PARAMETER), 0);
                app.getWindowControls().setPresenting(false);
                app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
                frames(app, FRAMES);
                return true;
            });
        }
        problems.removeIf(String::isEmpty);
        assertEquals(List.of(), problems.subList(0, Math.min(8, problems.size())),
                problems.size() + " problems");
    }

    @Test
    void presentingShowsTheBarsWhereTheSlideIsAboutEnergy() throws Exception {
        ParticleLabApp app = harness.app();
        assertEquals("bounce true, drag false", harness.call(() -> {
            StringBuilder shown = new StringBuilder();
            for (String name : new String[] {"bounce", "drag"}) {
                int index = DemoCatalog.names().indexOf(name);
                DemoState demo = app.getSwitcher().getDemos().get(index);
                app.getSwitcher().select(index);
                app.getWindowControls().setPresenting(true);
                frames(app, FRAMES);
                EnergyBars bars = demo.getEnergyPart().getBars();
                shown.append(shown.length() == 0 ? "" : ", ").append(name).append(' ')
                        .append(bars.isVisible()
                                && !demo.getWindow().getHud().getLayout().getLedger().isEmpty());
                app.getWindowControls().setPresenting(false);
                frames(app, FRAMES);
            }
            return shown.toString();
        }));
    }

    /**
     * The strip coming lays the HUD out again for the window the demo was laid out for, not
     * the camera's (1280x720 here): a demo laid out at 1920x1080 with the factor 1.25, as the
     * tour's scene-share test and the overlap matrix do, kept a scene laid out for 1280x720
     * (832 px wide, 18 % of the window) once presenting brought the bounce's bars.
     */
    @Test
    void theStripComingKeepsTheWindowTheDemoWasLaidOutFor() throws Exception {
        ParticleLabApp app = harness.app();
        int index = DemoCatalog.names().indexOf("bounce");
        DemoState demo = app.getSwitcher().getDemos().get(index);
        String laidOut = harness.call(() -> {
            app.getSwitcher().select(index);
            frames(app, FRAMES);
            demo.getDemoHud().setPresenting(true);
            demo.getDemoHud().layOut(1920, 1080, 1.25f);
            HeadlessHarness.fly(demo, FRAMES, H);
            HudLayout layout = demo.getWindow().getHud().getLayout();
            String found = layout.getWindow() + ", strip " + !layout.getLedger().isEmpty()
                    + ", scene right of the strip " + (layout.getScene().getRight()
                    > layout.getLedger().getX());
            demo.getDemoHud().setPresenting(false);
            demo.getDemoHud().layOut(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
            frames(app, FRAMES);
            return found;
        });
        assertEquals("[x 0.0..1920.0, y 0.0..1080.0], strip true, scene right of the strip false",
                laidOut);
    }

    @Test
    void theScaleHoldsStillWhileTheBallBounces() throws Exception {
        ParticleLabApp app = harness.app();
        int index = DemoCatalog.names().indexOf("bounce");
        DemoState demo = app.getSwitcher().getDemos().get(index);
        String changes = harness.call(() -> {
            app.getSwitcher().select(index);
            demo.getParameters().set(demo.getParameters().indexOf(EnergyPart.PARAMETER), 1);
            frames(app, FRAMES);
            EnergyBars bars = demo.getEnergyPart().getBars();
            double first = bars.getFullScale();
            StringBuilder found = new StringBuilder();
            for (int frame = 0; frame < STEADY_FRAMES; ++frame) {
                frames(app, 1);
                if (bars.getFullScale() != first) {
                    found.append(frame).append(": ").append(bars.getFullScale()).append(' ');
                }
            }
            // the bounce only loses energy: the start's scale is the scale throughout
            double start = demo.getEnergyPart().getEnergy().getLedger().getStartJoules();
            if (first != EnergyBars.roundUp(start)) {
                found.append("scale ").append(first).append(" for a start of ").append(start);
            }
            demo.getParameters().set(demo.getParameters().indexOf(EnergyPart.PARAMETER), 0);
            frames(app, FRAMES);
            return found.toString();
        });
        assertEquals("", changes);
    }

    /**
     * The window's hooks reach every part once, right after the demo's own: its views built
     * once, laid out with the first layout and again at every new one, a frame's afterFrame.
     */
    @Test
    void theWindowsHooksReachEveryPartOnceAfterTheDemosOwn() throws Exception {
        List<String> log = partsLog;
        DemoPartTest.RecordingDemo demo = recording;
        List<String> built = harness.call(() -> {
            List<String> seen = new ArrayList<>();
            for (String entry : log) {
                if (entry.endsWith("buildViews")) {
                    seen.add(entry);
                }
            }
            return seen;
        });
        assertEquals(List.of("demo.buildViews", "a.buildViews", "b.buildViews"), built);
        assertTrue(harness.call(() -> log.contains("a.layOut") && log.contains("b.layOut")),
                "the parts were laid out with the first layout: " + log);
        List<String> frame = harness.call(() -> {
            log.clear();
            demo.getWindow().advance(H);
            List<String> seen = new ArrayList<>();
            for (String entry : log) {
                if (entry.endsWith("afterFrame")) {
                    seen.add(entry);
                }
            }
            return seen;
        });
        assertEquals(List.of("demo.afterFrame", "a.afterFrame", "b.afterFrame"), frame);
        List<String> laidOut = harness.call(() -> {
            log.clear();
            demo.getDemoHud().layOut(640, 360);
            List<String> seen = new ArrayList<>();
            for (String entry : log) {
                if (entry.endsWith("layOut")) {
                    seen.add(entry);
                }
            }
            return seen;
        });
        // a new layout: the scene's area follows the HUD, then each part lays out once
        assertEquals(List.of("a.layOut", "b.layOut"), laidOut);
    }

    /** @return "" or what is wrong with the bars of a demo on screen */
    private static String check(DemoState demo, int[] window, boolean presenting) {
        String where = demo.getTitle() + " at " + window[0] + "x" + window[1]
                + (presenting ? " presenting" : "");
        List<String> found = new ArrayList<>();
        HudLayout layout = demo.getWindow().getHud().getLayout();
        ScreenRect strip = layout.getLedger();
        EnergyBars bars = demo.getEnergyPart().getBars();
        if (!(strip.getWidth() >= 0f && strip.getHeight() >= 0f)) {
            found.add("strip " + strip);
        }
        if (!strip.isEmpty()) {
            if (!layout.getWindow().contains(strip)) {
                found.add("strip " + strip + " leaves the window");
            }
            for (ScreenRect other : new ScreenRect[] {layout.getTitle(), layout.getBody(),
                layout.getWarning(), layout.getFooter(), layout.getReadout(),
                layout.getSidePanel(), layout.getGraph()}) {
                if (other.intersects(strip)) {
                    found.add(other + " over the strip " + strip);
                }
            }
            if (layout.getScene().getRight() > strip.getX()) {
                found.add("the scene " + layout.getScene() + " runs under " + strip);
            }
            if (!bars.isVisible()) {
                found.add("a strip but no bars");
            }
            int rows = bars.countRowsShown();
            double numerical = demo.getEnergyPart().getEnergy().getLedger()
                    .getNumericalJoules();
            int last = bars.getRowCount() - 1;
            if (rows == 0) {
                found.add("no row shown");
            } else if (bars.getValue(last) != numerical
                    || !bars.getName(last).equals("numerical")) {
                // the bar of the numerical column is last, with the ledger's value exactly
                found.add("last bar " + bars.getName(last) + " " + bars.getValue(last)
                        + ", numerical " + numerical);
            }
        } else if (window[0] >= 640) {
            found.add("no strip");
        }
        if (window[0] == 1280 && !presenting && bars.getTextSize() < BACK_ROW_PIXELS) {
            found.add("labels of " + bars.getTextSize() + " px");
        }
        demo.getApplication().getGuiViewPort().getScenes().get(0).depthFirstTraversal(s -> {
            Vector3f at = s.getWorldTranslation();
            Vector3f scale = s.getWorldScale();
            if (!Float.isFinite(at.x + at.y + at.z + scale.x + scale.y + scale.z)) {
                found.add(s.getName() + " at " + at + " scaled " + scale);
            }
        });
        return found.isEmpty() ? "" : where + ": " + found;
    }

    private static void frames(ParticleLabApp app, int count) {
        for (int i = 0; i < count; ++i) {
            SmallPanelHeadlessTest.frame(app);
        }
    }

    /** Choose the student lane with a class and a limit, launch, and run whole frames. */
    private static String[] runFrames(String className, long limitNanos) throws Exception {
        ParticleLabApp app = harness.app();
        harness.call(() -> {
            app.getSwitcher().select(app.getSwitcher().getDemos().indexOf(studentPull));
            return true;
        });
        harness.awaitFrames(3);
        return harness.call(() -> {
            studentPull.getLane().useStudentClass(className, limitNanos);
            studentPull.getParameters().set(ComparisonLane.PARAMETER,
                    ComparisonLane.Kind.STUDENT.ordinal());
            studentPull.restart();
            studentPull.getClock().setPaused(false);
            double before = studentPull.getClock().getSimulatedSeconds();
            for (int frame = 0; frame < LANE_FRAMES; ++frame) {
                SmallPanelHeadlessTest.frame(app);
            }
            return new String[] {studentPull.getWindow().getHud().getBodyText(),
                String.valueOf(studentPull.getClock().getSimulatedSeconds() - before),
                String.valueOf(app.getRecovered()), String.valueOf(app.getFailure())};
        });
    }

    /**
     * The student lane (issue 31 §3's acceptance): a student's recipe that throws, or never
     * returns, leaves the window running, whole frames and all, with one line on the HUD;
     * nothing is thrown on the render thread and the window recovers from nothing.
     */
    @Test
    void aThrowingRecipeLeavesTheWindowRunningWithOneLine() throws Exception {
        String[] result = runFrames(StudentLaneTest.ThrowingRecipe.class.getName(),
                10_000_000_000L);
        // one line, however the HUD's column wraps it (a continuation starts "\n    ")
        String hud = result[0].replace("\n    ", " ");
        assertTrue(hud.matches("(?s).*\nLane student's recipe \\(L\\):  step 3: threw"
                + " IllegalStateException: boom at call 3 \\(StudentLaneTest\\.java:\\d+\\)"
                + "\n.*"), hud);
        // 60 frames of h: the clock ran on (float sums: round-off ~1e-5 s)
        assertEquals(LANE_FRAMES * H, Double.parseDouble(result[1]), 1e-3);
        assertEquals("null", result[2], "the window recovered from");
        assertEquals("null", result[3], "the window failed");
        // and jME's own loop goes on
        harness.awaitFrames(3);
        assertNull(harness.app().getRecovered());
    }

    @Test
    void aRecipeThatNeverReturnsLeavesTheWindowRunningWithOneLine() throws Exception {
        StudentLaneTest.EndlessRecipe.released = false;
        try {
            String[] result = runFrames(StudentLaneTest.EndlessRecipe.class.getName(),
                    200_000_000L);
            // one line, however the HUD's column wraps it (a continuation starts "\n    ")
            assertTrue(result[0].replace("\n    ", " ").contains("\nLane student's recipe (L):"
                    + "  step 1: did not return within 0.2 s: an endless loop? (no more calls)\n"),
                    result[0]);
            assertEquals(LANE_FRAMES * H, Double.parseDouble(result[1]), 1e-3);
            assertEquals("null", result[2], "the window recovered from");
            harness.awaitFrames(3);
        } finally {
            StudentLaneTest.EndlessRecipe.released = true;
        }
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoState;
import particlelab.demo.OverlapProbe;
import particlelab.lecture.CollisionsDemo;
import particlelab.physics.SimulationClock;

/**
 * Issue 29 §3, "nothing on screen covers anything else": every demo of the catalogue and every
 * tour stop, laid out at 640x360, 1280x720, 1920x1080 and 3840x2160, presenting and not, its
 * parameter panel open and not, at moments of launch, flight and landing: no two texts cover
 * each other (HUD, distance marks, posts' names, particles' labels, readouts), no text leaves
 * the window, no text covers a sphere, and no particle's label covers a post or a trail
 * ({@link OverlapProbe}).
 *
 * <p>The physics runs once per case; at each sampled frame the same state is laid out in every
 * configuration of the matrix (layout moves no body). CI checks a fixed subset that covers
 * every demo, every stop, every size and both modes: each case in one of the 16
 * configurations, taken in turn so the 41 cases take each at least twice, at launch and after
 * a second of flight. A night's run sets
 * {@code PARTICLELAB_OVERLAP_FULL=1} for the whole matrix at four frames (docs/testing.md).
 */
class OverlapMatrixHeadlessTest {

    private static final float H = 1f / 60f;
    private static final int[][] WINDOWS = {{640, 360}, {1280, 720}, {1920, 1080},
        {3840, 2160}};
    /** Every configuration: 4 sizes x presenting or not x panel open or not. */
    private static final int CONFIGURATIONS = WINDOWS.length * 4;
    /** The whole matrix when this environment variable is set (a night's run). */
    static final String FULL = "PARTICLELAB_OVERLAP_FULL";
    /** Frames at which the layout is checked: launch, climb, flight, landing or later. */
    private static final int[] FULL_FRAMES = {1, 45, 120, 240};
    private static final int[] CI_FRAMES = {1, 60};
    /** Configurations a case takes in CI. */
    private static final int CI_CONFIGURATIONS = 1;
    /** Frames of the issue's screenshots ({@code --frames 200}): the shots have landed. */
    private static final int LANDED_FRAMES = 200;
    /** Frames of aiming's landing ({@code demo aiming --frames 400}): all shots down. */
    private static final int AIMING_LANDED_FRAMES = 400;
    /** Frames of iterate's screenshot ({@code demo iterate --frames 300}): rounds flown. */
    private static final int ITERATE_FRAMES = 300;
    /** Frames the impulse labels are followed for, and the gap between samples. */
    private static final int IMPULSE_FRAMES = 360;
    private static final int IMPULSE_SAMPLE = 6;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void noTextCoversAnotherASphereOrTheWindowsEdgeInAnyDemoOrStop() throws Exception {
        boolean full = System.getenv(FULL) != null;
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        List<DemoState> demos = app.getSwitcher().getDemos();
        int cases = demos.size() + LectureTour.stops().size();
        for (int c = 0; c < cases; ++c) {
            int index = c;
            String name;
            DemoState demo;
            if (c < demos.size()) {
                demo = demos.get(c);
                name = "demo " + DemoCatalog.names().get(c);
            } else {
                int stop = c - demos.size();
                demo = harness.call(() -> {
                    app.getTour().go(stop);
                    // The switch happens at the switcher's next update: without it the stop
                    // could be checked on the demo shown before (a race with the app's frames).
                    app.getSwitcher().update(0f);
                    return app.getSwitcher().getSelected();
                });
                assertEquals(DemoCatalog.indexOf(LectureTour.stops().get(stop).getDemo()),
                        demos.indexOf(demo), "tour stop " + (stop + 1) + "'s demo");
                name = "tour stop " + (stop + 1);
            }
            problems.addAll(runCase(demo, name, index, full));
        }
        harness.call(() -> {
            app.getTour().leave();
            return true;
        });
        assertEquals(List.of(), problems.subList(0, Math.min(40, problems.size())),
                problems.size() + " problems");
    }

    /**
     * The scenes issue 29 §3 names, at the frame its screenshots show (200 frames: every
     * shot of drag and pull has landed, trails drawn in full): no overlap, and every sphere
     * a viewer sees keeps its label (drag's linear-drag sphere had none at 1280x720, with
     * and without the RK4 lane, its every slot touching a trail), and a sphere that rolled
     * beyond the scene's side (clip's physics target) keeps its label at that side.
     */
    @Test
    void theIssuesScenesKeepEveryLabelClearOrPlatedAfterTheLanding() throws Exception {
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        // demo, lane (-1: the default), window, presenting, frames
        Object[][] cases = {
            {"drag", -1, 1280, 720, false, LANDED_FRAMES},
            {"drag", ComparisonLane.Kind.RK4.ordinal(), 1280, 720, false, LANDED_FRAMES},
            // "slide code" and "ball" on one sphere: one joined label names both
            {"pull", ComparisonLane.Kind.SLIDE.ordinal(), 1280, 720, false, LANDED_FRAMES},
            {"pull", ComparisonLane.Kind.SLIDE.ordinal(), 640, 360, false, LANDED_FRAMES},
            {"spring", -1, 1920, 1080, true, LANDED_FRAMES},
            {"aiming", -1, 1280, 720, false, LANDED_FRAMES},
            // "lecture" and "discrete" landed on one spot
            {"aiming", -1, 1280, 720, false, AIMING_LANDED_FRAMES},
            {"aiming", -1, 640, 360, false, AIMING_LANDED_FRAMES},
            // "gun" on its shots' trails, the targets' names over or under them
            {"iterate", -1, 1280, 720, false, ITERATE_FRAMES},
            {"iterate", -1, 640, 360, false, ITERATE_FRAMES},
            // the physics lane's target has rolled to x = 21 m, beyond the framed 9.5 m
            {"clip", -1, 1280, 720, false, LANDED_FRAMES},
            {"drag", -1, 640, 360, false, LANDED_FRAMES},
            {"drag", -1, 3840, 2160, true, LANDED_FRAMES},
        };
        for (Object[] c : cases) {
            DemoState demo = app.getSwitcher().getDemos().get(
                    DemoCatalog.names().indexOf((String) c[0]));
            int lane = (Integer) c[1];
            int width = (Integer) c[2];
            int height = (Integer) c[3];
            boolean presenting = (Boolean) c[4];
            int frames = (Integer) c[5];
            String where = c[0] + (lane >= 0 ? " lane " + ComparisonLane.Kind.values()[lane]
                    : "") + " " + width + "x" + height + (presenting ? " presenting" : "")
                    + " frame " + frames;
            problems.addAll(harness.call(() -> {
                demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
                demo.getClock().setPaused(false);
                float laneBefore = lane >= 0
                        ? demo.getParameters().getValue(ComparisonLane.PARAMETER) : 0f;
                if (lane >= 0) {
                    demo.getParameters().set(ComparisonLane.PARAMETER, lane);
                }
                demo.restart();
                demo.getDemoHud().setPresenting(presenting);
                demo.getDemoHud().layOut(width, height);
                for (int f = 0; f < frames; ++f) {
                    demo.update(H);
                }
                demo.update(0f);
                List<String> found = OverlapProbe.check(demo, width, height, where);
                found.addAll(OverlapProbe.labelsAboveTheGround(demo, where));
                if (lane >= 0) {
                    demo.getParameters().set(ComparisonLane.PARAMETER, laneBefore);
                    demo.restart();
                }
                demo.getDemoHud().setPresenting(false);
                demo.getDemoHud().layOut(1280, 720);
                return found;
            }));
        }
        assertEquals(List.of(), problems);
    }

    /**
     * Aiming with the longer step its page recommends ({@code --set h=1/10}): both shots land
     * at the foot of the target's post, and from the landing on no label drops into the
     * footer band nor covers anything (issue 29 §3: "discrete" lay under the ground marks,
     * beside the footer, at 1280x720 and 640x360), sampled every 20 frames from frame 200
     * (the shots land near frame 300) to 400.
     */
    @Test
    void aimingWithTheLongerStepKeepsItsLabelsOutOfTheFooterBand() throws Exception {
        ParticleLabApp app = harness.app();
        DemoState demo = app.getSwitcher().getDemos().get(DemoCatalog.names().indexOf("aiming"));
        List<String> problems = new ArrayList<>();
        for (int[] window : new int[][] {{1280, 720}, {640, 360}}) {
            problems.addAll(harness.call(() -> {
                List<String> found = new ArrayList<>();
                float hBefore = demo.getParameters().getValue("h");
                demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
                demo.getClock().setPaused(false);
                demo.getParameters().set("h", 0.1f);
                demo.restart();
                demo.getDemoHud().layOut(window[0], window[1]);
                for (int f = 1; f <= AIMING_LANDED_FRAMES; ++f) {
                    demo.update(H);
                    if (f >= LANDED_FRAMES && f % 20 == 0) {
                        demo.update(0f);
                        String where = "aiming h=1/10 " + window[0] + "x" + window[1]
                                + " frame " + f;
                        found.addAll(OverlapProbe.check(demo, window[0], window[1], where));
                        found.addAll(OverlapProbe.labelsAboveTheFooterBand(demo, where));
                    }
                }
                demo.getParameters().set("h", hBefore);
                demo.restart();
                demo.getDemoHud().layOut(1280, 720);
                return found;
            }));
        }
        assertEquals(List.of(), problems);
    }

    /**
     * Tour stop 1 (targets) presenting at 1280x720, sampled every 10 frames from 240 to 360
     * (the shot rolls back to the gun near frame 300): no label covers the gun's grey
     * platform nor a target, spheres the demo draws beside its particles (issue 29 §3:
     * "shot" lay over the platform).
     */
    @Test
    void targetsStopKeepsTheShotsLabelOffThePlatform() throws Exception {
        ParticleLabApp app = harness.app();
        List<String> problems = harness.call(() -> {
            app.getTour().go(0);
            app.getSwitcher().update(0f);
            DemoState demo = app.getSwitcher().getSelected();
            List<String> found = new ArrayList<>();
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.getClock().setPaused(false);
            demo.restart();
            demo.getDemoHud().setPresenting(true);
            demo.getDemoHud().layOut(1280, 720);
            for (int f = 1; f <= 360; ++f) {
                demo.update(H);
                if (f >= 240 && f % 10 == 0) {
                    demo.update(0f);
                    found.addAll(OverlapProbe.check(demo, 1280, 720,
                            "tour stop 1 1280x720 presenting frame " + f));
                }
            }
            demo.getDemoHud().setPresenting(false);
            demo.getDemoHud().layOut(1280, 720);
            app.getTour().leave();
            return found;
        });
        assertEquals(List.of(), problems);
    }

    /**
     * The collisions demo's impulse labels keep off the trails as drawn, in every preset
     * (issue 29 §3: "impulse labels over trails"), sampled every {@value #IMPULSE_SAMPLE}
     * frames through the contacts of the first {@value #IMPULSE_FRAMES} frames (a label is
     * held {@code ContactImpulses.HOLD_SECONDS}, longer than a sample's gap), at the default
     * window and the smallest.
     */
    @Test
    void impulseLabelsKeepOffTheTrailsInEveryPreset() throws Exception {
        ParticleLabApp app = harness.app();
        CollisionsDemo demo = (CollisionsDemo) app.getSwitcher().getDemos().get(
                DemoCatalog.names().indexOf("collisions"));
        List<String> problems = new ArrayList<>();
        int presets = CollisionsDemo.PRESET_NAMES.length;
        for (int preset = 0; preset < presets; ++preset) {
            for (int[] window : new int[][] {{1280, 720}, {640, 360}}) {
                int chosen = preset;
                String name = "collisions " + CollisionsDemo.PRESET_NAMES[preset] + " "
                        + window[0] + "x" + window[1];
                problems.addAll(harness.call(() -> {
                    List<String> found = new ArrayList<>();
                    demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
                    demo.getClock().setPaused(false);
                    demo.getParameters().set("preset", chosen);
                    demo.restart();
                    demo.getDemoHud().layOut(window[0], window[1]);
                    for (int f = 0; f < IMPULSE_FRAMES; f += IMPULSE_SAMPLE) {
                        for (int i = 0; i < IMPULSE_SAMPLE; ++i) {
                            demo.update(H);
                        }
                        demo.update(0f);
                        found.addAll(OverlapProbe.impulseLabelsClearOfTrails(demo,
                                name + " frame " + (f + IMPULSE_SAMPLE)));
                    }
                    return found;
                }));
            }
        }
        harness.call(() -> {
            demo.getParameters().set("preset", 0);
            demo.restart();
            demo.getDemoHud().layOut(1280, 720);
            return true;
        });
        assertEquals(List.of(), problems.subList(0, Math.min(20, problems.size())),
                problems.size() + " problems");
    }

    /**
     * Run one case's physics and check its frames in the configurations it takes, each piece
     * in a call of its own on jME's thread (a call has a time limit).
     */
    private static List<String> runCase(DemoState demo, String name, int index, boolean full)
            throws Exception {
        List<String> problems = new ArrayList<>();
        harness.call(() -> {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.getClock().setPaused(false);
            demo.restart();
            return true;
        });
        int done = 0;
        for (int sample : full ? FULL_FRAMES : CI_FRAMES) {
            int frames = sample - done;
            done = sample;
            harness.call(() -> {
                for (int f = 0; f < frames; ++f) {
                    demo.update(H);
                }
                return true;
            });
            for (int k = 0; k < (full ? CONFIGURATIONS : CI_CONFIGURATIONS); ++k) {
                // In CI, case i takes configuration i (mod 16): consecutive cases walk the
                // matrix, so every size, mode and panel state is met.
                int configuration = full ? k : (CI_CONFIGURATIONS * index + k) % CONFIGURATIONS;
                int[] window = WINDOWS[configuration / 4];
                boolean presenting = (configuration & 2) != 0;
                boolean panel = (configuration & 1) != 0;
                String where = name + " " + window[0] + "x" + window[1]
                        + (presenting ? " presenting" : "") + (panel ? " panel" : "")
                        + " frame " + sample;
                problems.addAll(harness.call(() -> {
                    demo.getDemoHud().setPresenting(presenting);
                    OverlapProbe.setPanel(demo, panel);
                    demo.getDemoHud().layOut(window[0], window[1]);
                    demo.update(0f);
                    return OverlapProbe.check(demo, window[0], window[1], where);
                }));
            }
        }
        harness.call(() -> {
            demo.getDemoHud().setPresenting(false);
            OverlapProbe.setPanel(demo, false);
            demo.getDemoHud().layOut(1280, 720);
            return true;
        });
        return problems;
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.app.state.AppStateManager;
import com.jme3.renderer.RenderManager;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.coursework.StudentRunner;
import particlelab.demo.ComparisonLane;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.EnergyPart;
import particlelab.demo.LensPart;
import particlelab.lecture.DragDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.physics.SimulationClock;

/**
 * A whole frame of every catalogued demo, in a real headless application, allocates nothing
 * on the render thread while things move and the HUD's numbers change: the steps of jME's
 * {@code SimpleApplication.update()} as the window's loop runs them (every AppState's update,
 * the demo's steps, views, HUD text and panel, the scene's logical and geometric state, and
 * the render manager's pass over the viewports; see {@link #frame}), measured with the
 * thread's allocation counter. Tested with the HUD refreshed every frame (the default: it
 * shows the frame it is drawn on) and at the slower 10 Hz a demo may choose, with the
 * inspector open on the demo's first body.
 *
 * <p>The tests of {@code advance} and {@code formatHud} alone could not see the HUD text
 * handed to jME, which made about 12 KB per frame in the fountain.
 */
class FrameAllocationHeadlessTest {

    private static final float H = 1f / 60f;
    /** Frames per measured window: one HUD refresh of 0.1 s at 60 frames per second. */
    private static final int FRAMES_PER_WINDOW = 6;
    private static final int WINDOWS = 20;
    /**
     * A small window (pixels), where HUD lines at a large HUD factor wrap. The factor is not
     * the largest: since issue 19 nothing shrinks the text the user chose, and at x2 the band
     * holds only the equations, so the HUD would not change at all.
     */
    private static final float LARGE_FACTOR = 1.5f;
    /** A small window (pixels), where HUD lines at {@link #LARGE_FACTOR} wrap. */
    private static final int SMALL_WIDTH = 800;
    private static final int SMALL_HEIGHT = 600;
    /**
     * Warm-up before measuring: at least this many frames, 12 s of flight, so the JIT has
     * compiled the path and the buffers that grow to a flight's length (the export's rows,
     * doubling from 256 steps) have grown, as they do once in the window's first flights.
     */
    private static final int MIN_WARM_UP_FRAMES = 720;
    /**
     * And at most this many, while a window still allocates: code the JIT has not compiled
     * yet allocates where its compiled form does not (jME's input manager iterates a map
     * with a new iterator until escape analysis removes it).
     */
    private static final int MAX_WARM_UP_FRAMES = 1800;
    /** Windows per warm-up call. */
    private static final int WARM_UP_WINDOWS = 10;
    /** Frames run unmeasured after a restart (its panel and legend update allocate once). */
    private static final int FRAMES_AFTER_RESTART = 3;
    /**
     * Frame times (in seconds) a window at the raw tpf cycles through: a real window's frames
     * are never all the same length, so h differs from one refire to the next.
     */
    private static final float[] WOBBLING_TPF = {H, 1.1f * H, 0.9f * H, 1.05f * H};
    /**
     * Windows of the cheat measured at the raw tpf: 12 s, several refires (each shot flies
     * under a second, then rests {@link FastBulletsDemo#REFIRE_SECONDS}).
     */
    private static final int CHEAT_WINDOWS = 120;
    /** The demos with the derivative lens. */
    private static final List<String> LENS_DEMOS = List.of("uniform", "pull", "drag", "thrust");

    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    private static final List<DemoState> demos = DemoCatalog.createAll();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> demos);
    /** True while the demos are measured in presentation mode (F8, --present). */
    private static boolean presenting;
    /** True while the demos are measured with the energy ledger's bars on. */
    private static boolean energyOn;

    @BeforeAll
    static void startApp() throws Exception {
        // Every demo runs once before any is measured: the code they share (the world, views,
        // HUD, jME's scene graph) is compiled by then, so the first demo measured does not
        // catch the JIT recompiling it for the next demo's paths.
        for (int i = 0; i < demos.size(); ++i) {
            int index = i;
            harness.call(() -> begin(index, DemoState.SLOW_HUD_REFRESH_SECONDS, 0, 0));
            for (int frames = 0; frames < MIN_WARM_UP_FRAMES;
                    frames += WARM_UP_WINDOWS * FRAMES_PER_WINDOW) {
                harness.call(() -> warmUp(demos.get(index)));
            }
            harness.call(() -> end(demos.get(index)));
        }
    }

    @Test
    void everyDemosRunningFrameAllocatesNothing() throws Exception {
        assertEquals(List.of(), measureAll(DemoState.SLOW_HUD_REFRESH_SECONDS, 0, 0,
                new int[1]));
    }

    @Test
    void everyDemosRunningFrameAllocatesNothingWithTheHudRefreshedEveryFrame()
            throws Exception {
        // Every frame is the default: the HUD shows the frame it is drawn on.
        assertEquals(0f, DemoState.HUD_REFRESH_SECONDS);
        assertEquals(List.of(), measureAll(DemoState.HUD_REFRESH_SECONDS, 0, 0, new int[1]));
    }

    /**
     * In a small window with the HUD's text enlarged all the way (a lecture hall's back row),
     * the HUD's lines are wrapped to its width at every refresh: that too allocates nothing,
     * with the HUD refreshed every frame.
     */
    @Test
    void aSmallWindowsWrappedHudAllocatesNothingRefreshedEveryFrame() throws Exception {
        int[] wrapped = new int[1];
        assertEquals(List.of(), measureAll(0f, SMALL_WIDTH, SMALL_HEIGHT, wrapped));
        // The test means something only if the window is small enough to wrap some HUDs.
        assertTrue(wrapped[0] >= 1, wrapped[0] + " demos wrapped their HUD");
    }

    /**
     * Presentation mode (F8, {@code --present}): the slide written every frame and shown in
     * large type, refreshed every frame, allocates nothing either.
     */
    @Test
    void presentationModesFrameAllocatesNothingRefreshedEveryFrame() throws Exception {
        presenting = true;
        try {
            assertEquals(List.of(), measureAll(0f, 0, 0, new int[1]));
        } finally {
            presenting = false;
        }
    }

    /**
     * The energy ledger's bars on ({@code --set energy=on}): the strip beside the scene, its
     * bars and values rewritten every frame, in a demo of each kind of column (drag, impacts,
     * a spring, a clip's script), laid out at the window's size and in a small window at a
     * large HUD factor, allocate nothing.
     */
    @Test
    void theEnergyBarsFrameAllocatesNothing() throws Exception {
        energyOn = true;
        try {
            List<String> problems = new ArrayList<>();
            for (int i = 0; i < demos.size(); ++i) {
                String name = DemoCatalog.names().get(i);
                if (name.equals("drag") || name.equals("bounce") || name.equals("spring")
                        || name.equals("clip")) {
                    problems.addAll(measureOne(i, 0f, 0, 0));
                    if (name.equals("bounce")) {
                        problems.addAll(measureOne(i, 0f, SMALL_WIDTH, SMALL_HEIGHT));
                    }
                }
            }
            assertEquals(List.of(), problems);
        } finally {
            energyOn = false;
        }
    }

    /**
     * A tour question asked (F4) and its scene running: each frame the guide checks the demo
     * shown is still the stop's, and the overlay stands over the scene; neither allocates. The
     * check found the stop's demo by name every frame, a string per demo passed: 2592 bytes per
     * window here, 1296 in CI's random-input run (seed 48).
     */
    @Test
    void aTourQuestionsFrameAllocatesNothing() throws Exception {
        TourGuide tour = harness.app().getTour();
        int stop = 0;
        while (TourQuestions.forStop(stop) == null
                || DemoCatalog.indexOf(LectureTour.stops().get(stop).getDemo()) == 0) {
            // Past a stop without a question; and the catalogue's first demo is found by its
            // name before any number is written, so its stop could not show the fault.
            ++stop;
        }
        int index = DemoCatalog.indexOf(LectureTour.stops().get(stop).getDemo());
        DemoState demo = demos.get(index);
        int questionStop = stop;
        List<String> problems = new ArrayList<>();
        harness.call(() -> begin(index, 0f, 0, 0));
        try {
            harness.call(() -> {
                tour.go(questionStop);
                tour.advanceQuestion();
                // As Space does: the scene runs under the question (F4 would stop it at the
                // answer, and a measured window must move).
                demo.getClock().setPaused(false);
                frame();
                return true;
            });
            assertTrue(harness.call(() -> tour.getVote() != null && harness.app()
                    .getSwitcher().getSelected() == demo), "the question is asked");
            warmUpAndMeasure(index, problems);
            assertTrue(harness.call(() -> tour.getVote() != null), "the question stayed");
        } finally {
            harness.call(() -> {
                tour.leave();
                return end(demo);
            });
        }
        assertEquals(List.of(), problems);
    }

    /**
     * The derivative lens on ({@code --set lens=on}, key O) in the free-flight demos: each
     * frame retakes the shown step, runs the exact path for h/2, points four arrows and
     * rewrites four HUD lines, refreshed every frame; none of it allocates.
     */
    @Test
    void theDerivativeLensFrameAllocatesNothing() throws Exception {
        List<String> problems = new ArrayList<>();
        for (int i = 0; i < demos.size(); ++i) {
            if (!LENS_DEMOS.contains(DemoCatalog.names().get(i))) {
                continue;
            }
            DemoState demo = demos.get(i);
            // A live parameter: it stays on through begin's reset.
            harness.call(() -> setLens(demo, 1f));
            try {
                problems.addAll(measureOne(i, 0f, 0, 0));
            } finally {
                harness.call(() -> setLens(demo, 0f));
            }
        }
        assertEquals(List.of(), problems);
    }

    /**
     * The drag demo's student lane running the reference solution (issue 31 §3): each step
     * hands the recipe's call to a worker thread and waits for it, and the HUD gives the
     * lane's readouts; the demo's thread allocates nothing for that either.
     */
    @Test
    void theStudentLanesFrameAllocatesNothing() throws Exception {
        int index = -1;
        for (int i = 0; i < demos.size(); ++i) {
            if (demos.get(i) instanceof DragDemo) {
                index = i;
            }
        }
        assertTrue(index >= 0, "drag is catalogued");
        DragDemo drag = (DragDemo) demos.get(index);
        int dragIndex = index;
        int lane = drag.getParameters().indexOf(ComparisonLane.PARAMETER);
        harness.call(() -> begin(dragIndex, 0f, 0, 0));
        try {
            harness.call(() -> {
                drag.getLane().useStudentClass("particlelab.solutions.Recipe",
                        StudentRunner.DEFAULT_LIMIT_NANOS);
                drag.getParameters().set(lane, ComparisonLane.Kind.STUDENT.ordinal());
                restart(drag);
                return true;
            });
            for (int frames = 0; frames < MIN_WARM_UP_FRAMES;
                    frames += WARM_UP_WINDOWS * FRAMES_PER_WINDOW) {
                harness.call(() -> warmUp(drag));
            }
            assertEquals("", harness.call(() -> measure(dragIndex)));
            // the recipe ran all along (jME's task result may not be null: "null" for none)
            assertEquals("null", harness.call(() -> String.valueOf(
                    drag.getLane().getStudentProblem())));
        } finally {
            harness.call(() -> {
                drag.getParameters().set(lane, ComparisonLane.Kind.OFF.ordinal());
                drag.getLane().useStudentClass(StudentRunner.className("Recipe"),
                        StudentRunner.DEFAULT_LIMIT_NANOS);
                return end(drag);
            });
        }
    }

    /**
     * The cheat at the raw tpf (the lecture's loop: h is the frame's time), its frame time
     * wobbling as a real window's does: each refire works the four ways out for the new h,
     * in place. It made a new {@code CheatFrontier} per refire, which the fixed-step tests
     * above never saw (h never changed there).
     */
    @Test
    void cheatRefiringAtTheRawTpfAllocatesNothing() throws Exception {
        int index = -1;
        for (int i = 0; i < demos.size(); ++i) {
            if (demos.get(i) instanceof FastBulletsDemo) {
                index = i;
            }
        }
        assertTrue(index >= 0, "the cheat is catalogued");
        FastBulletsDemo cheat = (FastBulletsDemo) demos.get(index);
        int cheatIndex = index;
        harness.call(() -> begin(cheatIndex, 0f, 0, 0));
        try {
            harness.call(() -> {
                cheat.getClock().setMode(SimulationClock.Mode.RAW_TPF);
                return true;
            });
            int[] frameCount = new int[1];
            // Warm-up with refires in it: the JIT compiles the refire's path too.
            for (int frames = 0; frames < MIN_WARM_UP_FRAMES;
                    frames += WARM_UP_WINDOWS * FRAMES_PER_WINDOW) {
                harness.call(() -> {
                    for (int w = 0; w < WARM_UP_WINDOWS; ++w) {
                        wobblingWindow(frameCount);
                    }
                    return true;
                });
            }
            long[] bytes = new long[CHEAT_WINDOWS];
            int refires = 0;
            int allocating = 0;
            boolean reached = cheat.isReached();
            for (int w = 0; w < CHEAT_WINDOWS; ++w) {
                bytes[w] = harness.call(() -> wobblingWindow(frameCount));
                if (bytes[w] != 0L) {
                    ++allocating;
                }
                // A refire: the shot that had reached the disc's plane is fired again.
                if (reached && !cheat.isReached()) {
                    ++refires;
                }
                reached = cheat.isReached();
            }
            // The test means something only if the demo refired while measured (each at the
            // h of its frame, which the wobble changes).
            assertTrue(refires >= 3, refires + " refires");
            // At most one window may allocate, a one-off of the JVM's (see measure).
            assertTrue(allocating <= 1, allocating + " of " + CHEAT_WINDOWS + " windows with "
                    + refires + " refires allocated " + Arrays.toString(bytes) + " bytes");
        } finally {
            harness.call(() -> {
                cheat.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
                return end(cheat);
            });
        }
    }

    /**
     * Measure each demo in turn; return a line for each that allocated or did not move.
     *
     * @param width the window to lay the HUD out for (in pixels), 0 for the application's
     * @param wrapped storage: counts the demos whose body was wrapped (modified)
     */
    private static List<String> measureAll(float hudRefreshSeconds, int width, int height,
            int[] wrapped) throws Exception {
        List<String> problems = new ArrayList<>();
        for (int i = 0; i < demos.size(); ++i) {
            int index = i;
            harness.call(() -> begin(index, hudRefreshSeconds, width, height));
            try {
                warmUpAndMeasure(index, problems);
                if (harness.call(() -> isBodyWrapped(demos.get(index)))) {
                    ++wrapped[0];
                }
            } finally {
                harness.call(() -> end(demos.get(index)));
            }
        }
        return problems;
    }

    /** Measure one demo as {@link #measureAll} does each. */
    private static List<String> measureOne(int index, float hudRefreshSeconds, int width,
            int height) throws Exception {
        List<String> problems = new ArrayList<>();
        harness.call(() -> begin(index, hudRefreshSeconds, width, height));
        try {
            warmUpAndMeasure(index, problems);
        } finally {
            harness.call(() -> end(demos.get(index)));
        }
        return problems;
    }

    /** Warm a demo up, then measure it; a problem found goes into the list. */
    private static void warmUpAndMeasure(int index, List<String> problems) throws Exception {
        // Warm up in calls of a few windows each, so none outlasts the harness's wait.
        int frames = 0;
        boolean quiet = false;
        while (frames < MAX_WARM_UP_FRAMES && !(quiet && frames >= MIN_WARM_UP_FRAMES)) {
            quiet = harness.call(() -> warmUp(demos.get(index)));
            frames += WARM_UP_WINDOWS * FRAMES_PER_WINDOW;
        }
        String problem = harness.call(() -> measure(index));
        if (!problem.isEmpty()) {
            problems.add(problem);
        }
    }

    /**
     * Switch to a demo and start it moving at a fixed tpf, the HUD at a refresh rate and laid
     * out for a window resized to a size at a large HUD factor (width 0: as it is).
     */
    private static Boolean begin(int index, float hudRefreshSeconds, int width, int height) {
        DemoState demo = demos.get(index);
        harness.app().getSwitcher().select(index);
        // As F8 does: the window's controls put the demo shown in the mode at its next frame.
        harness.app().getWindowControls().setPresenting(presenting);
        if (width > 0) {
            // As the window's resize and the HUD-factor key do: the window's controls lay
            // the demo out again at its next frame.
            resize(width, height);
            harness.app().getWindowControls().setUiFactor(LARGE_FACTOR);
        }
        if (energyOn) {
            demo.getParameters().set(demo.getParameters().indexOf(EnergyPart.PARAMETER), 1);
        }
        frame();
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        demo.getClock().setPaused(false);
        demo.getDemoHud().setRefreshSeconds(hudRefreshSeconds);
        // The inspector open on the first body shown: its numbers change every frame too.
        for (DemoParticle particle : demo.getParticles()) {
            if (!particle.isParked()) {
                demo.getWindow().getDragControl().inspect(particle);
                break;
            }
        }
        restart(demo);
        return true;
    }

    /** Put the HUD's refresh rate, the window's size and the HUD factor back. */
    private static Boolean end(DemoState demo) {
        demo.getWindow().getDragControl().clearPick();
        demo.getParameters().set(demo.getParameters().indexOf(EnergyPart.PARAMETER), 0);
        demo.getDemoHud().setRefreshSeconds(DemoState.HUD_REFRESH_SECONDS);
        resize(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
        harness.app().getWindowControls().setUiFactor(1f);
        harness.app().getWindowControls().setPresenting(false);
        frame();
        return true;
    }

    /** Switch the derivative lens ({@code --set lens=...}): 1 on, 0 off. */
    private static Boolean setLens(DemoState demo, float value) {
        demo.getParameters().set(LensPart.PARAMETER, value);
        return true;
    }

    /** Resize the scene's and the GUI's cameras, as a resized window does. */
    private static void resize(int width, int height) {
        harness.app().getCamera().resize(width, height, true);
        harness.app().getGuiViewPort().getCamera().resize(width, height, true);
    }

    /** @return true if the body shown is the HUD's text wrapped, not the text itself */
    private static Boolean isBodyWrapped(DemoState demo) {
        return !demo.getWindow().getHud().getBodyText()
                .equals(demo.getWindow().formatHud(new StringBuilder())
                .toString());
    }

    /** Run a few windows unmeasured; return true if the last allocated nothing. */
    private static boolean warmUp(DemoState demo) {
        long bytes = 0L;
        for (int w = 0; w < WARM_UP_WINDOWS; ++w) {
            bytes = window(demo);
        }
        return bytes == 0L;
    }

    /**
     * Measure a demo's windows and check them: each must advance the simulation, the HUD's
     * text must change, and at most one window may allocate (a one-off of the JVM's, as
     * {@code ExactGhostsHeadlessTest} allows: a method recompiled after a deoptimisation
     * runs interpreted for a while). Allocation per frame shows in every window.
     *
     * @return empty if fine, else what went wrong (not null: jME's task result must not be)
     */
    private static String measure(int index) {
        DemoState demo = demos.get(index);
        long[] bytes = new long[WINDOWS];
        double[] simulated = new double[WINDOWS];
        int textChanges = demo.getWindow().getHud().countTextChanges();
        int allocating = 0;
        for (int w = 0; w < WINDOWS; ++w) {
            if (demo.getRun().isSceneOver()) {
                restart(demo);
            }
            double before = demo.getClock().getSimulatedSeconds();
            bytes[w] = window(demo);
            simulated[w] = demo.getClock().getSimulatedSeconds() - before;
            if (bytes[w] != 0L) {
                ++allocating;
            }
        }
        textChanges = demo.getWindow().getHud().countTextChanges() - textChanges;
        String name = (index + 1) + ". " + demo.getTitle();
        if (allocating > 1) {
            return name + ": " + allocating + " of " + WINDOWS + " windows of "
                    + FRAMES_PER_WINDOW + " frames allocated " + Arrays.toString(bytes)
                    + " bytes";
        }
        for (int w = 0; w < WINDOWS; ++w) {
            if (!(simulated[w] > 0.0)) {
                return name + ": nothing moved in window " + w + " "
                        + Arrays.toString(simulated);
            }
        }
        if (presenting != demo.getDemoHud().isPresenting()) {
            return name + ": presentation mode " + demo.getDemoHud().isPresenting() + ", asked "
                    + presenting;
        }
        // A slide's one readout may rightly stand still (no impact yet): checked in the HUD.
        if (!presenting && textChanges < WINDOWS / 2) {
            return name + ": the HUD's text changed only " + textChanges + " times in "
                    + WINDOWS + " windows";
        }
        return "";
    }

    /**
     * Run one window of whole frames and return what they allocated. A scene that is over
     * (every particle landed) is restarted first, outside the window.
     */
    private static long window(DemoState demo) {
        if (demo.getRun().isSceneOver()) {
            restart(demo);
        }
        long bytes = 0L;
        for (int frame = 0; frame < FRAMES_PER_WINDOW; ++frame) {
            bytes += frame();
        }
        return bytes;
    }

    private static void restart(DemoState demo) {
        demo.restart();
        for (int frame = 0; frame < FRAMES_AFTER_RESTART; ++frame) {
            frame();
        }
    }

    /**
     * Run one frame of jME's {@code SimpleApplication.update()}, step by step at the fixed
     * tpf, and return what it allocated: every AppState's update (the demo's steps, views, HUD
     * text and panel), the scene graph's logical and geometric state, and the render pass.
     * Only jME's input poll runs before the measurement: {@code InputManager.invokeUpdateActions}
     * makes two map iterators a frame (64 bytes), which C2's escape analysis removes in some
     * runs and not in others, depending on what it inlined; that is jME's code, not the app's.
     *
     * @return the bytes allocated (&ge;0)
     */
    private static long frame() {
        return frame(H);
    }

    /**
     * Run one window of whole frames at the wobbling tpf, the frames counted on from where
     * the last window stopped.
     *
     * @param frameCount the frames run so far, which picks each frame's tpf (modified)
     * @return the bytes allocated (&ge;0)
     */
    private static long wobblingWindow(int[] frameCount) {
        long bytes = 0L;
        for (int frame = 0; frame < FRAMES_PER_WINDOW; ++frame) {
            bytes += frame(WOBBLING_TPF[frameCount[0] % WOBBLING_TPF.length]);
            ++frameCount[0];
        }
        return bytes;
    }

    /**
     * Run one frame as {@link #frame()} does, at a given tpf.
     *
     * @param tpf the frame's time (in seconds, &gt;0)
     * @return the bytes allocated (&ge;0)
     */
    private static long frame(float tpf) {
        ParticleLabApp app = harness.app();
        app.getInputManager().update(tpf);
        long start = THREADS.getCurrentThreadAllocatedBytes();
        AppStateManager states = app.getStateManager();
        RenderManager render = app.getRenderManager();
        states.update(tpf);
        app.simpleUpdate(tpf);
        app.getRootNode().updateLogicalState(tpf);
        app.getGuiNode().updateLogicalState(tpf);
        app.getRootNode().updateGeometricState();
        app.getGuiNode().updateGeometricState();
        states.render(render);
        render.render(tpf, app.getContext().isRenderable());
        app.simpleRender(render);
        states.postRender();
        return THREADS.getCurrentThreadAllocatedBytes() - start;
    }
}

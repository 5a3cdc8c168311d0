package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.app.state.AppStateManager;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.MouseInput;
import com.jme3.input.event.KeyInputEvent;
import com.jme3.input.event.MouseButtonEvent;
import com.jme3.input.event.MouseMotionEvent;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.scene.control.AbstractControl;
import java.lang.management.ManagementFactory;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.IntPredicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;
import particlelab.physics.SimulationClock;

/**
 * Issue 36: a careless user's input (keys, mouse drags, resizes, F2 and F8 in any order)
 * ended the window. Here every catalogue demo, in a real headless application, takes a seeded
 * random sequence of actions through jME's input manager and the app's own entry points: its
 * own and the application's keys (but E, which writes files, and F11, which needs a display),
 * bursts of Home and End (the replay's step back and forward) in one frame, Shift+Home,
 * Shift+End and Shift+Tab, mouse drags and clicks, resizes from 200x150 to 3840x2160, demo
 * switches, the panel (F2) and presentation mode (F8), with whole frames of jME's loop
 * between. Nothing may throw, the HUD shows no NaN or infinity, and afterwards a frame still
 * allocates nothing, moving: of the demo a switch left on screen, if one did, and of the demo.
 *
 * <p>On a failure the message names the seed, the demo, the action that failed, and the
 * shortest prefix of the demo's actions that fails again from a fresh start of the demo,
 * found by bisection ({@link #shortestFailingPrefix}).
 *
 * <p>The budget is short in CI; the environment variable {@value #ACTIONS_VARIABLE} sets the
 * actions per demo for a long run, and {@value #SEED_VARIABLE} the first demo's seed
 * (docs/testing.md).
 */
class RandomInputHeadlessTest {

    /** The environment variable that sets the actions per demo. */
    static final String ACTIONS_VARIABLE = "PARTICLELAB_RANDOM_ACTIONS";
    /** The environment variable that sets the seed of the first demo (the next: +1, ...). */
    static final String SEED_VARIABLE = "PARTICLELAB_RANDOM_SEED";
    /** The actions per demo in CI: a few seconds in all on an idle machine. */
    private static final int DEFAULT_ACTIONS = 12;
    private static final long DEFAULT_SEED = 36L;
    /** Actions per call on jME's thread, well within the harness's wait. */
    private static final int ACTIONS_PER_CALL = 4;
    private static final int FRAMES_PER_ACTION = 2;
    private static final float H = 1f / 60f;
    private static final int MIN_WIDTH = 200;
    private static final int MIN_HEIGHT = 150;
    private static final int MAX_WIDTH = 3840;
    private static final int MAX_HEIGHT = 2160;
    /** The most key presses in one burst of Home and End (within one frame). */
    private static final int MAX_BURST = 30;
    /** Mouse positions are drawn as a share of the window, in steps of 1/FRACTION. */
    private static final int FRACTION = 10_000;

    /** The kinds of action, drawn with the weights of {@link #KIND_WEIGHTS}. */
    private static final int KEY = 0;
    private static final int RESIZE = 1;
    private static final int DRAG = 2;
    private static final int CLICK = 3;
    private static final int PRESENT = 4;
    private static final int PANEL = 5;
    private static final int BURST = 6;
    private static final int SHIFT_KEY = 7;
    private static final int SWITCH = 8;
    /** Only injected by a test of the bisection: a view that throws on its next update. */
    private static final int FAIL = 9;
    /** How often each kind is drawn, out of their sum: keys the most. */
    private static final int[] KIND_WEIGHTS = {8, 3, 2, 2, 1, 1, 2, 1, 1};

    /**
     * Frames per measured window of the allocation check, and the windows: the least counts,
     * since a loaded JVM charges a window stray bytes of its own now and then (as in
     * {@code app.FrameAllocationHeadlessTest}); an allocation per frame shows in all of them.
     */
    private static final int FRAMES_PER_WINDOW = 6;
    private static final int MEASURED_WINDOWS = 5;
    /** Frames run before measuring: the paths of the state the input left are compiled. */
    private static final int WARM_UP_FRAMES = 120;
    /**
     * And at most this many, measuring again while every window allocates: code the JIT has
     * not compiled yet may allocate where its compiled form does not. The fountain's
     * vectorised step ({@code physics.VectorBatch}, the JDK's Vector API) boxes every
     * vector until C2 compiles it: on a loaded machine that showed as 4 to 44 MB per six
     * frames, growing with the fountain's particles, for its first 100 frames after a first
     * start, and 0 bytes from then on.
     */
    private static final int MAX_WARM_UP_FRAMES = 720;
    /**
     * HelloAiming's parameter that picks the bullets' code, and its value for the shared
     * recipe ({@code lecture.HelloAimingDemo.RECIPE_CODE}; the slide's listing allocates).
     */
    private static final String SLIDE_CODE_PARAMETER = "code";
    private static final float RECIPE_CODE = 0f;
    /** The comparison lane's choices: off, and the slide's own code (ComparisonLane.Kind). */
    private static final float LANE_OFF = ComparisonLane.Kind.OFF.ordinal();
    private static final float SLIDE_LANE = ComparisonLane.Kind.SLIDE.ordinal();
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    /**
     * One action as drawn: its kind and four random numbers, turned into keys, sizes and
     * positions only when it is carried out (against the demo then on screen), so that the
     * same list can be run again from the start, or any prefix of it.
     */
    record Action(int kind, int a, int b, int c, int d) {
    }

    @Test
    void everyDemoSurvivesASeededRandomSequenceOfInput() throws Exception {
        String budget = System.getenv(ACTIONS_VARIABLE);
        int actions = budget == null ? DEFAULT_ACTIONS : parsePositive(ACTIONS_VARIABLE, budget);
        String seedText = System.getenv(SEED_VARIABLE);
        long seed = seedText == null ? DEFAULT_SEED : parseSeed(seedText);
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        int count = app.getSwitcher().getDemos().size();
        for (int index = 0; index < count && problems.isEmpty(); ++index) {
            List<Action> drawn = draw(seed + index, actions);
            String problem = runFromFreshStart(index, drawn, drawn.size(), null);
            boolean allocation = problem.isEmpty();
            if (allocation) {
                int chosen = index;
                problem = allocationAfterwards(chosen);
            }
            if (!problem.isEmpty()) {
                problem = problem + "\n" + shortestPrefixReport(index, drawn, allocation);
            }
            if (!problem.isEmpty()) {
                problems.add("seed " + (seed + index) + ", demo " + (index + 1) + " ("
                        + app.getSwitcher().getDemos().get(index).getTitle() + "), "
                        + actions + " actions: " + problem);
            }
        }
        harness.call(() -> {
            restoreWindow(app);
            return true;
        });
        assertEquals(List.of(), problems);
    }

    /**
     * The bisection itself: a view made to throw at a known action (the 10th of 16) is found,
     * from a fresh start, as the failure of the shortest prefix of 10 actions, and the report
     * names it.
     */
    @Test
    void theBisectionFindsAnInjectedFailureAtItsAction() throws Exception {
        int injectedAt = 9;
        List<Action> drawn = new ArrayList<>(draw(DEFAULT_SEED, 16));
        drawn.set(injectedAt, new Action(FAIL, 0, 0, 0, 0));
        List<String> done = new ArrayList<>();
        String problem = runFromFreshStart(0, drawn, drawn.size(), done);
        assertTrue(problem.startsWith("action 10 of 16 (an injected failure): "
                + "java.lang.IllegalStateException: " + FailingView.MESSAGE), problem);
        assertEquals(10, done.size(), done.toString());
        int[] probes = new int[1];
        int shortest = shortestFailingPrefix(drawn.size(), prefix -> {
            ++probes[0];
            try {
                return !runFromFreshStart(0, drawn, prefix, null).isEmpty();
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        assertEquals(injectedAt + 1, shortest);
        // Bisection over 16 actions: log2(16) = 4 runs, where trying each prefix would take 10.
        assertEquals(4, probes[0]);
        String report = shortestPrefixReport(0, drawn, false);
        assertTrue(report.startsWith("the shortest failing prefix from a fresh start: "
                + "10 actions ["), report);
        assertTrue(report.endsWith(", an injected failure]"), report);
        harness.call(() -> {
            restoreWindow(harness.app());
            return true;
        });
    }

    /** The bisection's search alone, against failures at every place in a sequence. */
    @Test
    void theShortestFailingPrefixIsFoundInLogarithmicallyManyRuns() {
        for (int length = 1; length <= 40; ++length) {
            for (int failing = 1; failing <= length; ++failing) {
                int first = failing;
                int[] runs = new int[1];
                int found = shortestFailingPrefix(length, prefix -> {
                    ++runs[0];
                    return prefix >= first;
                });
                assertEquals(failing, found, "length " + length);
                // Each run halves the interval (0, length]: at most ceil(log2(length)) runs.
                int bound = 32 - Integer.numberOfLeadingZeros(length - 1);
                assertTrue(runs[0] <= bound, runs[0] + " runs for " + length + " actions");
            }
        }
    }

    /**
     * Find the shortest failing prefix of a sequence whose whole fails, by bisection: a
     * prefix that fails keeps failing when it grows (the same actions come first), so the
     * shortest is found in about log2(length) runs.
     *
     * @param length the sequence's length, whose whole fails (&ge;1)
     * @param fails runs a prefix of a length from a fresh start and says whether it failed
     * @return the shortest failing prefix's length (1 to length)
     */
    static int shortestFailingPrefix(int length, IntPredicate fails) {
        int passing = 0;
        int failing = length;
        while (failing - passing > 1) {
            int middle = (passing + failing) >>> 1;
            if (fails.test(middle)) {
                failing = middle;
            } else {
                passing = middle;
            }
        }
        return failing;
    }

    /**
     * Draw a demo's actions (no other randomness is used when they are carried out).
     *
     * @param seed the seed
     * @param count how many (&ge;0)
     * @return the actions (not null)
     */
    static List<Action> draw(long seed, int count) {
        Random random = new Random(seed);
        int total = 0;
        for (int weight : KIND_WEIGHTS) {
            total += weight;
        }
        List<Action> actions = new ArrayList<>(count);
        for (int i = 0; i < count; ++i) {
            int pick = random.nextInt(total);
            int kind = 0;
            while (pick >= KIND_WEIGHTS[kind]) {
                pick -= KIND_WEIGHTS[kind];
                ++kind;
            }
            actions.add(new Action(kind, random.nextInt(Integer.MAX_VALUE),
                    random.nextInt(Integer.MAX_VALUE), random.nextInt(Integer.MAX_VALUE),
                    random.nextInt(Integer.MAX_VALUE)));
        }
        return actions;
    }

    /**
     * Bisect a failing sequence of a demo and say what the shortest failing prefix is.
     *
     * @param allocation true if the failure is a frame's allocation afterwards, false if
     *     something went wrong during the actions
     */
    private static String shortestPrefixReport(int index, List<Action> drawn,
            boolean allocation) throws Exception {
        if (!fails(index, drawn, drawn.size(), allocation)) {
            return "it did not fail again from a fresh start of the demo: it depends on what"
                    + " ran before (the demos before it, or the JVM)";
        }
        int shortest = shortestFailingPrefix(drawn.size(), prefix -> {
            try {
                return fails(index, drawn, prefix, allocation);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        List<String> done = new ArrayList<>();
        runFromFreshStart(index, drawn, shortest, done);
        return "the shortest failing prefix from a fresh start: " + shortest + " actions "
                + done;
    }

    /**
     * Run a prefix of a demo's actions from a fresh start; say whether it fails as asked:
     * during the actions, or (allocation) by a frame's allocation afterwards.
     */
    private static boolean fails(int index, List<Action> drawn, int prefix,
            boolean allocation) throws Exception {
        String problem = runFromFreshStart(index, drawn, prefix, null);
        if (!allocation) {
            return !problem.isEmpty();
        }
        return problem.isEmpty() && !allocationAfterwards(index).isEmpty();
    }

    /**
     * Start a demo afresh (the window at its size, not presenting, the HUD factor 1, the panel
     * closed, the time scale 1, the demo restarted) and run a prefix of actions.
     *
     * @param done storage for what each action carried out was (modified), or null
     * @return "" or what went wrong, with the action's number
     */
    private static String runFromFreshStart(int index, List<Action> drawn, int prefix,
            List<String> done) throws Exception {
        ParticleLabApp app = harness.app();
        harness.call(() -> {
            restoreWindow(app);
            app.getSwitcher().select(index);
            return true;
        });
        harness.awaitFrames(FRAMES_PER_ACTION);
        harness.call(() -> {
            DemoState demo = app.getSwitcher().getSelected();
            if (demo.getParameterControls().isPanelVisible()) {
                HeadlessHarness.press(demo, "F2");
            }
            demo.getClock().setTimeScale(1f);
            demo.restart();
            frames(app, FRAMES_PER_ACTION);
            return true;
        });
        List<String> what = done == null ? new ArrayList<>() : done;
        for (int first = 0; first < prefix; first += ACTIONS_PER_CALL) {
            int from = first;
            int to = Math.min(prefix, first + ACTIONS_PER_CALL);
            String problem = harness.call(() -> act(drawn, from, to, prefix, what));
            if (!problem.isEmpty()) {
                return problem;
            }
        }
        return "";
    }

    /** Run actions [from, to) of a sequence of a length; return "" or what went wrong. */
    private static String act(List<Action> drawn, int from, int to, int length,
            List<String> done) {
        ParticleLabApp app = harness.app();
        for (int i = from; i < to; ++i) {
            String what;
            try {
                what = carryOut(app, drawn.get(i));
                done.add(what);
            } catch (RuntimeException e) {
                return "action " + (i + 1) + " of " + length + " (" + drawn.get(i) + "): " + e;
            }
            try {
                frames(app, FRAMES_PER_ACTION);
            } catch (RuntimeException e) {
                return "action " + (i + 1) + " of " + length + " (" + what + "): " + e;
            }
            if (app.getRecovered() != null) {
                return "action " + (i + 1) + " of " + length + " (" + what + "): "
                        + app.getRecovered();
            }
            String hud = app.getSwitcher().getSelected().getWindow().getHud().getBodyText();
            if (hud.contains("NaN") || hud.contains("Infinity")) {
                return "action " + (i + 1) + " of " + length + " (" + what
                        + "): the HUD shows " + hud;
            }
        }
        return "";
    }

    /**
     * Carry an action out against the demo on screen, through jME's input manager where a
     * user's input goes (its queue is read at the next frame's start), and return what it was.
     */
    private static String carryOut(ParticleLabApp app, Action action) {
        DemoState demo = app.getSwitcher().getSelected();
        InputManager input = app.getInputManager();
        int width = app.getCamera().getWidth();
        int height = app.getCamera().getHeight();
        switch (action.kind()) {
            case KEY: {
                List<KeyBinding> keys = new ArrayList<>(demo.getKeys().getBindings());
                keys.addAll(app.getSwitcher().getBindings());
                KeyBinding key = keys.get(action.a() % keys.size());
                int which = action.b() % key.countKeys();
                String label = key.getKeyLabel(which);
                if (label.equals("E") || label.equals("F11")) {
                    return "key " + label + " (skipped)";
                }
                pressKey(input, key.getKeyCode(which), false);
                return "key " + label;
            }
            case RESIZE: {
                int newWidth = MIN_WIDTH + action.a() % (MAX_WIDTH - MIN_WIDTH + 1);
                int newHeight = MIN_HEIGHT + action.b() % (MAX_HEIGHT - MIN_HEIGHT + 1);
                app.reshape(newWidth, newHeight);
                return "resize " + newWidth + "x" + newHeight;
            }
            case DRAG: {
                int x = share(action.a(), width);
                int y = share(action.b(), height);
                int toX = share(action.c(), width);
                int toY = share(action.d(), height);
                mouse(input, x, y, true);
                // A frame with the button held, then the move and the release.
                frames(app, 1);
                move(input, toX, toY, toX - x, toY - y);
                frames(app, 1);
                mouse(input, toX, toY, false);
                return "drag " + x + "," + y + " to " + toX + "," + toY;
            }
            case CLICK: {
                int x = share(action.a(), width);
                int y = share(action.b(), height);
                mouse(input, x, y, true);
                mouse(input, x, y, false);
                return "click " + x + "," + y;
            }
            case PRESENT:
                pressKey(input, KeyInput.KEY_F8, false);
                return "F8";
            case PANEL:
                pressKey(input, KeyInput.KEY_F2, false);
                return "F2";
            case BURST: {
                int presses = 2 + action.a() % (MAX_BURST - 1);
                boolean shift = action.c() % 4 == 0;
                StringBuilder keys = new StringBuilder(shift ? "Shift+" : "");
                for (int i = 0; i < presses; ++i) {
                    boolean home = (action.b() >>> (i % 31) & 1) == 0;
                    pressKey(input, home ? KeyInput.KEY_HOME : KeyInput.KEY_END, shift);
                    keys.append(home ? 'H' : 'E');
                }
                return "burst " + keys;
            }
            case SHIFT_KEY: {
                int[] codes = {KeyInput.KEY_HOME, KeyInput.KEY_END, KeyInput.KEY_TAB};
                String[] labels = {"Home", "End", "Tab"};
                int which = action.a() % codes.length;
                pressKey(input, codes[which], true);
                return "Shift+" + labels[which];
            }
            case SWITCH: {
                int demos = app.getSwitcher().getDemos().size();
                int chosen = action.a() % demos;
                app.getSwitcher().select(chosen);
                return "switch to " + (chosen + 1);
            }
            case FAIL:
                app.getRootNode().addControl(new FailingView());
                return "an injected failure";
            default:
                throw new IllegalStateException("no action of kind " + action.kind());
        }
    }

    /** Queue a key's press and release, with Shift held around them if asked. */
    private static void pressKey(InputManager input, int keyCode, boolean shift) {
        asADevice(input, () -> {
            if (shift) {
                input.onKeyEvent(new KeyInputEvent(KeyInput.KEY_LSHIFT, '\0', true, false));
            }
            input.onKeyEvent(new KeyInputEvent(keyCode, '\0', true, false));
            input.onKeyEvent(new KeyInputEvent(keyCode, '\0', false, false));
            if (shift) {
                input.onKeyEvent(new KeyInputEvent(KeyInput.KEY_LSHIFT, '\0', false, false));
            }
        });
    }

    /** Queue the mouse's move to a point and a press or release of the left button there. */
    private static void mouse(InputManager input, int x, int y, boolean pressed) {
        asADevice(input, () -> {
            input.onMouseMotionEvent(new MouseMotionEvent(x, y, 0, 0, 0, 0));
            input.onMouseButtonEvent(new MouseButtonEvent(MouseInput.BUTTON_LEFT, pressed, x,
                    y));
        });
    }

    /** Queue the mouse's move to a point. */
    private static void move(InputManager input, int x, int y, int dx, int dy) {
        asADevice(input, () -> input.onMouseMotionEvent(new MouseMotionEvent(x, y, dx, dy, 0,
                0)));
    }

    /**
     * Hand events to jME's input manager as a device does: it takes them only while it polls
     * its devices (the headless context's devices raise none), and queues them for the end
     * of that poll, where its listeners and mappings get them in order.
     */
    private static void asADevice(InputManager input, Runnable events) {
        try {
            Field permitted = InputManager.class.getDeclaredField("eventsPermitted");
            permitted.setAccessible(true);
            permitted.setBoolean(input, true);
            try {
                events.run();
            } finally {
                permitted.setBoolean(input, false);
            }
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot queue input in jME's input manager", e);
        }
    }

    /** A random number as a pixel of a window's side: from 0 to side - 1. */
    private static int share(int random, int side) {
        return (int) ((long) (random % FRACTION) * side / FRACTION);
    }

    /**
     * Run the demos the actions left, moving, and measure what a whole frame allocates (the
     * least of a few windows of frames, after a warm-up): the demo on screen, if a switch
     * took the window to another demo, then the demo whose actions ran.
     *
     * @return "" or what allocated
     */
    private static String allocationAfterwards(int index) throws Exception {
        ParticleLabApp app = harness.app();
        // First the demo on screen when the actions ended, if a switch took the window to
        // another one: in the state the switches and the input left it.
        DemoState shown = harness.call(() -> app.getSwitcher().getSelected());
        if (shown != app.getSwitcher().getDemos().get(index)) {
            String problem = allocationOf(app, index, "switched to");
            if (!problem.isEmpty()) {
                return problem;
            }
        }
        // Then the demo whose actions ran, in the state they left it.
        harness.call(() -> {
            app.getSwitcher().select(index);
            frames(app, FRAMES_PER_ACTION);
            return true;
        });
        return allocationOf(app, index, "on");
    }

    /**
     * Measure a frame of the demo on screen, moving: "" if the least window of a round
     * allocated nothing, else what the last round's windows allocated and the state.
     */
    private static String allocationOf(ParticleLabApp app, int index, String how)
            throws Exception {
        DemoState demo = harness.call(() -> {
            DemoState selected = app.getSwitcher().getSelected();
            // HelloAiming's bullets may fly the slide's own listing (its code parameter,
            // key J), which allocates four vectors a step on purpose (aiming.SlideCodeBullet):
            // that is the lecture's point, not the app's code, so they fly the shared recipe
            // from a restart before the frame is measured.
            int code = selected.getParameters().indexOf(SLIDE_CODE_PARAMETER);
            if (code >= 0 && selected.getParameters().getValue(code) != RECIPE_CODE) {
                selected.getParameters().set(code, RECIPE_CODE);
                selected.restart();
            }
            // Likewise the comparison lane's slide code (accuracy.SlideCode: jME's
            // allocating add/mult, a new vector a step, as the slide writes it): the lane
            // is switched off.
            int lane = selected.getParameters().indexOf(ComparisonLane.PARAMETER);
            if (lane >= 0 && selected.getParameters().getValue(lane) == SLIDE_LANE) {
                selected.getParameters().set(lane, LANE_OFF);
                selected.restart();
            }
            selected.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            selected.getClock().setPaused(false);
            for (int frame = 0; frame < WARM_UP_FRAMES; ++frame) {
                measuredFrame(app);
            }
            return selected;
        });
        long[] bytes = new long[MEASURED_WINDOWS];
        int frames = WARM_UP_FRAMES;
        while (true) {
            // One round a call: the harness's wait holds a round even on a loaded machine.
            long least = harness.call(() -> {
                long fewest = Long.MAX_VALUE;
                for (int w = 0; w < MEASURED_WINDOWS; ++w) {
                    bytes[w] = 0L;
                    for (int frame = 0; frame < FRAMES_PER_WINDOW; ++frame) {
                        bytes[w] += measuredFrame(app);
                    }
                    fewest = Math.min(fewest, bytes[w]);
                }
                return fewest;
            });
            frames += MEASURED_WINDOWS * FRAMES_PER_WINDOW;
            if (least == 0L) {
                return "";
            }
            if (frames >= MAX_WARM_UP_FRAMES) {
                break;
            }
        }
        String state = harness.call(() -> describe(app, demo));
        return "afterwards, " + how + " " + demo.getTitle() + " (demo " + (index + 1)
                + " was run; " + state + "), every window of " + FRAMES_PER_WINDOW
                + " frames allocated: " + Arrays.toString(bytes) + " bytes, " + frames
                + " frames after the actions";
    }

    /** The state the input left: what a frame's allocation may depend on. */
    private static String describe(ParticleLabApp app, DemoState demo) {
        return "window " + app.getCamera().getWidth() + "x" + app.getCamera().getHeight()
                + (demo.getDemoHud().isPresenting() ? ", presenting" : "")
                + (demo.getParameterControls().isPanelVisible() ? ", panel open" : "")
                + ", HUD factor " + app.getWindowControls().getUiFactor()
                + ", time scale " + demo.getClock().getTimeScale()
                + ", step " + demo.getClock().getStepSeconds() + " s; "
                + demo.getParameters().formatPanel(new StringBuilder()).toString()
                        .replace('\n', ';');
    }

    /**
     * One whole frame as {@code SimpleApplication.update()} runs it, measured after jME's
     * input poll (which makes map iterators of jME's own, see FrameAllocationHeadlessTest).
     *
     * @return the bytes the frame allocated (&ge;0)
     */
    private static long measuredFrame(ParticleLabApp app) {
        app.getInputManager().update(H);
        long start = THREADS.getCurrentThreadAllocatedBytes();
        AppStateManager states = app.getStateManager();
        RenderManager render = app.getRenderManager();
        states.update(H);
        app.simpleUpdate(H);
        app.getRootNode().updateLogicalState(H);
        app.getGuiNode().updateLogicalState(H);
        app.getRootNode().updateGeometricState();
        app.getGuiNode().updateGeometricState();
        states.render(render);
        render.render(H, app.getContext().isRenderable());
        app.simpleRender(render);
        states.postRender();
        return THREADS.getCurrentThreadAllocatedBytes() - start;
    }

    private static void frames(ParticleLabApp app, int count) {
        for (int frame = 0; frame < count; ++frame) {
            SmallPanelHeadlessTest.frame(app);
        }
    }

    /**
     * The window as the harness made it (its size, not presenting, the HUD factor 1), and no
     * injected failure left in the scene.
     */
    private static void restoreWindow(ParticleLabApp app) {
        app.getWindowControls().setPresenting(false);
        app.getWindowControls().setUiFactor(1f);
        app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
        while (app.getRootNode().getControl(FailingView.class) != null) {
            app.getRootNode().removeControl(FailingView.class);
        }
    }

    private static int parsePositive(String variable, String text) {
        try {
            int value = Integer.parseInt(text.trim());
            if (value > 0) {
                return value;
            }
        } catch (NumberFormatException e) {
            // Refused below, with the value.
        }
        throw new IllegalArgumentException(variable + " must be a whole number > 0,"
                + " but was \"" + text + "\"");
    }

    private static long parseSeed(String text) {
        try {
            return Long.parseLong(text.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(SEED_VARIABLE + " must be a whole number,"
                    + " but was \"" + text + "\"");
        }
    }

    /** A view that throws once, on its first update, and leaves the scene first. */
    static final class FailingView extends AbstractControl {

        static final String MESSAGE = "a view failed on purpose at a known action";

        @Override
        protected void controlUpdate(float tpf) {
            spatial.removeControl(this);
            throw new IllegalStateException(MESSAGE);
        }

        @Override
        protected void controlRender(RenderManager manager, ViewPort viewPort) {
        }
    }
}

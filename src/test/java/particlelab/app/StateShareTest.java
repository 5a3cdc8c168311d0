package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.event.KeyInputEvent;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.system.JmeContext;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.StringWriter;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.DragControl;
import particlelab.demo.Draggable;
import particlelab.demo.StateHash;
import particlelab.physics.SimulationClock;
import particlelab.view.ParameterPanel;

/**
 * Issue 33, part 2: a state as a command line. {@code --print-command} and the C key print
 * {@code particle-lab demo NAME --frames K --fixed-tpf H --set ...}, and that command, run in
 * a new JVM, ends in the same state, bit for bit (the same hash of the whole simulation's
 * ring entry); a state no command line can reach says so.
 */
class StateShareTest {

    /** The demos' default step h = 1/60 s as a float, as --fixed-tpf prints it. */
    private static final String FRAME = "0.016666668";
    /** Where the JDK 25 is installed on the lab's machines. */
    private static final String JDK_25 = "/usr/lib/jvm/temurin-25-jdk-amd64";
    /** A guard against a hung child JVM, not a timing: on a loaded machine it took 75 s. */
    private static final long CHILD_SECONDS = 600L;

    /**
     * A launch as an arrow drag leaves it (speed and angle) on a weak g, so the ball flies
     * the whole 600 steps: the printed command, run in a new JVM (the installed app's
     * entry point on this classpath), prints the same command and the same state line, its
     * hash included.
     */
    @Test
    void thePrintedCommandGivesTheSameStateInAFreshJvm() throws Exception {
        CommandRun first = CommandRun.of("demo", "pull", "--set", "speed=12.5", "--set",
                "angle=60", "--set", "g=2", "--frames", "600", "--fixed-tpf", FRAME,
                "--print-command");
        assertEquals(0, first.code, first.toString());
        List<String> lines = first.outLines();
        assertEquals(2, lines.size(), first.toString());
        // only what differs from the defaults, in the panel's order; 600 frames of one step
        assertEquals("particle-lab demo pull --frames 600 --fixed-tpf " + FRAME
                + " --set speed=12.5 --set angle=60.0 --set g=2.0", lines.get(0));
        assertTrue(lines.get(1).startsWith("state: step 600, t = 10.0000 s, hash "),
                lines.get(1));
        assertTrue(lines.get(1).endsWith("the command re-run gives the same bits"),
                lines.get(1));
        List<String> args = new ArrayList<>(Arrays.asList(lines.get(0).split(" ")));
        assertEquals(Program.NAME, args.remove(0));
        args.add(StateShare.PRINT_COMMAND);
        Child child = runInNewJvm(args);
        assertEquals(0, child.code, child.err);
        // the same command and the same hash: the new JVM's state is this one's, to the bit
        assertEquals(lines, Arrays.asList(child.out.split("\\R")), child.err);
    }

    /**
     * The window's C key shares the state shown: stepped back ten steps from the live end,
     * the command gives the step shown, and re-run it gives the shown state's bits. Fixed
     * steps of h make a state a count of steps whatever the frame times were. The key's
     * code and the demo run without jME (plain JUnit): the key reads the switcher's demo.
     */
    @Test
    void theKeyCSharesTheRecordedStepShown() throws Exception {
        DemoState bounce = DemoCatalog.entries().get(DemoCatalog.indexOf("bounce")).create();
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        // the check runs at once, on this thread: no application to hand the verdict to
        ShareKey key = new ShareKey(new DemoSwitcher(List.of(bounce), 0),
                new PrintStream(printed, true, StandardCharsets.UTF_8), Runnable::run);
        bounce.restart();
        bounce.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        bounce.getClock().setPaused(false);
        for (int frame = 0; frame < 300; ++frame) {
            bounce.getRun().advancePhysics(1f / 60f);
        }
        bounce.getClock().setPaused(true);
        for (int i = 0; i < 10; ++i) {
            bounce.getReplayControls().stepBack();
        }
        StateShare share = key.share().get(CHILD_SECONDS, TimeUnit.SECONDS);
        assertEquals("particle-lab demo bounce --frames 290 --fixed-tpf " + FRAME,
                share.command);
        assertTrue(share.reproduces(), share.stateLine());
        assertEquals(share.command + "\n" + share.stateLine() + "\n",
                printed.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n"));
        String notice = bounce.getDemoHud().getNotice();
        assertTrue(notice.startsWith("C: command printed to the terminal (step 290, hash "
                + StateHash.hex(share.hash).substring(0, 8)), notice);
        assertTrue(notice.endsWith("re-run: same bits)"), notice);
    }

    /**
     * The C key prints the command at once and checks it aside: until the re-run ends the
     * window goes on (the key returned), the HUD says the check is running and only the
     * command is printed; the verdict comes to the terminal and the HUD when the check ends.
     * The checks are held back here, so "not yet" is no matter of timing.
     */
    @Test
    void theKeyCChecksAsideAndTheWindowGoesOn() throws Exception {
        DemoState uniform = DemoCatalog.entries().get(DemoCatalog.indexOf("uniform"))
                .create();
        List<Runnable> held = new ArrayList<>();
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        ShareKey key = new ShareKey(new DemoSwitcher(List.of(uniform), 0),
                new PrintStream(printed, true, StandardCharsets.UTF_8), held::add);
        uniform.restart();
        uniform.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        uniform.getClock().setPaused(false);
        for (int frame = 0; frame < 40; ++frame) {
            uniform.getRun().advancePhysics(1f / 60f);
        }
        uniform.getClock().setPaused(true);
        CompletableFuture<StateShare> pending = key.share();
        // the key returned with the check still held: the window's frame goes on
        assertFalse(pending.isDone());
        assertEquals(1, held.size());
        assertTrue(uniform.getDemoHud().getNotice().endsWith("re-running it to check...)"),
                uniform.getDemoHud().getNotice());
        assertEquals("particle-lab demo uniform --frames 40 --fixed-tpf " + FRAME + "\n",
                printed.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n"));
        held.get(0).run();
        StateShare share = pending.get(CHILD_SECONDS, TimeUnit.SECONDS);
        assertTrue(share.reproduces(), share.stateLine());
        assertEquals(share.command + "\n" + share.stateLine() + "\n",
                printed.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n"));
        assertTrue(uniform.getDemoHud().getNotice().endsWith("re-run: same bits)"),
                uniform.getDemoHud().getNotice());
    }

    /**
     * A state changed by hand mid-flight (as a drag of a body's velocity does) is no count
     * of steps of any command line: the share says so and gives the two hashes.
     */
    @Test
    void aStateNoCommandReachesIsSaidToBeOne() {
        DemoState uniform = DemoCatalog.entries().get(DemoCatalog.indexOf("uniform"))
                .create();
        for (int i = 0; i < 30; ++i) {
            uniform.getRun().advancePhysics(1f / 60f);
        }
        StateShare untouched = StateShare.of(uniform);
        assertTrue(untouched.reproduces(), untouched.stateLine());
        uniform.getParticles().get(0).getParticle().velocity.x += 1f;
        uniform.getRun().advancePhysics(1f / 60f);
        StateShare changed = StateShare.of(uniform);
        assertEquals("particle-lab demo uniform --frames 31 --fixed-tpf " + FRAME,
                changed.command);
        assertFalse(changed.reproduces());
        assertNotEquals(changed.hash, changed.commandHash);
        assertTrue(changed.stateLine().contains("the command gives hash "
                + StateHash.hex(changed.commandHash) + ": this state came from inputs a"
                + " command line does not carry"), changed.stateLine());
    }

    /**
     * Issue 33, part 3: a run of the pull demo with the window's inputs, each through the path
     * the window takes (keys queued in jME's input manager: Space pauses and resumes, "-"
     * slows time; the panel's row and slider; the launch dragged with the mouse through the
     * drag control and the app's camera; Space again to fly the new launch), over real,
     * varying frame times, is recorded; the replay of the recording gives every hash again,
     * to the bit.
     */
    @Test
    void aRecordedRunWithKeysAPanelChangeAndADragReplaysIdentically() throws Exception {
        String recording = recordPullWithInputs();
        assertTrue(recording.startsWith(Recording.VERSION_LINE + "\ndemo pull\nsetting g=2.0\n"),
                recording);
        assertTrue(firstHashStepAfter(Arrays.asList(recording.split("\n")),
                recording.substring(0, recording.indexOf("drag release")).split("\n").length)
                > 0L, "no hash after the drag:\n" + recording);
        for (String expected : new String[] {"\nkey Space\n", "\nkey -\n", "\nselect g\n",
            "\nset g ", "\ndrag start 0 0\n", "\ndrag move 0 0 ", "\ndrag release\n"}) {
            assertTrue(recording.contains(expected), expected + " in\n" + recording);
        }
        Replay replay = replay(recording);
        assertEquals(0, replay.code, replay.toString());
        long steps = lastHashStep(recording);
        assertEquals("replayed " + steps + " steps: identical (" + countHashes(recording)
                + " hashes compared)", replay.out.strip(), replay.toString());
        // The same recording replayed by JDK 25 in a new JVM: the same hashes (Java's float
        // arithmetic is IEEE 754 strict since Java 17, so any JVM gives the same bits).
        Path jdk25 = Paths.get(JDK_25, "bin", "java");
        Assumptions.assumeTrue(Files.isExecutable(jdk25), "no JDK 25 at " + JDK_25);
        Path file = Files.createTempFile("particlelab-recording", ".txt");
        try {
            Files.writeString(file, recording, StandardCharsets.UTF_8);
            Child child = runInNewJvm(jdk25.toString(), List.of("demo", "pull",
                    Replayer.REPLAY, file.toString()));
            assertEquals(0, child.code, child.err);
            assertEquals(replay.out.strip(), child.out.strip(), child.err);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    /**
     * The panel's buttons clicked through the panel itself (Pause, Step twice, Pause, Fire,
     * Reset, Export) while the aiming demo is recorded: each is written as the key it stands
     * for (Export as "export"), and the replay presses the same bindings and finds every hash
     * again, to the bit. A button not recorded would leave a step, a shot or a reset out of
     * the replay, whose next hash then differs. The recorded export writes no files on replay.
     */
    @Test
    void aRecordedRunWithThePanelsButtonsReplaysIdentically() throws Exception {
        String recording = recordWithButtons();
        for (String expected : new String[] {"\nkey Space\n", "\nkey N\n", "\nkey F\n",
            "\nkey R\n", "\nexport\n"}) {
            assertTrue(recording.contains(expected), expected + " in\n" + recording);
        }
        assertTrue(firstHashStepAfter(Arrays.asList(recording.split("\n")),
                recording.substring(0, recording.indexOf("\nkey R\n")).split("\n").length)
                > 0L, "no hash after the reset:\n" + recording);
        long exportsBefore = countExports();
        Replay replay = replay("aiming", recording);
        assertEquals(0, replay.code, replay.toString());
        assertEquals("replayed " + lastHashStep(recording) + " steps: identical ("
                + countHashes(recording) + " hashes compared)", replay.out.strip(),
                replay.toString());
        assertEquals(exportsBefore, countExports(), "the replay wrote an export");
    }

    /**
     * One event changed in a recording (the drag's last value moved by 1 cm), or one frame
     * time (the first second's frames given 0.02 s): the replay stops at the first hash
     * after the change with "DIVERGED at step K" and exit status 1.
     */
    @Test
    void aChangedEventOrFrameTimeDivergesAtTheNextHash() throws Exception {
        String recording = recordPullWithInputs();
        List<String> lines = new ArrayList<>(Arrays.asList(recording.split("\n")));
        int move = -1;
        for (int i = 0; i < lines.size(); ++i) {
            if (lines.get(i).startsWith("drag move ")) {
                move = i;
            }
        }
        String[] words = lines.get(move).split(" ");
        words[4] = Float.toString(Float.parseFloat(words[4]) + 0.01f);
        lines.set(move, String.join(" ", words));
        Replay moved = replay(String.join("\n", lines) + "\n");
        assertEquals(Program.FAILED, moved.code, moved + "\n" + recording);
        long expected = firstHashStepAfter(lines, move);
        assertTrue(moved.out.startsWith("DIVERGED at step " + expected + ": hash "),
                expected + " expected: " + moved);

        List<String> timed = new ArrayList<>(Arrays.asList(recording.split("\n")));
        int frames = -1;
        for (int i = 0; i < timed.size() && frames < 0; ++i) {
            if (timed.get(i).startsWith("frames ")
                    && Float.parseFloat(timed.get(i).split(" ")[3]) < 0.05f) {
                frames = i;
            }
        }
        // a frame of the first second, before the pause, made 0.02 s longer (more than h =
        // 1/60 s, less than any cap on a frame's time; the first frame's own time, a long
        // start, is capped): the fixed step's clock takes one more step in that or the
        // next frame, so the step counts part and the next hash differs
        String[] frameWords = timed.get(frames).split(" ");
        frameWords[3] = Float.toString(Float.parseFloat(frameWords[3]) + 0.02f);
        timed.set(frames, String.join(" ", frameWords));
        Replay retimed = replay(String.join("\n", timed) + "\n");
        assertEquals(Program.FAILED, retimed.code, retimed.toString());
        long first = firstHashStepAfter(timed, frames);
        assertTrue(retimed.out.startsWith("DIVERGED at step " + first + ": hash "),
                first + " expected: " + retimed);
    }

    /**
     * Choosing another demo while recording ends the recording: its last line says so, the
     * new demo's HUD says so, and the frames up to the switch replay identically.
     */
    @Test
    void switchingDemosEndsTheRecording() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        int index = DemoCatalog.indexOf("pull");
        int other = DemoCatalog.indexOf("drag");
        DemoState demo = demos.get(index);
        ParticleLabApp app = new ParticleLabApp(demos, index, 120, null,
                Float.parseFloat(FRAME), false);
        StringWriter text = new StringWriter();
        Recorder recorder = new Recorder(app.getSwitcher(), demo, "pull", 0, text);
        app.getStateManager().attach(new BaseAppState() {
            private int frames;

            @Override
            public void update(float tpf) {
                if (demo.isInitialized() && ++frames == 80) {
                    app.getSwitcher().select(other);
                }
            }

            @Override
            protected void initialize(Application application) {
                // nothing to build
            }

            @Override
            protected void cleanup(Application application) {
                // nothing to tidy
            }

            @Override
            protected void onEnable() {
                // the switch comes from update
            }

            @Override
            protected void onDisable() {
                // the switch comes from update
            }
        });
        app.getStateManager().attach(recorder);
        app.start(JmeContext.Type.Headless);
        assertTrue(app.awaitFinished(CHILD_SECONDS), "the run did not end");
        assertEquals(null, app.getFailure());
        String recording = text.toString();
        assertTrue(recording.endsWith("\nend switched to another demo\n"), recording);
        // the switch is asked in frame 80 and made by the switcher in that frame, before the
        // demo's update: pull ran 79 frames of one step each
        assertTrue(recording.contains("\nframes 19 tpf " + FRAME + "\nhash 79 "), recording);
        assertEquals("the recording of pull ended: another demo was chosen",
                demos.get(other).getDemoHud().getNotice());
        Replay replay = replay(recording);
        assertEquals("replayed 79 steps: identical (2 hashes compared)", replay.out.strip(),
                replay.toString());
    }

    /** A replay's exit status and output. */
    private static final class Replay {
        final int code;
        final String out;
        final String err;

        Replay(int code, String out, String err) {
            this.code = code;
            this.out = out;
            this.err = err;
        }

        @Override
        public String toString() {
            return "exit " + code + ", out: " + out + ", err: " + err;
        }
    }

    /** Replay a recording's text with {@code demo --replay FILE}, in this JVM. */
    private static Replay replay(String recording) throws IOException {
        return replay("pull", recording);
    }

    private static Replay replay(String demo, String recording) throws IOException {
        Path file = Files.createTempFile("particlelab-recording", ".txt");
        try {
            Files.writeString(file, recording, StandardCharsets.UTF_8);
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            int code = DemoCommand.run(new String[] {demo, Replayer.REPLAY, file.toString()},
                    new PrintStream(out, true, StandardCharsets.UTF_8),
                    new PrintStream(err, true, StandardCharsets.UTF_8));
            return new Replay(code, out.toString(StandardCharsets.UTF_8),
                    err.toString(StandardCharsets.UTF_8));
        } finally {
            Files.deleteIfExists(file);
        }
    }

    /**
     * Record 300 frames of the pull demo (g = 2) in jME's headless app with the real clock,
     * pressing keys, moving the panel's slider and dragging the launch on the way.
     */
    private static String recordPullWithInputs() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        int index = DemoCatalog.indexOf("pull");
        DemoState demo = demos.get(index);
        DemoCommand.applySettings(demo, List.of("g=2"));
        ParticleLabApp app = new ParticleLabApp(demos, index, 300, null, Float.NaN, false);
        app.getStateManager().attach(new Inputs(demo));
        StringWriter text = new StringWriter();
        Recorder recorder = new Recorder(app.getSwitcher(), demo, "pull", 0, text);
        app.getStateManager().attach(recorder);
        app.start(JmeContext.Type.Headless);
        assertTrue(app.awaitFinished(CHILD_SECONDS), "the run did not end");
        assertEquals(null, app.getFailure());
        assertEquals(null, recorder.getFailure());
        return text.toString();
    }

    /**
     * Record 240 frames of the aiming demo in jME's headless app with the real clock, clicking
     * the panel's buttons on the way.
     */
    private static String recordWithButtons() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        int index = DemoCatalog.indexOf("aiming");
        DemoState demo = demos.get(index);
        ParticleLabApp app = new ParticleLabApp(demos, index, 240, null, Float.NaN, false);
        app.getStateManager().attach(new Buttons(demo));
        StringWriter text = new StringWriter();
        Recorder recorder = new Recorder(app.getSwitcher(), demo, "aiming", 0, text);
        app.getStateManager().attach(recorder);
        app.start(JmeContext.Type.Headless);
        assertTrue(app.awaitFinished(CHILD_SECONDS), "the run did not end");
        assertEquals(null, app.getFailure());
        assertEquals(null, recorder.getFailure());
        return text.toString();
    }

    /** The export folders in the working folder (where a replay's export would go). */
    private static long countExports() throws IOException {
        if (!Files.isDirectory(ExportState.BASE_FOLDER)) {
            return 0L;
        }
        try (java.util.stream.Stream<Path> folders = Files.list(ExportState.BASE_FOLDER)) {
            return folders.count();
        }
    }

    private static long lastHashStep(String recording) {
        long step = -1L;
        for (String line : recording.split("\n")) {
            if (line.startsWith("hash ")) {
                step = Long.parseLong(line.split(" ")[1]);
            }
        }
        return step;
    }

    private static int countHashes(String recording) {
        int count = 0;
        for (String line : recording.split("\n")) {
            count += line.startsWith("hash ") ? 1 : 0;
        }
        return count;
    }

    private static long firstHashStepAfter(List<String> lines, int from) {
        for (int i = from + 1; i < lines.size(); ++i) {
            if (lines.get(i).startsWith("hash ")) {
                return Long.parseLong(lines.get(i).split(" ")[1]);
            }
        }
        throw new AssertionError("no hash after line " + (from + 1));
    }

    /**
     * The window's inputs, given at fixed frames of the demo as a person would: attached
     * before the recorder, so what it does in a frame comes before that frame's demo update
     * (keys are queued and heard in the next frame's input, as a keyboard's are).
     */
    private static final class Inputs extends BaseAppState {
        private final DemoState demo;
        private final Vector3f grip = new Vector3f();
        private int frame;
        private float pressX;
        private float pressY;

        Inputs(DemoState demo) {
            this.demo = demo;
        }

        @Override
        public void update(float tpf) {
            if (!demo.isInitialized()) {
                return;
            }
            ++frame;
            Camera camera = getApplication().getCamera();
            DragControl drags = demo.getWindow().getDragControl();
            switch (frame) {
                case 20:
                case 50:
                    key(KeyInput.KEY_SPACE);
                    break;
                case 70:
                    key(KeyInput.KEY_MINUS);
                    break;
                case 90:
                    int g = demo.getParameters().indexOf("g");
                    demo.getParameters().select(g);
                    demo.getParameters().setSliderFraction(g, 0.25f);
                    break;
                case 120:
                    Draggable ball = drags.getDraggables().get(0);
                    DragControl.copyGripPoint(ball.getGrip(), ball.getParticles().get(0), grip);
                    Vector3f screen = camera.getScreenCoordinates(grip);
                    pressX = screen.x;
                    pressY = screen.y;
                    assertTrue(drags.press(camera, pressX, pressY), "the ball was not picked");
                    break;
                case 121:
                    assertTrue(drags.move(camera, pressX + 30f, pressY + 12f));
                    break;
                case 122:
                    assertTrue(drags.move(camera, pressX + 45f, pressY + 20f));
                    break;
                case 123:
                    assertTrue(drags.release());
                    break;
                case 126:
                    // the drag paused the clock: the new launch flies
                    key(KeyInput.KEY_SPACE);
                    break;
                default:
                    break;
            }
        }

        /** Queue a key's press and release, as a keyboard does (see WindowControls' test). */
        private void key(int keyCode) {
            InputManager input = getApplication().getInputManager();
            try {
                Field permitted = InputManager.class.getDeclaredField("eventsPermitted");
                permitted.setAccessible(true);
                permitted.setBoolean(input, true);
                try {
                    input.onKeyEvent(new KeyInputEvent(keyCode, '\0', true, false));
                    input.onKeyEvent(new KeyInputEvent(keyCode, '\0', false, false));
                } finally {
                    permitted.setBoolean(input, false);
                }
            } catch (ReflectiveOperationException failure) {
                throw new IllegalStateException(failure);
            }
        }

        @Override
        protected void initialize(Application app) {
            // nothing to build
        }

        @Override
        protected void cleanup(Application app) {
            // nothing to tidy
        }

        @Override
        protected void onEnable() {
            // inputs come from update
        }

        @Override
        protected void onDisable() {
            // inputs come from update
        }
    }

    /**
     * Clicks the panel's buttons at fixed frames of the demo, through the panel's own click
     * (the buttons' actions, as a mouse click runs them); attached before the recorder.
     */
    private static final class Buttons extends BaseAppState {
        private final DemoState demo;
        private int frame;

        Buttons(DemoState demo) {
            this.demo = demo;
        }

        @Override
        public void update(float tpf) {
            if (!demo.isInitialized()) {
                return;
            }
            ++frame;
            switch (frame) {
                case 20:
                case 60:
                    click("Pause");
                    break;
                case 30:
                case 40:
                    click("Step");
                    break;
                case 90:
                    click("Fire");
                    break;
                case 130:
                    click("Reset");
                    break;
                case 150:
                    click("Export");
                    // taken before the application's export state sees it: no files here
                    assertTrue(demo.getKeys().takeExportRequest(), "Export asked nothing");
                    break;
                default:
                    break;
            }
        }

        /** Click a button of the demo's panel (reached by reflection: package-private). */
        private void click(String label) {
            try {
                Method controls = DemoState.class.getDeclaredMethod("getParameterControls");
                controls.setAccessible(true);
                Object parameterControls = controls.invoke(demo);
                Method panel = parameterControls.getClass().getDeclaredMethod("getPanel");
                panel.setAccessible(true);
                ((ParameterPanel) panel.invoke(parameterControls)).click(label);
            } catch (ReflectiveOperationException failure) {
                throw new IllegalStateException(failure);
            }
        }

        @Override
        protected void initialize(Application app) {
            // nothing to build
        }

        @Override
        protected void cleanup(Application app) {
            // nothing to tidy
        }

        @Override
        protected void onEnable() {
            // clicks come from update
        }

        @Override
        protected void onDisable() {
            // clicks come from update
        }
    }

    /** A command's run in a new JVM: exit code, stdout, stderr. */
    private static final class Child {
        final int code;
        final String out;
        final String err;

        Child(int code, String out, String err) {
            this.code = code;
            this.out = out;
            this.err = err;
        }
    }

    /** Run {@code particle-lab ARGS} in a new JVM with this one's classpath and modules. */
    private static Child runInNewJvm(List<String> args) throws IOException,
            InterruptedException {
        return runInNewJvm(Paths.get(System.getProperty("java.home"), "bin", "java").toString(),
                args);
    }

    /** Run {@code particle-lab ARGS} in a new JVM of the given java launcher. */
    private static Child runInNewJvm(String java, List<String> args) throws IOException,
            InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(java);
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            // the Vector API module the build adds; nothing of the test runner's agents
            if (option.startsWith("--add-modules")) {
                command.add(option);
            }
        }
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(Main.class.getName());
        command.addAll(args);
        Process process = new ProcessBuilder(command).start();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Thread errReader = new Thread(() -> copy(process.getErrorStream(), err));
        errReader.start();
        String out = new String(process.getInputStream().readAllBytes(),
                StandardCharsets.UTF_8);
        assertTrue(process.waitFor(CHILD_SECONDS, TimeUnit.SECONDS), "the child ran too long");
        errReader.join();
        return new Child(process.exitValue(), out, err.toString(StandardCharsets.UTF_8));
    }

    private static void copy(InputStream in, ByteArrayOutputStream out) {
        try {
            in.transferTo(out);
        } catch (IOException ignored) {
            // the child's stderr is only shown when it fails
        }
    }
}

package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.math.Vector3f;
import com.jme3.renderer.RenderManager;
import com.jme3.system.JmeContext;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Paths;
import java.util.List;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.DragControl;
import particlelab.demo.KeyBinding;
import particlelab.demo.StateHash;
import particlelab.world.Fountain;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * Replays a {@link Recording} in a {@link ParticleLabApp}: its timer gives each frame the
 * recorded frame time, and this state, attached before the demos, gives the demo what came
 * between two frames (keys, the panel's changes, drags) through the paths the window's input
 * takes, and compares the state's hash with each recorded one after its frame. The first
 * hash that differs stops the replay.
 */
final class Replayer extends BaseAppState implements StepListener {

    /** The option that replays a recording. */
    static final String REPLAY = "--replay";

    private final Recording recording;
    private final DemoState demo;
    private final List<KeyBinding> bindings;
    private final FixedTimer timer = new FixedTimer(0f);
    private final Vector3f dragValue = new Vector3f();
    /** The next item to play. */
    private int next;
    /** The frames left of the frames item playing. */
    private int framesLeft;
    private boolean started;
    private boolean frameStarted;
    private long steps;
    /** Hashes compared, the last step found identical, and the first that differed. */
    private int checked;
    private long identicalStep = -1L;
    private Recording.Item diverged;
    private long divergedHash;
    private long divergedSteps;
    /** The recorded exports passed over: a replay writes no files. */
    private int exportsSkipped;

    /**
     * Replay a recording on a demo.
     *
     * @param recording the recording, checked against the demo by {@link #check} (not null)
     * @param demo the demo, its settings applied (not null)
     */
    Replayer(Recording recording, DemoState demo) {
        this.recording = recording;
        this.demo = demo;
        this.bindings = demo.getKeys().getBindings();
        timer.setFrameSeconds(firstFrameSeconds(recording));
    }

    /**
     * Check, before the replay runs, that every line names what the demo has: its keys, its
     * parameters with values in range, its draggables and their particles.
     *
     * @param recording the recording (not null)
     * @param demo the demo, its settings applied (not null)
     * @param shown the option and file, for messages (not null)
     * @throws UsageException naming the first line that does not fit
     */
    static void check(Recording recording, DemoState demo, String shown) {
        List<KeyBinding> bindings = demo.getKeys().getBindings();
        DemoParameters parameters = demo.getParameters();
        DragControl drags = demo.getWindow().getDragControl();
        for (Recording.Item item : recording.items) {
            String line = item.source;
            switch (item.kind) {
                case KEY:
                    if (findKey(bindings, item.text) == null) {
                        throw Recording.bad(shown, item.line, line, "the demo has no key "
                                + Options.show(item.text));
                    }
                    break;
                case SELECT:
                case SET:
                    int index = parameters.indexOf(item.text);
                    if (index < 0) {
                        throw Recording.bad(shown, item.line, line, "the demo has no parameter "
                                + Options.show(item.text));
                    }
                    if (item.kind == Recording.Kind.SET
                            && !parameters.get(index).accepts(item.value)) {
                        throw Recording.bad(shown, item.line, line, item.value
                                + " is outside the range of " + item.text);
                    }
                    break;
                case DRAG_START:
                case DRAG_MOVE:
                    if (item.count >= drags.getDraggables().size() || item.particle
                            >= drags.getDraggables().get(item.count).getParticles().size()) {
                        throw Recording.bad(shown, item.line, line, "the demo has no such"
                                + " draggable particle");
                    }
                    break;
                default:
                    break;
            }
        }
        if (Float.floatToRawIntBits(recording.stepSeconds)
                != Float.floatToRawIntBits(demo.getClock().getStepSeconds())) {
            throw new UsageException(shown + ": its settings give the step h = "
                    + demo.getClock().getStepSeconds() + " s, but it says step "
                    + recording.stepSeconds + "; it was edited");
        }
    }

    /**
     * Replay a recording headless ({@code demo [NAME] --replay FILE}) and print how it ended.
     *
     * @param named the demo named on the command line, or null
     * @param file the recording (not null)
     * @param out where the result goes (not null)
     * @param err where errors go (not null)
     * @return {@link Program#OK} if every hash was identical, {@link Program#FAILED} if one
     *     differed or the run failed
     * @throws UsageException if the file cannot be read or is refused
     */
    static int run(String named, String file, PrintStream out, PrintStream err) {
        String shown = REPLAY + " " + Options.showWhole(file);
        List<String> lines;
        try {
            lines = Files.readAllLines(Paths.get(file), StandardCharsets.UTF_8);
        } catch (IOException | InvalidPathException failure) {
            throw new UsageException(shown + ": cannot be read: " + (failure
                    instanceof IOException ? UsageException.reason((IOException) failure)
                            : "not a valid path"));
        }
        Recording recording = Recording.parse(Options.showWhole(file), lines);
        int index = DemoCatalog.indexOf(recording.demo);
        if (index < 0) {
            throw new UsageException(shown + " is a recording of demo "
                    + Options.show(recording.demo) + ", which this " + Program.NAME
                    + " does not have; the demos are " + String.join(", ",
                            DemoCatalog.names()));
        }
        if (named != null && DemoCatalog.indexOf(named) != index) {
            throw new UsageException(shown + " is a recording of demo " + recording.demo
                    + ", not " + Options.show(named) + "; replay it with: " + Program.NAME
                    + " " + DemoCommand.NAME + " " + recording.demo + " " + REPLAY + " "
                    + Options.showWhole(file));
        }
        long frames = recording.countFrames();
        if (frames > Integer.MAX_VALUE) {
            throw new UsageException(shown + " holds " + frames + " frames; at most "
                    + Integer.MAX_VALUE + " are replayed");
        }
        List<DemoState> demos = DemoCatalog.createAll(recording.particles > 0
                ? recording.particles : Fountain.DEFAULT_PARTICLES);
        DemoState demo = demos.get(index);
        try {
            DemoCommand.applySettings(demo, recording.settings);
        } catch (UsageException badSetting) {
            throw new UsageException(shown + ": a setting of its header is refused: "
                    + badSetting.getMessage());
        }
        check(recording, demo, shown);
        Replayer replayer = new Replayer(recording, demo);
        if (frames > 0L) {
            DemoCommand.quietLogs();
            ParticleLabApp app = new ParticleLabApp(demos, index, (int) frames, null,
                    replayer.timer.getTimePerFrame(), false);
            app.setTimer(replayer.getTimer());
            app.getStateManager().attach(replayer);
            app.start(JmeContext.Type.Headless);
            try {
                app.awaitFinished(Long.MAX_VALUE);
            } catch (InterruptedException interrupted) {
                Thread.currentThread().interrupt();
                app.stop();
                err.println(Program.NAME + ": interrupted");
                return Program.FAILED;
            }
            if (app.getFailure() != null) {
                err.println(Program.NAME + ": the replay failed: " + app.getFailure());
                return Program.FAILED;
            }
        }
        replayer.finish();
        out.println(replayer.resultLine());
        return replayer.hasDiverged() ? Program.FAILED : Program.OK;
    }

    /** @return the timer to give the application (not null) */
    FixedTimer getTimer() {
        return timer;
    }

    /** @return steps taken since the replay began (&ge;0) */
    long countSteps() {
        return steps;
    }

    /** @return how many hashes were compared (&ge;0) */
    int countChecked() {
        return checked;
    }

    /** @return how many recorded exports were passed over, writing nothing (&ge;0) */
    int countExportsSkipped() {
        return exportsSkipped;
    }

    /** @return true once a hash differed */
    boolean hasDiverged() {
        return diverged != null;
    }

    /**
     * Say how the replay ended: {@code replayed N steps: identical (K hashes compared)} or
     * {@code DIVERGED at step K: hash A recorded, B replayed (identical at step J)}.
     *
     * @return the line (not null)
     */
    String resultLine() {
        if (diverged == null) {
            return "replayed " + steps + " steps: identical (" + checked + " hashes compared)";
        }
        String line = "DIVERGED at step " + diverged.step + ": hash "
                + StateHash.hex(diverged.hash) + " recorded, " + StateHash.hex(divergedHash)
                + " replayed";
        if (divergedSteps != diverged.step) {
            line += " after " + divergedSteps + " steps";
        }
        return line + (identicalStep < 0L ? " (no earlier hash)"
                : " (identical at step " + identicalStep + ")");
    }

    /** Compare the hashes that follow the last frame: the end of the run. */
    void finish() {
        playUntilFrames();
    }

    @Override
    public void afterStep(World world, float stepSeconds) {
        ++steps;
    }

    @Override
    protected void initialize(Application app) {
        demo.getWorld().addStepListener(this);
    }

    @Override
    protected void cleanup(Application app) {
        demo.getWorld().removeStepListener(this);
    }

    @Override
    protected void onEnable() {
        // nothing: the replay runs from initialize to cleanup
    }

    @Override
    protected void onDisable() {
        // nothing: the replay runs from initialize to cleanup
    }

    @Override
    public void update(float tpf) {
        frameStarted = demo.isInitialized() && demo.isEnabled() && diverged == null;
        if (frameStarted && !started) {
            // what came before the first frame
            started = true;
            playUntilFrames();
        }
    }

    @Override
    public void render(RenderManager renderManager) {
        if (!frameStarted) {
            return;
        }
        frameStarted = false;
        if (--framesLeft <= 0) {
            ++next;
            playUntilFrames();
        }
        if (diverged != null) {
            getApplication().stop();
        }
    }

    /** Play the items up to the next frames item (or the end), and set its frame time. */
    private void playUntilFrames() {
        while (next < recording.items.size() && diverged == null) {
            Recording.Item item = recording.items.get(next);
            if (item.kind == Recording.Kind.FRAMES) {
                framesLeft = item.count;
                timer.setFrameSeconds(item.value);
                return;
            }
            play(item);
            ++next;
        }
    }

    private void play(Recording.Item item) {
        DemoParameters parameters = demo.getParameters();
        DragControl drags = demo.getWindow().getDragControl();
        switch (item.kind) {
            case KEY:
                Object[] key = findKey(bindings, item.text);
                ((KeyBinding) key[0]).press((Integer) key[1]);
                break;
            case EXPORT:
                // An export reads the state and writes files: the replay changes nothing by
                // skipping it, and writes nothing where the recording was made (issue 33).
                ++exportsSkipped;
                break;
            case SELECT:
                parameters.select(parameters.indexOf(item.text));
                break;
            case SET:
                parameters.set(parameters.indexOf(item.text), item.value);
                break;
            case DRAG_START:
                drags.startDrag(item.count, item.particle);
                break;
            case DRAG_MOVE:
                drags.dragTo(dragValue.set(item.value, item.y, item.z));
                break;
            case DRAG_RELEASE:
                drags.release();
                break;
            case HASH:
                long hash = StateHash.of(demo);
                ++checked;
                if (hash == item.hash && steps == item.step) {
                    identicalStep = item.step;
                } else {
                    diverged = item;
                    divergedHash = hash;
                    divergedSteps = steps;
                }
                break;
            default:
                throw new IllegalStateException("not an event: " + item.kind);
        }
    }

    private static float firstFrameSeconds(Recording recording) {
        for (Recording.Item item : recording.items) {
            if (item.kind == Recording.Kind.FRAMES) {
                return item.value;
            }
        }
        return 0f;
    }

    /** The binding and key index of a key's label, or null. */
    private static Object[] findKey(List<KeyBinding> bindings, String label) {
        for (KeyBinding binding : bindings) {
            for (int key = 0; key < binding.countKeys(); ++key) {
                if (binding.getKeyLabel(key).equals(label)) {
                    return new Object[] {binding, key};
                }
            }
        }
        return null;
    }
}

package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.controls.ActionListener;
import com.jme3.input.controls.KeyTrigger;
import com.jme3.math.Vector3f;
import com.jme3.renderer.RenderManager;
import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import particlelab.demo.DemoKeys;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.DragControl;
import particlelab.demo.KeyBinding;
import particlelab.demo.StateHash;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * Writes a {@link Recording} of one demo's run while the window (or the headless app) runs
 * it: the frame times the demo was given, its key presses (the panel's buttons as the keys
 * they stand for), its exports, the panel's changes and the drags, each in the order it came,
 * and the state's hash after the frame at which each simulated second is complete. Attached
 * before the demos, so its update runs before theirs in a frame: a frame is written when it
 * starts, and what comes after it (a slider the demo's update reads) belongs before the next
 * frame, as it does in the window. The hash is taken in {@link #render}, after every update of
 * the frame. Switching to another demo ends the recording, in the file and on the new demo's
 * HUD.
 *
 * <p>Writing allocates (a line a frame when the frame times vary): a recording is not a
 * lecture's run, and nothing is done without one.
 */
final class Recorder extends BaseAppState implements DemoParameters.PanelListener,
        DragControl.Listener, StepListener, DemoKeys.PressListener {

    /** Simulated seconds between two hashes. */
    static final double HASH_SECONDS = 1.0;
    private static final String MAPPING_PREFIX = "particlelab/record/";

    private final DemoSwitcher switcher;
    private final DemoState demo;
    private final String demoName;
    private final int particles;
    private final Writer writer;
    private final StringBuilder line = new StringBuilder(64);
    private final StringBuilder framesLine = new StringBuilder(48);
    private final List<String> mappings = new ArrayList<>();
    private final List<String> labels = new ArrayList<>();
    private final ActionListener keyListener = this::onKey;
    /** The frames not written yet, all of frame time {@link #pendingTpf}. */
    private int pendingFrames;
    private float pendingTpf;
    /** Whether this frame started with the demo running (written in update). */
    private boolean frameStarted;
    /** Steps since the recording began, and their simulated time (in seconds). */
    private long steps;
    private double seconds;
    private double nextHashSeconds = HASH_SECONDS;
    private boolean ended;
    /** True once the header was written (the run started). */
    private boolean started;
    private IOException failure;
    /** The drag on: its declaration and particle, for its moves' lines. */
    private int dragDeclaration;
    private int dragParticle;

    /**
     * Record a demo's run.
     *
     * @param switcher the window's switcher (not null)
     * @param demo the demo recorded, the switcher's selected one (not null)
     * @param demoName its catalogue name (not null)
     * @param particles the fountain's count, or 0 for the default
     * @param writer where the recording goes (not null, empty; closed at the end)
     */
    Recorder(DemoSwitcher switcher, DemoState demo, String demoName, int particles,
            Writer writer) {
        this.switcher = switcher;
        this.demo = demo;
        this.demoName = demoName;
        this.particles = particles;
        this.writer = writer;
    }

    /** @return the write's failure, or null if every line was written */
    IOException getFailure() {
        return failure;
    }

    /** @return true once the run started and the header was written */
    boolean hasStarted() {
        return started;
    }

    /** @return true once the recording ended (its end line written) */
    boolean isEnded() {
        return ended;
    }

    /** @return steps since the recording began (&ge;0) */
    long countSteps() {
        return steps;
    }

    @Override
    public void panelSelected(int row) {
        write(line().append("select ").append(demo.getParameters().get(row).getName()));
    }

    @Override
    public void panelSet(int row, float value) {
        write(line().append("set ").append(demo.getParameters().get(row).getName())
                .append(' ').append(Float.toString(value)));
    }

    @Override
    public void buttonPressed(String keyLabel) {
        if (demo.isEnabled()) {
            write(line().append("key ").append(keyLabel));
        }
    }

    @Override
    public void exportRequested() {
        if (demo.isEnabled()) {
            write(line().append("export"));
        }
    }

    @Override
    public void dragStarted(int draggable, int particle) {
        dragDeclaration = draggable;
        dragParticle = particle;
        write(line().append("drag start ").append(draggable).append(' ').append(particle));
    }

    @Override
    public void draggedTo(Vector3f value) {
        write(line().append("drag move ").append(dragDeclaration).append(' ')
                .append(dragParticle).append(' ').append(Float.toString(value.x)).append(' ')
                .append(Float.toString(value.y)).append(' ').append(Float.toString(value.z)));
    }

    @Override
    public void dragEnded() {
        write(line().append("drag release"));
    }

    @Override
    public void afterStep(World world, float stepSeconds) {
        ++steps;
        seconds += stepSeconds;
    }

    @Override
    protected void initialize(Application app) {
        demo.getParameters().setPanelListener(this);
        demo.getWindow().getDragControl().setListener(this);
        demo.getKeys().setPressListener(this);
        demo.getWorld().addStepListener(this);
        // The demo's keys, heard beside the demo's own mappings: a press is written with the
        // label of its key.
        // The bindings build the scene if it was not yet: its settings are then in place.
        List<KeyBinding> bindings = demo.getKeys().getBindings();
        StringBuilder header = new StringBuilder();
        Recording.writeHeader(demoName, particles, StateShare.settingsOf(demo),
                demo.getClock().getStepSeconds(), header);
        writeLine(header.deleteCharAt(header.length() - 1));
        started = true;
        InputManager input = app.getInputManager();
        for (int i = 0; i < bindings.size(); ++i) {
            KeyBinding binding = bindings.get(i);
            for (int key = 0; key < binding.countKeys(); ++key) {
                String name = MAPPING_PREFIX + mappings.size();
                input.addMapping(name, new KeyTrigger(binding.getKeyCode(key)));
                mappings.add(name);
                labels.add(binding.getKeyLabel(key));
            }
        }
        input.addListener(keyListener, mappings.toArray(new String[0]));
    }

    @Override
    public void update(float tpf) {
        if (ended) {
            return;
        }
        frameStarted = demo.isInitialized() && demo.isEnabled();
        if (!frameStarted) {
            return;
        }
        if (pendingFrames > 0
                && Float.floatToRawIntBits(tpf) != Float.floatToRawIntBits(pendingTpf)) {
            flushFrames();
        }
        pendingTpf = tpf;
        ++pendingFrames;
    }

    @Override
    public void render(RenderManager renderManager) {
        if (ended || !frameStarted) {
            return;
        }
        frameStarted = false;
        if (switcher.getSelected() != demo || !demo.isEnabled()) {
            // the switch came after this state's update: the demo did not run this frame
            --pendingFrames;
            finish("switched to another demo");
            switcher.getSelected().getDemoHud().showNotice("the recording of " + demoName
                    + " ended: another demo was chosen");
            return;
        }
        if (seconds >= nextHashSeconds) {
            writeHash();
            nextHashSeconds = Math.floor(seconds / HASH_SECONDS) * HASH_SECONDS
                    + HASH_SECONDS;
        }
    }

    @Override
    protected void cleanup(Application app) {
        finish("the run ended");
        InputManager input = app.getInputManager();
        input.removeListener(keyListener);
        for (String name : mappings) {
            input.deleteMapping(name);
        }
    }

    @Override
    protected void onEnable() {
        // nothing: the recording runs from initialize to cleanup
    }

    @Override
    protected void onDisable() {
        // nothing: the recording runs from initialize to cleanup
    }

    /** End the recording: the frames not written yet, the last hash, the end line. */
    void finish(String why) {
        if (ended) {
            return;
        }
        flushFrames();
        writeHash();
        write(line().append("end ").append(why));
        ended = true;
        demo.getParameters().setPanelListener(null);
        demo.getWindow().getDragControl().setListener(null);
        demo.getKeys().setPressListener(null);
        demo.getWorld().removeStepListener(this);
        try {
            writer.close();
        } catch (IOException closeFailure) {
            failure = failure == null ? closeFailure : failure;
        }
    }

    private void onKey(String name, boolean isPressed, float tpf) {
        if (!isPressed || ended || !demo.isEnabled()) {
            return;
        }
        int index = mappings.indexOf(name);
        if (index >= 0) {
            write(line().append("key ").append(labels.get(index)));
        }
    }

    private void writeHash() {
        write(line().append("hash ").append(steps).append(' ')
                .append(StateHash.hex(StateHash.of(demo))));
    }

    private void flushFrames() {
        if (pendingFrames > 0) {
            framesLine.setLength(0);
            framesLine.append("frames ").append(pendingFrames).append(" tpf ")
                    .append(Float.toString(pendingTpf));
            pendingFrames = 0;
            writeLine(framesLine);
        }
    }

    private StringBuilder line() {
        line.setLength(0);
        return line;
    }

    /** Write a line; the frames before it first, so the order is kept. */
    private void write(StringBuilder text) {
        if (ended) {
            return;
        }
        flushFrames();
        writeLine(text);
    }

    private void writeLine(StringBuilder text) {
        if (failure != null) {
            return;
        }
        try {
            writer.append(text).append('\n');
            if (text.charAt(0) == 'h') {
                // a hash a second: what a crash leaves is a recording up to its last second
                writer.flush();
            }
        } catch (IOException writeFailure) {
            failure = writeFailure;
        }
    }
}

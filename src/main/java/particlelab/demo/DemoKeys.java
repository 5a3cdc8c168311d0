package particlelab.demo;

import com.jme3.input.KeyInput;
import java.util.ArrayList;
import java.util.List;
import particlelab.view.HelpText;

/**
 * The keys of one demo, in three groups: the controls every demo shares, the demo's own, and
 * the application's (choosing a demo), which the application maps and the help only lists.
 * Refuses a key that jME or the application uses, or one already bound, with a message naming
 * both; and writes the help overlay and the footer from the bindings, so that neither drifts
 * from them; and holds the export the E key or the panel's button asked for, until the
 * application takes it. The application reaches it through {@link DemoState#getKeys()}.
 */
public final class DemoKeys {

    /** Keys jME itself uses (quit, stats, camera, memory, flying), which a demo may not bind. */
    private static final int[] RESERVED_KEYS = {KeyInput.KEY_ESCAPE, KeyInput.KEY_F5,
        KeyInput.KEY_C, KeyInput.KEY_M, KeyInput.KEY_W, KeyInput.KEY_A, KeyInput.KEY_S,
        KeyInput.KEY_D, KeyInput.KEY_Q, KeyInput.KEY_Z, KeyInput.KEY_SYSRQ};
    /** Between two entries of the footer. */
    private static final String FOOTER_GAP = "     ";

    private final List<KeyBinding> shared = new ArrayList<>();
    private final List<KeyBinding> own = new ArrayList<>();
    private final List<KeyBinding> application = new ArrayList<>();
    /** The application's demos, in catalogue order: numbered from 1 in the help. */
    private final List<String> demoTitles = new ArrayList<>();
    /** What the demo lets the mouse drag, for the help's "Mouse" section. */
    private List<Draggable> draggables = new ArrayList<>();
    /** The demo's key that fires or launches, for the panel's Fire button, or null. */
    private KeyBinding fireKey;
    /** The help overlay's text, as last built (empty before the window). */
    private String helpText = "";
    /** An export asked for (key or button), for the application to carry out. */
    private boolean exportRequested;
    /** Hears the panel's buttons and the export requests (a recording), or null. */
    private PressListener pressListener;
    /** Declares the demo's scene, and with it its keys, if not done yet. */
    private final Runnable declareScene;

    /** Hears what a recording needs beyond the mapped keys: the panel's buttons, exports. */
    public interface PressListener {
        /**
         * A panel button was clicked that does what a key of the demo does.
         *
         * @param keyLabel the label of that key (its first), as {@link KeyBinding} prints it
         */
        void buttonPressed(String keyLabel);

        /** An export was asked for (the E key or the panel's Export button). */
        void exportRequested();
    }

    /** Create the keys of a demo without a scene to declare (a test of the keys alone). */
    DemoKeys() {
        this(() -> { });
    }

    /**
     * Create the keys of a demo.
     *
     * @param declareScene declares the demo's scene, and with it its keys, if not done yet
     *     (not null; run before the bindings are read)
     */
    DemoKeys(Runnable declareScene) {
        this.declareScene = declareScene;
    }

    /**
     * Declare a key every demo has.
     *
     * @param binding the action and its keys, none reserved nor bound yet (not null)
     * @return binding
     */
    KeyBinding addShared(KeyBinding binding) {
        add(shared, binding);
        return binding;
    }

    /**
     * Declare a key of the demo's own.
     *
     * @param keyCode the key, a {@link KeyInput} code, not reserved nor bound yet
     * @param keyLabel the key as printed for the help overlay (not null)
     * @param description what it does (not null)
     * @param action run once per press (not null)
     * @return the new binding (not null)
     */
    KeyBinding addOwn(int keyCode, String keyLabel, String description, Runnable action) {
        return bindKeys(new KeyBinding(keyCode, keyLabel, description, action));
    }

    /**
     * Declare keys of the demo's own that share one action and one help row (a key pair, a
     * group). Call from the demo's {@code declareKeys()}.
     *
     * @param binding the keys, none reserved nor bound yet (not null)
     * @return binding
     */
    public KeyBinding bindKeys(KeyBinding binding) {
        add(own, binding);
        return binding;
    }

    /**
     * Tell the demo the keys the application handles (the help, the footer, the panel, the
     * slide's footer), which it may not bind. Call before the demo declares its keys (before
     * its initialisation).
     *
     * @param bindings the application's keys (not null, copied)
     */
    public void setApplicationBindings(List<KeyBinding> bindings) {
        application.clear();
        application.addAll(bindings);
    }

    /**
     * Find the application's key with a key code.
     *
     * @param keyCode a {@link KeyInput} code
     * @return the application's binding whose first key it is, or null if none
     */
    KeyBinding findApplicationKey(int keyCode) {
        for (int i = 0; i < application.size(); ++i) {
            KeyBinding binding = application.get(i);
            if (binding.getKeyCode(0) == keyCode) {
                return binding;
            }
        }
        return null;
    }

    /**
     * Copy every key the demo responds to, its scene declared first: the shared ones, then
     * its own.
     *
     * @return a new list (not null)
     */
    public List<KeyBinding> getBindings() {
        declareScene.run();
        return copyMapped();
    }

    /**
     * Name what the demo lets the mouse drag, for the help's "Mouse" section.
     *
     * @param declared the declarations (not null, live)
     */
    void setDraggables(List<Draggable> declared) {
        draggables = declared;
    }

    /**
     * Replace the list of demos the help shows by number, the numbers a digit entry reaches.
     *
     * @param titles the demos' titles, in catalogue order (not null, copied)
     */
    public void setDemoTitles(List<String> titles) {
        demoTitles.clear();
        demoTitles.addAll(titles);
    }

    /**
     * Copy the keys the demo maps: the shared ones, then its own.
     *
     * @return a new list (not null)
     */
    List<KeyBinding> copyMapped() {
        List<KeyBinding> all = new ArrayList<>(shared);
        all.addAll(own);
        return all;
    }

    /**
     * Name the key that fires or launches, so the panel gets a Fire button for it. Call from
     * the demo's {@code declareKeys()}.
     *
     * @param binding one of the demo's bindings (not null)
     */
    public void setFireKey(KeyBinding binding) {
        fireKey = binding;
    }

    /**
     * List the parameter panel's buttons, each doing what a key does: Pause, Step, Reset,
     * Fire (if the demo named its fire key), Export, and Next demo (if the application binds
     * Tab).
     *
     * @param labels where to add the buttons' texts (not null, modified)
     * @param actions where to add what each does, one per label (not null, modified)
     * @param pause pauses or resumes the clock (not null)
     * @param step takes a single step (not null)
     * @param reset restarts and reframes (not null)
     * @param export asks for an export (not null)
     */
    void listPanelButtons(List<String> labels, List<Runnable> actions, Runnable pause,
            Runnable step, Runnable reset, Runnable export) {
        labels.addAll(List.of("Pause", "Step", "Reset"));
        actions.addAll(List.of(heard(KeyInput.KEY_SPACE, pause), heard(KeyInput.KEY_N, step),
                heard(KeyInput.KEY_R, reset)));
        if (fireKey != null) {
            KeyBinding fire = fireKey;
            String label = fire.getKeyLabel(0);
            labels.add("Fire");
            actions.add(() -> {
                if (pressListener != null) {
                    pressListener.buttonPressed(label);
                }
                fire.press(0);
            });
        }
        labels.add("Export");
        actions.add(export);
        for (int i = 0; i < application.size(); ++i) {
            KeyBinding binding = application.get(i);
            if (binding.getKeyCode(0) == KeyInput.KEY_TAB) {
                labels.add("Next demo");
                actions.add(() -> binding.press(0));
            }
        }
    }

    /**
     * Write the help overlay: the demo's keys, the shared ones, the application's, the demos
     * by number and the camera's.
     *
     * @param title the demo's name, heading its own keys (not null)
     * @return the text (not null)
     */
    String buildHelp(String title) {
        HelpText help = new HelpText();
        help.section(title + " - keys");
        addSection(help, own);
        help.section("Mouse");
        List<String[]> mouse = DragControl.helpRows(draggables);
        for (int i = 0; i < mouse.size(); ++i) {
            help.key(mouse.get(i)[0], mouse.get(i)[1]);
        }
        help.section("Every demo");
        addSection(help, shared);
        if (!application.isEmpty()) {
            help.section("Choosing a demo");
            addSection(help, application);
        }
        if (!demoTitles.isEmpty()) {
            help.section("The demos, by number");
            // Two a line: with 19 demos a line each pushed the help below legible size.
            for (int i = 0; i < demoTitles.size(); i += 2) {
                if (i + 1 < demoTitles.size()) {
                    help.keys(Integer.toString(i + 1), demoTitles.get(i),
                            Integer.toString(i + 2), demoTitles.get(i + 1));
                } else {
                    help.key(Integer.toString(i + 1), demoTitles.get(i));
                }
            }
        }
        help.jmeKeys();
        helpText = help.toString();
        return helpText;
    }

    /** @return the help overlay's text, from the bindings (empty before the window) */
    public String getHelpText() {
        return helpText;
    }

    /** Ask for an export of the trajectories (key, panel), carried out by the application. */
    public void requestExport() {
        if (pressListener != null) {
            pressListener.exportRequested();
        }
        exportRequested = true;
    }

    /**
     * Replace what hears the panel's buttons and the export requests (a recording).
     *
     * @param listener the listener, or null for none
     */
    public void setPressListener(PressListener listener) {
        pressListener = listener;
    }

    /**
     * A button's action that first tells the listener which shared key it stands for, so a
     * recording writes the press as that key's and a replay presses the same binding.
     */
    private Runnable heard(int keyCode, Runnable action) {
        String label = null;
        for (int i = 0; i < shared.size() && label == null; ++i) {
            if (shared.get(i).getKeyCode(0) == keyCode) {
                label = shared.get(i).getKeyLabel(0);
            }
        }
        if (label == null) {
            throw new IllegalStateException("no shared key " + keyCode + " for a button");
        }
        String keyLabel = label;
        return () -> {
            if (pressListener != null) {
                pressListener.buttonPressed(keyLabel);
            }
            action.run();
        };
    }

    /** @return true if an export was asked for since the last call, which forgets it */
    public boolean takeExportRequest() {
        boolean requested = exportRequested;
        exportRequested = false;
        return requested;
    }

    /**
     * Write the footer: every shared and application binding that has a summary, as
     * "keys  summary", in declaration order.
     *
     * @return the text (not null)
     */
    String buildFooter() {
        StringBuilder footer = new StringBuilder();
        appendFooter(footer, shared);
        appendFooter(footer, application);
        footer.append(footer.length() == 0 ? "" : FOOTER_GAP).append(DragControl.CAMERA_GESTURE)
                .append("  camera");
        return footer.toString();
    }

    private static void appendFooter(StringBuilder footer, List<KeyBinding> bindings) {
        for (int i = 0; i < bindings.size(); ++i) {
            KeyBinding binding = bindings.get(i);
            if (binding.getSummary() != null) {
                footer.append(footer.length() == 0 ? "" : FOOTER_GAP)
                        .append(binding.getKeyLabel()).append("  ").append(binding.getSummary());
            }
        }
    }

    private static void addSection(HelpText help, List<KeyBinding> bindings) {
        for (int i = 0; i < bindings.size(); ++i) {
            help.key(bindings.get(i).getKeyLabel(), bindings.get(i).getDescription());
        }
    }

    private void add(List<KeyBinding> list, KeyBinding binding) {
        for (int key = 0; key < binding.countKeys(); ++key) {
            int code = binding.getKeyCode(key);
            String label = binding.getKeyLabel(key);
            for (int reserved : RESERVED_KEYS) {
                if (code == reserved) {
                    throw new IllegalArgumentException("key " + label + " is used by jME;"
                            + " choose another for \"" + binding.getDescription() + "\"");
                }
            }
            KeyBinding owner = findOwner(application, code);
            if (owner != null) {
                throw new IllegalArgumentException("key " + label + " is used by the"
                        + " application for \"" + owner.getDescription()
                        + "\"; choose another for \"" + binding.getDescription() + "\"");
            }
            owner = findOwner(copyMapped(), code);
            if (owner != null) {
                throw new IllegalArgumentException("key " + label + " is already bound to \""
                        + owner.getDescription() + "\"");
            }
        }
        list.add(binding);
    }

    private static KeyBinding findOwner(List<KeyBinding> bindings, int code) {
        for (int i = 0; i < bindings.size(); ++i) {
            KeyBinding binding = bindings.get(i);
            for (int key = 0; key < binding.countKeys(); ++key) {
                if (binding.getKeyCode(key) == code) {
                    return binding;
                }
            }
        }
        return null;
    }
}

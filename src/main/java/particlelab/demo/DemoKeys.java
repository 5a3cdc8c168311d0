package particlelab.demo;

import com.jme3.input.KeyInput;
import java.util.ArrayList;
import java.util.List;
import particlelab.view.HelpText;

/**
 * The keys of one demo, in three groups: the controls every demo shares, the demo's own, and
 * the application's (choosing a demo), which the application maps and the help only lists.
 * Refuses a key that jME or the application uses, or one already bound, with a message naming
 * both; and writes the help overlay from the bindings, so that it never drifts from them.
 */
final class DemoKeys {

    /** Keys the application or jME itself use, which a demo may not bind. */
    private static final int[] RESERVED_KEYS = {KeyInput.KEY_ESCAPE, KeyInput.KEY_F5,
        KeyInput.KEY_C, KeyInput.KEY_M, KeyInput.KEY_W, KeyInput.KEY_A, KeyInput.KEY_S,
        KeyInput.KEY_D, KeyInput.KEY_Q, KeyInput.KEY_Z, KeyInput.KEY_TAB, KeyInput.KEY_SYSRQ,
        KeyInput.KEY_1, KeyInput.KEY_2, KeyInput.KEY_3, KeyInput.KEY_4, KeyInput.KEY_5,
        KeyInput.KEY_6, KeyInput.KEY_7, KeyInput.KEY_8, KeyInput.KEY_9};

    private final List<KeyBinding> shared = new ArrayList<>();
    private final List<KeyBinding> own = new ArrayList<>();
    private final List<KeyBinding> application = new ArrayList<>();

    /**
     * Declare a key every demo has.
     *
     * @param keyCode the key, a {@link KeyInput} code, not reserved nor bound yet
     * @param keyLabel the key as printed for the help overlay (not null)
     * @param description what it does (not null)
     * @param action run once per press (not null)
     */
    void addShared(int keyCode, String keyLabel, String description, Runnable action) {
        add(shared, new KeyBinding(keyCode, keyLabel, description, action));
    }

    /**
     * Declare a key of the demo's own.
     *
     * @param keyCode the key, a {@link KeyInput} code, not reserved nor bound yet
     * @param keyLabel the key as printed for the help overlay (not null)
     * @param description what it does (not null)
     * @param action run once per press (not null)
     */
    void addOwn(int keyCode, String keyLabel, String description, Runnable action) {
        add(own, new KeyBinding(keyCode, keyLabel, description, action));
    }

    /**
     * Replace the application's keys, listed in the help overlay only.
     *
     * @param bindings the application's keys (not null, copied)
     */
    void setApplication(List<KeyBinding> bindings) {
        application.clear();
        application.addAll(bindings);
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
     * Write the help overlay: the demo's keys, the shared ones, the application's and the
     * camera's.
     *
     * @param title the demo's name, heading its own keys (not null)
     * @return the text (not null)
     */
    String buildHelp(String title) {
        HelpText help = new HelpText();
        help.section(title + " - keys");
        addSection(help, own);
        help.section("Every demo");
        addSection(help, shared);
        if (!application.isEmpty()) {
            help.section("Choosing a demo");
            addSection(help, application);
        }
        help.jmeKeys();
        return help.toString();
    }

    private static void addSection(HelpText help, List<KeyBinding> bindings) {
        for (int i = 0; i < bindings.size(); ++i) {
            help.key(bindings.get(i).getKeyLabel(), bindings.get(i).getDescription());
        }
    }

    private void add(List<KeyBinding> list, KeyBinding binding) {
        int code = binding.getKeyCode();
        for (int reserved : RESERVED_KEYS) {
            if (code == reserved) {
                throw new IllegalArgumentException("key " + binding.getKeyLabel()
                        + " is used by jME or the application; choose another for \""
                        + binding.getDescription() + "\"");
            }
        }
        List<KeyBinding> all = copyMapped();
        for (int i = 0; i < all.size(); ++i) {
            if (all.get(i).getKeyCode() == code) {
                throw new IllegalArgumentException("key " + binding.getKeyLabel()
                        + " is already bound to \"" + all.get(i).getDescription() + "\"");
            }
        }
        list.add(binding);
    }
}

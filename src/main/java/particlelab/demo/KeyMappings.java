package particlelab.demo;

import com.jme3.input.InputManager;
import com.jme3.input.controls.ActionListener;
import com.jme3.input.controls.KeyTrigger;
import java.util.ArrayList;
import java.util.List;

/**
 * The input mappings of a list of {@link KeyBinding}s, added when an AppState is enabled and
 * removed when it is disabled, so that toggling it leaves no mapping or listener behind. Each
 * key of a binding gets its own mapping, so the action learns which key was pressed; a press
 * runs the action (key releases are ignored).
 */
public final class KeyMappings {

    private final String prefix;
    private final Runnable afterAction;
    private final List<String> names = new ArrayList<>();
    private final List<KeyBinding> mapped = new ArrayList<>();
    /** For each mapping, which key of its binding it is. */
    private final List<Integer> keyIndexes = new ArrayList<>();
    private final ActionListener listener = this::onAction;

    /**
     * Create an empty set of mappings.
     *
     * @param prefix starts every mapping name, so that names stay unique across states (not
     *     null)
     * @param afterAction runs after every action, e.g. to redraw a HUD (may be null)
     */
    public KeyMappings(String prefix, Runnable afterAction) {
        this.prefix = prefix;
        this.afterAction = afterAction;
    }

    /**
     * Map the bindings and start listening. Call from {@code onEnable}.
     *
     * @param input the application's input manager (not null)
     * @param bindings the keys to map (not null, not modified)
     */
    public void map(InputManager input, List<KeyBinding> bindings) {
        for (int i = 0; i < bindings.size(); ++i) {
            KeyBinding binding = bindings.get(i);
            for (int key = 0; key < binding.countKeys(); ++key) {
                String name = prefix + i + "." + key + " " + binding.getDescription();
                input.addMapping(name, new KeyTrigger(binding.getKeyCode(key)));
                names.add(name);
                mapped.add(binding);
                keyIndexes.add(key);
            }
        }
        input.addListener(listener, names.toArray(new String[0]));
    }

    /**
     * Stop listening and remove every mapping. Call from {@code onDisable}.
     *
     * @param input the application's input manager (not null)
     */
    public void unmap(InputManager input) {
        input.removeListener(listener);
        for (int i = 0; i < names.size(); ++i) {
            input.deleteMapping(names.get(i));
        }
        names.clear();
        mapped.clear();
        keyIndexes.clear();
    }

    /**
     * Count the mappings now in place.
     *
     * @return the count (&ge;0)
     */
    public int count() {
        return names.size();
    }

    private void onAction(String name, boolean isPressed, float tpf) {
        if (!isPressed) {
            return;
        }
        for (int i = 0; i < names.size(); ++i) {
            if (names.get(i).equals(name)) {
                mapped.get(i).press(keyIndexes.get(i));
                if (afterAction != null) {
                    afterAction.run();
                }
                return;
            }
        }
    }
}

package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.KeyInput;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.KeyMappings;

/**
 * Keeps exactly one demo enabled: keys 1–9 choose a demo, Tab the next one. The others stay
 * attached but disabled (scene detached, keys unmapped), so switching back resumes them. A
 * digit with no demo behind it says so on the HUD instead of doing nothing.
 *
 * <p>A key press only records the choice; the switch happens in {@link #update}, outside jME's
 * input dispatch, because disabling a demo deletes the very mappings being dispatched.
 */
public final class DemoSwitcher extends BaseAppState {

    private static final int MAX_NUMBERED = 9;
    private static final int[] DIGIT_KEYS = {KeyInput.KEY_1, KeyInput.KEY_2, KeyInput.KEY_3,
        KeyInput.KEY_4, KeyInput.KEY_5, KeyInput.KEY_6, KeyInput.KEY_7, KeyInput.KEY_8,
        KeyInput.KEY_9};

    private final List<DemoState> demos;
    private final List<KeyBinding> bindings = new ArrayList<>();
    private final KeyMappings keyMappings = new KeyMappings("particlelab/switcher/", null);
    private int selected;
    private int requested;

    /**
     * Create a switcher.
     *
     * @param demos the demos, in menu order (not null, not empty, copied)
     * @param first the index of the demo to show first (&ge;0, &lt;demos.size())
     */
    public DemoSwitcher(List<DemoState> demos, int first) {
        if (demos == null || demos.isEmpty()) {
            throw new IllegalArgumentException("the switcher needs at least one demo");
        }
        if (first < 0 || first >= demos.size()) {
            throw new IllegalArgumentException("first demo index must be from 0 to "
                    + (demos.size() - 1) + ", but was " + first);
        }
        this.demos = Collections.unmodifiableList(new ArrayList<>(demos));
        this.selected = first;
        this.requested = first;
        int numbered = Math.min(demos.size(), MAX_NUMBERED);
        for (int i = 0; i < numbered; ++i) {
            int index = i;
            bindings.add(new KeyBinding(DIGIT_KEYS[i], Integer.toString(i + 1),
                    demos.get(i).getTitle(), () -> select(index)));
        }
        String range = numbered == 1 ? "1" : "1-" + numbered;
        bindings.add(new KeyBinding(KeyInput.KEY_TAB, "Tab", "next demo",
                () -> select((requested + 1) % this.demos.size()))
                .withSummary("next demo (" + range + " by number)"));
        if (numbered < MAX_NUMBERED) {
            bindings.add(unusedDigits(numbered));
        }
    }

    /**
     * Return the application's own keys, for the demos' help overlays.
     *
     * @return an unmodifiable list (not null)
     */
    public List<KeyBinding> getBindings() {
        return Collections.unmodifiableList(bindings);
    }

    /**
     * Add application keys carried out elsewhere (the window's, the export's): the switcher
     * maps them with its own and every demo's help lists them. Call before it is attached.
     *
     * @param more the keys (not null, copied)
     */
    public void addBindings(List<KeyBinding> more) {
        if (isInitialized()) {
            throw new IllegalStateException("add application keys before the switcher starts");
        }
        bindings.addAll(more);
    }

    /**
     * Access the demos.
     *
     * @return an unmodifiable list (not null)
     */
    public List<DemoState> getDemos() {
        return demos;
    }

    /**
     * Return the enabled demo.
     *
     * @return the demo (not null)
     */
    public DemoState getSelected() {
        return demos.get(selected);
    }

    /**
     * Ask for a demo; the switch happens on the next update.
     *
     * @param index which demo (&ge;0, &lt;number of demos)
     */
    public void select(int index) {
        if (index < 0 || index >= demos.size()) {
            throw new IllegalArgumentException("demo index must be from 0 to "
                    + (demos.size() - 1) + ", but was " + index);
        }
        requested = index;
    }

    @Override
    protected void initialize(Application app) {
        for (int i = 0; i < demos.size(); ++i) {
            DemoState demo = demos.get(i);
            demo.setCatalogNumber(i + 1);
            demo.setApplicationBindings(bindings);
            demo.setEnabled(i == selected);
            app.getStateManager().attach(demo);
        }
    }

    @Override
    protected void cleanup(Application app) {
        for (int i = 0; i < demos.size(); ++i) {
            app.getStateManager().detach(demos.get(i));
        }
    }

    @Override
    protected void onEnable() {
        keyMappings.map(getApplication().getInputManager(), bindings);
    }

    @Override
    protected void onDisable() {
        keyMappings.unmap(getApplication().getInputManager());
    }

    @Override
    public void update(float tpf) {
        if (requested != selected) {
            demos.get(selected).setEnabled(false);
            selected = requested;
            demos.get(selected).setEnabled(true);
        }
    }

    /**
     * Bind the digits beyond the last demo to a notice on the HUD, e.g. "no demo 7: there
     * are 6; Tab cycles".
     *
     * @param numbered how many digits choose a demo (&ge;1, &lt;{@link #MAX_NUMBERED})
     * @return one binding for the remaining digits (not null)
     */
    private KeyBinding unusedDigits(int numbered) {
        int unused = MAX_NUMBERED - numbered;
        int[] codes = new int[unused];
        String[] labels = new String[unused];
        String[] notices = new String[unused];
        String count = numbered == 1 ? "there is 1" : "there are " + numbered;
        for (int i = 0; i < unused; ++i) {
            codes[i] = DIGIT_KEYS[numbered + i];
            labels[i] = Integer.toString(numbered + i + 1);
            notices[i] = "no demo " + labels[i] + ": " + count + "; Tab cycles";
        }
        return new KeyBinding(codes, labels, "no demo (" + count + "; Tab cycles)", null,
                key -> getSelected().showNotice(notices[key]));
    }
}

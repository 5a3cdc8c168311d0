package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.controls.ActionListener;
import com.jme3.input.controls.KeyTrigger;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.IntPredicate;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.KeyMappings;
import particlelab.view.TextFormat;

/**
 * Keeps exactly one demo enabled and lets the lecturer reach any of them directly: type a
 * demo's number, or Tab for the next one and Shift+Tab for the previous. The others stay
 * attached but disabled (scene detached, keys unmapped), so switching back resumes them.
 *
 * <p>Typing a number: a digit that no two-digit demo starts with chooses its demo at once
 * (with 19 demos, 2 to 9; a 20th would make 2 wait too); a digit that one does (1) waits up
 * to {@link #ENTRY_SECONDS} of frame time for a second digit, which completes the number (1
 * then 2: demo 12), and chooses demo 1 if none comes; meanwhile the title says what was typed
 * ("typed 1_"). A number with no demo behind it (0) says so on the HUD instead of doing
 * nothing. Tab or Shift+Tab
 * during an entry drops it and steps from the demo shown.
 * The help overlay states this rule, generated with the bindings, and lists the demos by
 * number.
 *
 * <p>jME's key input has no modifier state, so the switcher tracks both Shift keys through
 * mappings of its own while it is enabled.
 *
 * <p>A key press only records the choice; the switch happens in {@link #update}, outside jME's
 * input dispatch, because disabling a demo deletes the very mappings being dispatched.
 */
public final class DemoSwitcher extends BaseAppState {

    /** How long a first digit waits for a second one (in seconds of frame time). */
    public static final float ENTRY_SECONDS = 1f;
    /** The digit keys, by the digit they type. */
    private static final int[] DIGIT_KEYS = {KeyInput.KEY_0, KeyInput.KEY_1, KeyInput.KEY_2,
        KeyInput.KEY_3, KeyInput.KEY_4, KeyInput.KEY_5, KeyInput.KEY_6, KeyInput.KEY_7,
        KeyInput.KEY_8, KeyInput.KEY_9};
    /** The digits in the order they are bound (and printed): 1 to 9, then 0. */
    private static final int[] DIGITS_BOUND = {1, 2, 3, 4, 5, 6, 7, 8, 9, 0};
    private static final String MAPPING_PREFIX = "particlelab/switcher/";
    private static final String LEFT_SHIFT = MAPPING_PREFIX + "left shift";
    private static final String RIGHT_SHIFT = MAPPING_PREFIX + "right shift";

    private final List<DemoState> demos;
    private final List<KeyBinding> bindings = new ArrayList<>();
    private final KeyMappings keyMappings = new KeyMappings(MAPPING_PREFIX, null);
    private final ActionListener shiftListener = this::onShift;
    private boolean leftShiftDown;
    private boolean rightShiftDown;
    private int selected;
    private int requested;
    /** The first digit of an entry waiting for a second one, or -1 if none waits. */
    private int pendingDigit = -1;
    /** How long the pending digit has waited (in seconds of frame time). */
    private float pendingSeconds;
    /** The demo whose title shows the pending digit, or null. */
    private DemoState showingEntry;
    /** The note the entry's demo had before (a tour stop's), put back when the entry ends. */
    private String noteBeforeEntry;
    /** Takes a digit before it chooses a demo (a tour question's vote), or null. */
    private IntPredicate digitFilter;

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
        int[] codes = new int[DIGITS_BOUND.length];
        String[] labels = new String[DIGITS_BOUND.length];
        for (int i = 0; i < DIGITS_BOUND.length; ++i) {
            codes[i] = DIGIT_KEYS[DIGITS_BOUND[i]];
            labels[i] = Integer.toString(DIGITS_BOUND[i]);
        }
        bindings.add(new KeyBinding(codes, labels, describeDigits(), null,
                key -> typeDigit(DIGITS_BOUND[key])).withKeyLabel("0-9"));
        bindings.add(new KeyBinding(KeyInput.KEY_TAB, "Tab",
                "next demo; with Shift, the previous one (both wrap around)",
                () -> step(isShiftDown() ? -1 : 1))
                .withKeyLabel("Tab / Shift+Tab")
                .withSummary("demos (or " + range() + ")"));
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

    /**
     * Test whether a demo was asked for and is not shown yet (it is from the next update).
     *
     * @return true between {@link #select} of another demo and the switch
     */
    public boolean isSwitchPending() {
        return requested != selected;
    }

    /**
     * Test whether a digit is waiting for a second one.
     *
     * @return true while an entry such as "1_" is pending
     */
    public boolean isEntryPending() {
        return pendingDigit >= 0;
    }

    @Override
    protected void initialize(Application app) {
        List<String> titles = new ArrayList<>();
        for (int i = 0; i < demos.size(); ++i) {
            titles.add(demos.get(i).getTitle());
        }
        for (int i = 0; i < demos.size(); ++i) {
            DemoState demo = demos.get(i);
            demo.getDemoHud().setCatalogNumber(i + 1);
            demo.getKeys().setApplicationBindings(bindings);
            demo.getKeys().setDemoTitles(titles);
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
        InputManager input = getApplication().getInputManager();
        keyMappings.map(input, bindings);
        input.addMapping(LEFT_SHIFT, new KeyTrigger(KeyInput.KEY_LSHIFT));
        input.addMapping(RIGHT_SHIFT, new KeyTrigger(KeyInput.KEY_RSHIFT));
        input.addListener(shiftListener, LEFT_SHIFT, RIGHT_SHIFT);
    }

    @Override
    protected void onDisable() {
        InputManager input = getApplication().getInputManager();
        keyMappings.unmap(input);
        input.removeListener(shiftListener);
        input.deleteMapping(LEFT_SHIFT);
        input.deleteMapping(RIGHT_SHIFT);
        leftShiftDown = false;
        rightShiftDown = false;
    }

    /**
     * Let frame time pass for a pending digit, and switch to the demo asked for.
     *
     * @param tpf the frame time (in seconds, &ge;0)
     */
    @Override
    public void update(float tpf) {
        if (pendingDigit >= 0) {
            pendingSeconds += tpf;
            if (pendingSeconds >= ENTRY_SECONDS) {
                choose(endEntry());
            }
        }
        if (requested != selected) {
            demos.get(selected).setEnabled(false);
            selected = requested;
            demos.get(selected).setEnabled(true);
        }
    }

    /**
     * Let something take the digit keys first: while it returns true for a digit, that digit
     * chooses no demo (a tour question's vote, issue 34).
     *
     * @param filter the filter, or null for none
     */
    void setDigitFilter(IntPredicate filter) {
        digitFilter = filter;
    }

    /**
     * A digit key: complete a pending entry, start one if some two-digit demo begins with
     * this digit, or choose the demo of that number.
     */
    private void typeDigit(int digit) {
        if (digitFilter != null && digitFilter.test(digit)) {
            return;
        }
        if (pendingDigit >= 0) {
            choose(10 * endEntry() + digit);
        } else if (startsTwoDigitNumber(digit)) {
            pendingDigit = digit;
            pendingSeconds = 0f;
            int first = 10 * digit;
            int last = Math.min(demos.size(), first + 9);
            showingEntry = getSelected();
            noteBeforeEntry = showingEntry.getDemoHud().getTitleNote();
            showingEntry.getDemoHud().setTitleNote("typed " + digit + "_  (a second digit for "
                    + first + "-" + last + ")");
        } else {
            choose(digit);
        }
    }

    /** Ask for the demo of a number, or say on the HUD that there is none. */
    private void choose(int number) {
        if (number >= 1 && number <= demos.size()) {
            select(number - 1);
        } else {
            String count = demos.size() == 1 ? "there is 1" : "there are " + demos.size();
            getSelected().getDemoHud().showNotice("no demo " + number + ": " + count
                    + "; Tab cycles");
        }
    }

    /**
     * End the pending entry: forget it and take its note off the title.
     *
     * @return the digit that was pending (or -1 if none was)
     */
    private int endEntry() {
        int digit = pendingDigit;
        pendingDigit = -1;
        if (showingEntry != null) {
            showingEntry.getDemoHud().setTitleNote(noteBeforeEntry);
            showingEntry = null;
            noteBeforeEntry = null;
        }
        return digit;
    }

    /** Tab (+1) or Shift+Tab (-1): the next or previous demo, wrapping around. */
    private void step(int direction) {
        endEntry();
        select(Math.floorMod(requested + direction, demos.size()));
    }

    /** @return true if some demo's number has two digits and starts with this digit */
    private boolean startsTwoDigitNumber(int digit) {
        return digit >= 1 && 10 * digit <= demos.size();
    }

    private boolean isShiftDown() {
        return leftShiftDown || rightShiftDown;
    }

    private void onShift(String name, boolean isPressed, float tpf) {
        if (LEFT_SHIFT.equals(name)) {
            leftShiftDown = isPressed;
        } else if (RIGHT_SHIFT.equals(name)) {
            rightShiftDown = isPressed;
        }
    }

    /** @return the demos' numbers, e.g. "1-17" (or "1" for a single demo) */
    private String range() {
        return demos.size() == 1 ? "1" : "1-" + demos.size();
    }

    /**
     * The digit keys' help line, with the rule for the catalogue's size, e.g. for 19 demos:
     * "type a demo's number (1-19): 2-9 choose at once; 1 waits 1 s for a second digit (1
     * then 2: demo 12), else it is demo 1".
     */
    private String describeDigits() {
        StringBuilder text = new StringBuilder("type a demo's number (").append(range())
                .append(")");
        int waiting = demos.size() / 10;
        if (waiting == 0) {
            return text.append(": it is chosen at once").toString();
        }
        text.append(": ");
        if (waiting < 9) {
            text.append(waiting + 1 == 9 ? "9 chooses" : (waiting + 1) + "-9 choose")
                    .append(" at once; ");
        }
        String digits = waiting == 1 ? "1" : "1-" + waiting;
        int example = Math.min(12, demos.size());
        text.append(digits).append(waiting == 1 ? " waits " : " wait ");
        TextFormat.appendFixed(text, ENTRY_SECONDS, 0).append(" s for a second digit (")
                .append(example / 10).append(" then ").append(example % 10).append(": demo ")
                .append(example).append("), else ")
                .append(waiting == 1 ? "it is demo 1" : "they are demos " + digits);
        return text.toString();
    }
}

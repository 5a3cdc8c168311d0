package particlelab.demo;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import particlelab.view.ParameterPanelModel;

/**
 * The parameters of one demo, as {@link DemoKeys} is its keys: collects the declarations,
 * refuses a name declared twice, holds each value, and is the model of the parameter panel
 * (which line is selected, a key press up or down, a slider's place), so the panel is tested
 * without jME.
 *
 * <p>Each parameter has two values: the one asked for (shown in the panel) and the one in the
 * scene. Before {@link #start()} nothing reaches the scene ({@code --set} asks before the
 * window opens); {@code start} applies every value. After it, a {@link DemoParameter.Applies#LIVE
 * LIVE} value is applied at once, a {@link DemoParameter.Applies#NEXT_LAUNCH NEXT_LAUNCH} one
 * at the next {@link #applyPending()} (a reset or a launch). Changing a value allocates
 * nothing.
 */
public final class DemoParameters implements ParameterPanelModel {

    /**
     * Told of what the panel's user does to the values (a recording, issue 33): a row clicked
     * or a slider moved; not of keys, of {@code --set} or of a demo's own changes.
     */
    public interface PanelListener {
        /** @param row the row the panel selected (&ge;0) */
        void panelSelected(int row);

        /**
         * @param row the row whose slider moved (&ge;0)
         * @param value the value asked for, as {@link #set(int, float)} gets it
         */
        void panelSet(int row, float value);
    }

    /** What marks the selected line of the panel. */
    public static final String SELECTED_MARK = "> ";
    /** What marks the other lines. */
    public static final String UNSELECTED_MARK = "  ";
    /** After a value asked for that waits for the next launch. */
    public static final String PENDING_NOTE = "  (next launch)";

    private final List<DemoParameter> declared = new ArrayList<>();
    private float[] asked = new float[8];
    private float[] inScene = new float[8];
    private boolean started;
    private int selected;
    /** Counts changes of any value or the selection, so a view knows when to redraw. */
    private int version;
    /** Told of the panel's changes, or null. */
    private PanelListener panelListener;

    /**
     * Declare a parameter; its value starts at the default.
     *
     * @param parameter the declaration (not null, its name not declared yet)
     * @return parameter
     */
    public DemoParameter add(DemoParameter parameter) {
        if (parameter == null) {
            throw new IllegalArgumentException("parameter must not be null");
        }
        if (indexOf(parameter.getName()) >= 0) {
            throw new IllegalArgumentException("parameter " + parameter.getName()
                    + " is declared twice");
        }
        int index = declared.size();
        if (index == asked.length) {
            asked = Arrays.copyOf(asked, 2 * index);
            inScene = Arrays.copyOf(inScene, 2 * index);
        }
        declared.add(parameter);
        asked[index] = parameter.getDefault();
        inScene[index] = parameter.getDefault();
        ++version;
        return parameter;
    }

    /** @return how many parameters are declared (&ge;0) */
    public int size() {
        return declared.size();
    }

    /**
     * Return one declaration.
     *
     * @param index which (&ge;0, &lt;{@link #size()})
     * @return the declaration (not null)
     */
    public DemoParameter get(int index) {
        return declared.get(index);
    }

    /**
     * Find a parameter by its name.
     *
     * @param name the command-line name (case-sensitive)
     * @return its index, or -1 if none has that name
     */
    public int indexOf(String name) {
        for (int i = 0; i < declared.size(); ++i) {
            if (declared.get(i).getName().equals(name)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Return the value asked for: what the panel shows and the next launch uses.
     *
     * @param index which (&ge;0, &lt;{@link #size()})
     * @return the value
     */
    public float getValue(int index) {
        checkIndex(index);
        return asked[index];
    }

    /**
     * Return the value asked for, by name: e.g. for framing the camera on what the current
     * parameters can reach.
     *
     * @param name the command-line name (one of those declared)
     * @return the value
     */
    public float getValue(String name) {
        return asked[require(name)];
    }

    /**
     * Return the value the scene runs with now (differs from {@link #getValue(int)} while a
     * {@code NEXT_LAUNCH} change waits for the launch).
     *
     * @param index which (&ge;0, &lt;{@link #size()})
     * @return the value
     */
    public float getValueInScene(int index) {
        checkIndex(index);
        return inScene[index];
    }

    /**
     * Ask for a value by name, as {@code --set NAME=VALUE} does.
     *
     * @param name the command-line name
     * @param value the value
     * @throws IllegalArgumentException if no parameter has that name or the value is out of
     *     its range; the message lists every parameter with its range
     */
    public void set(String name, float value) {
        int index = indexOf(name);
        if (index < 0) {
            throw new IllegalArgumentException("no parameter named \"" + name + "\"; "
                    + describeAll());
        }
        if (!declared.get(index).accepts(value)) {
            throw new IllegalArgumentException(name + " = " + value + " is out of range; "
                    + describeAll());
        }
        set(index, value);
    }

    /**
     * Ask for a value.
     *
     * @param index which (&ge;0, &lt;{@link #size()})
     * @param value the value (within the parameter's range)
     * @throws IllegalArgumentException naming the value and the range if it is outside
     */
    public void set(int index, float value) {
        checkIndex(index);
        DemoParameter parameter = declared.get(index);
        parameter.check(value);
        if (asked[index] != value) {
            asked[index] = value;
            ++version;
        }
        if (started && parameter.getApplies() == DemoParameter.Applies.LIVE) {
            applyAt(index);
        }
    }

    /**
     * Apply every value to the scene: once, after the scene was built.
     */
    public void start() {
        started = true;
        for (int i = 0; i < declared.size(); ++i) {
            applyAt(i);
        }
    }

    /** @return true once {@link #start()} ran */
    public boolean isStarted() {
        return started;
    }

    /**
     * Apply the values that wait for a launch; call just before a reset or a launch puts the
     * particles at their launch states. Does nothing before {@link #start()}.
     */
    public void applyPending() {
        if (!started) {
            return;
        }
        for (int i = 0; i < declared.size(); ++i) {
            if (inScene[i] != asked[i]) {
                applyAt(i);
            }
        }
    }

    /**
     * Test whether a value asked for waits for the next launch.
     *
     * @param index which (&ge;0, &lt;{@link #size()})
     * @return true if the scene runs with another value until then
     */
    public boolean isPending(int index) {
        checkIndex(index);
        return started && inScene[index] != asked[index];
    }

    /**
     * Copy the values the scene runs with, e.g. to remember a launch.
     *
     * @param storeResult where to write them (not null, at least {@link #size()} long)
     * @return storeResult
     */
    public float[] copyValuesInScene(float[] storeResult) {
        System.arraycopy(inScene, 0, storeResult, 0, declared.size());
        return storeResult;
    }

    /**
     * Write what differs between two sets of values, e.g. "h = 1/10 s vs 1/60 s,  b = 0.30
     * vs 0.90 N s/m": the kept shot's label. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param then the values of the earlier launch (from {@link #copyValuesInScene})
     * @param now the values to compare with (the same length)
     * @return how many values differ (&ge;0); nothing is appended when none does
     */
    public int appendDifferences(StringBuilder text, float[] then, float[] now) {
        int differences = 0;
        for (int i = 0; i < declared.size(); ++i) {
            if (then[i] != now[i]) {
                DemoParameter parameter = declared.get(i);
                text.append(differences == 0 ? "" : ",  ").append(parameter.getName())
                        .append(" = ");
                parameter.appendValue(text, then[i]).append(" vs ");
                parameter.appendValue(text, now[i]);
                ++differences;
            }
        }
        return differences;
    }

    /**
     * Write every parameter with its range on one line, for a message about a bad value.
     *
     * @return e.g. "the parameters are h (fixed step) from 1/240 s to 1/5 s, b (...) ..."
     */
    public String describeAll() {
        StringBuilder text = new StringBuilder();
        if (declared.isEmpty()) {
            return "this demo has no parameters";
        }
        text.append("the parameters are ");
        for (int i = 0; i < declared.size(); ++i) {
            text.append(i == 0 ? "" : ", ");
            declared.get(i).appendRange(text);
        }
        return text.toString();
    }

    // ------------------------------------------------------- the panel's model ----

    @Override
    public int countRows() {
        return declared.size();
    }

    @Override
    public int getSelected() {
        return selected;
    }

    /**
     * Tell a listener of the panel's changes from now on (one at a time).
     *
     * @param listener the listener, or null for none
     */
    public void setPanelListener(PanelListener listener) {
        panelListener = listener;
    }

    @Override
    public void select(int row) {
        checkIndex(row);
        if (panelListener != null) {
            panelListener.panelSelected(row);
        }
        selectRow(row);
    }

    /**
     * Select the line above or below, wrapping around.
     *
     * @param direction +1 for the next line, -1 for the one before
     */
    public void moveSelection(int direction) {
        if (declared.isEmpty()) {
            return;
        }
        int count = declared.size();
        selectRow(((selected + direction) % count + count) % count);
    }

    /**
     * Change the selected value by one step or stop, clamped to its range.
     *
     * @param direction +1 up, -1 down
     */
    public void nudgeSelected(int direction) {
        if (declared.isEmpty()) {
            return;
        }
        set(selected, declared.get(selected).nudged(asked[selected], direction));
    }

    @Override
    public float getSliderFraction(int row) {
        checkIndex(row);
        return declared.get(row).sliderFraction(asked[row]);
    }

    @Override
    public void setSliderFraction(int row, float fraction) {
        checkIndex(row);
        float value = declared.get(row).valueAtFraction(fraction);
        if (panelListener != null) {
            panelListener.panelSet(row, value);
        }
        set(row, value);
    }

    @Override
    public float getSliderStep(int row) {
        checkIndex(row);
        return declared.get(row).sliderStep();
    }

    @Override
    public StringBuilder formatRow(int row, StringBuilder text) {
        checkIndex(row);
        DemoParameter parameter = declared.get(row);
        text.append(row == selected ? SELECTED_MARK : UNSELECTED_MARK)
                .append(parameter.getName()).append(" = ");
        parameter.appendValue(text, asked[row]).append("   ").append(parameter.getLabel());
        if (isPending(row)) {
            text.append(PENDING_NOTE);
        }
        return text;
    }

    @Override
    public int getVersion() {
        return version;
    }

    /**
     * Write the whole panel as text, one line per parameter: what a test or the keyboard
     * user reads.
     *
     * @param text where to append (not null, modified)
     * @return text
     */
    public StringBuilder formatPanel(StringBuilder text) {
        for (int i = 0; i < declared.size(); ++i) {
            formatRow(i, text).append('\n');
        }
        return text;
    }

    private void selectRow(int row) {
        if (selected != row) {
            selected = row;
            ++version;
        }
    }

    private void applyAt(int index) {
        // Recorded first: a setter that resets the scene (which applies what waits) must
        // not apply this value again.
        inScene[index] = asked[index];
        ++version;
        declared.get(index).apply(asked[index]);
    }

    private int require(String name) {
        int index = indexOf(name);
        if (index < 0) {
            throw new IllegalArgumentException("no parameter named \"" + name + "\"; "
                    + describeAll());
        }
        return index;
    }

    private void checkIndex(int index) {
        if (index < 0 || index >= declared.size()) {
            throw new IllegalArgumentException("parameter index must be from 0 to "
                    + (declared.size() - 1) + ", but was " + index);
        }
    }
}

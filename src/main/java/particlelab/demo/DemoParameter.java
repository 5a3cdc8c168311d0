package particlelab.demo;

import particlelab.view.TextFormat;

/**
 * One number a demo lets the user change, declared the way a key is ({@link KeyBinding}): a
 * command-line-safe name ({@code b}), a label ("linear drag"), a unit, a range, the step the
 * panel's keys change it by, a default, whether a change applies {@link Applies#LIVE} or at
 * the {@link Applies#NEXT_LAUNCH}, and the setter that puts the value into the scene. The
 * panel, {@code --set} and the kept shots' labels are all written from these declarations.
 * Immutable.
 *
 * <p>Values are floats, as the physics is. The setter is a primitive functional interface,
 * so applying a value boxes nothing. A state that is no number (a preset, a strategy, a
 * switch) is a {@link #choice}: its values are the indexes 0, 1, ... of a few named values,
 * set by name from the command line ({@code --set preset=glancing}) and shown by name.
 *
 * <p>A parameter is one value, and no parameter has a grid: any value in the range reaches
 * the setter as given, and the setter puts it, unrounded, into the one object that uses it
 * (a force, a contact response, the launch). The step and the {@link #withStops stops} only
 * say where a key press or the slider goes next. A state that has only certain values is a
 * choice.
 */
public final class DemoParameter {

    /** When a new value reaches the scene. */
    public enum Applies {
        /** At once, in the middle of a flight (a drag coefficient, the step h). */
        LIVE,
        /** At the next reset or launch (a launch speed, a mass). */
        NEXT_LAUNCH
    }

    /** Puts a value into the scene. */
    @FunctionalInterface
    public interface Setter {
        /**
         * Apply a value.
         *
         * @param value the new value (within the parameter's range)
         */
        void set(float value);
    }

    /** Writes a value for people, e.g. a step h as "1/60 s". */
    @FunctionalInterface
    public interface Display {
        /**
         * Append a value with its unit, allocating nothing.
         *
         * @param text where to append (not null, modified)
         * @param value the value
         * @return text
         */
        StringBuilder append(StringBuilder text, float value);
    }

    /** The largest denominator n for which a step is shown as "1/n s". */
    private static final int MAX_DENOMINATOR = 1000;
    /** How close h·n must be to 1 to be shown as "1/n" (a float's round-off, with room). */
    private static final float FRACTION_TOLERANCE = 1e-4f;

    private final String name;
    private final String label;
    private final String unit;
    private final float min;
    private final float max;
    private final float step;
    private final float defaultValue;
    private final Applies applies;
    private final int decimals;
    private final Setter setter;
    private final Display display;
    /** The values the keys and the slider step through, ascending; null: every step. */
    private final float[] stops;
    /** A choice's names, by index; null for a number. */
    private final String[] choices;

    /**
     * Declare a parameter shown with a fixed number of decimals and its unit.
     *
     * @param name the command-line name, e.g. "b" or "speed" (a lower-case letter, then
     *     letters, digits or '_')
     * @param label what it is, e.g. "linear drag" (not null, not empty)
     * @param unit its unit as printed, e.g. "N s/m", or "" for a pure number (not null)
     * @param min the smallest value allowed (finite)
     * @param max the largest value allowed (finite, &gt;min)
     * @param step what one key press adds or takes (&gt;0, at most max − min)
     * @param defaultValue the value at the start (from min to max)
     * @param decimals how many decimals to print (0 to {@link TextFormat#MAX_DECIMALS})
     * @param applies when a change reaches the scene (not null)
     * @param setter puts a value into the scene (not null)
     */
    public DemoParameter(String name, String label, String unit, float min, float max,
            float step, float defaultValue, int decimals, Applies applies, Setter setter) {
        this(name, label, unit, min, max, step, defaultValue, decimals, applies, setter, null,
                null, null);
    }

    private DemoParameter(String name, String label, String unit, float min, float max,
            float step, float defaultValue, int decimals, Applies applies, Setter setter,
            Display display, float[] stops, String[] choices) {
        if (name == null || !name.matches("[a-z][a-z0-9_]*")) {
            throw new IllegalArgumentException("parameter name must be a lower-case letter"
                    + " followed by letters, digits or '_', but was "
                    + (name == null ? "null" : "\"" + name + "\""));
        }
        if (label == null || label.isEmpty() || unit == null) {
            throw new IllegalArgumentException("parameter " + name
                    + " needs a non-empty label and a unit (\"\" for none)");
        }
        if (!Float.isFinite(min) || !Float.isFinite(max) || !(min < max)) {
            throw new IllegalArgumentException("parameter " + name + ": the range must be"
                    + " finite with min < max, but was " + min + " to " + max);
        }
        if (!(step > 0f) || step > max - min) {
            throw new IllegalArgumentException("parameter " + name + ": the step must be > 0"
                    + " and at most " + (max - min) + ", but was " + step);
        }
        if (!(defaultValue >= min && defaultValue <= max)) {
            throw new IllegalArgumentException("parameter " + name + ": the default must be"
                    + " from " + min + " to " + max + ", but was " + defaultValue);
        }
        if (decimals < 0 || decimals > TextFormat.MAX_DECIMALS) {
            throw new IllegalArgumentException("parameter " + name + ": decimals must be from"
                    + " 0 to " + TextFormat.MAX_DECIMALS + ", but was " + decimals);
        }
        if (applies == null || setter == null) {
            throw new IllegalArgumentException("parameter " + name
                    + " needs when it applies and a setter");
        }
        this.name = name;
        this.label = label;
        this.unit = unit;
        this.min = min;
        this.max = max;
        this.step = step;
        this.defaultValue = defaultValue;
        this.decimals = decimals;
        this.applies = applies;
        this.setter = setter;
        this.display = display;
        this.stops = stops;
        this.choices = choices;
    }

    /**
     * Declare a state that is one of a few named values, e.g. a collision preset: its values
     * are the indexes 0 to n − 1, the keys step through them, the command line names them
     * ({@code --set preset=glancing}) and the panel shows the name.
     *
     * @param name the command-line name (as for a number)
     * @param label what it is, e.g. "collision preset" (not null, not empty)
     * @param names the values' names in key order (at least 2, each a lower-case letter or
     *     a digit, then letters, digits, '.', '-' or '_'; distinct; copied)
     * @param defaultIndex the value at the start (0 to n − 1)
     * @param applies when a change reaches the scene (not null)
     * @param setter puts an index into the scene, as a whole float (not null)
     * @return the declaration (not null)
     */
    public static DemoParameter choice(String name, String label, String[] names,
            int defaultIndex, Applies applies, Setter setter) {
        if (names == null || names.length < 2) {
            throw new IllegalArgumentException("choice " + name + " needs at least 2 names");
        }
        for (int i = 0; i < names.length; ++i) {
            if (names[i] == null || !names[i].matches("[a-z0-9][a-z0-9._-]*")) {
                throw new IllegalArgumentException("choice " + name + ": a name must be a"
                        + " lower-case letter or a digit, then letters, digits, '.', '-' or"
                        + " '_', but name " + i + " was " + names[i]);
            }
            for (int j = 0; j < i; ++j) {
                if (names[j].equals(names[i])) {
                    throw new IllegalArgumentException("choice " + name + ": the name "
                            + names[i] + " is given twice");
                }
            }
        }
        return new DemoParameter(name, label, "", 0f, names.length - 1f, 1f, defaultIndex, 0,
                applies, setter, null, null, names.clone());
    }

    /**
     * Copy this declaration with another way to print values.
     *
     * @param newDisplay writes a value with its unit (not null)
     * @return a new declaration (not null)
     */
    public DemoParameter withDisplay(Display newDisplay) {
        if (newDisplay == null) {
            throw new IllegalArgumentException("display of parameter " + name
                    + " must not be null");
        }
        return new DemoParameter(name, label, unit, min, max, step, defaultValue, decimals,
                applies, setter, newDisplay, stops, choices);
    }

    /**
     * Copy this declaration with values for the keys and the slider to step through, instead
     * of even steps: for a step h, 1/240, 1/120, 1/60 ... s. Any value in the range may still
     * be set from the command line.
     *
     * @param newStops the values (not null, at least 2, ascending, each in the range; copied)
     * @return a new declaration (not null)
     */
    public DemoParameter withStops(float... newStops) {
        if (newStops == null || newStops.length < 2) {
            throw new IllegalArgumentException("parameter " + name
                    + " needs at least 2 stops");
        }
        for (int i = 0; i < newStops.length; ++i) {
            if (!accepts(newStops[i]) || i > 0 && !(newStops[i] > newStops[i - 1])) {
                throw new IllegalArgumentException("parameter " + name + ": stops must ascend"
                        + " from " + min + " to " + max + ", but stop " + i + " was "
                        + newStops[i]);
            }
        }
        return new DemoParameter(name, label, unit, min, max, step, defaultValue, decimals,
                applies, setter, display, newStops.clone(), choices);
    }

    /**
     * Write a duration as a fraction "1/n s" when it is one (to float round-off), else in
     * seconds with four decimals: how the lecture names a step h.
     *
     * @param text where to append (not null, modified)
     * @param seconds the duration (in seconds, &gt;0)
     * @return text
     */
    public static StringBuilder appendStep(StringBuilder text, float seconds) {
        float denominator = 1f / seconds;
        int n = Math.round(denominator);
        if (n >= 1 && n <= MAX_DENOMINATOR
                && Math.abs(denominator - n) <= FRACTION_TOLERANCE * n) {
            return text.append("1/").append(n).append(" s");
        }
        return TextFormat.appendFixed(text, seconds, 4).append(" s");
    }

    /**
     * Write a number as short as it reads: rounded to at most some decimals, without
     * trailing zeros ("10", "0.9", "0.064"), for equations in the HUD. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param value the number
     * @param maxDecimals the most decimals (0 to {@link TextFormat#MAX_DECIMALS})
     * @return text
     */
    public static StringBuilder appendShort(StringBuilder text, float value, int maxDecimals) {
        int start = text.length();
        TextFormat.appendFixed(text, value, maxDecimals);
        if (maxDecimals > 0 && text.indexOf(".", start) >= 0) {
            int end = text.length();
            while (text.charAt(end - 1) == '0') {
                --end;
            }
            if (text.charAt(end - 1) == '.') {
                --end;
            }
            text.setLength(end);
        }
        return text;
    }

    /** @return the command-line name, e.g. "b" (not null) */
    public String getName() {
        return name;
    }

    /** @return what it is, e.g. "linear drag" (not null) */
    public String getLabel() {
        return label;
    }

    /** @return the unit as printed ("" for none; not null) */
    public String getUnit() {
        return unit;
    }

    /** @return the smallest value allowed */
    public float getMin() {
        return min;
    }

    /** @return the largest value allowed */
    public float getMax() {
        return max;
    }

    /** @return what one key press adds or takes (&gt;0) */
    public float getStep() {
        return step;
    }

    /** @return the value at the start */
    public float getDefault() {
        return defaultValue;
    }

    /** @return when a change reaches the scene (not null) */
    public Applies getApplies() {
        return applies;
    }

    /** @return true if this is a {@link #choice} of named values, false for a number */
    public boolean isChoice() {
        return choices != null;
    }

    /**
     * Count a choice's values.
     *
     * @return how many names (&ge;2), or 0 for a number
     */
    public int countChoices() {
        return choices == null ? 0 : choices.length;
    }

    /**
     * Return one of a choice's names.
     *
     * @param index which (0 to {@link #countChoices()} − 1)
     * @return the name, e.g. "glancing" (not null)
     */
    public String getChoice(int index) {
        if (choices == null || index < 0 || index >= choices.length) {
            throw new IllegalArgumentException("parameter " + name + " has no choice "
                    + index);
        }
        return choices[index];
    }

    /**
     * Find a choice's value by its name, as {@code --set NAME=VALUE} gives it.
     *
     * @param text the name (case-sensitive)
     * @return the index, or -1 if this is no choice or none has that name
     */
    public int indexOfChoice(String text) {
        if (choices != null) {
            for (int i = 0; i < choices.length; ++i) {
                if (choices[i].equals(text)) {
                    return i;
                }
            }
        }
        return -1;
    }

    /**
     * Test whether a value is allowed.
     *
     * @param value the value
     * @return true if finite and from min to max (for a choice: one of its indexes)
     */
    public boolean accepts(float value) {
        return value >= min && value <= max && (choices == null || value == Math.round(value));
    }

    /**
     * Refuse a value out of range.
     *
     * @param value the value
     * @return value
     * @throws IllegalArgumentException naming the parameter, the value and the range
     */
    public float check(float value) {
        if (!accepts(value)) {
            StringBuilder text = new StringBuilder();
            text.append(name).append(" = ").append(value).append(" is out of range: ");
            appendRange(text);
            throw new IllegalArgumentException(text.toString());
        }
        return value;
    }

    /**
     * Write a value for people: with the declared display, else with the declared decimals
     * and the unit.
     *
     * @param text where to append (not null, modified)
     * @param value the value
     * @return text
     */
    public StringBuilder appendValue(StringBuilder text, float value) {
        if (choices != null) {
            return text.append(choices[Math.max(0, Math.min(choices.length - 1,
                    Math.round(value)))]);
        }
        if (display != null) {
            return display.append(text, value);
        }
        TextFormat.appendFixed(text, value, decimals);
        if (!unit.isEmpty()) {
            text.append(' ').append(unit);
        }
        return text;
    }

    /**
     * Write a value as {@link #appendValue} does, in ASCII for a terminal that may not show
     * more: a superscript 2 becomes {@code ^2} (m/s² → m/s^2).
     */
    private StringBuilder appendAsciiValue(StringBuilder text, float value) {
        int start = text.length();
        appendValue(text, value);
        for (int i = text.length() - 1; i >= start; --i) {
            if (text.charAt(i) == '\u00B2') {
                text.replace(i, i + 1, "^2");
            }
        }
        return text;
    }

    /**
     * Write the declaration and its range for the command line, e.g. "b (linear drag) from
     * 0.00 N s/m to 5.00 N s/m" (in ASCII: "g (gravity) from 1.0 m/s^2 to ..."); a choice's
     * names, e.g. "preset (collision preset) one of head-on|glancing|cradle|paddle".
     *
     * @param text where to append (not null, modified)
     * @return text
     */
    public StringBuilder appendRange(StringBuilder text) {
        if (choices != null) {
            text.append(name).append(" (").append(label).append(") one of ");
            for (int i = 0; i < choices.length; ++i) {
                text.append(i == 0 ? "" : "|").append(choices[i]);
            }
            return text;
        }
        text.append(name).append(" (").append(label).append(") from ");
        appendAsciiValue(text, min).append(" to ");
        return appendAsciiValue(text, max);
    }

    /**
     * Return the value one key press up or down from a value: one step, or the next stop,
     * clamped to the range.
     *
     * @param value the value now
     * @param direction +1 for up, -1 for down
     * @return the new value, within the range
     */
    public float nudged(float value, int direction) {
        if (stops == null) {
            // Round to whole steps from min, so repeated presses land on even values.
            float steps = Math.round((value - min) / step) + Math.signum(direction);
            return clamp(min + steps * step);
        }
        if (direction > 0) {
            for (int i = 0; i < stops.length; ++i) {
                if (stops[i] > value * (1f + FRACTION_TOLERANCE)) {
                    return stops[i];
                }
            }
            return stops[stops.length - 1];
        }
        for (int i = stops.length - 1; i >= 0; --i) {
            if (stops[i] < value * (1f - FRACTION_TOLERANCE)) {
                return stops[i];
            }
        }
        return stops[0];
    }

    /**
     * Return where a value sits on a slider: its share of the range, or of the stops.
     *
     * @param value the value
     * @return from 0 to 1
     */
    public float sliderFraction(float value) {
        if (stops == null) {
            return Math.max(0f, Math.min(1f, (value - min) / (max - min)));
        }
        int nearest = 0;
        for (int i = 1; i < stops.length; ++i) {
            if (Math.abs(stops[i] - value) < Math.abs(stops[nearest] - value)) {
                nearest = i;
            }
        }
        return nearest / (float) (stops.length - 1);
    }

    /**
     * Return one step or stop as a share of a slider.
     *
     * @return the share (&gt;0, &le;1)
     */
    public float sliderStep() {
        return stops == null ? step / (max - min) : 1f / (stops.length - 1);
    }

    /**
     * Return the value at a place on a slider, on a whole step or a stop.
     *
     * @param fraction the place (0 for the left end, 1 for the right; clamped)
     * @return the value, within the range
     */
    public float valueAtFraction(float fraction) {
        float f = Math.max(0f, Math.min(1f, fraction));
        if (stops == null) {
            return clamp(min + Math.round(f * (max - min) / step) * step);
        }
        return stops[Math.round(f * (stops.length - 1))];
    }

    /**
     * Put a value into the scene.
     *
     * @param value the value (checked against the range)
     */
    void apply(float value) {
        setter.set(check(value));
    }

    @Override
    public String toString() {
        return appendRange(new StringBuilder()).toString();
    }

    private float clamp(float value) {
        return Math.max(min, Math.min(max, value));
    }
}

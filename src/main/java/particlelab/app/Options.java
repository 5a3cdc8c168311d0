package particlelab.app;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The options of one subcommand, shared by every command of {@code particle-lab}: declare each
 * option with a line of help, parse the arguments, then read typed, validated values.
 *
 * <pre>
 *   Options options = new Options("particle-lab demo", "Run one demo headless.");
 *   options.value("--demo", "NAME", "the demo to run (required)");
 *   options.value("--frames", "N", "frames to run; default 600");
 *   options.flag("--csv", "print CSV instead of text");
 *   options.parse(args);                    // UsageException on a bad command line
 *   if (options.isHelpRequested()) {
 *       out.print(options.help());          // generated from the declarations above
 *       return 0;
 *   }
 *   String demo = options.string("--demo");            // no default: required
 *   int frames = options.intInRange("--frames", 600, 1, 1_000_000);
 * </pre>
 *
 * <p>The command line accepts {@code --name value} and {@code --name=value} for options with a
 * value, and {@code --name} alone for flags; {@code -h} and {@code --help} are always declared.
 * A value may start with a single minus ({@code --g 0,-9.8,0}); a token starting with
 * {@code --} is never taken as a value. Numbers are decimals ({@code 0.5}, {@code -1e-3}) or
 * fractions of two decimals ({@code 1/60}), in ASCII digits ({@link #number}, which
 * {@code demo --set} reads too); {@code NaN} and infinities are refused. Vectors are three
 * numbers separated by commas, {@code X,Y,Z}.
 *
 * <p>Every error is a {@link UsageException} whose message is one line naming the option, the
 * bad value and what is allowed: {@code --mass: must be a finite number > 0, but was -1}.
 * Calling a getter for an option that was never declared is a programming error
 * ({@link IllegalArgumentException}).
 */
public final class Options {

    /** The long help option, declared for every command. */
    public static final String HELP = "--help";
    /** The short help option. */
    public static final String SHORT_HELP = "-h";

    /** Help text is wrapped to fit an 80-column terminal. */
    private static final int HELP_WIDTH = 79;
    /** Where option descriptions start in the help text, unless a name is longer. */
    private static final int HELP_DESCRIPTION_COLUMN = 24;
    /**
     * The longest number accepted, in characters: far more than a float's 9 significant
     * digits need, short enough that no argument can make parsing slow.
     */
    static final int MAX_NUMBER_LENGTH = 64;
    /** Messages show at most this many characters of a value, then its length. */
    private static final int MAX_SHOWN_LENGTH = 40;

    private final String command;
    private final String summary;
    /** Declared options by name, in the order the help lists them. */
    private final Map<String, Declaration> declared = new LinkedHashMap<>();
    /** Options given on the command line: name to raw value ("" for flags). */
    private final Map<String, String> given = new LinkedHashMap<>();
    /** Every value of each repeatable option given, in order. */
    private final Map<String, List<String>> repeated = new LinkedHashMap<>();
    private final List<String> notes = new ArrayList<>();
    private boolean helpRequested;

    /**
     * Create the options of one command, with only {@code -h, --help} declared.
     *
     * @param command how the user invokes the command, e.g. "particle-lab trajectory" (not null)
     * @param summary one or two sentences saying what the command does (not null)
     */
    public Options(String command, String summary) {
        this.command = command;
        this.summary = summary;
    }

    /**
     * Declare an option that takes a value.
     *
     * @param name the option, e.g. "--mass" (starts with "--", not declared before)
     * @param placeholder how the help shows the value, e.g. "KG" or "X,Y,Z" (not null)
     * @param description what it means, its unit and its default (not null)
     * @return this, to chain declarations
     */
    public Options value(String name, String placeholder, String description) {
        declare(new Declaration(name, placeholder, description));
        return this;
    }

    /**
     * Declare an option that takes a value and may be given any number of times, e.g.
     * {@code --set b=0.5 --set h=1/10}; read with {@link #strings}.
     *
     * @param name the option (starts with "--", not declared before)
     * @param placeholder how the help shows the value (not null)
     * @param description what it means (not null)
     * @return this, to chain declarations
     */
    public Options repeatable(String name, String placeholder, String description) {
        Declaration option = new Declaration(name, placeholder, description);
        option.repeatable = true;
        declare(option);
        return this;
    }

    /**
     * Read every value of a repeatable option, in the order given.
     *
     * @param name a declared repeatable option
     * @return a new list (not null, empty if not given)
     */
    public List<String> strings(String name) {
        checkDeclared(name);
        List<String> values = repeated.get(name);
        return values == null ? new ArrayList<>() : new ArrayList<>(values);
    }

    /**
     * Declare a flag: an option that takes no value.
     *
     * @param name the option, e.g. "--csv" (starts with "--", not declared before)
     * @param description what it does (not null)
     * @return this, to chain declarations
     */
    public Options flag(String name, String description) {
        declare(new Declaration(name, null, description));
        return this;
    }

    /**
     * Add a paragraph the help prints after the options (decisions, units, exit codes).
     *
     * @param paragraph the text, wrapped when printed (not null)
     * @return this, to chain declarations
     */
    public Options note(String paragraph) {
        notes.add(paragraph);
        return this;
    }

    /**
     * Parse a command line, forgetting any earlier one. When {@code -h} or {@code --help} is
     * among the arguments nothing else is checked: the caller should print {@link #help()}.
     *
     * @param args the arguments after the command's name (not null)
     * @throws UsageException on an unknown option, a flag given a value, an option given twice,
     *     a missing value, or an argument that is not an option
     */
    public void parse(String[] args) {
        given.clear();
        repeated.clear();
        helpRequested = false;
        for (String arg : args) {
            if (HELP.equals(arg) || SHORT_HELP.equals(arg)) {
                helpRequested = true;
                return;
            }
        }
        for (int i = 0; i < args.length; ++i) {
            String arg = args[i];
            if (!arg.startsWith("-")) {
                throw new UsageException("unexpected argument " + show(arg)
                        + ": options start with --" + seeHelp());
            }
            String name = arg;
            String value = null;
            int equals = arg.indexOf('=');
            if (equals >= 0) {
                name = arg.substring(0, equals);
                value = arg.substring(equals + 1);
            }
            Declaration option = declared.get(name);
            if (option == null) {
                throw new UsageException(show(name) + ": unknown option for " + command
                        + "; the options are " + String.join(", ", declared.keySet()) + ", "
                        + HELP);
            }
            if (given.containsKey(name) && !option.repeatable) {
                throw new UsageException(name + ": given twice; give it once" + seeHelp());
            }
            if (option.isFlag()) {
                if (value != null) {
                    throw new UsageException(name + ": is a flag and takes no value, but was "
                            + "given " + show(value));
                }
                value = "";
            } else if (value == null) {
                if (i + 1 < args.length && !args[i + 1].startsWith("--")) {
                    value = args[++i];
                } else {
                    value = "";
                }
            }
            if (!option.isFlag() && value.isEmpty()) {
                throw new UsageException(name + ": needs a value " + option.placeholder
                        + ", but none was given" + seeHelp());
            }
            given.put(name, value);
            if (option.repeatable) {
                repeated.computeIfAbsent(name, key -> new ArrayList<>()).add(value);
            }
        }
    }

    /**
     * Test whether {@code -h} or {@code --help} was given.
     *
     * @return true if the caller should print {@link #help()} and do nothing else
     */
    public boolean isHelpRequested() {
        return helpRequested;
    }

    /**
     * Test whether an option was given.
     *
     * @param name a declared option
     * @return true if it was on the command line
     */
    public boolean has(String name) {
        checkDeclared(name);
        return given.containsKey(name);
    }

    /**
     * Require that at most one of several options was given.
     *
     * @param names declared options (at least two)
     * @throws UsageException if two or more were given
     */
    public void atMostOneOf(String... names) {
        List<String> present = present(names);
        if (present.size() > 1) {
            throw new UsageException(present.get(0) + ": cannot be combined with "
                    + present.get(1) + "; give at most one of " + String.join(", ", names));
        }
    }

    /**
     * Require that exactly one of several options was given.
     *
     * @param names declared options (at least two)
     * @throws UsageException if none or more than one was given
     */
    public void exactlyOneOf(String... names) {
        atMostOneOf(names);
        if (present(names).isEmpty()) {
            throw new UsageException(names[0] + ": missing; give exactly one of "
                    + String.join(", ", names) + seeHelp());
        }
    }

    /**
     * Read a required text value.
     *
     * @param name a declared option with a value
     * @return the value (not null, not empty)
     * @throws UsageException if the option was not given
     */
    public String string(String name) {
        checkDeclared(name);
        return required(name, "a value " + declared.get(name).placeholder);
    }

    /**
     * Read an optional text value.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent (may be null)
     * @return the value given, or defaultValue
     */
    public String string(String name, String defaultValue) {
        String text = raw(name);
        return text == null ? defaultValue : text;
    }

    /**
     * Read a value that must be one of a few words.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent
     * @param allowed the words allowed (at least one)
     * @return one of allowed, or defaultValue
     * @throws UsageException if the value given is not one of allowed
     */
    public String choice(String name, String defaultValue, String... allowed) {
        String text = raw(name);
        if (text == null) {
            return defaultValue;
        }
        for (String word : allowed) {
            if (word.equals(text)) {
                return word;
            }
        }
        throw bad(name, "must be one of " + String.join(", ", allowed), text);
    }

    /**
     * Read a required number greater than zero.
     *
     * @param name a declared option with a value
     * @return the value (finite, &gt;0)
     * @throws UsageException if the option is absent or its value is not a finite number
     *     &gt;0
     */
    public float positiveFloat(String name) {
        required(name, "a finite number > 0");
        return positiveFloat(name, Float.NaN);
    }

    /**
     * Read an optional number greater than zero.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent
     * @return the value given (finite, &gt;0), or defaultValue
     * @throws UsageException if the value given is not a finite number &gt;0
     */
    public float positiveFloat(String name, float defaultValue) {
        String text = raw(name);
        if (text == null) {
            return defaultValue;
        }
        float value = parseNumber(name, text);
        if (!(Float.isFinite(value) && value > 0f)) {
            throw bad(name, "must be a finite number > 0", text);
        }
        return value;
    }

    /**
     * Read an optional number of at least a minimum.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent
     * @param min the smallest value allowed (finite)
     * @param why why that is the minimum, for the message, e.g. "so that 1/m is finite"
     * @return the value given (finite, &ge;min), or defaultValue
     * @throws UsageException if the value given is not a finite number &ge;min
     */
    public float floatAtLeast(String name, float defaultValue, float min, String why) {
        String text = raw(name);
        if (text == null) {
            return defaultValue;
        }
        float value = parseNumber(name, text);
        if (!(Float.isFinite(value) && value >= min)) {
            throw bad(name, "must be a finite number >= " + min + " (" + why + ")", text);
        }
        return value;
    }

    /**
     * Read an optional number of at least zero.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent
     * @return the value given (finite, &ge;0), or defaultValue
     * @throws UsageException if the value given is not a finite number &ge;0
     */
    public float nonNegativeFloat(String name, float defaultValue) {
        String text = raw(name);
        if (text == null) {
            return defaultValue;
        }
        float value = parseNumber(name, text);
        if (!(Float.isFinite(value) && value >= 0f)) {
            throw bad(name, "must be a finite number >= 0", text);
        }
        return value;
    }

    /**
     * Read an optional finite number.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent
     * @return the value given (finite), or defaultValue
     * @throws UsageException if the value given is not a finite number
     */
    public float finiteFloat(String name, float defaultValue) {
        String text = raw(name);
        if (text == null) {
            return defaultValue;
        }
        float value = parseNumber(name, text);
        if (!Float.isFinite(value)) {
            throw bad(name, "must be a finite number", text);
        }
        return value;
    }

    /**
     * Read an optional whole number in a range.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent
     * @param min the smallest value allowed
     * @param max the largest value allowed (&ge;min)
     * @return the value given (from min to max), or defaultValue
     * @throws UsageException if the value given is not a whole number from min to max
     */
    public int intInRange(String name, int defaultValue, int min, int max) {
        String text = raw(name);
        if (text == null) {
            return defaultValue;
        }
        if (isWhole(text)) {
            try {
                long value = Long.parseLong(text);
                if (value >= min && value <= max) {
                    return (int) value;
                }
            } catch (NumberFormatException tooManyDigits) {
                // out of range: reported below
            }
        }
        throw bad(name, "must be a whole number from " + min + " to " + max, text);
    }

    /**
     * Read an optional vector {@code X,Y,Z} of finite numbers.
     *
     * @param name a declared option with a value
     * @param defaultValue the value when the option is absent (not null, not modified)
     * @return a new vector: the value given, or a copy of defaultValue
     * @throws UsageException if the value given is not three finite numbers
     */
    public Vector3f vector(String name, Vector3f defaultValue) {
        String text = raw(name);
        if (text == null) {
            return defaultValue.clone();
        }
        String[] parts = text.split(",", -1);
        if (parts.length == 3) {
            float x = parseNumber(name, parts[0].trim());
            float y = parseNumber(name, parts[1].trim());
            float z = parseNumber(name, parts[2].trim());
            if (Float.isFinite(x) && Float.isFinite(y) && Float.isFinite(z)) {
                return new Vector3f(x, y, z);
            }
        }
        throw bad(name, "must be three finite numbers X,Y,Z such as 0,-9.8,0", text);
    }

    /**
     * Generate the help text from the declarations: usage, summary, every option with its
     * description, then the notes.
     *
     * @return the text, lines ending in '\n' (not null)
     */
    public String help() {
        StringBuilder text = new StringBuilder();
        text.append("Usage: ").append(command).append(" [OPTIONS]\n");
        wrap(summary, 0, text);
        text.append("\nOptions:\n");
        for (Declaration option : declared.values()) {
            String left = "  " + option.name
                    + (option.isFlag() ? "" : " " + option.placeholder);
            appendEntry(left, option.description, text);
        }
        appendEntry("  " + SHORT_HELP + ", " + HELP, "show this help and exit", text);
        for (String paragraph : notes) {
            text.append('\n');
            wrap(paragraph, 0, text);
        }
        return text.toString();
    }

    /**
     * List the declared options (not {@code --help}), in declaration order.
     *
     * @return the names (a new list)
     */
    public List<String> names() {
        return new ArrayList<>(declared.keySet());
    }

    private void declare(Declaration option) {
        if (!option.name.startsWith("--") || HELP.equals(option.name)
                || declared.containsKey(option.name)) {
            throw new IllegalArgumentException("option name must start with -- and be new, but"
                    + " was " + option.name);
        }
        declared.put(option.name, option);
    }

    private void checkDeclared(String name) {
        if (!declared.containsKey(name)) {
            throw new IllegalArgumentException(command + " declares no option " + name);
        }
    }

    private String raw(String name) {
        checkDeclared(name);
        return given.get(name);
    }

    private String required(String name, String allowed) {
        String text = raw(name);
        if (text == null) {
            throw new UsageException(name + ": is required, " + allowed + seeHelp());
        }
        return text;
    }

    private List<String> present(String... names) {
        List<String> present = new ArrayList<>();
        for (String name : names) {
            if (has(name)) {
                present.add(name);
            }
        }
        return present;
    }

    private String seeHelp() {
        return " (see " + command + " " + HELP + ")";
    }

    private static UsageException bad(String name, String rule, String text) {
        return new UsageException(name + ": " + rule + ", but was " + show(text));
    }

    /**
     * Parse a decimal or a fraction {@code A/B} of two decimals, in time linear in its length.
     *
     * @param name the option, for the message when the text is too long
     * @return the value, or NaN if the text is neither
     * @throws UsageException if the text is longer than {@link #MAX_NUMBER_LENGTH}
     */
    private static float parseNumber(String name, String text) {
        if (text.length() > MAX_NUMBER_LENGTH) {
            throw bad(name, "a number has at most " + MAX_NUMBER_LENGTH + " characters", text);
        }
        return number(text);
    }

    /**
     * Read a number in the grammar every option uses: a decimal
     * {@code [+-]digits[.digits][(e|E)[+-]digits]} or a fraction {@code A/B} of two decimals,
     * ASCII digits only, no spaces, no suffix ({@code 1f}), no hexadecimal, no words
     * ({@code NaN}, {@code Infinity}). What {@code --set} and every numeric option read.
     *
     * @param text the text (not null)
     * @return the value (infinite if it overflows the float range), or NaN if the text is
     *     not a number in that grammar or longer than {@link #MAX_NUMBER_LENGTH} characters
     */
    static float number(String text) {
        if (text.length() > MAX_NUMBER_LENGTH) {
            return Float.NaN;
        }
        int slash = text.indexOf('/');
        if (slash < 0) {
            return isDecimal(text) ? Float.parseFloat(text) : Float.NaN;
        }
        String numerator = text.substring(0, slash);
        String denominator = text.substring(slash + 1);
        if (!isDecimal(numerator) || !isDecimal(denominator)) {
            return Float.NaN;
        }
        return (float) (Double.parseDouble(numerator) / Double.parseDouble(denominator));
    }

    /**
     * Test for a whole number {@code [+-]digits} of ASCII digits, the grammar of every
     * whole-number option (full-width and other scripts' digits are not digits here).
     *
     * @param text the text (not null)
     * @return true if it is one
     */
    static boolean isWhole(String text) {
        int start = skipSign(text, 0);
        return text.length() > start && skipDigits(text, start) == text.length();
    }

    /**
     * Test for a decimal {@code [+-]digits[.digits][(e|E)[+-]digits]} with at least one digit
     * before the exponent ({@code 5.} and {@code .5} are decimals, {@code .} is not), in one
     * pass over the characters (a regular expression backtracks on long digit runs).
     */
    private static boolean isDecimal(String text) {
        int length = text.length();
        int i = skipSign(text, 0);
        int end = skipDigits(text, i);
        int digits = end - i;
        i = end;
        if (i < length && text.charAt(i) == '.') {
            end = skipDigits(text, i + 1);
            digits += end - (i + 1);
            i = end;
        }
        if (digits == 0) {
            return false;
        }
        if (i < length && (text.charAt(i) == 'e' || text.charAt(i) == 'E')) {
            int start = skipSign(text, i + 1);
            i = skipDigits(text, start);
            if (i == start) {
                return false;
            }
        }
        return i == length;
    }

    private static int skipSign(String text, int i) {
        return i < text.length() && (text.charAt(i) == '+' || text.charAt(i) == '-') ? i + 1 : i;
    }

    private static int skipDigits(String text, int i) {
        int j = i;
        while (j < text.length() && text.charAt(j) >= '0' && text.charAt(j) <= '9') {
            ++j;
        }
        return j;
    }

    /**
     * Show a value in a one-line message: control characters (line breaks, terminal escapes)
     * made visible as four-digit Unicode escapes, and a long value cut to its first
     * {@value #MAX_SHOWN_LENGTH} characters followed by its length.
     *
     * @param text the value as given (not null)
     * @return the text to print (not null, no control characters)
     */
    static String show(String text) {
        return escape(text, MAX_SHOWN_LENGTH);
    }

    /**
     * Show a text whole in a one-line message: control characters made visible as in
     * {@link #show}, nothing cut (for a reason, which must be read to the end).
     *
     * @param text the text (not null)
     * @return the text to print (not null, no control characters)
     */
    static String showWhole(String text) {
        return escape(text, Integer.MAX_VALUE);
    }

    private static String escape(String text, int maxShown) {
        int shown = Math.min(text.length(), maxShown);
        StringBuilder result = new StringBuilder(shown + 32);
        for (int i = 0; i < shown; ++i) {
            char c = text.charAt(i);
            if (Character.isISOControl(c) || Character.getType(c) == Character.LINE_SEPARATOR
                    || Character.getType(c) == Character.PARAGRAPH_SEPARATOR) {
                result.append(String.format("\\u%04x", (int) c));
            } else {
                result.append(c);
            }
        }
        if (shown < text.length()) {
            result.append("... (").append(text.length()).append(" characters)");
        }
        return result.toString();
    }

    private static void appendEntry(String left, String description, StringBuilder text) {
        text.append(left);
        if (left.length() + 2 > HELP_DESCRIPTION_COLUMN) {
            text.append('\n').append(" ".repeat(HELP_DESCRIPTION_COLUMN));
        } else {
            text.append(" ".repeat(HELP_DESCRIPTION_COLUMN - left.length()));
        }
        int start = text.length();
        wrap(description, HELP_DESCRIPTION_COLUMN, text);
        // The first line's indent is already there.
        text.delete(start, start + HELP_DESCRIPTION_COLUMN);
    }

    /** Append words wrapped to {@link #HELP_WIDTH} columns, each line indented. */
    private static void wrap(String paragraph, int indent, StringBuilder text) {
        String pad = " ".repeat(indent);
        int column = 0;
        for (String word : paragraph.trim().split("\\s+")) {
            if (column > 0 && column + 1 + word.length() > HELP_WIDTH) {
                text.append('\n');
                column = 0;
            }
            if (column == 0) {
                text.append(pad).append(word);
                column = indent + word.length();
            } else {
                text.append(' ').append(word);
                column += 1 + word.length();
            }
        }
        text.append('\n');
    }

    /** One declared option. */
    private static final class Declaration {
        final String name;
        /** How the help shows the value; null for a flag. */
        final String placeholder;
        final String description;
        /** True if it may be given more than once. */
        boolean repeatable;

        Declaration(String name, String placeholder, String description) {
            this.name = name;
            this.placeholder = placeholder;
            this.description = description;
        }

        boolean isFlag() {
            return placeholder == null;
        }
    }
}

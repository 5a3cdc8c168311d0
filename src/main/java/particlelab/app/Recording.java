package particlelab.app;

import java.util.ArrayList;
import java.util.List;

/**
 * A recording of a demo's run ({@code demo NAME --record FILE}, issue 33) as plain text, one
 * item a line, and its reading ({@code --replay FILE}). A game loop's input is its frame times,
 * so the recording is per frame:
 * <pre>
 * particle-lab recording 1
 * demo drag
 * setting b=0.3              (each parameter that differs from its default at the start)
 * particles 2000             (the fountain's count, when not the default)
 * step 0.016666668           (the clock's step h at the start, as a check)
 * frames 60 tpf 0.016666668  (60 frames of the same frame time, as Float.toString writes it)
 * key Space                  (a press of one of the demo's keys, by its label, or of the
 *                            panel's button that does what the key does: Pause is Space)
 * export                     (an export was asked for: E or the panel's Export button)
 * select b                   (the panel selected a row)
 * set b 0.25                 (the panel's slider asked for a value)
 * drag start 0 0             (a drag of declaration 0's particle 0 starts)
 * drag move 0 0 1.5 2.0 0.0  (the value handed to Draggable.moveTo)
 * drag release
 * hash 60 1a2b3c4d5e6f7081   (after the frame: steps since the recording began, StateHash)
 * end the window closed      (the last line: why the recording ended)
 * </pre>
 * Numbers are written as {@link Float#toString} writes them, so they read back to the same
 * bits. Reading is strict: a line that is not one of these, a number that does not read or
 * is not finite, is refused with its line number.
 */
final class Recording {

    /** The first line's words before the version. */
    static final String MAGIC = Program.NAME + " recording";
    /** The version this program writes and reads. */
    static final int VERSION = 1;
    /** The first line. */
    static final String VERSION_LINE = MAGIC + " " + VERSION;

    /** What a line of the body is. */
    enum Kind {
        FRAMES, KEY, EXPORT, SELECT, SET, DRAG_START, DRAG_MOVE, DRAG_RELEASE, HASH
    }

    /** One line of the body. */
    static final class Item {
        final int line;
        /** The line as written. */
        final String source;
        final Kind kind;
        /** FRAMES: the count; DRAG_*: the declaration. */
        int count;
        /** DRAG_*: the particle. */
        int particle;
        /** FRAMES: the frame time (s); SET: the value; DRAG_MOVE: x (with y, z). */
        float value;
        float y;
        float z;
        /** KEY: the label; SELECT, SET: the parameter's name. */
        String text;
        /** HASH: the step and the hash. */
        long step;
        long hash;

        Item(int line, String source, Kind kind) {
            this.line = line;
            this.source = source;
            this.kind = kind;
        }
    }

    /** The demo's name. */
    String demo;
    /** The fountain's particle count, or 0 when not given. */
    int particles;
    /** The settings at the start, each NAME=VALUE as {@code --set} reads it. */
    final List<String> settings = new ArrayList<>();
    /** The clock's step at the start (in seconds). */
    float stepSeconds;
    /** The body, in order. */
    final List<Item> items = new ArrayList<>();
    /** Why the recording ended, or null if the file has no end line. */
    String end;

    /**
     * Read a recording.
     *
     * @param name the file as the user named it, for messages (not null)
     * @param lines its lines (not null)
     * @return the recording (not null)
     * @throws UsageException naming the file, the line and what is wrong with it
     */
    static Recording parse(String name, List<String> lines) {
        Recording recording = new Recording();
        String shown = "--replay " + name;
        if (lines.isEmpty() || !lines.get(0).startsWith(MAGIC + " ")) {
            throw new UsageException(shown + " is not a recording: its first line should be '"
                    + VERSION_LINE + "'");
        }
        String version = lines.get(0).substring(MAGIC.length() + 1);
        if (!version.equals(Integer.toString(VERSION))) {
            throw new UsageException(shown + " is a recording of version "
                    + Options.show(version) + "; this "
                    + Program.NAME + " reads version " + VERSION + " only");
        }
        boolean body = false;
        for (int i = 1; i < lines.size(); ++i) {
            int number = i + 1;
            String line = lines.get(i);
            if (recording.end != null) {
                throw bad(shown, number, line, "nothing may follow the end line");
            }
            String[] words = line.split(" ", -1);
            String kind = words[0];
            if (number == 2) {
                if (!kind.equals("demo") || words.length != 2 || words[1].isEmpty()) {
                    throw bad(shown, number, line, "the second line names the demo: demo NAME");
                }
                recording.demo = words[1];
                continue;
            }
            if (!body && kind.equals("setting") && words.length == 2
                    && words[1].indexOf('=') > 0) {
                recording.settings.add(words[1]);
                continue;
            }
            if (!body && kind.equals("particles") && words.length == 2) {
                recording.particles = (int) whole(shown, number, line, words[1], 1);
                continue;
            }
            if (!body && kind.equals("step") && words.length == 2) {
                recording.stepSeconds = number(shown, number, line, words[1]);
                continue;
            }
            if (kind.equals("end")) {
                recording.end = line.length() > 4 ? line.substring(4) : "";
                continue;
            }
            if (!body && recording.stepSeconds <= 0f) {
                throw bad(shown, number, line, "the header ends with the line step H");
            }
            body = true;
            recording.items.add(item(shown, number, line, words));
        }
        if (recording.demo == null) {
            throw new UsageException(shown + " has no line 2 (demo NAME)");
        }
        return recording;
    }

    /**
     * Write the header.
     *
     * @param demo the demo's name (not null)
     * @param particles the fountain's count, or 0 to leave it out
     * @param settings the settings that differ from the defaults (not null)
     * @param stepSeconds the clock's step (in seconds)
     * @param text where to write (not null, modified)
     */
    static void writeHeader(String demo, int particles, List<String> settings,
            float stepSeconds, StringBuilder text) {
        text.append(VERSION_LINE).append('\n').append("demo ").append(demo).append('\n');
        for (String setting : settings) {
            text.append("setting ").append(setting).append('\n');
        }
        if (particles > 0) {
            text.append("particles ").append(particles).append('\n');
        }
        text.append("step ").append(Float.toString(stepSeconds)).append('\n');
    }

    /** @return the frames the body holds (&ge;0) */
    long countFrames() {
        long frames = 0L;
        for (Item item : items) {
            if (item.kind == Kind.FRAMES) {
                frames += item.count;
            }
        }
        return frames;
    }

    private static Item item(String shown, int number, String line, String[] words) {
        String kind = words[0];
        switch (kind) {
            case "frames":
                if (words.length != 4 || !words[2].equals("tpf")) {
                    throw bad(shown, number, line, "frames N tpf T");
                }
                Item frames = new Item(number, line, Kind.FRAMES);
                frames.count = (int) whole(shown, number, line, words[1], 1);
                frames.value = number(shown, number, line, words[3]);
                if (frames.value < 0f) {
                    throw bad(shown, number, line, "a frame time is >= 0");
                }
                return frames;
            case "key":
                if (words.length < 2 || line.length() <= 4) {
                    throw bad(shown, number, line, "key LABEL");
                }
                Item key = new Item(number, line, Kind.KEY);
                key.text = line.substring(4);
                return key;
            case "export":
                if (words.length != 1) {
                    throw bad(shown, number, line, "export (nothing after it)");
                }
                return new Item(number, line, Kind.EXPORT);
            case "select":
                if (words.length != 2 || words[1].isEmpty()) {
                    throw bad(shown, number, line, "select NAME");
                }
                Item select = new Item(number, line, Kind.SELECT);
                select.text = words[1];
                return select;
            case "set":
                if (words.length != 3 || words[1].isEmpty()) {
                    throw bad(shown, number, line, "set NAME VALUE");
                }
                Item set = new Item(number, line, Kind.SET);
                set.text = words[1];
                set.value = number(shown, number, line, words[2]);
                return set;
            case "drag":
                return drag(shown, number, line, words);
            case "hash":
                if (words.length != 3 || words[2].length() != 16) {
                    throw bad(shown, number, line, "hash STEP HEX (16 hex digits)");
                }
                Item hash = new Item(number, line, Kind.HASH);
                hash.step = whole(shown, number, line, words[1], 0);
                try {
                    hash.hash = Long.parseUnsignedLong(words[2], 16);
                } catch (NumberFormatException notHex) {
                    throw bad(shown, number, line, "hash STEP HEX (16 hex digits)");
                }
                return hash;
            default:
                throw bad(shown, number, line, "a line is frames, key, export, select, set, drag,"
                        + " hash or end");
        }
    }

    private static Item drag(String shown, int number, String line, String[] words) {
        if (words.length == 2 && words[1].equals("release")) {
            return new Item(number, line, Kind.DRAG_RELEASE);
        }
        boolean start = words.length == 4 && words[1].equals("start");
        boolean move = words.length == 7 && words[1].equals("move");
        if (!start && !move) {
            throw bad(shown, number, line, "drag start D P, drag move D P X Y Z or drag"
                    + " release");
        }
        Item drag = new Item(number, line, start ? Kind.DRAG_START : Kind.DRAG_MOVE);
        drag.count = (int) whole(shown, number, line, words[2], 0);
        drag.particle = (int) whole(shown, number, line, words[3], 0);
        if (move) {
            drag.value = number(shown, number, line, words[4]);
            drag.y = number(shown, number, line, words[5]);
            drag.z = number(shown, number, line, words[6]);
        }
        return drag;
    }

    private static float number(String shown, int number, String line, String text) {
        float value;
        try {
            value = Float.parseFloat(text);
        } catch (NumberFormatException notNumber) {
            throw bad(shown, number, line, Options.show(text) + " is not a number");
        }
        if (!Float.isFinite(value) || !text.matches("-?[0-9.]+(E-?[0-9]+)?")) {
            throw bad(shown, number, line, Options.show(text) + " is not a finite number as"
                    + " Float.toString writes it");
        }
        return value;
    }

    private static long whole(String shown, int number, String line, String text, long least) {
        long value;
        try {
            value = text.matches("[0-9]{1,18}") ? Long.parseLong(text) : -1L;
        } catch (NumberFormatException tooLong) {
            value = -1L;
        }
        if (value < least || value > Integer.MAX_VALUE) {
            throw bad(shown, number, line, Options.show(text) + " is not a whole number from "
                    + least + " to " + Integer.MAX_VALUE);
        }
        return value;
    }

    /** The refusal of a line: the file, its number, the line, and what was expected. */
    static UsageException bad(String shown, int number, String line, String expected) {
        return new UsageException(shown + " line " + number + ": '" + Options.show(line)
                + "' is refused: " + expected);
    }
}

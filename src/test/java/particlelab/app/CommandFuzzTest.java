package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A sweep of hostile command lines over every command: extreme and malformed numbers, steps
 * that overflow or cannot move, masses at the edge of the float range. Each must be refused
 * with exit 2 and exactly one stderr line, with no exception text and no stack frame. Of these
 * 40 lines the code before this test mishandled 12 (stack traces, runs of minutes, silent
 * wrong answers, two-line errors, exit 1).
 *
 * <p>{@link #everyOptionTakesEveryHostileNumberWithoutAnInternalError} then gives every option
 * of every command each of {@link #HOSTILE} (and, for a vector option, each as every
 * component): the audit's categories.
 */
class CommandFuzzTest {

    /**
     * The hostile numbers: NaN, the infinities, the smallest subnormal, the edges of the float
     * range, fractions, and digits of other scripts (full-width, Arabic-Indic) that
     * {@link Character#isDigit} and {@link Double#parseDouble} would take for 12.
     */
    static final List<String> HOSTILE = List.of("NaN", "Infinity", "-Infinity", "1e-45",
            "3.4e38", "-3.4e38", "1/3", "-1/3", "\uff11\uff12", "\u0661\u0662");

    /**
     * Options whose value is a file or folder (the files' own tests cover them: a number is a
     * valid file name there, and the run would write it).
     */
    private static final Set<String> PATH_OPTIONS = Set.of("--screenshot", "--export",
            "--out", "--jmh");

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {
        "aim --distance 100 --vx 1e-45",
        "aim --distance 100 --vx 20 --g 3e38",
        "aim --distance 100 --vx 20 --g 1e38 --method iterative",
        "aim --distance 100 --vx 20 --g 3e38 --tpf 1e-3 --method discrete",
        "aim --distance 100 --vx 20 --tpf 1e-9",
        "aim --distance 100 --vx 20 --tpf 1e-45",
        "aim --distance 100 --vx 20 --tpf 1e-7",
        "aim --distance 3e38 --vx 20",
        "aim --distance 1e-45 --vx 3e38",
        "aim --distance 100 --vx 3e38 --g 1e-45",
        "aim --distance 100 --vx 20 --mass 1e-39",
        "aim --distance 100 --vx 20 --mass 1e-39 --linear-drag 1",
        "aim --distance 100 --vx 20 --quadratic-drag 3e38 --method iterative",
        "aim --distance 100 --vx 20 --method iterative --tolerance 1e-45",
        "aim --distance 1/0 --vx 20",
        "aim --distance 0x10 --vx 20",
        "aim --distance 1e39 --vx 20",
        "aim --distance 1// --vx 20",
        "aim --distance . --vx 20",
        "aim --distance e5 --vx 20",
        "aim --distance 1e --vx 20",
        "aim --distance 100 --vx 20 --tpf 1/0",
        "trajectory --steps 10 --p0 3e38,0,0 --v0 3e38,0,0",
        "trajectory --steps 10 --v0 3e38,3e38,3e38 --quadratic-drag 1",
        "trajectory --steps 10 --mass 1e-39",
        "trajectory --steps 10 --mass 1e-39 --linear-drag 1",
        "trajectory --steps 10 --g 0,-3e38,0 --tpf 10",
        "trajectory --steps 1000 --linear-drag 10 --tpf 5",
        "trajectory --tpf 1e-7 --p0 1000,0,0 --steps 3",
        "trajectory --tpf 1e-45 --steps 3 --p0 1,1,1",
        "trajectory --duration 3e38",
        "trajectory --until-ground --g 0,0,0",
        "trajectory --steps 99999999999999999999",
        "trajectory --steps 10 --p0 1,2,3,4",
        "trajectory --steps 10 --v0 ,,",
        "demo --frames 0",
        "demo --fixed-tpf 0",
        "demo nosuch",
        "report --quick --tiny",
        "help nosuch",
    })
    void hostileCommandLineIsOneLineAndExitTwo(String commandLine) {
        CommandRun run = CommandRun.of(commandLine.split(" "));
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertFalse(run.err.contains("at particlelab"), run.toString());
    }

    /**
     * Every option with a value, of every command, given each hostile number in a command line
     * that is otherwise valid (or, for {@code demo}, refused only at its very last check, an
     * unknown {@code --set} name, so that no window opens): exit 0, or exit 2 with one line;
     * never exit 1, an internal error or an exception's text. {@code demo}'s {@code --set} is
     * given each number as {@code b=VALUE}. {@code report} has only flags and paths.
     *
     * @param base a valid command line, space-separated
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {
        "trajectory --steps 3",
        "trajectory --duration 0.05 --linear-drag 0.1 --quadratic-drag 0.01 --thrust 1",
        "aim --distance 100 --vx 50",
        "aim --distance 100 --vx 50 --method discrete",
        "aim --distance 100 --vx 50 --method discrete --predict-tpf 1/30",
        "aim --distance 100 --vx 50 --method iterative --predict-tpf 1/30",
        "aim --distance 100 --vx 50 --method iterative --strategy believable --seed 2",
        "hitscan --distance 100 --speed 100",
        "bounce --height 1 --restitution 0.5 --duration 2",
        "bounce --height 1 --restitution 0.5 --radius 0.1 --detection overlap --duration 2",
        "collide --m1 1 --m2 1 --p1 0,0,0 --p2 5,0,0 --v1 1,0,0 --v2 -1,0,0 --r1 1 --r2 1"
                + " --restitution 1",
        "collide --m1 1 --m2 2 --p1 0,0,0 --p2 5,0,0 --v1 1,0,0 --v2 -1,0,0 --r1 1 --r2 1"
                + " --restitution 0.5 --detection overlap",
        "tunnel --speed 10 --radius 0.1 --thickness 0.1 --detection overlap --shots 10",
        "tunnel --speed 10 --radius 0.1 --thickness 0.1 --detection swept --shots 10",
        "rotate --omega 0,0,6.2831855 --steps 3",
        "demo drag --frames 1 --set zz=1",
        "demo fountain --frames 1 --set zz=1",
    })
    void everyOptionTakesEveryHostileNumberWithoutAnInternalError(String base) {
        String[] words = base.split(" ");
        String command = words[0];
        Options options = optionsOf(command);
        String help = options.help();
        List<String> failures = new ArrayList<>();
        int runs = 0;
        for (String name : options.names()) {
            String placeholder = placeholder(help, name);
            if (placeholder == null || PATH_OPTIONS.contains(name)) {
                continue;
            }
            for (String number : HOSTILE) {
                List<String> values = new ArrayList<>();
                if ("--set".equals(name)) {
                    values.add("b=" + number);
                } else if (placeholder.split(",").length == 3) {
                    values.add(number + "," + number + "," + number);
                    values.add("0," + number + ",1");
                } else {
                    values.add(number);
                }
                for (String value : values) {
                    String[] args = withOption(words, name, value);
                    CommandRun run = CommandRun.of(args);
                    ++runs;
                    if (!promiseKept(run)) {
                        failures.add(String.join(" ", args) + "\n" + run);
                    }
                }
            }
        }
        assertTrue(runs > 0, base);
        assertTrue(failures.isEmpty(), failures.size() + " of " + runs + " runs broke the"
                + " promise; the first:\n" + String.join("\n", failures.subList(0,
                        Math.min(3, failures.size()))));
    }

    /** Exit 0 with no exception text, or exit 2 with exactly one line and none. */
    private static boolean promiseKept(CommandRun run) {
        boolean clean = !run.err.contains("Exception") && !run.err.contains("at particlelab")
                && !run.err.contains("internal error");
        if (run.code == 0) {
            return clean;
        }
        return run.code == Program.USAGE && run.errLines().size() == 1 && clean;
    }

    /** The declared options of a command, the source of its help. */
    private static Options optionsOf(String command) {
        switch (command) {
            case TrajectoryCommand.NAME:
                return TrajectoryCommand.options();
            case AimCommand.NAME:
                return AimCommand.options();
            case HitscanCommand.NAME:
                return HitscanCommand.options();
            case BounceCommand.NAME:
                return BounceCommand.options();
            case CollideCommand.NAME:
                return CollideCommand.options();
            case TunnelCommand.NAME:
                return TunnelCommand.options();
            case RotateCommand.NAME:
                return RotateCommand.options();
            case DemoCommand.NAME:
                return DemoCommand.declareOptions();
            default:
                throw new IllegalArgumentException(command);
        }
    }

    /**
     * Read an option's placeholder from the help, where it follows the name after one space
     * ({@code "  --p0 X,Y,Z   ..."}); a flag's name is followed by the padding or a line end.
     *
     * @return the placeholder, or null for a flag
     */
    private static String placeholder(String help, String name) {
        String entry = "\n  " + name + " ";
        int start = help.indexOf(entry);
        assertTrue(start >= 0 || help.contains("\n  " + name), name + " in\n" + help);
        if (start < 0 || help.charAt(start + entry.length()) == ' ') {
            return null;
        }
        int end = start + entry.length();
        while (end < help.length() && !Character.isWhitespace(help.charAt(end))) {
            ++end;
        }
        return help.substring(start + entry.length(), end);
    }

    /**
     * The base command line with one option set: its value replaced where the base gives it,
     * appended otherwise ({@code --set} is repeatable: the base's stays, after the new one).
     */
    private static String[] withOption(String[] base, String name, String value) {
        List<String> args = new ArrayList<>(Arrays.asList(base));
        int at = args.indexOf(name);
        if (at >= 0 && !"--set".equals(name)) {
            args.set(at + 1, value);
        } else {
            args.add(1 + (base.length > 1 && !base[1].startsWith("-") ? 1 : 0), value);
            args.add(1 + (base.length > 1 && !base[1].startsWith("-") ? 1 : 0), name);
        }
        return args.toArray(new String[0]);
    }
}

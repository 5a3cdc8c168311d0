package particlelab.app;

import java.io.BufferedOutputStream;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.PrintStream;
import java.util.Arrays;

/**
 * The {@code particle-lab} launcher: with no arguments it opens the window; otherwise the first
 * argument names a subcommand, one of {@link Commands} or {@code help}. Each subcommand returns
 * an exit code; {@link #main} exits with it only when it is not zero, so a window keeps running
 * after {@code main} returns. The list of commands in the help and in the "unknown command"
 * line is made from {@link Commands}.
 */
public final class Main {

    /** The help subcommand: alone, or followed by a command whose help to show. */
    public static final String HELP = "help";

    /** Where the summaries start in the help's command list (in columns). */
    private static final int SUMMARY_COLUMN = 14;
    /** The help's lines end by this column, so they fit an 80-column terminal. */
    private static final int HELP_WIDTH = 76;
    /** The summary of {@link #HELP}, which is the launcher's own and not in {@link Commands}. */
    private static final String HELP_SUMMARY =
            "show this help; help COMMAND shows that command's help";

    private Main() {
    }

    /**
     * Run the launcher and exit with the subcommand's code when it is not zero.
     *
     * @param args the command line (not null)
     */
    public static void main(String[] args) {
        // Buffer stdout: a trajectory may print a million rows.
        PrintStream out = new PrintStream(
                new BufferedOutputStream(new FileOutputStream(FileDescriptor.out)), false);
        int code = run(args, out, System.err);
        if (code != 0) {
            System.exit(code);
        }
    }

    /**
     * Run the launcher without exiting: what tests call.
     *
     * @param args the command line (not null)
     * @param out where results and help go (not null)
     * @param err where warnings and error lines go (not null)
     * @return the exit code ({@link Program}): OK on success, USAGE on a bad command line,
     *     FAILED when out could not be written (closed, full), a window could not run or on a
     *     bug
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        int code;
        try {
            code = runCommand(args, out, err);
        } catch (RuntimeException bug) {
            // Every bad input has its own message; this is a bug. One line, still.
            err.println(internalErrorLine(bug));
            return Program.FAILED;
        }
        // checkError flushes out and tells whether any write to it failed.
        if (out.checkError()) {
            err.println(Program.NAME + ": could not write the output (stdout is closed or full);"
                    + " the output is incomplete");
            return Program.FAILED;
        }
        return code;
    }

    private static int runCommand(String[] args, PrintStream out, PrintStream err) {
        if (args.length == 0) {
            // What gradle run does: the window on the first demo, until it is closed.
            return DemoCommand.run(args, out, err);
        }
        String command = args[0];
        String[] rest = Arrays.copyOfRange(args, 1, args.length);
        Command declared = Commands.find(command);
        if (declared != null) {
            return declared.runner().run(rest, out, err);
        }
        switch (command) {
            case HELP:
                if (rest.length == 1 && !rest[0].startsWith("-")) {
                    // "help COMMAND" is "COMMAND --help".
                    return run(new String[] {rest[0], Options.HELP}, out, err);
                }
                if (rest.length > 1 || rest.length == 1 && !Options.HELP.equals(rest[0])
                        && !Options.SHORT_HELP.equals(rest[0])) {
                    err.println(Program.NAME + " " + HELP + ": takes at most one command, e.g. "
                            + Program.NAME + " " + HELP + " " + AimCommand.NAME + ", but was given "
                            + Options.show(String.join(" ", rest)) + " (see " + Program.NAME
                            + " --help)");
                    return Program.USAGE;
                }
                out.print(help());
                return Program.OK;
            case Options.HELP:
            case Options.SHORT_HELP:
                out.print(help());
                return Program.OK;
            default:
                err.println(Program.NAME + ": unknown command " + Options.show(command)
                        + "; the commands are "
                        + commandNames() + " (see " + Program.NAME + " --help)");
                return Program.USAGE;
        }
    }

    /**
     * Word the one line that reports a bug: the exception's class and its whole message (the
     * message names the value and the limit; a cut one named neither), control characters
     * escaped.
     *
     * @param bug the exception that escaped a command (not null)
     * @return the line, without a line end (not null)
     */
    static String internalErrorLine(RuntimeException bug) {
        return Program.NAME + ": internal error, please report it with the command line: "
                + bug.getClass().getSimpleName() + ": "
                + Options.showWhole(String.valueOf(bug.getMessage()));
    }

    /**
     * Describe the launcher and its subcommands.
     *
     * @return the help text, lines ending in '\n' (not null)
     */
    public static String help() {
        return "Usage: " + Program.NAME + " [COMMAND [OPTIONS]]\n"
                + "Particle Lab: the lecture's game particle physics, every particle moved by\n"
                + "the same semi-implicit Euler step.\n"
                + "\n"
                + "With no command, opens the window with the lecture's demos.\n"
                + "\n"
                + "Commands:\n"
                + commandList()
                + "\n"
                + "Every option of a command, with defaults and units: " + Program.NAME
                + " COMMAND --help.\n"
                + "The demo and report commands are described by " + Program.NAME + " demo --help\n"
                + "and " + Program.NAME + " report --help.\n"
                + "\n"
                + "Exit status: 0 on success; 2 on a bad command line, with one line on stderr;\n"
                + "1 when the output cannot be written (stdout closed or full) or the window\n"
                + "cannot run.\n";
    }

    /** "trajectory, aim, ..., help": every command's name, in help order. */
    private static String commandNames() {
        StringBuilder names = new StringBuilder();
        for (Command command : Commands.all()) {
            names.append(command.name()).append(", ");
        }
        return names.append(HELP).toString();
    }

    /** The help's command list: each name, then its summary wrapped at {@link #HELP_WIDTH}. */
    private static String commandList() {
        StringBuilder list = new StringBuilder();
        for (Command command : Commands.all()) {
            appendSummary(command.name(), command.summary(), list);
        }
        appendSummary(HELP, HELP_SUMMARY, list);
        return list.toString();
    }

    private static void appendSummary(String name, String summary, StringBuilder list) {
        StringBuilder line = new StringBuilder("  ").append(name);
        for (String word : summary.split(" ")) {
            boolean first = line.length() <= SUMMARY_COLUMN;
            if (!first && line.length() + 1 + word.length() > HELP_WIDTH) {
                list.append(line).append('\n');
                line.setLength(0);
                first = true;
            }
            if (first) {
                while (line.length() < SUMMARY_COLUMN) {
                    line.append(' ');
                }
            } else {
                line.append(' ');
            }
            line.append(word);
        }
        list.append(line).append('\n');
    }
}

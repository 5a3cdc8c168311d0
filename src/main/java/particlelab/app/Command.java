package particlelab.app;

import java.io.PrintStream;
import java.util.function.Supplier;

/**
 * One subcommand of the {@code particle-lab} launcher, declared once: its name, the one-line
 * summary {@code particle-lab --help} lists, its options (whose help is the command's
 * {@code --help}) and how to run it. {@link Commands} holds every command in the order the help
 * lists them; {@link Main} dispatches by that list and builds its help from it, and the tests
 * walk the same list, so a new command is one class and one line in {@link Commands}.
 *
 * @param name the word after {@code particle-lab} (not null, lower case, no spaces)
 * @param summary what the command does, one sentence without a full stop (not null)
 * @param options makes the command's declared options, for the help and the tests (not null)
 * @param runner runs the command on the arguments after its name (not null)
 */
public record Command(String name, String summary, Supplier<Options> options, Runner runner) {

    /** How a command runs: the same shape as every command's static {@code run}. */
    @FunctionalInterface
    public interface Runner {

        /**
         * Run the command.
         *
         * @param args the arguments after the command's name (not null)
         * @param out where results and help go (not null)
         * @param err where warnings and error lines go (not null)
         * @return the exit code: 0 on success, 2 on a bad command line
         */
        int run(String[] args, PrintStream out, PrintStream err);
    }
}

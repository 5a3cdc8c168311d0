package particlelab.app;

import java.util.Arrays;

/**
 * The {@code particle-lab} command: no arguments open the window on the first demo (what
 * {@code gradle run} does); {@code demo ...} opens it with options (see {@link DemoCommand}).
 */
public final class Main {

    private Main() {
    }

    /**
     * Run the command.
     *
     * @param args the command line
     */
    public static void main(String[] args) {
        if (args.length == 0) {
            System.exit(DemoCommand.run(args, System.out, System.err));
        }
        if ("demo".equals(args[0])) {
            System.exit(DemoCommand.run(Arrays.copyOfRange(args, 1, args.length), System.out,
                    System.err));
        }
        System.err.println("particle-lab: unknown command '" + args[0] + "'; try 'demo'");
        System.exit(2);
    }
}

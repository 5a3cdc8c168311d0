package particlelab.app;

import java.util.List;

/**
 * Every subcommand of {@code particle-lab}, in the order {@code particle-lab --help} lists them:
 * an explicit list, like {@link DemoCatalog}. To add a command, write its class (a static
 * {@code NAME}, {@code options()} and {@code run(args, out, err)}, as {@link TrajectoryCommand}
 * has) and add one line here; {@link Main}'s dispatch, its help and the tests follow.
 */
public final class Commands {

    /** The commands, in help order; {@code help} itself is {@link Main}'s and not listed. */
    private static final List<Command> ALL = List.of(
            new Command(TrajectoryCommand.NAME,
                    "print one particle's stepped trajectory as CSV",
                    TrajectoryCommand::options, TrajectoryCommand::run),
            new Command(AimCommand.NAME,
                    "find vy that lands a level shot at distance S (lecture, discrete or"
                            + " iterative) and fire it",
                    AimCommand::options, AimCommand::run),
            new Command(HitscanCommand.NAME,
                    "the straight-line cheat against a stepped projectile: the drop, and"
                            + " whether it still hits, as CSV",
                    HitscanCommand::options, HitscanCommand::run),
            new Command(BounceCommand.NAME,
                    "drop a ball on the ground; one CSV row per impact",
                    BounceCommand::options, BounceCommand::run),
            new Command(CollideCommand.NAME,
                    "two spheres until their first impact: velocities, momentum, kinetic"
                            + " energy before and after, as CSV",
                    CollideCommand::options, CollideCommand::run),
            new Command(TunnelCommand.NAME,
                    "fire shots at a thin wall: how many the overlap or swept test misses,"
                            + " as CSV",
                    TunnelCommand::options, TunnelCommand::run),
            new Command(RotateCommand.NAME,
                    "spin one torque-free rigid body: det R, drift from a rotation, angle"
                            + " error, omega, energy and |L| per step, as CSV",
                    RotateCommand::options, RotateCommand::run),
            new Command(DemoCommand.NAME,
                    "open the window on one demo (--list, --frames, --screenshot)",
                    DemoCommand::declareOptions, DemoCommand::run),
            new Command(TourCommand.NAME, "walk lecture 15 slide by slide, each stop a demo in"
                    + " the slide's state (--list, --stop N)", TourCommand::options,
                    TourCommand::run),
            new Command(ReportCommand.NAME,
                    "write the accuracy and speed report",
                    ReportCommand::options, ReportCommand::run));

    private Commands() {
    }

    /**
     * Access every command, in help order.
     *
     * @return the commands (not null, unmodifiable)
     */
    public static List<Command> all() {
        return ALL;
    }

    /**
     * Find a command by name.
     *
     * @param name the word after {@code particle-lab} (not null)
     * @return the command, or null if none has that name
     */
    public static Command find(String name) {
        for (Command command : ALL) {
            if (command.name().equals(name)) {
                return command;
            }
        }
        return null;
    }
}

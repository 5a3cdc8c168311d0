package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import java.util.Random;
import particlelab.collision.ThinWall;
import particlelab.physics.NonFiniteStepException;
import particlelab.world.Detection;
import particlelab.world.TunnelShots;

/**
 * {@code particle-lab tunnel}: N shots straight at a thin wall, each from a random phase, and
 * one CSV row counting the hits and misses of the chosen detection:
 * {@code shots,hits,misses,predicted_miss_probability}.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>The wall is the slab {@code |x| ≤ D/2}; each shot starts at
 * {@code x = −(r + D/2) − (1 + φ)·v·h}, clear of the wall by at least one step's travel plus
 * the random phase φ ∈ [0, 1) (a seeded {@code java.util.Random}, one number per shot), and
 * flies at {@code +v} along x without forces until it hits or is a step past the far side.</li>
 * <li>{@code predicted_miss_probability} is {@code max(0, 1 − (2r + D)/(v·h))} for the overlap
 * test and 0 for the swept test, which is exact for the straight segment of each step.</li>
 * </ul>
 */
public final class TunnelCommand {

    /** The subcommand's name. */
    public static final String NAME = "tunnel";
    /** The CSV header, exactly. */
    public static final String HEADER = "shots,hits,misses,predicted_miss_probability";
    /** The default seed. */
    public static final int DEFAULT_SEED = 1;
    /** The most shots one run fires. */
    public static final int MAX_SHOTS = 1_000_000;

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String SPEED = "--speed";
    private static final String RADIUS = "--radius";
    private static final String THICKNESS = "--thickness";
    private static final String TPF = "--tpf";
    private static final String SHOTS = "--shots";
    private static final String SEED = "--seed";

    private TunnelCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Fire N shots straight at a thin wall (perpendicular, no"
                + " gravity, constant speed), each from a random phase, and count how many the"
                + " chosen detection sees: " + HEADER + ".")
                .value(SPEED, "V", "shot speed v (m/s, > 0). Required.")
                .value(RADIUS, "R", "shot radius r (m, > 0). Required.")
                .value(THICKNESS, "D", "wall thickness D (m, > 0). Required.")
                .value(TPF, "H", "time step h (s, > 0), a decimal or a fraction such as 1/60."
                        + " Default 1/60.")
                .value(CollisionOptions.DETECTION, "overlap|swept",
                        CollisionOptions.DETECTION_HELP + " Required.")
                .value(SHOTS, "N", "number of shots (1 to " + MAX_SHOTS + "). Required.")
                .value(SEED, "S", "seed of the random phases (a whole number). Default "
                        + DEFAULT_SEED + ".")
                .note("Each shot starts (1 + phi)*v*h before the wall's near side, phi uniformly"
                        + " random in [0, 1): the start offset along the flight is a random"
                        + " fraction of one step's travel v*h.")
                .note("The overlap test sees the shot only if a step ends with its centre"
                        + " within r + D/2 of the wall's centre plane: with v*h > 2r + D it can"
                        + " jump over, with probability max(0, 1 - (2r+D)/(v*h)) for a random"
                        + " phase (the predicted_miss_probability column; 0 for the swept test,"
                        + " which never misses). A hit is a shot the test saw; the overlap test"
                        + " pushes a shot out of the nearer face, so one seen more than half-way"
                        + " through still leaves by the far side.")
                .note("Exit status: 0 on success; 2 on a bad command line, with one line on"
                        + " stderr.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "tunnel" (not null)
     * @param out where the CSV or help goes (not null)
     * @param err where the error line goes (not null)
     * @return the exit code: 0 on success, 2 on a bad command line
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                parsed -> runParsed(parsed, out, err));
    }

    /** The command proper, once the options are parsed and no help was asked for. */
    private static int runParsed(Options options, PrintStream out, PrintStream err) {
        float speed = options.positiveFloat(SPEED);
        float radius = options.positiveFloat(RADIUS);
        float thickness = options.positiveFloat(THICKNESS);
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        Detection detection = CollisionOptions.detection(options, true, COMMAND);
        if (!options.has(SHOTS)) {
            throw new UsageException(SHOTS + ": is required, a whole number from 1 to "
                    + MAX_SHOTS + " (see " + COMMAND + " " + Options.HELP + ")");
        }
        int shots = options.intInRange(SHOTS, 1, 1, MAX_SHOTS);
        int seed = options.intInRange(SEED, DEFAULT_SEED, Integer.MIN_VALUE,
                Integer.MAX_VALUE);
        double flight = 2.0 * radius + thickness + 3.0 * speed * (double) step;
        if (flight / ((double) speed * step) > CollisionOptions.MAX_STEPS) {
            throw new UsageException(SPEED + ": a shot at " + speed + " m/s would take more"
                    + " than " + CollisionOptions.MAX_STEPS + " steps to cross the wall");
        }
        // The farthest start, r + D/2 + 2*v*h before the wall's centre, must be a float.
        double farthest = radius + 0.5 * thickness + 2.0 * speed * (double) step;
        if (farthest > Float.MAX_VALUE) {
            throw new UsageException(TPF + ": a shot at " + speed + " m/s with a step of "
                    + step + " s starts up to r + D/2 + 2*v*h = " + farthest + " m before the"
                    + " wall, beyond the float range (" + Float.MAX_VALUE + "); choose a"
                    + " smaller " + TPF + ", " + SPEED + ", " + RADIUS + " or " + THICKNESS);
        }
        ThinWall wall = new ThinWall(Vector3f.UNIT_X, 0f, thickness);
        int hits;
        try {
            hits = TunnelShots.fire(wall, speed, radius, step, detection, shots,
                    new Random(seed));
        } catch (NonFiniteStepException nonFinite) {
            // The elastic bounce off the wall, v - (1+e)*v = -v, overflows in its impulse.
            throw new UsageException(SPEED + ": a shot at " + speed + " m/s left its bounce"
                    + " off the wall non-finite (NaN or infinite): the impulse (1+e)*m*v"
                    + " overflowed the float range; choose a smaller " + SPEED);
        }
        double predicted = detection == Detection.OVERLAP
                ? wall.overlapMissProbability(radius, speed, step) : 0.0;
        out.println(HEADER);
        out.println(shots + "," + hits + "," + (shots - hits) + "," + predicted);
        return Program.OK;
    }
}

package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import particlelab.aiming.Hitscan;
import particlelab.aiming.TargetImpact;
import particlelab.physics.Gravity;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.ParticleIntegrator;

/**
 * {@code particle-lab hitscan}: the lecture's cheat for fast bullets against a real projectile,
 * one CSV row {@code speed,distance,flight_time,drop_formula,drop_stepped,projectile_hits}.
 * The straight-line ray always hits the target's centre; the projectile is fired level at the
 * centre (no compensation for the drop) and stepped with the shared integrator under gravity.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>The target is a thin disc of radius r facing the gun at distance d, its centre level
 * with the muzzle; {@code projectile_hits} is true when the projectile crosses the disc's
 * plane within r of the centre (each step's segment is tested, so the crossing is found
 * inside the step however fast the bullet is).</li>
 * <li>The default radius is {@link #DEFAULT_RADIUS_METRES} m; {@code --g} is the magnitude
 * of gravity, pointing down, as in {@code aim}.</li>
 * <li>{@code flight_time} is the stepped projectile's, at the crossing (d/v to round-off).</li>
 * </ul>
 */
public final class HitscanCommand {

    /** The subcommand's name. */
    public static final String NAME = "hitscan";
    /** The CSV header, exactly. */
    public static final String HEADER =
            "speed,distance,flight_time,drop_formula,drop_stepped,projectile_hits";
    /** The target's radius when {@code --target-radius} is not given (in metres). */
    public static final float DEFAULT_RADIUS_METRES = 0.5f;

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String DISTANCE = "--distance";
    private static final String SPEED = "--speed";
    private static final String G = "--g";
    private static final String RADIUS = "--target-radius";
    private static final String TPF = "--tpf";

    private HitscanCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "The straight-line cheat for fast bullets against a real"
                + " projectile: fire level at the centre of a target at distance d, once as a"
                + " ray (no travel time, no drop: always a hit) and once as a projectile stepped"
                + " with the shared Euler integrator under gravity, and print one CSV row: "
                + HEADER + ".")
                .value(DISTANCE, "D", "distance to the target's centre d (m, > 0). Required.")
                .value(SPEED, "V", "muzzle speed v (m/s, > 0). Required.")
                .value(G, "G", "magnitude of gravity g, pointing down (m/s^2, at least "
                        + Float.MIN_NORMAL + ", the smallest normal float). Default 9.8.")
                .value(RADIUS, "R", "radius r of the target, a thin disc facing the gun (m,"
                        + " > 0). Default " + DEFAULT_RADIUS_METRES + ".")
                .value(TPF, "H", "time step h of the projectile (s, > 0), a decimal or a"
                        + " fraction such as 1/60. Default 1/60. A step that needs more than "
                        + AimCommand.MAX_STEPS_PER_SHOT + " steps to cover d (d/(v*h)) is"
                        + " refused.")
                .note("drop_formula is 0.5*g*(d/v)^2, the drop the straight line ignores;"
                        + " drop_stepped is how far below the centre the stepped projectile"
                        + " crosses the target's plane x = d, each step's segment tested so the"
                        + " crossing is found inside the step. The Euler step falls more: by"
                        + " 0.5*g*h*(d/v) plus at most g*h^2/8. projectile_hits is true when"
                        + " drop_stepped <= r: then the cheat was right. The cheat is good"
                        + " enough for d < v*sqrt(2r/g). flight_time is the projectile's, at the"
                        + " crossing.")
                .note("Exit status: 0 on success; 2 on a bad command line, with one line on"
                        + " stderr.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "hitscan" (not null)
     * @param out where the row or help goes (not null)
     * @param err where the error line goes (not null)
     * @return the exit code: 0 on success, 2 on a bad command line
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                parsed -> runParsed(parsed, out, err));
    }

    /** The command proper, once the options are parsed and no help was asked for. */
    private static int runParsed(Options options, PrintStream out, PrintStream err) {
        float distance = options.positiveFloat(DISTANCE);
        float speed = options.positiveFloat(SPEED);
        float gravity = options.floatAtLeast(G, Gravity.STANDARD_G, Float.MIN_NORMAL,
                "the smallest normal float, as for masses: a subnormal g is lost to underflow"
                        + " in the step's g*h");
        float radius = options.positiveFloat(RADIUS, DEFAULT_RADIUS_METRES);
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        double steps = distance / ((double) speed * step);
        if (steps > AimCommand.MAX_STEPS_PER_SHOT) {
            throw new UsageException(TPF + ": a step of " + step + " s needs d/(v*h) = "
                    + steps + " steps to reach d=" + distance + " m at v=" + speed
                    + " m/s, more than the limit " + AimCommand.MAX_STEPS_PER_SHOT
                    + "; use a larger " + TPF + " or " + SPEED + ", or a smaller "
                    + DISTANCE);
        }
        // The decimals the user typed, not their floats: g = 9.8, not 9.800000190734863.
        double formula = Hitscan.formulaDrop(typed(gravity), typed(distance), typed(speed));
        ParticleIntegrator integrator = CommandSupport.integrator(
                new Vector3f(0f, -gravity, 0f), 0f, 0f, 0f);
        Hitscan range = new Hitscan(integrator, step, AimCommand.MAX_STEPS_PER_SHOT + 1);
        TargetImpact impact = new TargetImpact();
        boolean reached;
        try {
            reached = range.fireAtDisc(speed, distance, radius, impact);
        } catch (NonFiniteStepException nonFinite) {
            throw CommandSupport.blewUp(step, "during the projectile's flight",
                    Float.POSITIVE_INFINITY);
        }
        if (!reached || !Double.isFinite(impact.getDrop())) {
            throw new UsageException(DISTANCE + ": the projectile did not reach the target"
                    + " at d=" + distance + " m at v=" + speed + " m/s within "
                    + AimCommand.MAX_STEPS_PER_SHOT + " steps of " + step + " s (float x"
                    + " stopped growing); choose a larger " + TPF);
        }
        out.println(HEADER);
        out.println(speed + "," + distance + "," + impact.getTimeSeconds() + "," + formula
                + "," + impact.getDrop() + "," + impact.isHit());
        return Program.OK;
    }

    /** The shortest decimal that reads back as the float, as a double. */
    private static double typed(float value) {
        return Double.parseDouble(Float.toString(value));
    }
}

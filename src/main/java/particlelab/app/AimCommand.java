package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.Locale;
import particlelab.aiming.AimResult;
import particlelab.aiming.AimStrategy;
import particlelab.aiming.IterativeAim;
import particlelab.aiming.Landing;
import particlelab.aiming.LevelAim;
import particlelab.aiming.PredictorMismatch;
import particlelab.aiming.ShotLog;
import particlelab.aiming.ShotSimulator;
import particlelab.physics.Gravity;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * {@code particle-lab aim}: HelloAiming on the command line. Gun and target are level, S
 * apart; vx is given; the command finds vy by the lecture's formula, the discrete correction
 * or iterative shoot-and-adjust, then fires that shot with the shared integrator at the given
 * step and forces and reports where it lands.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>Every method's shot is stepped with the given drag, so {@code lecture} and
 * {@code discrete} (closed forms for gravity alone) show how far drag makes them miss.</li>
 * <li>The flight time reported is the stepped shot's, at its interpolated ground crossing,
 * the same shot as the landing; the readable output also shows the formula's {@code S/vx}.</li>
 * <li>vy is reported as fired: the float the bullet was launched with.</li>
 * <li>With linear drag a target at {@code S ≥ vx·m/b} is out of reach for every method; the
 * iterative method also finds out by itself, for the slightly shorter reach of the stepped
 * bullet and for quadratic drag.</li>
 * <li>Without {@code --strategy} the iterative method keeps the search it has always used,
 * bracketed regula falsi, named {@code illinois} (also accepted by {@code --strategy}).</li>
 * <li>The believable player's seed defaults to {@link #DEFAULT_SEED}; its invisible search for
 * the right vy is not printed or counted, only the shots it fires.</li>
 * <li>{@code --predict-tpf} works for {@code iterative} and {@code discrete} (the two that use
 * a step); the reported shot, and the last {@code --shots-csv} row, is the predicted vy flown
 * at {@code --tpf}, counted as one more shot.</li>
 * </ul>
 */
public final class AimCommand {

    /** The subcommand's name. */
    public static final String NAME = "aim";
    /** The CSV header, exactly. */
    public static final String HEADER = "method,vx,vy,flight_time,landing_x,miss,shots";
    /** The header of {@code --shots-csv}, exactly. */
    public static final String SHOTS_HEADER = "shot,vy,landing_x,miss";
    /** The believable player's seed when {@code --seed} is not given. */
    public static final int DEFAULT_SEED = 1;
    /** The default tolerance of the iterative method (in metres). */
    public static final float DEFAULT_TOLERANCE_METRES = 0.001f;
    /** The most shots the iterative method fires. */
    public static final int MAX_SHOTS = 100;
    /** A shot still in the air after this long never lands (in seconds). */
    public static final float MAX_FLIGHT_SECONDS = 3600f;
    /**
     * The most steps one shot may take. A step so small that the shot needs more (S/(vx·h)
     * steps to cover S) is refused: it would take minutes, and each step would move x by
     * fewer than 8 units of float round-off at S ({@code S/1e6 ≥ 8·ulp(S)} since
     * {@code S/ulp(S) ≥ 2^23}), until x stops moving altogether.
     */
    public static final int MAX_STEPS_PER_SHOT = 1_000_000;

    private static final String COMMAND = Program.NAME + " " + NAME;
    /** The decimals of the readable output. */
    private static final int READABLE_DECIMALS = 4;
    /** Smaller magnitudes are shown with significant digits instead of decimals. */
    private static final double SMALL_READABLE = 1e-3;
    /** Larger magnitudes are shown in scientific notation. */
    private static final double LARGE_READABLE = 1e7;
    private static final String LECTURE = "lecture";
    private static final String DISCRETE = "discrete";
    private static final String DISTANCE = "--distance";
    private static final String VX = "--vx";
    private static final String G = "--g";
    private static final String TPF = "--tpf";
    private static final String MASS = "--mass";
    private static final String LINEAR_DRAG = "--linear-drag";
    private static final String QUADRATIC_DRAG = "--quadratic-drag";
    private static final String METHOD = "--method";
    private static final String TOLERANCE = "--tolerance";
    private static final String CSV = "--csv";
    private static final String STRATEGY = "--strategy";
    private static final String SEED = "--seed";
    private static final String SHOTS_CSV = "--shots-csv";
    private static final String PREDICT_TPF = "--predict-tpf";

    private AimCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Find the vertical launch speed vy that lands a shot on a"
                + " level target at distance S, vx given, then step that shot with the shared"
                + " Euler integrator and report where it lands.")
                .value(DISTANCE, "S", "distance to the target S (m, > 0). Required.")
                .value(VX, "VX", "horizontal launch speed vx (m/s, > 0). Required.")
                .value(G, "G", "magnitude of gravity g, pointing down (m/s^2, > 0). Default"
                        + " 9.8.")
                .value(TPF, "H", "time step h of the stepped shot (s, > 0), a decimal or a"
                        + " fraction such as 1/60. Default 1/60. A step that needs more than "
                        + MAX_STEPS_PER_SHOT + " steps to cover S (S/(vx*h)) is refused, and"
                        + " so is one longer than the " + MAX_FLIGHT_SECONDS + " s a shot may"
                        + " fly.")
                .value(MASS, "KG", "bullet mass m (kg, > 0). At least " + Particle.MIN_MASS_KG
                        + ", so that 1/m is a finite float. Default 1.")
                .value(LINEAR_DRAG, "B", "linear drag b in F = -b*V (N*s/m = kg/s, >= 0)."
                        + " Default 0: none.")
                .value(QUADRATIC_DRAG, "C", "quadratic drag c in F = -c*|V|*V (kg/m, >= 0)."
                        + " Default 0: none.")
                .value(METHOD, "NAME", "lecture: vy = g*S/(2*vx), exact for the continuous"
                        + " parabola, lands vx*h short when stepped; discrete: the correction"
                        + " that makes the stepped shot land at S (g*(S/vx + h)/2 when S/(vx*h)"
                        + " is whole); iterative: shoot, see where it lands, adjust vy (handles"
                        + " drag). Default lecture.")
                .value(TOLERANCE, "METRES", "iterative only: stop once the landing is this"
                        + " close to S (m, > 0). Default " + DEFAULT_TOLERANCE_METRES + ". Float"
                        + " round-off (vy is fired as a float) limits it to about 1e-5 m at"
                        + " 100 m. With --strategy believable it must be less than S, so that"
                        + " a first shot can miss.")
                .value(STRATEGY, "NAME", "iterative only: how vy is adjusted after each shot."
                        + " lecture: the lecture's rule, undershot -> more power, overshot -> less,"
                        + " vy changed by half the first guess and the change halved at each sign"
                        + " change of the miss; bisection: double vy until a shot overshoots,"
                        + " then halve the bracket; secant: the same bracket, then the secant"
                        + " through the last two shots; believable: a computer player that finds"
                        + " the right vy invisibly, misses with its first shot (off by "
                        + percent(IterativeAim.BELIEVABLE_FIRST_MIN_ERROR) + "-"
                        + percent(IterativeAim.BELIEVABLE_FIRST_MAX_ERROR) + "%) and then moves a"
                        + " seeded random " + percent(IterativeAim.BELIEVABLE_MIN_MOVE) + "-"
                        + percent(IterativeAim.BELIEVABLE_MAX_MOVE) + "% of the way toward it;"
                        + " illinois: bracket, then regula falsi. Default illinois.")
                .value(SEED, "N", "with --strategy believable: the random seed (an integer"
                        + " 0-" + Integer.MAX_VALUE + "); the same seed gives the same shots."
                        + " Default " + DEFAULT_SEED + ".")
                .value(PREDICT_TPF, "H", "iterative and discrete: the aimer predicts its shots"
                        + " with this step (s, > 0) while the shot flies at --tpf; it then"
                        + " misses by about vx*(H - h) (long when H > h). Default: --tpf.")
                .flag(CSV, "print one CSV row under the header " + HEADER + " instead of text.")
                .flag(SHOTS_CSV, "iterative only: print one CSV row per simulated shot under"
                        + " the header " + SHOTS_HEADER + " instead of the summary (vy as"
                        + " fired; miss = landing_x - S; with " + PREDICT_TPF + " the last row is"
                        + " the shot flown at --tpf).")
                .note("Every method's shot is fired from the origin and stepped at h with the"
                        + " given forces until it crosses y = 0; landing_x and flight_time are"
                        + " read at the crossing, interpolated inside the last step; miss is"
                        + " landing_x - S (negative: short); shots counts the simulated shots"
                        + " (1 for lecture and discrete, which are closed forms for gravity"
                        + " alone: with drag their shot still flies with drag and shows the"
                        + " miss). vy is printed as fired, a float.")
                .note("Out of reach: with linear drag no launch passes vx*m/b, so S >= vx*m/b"
                        + " is refused for every method; the iterative method also reports a"
                        + " target it cannot reach (the stepped bullet's reach, quadratic drag's"
                        + " peak reach) or cannot hit within " + MAX_SHOTS + " shots.")
                .note(CommandSupport.STABILITY_NOTE)
                .note("Exit status: 0 on success; 2 on a bad command line or a target out of"
                        + " reach, with one line on stderr.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "aim" (not null)
     * @param out where the result or help goes (not null)
     * @param err where warnings and the error line go (not null)
     * @return the exit code: 0 on success, 2 on a bad command line or a target out of reach
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                parsed -> runParsed(parsed, out, err));
    }

    /** The command proper, once the options are parsed and no help was asked for. */
    private static int runParsed(Options options, PrintStream out, PrintStream err) {
        float distance = options.positiveFloat(DISTANCE);
        float vx = options.positiveFloat(VX);
        float gravity = options.positiveFloat(G, Gravity.STANDARD_G);
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        float mass = options.floatAtLeast(MASS, CommandSupport.DEFAULT_MASS_KG,
                Particle.MIN_MASS_KG, "the smallest mass whose 1/m is a finite float");
        float linearDrag = options.nonNegativeFloat(LINEAR_DRAG, 0f);
        float quadraticDrag = options.nonNegativeFloat(QUADRATIC_DRAG, 0f);
        String method = options.choice(METHOD, LECTURE, LECTURE, DISCRETE,
                IterativeAim.METHOD);
        float tolerance = options.positiveFloat(TOLERANCE, DEFAULT_TOLERANCE_METRES);
        for (String iterativeOnly : new String[] {TOLERANCE, STRATEGY, SEED, SHOTS_CSV}) {
            if (options.has(iterativeOnly) && !IterativeAim.METHOD.equals(method)) {
                throw new UsageException(iterativeOnly + ": applies only to " + METHOD + " "
                        + IterativeAim.METHOD + ", but the method is " + method);
            }
        }
        AimStrategy strategy = AimStrategy.fromCliName(options.choice(STRATEGY,
                AimStrategy.ILLINOIS.cliName(), strategyNames()));
        int seed = options.intInRange(SEED, DEFAULT_SEED, 0, Integer.MAX_VALUE);
        if (options.has(SEED) && strategy != AimStrategy.BELIEVABLE) {
            throw new UsageException(SEED + ": applies only to " + STRATEGY + " "
                    + AimStrategy.BELIEVABLE.cliName() + ", but the strategy is "
                    + strategy.cliName());
        }
        if (strategy == AimStrategy.BELIEVABLE && tolerance >= distance) {
            throw new UsageException(TOLERANCE + ": with " + STRATEGY + " "
                    + AimStrategy.BELIEVABLE.cliName() + " it must be less than S="
                    + distance + " m, so that a first shot can miss, but was " + tolerance);
        }
        options.atMostOneOf(CSV, SHOTS_CSV);
        float predictStep = options.positiveFloat(PREDICT_TPF, step);
        if (options.has(PREDICT_TPF) && LECTURE.equals(method)) {
            throw new UsageException(PREDICT_TPF + ": applies only to " + METHOD + " "
                    + IterativeAim.METHOD + " or " + DISCRETE + " (the lecture's formula"
                    + " uses no step), but the method is " + method);
        }
        if (linearDrag > 0f && distance >= (double) vx * mass / linearDrag) {
            throw new UsageException(DISTANCE + ": the target at S=" + distance + " m is out"
                    + " of reach at vx=" + vx + " m/s with linear drag b=" + linearDrag
                    + " and mass m=" + mass + ": no launch passes vx*m/b = "
                    + (float) ((double) vx * mass / linearDrag) + " m");
        }

        checkFloatRange(gravity, distance, vx);
        checkStepLength(TPF, step);
        checkStepLength(PREDICT_TPF, predictStep);
        checkStepCount(TPF, distance, vx, step);
        checkStepCount(PREDICT_TPF, distance, vx, predictStep);
        if (DISCRETE.equals(method)) {
            String stepOption = options.has(PREDICT_TPF) ? PREDICT_TPF : TPF;
            checkDiscreteRange(stepOption, gravity, distance, vx, predictStep);
        }

        ParticleIntegrator integrator = CommandSupport.integrator(
                new Vector3f(0f, -gravity, 0f), linearDrag, quadraticDrag, 0f);
        ShotSimulator simulator = new ShotSimulator(integrator, mass, step,
                maxFlightSeconds(step));
        boolean mismatch = options.has(PREDICT_TPF);
        ShotSimulator predictor = mismatch ? new ShotSimulator(integrator, mass,
                predictStep, maxFlightSeconds(predictStep)) : simulator;
        ShotLog log = new ShotLog(MAX_SHOTS + 1);
        AimResult result;
        float blewUpStep = step;
        // The decimal the user typed, not its float: 0.001, not 0.0010000000474974513.
        double toleranceMetres = Double.parseDouble(Float.toString(tolerance));
        try {
            blewUpStep = predictStep;
            result = aim(method, strategy, seed, predictor, gravity, distance, vx,
                    predictStep, toleranceMetres, log);
            if (mismatch) {
                blewUpStep = step;
                result = PredictorMismatch.fly(result, simulator, toleranceMetres, log);
                if (Double.isNaN(result.getLandingX())) {
                    throw new UsageException(DISTANCE + ": " + result.getExplanation()
                            + " (limit " + maxFlightSeconds(step) + " s); the target at S="
                            + distance + " m is out of reach");
                }
            }
        } catch (NonFiniteStepException nonFinite) {
            float limit = integrator.maxStableStep(launch(vx,
                    (float) LevelAim.lectureVy(gravity, distance, vx), mass));
            UsageException blewUp = CommandSupport.blewUp(blewUpStep, "during a shot",
                    limit);
            if (blewUpStep == step) {
                throw blewUp;
            }
            // The predictor's step blew up: name its option, not --tpf.
            throw new UsageException(blewUp.getMessage().replaceFirst(TPF, PREDICT_TPF));
        }
        CommandSupport.warnIfUnstable(integrator,
                launch(vx, (float) result.getVerticalSpeed(), mass), step, err);
        if (options.has(CSV)) {
            printCsv(result, out);
        } else if (options.has(SHOTS_CSV)) {
            printShots(log, out);
        } else {
            printText(result, linearDrag > 0f || quadraticDrag > 0f, tolerance,
                    options.has(STRATEGY) ? strategy : null, out);
            if (mismatch) {
                out.println("predictor:         aimed with h_predict = "
                        + readable(predictStep) + " s, flown at h = " + readable(step)
                        + " s; expected miss about vx*(h_predict - h) = "
                        + readable(PredictorMismatch.expectedMiss(vx, predictStep, step))
                        + " m");
            }
        }
        return Program.OK;
    }

    /**
     * Aim by the method chosen and fire the shot.
     *
     * @return a result whose shot landed (not null)
     * @throws UsageException if the target is out of reach or the shot never lands
     */
    private static AimResult aim(String method, AimStrategy strategy, int seed,
            ShotSimulator simulator, float gravity, float distance, float vx, float step,
            double tolerance, ShotLog log) {
        if (IterativeAim.METHOD.equals(method)) {
            AimResult result = new IterativeAim(simulator, gravity, tolerance, MAX_SHOTS,
                    strategy, seed).aim(distance, vx, log);
            if (!result.isHit()) {
                String option = result.getExplanation().contains("out of reach")
                        ? DISTANCE : TOLERANCE;
                throw new UsageException(option + ": " + result.getExplanation());
            }
            return result;
        }
        double vy = LECTURE.equals(method)
                ? LevelAim.lectureVy(gravity, distance, vx)
                : LevelAim.discreteVy(gravity, distance, vx, step);
        float firedVy = (float) vy;
        Landing landing = new Landing();
        boolean landed = simulator.fire(vx, firedVy, landing);
        log.clear();
        if (!landed) {
            throw new UsageException(DISTANCE + ": the " + method + " shot with vy=" + firedVy
                    + " m/s is still in the air after " + maxFlightSeconds(step) + " s; the"
                    + " target at S=" + distance + " m is out of reach");
        }
        double miss = landing.getX() - distance;
        return new AimResult(method, Math.abs(miss) <= tolerance, vx, firedVy,
                landing.getTimeSeconds(), landing.getX(), distance, 1, "closed form");
    }

    /**
     * Refuse a step longer than the {@link #MAX_FLIGHT_SECONDS} a shot may fly: its first step
     * would end past the time allowed, and the shot would be reported as never landing.
     */
    private static void checkStepLength(String option, float step) {
        if (step > MAX_FLIGHT_SECONDS) {
            throw new UsageException(option + ": must be at most " + MAX_FLIGHT_SECONDS + " s,"
                    + " the longest a shot is stepped for, but was " + step);
        }
    }

    /**
     * Refuse a discrete correction whose vy, about {@code g·(S/vx + h)/2}, is beyond the float
     * range the bullet flies in, naming the step when its term {@code g·h/2} is the larger.
     *
     * @param stepOption the option the aiming step came from
     */
    private static void checkDiscreteRange(String stepOption, float gravity, float distance,
            float vx, float step) {
        double vy = LevelAim.discreteVy(gravity, distance, vx, step);
        if (vy > Float.MAX_VALUE) {
            String option = step > distance / (double) vx ? stepOption : VX;
            throw new UsageException(option + ": the discrete correction needs vy = g*(S/vx +"
                    + " h)/2 = " + vy + " m/s (h = " + step + " s), beyond the float range ("
                    + Float.MAX_VALUE + ") the shot is stepped in; choose a smaller "
                    + stepOption + " or " + G + " or " + DISTANCE + ", or a larger " + VX);
        }
    }

    /**
     * Refuse a step so small that the shot would need more than {@link #MAX_STEPS_PER_SHOT}
     * steps just to cover S at vx.
     */
    private static void checkStepCount(String option, float distance, float vx, float step) {
        double steps = distance / ((double) vx * step);
        if (steps > MAX_STEPS_PER_SHOT) {
            double smallest = distance / ((double) vx * MAX_STEPS_PER_SHOT);
            float suggested = (float) smallest;
            if (suggested < smallest) {
                suggested = Math.nextUp(suggested);
            }
            throw new UsageException(option + ": a step of " + step + " s needs S/(vx*h) = "
                    + (float) steps + " steps to reach S=" + distance + " m at vx=" + vx
                    + " m/s, more than the limit " + MAX_STEPS_PER_SHOT + " (each step would"
                    + " move x by less than 8 float round-off units); use " + option + " >= "
                    + suggested);
        }
    }

    /**
     * Refuse a shot whose drag-free vy, {@code g·S/(2·vx)}, is beyond the float range the
     * bullet flies in, or so small that it rounds to a subnormal or to 0 (every method starts
     * from it).
     */
    private static void checkFloatRange(float gravity, float distance, float vx) {
        double vy = gravity * (double) distance / (2.0 * vx);
        if (vy > Float.MAX_VALUE) {
            throw new UsageException(VX + ": the launch needs vy = g*S/(2*vx) = " + vy
                    + " m/s, beyond the float range (" + Float.MAX_VALUE + ") the shot is"
                    + " stepped in; choose a larger " + VX + " or a smaller " + G + " or "
                    + DISTANCE);
        }
        if (vy < Float.MIN_NORMAL) {
            throw new UsageException(VX + ": the launch needs vy = g*S/(2*vx) = " + vy
                    + " m/s, below the smallest normal float (" + Float.MIN_NORMAL + "): the"
                    + " shot would be fired flat; choose a smaller " + VX + " or a larger "
                    + G + " or " + DISTANCE);
        }
    }

    /** The flight time allowed: {@link #MAX_FLIGHT_SECONDS}, or fewer at a tiny step. */
    private static float maxFlightSeconds(float step) {
        return (float) Math.min(MAX_FLIGHT_SECONDS, (double) MAX_STEPS_PER_SHOT * step);
    }

    private static Particle launch(float vx, float vy, float mass) {
        return new Particle(Vector3f.ZERO, new Vector3f(vx, vy, 0f), mass);
    }

    private static void printCsv(AimResult result, PrintStream out) {
        out.println(HEADER);
        out.println(result.getMethod() + "," + (float) result.getHorizontalSpeed() + ","
                + (float) result.getVerticalSpeed() + "," + result.getFlightSeconds() + ","
                + result.getLandingX() + "," + result.getMiss() + "," + result.getShots());
    }

    private static void printShots(ShotLog log, PrintStream out) {
        out.println(SHOTS_HEADER);
        for (int i = 0; i < log.size(); ++i) {
            out.println((i + 1) + "," + log.getVerticalSpeed(i) + "," + log.getLandingX(i) + ","
                    + log.getMiss(i));
        }
    }

    private static String[] strategyNames() {
        AimStrategy[] all = AimStrategy.values();
        String[] names = new String[all.length];
        for (int i = 0; i < all.length; ++i) {
            names[i] = all[i].cliName();
        }
        return names;
    }

    /** A fraction as a whole percentage: 0.3 → "30". */
    private static String percent(double fraction) {
        return Long.toString(Math.round(100.0 * fraction));
    }

    /**
     * Print the readable summary.
     *
     * @param strategy the strategy to name, or null to name none
     */
    private static void printText(AimResult result, boolean drag, float tolerance,
            AimStrategy strategy, PrintStream out) {
        String method = result.getMethod();
        double distance = result.getTargetDistance();
        double vx = result.getHorizontalSpeed();
        if (LECTURE.equals(method)) {
            out.println("method:            lecture, vy = g*S/(2*vx)");
        } else if (DISCRETE.equals(method)) {
            out.println("method:            discrete, vy corrected for the stepped shot");
        } else {
            out.println("method:            iterative, shoot and adjust ("
                    + (strategy == null ? "" : "strategy " + strategy.cliName() + ", ")
                    + "tolerance " + readable(tolerance) + " m)");
        }
        out.println("launch:            vx = " + readable(vx) + " m/s, vy = "
                + readable(result.getVerticalSpeed()) + " m/s");
        String flight = "flight time:       " + readable(result.getFlightSeconds())
                + " s (stepped shot)";
        if (!IterativeAim.METHOD.equals(method)) {
            flight += "; formula S/vx = " + readable(LevelAim.flightTime(distance, vx)) + " s";
        }
        out.println(flight);
        out.println("predicted landing: " + readable(result.getLandingX()) + " m (target S = "
                + readable(distance) + " m)");
        double miss = result.getMiss();
        out.println("miss:              " + readable(miss) + " m" + (miss < 0.0 ? " (short)"
                : miss > 0.0 ? " (long)" : ""));
        out.println("shots simulated:   " + result.getShots());
        if (drag && !IterativeAim.METHOD.equals(method)) {
            out.println("note:              the " + method + " formula ignores drag; the"
                    + " stepped shot includes it");
        }
    }

    /**
     * Format a number for a person: at most {@value #READABLE_DECIMALS} decimals, trailing
     * zeros dropped ({@code 99.6668}, {@code 24.5}, {@code 5}); below 0.001 or from 1e7 on,
     * three significant digits ({@code 0.000127}, {@code 2.50e+38}). {@code --csv} keeps
     * every digit.
     *
     * @param value the number (finite)
     * @return the text (not null)
     */
    static String readable(double value) {
        double magnitude = Math.abs(value);
        if (value != 0.0 && (magnitude < SMALL_READABLE || magnitude >= LARGE_READABLE)) {
            return String.format(Locale.ROOT, "%.3g", value);
        }
        String text = new BigDecimal(value).setScale(READABLE_DECIMALS, RoundingMode.HALF_EVEN)
                .stripTrailingZeros().toPlainString();
        return "-0".equals(text) ? "0" : text;
    }
}

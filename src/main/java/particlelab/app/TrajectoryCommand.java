package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import particlelab.aiming.Flight;
import particlelab.physics.EnergyLedger;
import particlelab.physics.Gravity;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * {@code particle-lab trajectory}: step one particle with the shared integrator and print its
 * states as CSV, {@code t,x,y,z,vx,vy,vz}, one row per step with the initial state first.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>{@code --v0} defaults to the lecture's gravitational-pull example (10, 10, 0) m/s.</li>
 * <li>{@code t} is {@code n·h} computed from the step count n, not summed, so it does not
 * drift; like every value it is printed with {@link Float#toString(float)}, which reads back
 * as the same float.</li>
 * <li>{@code --duration T} takes {@code T/h} rounded to the nearest whole number of steps (at
 * least one), so the last row's t is the multiple of h nearest T.</li>
 * <li>{@code --until-ground} needs a start at {@code y ≥ 0} and gives up after
 * {@link #MAX_STEPS} steps with a one-line error and no CSV.</li>
 * <li>The whole run is simulated before anything is printed, so a run that fails (never lands,
 * blows up) prints one error line and no partial CSV.</li>
 * </ul>
 */
public final class TrajectoryCommand {

    /** The subcommand's name. */
    public static final String NAME = "trajectory";
    /** The CSV header, exactly. */
    public static final String HEADER = "t,x,y,z,vx,vy,vz";
    /** The most steps one run takes, whichever way its length is given. */
    public static final int MAX_STEPS = 1_000_000;
    /** While printing, rows between checks that stdout still takes them. */
    private static final int ROWS_PER_OUTPUT_CHECK = 1024;

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String P0 = "--p0";
    private static final String V0 = "--v0";
    private static final String MASS = "--mass";
    private static final String G = "--g";
    private static final String LINEAR_DRAG = "--linear-drag";
    private static final String QUADRATIC_DRAG = "--quadratic-drag";
    private static final String THRUST = "--thrust";
    private static final String TPF = "--tpf";
    private static final String STEPS = "--steps";
    private static final String DURATION = "--duration";
    private static final String UNTIL_GROUND = "--until-ground";
    private static final String ENERGY = "--energy";

    private TrajectoryCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Step one particle with the lecture's Euler step and print"
                + " its trajectory as CSV (t,x,y,z,vx,vy,vz), one row per step, the initial"
                + " state first.")
                .value(P0, "X,Y,Z", "initial position P0 (m). Default 0,0,0.")
                .value(V0, "X,Y,Z", "initial velocity V0 (m/s). Default 10,10,0, the lecture's"
                        + " gravitational-pull example.")
                .value(MASS, "KG", "mass m (kg, > 0). At least " + Particle.MIN_MASS_KG
                        + ", so that 1/m is a finite float. Default 1.")
                .value(G, "X,Y,Z", "gravitational acceleration g (m/s^2), a vector. Default"
                        + " 0,-9.8,0; 0,0,0 leaves gravity out.")
                .value(LINEAR_DRAG, "B", "linear drag b in F = -b*V (N*s/m = kg/s, >= 0)."
                        + " Default 0: none.")
                .value(QUADRATIC_DRAG, "C", "quadratic drag c in F = -c*|V|*V (kg/m, >= 0)."
                        + " Default 0: none.")
                .value(THRUST, "K", "thrust k in F = k*V/|V|, along the particle's own"
                        + " velocity, none at rest (N, >= 0). Default 0: none.")
                .value(TPF, "H", "time step h (s, > 0), a decimal or a fraction such as 1/60."
                        + " Default 1/60. A step too small to move the particle (h*|V0| below"
                        + " half the float spacing at P0 on some axis) is refused.")
                .value(STEPS, "N", "take N steps (0 to " + MAX_STEPS + "): N+1 rows.")
                .value(DURATION, "T", "simulate T seconds (> 0): T/h rounded to the nearest"
                        + " whole number of steps, at least 1, at most " + MAX_STEPS + "; the"
                        + " last row's t is the multiple of h nearest T.")
                .flag(UNTIL_GROUND, "stop at the first step with y < 0, that row included. The"
                        + " start needs y >= 0; a particle still up after " + MAX_STEPS
                        + " steps is an error (exit 2).")
                .flag(ENERGY, "append the energy ledger's columns to each row (issue 32):"
                        + " kinetic_J, potential_J, and thrust_work_J and drag_loss_J where"
                        + " those forces are on, then numerical_J, the energy the steps"
                        + " themselves created: total now - total at the start - the forces'"
                        + " work (docs/energy.md).")
                .note("Give exactly one of " + STEPS + ", " + DURATION + ", " + UNTIL_GROUND
                        + ". Only the forces with non-zero coefficients are composed.")
                .note("Each step is the lecture's semi-implicit Euler step: a = g + F/m,"
                        + " V += h*a, then P += h*V with the new V. t is n*h computed from the"
                        + " step count n (no drift). Every value is printed with enough digits"
                        + " to read back the same float.")
                .note(CommandSupport.STABILITY_NOTE)
                .note("Exit status: 0 on success; 2 on a bad command line, a particle that"
                        + " never lands with " + UNTIL_GROUND + ", or a step that overflows,"
                        + " with one line on stderr and no CSV.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "trajectory" (not null)
     * @param out where the CSV or help goes (not null)
     * @param err where warnings and the error line go (not null)
     * @return the exit code: 0 on success, 2 on a bad command line
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                parsed -> runParsed(parsed, out, err));
    }

    /** The command proper, once the options are parsed and no help was asked for. */
    private static int runParsed(Options options, PrintStream out, PrintStream err) {
        Vector3f p0 = options.vector(P0, Vector3f.ZERO);
        Vector3f v0 = options.vector(V0, new Vector3f(10f, 10f, 0f));
        float mass = options.floatAtLeast(MASS, CommandSupport.DEFAULT_MASS_KG,
                Particle.MIN_MASS_KG, "the smallest mass whose 1/m is a finite float");
        Vector3f gravity = options.vector(G, new Vector3f(0f, -Gravity.STANDARD_G, 0f));
        float linearDrag = options.nonNegativeFloat(LINEAR_DRAG, 0f);
        float quadraticDrag = options.nonNegativeFloat(QUADRATIC_DRAG, 0f);
        float thrust = options.nonNegativeFloat(THRUST, 0f);
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        options.exactlyOneOf(STEPS, DURATION, UNTIL_GROUND);

        ParticleIntegrator integrator =
                CommandSupport.integrator(gravity, linearDrag, quadraticDrag, thrust);
        Particle start = new Particle(p0, v0, mass);
        int steps;
        if (options.has(STEPS)) {
            steps = options.intInRange(STEPS, 0, 0, MAX_STEPS);
        } else if (options.has(DURATION)) {
            steps = stepsFor(options.positiveFloat(DURATION), step);
        } else {
            if (p0.y < 0f) {
                throw new UsageException(P0 + ": with " + UNTIL_GROUND + " the start must"
                        + " be at or above the ground (y >= 0), but was " + p0.x + ","
                        + p0.y + "," + p0.z);
            }
            steps = MAX_STEPS;
        }
        checkStepMoves(p0, v0, step);
        int taken = fly(integrator, start, step, steps, options.has(UNTIL_GROUND), null, false);
        // Only a run that succeeded gets the warning: a blow-up is its one error line.
        CommandSupport.warnIfUnstable(integrator, start, step, err);
        fly(integrator, start, step, taken, false, out, options.has(ENERGY));
        return Program.OK;
    }

    /**
     * Turn a duration into a step count: {@code T/h} rounded to the nearest whole number,
     * halves up, at least 1.
     */
    private static int stepsFor(float durationSeconds, float stepSeconds) {
        double steps = Math.floor(durationSeconds / (double) stepSeconds + 0.5);
        if (steps > MAX_STEPS) {
            throw new UsageException(DURATION + ": must take at most " + MAX_STEPS + " steps of "
                    + stepSeconds + " s (" + (MAX_STEPS * (double) stepSeconds) + " s), but was "
                    + durationSeconds);
        }
        return Math.max(1, (int) steps);
    }

    /**
     * Refuse a step too small to move the particle at all: on an axis where it starts moving,
     * {@code h·|V0|} below half the float spacing at P0 rounds every step's move to nothing,
     * and the CSV would show a particle standing still.
     */
    private static void checkStepMoves(Vector3f p0, Vector3f v0, float stepSeconds) {
        String[] axes = {"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis) {
            float position = p0.get(axis);
            double move = Math.abs((double) stepSeconds * v0.get(axis));
            double halfSpacing = Math.ulp(position) / 2.0;
            if (move > 0.0 && move < halfSpacing) {
                String name = axes[axis];
                throw new UsageException(TPF + ": a step of " + stepSeconds + " s moves "
                        + name + " by h*|v" + name + "| = " + (float) move + " m, less than half"
                        + " the float spacing at " + name + " = " + position + " m ("
                        + (float) halfSpacing + " m), so " + name + " could never change; use"
                        + " --tpf >= " + (float) (2.0 * halfSpacing / Math.abs(v0.get(axis))));
            }
        }
    }

    /**
     * Step a copy of the start with the one flight helper ({@link Flight}), printing each
     * state to out if out is not null. From a start at {@code y ≥ 0} the first step whose
     * segment comes down through the ground is the first with {@code y < 0}.
     *
     * @param maxSteps the steps to take, or the most to take until the ground
     * @param untilGround stop after the first step with y &lt; 0
     * @param energy true to append the energy ledger's columns to each row
     * @return the number of steps taken
     * @throws UsageException if the particle became non-finite, or never came down
     */
    private static int fly(ParticleIntegrator integrator, Particle start, float stepSeconds,
            int maxSteps, boolean untilGround, PrintStream out, boolean energy) {
        Particle particle = new Particle();
        particle.copyFrom(start);
        Flight flight = new Flight(integrator);
        Particle atStart = new Particle();
        StringBuilder row = new StringBuilder();
        EnergyLedger ledger = new EnergyLedger();
        int columns = EnergyLedger.KINETIC | EnergyLedger.columnsOf(integrator);
        measure(ledger, integrator, particle);
        ledger.start();
        if (out != null) {
            out.println(energy ? EnergyLedger.csvHeader(columns, HEADER) : HEADER);
            printRow(0, stepSeconds, particle, row, out, energy ? ledger : null, columns);
        }
        for (int n = 1; n <= maxSteps; ++n) {
            atStart.copyFrom(particle);
            double landing;
            try {
                landing = flight.step(particle, stepSeconds);
            } catch (NonFiniteStepException nonFinite) {
                throw CommandSupport.blewUp(stepSeconds, "at step " + n,
                        integrator.maxStableStep(start));
            }
            if (energy) {
                ledger.addStepWork(integrator, atStart, stepSeconds, particle.velocity);
                measure(ledger, integrator, particle);
            }
            if (out != null) {
                printRow(n, stepSeconds, particle, row, out, energy ? ledger : null, columns);
                if (n % ROWS_PER_OUTPUT_CHECK == 0 && out.checkError()) {
                    // The reader has gone (a closed pipe) or the disk is full: stop here;
                    // Main reports it in one line.
                    return n;
                }
            }
            if (untilGround && landing != Flight.NO_LANDING) {
                return n;
            }
        }
        if (untilGround) {
            throw new UsageException(UNTIL_GROUND + ": the particle is still at y = "
                    + particle.position.y + " m after " + maxSteps + " steps (t = "
                    + (float) (maxSteps * (double) stepSeconds) + " s); with these forces it"
                    + " does not come down in time");
        }
        return maxSteps;
    }

    /** The particle's state as the ledger's kinetic and potential columns. */
    private static void measure(EnergyLedger ledger, ParticleIntegrator integrator,
            Particle particle) {
        ledger.beginState();
        ledger.addBody(integrator, particle);
        ledger.endState();
    }

    private static void printRow(int n, float stepSeconds, Particle particle, StringBuilder row,
            PrintStream out, EnergyLedger ledger, int columns) {
        Vector3f p = particle.position;
        Vector3f v = particle.velocity;
        row.setLength(0);
        // t = n·h from the step count: no accumulated drift.
        row.append((float) (n * (double) stepSeconds))
                .append(',').append(p.x).append(',').append(p.y).append(',').append(p.z)
                .append(',').append(v.x).append(',').append(v.y).append(',').append(v.z);
        if (ledger != null) {
            // the energies to float's digits, as the state (summed in double)
            for (int column = 0; column < EnergyLedger.NUMERICAL_COLUMN; ++column) {
                if ((columns & (1 << column)) != 0) {
                    row.append(',').append((float) ledger.getColumn(column));
                }
            }
            row.append(',').append((float) ledger.getNumericalJoules());
        }
        out.println(row);
    }
}

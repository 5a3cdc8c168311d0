package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SimulationClock;
import particlelab.physics.StepRegime;
import particlelab.physics.Thrust;
import particlelab.physics.Validate;

/**
 * What the physics subcommands share: the scene's forces from the options, the stability check
 * and the one-line error report.
 */
final class CommandSupport {

    /** The default step h (in seconds): the clock's 60 steps per second. */
    static final float DEFAULT_STEP_SECONDS = SimulationClock.DEFAULT_STEP_SECONDS;
    /** The default mass (in kg). */
    static final float DEFAULT_MASS_KG = 1f;
    /** The help texts' statement of the limits that {@link #warnIfUnstable} checks. */
    static final String STABILITY_NOTE = "Stability: with sigma = b/m + c*|V|/m at the start,"
            + " h > 2/sigma makes drag grow the speed every step (the run blows up) and"
            + " h > 1/sigma makes it reverse the velocity every step while still shrinking it."
            + " With lambda = b/m + 2c*|V|/m (how fast a small change of speed dies out;"
            + " quadratic drag's force grows with the square of the speed) at the terminal"
            + " speed v_t, where drag balances the pull, h > 2/lambda means the run never"
            + " settles there (quadratic drag alone: h > v_t/g, v_t = sqrt(m*g/c)) and"
            + " h > 1/lambda that it swings about v_t before settling. Linear drag has"
            + " sigma = lambda = b/m. A step past a limit gives one warning on stderr and the"
            + " run goes on as asked.";
    /** The most halvings of the bracket in the terminal-speed search (from 1 m/s to 1e-45). */
    private static final int TERMINAL_BISECTIONS = 300;
    /** The terminal-speed search stops at this relative width: float resolution. */
    private static final double TERMINAL_TOLERANCE = 1e-7;

    private CommandSupport() {
    }

    /**
     * Compose only the forces with non-zero coefficients, as every scene does.
     *
     * @param gravity g (in m/s², not null, copied; zero leaves gravity out)
     * @param linearDrag b (in N·s/m, &ge;0)
     * @param quadraticDrag c (in kg/m, &ge;0)
     * @param thrust k (in N, &ge;0)
     * @return the integrator for those forces (not null)
     */
    static ParticleIntegrator integrator(Vector3f gravity, float linearDrag,
            float quadraticDrag, float thrust) {
        List<Force> forces = new ArrayList<>();
        if (gravity.x != 0f || gravity.y != 0f || gravity.z != 0f) {
            forces.add(new Gravity(gravity));
        }
        if (linearDrag > 0f) {
            forces.add(new LinearDrag(linearDrag));
        }
        if (quadraticDrag > 0f) {
            forces.add(new QuadraticDrag(quadraticDrag));
        }
        if (thrust > 0f) {
            forces.add(new Thrust(thrust));
        }
        return new ParticleIntegrator(forces.toArray(new Force[0]));
    }

    /**
     * Warn on err, in one line, when the step passes a limit of the Euler step (see
     * {@link StepRegime}), checked where each limit means something:
     * <ul>
     * <li>at the initial state, the drag rate σ ({@code b/m + c·|V|/m}): drag makes the speed
     * grow every step (the run blows up) once {@code h > 2/σ}, and reverses the velocity every
     * step while still shrinking it once {@code h > 1/σ};</li>
     * <li>at the terminal velocity, if the forces have one, the damping rate λ
     * ({@code b/m + 2c·v_t/m}): the run cannot settle there once {@code h > 2/λ} (for quadratic
     * drag alone {@code v_t/g}) and swings about it before settling once {@code h > 1/λ}.</li>
     * </ul>
     * The most serious case found is reported. Linear drag has σ = λ everywhere, so its two
     * checks agree.
     *
     * @param integrator the scene's forces (not null)
     * @param particle the state to check (not null, not modified)
     * @param stepSeconds h (in seconds, &gt;0)
     * @param err where the warning goes (not null)
     */
    static void warnIfUnstable(ParticleIntegrator integrator, Particle particle,
            float stepSeconds, PrintStream err) {
        String warning = stabilityWarning(integrator, particle, stepSeconds);
        if (warning != null) {
            err.println(warning);
        }
    }

    /**
     * Word the warning of {@link #warnIfUnstable}.
     *
     * @return the line, or null when the step is within every limit
     */
    static String stabilityWarning(ParticleIntegrator integrator, Particle particle,
            float stepSeconds) {
        float sigma = integrator.dragRate(particle);
        StepRegime atStart = StepRegime.of(stepSeconds, sigma, Float.POSITIVE_INFINITY,
                Float.POSITIVE_INFINITY);
        Particle terminal = terminalState(integrator, particle);
        StepRegime atTerminal = terminal == null ? StepRegime.STABLE
                : StepRegime.of(stepSeconds, 0f, integrator.maxStableStep(terminal),
                        integrator.maxMonotoneStep(terminal));
        String head = "warning: --tpf " + stepSeconds + " s exceeds ";
        String tail = "; carrying on as asked";
        // atStart is STABLE, REVERSES or GROWS, atTerminal STABLE, OVERSHOOTS or UNSTABLE.
        if (atStart.compareTo(atTerminal) > 0) {
            float limit = (atStart == StepRegime.GROWS ? 2f : 1f) / sigma;
            return head + (atStart == StepRegime.GROWS ? "2" : "1") + "/sigma = " + limit
                    + " s at the initial state (drag rate sigma = " + sigma + " /s): "
                    + atStart.consequence() + tail;
        }
        if (atTerminal == StepRegime.STABLE) {
            return null;
        }
        float lambda = integrator.dampingRate(terminal);
        boolean unstable = atTerminal == StepRegime.UNSTABLE;
        float limit = unstable ? integrator.maxStableStep(terminal)
                : integrator.maxMonotoneStep(terminal);
        return head + (unstable ? "the stability limit 2/lambda" : "1/lambda") + " = " + limit
                + " s at the terminal speed " + terminal.velocity.length() + " m/s (damping"
                + " rate lambda = " + lambda + " /s): " + atTerminal.consequence()
                + (unstable ? ", so the run never settles there" : "") + tail;
    }

    /**
     * Find the terminal velocity of the particle's forces: the speed along the steady pull (the
     * field acceleration at rest, or else the initial velocity's direction, for thrust) at which
     * the acceleration along it vanishes, by bisection. The forces of the commands do not
     * depend on position, so the particle's position is kept.
     *
     * @return a particle at the terminal velocity, or null if there is no pull or no drag to
     *     balance it
     */
    static Particle terminalState(ParticleIntegrator integrator, Particle particle) {
        Particle probe = new Particle();
        probe.copyFrom(particle);
        probe.velocity.zero();
        Vector3f direction = integrator.acceleration(probe, new Vector3f());
        if (direction.lengthSquared() == 0f) {
            direction.set(particle.velocity);
        }
        if (direction.lengthSquared() == 0f || !Validate.isFinite(direction)) {
            return null;
        }
        direction.normalizeLocal();
        double low = 0.0;
        double high = 1.0;
        while (pullAlong(integrator, probe, direction, high) > 0f) {
            low = high;
            high *= 2.0;
            if (high > Float.MAX_VALUE) {
                return null;
            }
        }
        for (int i = 0; i < TERMINAL_BISECTIONS && high - low > TERMINAL_TOLERANCE * high; ++i) {
            double mid = 0.5 * (low + high);
            if (pullAlong(integrator, probe, direction, mid) > 0f) {
                low = mid;
            } else {
                high = mid;
            }
        }
        probe.velocity.set(direction).multLocal((float) (0.5 * (low + high)));
        return probe;
    }

    /** The acceleration along the direction at the given speed along it (m/s²). */
    private static float pullAlong(ParticleIntegrator integrator, Particle probe,
            Vector3f direction, double speed) {
        probe.velocity.set(direction).multLocal((float) speed);
        float along = integrator.acceleration(probe, new Vector3f()).dot(direction);
        // NaN or infinite forces: no balance to find at this speed or beyond.
        return Float.isNaN(along) ? -1f : along;
    }

    /**
     * Explain a step that left the particle non-finite, as a bad command line.
     *
     * @param stepSeconds h (in seconds)
     * @param when where it happened, e.g. "at step 12" (not null)
     * @param limitSeconds the stability limit at the start (in seconds, may be infinite)
     * @return the exception to throw (not null)
     */
    static UsageException blewUp(float stepSeconds, String when, float limitSeconds) {
        String why = Float.isInfinite(limitSeconds)
                ? "the numbers overflowed the float range"
                : "the stability limit at the start was " + limitSeconds + " s";
        return new UsageException("--tpf: the Euler step of " + stepSeconds + " s left the"
                + " particle non-finite (NaN or infinite) " + when + "; " + why
                + "; choose a smaller step");
    }

    /** A command's work once its options are parsed. */
    interface ParsedCommand {
        /**
         * Run with parsed options.
         *
         * @param options the parsed options (not null)
         * @return the exit code
         * @throws UsageException for a bad command line, reported as one line
         */
        int run(Options options);
    }

    /**
     * Run a command the way every subcommand runs: parse the arguments, print the help if it
     * was asked for, else run the command; a bad command line is one line on err and
     * {@link Program#USAGE}.
     *
     * @param command the command's full name, e.g. "particle-lab aim" (not null)
     * @param options the command's declared options (not null)
     * @param args the arguments after the command's name (not null)
     * @param out where the help goes (not null)
     * @param err where the error line goes (not null)
     * @param body the command proper (not null)
     * @return the exit code
     */
    static int execute(String command, Options options, String[] args, PrintStream out,
            PrintStream err, ParsedCommand body) {
        try {
            options.parse(args);
            if (options.isHelpRequested()) {
                out.print(options.help());
                return Program.OK;
            }
            return body.run(options);
        } catch (UsageException problem) {
            return reportUsage(command, problem, err);
        }
    }

    /**
     * Print a bad command line as one line on err.
     *
     * @param command the command's full name, e.g. "particle-lab aim" (not null)
     * @param problem the exception (not null)
     * @param err where to print (not null)
     * @return {@link Program#USAGE}
     */
    static int reportUsage(String command, UsageException problem, PrintStream err) {
        err.println(command + ": " + problem.getMessage());
        return Program.USAGE;
    }
}

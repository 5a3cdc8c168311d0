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
import particlelab.physics.Thrust;

/**
 * What the physics subcommands share: the scene's forces from the options, the stability check
 * and the one-line error report.
 */
final class CommandSupport {

    /** The default step h (in seconds): the clock's 60 steps per second. */
    static final float DEFAULT_STEP_SECONDS = SimulationClock.DEFAULT_STEP_SECONDS;
    /** The default mass (in kg). */
    static final float DEFAULT_MASS_KG = 1f;

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
     * Warn on err when the step exceeds a stability limit at the particle's state: the Euler
     * step diverges beyond {@code 2/λ} and overshoots beyond {@code 1/λ}, where λ is the
     * forces' damping rate ({@link particlelab.physics.Force#dampingRate}: {@code b/m} for
     * linear drag, {@code 2c·|V|/m} for quadratic drag). Quadratic drag damps faster as the
     * speed grows, so the check holds only at this state.
     *
     * @param integrator the scene's forces (not null)
     * @param particle the state to check (not null, not modified)
     * @param stepSeconds h (in seconds, &gt;0)
     * @param err where the warning goes (not null)
     */
    static void warnIfUnstable(ParticleIntegrator integrator, Particle particle,
            float stepSeconds, PrintStream err) {
        float rate = integrator.dampingRate(particle);
        float stable = integrator.maxStableStep(particle);
        float monotone = integrator.maxMonotoneStep(particle);
        if (stepSeconds > stable) {
            err.println("warning: --tpf " + stepSeconds + " s exceeds the stability limit 2/lambda"
                    + " = " + stable + " s at the initial state (damping rate lambda = " + rate
                    + " /s): the Euler step will blow up; carrying on as asked");
        } else if (stepSeconds > monotone) {
            err.println("warning: --tpf " + stepSeconds + " s exceeds 1/lambda = " + monotone
                    + " s at the initial state (damping rate lambda = " + rate + " /s): the"
                    + " velocity will overshoot and oscillate; carrying on as asked");
        }
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

    /**
     * Print a bad command line as one line on err.
     *
     * @param command the command's full name, e.g. "particle-lab aim" (not null)
     * @param problem the exception (not null)
     * @param err where to print (not null)
     * @return {@link UsageException#EXIT_CODE}
     */
    static int reportUsage(String command, UsageException problem, PrintStream err) {
        err.println(command + ": " + problem.getMessage());
        return UsageException.EXIT_CODE;
    }
}

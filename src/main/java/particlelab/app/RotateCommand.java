package particlelab.app;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.io.PrintStream;
import particlelab.physics.NonFiniteStepException;
import particlelab.rigid.Inertia;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationCheck;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;
import particlelab.rigid.RotationIntegrator;
import particlelab.rigid.SpinAngle;

/**
 * {@code particle-lab rotate}: one torque-free rigid body turned by the
 * {@link RotationIntegrator}, one CSV row per step with the start first:
 * {@code t,det,orthogonality_error,angle_error,wx,wy,wz,energy,angular_momentum,angle_lag}.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>{@code --orientation} defaults to {@code euler}, the lecture's plain matrix step, as
 * {@code trajectory} defaults to the lecture's particle step: the command is there to show its
 * drift (the det and orthogonality columns) and each cure is one word away.</li>
 * <li>{@code angle_error} is computed whenever the exact motion is the steady spin
 * {@code R(t) = exp(t·[ω]×)}: without the gyroscopic term (ω then stays constant), or when ω
 * lies in one eigenspace of the inertia (a principal axis, or any axis of a sphere); otherwise
 * the column is empty.</li>
 * <li>{@code angle_lag}, added last so that the earlier columns keep their places, is given
 * under the same condition: {@code |ω|·t} minus the angle R has turned about ω, summed step by
 * step ({@link SpinAngle}). {@code angle_error} is a distance between orientations and wraps
 * at π, so at a large {@code |ω|h} a method a turn behind reads nearly 0 there; the lag does
 * not wrap, and ranks the methods by how far behind they are.</li>
 * <li>{@code energy} and {@code angular_momentum} are computed from the printed body-frame
 * ω, in double.</li>
 * <li>The whole run is simulated before anything is printed, so a run that blows up prints one
 * error line and no partial CSV.</li>
 * </ul>
 */
public final class RotateCommand {

    /** The subcommand's name. */
    public static final String NAME = "rotate";
    /** The CSV header, exactly. */
    public static final String HEADER =
            "t,det,orthogonality_error,angle_error,wx,wy,wz,energy,angular_momentum,angle_lag";

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String OMEGA = "--omega";
    private static final String INERTIA = "--inertia";
    private static final String TPF = "--tpf";
    private static final String STEPS = "--steps";
    private static final String DURATION = "--duration";
    private static final String ORIENTATION = "--orientation";
    private static final String ANGULAR = "--angular";
    private static final String GYROSCOPIC = "--gyroscopic";
    /** The words of --orientation, in the order of {@link Orientation}'s constants. */
    private static final String[] ORIENTATION_WORDS =
            {"euler", "gram-schmidt", "polar", "quaternion", "exact"};
    private static final String[] ANGULAR_WORDS = {"explicit", "midpoint"};

    private RotateCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Turn one torque-free rigid body, its principal axes along"
                + " the world axes at t = 0, and print one CSV row per step, the start first: "
                + HEADER + ".")
                .value(OMEGA, "X,Y,Z", "initial angular velocity omega (rad/s), world frame"
                        + " (at t = 0 also the body frame). Required.")
                .value(INERTIA, "A,B,C", "principal moments of inertia about the body x, y, z"
                        + " axes (kg*m^2, each > 0 and at most the sum of the other two, as for"
                        + " every solid body). Default 1,1,1: a uniform sphere, whose omega"
                        + " stays constant.")
                .value(TPF, "H", "time step h (s, > 0), a decimal or a fraction such as 1/60."
                        + " Default 1/60.")
                .value(STEPS, "N", "take N steps (0 to " + CollisionOptions.MAX_STEPS
                        + "): N+1 rows.")
                .value(DURATION, "T", "simulate T seconds (> 0): T/h rounded to the nearest"
                        + " whole number of steps, at least 1.")
                .value(ORIENTATION, String.join("|", ORIENTATION_WORDS), "how R follows"
                        + " dR/dt = [omega]x R: euler is the lecture's R += h*[omega]x*R with"
                        + " no cure (det R grows by a factor 1 + (|omega|h)^2 a step);"
                        + " gram-schmidt and polar re-orthonormalise after it; quaternion steps"
                        + " q += (h/2)(0,omega)q and normalises; exact is R = exp(h[omega]x)R."
                        + " Default euler, the lecture's step, whose drift this command is"
                        + " for.")
                .value(ANGULAR, String.join("|", ANGULAR_WORDS), "how omega follows Euler's"
                        + " equations I*domega/dt = -omega x (I*omega) in the body frame:"
                        + " explicit Euler, or the implicit midpoint rule, which keeps energy"
                        + " and |L|. Default explicit.")
                .value(GYROSCOPIC, "on|off", "keep the gyroscopic term omega x (I*omega);"
                        + " off leaves omega constant. Default on.")
                .note("Give exactly one of " + STEPS + ", " + DURATION + ". Each step turns"
                        + " omega first, then R with the new omega.")
                .note("Columns: t (s) is n*h; det is det R; orthogonality_error is the"
                        + " Frobenius norm |R^T R - I|; angle_error is the angle (rad) between"
                        + " the exact rotation and the nearest rotation to R, given only while"
                        + " the exact motion is a steady spin (gyroscopic off, or omega along"
                        + " a principal axis, or any omega of a sphere), else empty; wx,wy,wz"
                        + " is omega in the body frame, R^T omega (rad/s), so each flip of a"
                        + " body spun near its middle axis shows as a sign change of wy;"
                        + " energy is 1/2 omega^T I omega (J) and angular_momentum is |I omega|"
                        + " (kg*m^2/s), both from wx,wy,wz; angle_lag is |omega|*t minus the"
                        + " angle (rad) R has turned about omega, summed step by step so that it"
                        + " never wraps (angle_error wraps at pi), given when angle_error is.")
                .note("Exit status: 0 on success; 2 on a bad command line or a step that"
                        + " overflows, with one line on stderr and no CSV.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "rotate" (not null)
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
        options.string(OMEGA);
        Vector3f omega = options.vector(OMEGA, Vector3f.ZERO);
        Inertia inertia = inertia(options.vector(INERTIA, new Vector3f(1f, 1f, 1f)));
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        options.exactlyOneOf(STEPS, DURATION);
        int steps = options.has(STEPS)
                ? options.intInRange(STEPS, 0, 0, CollisionOptions.MAX_STEPS)
                : CollisionOptions.stepsFor(DURATION, options.positiveFloat(DURATION),
                        step);
        Orientation orientation = Orientation.values()[indexOf(ORIENTATION_WORDS,
                options.choice(ORIENTATION, ORIENTATION_WORDS[0], ORIENTATION_WORDS))];
        Angular angular = Angular.values()[indexOf(ANGULAR_WORDS,
                options.choice(ANGULAR, ANGULAR_WORDS[0], ANGULAR_WORDS))];
        boolean gyroscopic = "on".equals(options.choice(GYROSCOPIC, "on", "on", "off"));
        RotationIntegrator integrator =
                new RotationIntegrator(orientation, angular, gyroscopic);
        boolean steady = !gyroscopic || inertia.isSteadySpin(omega);
        spin(integrator, inertia, omega, steady, step, steps, null);
        spin(integrator, inertia, omega, steady, step, steps, out);
        return Program.OK;
    }

    /** The moments from --inertia, as a usage error when no solid body has them. */
    private static Inertia inertia(Vector3f moments) {
        try {
            return Inertia.of(moments.x, moments.y, moments.z);
        } catch (IllegalArgumentException impossible) {
            throw new UsageException(INERTIA + ": " + impossible.getMessage());
        }
    }

    private static int indexOf(String[] words, String word) {
        for (int i = 0; i < words.length; ++i) {
            if (words[i].equals(word)) {
                return i;
            }
        }
        throw new IllegalArgumentException(word + " is not one of the words");
    }

    /**
     * Step the body from the start, printing each row to out if out is not null.
     *
     * @throws UsageException if a step would go non-finite
     */
    private static void spin(RotationIntegrator integrator, Inertia inertia, Vector3f omega,
            boolean steady, float stepSeconds, int steps, PrintStream out) {
        RigidBody body = new RigidBody(1f, inertia);
        body.setAngularVelocity(omega);
        RotationCheck check = new RotationCheck();
        SpinAngle turned = new SpinAngle();
        turned.start(body.orientation, omega);
        Matrix3f start = new Matrix3f();
        Matrix3f exact = new Matrix3f();
        Vector3f bodyOmega = new Vector3f();
        StringBuilder row = new StringBuilder();
        if (out != null) {
            out.println(HEADER);
            printRow(0, stepSeconds, body, omega, steady, check, turned, start, exact,
                    bodyOmega, row, out);
        }
        for (int n = 1; n <= steps; ++n) {
            try {
                integrator.step(body, stepSeconds);
            } catch (NonFiniteStepException nonFinite) {
                throw new UsageException(TPF + ": the rotation step of " + stepSeconds + " s"
                        + " left omega or R non-finite (NaN or infinite) at step " + n
                        + "; the numbers overflowed the float range; choose a smaller step or"
                        + " a slower spin");
            }
            if (steady) {
                try {
                    turned.add(body.orientation);
                } catch (IllegalArgumentException unmeasurable) {
                    // Finite, but its determinant left the float range: no nearest rotation.
                    throw new UsageException(OMEGA + ": after step " + n + " of " + stepSeconds
                            + " s, R is too far from a rotation (det R out of the float range)"
                            + " to measure the angle it turned; choose a slower spin or a"
                            + " smaller " + TPF);
                }
            }
            if (out != null) {
                printRow(n, stepSeconds, body, omega, steady, check, turned, start, exact,
                        bodyOmega, row, out);
            }
        }
    }

    private static void printRow(int n, float stepSeconds, RigidBody body, Vector3f omega,
            boolean steady, RotationCheck check, SpinAngle turned, Matrix3f start,
            Matrix3f exact, Vector3f bodyOmega, StringBuilder row, PrintStream out) {
        double t = n * (double) stepSeconds;
        Matrix3f r = body.orientation;
        body.bodyAngularVelocity(bodyOmega);
        Inertia inertia = body.getInertia();
        row.setLength(0);
        row.append((float) t).append(',').append(check.determinant(r)).append(',')
                .append(check.orthogonalityError(r)).append(',');
        if (steady) {
            // The steady spin keeps the initial ω (world frame).
            check.exactRotation(start, omega, t, exact);
            row.append(check.angleError(r, exact));
        }
        row.append(',').append(bodyOmega.x).append(',').append(bodyOmega.y).append(',')
                .append(bodyOmega.z).append(',').append(inertia.kineticEnergy(bodyOmega))
                .append(',').append(inertia.angularMomentum(bodyOmega)).append(',');
        if (steady) {
            double rate = Math.sqrt((double) omega.x * omega.x + (double) omega.y * omega.y
                    + (double) omega.z * omega.z);
            row.append(turned.lagRadians(rate * t));
        }
        out.println(row);
    }
}

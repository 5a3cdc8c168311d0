package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import java.util.Locale;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SphereRule;
import particlelab.world.World;

/**
 * {@code particle-lab collide}: two spheres in free flight (no forces) until their first
 * impact, resolved by the impulse with restitution e, and one CSV row:
 * {@code t_impact,v1x,v1y,v1z,v2x,v2y,v2z,px_before,py_before,pz_before,px_after,py_after,
 * pz_after,ke_before,ke_after}.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>Whether the spheres meet is decided from their straight paths before stepping; if they
 * do and the overlap test steps past the impact without seeing it (tunnelling), that is
 * reported as an error too.</li>
 * <li>The overlap test sees the impact at the end of a step, already overlapping: its t is that
 * step's end, and the overlap is removed in proportion to inverse mass.</li>
 * <li>Momentum and kinetic energy are summed in double precision from the float velocities.</li>
 * </ul>
 */
public final class CollideCommand {

    /** The subcommand's name. */
    public static final String NAME = "collide";
    /** The CSV header, exactly. */
    public static final String HEADER = "t_impact,v1x,v1y,v1z,v2x,v2y,v2z,px_before,py_before,"
            + "pz_before,px_after,py_after,pz_after,ke_before,ke_after";

    /**
     * The share of the exchanged momentum {@code |m1·Δv1|} the float velocities may lose
     * before a warning: rounding each velocity to a float loses about 6e-8 of it when the
     * masses are alike, and more the more they differ (a change {@code j/m} far below the
     * velocity's resolution is rounded away whole), so 0.1% is well past ordinary round-off.
     */
    static final double LOST_MOMENTUM_FRACTION = 1e-3;

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String M1 = "--m1";
    private static final String M2 = "--m2";
    private static final String P1 = "--p1";
    private static final String P2 = "--p2";
    private static final String V1 = "--v1";
    private static final String V2 = "--v2";
    private static final String R1 = "--r1";
    private static final String R2 = "--r2";
    private static final String RESTITUTION = "--restitution";
    private static final String TPF = "--tpf";

    private CollideCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Fly two spheres without forces until their first impact,"
                + " resolve it with the impulse j = -(1+e)*v_rel.n/(1/m1+1/m2) and print one CSV"
                + " row under the header t_impact, v1x..v2z, px_before..pz_before, px_after.."
                + "pz_after, ke_before, ke_after (written without spaces).")
                .value(M1, "KG", "mass of sphere 1 (kg, > 0). Required.")
                .value(M2, "KG", "mass of sphere 2 (kg, > 0). Required.")
                .value(P1, "X,Y,Z", "centre of sphere 1 at t = 0 (m). Required.")
                .value(P2, "X,Y,Z", "centre of sphere 2 at t = 0 (m). Required.")
                .value(V1, "X,Y,Z", "velocity of sphere 1 (m/s). Required.")
                .value(V2, "X,Y,Z", "velocity of sphere 2 (m/s). Required.")
                .value(R1, "R", "radius of sphere 1 (m, > 0). Required.")
                .value(R2, "R", "radius of sphere 2 (m, > 0). Required.")
                .value(RESTITUTION, "E", "restitution e (0 to 1). Required.")
                .value(TPF, "H", "time step h (s, > 0), a decimal or a fraction such as 1/60."
                        + " Default 1/60.")
                .value(CollisionOptions.DETECTION, "overlap|swept",
                        CollisionOptions.DETECTION_HELP + " Default swept.")
                .note("Columns: t_impact is the time of impact (s; with the overlap test, the end"
                        + " of the step that found the spheres overlapping); v1*, v2* the"
                        + " velocities just after it (m/s); p*_before, p*_after the total"
                        + " momentum m1*v1 + m2*v2 just before and after (kg*m/s); ke_before,"
                        + " ke_after the total kinetic energy (J). Momentum is conserved (when"
                        + " rounding the velocities to floats loses more than "
                        + (float) (100.0 * LOST_MOMENTUM_FRACTION) + "% of the momentum the"
                        + " impulse exchanged, as when the masses differ by many orders, one"
                        + " warning on stderr says how much); the energy lost is"
                        + " 0.5*mu*(1-e^2)*v_n^2, mu = m1*m2/(m1+m2), v_n the normal approach"
                        + " speed.")
                .note("Exit status: 0 on success; 2 on a bad command line (spheres overlapping"
                        + " at the start included), or when the spheres never meet or the"
                        + " overlap test steps past their impact, with one line on stderr.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "collide" (not null)
     * @param out where the CSV or help goes (not null)
     * @param err where the error line goes (not null)
     * @return the exit code: 0 on success, 2 on a bad command line or no impact
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                parsed -> runParsed(parsed, out, err));
    }

    /** The command proper, once the options are parsed and no help was asked for. */
    private static int runParsed(Options options, PrintStream out, PrintStream err) {
        float m1 = requiredMass(options, M1);
        float m2 = requiredMass(options, M2);
        Vector3f p1 = CollisionOptions.requiredVector(options, P1, COMMAND);
        Vector3f p2 = CollisionOptions.requiredVector(options, P2, COMMAND);
        Vector3f v1 = CollisionOptions.requiredVector(options, V1, COMMAND);
        Vector3f v2 = CollisionOptions.requiredVector(options, V2, COMMAND);
        float r1 = options.positiveFloat(R1);
        float r2 = options.positiveFloat(R2);
        float e = CollisionOptions.restitution(options, RESTITUTION, COMMAND);
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        Detection detection = CollisionOptions.detection(options, false, COMMAND);

        double[] meeting = meeting(p1, p2, v1, v2, r1 + r2);
        int steps = (int) Math.min(CollisionOptions.MAX_STEPS,
                Math.ceil(meeting[1] / step) + 1.0);
        if (meeting[0] / step > CollisionOptions.MAX_STEPS) {
            throw new UsageException(TPF + ": the spheres meet at t = " + (float) meeting[0]
                    + " s, more than " + CollisionOptions.MAX_STEPS + " steps of " + step
                    + " s away");
        }
        Recorder recorder = simulate(m1, m2, p1, p2, v1, v2, r1, r2, e, step, detection,
                steps);
        if (!recorder.done) {
            throw new UsageException(CollisionOptions.DETECTION + ": the overlap test"
                    + " missed the impact at t = " + (float) meeting[0] + " s: the spheres"
                    + " passed through each other between two steps of " + step + " s"
                    + " (tunnelling); the swept test finds it");
        }
        if (recorder.lostMomentum > LOST_MOMENTUM_FRACTION * recorder.exchangedMomentum) {
            err.println("warning: the float velocities after the impact lose "
                    + (float) recorder.lostMomentum + " kg*m/s of momentum, "
                    + (float) (100.0 * recorder.lostMomentum / recorder.exchangedMomentum)
                    + "% of the " + (float) recorder.exchangedMomentum + " kg*m/s the impulse"
                    + " exchanged: a velocity change j/m too small for the float velocity it is"
                    + " added to is rounded away (m1/m2 = "
                    + String.format(Locale.ROOT, "%.1e", m1 / (double) m2) + "); the"
                    + " momentum columns, summed in double, may not show it; carrying on");
        }
        out.println(HEADER);
        out.println(recorder.row);
        return Program.OK;
    }

    /**
     * Read a required mass, at least {@link Particle#MIN_MASS_KG} as {@code trajectory} and
     * {@code aim} require of {@code --mass}.
     */
    private static float requiredMass(Options options, String name) {
        if (!options.has(name)) {
            throw new UsageException(name + ": is required, a finite number >= "
                    + Particle.MIN_MASS_KG + " (see " + COMMAND + " " + Options.HELP + ")");
        }
        return options.floatAtLeast(name, Float.NaN, Particle.MIN_MASS_KG,
                "the smallest mass whose 1/m is a finite float");
    }

    /** Records the first resolved impact. */
    private static final class Recorder implements ContactListener {
        private final double[] before = new double[4];
        /** The bodies' velocities just before the impact: v1 then v2 (m/s). */
        private final double[] velocitiesBefore = new double[6];
        private final StringBuilder row = new StringBuilder();
        private boolean done;
        /** |m1·Δv1 + m2·Δv2| over the impact, summed in double (kg·m/s). */
        private double lostMomentum;
        /** The larger of |m1·Δv1| and |m2·Δv2|: the momentum the impulse moved (kg·m/s). */
        private double exchangedMomentum;

        @Override
        public boolean accept(Contact contact, World world) {
            if (!done) {
                totals(world, before);
                for (int i = 0; i < 2; ++i) {
                    Vector3f v = world.getBody(i).getVelocity();
                    velocitiesBefore[3 * i] = v.x;
                    velocitiesBefore[3 * i + 1] = v.y;
                    velocitiesBefore[3 * i + 2] = v.z;
                }
            }
            return true;
        }

        @Override
        public void resolved(Contact contact, World world) {
            if (done) {
                return;
            }
            done = true;
            double[] after = new double[4];
            totals(world, after);
            Vector3f v1 = world.getBody(0).getVelocity();
            Vector3f v2 = world.getBody(1).getVelocity();
            row.append((float) contact.getTimeSeconds()).append(',')
                    .append(v1.x).append(',').append(v1.y).append(',').append(v1.z).append(',')
                    .append(v2.x).append(',').append(v2.y).append(',').append(v2.z);
            for (int i = 0; i < 3; ++i) {
                row.append(',').append(before[i]);
            }
            for (int i = 0; i < 3; ++i) {
                row.append(',').append(after[i]);
            }
            row.append(',').append(before[3]).append(',').append(after[3]);
            measureLoss(world);
        }

        /** Compare each body's momentum change with the other's, which should cancel it. */
        private void measureLoss(World world) {
            double[] change = new double[6];
            for (int i = 0; i < 2; ++i) {
                Body body = world.getBody(i);
                Vector3f v = body.getVelocity();
                double m = body.getMass();
                change[3 * i] = m * (v.x - velocitiesBefore[3 * i]);
                change[3 * i + 1] = m * (v.y - velocitiesBefore[3 * i + 1]);
                change[3 * i + 2] = m * (v.z - velocitiesBefore[3 * i + 2]);
            }
            lostMomentum = Math.sqrt(square(change[0] + change[3]) + square(change[1] + change[4])
                    + square(change[2] + change[5]));
            exchangedMomentum = Math.max(
                    Math.sqrt(square(change[0]) + square(change[1]) + square(change[2])),
                    Math.sqrt(square(change[3]) + square(change[4]) + square(change[5])));
        }

        private static double square(double x) {
            return x * x;
        }

        /** Total momentum (3) and kinetic energy (1), in double. */
        private static void totals(World world, double[] store) {
            java.util.Arrays.fill(store, 0.0);
            for (int i = 0; i < world.countBodies(); ++i) {
                Body body = world.getBody(i);
                double m = body.getMass();
                Vector3f v = body.getVelocity();
                store[0] += m * v.x;
                store[1] += m * v.y;
                store[2] += m * v.z;
                store[3] += 0.5 * m * ((double) v.x * v.x + (double) v.y * v.y
                        + (double) v.z * v.z);
            }
        }
    }

    private static Recorder simulate(float m1, float m2, Vector3f p1, Vector3f p2, Vector3f v1,
            Vector3f v2, float r1, float r2, float e, float step, Detection detection,
            int steps) {
        World world = new World();
        ParticleIntegrator freeFlight = new ParticleIntegrator();
        world.addBody(freeFlight, p1, v1, m1, r1);
        world.addBody(freeFlight, p2, v2, m2, r2);
        world.addRule(new SphereRule(new ImpulseResponse(e, 0f, false), detection));
        Recorder recorder = new Recorder();
        world.addContactListener(recorder);
        for (int n = 0; n < steps && !recorder.done; ++n) {
            try {
                world.step(step);
            } catch (NonFiniteStepException nonFinite) {
                throw CommandSupport.blewUp(step, "at step " + (n + 1), Float.POSITIVE_INFINITY);
            }
        }
        return recorder;
    }

    /**
     * Decide from the straight paths whether the spheres meet.
     *
     * @return {first touch, last touch} (in seconds)
     * @throws UsageException if they overlap at the start or never meet
     */
    private static double[] meeting(Vector3f p1, Vector3f p2, Vector3f v1, Vector3f v2,
            float reach) {
        double px = (double) p1.x - p2.x;
        double py = (double) p1.y - p2.y;
        double pz = (double) p1.z - p2.z;
        double vx = (double) v1.x - v2.x;
        double vy = (double) v1.y - v2.y;
        double vz = (double) v1.z - v2.z;
        double distance = Math.sqrt(px * px + py * py + pz * pz);
        if (distance < reach) {
            throw new UsageException(P1 + ", " + P2 + ": the spheres overlap at the start:"
                    + " their centres are " + (float) distance + " m apart, less than r1 + r2 = "
                    + reach + " m; start them apart or touching");
        }
        double a = vx * vx + vy * vy + vz * vz;
        double b = 2.0 * (px * vx + py * vy + pz * vz);
        double c = distance * distance - (double) reach * reach;
        double discriminant = b * b - 4.0 * a * c;
        if (!(a > 0.0) || !(b < 0.0) || discriminant < 0.0) {
            double closest = a > 0.0 && b < 0.0 ? Math.sqrt(Math.max(0.0, c - b * b / (4.0 * a)
                    + (double) reach * reach)) : distance;
            throw new UsageException(V1 + ", " + V2 + ": the spheres never meet: their centres"
                    + " come no closer than " + (float) closest + " m, more than r1 + r2 = "
                    + reach + " m");
        }
        double root = Math.sqrt(discriminant);
        return new double[] {2.0 * c / (-b + root), (-b + root) / (2.0 * a)};
    }
}

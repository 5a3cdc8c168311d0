package particlelab.app;

import com.jme3.math.Vector3f;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import particlelab.physics.Gravity;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.HopCycle;
import particlelab.world.ImpulseResponse;
import particlelab.world.StepListener;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * {@code particle-lab bounce}: a ball dropped on the ground, stepped in a {@link World} with
 * the ground's contact rule, and one CSV row per impact:
 * {@code impact,t,impact_speed,rebound_speed,apex_after}.
 *
 * <p>Decisions the issue left open, also stated in the help text:
 * <ul>
 * <li>An impact is every resolved ground contact except those of a ball at rest: a contact
 * that leaves the ball with rebound 0 after one that did too. So a ball that settles gives a
 * last row with rebound 0 and then no more rows; a ball that hops on (no resting fix, and
 * no threshold at or above the slowest impact of the orbit its hops end on, a fixed point or
 * a cycle, {@link HopCycle}) keeps giving rows.</li>
 * <li>{@code rebound_speed} is the normal speed right after the impact's resolution; with the
 * resting fix on it is {@code e·(v − g·h)} rather than {@code e·v}, as in Cyclone.</li>
 * <li>The overlap test finds an impact at the end of the step it happened in: its t is that
 * step's end.</li>
 * <li>{@code apex_after} is the highest centre height at the end of a step after the impact and
 * before the next one (the stepped path is straight between steps, so no point is higher).</li>
 * </ul>
 */
public final class BounceCommand {

    /** The subcommand's name. */
    public static final String NAME = "bounce";
    /** The CSV header, exactly. */
    public static final String HEADER = "impact,t,impact_speed,rebound_speed,apex_after";
    /** The default duration (in seconds). */
    public static final float DEFAULT_DURATION_SECONDS = 10f;

    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String HEIGHT = "--height";
    private static final String RESTITUTION = "--restitution";
    private static final String THRESHOLD = "--threshold";
    private static final String RESTING_FIX = "--resting-fix";
    private static final String TPF = "--tpf";
    private static final String G = "--g";
    private static final String RADIUS = "--radius";
    private static final String DURATION = "--duration";

    private BounceCommand() {
    }

    /**
     * Declare this command's options (also the source of its help text).
     *
     * @return new, unparsed options (not null)
     */
    public static Options options() {
        return new Options(COMMAND, "Drop a ball (its centre) from height H0 onto the ground"
                + " plane y = 0, touching when y = R, and print one CSV row per impact: "
                + HEADER + ".")
                .value(HEIGHT, "H0", "drop height of the centre (m, > R). Required.")
                .value(RESTITUTION, "E", "restitution e (0 to 1). Required.")
                .value(THRESHOLD, "V", "restitution threshold (m/s, >= 0): an impact at or"
                        + " below it is perfectly inelastic (rebound 0). Default 0: none;"
                        + " Cyclone uses " + ImpulseResponse.CYCLONE_THRESHOLD + ", Box2D and"
                        + " Jolt " + ImpulseResponse.BOX2D_THRESHOLD + ".")
                .value(RESTING_FIX, "on|off", "Cyclone's resting-contact fix: remove from the"
                        + " rebound the velocity gravity added during the step. Default on.")
                .value(CollisionOptions.DETECTION, "overlap|swept",
                        CollisionOptions.DETECTION_HELP + " Default swept.")
                .value(TPF, "H", "time step h (s, > 0), a decimal or a fraction such as 1/60."
                        + " Default 1/60.")
                .value(G, "G", "magnitude of gravity g, pointing down (m/s^2, > 0). Default "
                        + Gravity.STANDARD_G + ".")
                .value(RADIUS, "R", "ball radius (m, >= 0). Default 0: a point.")
                .value(DURATION, "T", "simulate T seconds (> 0), T/h rounded to whole steps."
                        + " Default " + DEFAULT_DURATION_SECONDS + ".")
                .note("Columns: impact counts from 1; t is the time of impact (s); impact_speed"
                        + " and rebound_speed are the normal speeds just before and after it"
                        + " (m/s); apex_after is the highest centre height reached after it and"
                        + " before the next impact (m), empty for the last.")
                .note("The ideal ball: apexes e^(2n)*H0 above the touching height, impact"
                        + " speeds e^n*sqrt(2*g*(H0-R)), at rest after t0*(1+e)/(1-e),"
                        + " t0 = sqrt(2*(H0-R)/g). A stepped ball cannot show a bounce shorter"
                        + " than a step. Once the ball rests it gives no more rows and stays"
                        + " exactly still.")
                .note("Without the resting fix a ball with e > 0 never rests unless the"
                        + " threshold stops it, and a threshold is no sure cure: with the swept"
                        + " test the rest of an impact's step has no gravity, so the hops end on"
                        + " an orbit that repeats. Either hops of K whole steps each at the"
                        + " fixed point w* = K*g*h/(1+e) (K at most (1+e)/(1-e)), or a cycle of"
                        + " several hops mixing K values; which one depends on the drop. A"
                        + " threshold stops the ball at its first impact at or below it: on a"
                        + " fixed point only if it is at or above w*, on a cycle once it"
                        + " reaches the cycle's slowest impact. H0 = 4 with e = 0.8 and"
                        + " h = 1/60 settles on K = 4, w* = " + hopExample() + " m/s, above"
                        + " Cyclone's " + ImpulseResponse.CYCLONE_THRESHOLD + ", so that ball"
                        + " never rests; H0 = 4.25 with R = 0.25 and e = 0.9 ends on a cycle"
                        + " of 64 hops, K 4 to 9. The resting fix always stops it.")
                .note("Exit status: 0 on success; 2 on a bad command line, with one line on"
                        + " stderr.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after "bounce" (not null)
     * @param out where the CSV or help goes (not null)
     * @param err where the error line goes (not null)
     * @return the exit code: 0 on success, 2 on a bad command line
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err,
                parsed -> runParsed(parsed, out, err));
    }

    /** The help's worked example: w* of the 4-step hop, e = 0.8, default g and h, 5 digits. */
    private static String hopExample() {
        double speed = HopCycle.fixedPointSpeed(4, 0.8f, Gravity.STANDARD_G,
                CommandSupport.DEFAULT_STEP_SECONDS);
        return String.format(Locale.ROOT, "%.5f", speed);
    }

    /** The command proper, once the options are parsed and no help was asked for. */
    private static int runParsed(Options options, PrintStream out, PrintStream err) {
        float height = options.positiveFloat(HEIGHT);
        float e = CollisionOptions.restitution(options, RESTITUTION, COMMAND);
        float threshold = options.nonNegativeFloat(THRESHOLD, 0f);
        boolean restingFix = "on".equals(options.choice(RESTING_FIX, "on", "on", "off"));
        Detection detection = CollisionOptions.detection(options, false, COMMAND);
        float step = options.positiveFloat(TPF, CommandSupport.DEFAULT_STEP_SECONDS);
        float gravity = options.positiveFloat(G, Gravity.STANDARD_G);
        float radius = options.nonNegativeFloat(RADIUS, 0f);
        float duration = options.positiveFloat(DURATION, DEFAULT_DURATION_SECONDS);
        if (!(height > radius)) {
            throw new UsageException(HEIGHT + ": the ball must start above the ground,"
                    + " H0 > R = " + radius + " m, but was " + height);
        }
        int steps = CollisionOptions.stepsFor(DURATION, duration, step);
        List<Impact> impacts = simulate(height, e, threshold, restingFix, detection, step,
                gravity, radius, steps);
        print(impacts, out);
        return Program.OK;
    }

    /** One row. */
    static final class Impact {
        final float timeSeconds;
        final float impactSpeed;
        final float reboundSpeed;
        float apexAfter = Float.NaN;

        Impact(float timeSeconds, float impactSpeed, float reboundSpeed) {
            this.timeSeconds = timeSeconds;
            this.impactSpeed = impactSpeed;
            this.reboundSpeed = reboundSpeed;
        }
    }

    /** Records the impacts (epilogue) and the highest point after each (after the step). */
    private static final class Recorder implements ContactListener, StepListener {
        final List<Impact> impacts = new ArrayList<>();
        private boolean resting;
        private float apex = Float.NEGATIVE_INFINITY;

        @Override
        public void resolved(Contact contact, World world) {
            float rebound = contact.getBodyA().getVelocity().dot(contact.getNormal());
            if (resting && rebound == 0f) {
                return;
            }
            closeApex();
            impacts.add(new Impact((float) contact.getTimeSeconds(), contact.getApproachSpeed(),
                    rebound));
            resting = rebound == 0f;
        }

        @Override
        public void afterStep(World world, float stepSeconds) {
            if (!impacts.isEmpty()) {
                apex = Math.max(apex, world.getBody(0).getPosition().y);
            }
        }

        void closeApex() {
            if (!impacts.isEmpty()) {
                impacts.get(impacts.size() - 1).apexAfter = apex;
            }
            apex = Float.NEGATIVE_INFINITY;
        }
    }

    /**
     * Drop the ball and record its impacts.
     *
     * @return the impacts in time order; each but the last has its apex
     */
    static List<Impact> simulate(float height, float e, float threshold, boolean restingFix,
            Detection detection, float step, float gravity, float radius, int steps) {
        World world = new World();
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Gravity(new Vector3f(0f, -gravity, 0f)));
        Body ball = world.addBody(integrator, new Vector3f(0f, height, 0f), Vector3f.ZERO, 1f,
                radius);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e, threshold, restingFix),
                detection));
        Recorder recorder = new Recorder();
        world.addContactListener(recorder);
        world.addStepListener(recorder);
        for (int n = 1; n <= steps; ++n) {
            try {
                world.step(step);
            } catch (NonFiniteStepException nonFinite) {
                throw CommandSupport.blewUp(step, "at step " + n,
                        integrator.maxStableStep(ball.getParticle()));
            }
        }
        return recorder.impacts;
    }

    private static void print(List<Impact> impacts, PrintStream out) {
        out.println(HEADER);
        StringBuilder row = new StringBuilder();
        for (int i = 0; i < impacts.size(); ++i) {
            Impact impact = impacts.get(i);
            row.setLength(0);
            row.append(i + 1).append(',').append(impact.timeSeconds).append(',')
                    .append(impact.impactSpeed).append(',').append(impact.reboundSpeed)
                    .append(',');
            if (i + 1 < impacts.size()) {
                row.append(impact.apexAfter);
            }
            out.println(row);
        }
    }
}

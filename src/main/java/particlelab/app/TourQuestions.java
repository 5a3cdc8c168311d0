package particlelab.app;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import particlelab.aiming.Hitscan;
import particlelab.aiming.Landing;
import particlelab.aiming.ShotSimulator;
import particlelab.aiming.TargetImpact;
import particlelab.collision.ThinWall;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.RotationDemo;
import particlelab.lecture.TunnellingDemo;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SlideFormDrag;
import particlelab.physics.Thrust;
import particlelab.rigid.RotationIntegrator;
import particlelab.world.Detection;
import particlelab.world.TunnelShots;

/**
 * The tour's questions for the room (issue 34 §1), one per {@link LectureTour} stop, in the
 * stops' order, kept beside the tour rather than in it so the stops' slides and watch lines
 * stay one list. Each right answer is worked out from the stop's state with the code the
 * command-line tools use ({@code trajectory}/{@code aim}: {@link ShotSimulator};
 * {@code rotate}: {@link RotationIntegrator}; {@code tunnel}: {@link TunnelShots};
 * {@code hitscan}: {@link Hitscan}), never a copied constant. A stop without a question yet
 * has null here, and {@code tour --questions} says so.
 */
public final class TourQuestions {

    /**
     * How near the exact landing a stepped landing counts as "on" it (m). The lecture's step
     * lands {@code vx·h} short, 0.17 m at the pull's 10 m/s and 1/60 s: twenty times this.
     */
    public static final double ON_METRES = 0.01;
    /** How near 1 det R counts as "at 1": float round-off over 100 steps is about 1e-5. */
    public static final double DET_AT_ONE = 1e-3;
    /**
     * How much of the kinetic energy may change in an impact and still count as "kept": a
     * float32 impulse changes it by about 1e-6 of itself; e = 0.8 loses a third of it.
     */
    public static final double ENERGY_KEPT_FRACTION = 1e-3;
    /** When the uniform-motion question compares the sphere with the line (s). */
    public static final int UNIFORM_SECONDS = 2;
    /**
     * How near the line {@code P0 + V0·t} counts as "on" it (m): the float sums of 120 steps
     * stray about 1e-5 m from it.
     */
    public static final double ON_LINE_METRES = 1e-3;
    /** The steps after which the rotation question reads det R. */
    public static final int ROTATION_STEPS = 100;
    /** The overlap test's shots the tunnel rule fires (as {@code tunnel --shots}). */
    public static final int TUNNEL_SHOTS = 1000;
    /** The overlap lane's shots the scene must show before its share counts. */
    public static final int TUNNEL_SHOTS_SHOWN = 12;

    /** The pull demo's ball, as it labels it. */
    private static final String PULL_BALL = "ball";
    private static final String[] SHORT_ON_LONG = {"short", "on", "long"};
    /** The drag demo's spheres, in its order (its first three particles). */
    private static final String[] DRAG_SPHERES = {"gravity only", "linear drag",
        "quadratic drag"};
    /** The thrust demo's spheres, in its order. */
    private static final String[] THRUST_SPHERES = {"pull + drag", "pull + drag + thrust"};
    private static final String[] KEPT_LOST_GAINED = {"kept", "lost", "gained"};

    /** Per stop, in the tour's order: its question, or null. */
    private static final List<TourQuestion> QUESTIONS = Collections.unmodifiableList(
            Arrays.asList(
            null,
            energyQuestion(),
            null,
            energyQuestion(),
            null,
            null,
            new TourQuestion("After " + UNIFORM_SECONDS + " s of steps, is the sphere behind,"
                    + " on, or ahead of P0 + V0·t?", TourQuestions::uniformRule,
                    TourQuestions::uniformOutcome, "behind", "on", "ahead"),
            landingQuestion(),
            new TourQuestion("Which sphere lands nearest the launch?",
                    TourQuestions::nearestRule, TourQuestions::nearestOutcome, DRAG_SPHERES),
            null,
            new TourQuestion("Which sphere lands farther out?", TourQuestions::farthestRule,
                    TourQuestions::farthestOutcome, THRUST_SPHERES),
            null,
            new TourQuestion("After " + ROTATION_STEPS + " plain Euler steps, is det R above 1,"
                    + " at 1, or below?", TourQuestions::determinantRule,
                    TourQuestions::determinantOutcome, "above 1", "at 1", "below 1"),
            null,
            null,
            landingQuestion(),
            null,
            null,
            null,
            new TourQuestion("How many of the balls does the overlap test miss?",
                    TourQuestions::tunnelRule, TourQuestions::tunnelOutcome, "none",
                    "some", "all"),
            new TourQuestion("Does the stepped shot hit the disc the straight ray aims at?",
                    TourQuestions::hitscanRule, TourQuestions::hitscanOutcome, "yes, it hits",
                    "no, it drops below"),
            null));

    private TourQuestions() {
    }

    /**
     * Access a stop's question.
     *
     * @param stop the stop (from 0, less than the tour's stops)
     * @return the question, or null if the stop has none yet
     */
    public static TourQuestion forStop(int stop) {
        return QUESTIONS.get(stop);
    }

    /** @return the number of entries, one per tour stop */
    static int size() {
        return QUESTIONS.size();
    }

    /**
     * Sort a value against a reference: below, at (within the tolerance) or above it.
     *
     * @param value the value
     * @param reference what it is compared with
     * @param tolerance how near counts as "at" (&ge;0)
     * @return 0 below, 1 at, 2 above (NaN counts as below, never "at")
     */
    static int compare(double value, double reference, double tolerance) {
        if (Math.abs(value - reference) <= tolerance) {
            return 1;
        }
        return value > reference ? 2 : 0;
    }

    // ---------------------------------------------- the pull: where Euler lands ----

    private static TourQuestion landingQuestion() {
        return new TourQuestion("Euler lands short, on, or long of the exact landing?",
                TourQuestions::landingRule, TourQuestions::landingOutcome, SHORT_ON_LONG);
    }

    /** The launch velocity the pull's ball gets (m/s), as its launch control works it out. */
    private static Vector3f launchVelocity(DemoState demo) {
        double speed = demo.getParameters().getValue("speed");
        double radians = Math.toRadians(demo.getParameters().getValue("angle"));
        return new Vector3f((float) (speed * Math.cos(radians)),
                (float) (speed * Math.sin(radians)), 0f);
    }

    /**
     * The continuous landing of a level launch from the ground: {@code x = 2·vx·vy/g}.
     */
    private static double exactLandingX(Vector3f velocity, double g) {
        return 2.0 * velocity.x * velocity.y / g;
    }

    private static int landingRule(DemoState demo) {
        Vector3f velocity = launchVelocity(demo);
        float g = demo.getParameters().getValue("g");
        float h = demo.getParameters().getValue("h");
        // The aim command's simulator: the shared Euler step, the crossing interpolated.
        ShotSimulator simulator = new ShotSimulator(
                new ParticleIntegrator(gravity(g)),
                demo.getParameters().getValue("mass"), h, AimCommand.MAX_STEPS_PER_SHOT * h);
        Landing landing = new Landing();
        simulator.fire(velocity.x, velocity.y, landing);
        return compare(landing.getX(), exactLandingX(velocity, g), ON_METRES);
    }

    private static int landingOutcome(DemoState demo) {
        DemoParticle ball = null;
        List<DemoParticle> particles = demo.getParticles();
        for (int i = 0; i < particles.size(); ++i) {
            // The lecture's ball, not a comparison lane's sphere (lane=rk4 adds one).
            if (particles.get(i).getLabel().equals(PULL_BALL)) {
                ball = particles.get(i);
            }
        }
        if (ball == null || !ball.hasLanded()) {
            return TourQuestion.UNDECIDED;
        }
        Vector3f velocity = ball.copyLaunchVelocity(new Vector3f());
        return compare(ball.getLandingX(), exactLandingX(velocity,
                demo.getParameters().getValue("g")), ON_METRES);
    }

    // ------------------------------------ uniform motion: is the step exact here ----

    private static int uniformRule(DemoState demo) {
        Vector3f velocity = launchVelocity(demo);
        float h = demo.getParameters().getValue("h");
        int steps = Math.round(UNIFORM_SECONDS / h);
        // The step the trajectory command runs, with no force: P += h·V.
        Particle sphere = new Particle();
        sphere.velocity.set(velocity);
        ParticleIntegrator noForce = new ParticleIntegrator();
        for (int i = 0; i < steps; ++i) {
            noForce.step(sphere, h);
        }
        return aheadOfLine(sphere.position, velocity, (double) steps * h);
    }

    private static int uniformOutcome(DemoState demo) {
        double t = demo.getClock().getSimulatedSeconds();
        if (t < UNIFORM_SECONDS) {
            return TourQuestion.UNDECIDED;
        }
        DemoParticle sphere = demo.getParticles().get(0);
        Vector3f moved = sphere.copyLaunchPosition(new Vector3f()).negateLocal()
                .addLocal(sphere.getParticle().position);
        return aheadOfLine(moved, sphere.copyLaunchVelocity(new Vector3f()), t);
    }

    /**
     * Sort a displacement against {@code V·t} along V: behind, on or ahead.
     *
     * @return 0 behind, 1 on (within {@link #ON_LINE_METRES}), 2 ahead
     */
    private static int aheadOfLine(Vector3f moved, Vector3f velocity, double t) {
        double speed = velocity.length();
        double along = (moved.x * (double) velocity.x + moved.y * (double) velocity.y
                + moved.z * (double) velocity.z) / speed;
        return compare(along, speed * t, ON_LINE_METRES);
    }

    // ------------------------------------------- drag: which sphere lands nearest ----

    private static int nearestRule(DemoState demo) {
        float g = demo.getParameters().getValue("g");
        float c = demo.getParameters().getValue("c");
        // The law is a choice: 0 the physical -c|V|V, 1 the slide's -c|V|²V.
        Force quadratic = demo.getParameters().getValue("law") == 0f ? new QuadraticDrag(c)
                : new SlideFormDrag(c);
        ParticleIntegrator[] integrators = {
            new ParticleIntegrator(gravity(g)),
            new ParticleIntegrator(gravity(g),
                    new LinearDrag(demo.getParameters().getValue("b"))),
            new ParticleIntegrator(gravity(g), quadratic)};
        return extremeLanding(demo, integrators, -1);
    }

    /**
     * Fly one shot per integrator from the demo's launch, with the trajectory command's step,
     * and find the landing nearest (sign -1) or farthest (sign +1) out.
     *
     * @return the index of that integrator
     */
    private static int extremeLanding(DemoState demo, ParticleIntegrator[] integrators,
            int sign) {
        Vector3f velocity = launchVelocity(demo);
        float h = demo.getParameters().getValue("h");
        int extreme = 0;
        double extremeX = Double.NEGATIVE_INFINITY;
        Landing landing = new Landing();
        for (int i = 0; i < integrators.length; ++i) {
            new ShotSimulator(integrators[i], demo.getParameters().getValue("mass"), h,
                    AimCommand.MAX_STEPS_PER_SHOT * h).fire(velocity.x, velocity.y, landing);
            if (sign * landing.getX() > extremeX) {
                extremeX = sign * landing.getX();
                extreme = i;
            }
        }
        return extreme;
    }

    /**
     * Find the first spheres' landing nearest (sign -1) or farthest (sign +1) out, once all
     * have landed.
     *
     * @return the sphere's index, or {@link TourQuestion#UNDECIDED} while one still flies
     */
    private static int extremeLanded(DemoState demo, int count, int sign) {
        List<DemoParticle> particles = demo.getParticles();
        int extreme = 0;
        for (int i = 0; i < count; ++i) {
            if (!particles.get(i).hasLanded()) {
                return TourQuestion.UNDECIDED;
            }
            if (sign * particles.get(i).getLandingX()
                    > sign * particles.get(extreme).getLandingX()) {
                extreme = i;
            }
        }
        return extreme;
    }

    // ------------------------------------------ thrust: which sphere lands farther ----

    private static int farthestRule(DemoState demo) {
        float g = demo.getParameters().getValue("g");
        float b = demo.getParameters().getValue("b");
        ParticleIntegrator[] integrators = {
            new ParticleIntegrator(gravity(g), new LinearDrag(b)),
            new ParticleIntegrator(gravity(g), new LinearDrag(b),
                    new Thrust(demo.getParameters().getValue("k")))};
        return extremeLanding(demo, integrators, 1);
    }

    private static int farthestOutcome(DemoState demo) {
        return extremeLanded(demo, THRUST_SPHERES.length, 1);
    }

    private static Gravity gravity(float g) {
        return new Gravity(new Vector3f(0f, -g, 0f));
    }

    private static int nearestOutcome(DemoState demo) {
        return extremeLanded(demo, DRAG_SPHERES.length, -1);
    }

    // ---------------------------------------- collisions: is kinetic energy kept ----

    private static TourQuestion energyQuestion() {
        return new TourQuestion("In the impact, is kinetic energy kept, lost, or gained?",
                TourQuestions::energyRule, TourQuestions::energyOutcome, KEPT_LOST_GAINED);
    }

    /**
     * The impulse along n loses {@code ½·μ·(1 − e²)·v_n²}: nothing at e = 1, some for any
     * e &lt; 1 (the balls close in, so v_n is not 0), never a gain for 0 &le; e &le; 1.
     */
    private static int energyRule(DemoState demo) {
        float e = demo.getParameters().getValue("e");
        double lossPerHalfMuVn2 = 1.0 - (double) e * e;
        return lossPerHalfMuVn2 <= ENERGY_KEPT_FRACTION ? 0 : 1;
    }

    private static int energyOutcome(DemoState demo) {
        CollisionsDemo collisions = (CollisionsDemo) demo;
        if (collisions.countImpactSteps() == 0) {
            return TourQuestion.UNDECIDED;
        }
        double before = collisions.getImpactEnergyBefore();
        double change = collisions.getImpactEnergyAfter() - before;
        if (Math.abs(change) <= ENERGY_KEPT_FRACTION * before) {
            return 0;
        }
        return change < 0 ? 1 : 2;
    }

    // ------------------------------------------- rotation: det R after 100 steps ----

    private static int determinantRule(DemoState demo) {
        float h = demo.getParameters().getValue("h");
        Vector3f omega = RotationDemo.AXIS.mult(demo.getParameters().getValue("omega"));
        // The rotate command's integrator: R += h·[ω]×·R, as the plain box steps.
        RotationIntegrator plain = new RotationIntegrator(RotationDemo.METHODS[0],
                RotationIntegrator.Angular.EXPLICIT, false);
        Matrix3f r = new Matrix3f();
        for (int i = 0; i < ROTATION_STEPS; ++i) {
            plain.stepOrientation(r, omega, h);
        }
        return 2 - compare(r.determinant(), 1.0, DET_AT_ONE);
    }

    private static int determinantOutcome(DemoState demo) {
        RotationDemo rotation = (RotationDemo) demo;
        double steps = rotation.getElapsedSeconds(0) / demo.getClock().getStepSeconds();
        // Read once 100 steps have passed (the plain box starts over at det 3.375).
        if (steps < ROTATION_STEPS - 0.5) {
            return TourQuestion.UNDECIDED;
        }
        return 2 - compare(rotation.getOrientation(0).determinant(), 1.0, DET_AT_ONE);
    }

    // --------------------------------------- tunnelling: what the overlap test misses ----

    private static int tunnelRule(DemoState demo) {
        TunnellingDemo tunnelling = (TunnellingDemo) demo;
        // The tunnel command's shots: random phases against a wall of the demo's size.
        ThinWall wall = new ThinWall(Vector3f.UNIT_X, 0f, TunnellingDemo.THICKNESS);
        int hits = TunnelShots.fire(wall, tunnelling.getSpeed(), TunnellingDemo.RADIUS,
                demo.getParameters().getValue("h"), Detection.OVERLAP, TUNNEL_SHOTS,
                new Random(TunnellingDemo.SEED));
        return missShare(hits, TUNNEL_SHOTS);
    }

    private static int tunnelOutcome(DemoState demo) {
        TunnellingDemo tunnelling = (TunnellingDemo) demo;
        int shots = tunnelling.countShots(false);
        if (shots < TUNNEL_SHOTS_SHOWN) {
            return TourQuestion.UNDECIDED;
        }
        return missShare(tunnelling.countHits(false), shots);
    }

    /** @return 0 if every shot was seen, 2 if none was, 1 between */
    private static int missShare(int hits, int shots) {
        if (hits == shots) {
            return 0;
        }
        return hits == 0 ? 2 : 1;
    }

    // ---------------------------------------------- the cheat: does the ray's hit hold ----

    private static int hitscanRule(DemoState demo) {
        float h = demo.getParameters().getValue("h");
        // The speed is a choice among the demo's speeds: its value is the index.
        float speed = FastBulletsDemo.SPEEDS[(int) demo.getParameters().getValue("speed")];
        // The hitscan command's range: the stepped shot's crossing of the disc's plane.
        Hitscan range = new Hitscan(new ParticleIntegrator(new Gravity()), h,
                AimCommand.MAX_STEPS_PER_SHOT + 1);
        TargetImpact impact = new TargetImpact();
        range.fireAtDisc(speed, FastBulletsDemo.DISTANCE,
                FastBulletsDemo.TARGET_RADIUS, impact);
        return impact.isHit() ? 0 : 1;
    }

    private static int hitscanOutcome(DemoState demo) {
        FastBulletsDemo cheat = (FastBulletsDemo) demo;
        if (!cheat.isReached()) {
            return TourQuestion.UNDECIDED;
        }
        return cheat.isHit() ? 0 : 1;
    }
}

package particlelab.app;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import particlelab.aiming.FrameRateRun;
import particlelab.aiming.Hitscan;
import particlelab.aiming.IterativeAim;
import particlelab.aiming.Landing;
import particlelab.aiming.LaunchAngles;
import particlelab.aiming.LevelAim;
import particlelab.aiming.ShotSimulator;
import particlelab.aiming.TargetImpact;
import particlelab.collision.Plane;
import particlelab.collision.SphereTests;
import particlelab.collision.Surface;
import particlelab.collision.ThinWall;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.RateLanes;
import particlelab.lecture.AnyHeightDemo;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.ClipResponseDemo;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.FountainDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.HelloAimingDemo;
import particlelab.lecture.IterativeAimingDemo;
import particlelab.lecture.RotationDemo;
import particlelab.lecture.SpinThrowDemo;
import particlelab.lecture.SpringDemo;
import particlelab.lecture.TargetsDemo;
import particlelab.lecture.TennisRacketDemo;
import particlelab.lecture.TunnellingDemo;
import particlelab.lecture.WindDemo;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SimulationClock;
import particlelab.physics.SlideFormDrag;
import particlelab.physics.Thrust;
import particlelab.rigid.Inertia;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationIntegrator;
import particlelab.world.Clip;
import particlelab.world.ClipReader;
import particlelab.world.Detection;
import particlelab.world.Fountain;
import particlelab.world.TunnelShots;

/**
 * The tour's questions for the room (issue 34 §1), one per {@link LectureTour} stop, in the
 * stops' order, kept beside the tour rather than in it so the stops' slides and watch lines
 * stay one list. Each right answer is worked out from the stop's state with the code the
 * command-line tools use ({@code trajectory}/{@code aim}: {@link ShotSimulator};
 * {@code rotate}: {@link RotationIntegrator}; {@code tunnel}: {@link TunnelShots};
 * {@code hitscan}: {@link Hitscan}; the targets' first hit: the world's swept tests,
 * {@link SphereTests} and the surfaces), never a copied constant. A stop without a question
 * has null here, and {@code tour --questions} says so (every stop has one now).
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
    /** The rate lanes' monitors, in their order. */
    private static final String[] RATE_LANES = rateLaneNames();
    /** The drag demo's spheres, in its order (its first three particles). */
    private static final String[] DRAG_SPHERES = {"gravity only", "linear drag",
        "quadratic drag"};
    /** The thrust demo's spheres, in its order. */
    private static final String[] THRUST_SPHERES = {"pull + drag", "pull + drag + thrust"};
    private static final String[] KEPT_LOST_GAINED = {"kept", "lost", "gained"};
    /** The wind demo's balls, in its order. */
    private static final String[] WIND_BALLS = {"still air", "in the wind"};
    /**
     * How many times its starting energy the undamped spring's swing must reach to count as
     * growing: a stable step's modified energy strays from the true one by a factor of about
     * {@code 1 ± h·ω/2} (1.1 at the tour's h·ω = 0.2), an unstable one grows without bound.
     */
    public static final double SPRING_GROWN_FACTOR = 10;
    /** When the spring question calls a swing that has not grown bounded (s). */
    public static final int SPRING_SECONDS = 3;
    /** The iterate question's answers: how many shots the search flies, at most. */
    public static final int[] SEARCH_SHOTS_AT_MOST = {4, 9};
    /** The bounce question's answers: by when the ball comes to rest, if it does (s). */
    public static final int[] REST_SECONDS_BY = {10, 30};
    /** When the throw question compares the stepped angle with the formula's (s). */
    public static final int SPIN_SECONDS = 1;
    /**
     * How near the formula's angle the stepped angle counts as "as far" (rad): float
     * round-off over 60 turns of 0.17 rad is about 1e-5 rad; the step's own gap
     * {@code ½·(τ/I)·h·t} is 0.019 rad after 1 s at h = 1/60 s with the key's torque.
     */
    public static final double SAME_ANGLE_RADIANS = 1e-3;
    /**
     * How near the two lanes' energies after the impact count as "the same", as a fraction of
     * the physics lane's: float sums of a few squares stray by about 1e-7 of it.
     */
    public static final double SAME_ENERGY_FRACTION = 1e-3;
    /** When the fountain question counts the particles in flight (s). */
    public static final int FOUNTAIN_SECONDS = 10;
    /** How long the racket question waits for a first flip (s). */
    public static final int FLIP_SECONDS = 20;
    /** How near the two aims' misses count as "the same" (m). */
    public static final double SAME_MISS_METRES = ON_METRES;
    /** The targets question's answers: each target, then a surface first. */
    private static final String[] FIRST_HITS = {"target 1", "target 2", "target 3",
        "none: a surface first"};
    /** How long the targets rule follows the shot (s): it is down within two. */
    public static final int TARGETS_SECONDS = 10;

    /** Per stop, in the tour's order: its question, or null. */
    private static final List<TourQuestion> QUESTIONS = Collections.unmodifiableList(
            Arrays.asList(
            new TourQuestion("Which target does the shot hit before anything else?",
                    TourQuestions::firstHitRule, TourQuestions::firstHitOutcome, FIRST_HITS),
            energyQuestion(),
            new TourQuestion("With this e and threshold, when does the ball come to rest?",
                    TourQuestions::restRule, TourQuestions::restOutcome,
                    "within " + REST_SECONDS_BY[0] + " s",
                    REST_SECONDS_BY[0] + " to " + REST_SECONDS_BY[1] + " s",
                    "not within " + REST_SECONDS_BY[1] + " s"),
            energyQuestion(),
            new TourQuestion("Which lane's pair leaves the impact with more kinetic energy?",
                    TourQuestions::clipRule, TourQuestions::clipOutcome, "the physics lane",
                    "the clip lane", "the same"),
            new TourQuestion("In the paddle's hits, is the balls' kinetic energy kept, lost,"
                    + " or gained?", TourQuestions::paddleRule, TourQuestions::paddleOutcome,
                    KEPT_LOST_GAINED),
            new TourQuestion("After " + UNIFORM_SECONDS + " s of steps, is the sphere behind,"
                    + " on, or ahead of P0 + V0·t?", TourQuestions::uniformRule,
                    TourQuestions::uniformOutcome, "behind", "on", "ahead"),
            landingQuestion(),
            new TourQuestion("Which sphere lands nearest the launch?",
                    TourQuestions::nearestRule, TourQuestions::nearestOutcome, DRAG_SPHERES),
            new TourQuestion("Which ball lands farther out?", TourQuestions::windRule,
                    TourQuestions::windOutcome, WIND_BALLS),
            new TourQuestion("Which sphere lands farther out?", TourQuestions::farthestRule,
                    TourQuestions::farthestOutcome, THRUST_SPHERES),
            new TourQuestion("At this step, does the undamped spring's swing stay bounded or"
                    + " grow?", TourQuestions::springRule, TourQuestions::springOutcome,
                    "stays bounded", "grows without bound"),
            new TourQuestion("After " + ROTATION_STEPS + " plain Euler steps, is det R above 1,"
                    + " at 1, or below?", TourQuestions::determinantRule,
                    TourQuestions::determinantOutcome, "above 1", "at 1", "below 1"),
            new TourQuestion("After " + SPIN_SECONDS + " s, has the stepped box turned less,"
                    + " as far, or farther than the formula's θ?", TourQuestions::spinRule,
                    TourQuestions::spinOutcome, "less", "as far", "farther"),
            new TourQuestion("Spun near its middle axis, does the racket flip within "
                    + FLIP_SECONDS + " s?", TourQuestions::flipRule, TourQuestions::flipOutcome,
                    "yes, it flips", "no, it spins steadily"),
            landingQuestion(),
            new TourQuestion("Which monitor's lane lands farthest out?",
                    TourQuestions::rateRule, TourQuestions::rateOutcome, RATE_LANES),
            new TourQuestion("Which arc reaches the target's distance first?",
                    TourQuestions::arrivalRule, TourQuestions::arrivalOutcome, "direct",
                    "lob"),
            new TourQuestion("Which aim lands nearer the target?", TourQuestions::aimingRule,
                    TourQuestions::aimingOutcome, "the lecture's", "the discrete correction",
                    "both the same"),
            new TourQuestion("After " + FOUNTAIN_SECONDS + " s, how many of the pool's"
                    + " particles are in flight?", TourQuestions::fountainRule,
                    TourQuestions::fountainOutcome, "all of them", "half or more",
                    "fewer than half"),
            new TourQuestion("How many of the balls does the overlap test miss?",
                    TourQuestions::tunnelRule, TourQuestions::tunnelOutcome, "none",
                    "some", "all"),
            new TourQuestion("Does the stepped shot hit the disc the straight ray aims at?",
                    TourQuestions::hitscanRule, TourQuestions::hitscanOutcome, "yes, it hits",
                    "no, it drops below"),
            new TourQuestion("How many shots does the search fly to land within "
                    + IterativeAimingDemo.TOLERANCE_METRES + " m?", TourQuestions::searchRule,
                    TourQuestions::searchOutcome, "at most " + SEARCH_SHOTS_AT_MOST[0],
                    (SEARCH_SHOTS_AT_MOST[0] + 1) + " to " + SEARCH_SHOTS_AT_MOST[1],
                    (SEARCH_SHOTS_AT_MOST[1] + 1) + " or more")));

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

    // --------------------------------------- targets: what the shot hits first ----

    /**
     * The shot stepped by the shared Euler step from the gun at the stop's aim, each step's
     * segment swept against the three targets and the surfaces the prologue accepts (the
     * ground, the walls, the ceiling, the pane only when solid: the gun's platform and the
     * ghost pane are ignored), as the world's swept rules test it: the earliest touch wins.
     */
    private static int firstHitRule(DemoState demo) {
        float h = demo.getParameters().getValue("h");
        boolean paneSolid = demo.getParameters().getValue("pane") == 1f;
        List<Surface> surfaces = new java.util.ArrayList<>(List.of(Plane.ground(),
                new Plane(new Vector3f(-1f, 0f, 0f), -TargetsDemo.WALL_X),
                new Plane(Vector3f.UNIT_X, TargetsDemo.X_MIN),
                new Plane(new Vector3f(0f, -1f, 0f), -TargetsDemo.Y_MAX)));
        if (paneSolid) {
            surfaces.add(new ThinWall(Vector3f.UNIT_X, TargetsDemo.PANE_X,
                    TargetsDemo.PANE_THICKNESS));
        }
        Vector3f[] centres = new Vector3f[TargetsDemo.TARGETS];
        for (int i = 0; i < centres.length; ++i) {
            centres[i] = TargetsDemo.copyTargetCentre(i, new Vector3f());
        }
        Particle shot = new Particle(new Vector3f(0f, TargetsDemo.GUN_Y, 0f),
                TargetsDemo.launchVelocity(demo.getParameters().getValue("angle"),
                        new Vector3f()), 1f);
        ParticleIntegrator falling = new ParticleIntegrator(new Gravity());
        Vector3f start = new Vector3f();
        Vector3f normal = new Vector3f();
        int steps = Math.round(TARGETS_SECONDS / h);
        for (int n = 0; n < steps; ++n) {
            start.set(shot.position);
            falling.step(shot, h);
            int first = TourQuestion.UNDECIDED;
            double earliest = Double.POSITIVE_INFINITY;
            for (int i = 0; i < centres.length; ++i) {
                double u = SphereTests.sweep(start, shot.position, centres[i], centres[i],
                        TargetsDemo.SHOT_RADIUS + TargetsDemo.TARGET_RADIUS);
                if (u != Surface.NO_HIT && u < earliest) {
                    earliest = u;
                    first = i;
                }
            }
            for (int i = 0; i < surfaces.size(); ++i) {
                double u = surfaces.get(i).sweep(start, shot.position,
                        TargetsDemo.SHOT_RADIUS, normal);
                if (u != Surface.NO_HIT && u < earliest) {
                    earliest = u;
                    first = TargetsDemo.TARGETS;
                }
            }
            if (first != TourQuestion.UNDECIDED) {
                return first;
            }
        }
        return TargetsDemo.TARGETS;
    }

    private static int firstHitOutcome(DemoState demo) {
        int first = ((TargetsDemo) demo).getFirstContact();
        return first < 0 ? TourQuestion.UNDECIDED : first;
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

    // ------------------------- the lecture's loop at each monitor's rate: farthest ----

    /** @return "30 Hz", "60 Hz" ... in the lanes' order */
    private static String[] rateLaneNames() {
        String[] names = new String[RateLanes.RATES_HZ.length];
        for (int i = 0; i < names.length; ++i) {
            names[i] = (int) RateLanes.RATES_HZ[i] + " Hz";
        }
        return names;
    }

    /**
     * Each monitor's raw-tpf run of the pull's launch, flown by {@link FrameRateRun} (the code
     * {@code trajectory --tpf 1/f} is checked against byte for byte): the farthest landing.
     */
    private static int rateRule(DemoState demo) {
        Particle launch = new Particle(new Vector3f(), launchVelocity(demo),
                demo.getParameters().getValue("mass"));
        FrameRateRun run = new FrameRateRun(new ParticleIntegrator(
                gravity(demo.getParameters().getValue("g"))));
        int farthest = TourQuestion.UNDECIDED;
        double farthestX = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
            run.start(launch, RateLanes.RATES_HZ[i], SimulationClock.Mode.RAW_TPF,
                    demo.getParameters().getValue("h"));
            if (run.flyToLanding() && run.getLanding().getX() > farthestX) {
                farthestX = run.getLanding().getX();
                farthest = i;
            }
        }
        return farthest;
    }

    /** The lanes' landings in the scene, once every lane has landed. */
    private static int rateOutcome(DemoState demo) {
        RateLanes rates = ((GravitationalPullDemo) demo).getRates();
        int farthest = TourQuestion.UNDECIDED;
        for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
            FrameRateRun run = rates.getRun(i);
            if (run == null || !rates.isOn() || !run.hasLanded()) {
                return TourQuestion.UNDECIDED;
            }
            if (farthest == TourQuestion.UNDECIDED || run.getLanding().getX()
                    > rates.getRun(farthest).getLanding().getX()) {
                farthest = i;
            }
        }
        return farthest;
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

    // --------------------------------- clip: which lane leaves more kinetic energy ----

    /**
     * The physics lane's level shot hits the resting target head-on at the rocket's speed v:
     * the impulse leaves {@code ½·m_r·v² − ½·μ·(1 − e²)·v²}, {@code μ = m_r·m_t/(m_r + m_t)}.
     * The clip lane's bodies leave with the slopes of their tracks' first segments, read
     * from the clip file the demo plays, whatever the shot.
     */
    private static int clipRule(DemoState demo) {
        DemoParameters parameters = demo.getParameters();
        double v = parameters.getValue("speed");
        double e = parameters.getValue("e");
        double rocketKg = parameters.getValue("m_rocket");
        double targetKg = parameters.getValue("m_target");
        double mu = rocketKg * targetKg / (rocketKg + targetKg);
        double physics = 0.5 * rocketKg * v * v - 0.5 * mu * (1.0 - e * e) * v * v;
        DemoParameter choice = parameters.get(parameters.indexOf("clip"));
        Clip clip = ClipReader.readResource("clips/"
                + choice.getChoice(Math.round(parameters.getValue("clip"))) + ".clip");
        Vector3f velocity = new Vector3f();
        // The clip file's tracks are named for the bodies they move.
        double clipEnergy = 0.5 * rocketKg * clip.copyStartVelocity(clip.indexOf("rocket"),
                velocity).lengthSquared() + 0.5 * targetKg * clip.copyStartVelocity(
                clip.indexOf("target"), velocity).lengthSquared();
        return moreEnergy(physics, clipEnergy);
    }

    private static int clipOutcome(DemoState demo) {
        ClipResponseDemo clip = (ClipResponseDemo) demo;
        if (!clip.hasHit(ClipResponseDemo.PHYSICS_LANE)
                || !clip.hasHit(ClipResponseDemo.CLIP_LANE)) {
            return TourQuestion.UNDECIDED;
        }
        return moreEnergy(clip.energyAfter(ClipResponseDemo.PHYSICS_LANE),
                clip.energyAfter(ClipResponseDemo.CLIP_LANE));
    }

    /** @return 0 if the physics lane keeps more, 1 if the clip does, 2 if the same */
    private static int moreEnergy(double physics, double clip) {
        if (Math.abs(physics - clip) <= SAME_ENERGY_FRACTION * physics) {
            return 2;
        }
        return physics > clip ? 0 : 1;
    }

    // ------------------------------------- paddle: the script's work on the balls ----

    /**
     * The paddle has infinite mass and a scripted speed u: a ball at rest it hits leaves at
     * {@code (1+e)·u_n} along the normal, so the balls, at rest with no energy before, gain
     * {@code ½·m·((1+e)·u_n)²} each whatever e is, unless the paddle does not move.
     */
    private static int paddleRule(DemoState demo) {
        float e = demo.getParameters().getValue("e");
        double leaving = (1.0 + e) * CollisionsDemo.PADDLE_SPEED;
        return leaving > 0.0 ? 2 : 0;
    }

    private static int paddleOutcome(DemoState demo) {
        CollisionsDemo collisions = (CollisionsDemo) demo;
        if (collisions.paddleImpulseLength() == 0f) {
            return TourQuestion.UNDECIDED;
        }
        // The balls start at rest: any energy now is what the hits gave them.
        return collisions.kineticEnergy() > 0f ? 2 : 0;
    }

    // --------------------------------------------- fountain: how many in flight ----

    /** The fountain's own simulation (seeded, as the demo's), stepped without a window. */
    private static int fountainRule(DemoState demo) {
        int particles = demo.getRun().countSimulatedParticles();
        return inFlightShare(liveAfter(demo.getParameters().getValue("h"), particles),
                particles);
    }

    /**
     * Step a fountain of the given pool for {@link #FOUNTAIN_SECONDS}.
     *
     * @param h the step (s)
     * @param particles the pool's size
     * @return the particles in flight then
     */
    static int liveAfter(float h, int particles) {
        Fountain fountain = new Fountain(particles);
        int steps = Math.round(FOUNTAIN_SECONDS / h);
        for (int n = 0; n < steps; ++n) {
            fountain.step(h);
        }
        return fountain.countLive();
    }

    private static int fountainOutcome(DemoState demo) {
        if (demo.getClock().getSimulatedSeconds() < FOUNTAIN_SECONDS) {
            return TourQuestion.UNDECIDED;
        }
        Fountain fountain = ((FountainDemo) demo).getFountain();
        return inFlightShare(fountain.countLive(), fountain.getCapacity());
    }

    /** @return 0 all in flight, 1 half or more, 2 fewer than half */
    private static int inFlightShare(int live, int capacity) {
        if (live == capacity) {
            return 0;
        }
        return 2 * live >= capacity ? 1 : 2;
    }

    // ------------------------------------- bounce: does the threshold stop the ball ----

    /**
     * The bounce command's drop ({@code bounce --h0 ... --e ... --threshold ...}) with the
     * demo's ball, e, threshold, resting fix, detection and step: when its last impact left
     * it at rest.
     */
    private static int restRule(DemoState demo) {
        BounceDemo bounce = (BounceDemo) demo;
        float h = demo.getParameters().getValue("h");
        int steps = Math.round(REST_SECONDS_BY[REST_SECONDS_BY.length - 1] / h);
        List<BounceCommand.Impact> impacts = BounceCommand.simulate(
                BounceDemo.DROP_HEIGHT + BounceDemo.RADIUS, bounce.getRestitution(),
                bounce.getThresholdSpeed(), bounce.isRestingFix(), bounce.getDetection(), h,
                Gravity.STANDARD_G, BounceDemo.RADIUS, steps);
        BounceCommand.Impact last = impacts.isEmpty() ? null : impacts.get(impacts.size() - 1);
        if (last == null || last.reboundSpeed != 0f) {
            return REST_SECONDS_BY.length;
        }
        return restBin(last.timeSeconds);
    }

    private static int restOutcome(DemoState demo) {
        double rest = ((BounceDemo) demo).getRestSeconds();
        if (!Double.isNaN(rest)) {
            return restBin(rest);
        }
        return demo.getClock().getSimulatedSeconds() > REST_SECONDS_BY[REST_SECONDS_BY.length
                - 1] ? REST_SECONDS_BY.length : TourQuestion.UNDECIDED;
    }

    /** @return the answer a rest time falls in */
    private static int restBin(double seconds) {
        for (int i = 0; i < REST_SECONDS_BY.length; ++i) {
            if (seconds <= REST_SECONDS_BY[i]) {
                return i;
            }
        }
        return REST_SECONDS_BY.length;
    }

    // ------------------------------------- throw: the stepped angle against θ(t) ----

    /**
     * The rotation step the rotate command runs ({@code ω += h·τ/I}, then R turned by the
     * new ω) on the demo's box with its torque, for {@link #SPIN_SECONDS}; the angle about z
     * unwrapped step by step from R, as the demo measures it.
     */
    private static int spinRule(DemoState demo) {
        SpinThrowDemo spin = (SpinThrowDemo) demo;
        float h = demo.getParameters().getValue("h");
        RigidBody box = new RigidBody(SpinThrowDemo.MASS_KG, Inertia.box(SpinThrowDemo.MASS_KG,
                SpinThrowDemo.SIDES.x, SpinThrowDemo.SIDES.y, SpinThrowDemo.SIDES.z));
        box.angularVelocity.set(0f, 0f, SpinThrowDemo.SPIN);
        box.torque.set(0f, 0f, spin.getTorque());
        RotationIntegrator rotation = new RotationIntegrator(
                RotationIntegrator.Orientation.EXACT, RotationIntegrator.Angular.EXPLICIT, true);
        int steps = Math.round(SPIN_SECONDS / h);
        double angle = 0.0;
        double lastAtan = 0.0;
        for (int n = 0; n < steps; ++n) {
            rotation.step(box, h);
            double atan = Math.atan2(box.orientation.get(1, 0), box.orientation.get(0, 0));
            double turn = atan - lastAtan;
            angle += turn - 2.0 * Math.PI * Math.rint(turn / (2.0 * Math.PI));
            lastAtan = atan;
        }
        return compare(angle, spin.formulaAngle((double) steps * h), SAME_ANGLE_RADIANS);
    }

    private static int spinOutcome(DemoState demo) {
        SpinThrowDemo spin = (SpinThrowDemo) demo;
        double t = spin.getSpinSeconds();
        if (t < SPIN_SECONDS - 1e-6) {
            return TourQuestion.UNDECIDED;
        }
        return compare(spin.getMeasuredAngle(), spin.formulaAngle(t), SAME_ANGLE_RADIANS);
    }

    // ---------------------------------------- racket: which method flips first ----

    /**
     * The rotate command's spin ({@code rotate --inertia 1,2,3 --omega 0.1,4,0.1 --angular
     * ...}) with the demo's step and gyroscopic term, each method's body stepped until its
     * body-frame ωy changes sign, as the demo counts a flip: the middle axis is unstable, so
     * with the gyroscopic term it flips (Dzhanibekov), without it ω stays and it never does.
     */
    private static int flipRule(DemoState demo) {
        float h = demo.getParameters().getValue("h");
        boolean gyroscopic = demo.getParameters().getValue("gyro") == 1f;
        // Either method's body flipping shows it; both start from the same spin.
        return firstFlipStep(0, gyroscopic, h) < Integer.MAX_VALUE
                || firstFlipStep(1, gyroscopic, h) < Integer.MAX_VALUE ? 0 : 1;
    }

    private static int flipOutcome(DemoState demo) {
        TennisRacketDemo racket = (TennisRacketDemo) demo;
        if (racket.countFlips(0) > 0 || racket.countFlips(1) > 0) {
            return 0;
        }
        return demo.getClock().getSimulatedSeconds() > FLIP_SECONDS ? 1
                : TourQuestion.UNDECIDED;
    }

    /**
     * Step one method's racket until its body-frame ωy changes sign.
     *
     * @param method 0 for explicit Euler, 1 for implicit midpoint
     * @param gyroscopic whether the gyroscopic term is on
     * @param h the step (s)
     * @return the step of the first flip (from 1), or {@link Integer#MAX_VALUE} if none
     *     within {@link #FLIP_SECONDS}
     */
    static int firstFlipStep(int method, boolean gyroscopic, float h) {
        RigidBody body = new RigidBody(1f, TennisRacketDemo.INERTIA);
        body.setAngularVelocity(TennisRacketDemo.BODY_SPIN);
        RotationIntegrator integrator = new RotationIntegrator(
                RotationIntegrator.Orientation.EXACT, TennisRacketDemo.METHODS[method],
                gyroscopic);
        boolean positive = TennisRacketDemo.BODY_SPIN.y > 0f;
        Vector3f bodyOmega = new Vector3f();
        int maxSteps = Math.round(FLIP_SECONDS / h);
        for (int n = 1; n <= maxSteps; ++n) {
            integrator.step(body, h);
            if ((body.bodyAngularVelocity(bodyOmega).y > 0f) != positive) {
                return n;
            }
        }
        return Integer.MAX_VALUE;
    }

    // ----------------------------------------------- wind: which ball lands farther ----

    private static int windRule(DemoState demo) {
        float h = demo.getParameters().getValue("h");
        Vector3f wind = new Vector3f(demo.getParameters().getValue("w"), 0f, 0f);
        ParticleIntegrator[] integrators = {
            new ParticleIntegrator(new Gravity()),
            new ParticleIntegrator(new Gravity(), new WindDemo.Wind(wind, WindDemo.WIND_B))};
        // The trajectory command's stepped flight of each ball, 1 kg as the demo's.
        Landing landing = new Landing();
        double[] landingX = new double[integrators.length];
        for (int i = 0; i < integrators.length; ++i) {
            new ShotSimulator(integrators[i], CommandSupport.DEFAULT_MASS_KG, h,
                    AimCommand.MAX_STEPS_PER_SHOT * h).fire(WindDemo.LAUNCH_VELOCITY.x,
                    WindDemo.LAUNCH_VELOCITY.y, landing);
            landingX[i] = landing.getX();
        }
        return landingX[1] > landingX[0] ? 1 : 0;
    }

    private static int windOutcome(DemoState demo) {
        return extremeLanded(demo, WIND_BALLS.length, 1);
    }

    // ------------------------------------------- spring: is the step stable there ----

    /**
     * The shared step on {@code F = −k·x} is stable while {@code h < 2/ω}, the limit the
     * demo's HUD shows ({@link ParticleIntegrator#stableStepLimit}).
     */
    private static int springRule(DemoState demo) {
        double omegaSquared = demo.getParameters().getValue("k") / (double) SpringDemo.MASS_KG;
        double limit = ParticleIntegrator.stableStepLimit(0.0, omegaSquared);
        return demo.getParameters().getValue("h") < limit ? 0 : 1;
    }

    private static int springOutcome(DemoState demo) {
        Particle mass = demo.getParticles().get(0).getParticle();
        double omegaSquared = demo.getParameters().getValue("k") / (double) SpringDemo.MASS_KG;
        // The spring's rest height under gravity, and where the mass started from rest.
        double rest = SpringDemo.ANCHOR_Y - Gravity.STANDARD_G / omegaSquared;
        double start = SpringDemo.ANCHOR_Y - SpringDemo.PULL_METRES - rest;
        double offset = mass.position.y - rest;
        double energy = 0.5 * mass.velocity.y * mass.velocity.y
                + 0.5 * omegaSquared * offset * offset;
        if (!(energy <= SPRING_GROWN_FACTOR * 0.5 * omegaSquared * start * start)) {
            return 1;
        }
        return demo.getClock().getSimulatedSeconds() >= SPRING_SECONDS ? 0
                : TourQuestion.UNDECIDED;
    }

    // ------------------------------------------ height: which arc arrives first ----

    /**
     * Both arcs keep the launch's {@code vx = v·cos θ}, so the flatter one, at the lower of
     * the two angles the demo solves for ({@link LaunchAngles}), crosses the distance first.
     */
    private static int arrivalRule(DemoState demo) {
        AnyHeightDemo height = (AnyHeightDemo) demo;
        LaunchAngles angles = LaunchAngles.solve(AnyHeightDemo.LAUNCH_SPEED,
                height.getTargetDistance(), height.getTargetHeight(), Gravity.STANDARD_G);
        double low = height.getTargetDistance()
                / (AnyHeightDemo.LAUNCH_SPEED * Math.cos(angles.getLowRadians()));
        double high = height.getTargetDistance()
                / (AnyHeightDemo.LAUNCH_SPEED * Math.cos(angles.getHighRadians()));
        return high < low ? 1 : 0;
    }

    private static int arrivalOutcome(DemoState demo) {
        AnyHeightDemo height = (AnyHeightDemo) demo;
        if (!height.hasArrived(false) || !height.hasArrived(true)) {
            return TourQuestion.UNDECIDED;
        }
        return height.getArrivalSeconds(true) < height.getArrivalSeconds(false) ? 1 : 0;
    }

    // ------------------------------------ HelloAiming: which aim lands nearer ----

    /** The aim command's two formulas, each shot flown with its stepped flight. */
    private static int aimingRule(DemoState demo) {
        float h = demo.getParameters().getValue("h");
        float g = demo.getParameters().getValue("g");
        float vx = demo.getParameters().getValue("vx");
        double distance = HelloAimingDemo.TARGET_DISTANCE;
        ShotSimulator simulator = new ShotSimulator(new ParticleIntegrator(gravity(g)),
                CommandSupport.DEFAULT_MASS_KG, h, AimCommand.MAX_STEPS_PER_SHOT * h);
        Landing landing = new Landing();
        simulator.fire(vx, (float) LevelAim.lectureVy(g, distance, vx), landing);
        double lectureMiss = Math.abs(landing.getX() - distance);
        simulator.fire(vx, (float) LevelAim.discreteVy(g, distance, vx, h), landing);
        return nearer(lectureMiss, Math.abs(landing.getX() - distance));
    }

    private static int aimingOutcome(DemoState demo) {
        HelloAimingDemo aiming = (HelloAimingDemo) demo;
        int shot = aiming.getLandedShotNumber(HelloAimingDemo.Aim.LECTURE);
        if (shot == 0 || aiming.getLandedShotNumber(HelloAimingDemo.Aim.DISCRETE) != shot) {
            return TourQuestion.UNDECIDED;
        }
        double distance = HelloAimingDemo.TARGET_DISTANCE;
        return nearer(Math.abs(aiming.getLastLandingX(HelloAimingDemo.Aim.LECTURE) - distance),
                Math.abs(aiming.getLastLandingX(HelloAimingDemo.Aim.DISCRETE) - distance));
    }

    /** @return 0 if the first miss is smaller, 1 if the second, 2 if they are the same */
    private static int nearer(double firstMiss, double secondMiss) {
        if (Math.abs(firstMiss - secondMiss) <= SAME_MISS_METRES) {
            return 2;
        }
        return firstMiss < secondMiss ? 0 : 1;
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

    // ------------------------------------------- iterate: how many shots it takes ----

    /**
     * The aim command's search ({@code aim --method iterative --strategy ...}) with the demo's
     * strategy, seed, drag, tolerance and predictor's step: its count of shots.
     */
    private static int searchRule(DemoState demo) {
        IterativeAimingDemo iterate = (IterativeAimingDemo) demo;
        float h = demo.getParameters().getValue("h");
        boolean linear = iterate.getDrag() == IterativeAimingDemo.Drag.LINEAR;
        ParticleIntegrator integrator = CommandSupport.integrator(
                new Vector3f(0f, -Gravity.STANDARD_G, 0f),
                linear ? IterativeAimingDemo.LINEAR_DRAG : 0f,
                linear ? 0f : IterativeAimingDemo.QUADRATIC_DRAG, 0f);
        float predictStep = iterate.isMismatch()
                ? IterativeAimingDemo.PREDICT_STEP_MS / 1000f : h;
        ShotSimulator simulator = new ShotSimulator(integrator, IterativeAimingDemo.MASS_KG,
                predictStep, AimCommand.MAX_STEPS_PER_SHOT * predictStep);
        int shots = new IterativeAim(simulator, Gravity.STANDARD_G,
                IterativeAimingDemo.TOLERANCE_METRES, IterativeAimingDemo.MAX_SHOTS,
                iterate.getStrategy(), iterate.getSeed()).aim(
                IterativeAimingDemo.TARGET_DISTANCE, IterativeAimingDemo.HORIZONTAL_SPEED)
                .getShots();
        return searchBin(shots);
    }

    private static int searchOutcome(DemoState demo) {
        IterativeAimingDemo iterate = (IterativeAimingDemo) demo;
        return iterate.isRoundOver() ? searchBin(iterate.countLanded())
                : TourQuestion.UNDECIDED;
    }

    /** @return the answer a count of shots falls in */
    private static int searchBin(int shots) {
        for (int i = 0; i < SEARCH_SHOTS_AT_MOST.length; ++i) {
            if (shots <= SEARCH_SHOTS_AT_MOST[i]) {
                return i;
            }
        }
        return SEARCH_SHOTS_AT_MOST.length;
    }
}

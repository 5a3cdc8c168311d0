package particlelab.accuracy;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import particlelab.collision.Plane;
import particlelab.collision.ThinWall;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.reference.CostMeter;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SphereRule;
import particlelab.world.StepListener;
import particlelab.world.SurfaceRule;
import particlelab.world.TunnelShots;
import particlelab.world.World;


/**
 * Collisions, speed against error: the world's overlap test against its swept (intersection)
 * test, in three parts.
 *
 * <ol>
 * <li><b>Tunnelling.</b> The scene of {@code particle-lab tunnel}: shots of radius r straight
 * at a wall of thickness D, each from a seeded random phase, for a sweep of
 * {@code v·h/(2r+D)}. The overlap test's miss rate is measured beside the formula
 * {@code max(0, 1 − (2r+D)/(v·h))}, with a 95 % binomial (Wilson) interval.</li>
 * <li><b>Cost per step.</b> {@value #COST_BALLS} balls bouncing on the ground, off two walls
 * and off each other, stepped at 1/60 s with each test, timed side by side by the report's
 * {@link CostMeter}. The scene restarts from its launch every {@value #COST_RESTART_STEPS}
 * steps, while most balls are still bouncing, so every timed step has balls in flight; a
 * ball that settles before rests exactly (the resting fix: velocity 0, no decaying
 * subnormals).</li>
 * <li><b>Bounce sequence.</b> A ball dropped from {@value #BOUNCE_HEIGHT_METRES} m with
 * e = {@value #BOUNCE_RESTITUTION} (no threshold, no resting fix), at the full report's step
 * sizes ({@link #bounceSteps}): the first {@value #BOUNCE_IMPACTS} impact times and apexes
 * against the ideal {@code t_1 = t0}, {@code t_{k+1} = t_k + 2·t0·e^k}, apex {@code e^{2k}·h0},
 * {@code t0 = √(2·h0/g)}, and the fitted order of the worst error.</li>
 * </ol>
 */
final class CollisionStudy {

    /** Shot radius r of the tunnelling scene (in metres). */
    static final float SHOT_RADIUS_METRES = 0.05f;
    /** Wall thickness D of the tunnelling scene (in metres). */
    static final float WALL_THICKNESS_METRES = 0.1f;
    /** Step of the tunnelling and cost scenes: the demos' 1/60 s (in seconds). */
    static final float STEP_SECONDS = 1f / 60f;
    /** The values of {@code v·h/(2r+D)} swept. */
    static final double[] TRAVEL_RATIOS = {0.5, 0.75, 1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10};
    /** The seed of the first speed's phases; speed i uses {@code SEED + i}. */
    static final int SEED = 1;
    /** z of a two-sided 95 % normal interval. */
    static final double Z95 = 1.959963984540054;

    /** Balls in the cost scene. */
    static final int COST_BALLS = 12;
    /** Steps between restarts of the cost scene. */
    static final int COST_RESTART_STEPS = 480;
    /** Radius of the cost scene's balls (in metres). */
    static final float COST_RADIUS_METRES = 0.15f;
    /** The cost scene's walls stand at x = ± this (in metres). */
    static final float COST_HALF_WIDTH_METRES = 2f;
    /** Timing passes of the cost scene, alternating the two tests. */
    static final int COST_PASSES = 3;
    /** Launches of the cost scene in the untimed pass that counts its contacts. */
    static final int COST_COUNT_LAUNCHES = 10;

    /** Drop height of the bounce scene (in metres). */
    static final float BOUNCE_HEIGHT_METRES = 10f;
    /** Restitution of the bounce scene. */
    static final float BOUNCE_RESTITUTION = 0.8f;
    /** Impacts of the bounce scene compared with the ideal sequence. */
    static final int BOUNCE_IMPACTS = 5;

    /** One speed of the tunnelling sweep. */
    static final class Tunnel {
        final double travelRatio;
        final float speed;
        final int shots;
        final int overlapMisses;
        final int sweptMisses;
        final double predicted;

        Tunnel(double travelRatio, float speed, int shots, int overlapMisses, int sweptMisses,
                double predicted) {
            this.travelRatio = travelRatio;
            this.speed = speed;
            this.shots = shots;
            this.overlapMisses = overlapMisses;
            this.sweptMisses = sweptMisses;
            this.predicted = predicted;
        }

        double overlapRate() {
            return (double) overlapMisses / shots;
        }

        /** Wilson's 95 % interval of the overlap miss rate: {low, high}. */
        double[] overlapInterval() {
            double n = shots;
            double p = overlapRate();
            double z2 = Z95 * Z95;
            double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
            double half = Z95 * Math.sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n);
            // at 0 or N misses the interval ends exactly at 0 or 1 (round-off would miss it)
            double low = overlapMisses == 0 ? 0.0 : Math.max(0.0, centre - half);
            double high = overlapMisses == shots ? 1.0 : Math.min(1.0, centre + half);
            return new double[] {low, high};
        }

        /** The binomial standard deviation of a rate of N shots with the predicted odds. */
        double predictedSigma() {
            return Math.sqrt(predicted * (1 - predicted) / shots);
        }
    }

    /** The cost of one step of the cost scene with one test. */
    static final class Cost {
        final Detection detection;
        final double nanosPerStep;
        final double bytesPerStep;
        final double contactsPerStep;
        final long capHits;

        Cost(Detection detection, double nanosPerStep, double bytesPerStep,
                double contactsPerStep, long capHits) {
            this.detection = detection;
            this.nanosPerStep = nanosPerStep;
            this.bytesPerStep = bytesPerStep;
            this.contactsPerStep = contactsPerStep;
            this.capHits = capHits;
        }
    }

    /** One impact of the bounce scene at one step size. */
    static final class Impact {
        final Detection detection;
        final double stepSeconds;
        final int number;
        final double timeSeconds;
        final double idealTimeSeconds;
        final double apexMetres;
        final double idealApexMetres;

        Impact(Detection detection, double stepSeconds, int number, double timeSeconds,
                double idealTimeSeconds, double apexMetres, double idealApexMetres) {
            this.detection = detection;
            this.stepSeconds = stepSeconds;
            this.number = number;
            this.timeSeconds = timeSeconds;
            this.idealTimeSeconds = idealTimeSeconds;
            this.apexMetres = apexMetres;
            this.idealApexMetres = idealApexMetres;
        }

        double timeError() {
            return timeSeconds - idealTimeSeconds;
        }

        double apexError() {
            return apexMetres - idealApexMetres;
        }
    }

    /** The worst bounce errors of one test at one step size. */
    static final class BounceError {
        final Detection detection;
        final double stepSeconds;
        final double worstTimeError;
        final double worstApexError;

        BounceError(Detection detection, double stepSeconds, double worstTimeError,
                double worstApexError) {
            this.detection = detection;
            this.stepSeconds = stepSeconds;
            this.worstTimeError = worstTimeError;
            this.worstApexError = worstApexError;
        }
    }

    /** The fitted orders of one test's bounce errors. */
    static final class BounceOrder {
        final Detection detection;
        final double timeOrder;
        final double apexOrder;

        BounceOrder(Detection detection, double timeOrder, double apexOrder) {
            this.detection = detection;
            this.timeOrder = timeOrder;
            this.apexOrder = apexOrder;
        }
    }

    final List<Tunnel> tunnels = new ArrayList<>();
    final List<Cost> costs = new ArrayList<>();
    final List<Impact> impacts = new ArrayList<>();
    final List<BounceError> bounceErrors = new ArrayList<>();
    final List<BounceOrder> bounceOrders = new ArrayList<>();
    final double[] bounceSteps;
    /** Untimed steps over which the cost scene's contacts were counted. */
    int costCountSteps;

    /**
     * Prepare a study; {@link #run} runs every part, tests run them one by one.
     *
     * @param bounceSteps the step sizes of the bounce part (in seconds, largest first)
     */
    CollisionStudy(double[] bounceSteps) {
        this.bounceSteps = bounceSteps;
    }

    /**
     * Shots per speed of the tunnelling sweep.
     *
     * @param config the report's size (not null)
     * @return the count (&gt;0)
     */
    static int shotsPerSpeed(ReportConfig config) {
        switch (config.size()) {
            case FULL:
                return 10_000;
            case QUICK:
                return 4_000;
            default:
                return 400;
        }
    }

    /**
     * The shot speed of a travel ratio: {@code v = ratio·(2r+D)/h}, in float as the
     * {@code tunnel} command takes it.
     *
     * @param travelRatio {@code v·h/(2r+D)} (&gt;0)
     * @return the speed (in m/s)
     */
    static float speedFor(double travelRatio) {
        return (float) (travelRatio * (2.0 * SHOT_RADIUS_METRES + WALL_THICKNESS_METRES)
                / STEP_SECONDS);
    }

    /**
     * The step sizes of the bounce part, whatever the report's size: those of the full sweep,
     * 1/15 s to 1/1920 s. The bounce errors zigzag around their trend (see
     * {@link #fittedOrder}), so a fit needs the whole range; the part takes well under a
     * second.
     *
     * @return new array, largest first (in seconds)
     */
    static double[] bounceSteps() {
        return ReportConfig.of(ReportConfig.Size.FULL).steps();
    }

    /**
     * Run every part.
     *
     * @param config the report's size (not null)
     * @param meter the report's timing loop (not null)
     * @return the results
     */
    static CollisionStudy run(ReportConfig config, CostMeter meter) {
        CollisionStudy study = new CollisionStudy(bounceSteps());
        study.runTunnelling(shotsPerSpeed(config));
        study.runCost(meter, config.size() == ReportConfig.Size.TINY ? COST_RESTART_STEPS
                : COST_COUNT_LAUNCHES * COST_RESTART_STEPS);
        study.runBounces();
        return study;
    }

    // ---- tunnelling ---------------------------------------------------------------------------

    void runTunnelling(int shots) {
        ThinWall wall = new ThinWall(Vector3f.UNIT_X, 0f, WALL_THICKNESS_METRES);
        for (int i = 0; i < TRAVEL_RATIOS.length; ++i) {
            float speed = speedFor(TRAVEL_RATIOS[i]);
            int overlapHits = TunnelShots.fire(wall, speed, SHOT_RADIUS_METRES, STEP_SECONDS,
                    Detection.OVERLAP, shots, new Random(SEED + i));
            int sweptHits = TunnelShots.fire(wall, speed, SHOT_RADIUS_METRES, STEP_SECONDS,
                    Detection.SWEPT, shots, new Random(SEED + i));
            tunnels.add(new Tunnel(TRAVEL_RATIOS[i], speed, shots, shots - overlapHits,
                    shots - sweptHits,
                    wall.overlapMissProbability(SHOT_RADIUS_METRES, speed, STEP_SECONDS)));
        }
    }

    // ---- cost ---------------------------------------------------------------------------------

    /** Counts resolved contacts. */
    private static final class ContactCounter implements ContactListener {
        private long count;

        @Override
        public void resolved(Contact contact, World world) {
            ++count;
        }
    }

    /** The cost scene with one test, stepped and restarted as a workload. */
    static final class BouncingBalls implements CostMeter.Workload {
        final World world = new World(1);
        private int stepsSinceRestart;
        /** Cap hits of the launches before the current one ({@code restart} clears them). */
        private long earlierCapHits;

        BouncingBalls(Detection detection) {
            Random random = new Random(SEED);
            ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
            Vector3f position = new Vector3f();
            Vector3f velocity = new Vector3f();
            int columns = COST_BALLS / 2;
            float spacing = 2f * COST_HALF_WIDTH_METRES / columns;
            for (int i = 0; i < COST_BALLS; ++i) {
                // two rows of six, a metre apart: no two balls touch at the launch
                float x = -COST_HALF_WIDTH_METRES + spacing * (0.5f + i % columns);
                float y = 1f + (i / columns) + 0.5f * random.nextFloat();
                position.set(x, y, 0f);
                velocity.set(6f * (random.nextFloat() - 0.5f), 0f, 0f);
                world.addBody(gravity, position, velocity, 1f, COST_RADIUS_METRES);
            }
            ImpulseResponse ground = new ImpulseResponse(0.9f,
                    ImpulseResponse.CYCLONE_THRESHOLD, true);
            ImpulseResponse walls = new ImpulseResponse(0.9f);
            world.addRule(SurfaceRule.ground(ground, detection));
            world.addRule(new SurfaceRule("left wall",
                    new Plane(Vector3f.UNIT_X, -COST_HALF_WIDTH_METRES), walls, detection));
            world.addRule(new SurfaceRule("right wall",
                    new Plane(new Vector3f(-1f, 0f, 0f), -COST_HALF_WIDTH_METRES), walls,
                    detection));
            world.addRule(new SphereRule(new ImpulseResponse(0.9f), detection));
        }

        @Override
        public Object run(int units) {
            for (int i = 0; i < units; ++i) {
                if (stepsSinceRestart == COST_RESTART_STEPS) {
                    earlierCapHits += world.getCapHits();
                    world.restart();
                    stepsSinceRestart = 0;
                }
                world.step(STEP_SECONDS);
                ++stepsSinceRestart;
            }
            return world;
        }

        /** The times a step reached the world's impact cap since this scene was made. */
        long capHits() {
            return earlierCapHits + world.getCapHits();
        }
    }

    /**
     * Count the contacts of the cost scene over {@code countSteps} untimed steps for each test
     * (which also warms both up), then time a step of each, alternating
     * {@value #COST_PASSES} times and keeping each test's fastest pass, so that a slow moment
     * of a shared machine does not land on one test only.
     */
    void runCost(CostMeter meter, int countSteps) {
        this.costCountSteps = countSteps;
        Detection[] tests = {Detection.OVERLAP, Detection.SWEPT};
        double[] contactsPerStep = new double[tests.length];
        long[] capHits = new long[tests.length];
        // the counted runs come first: they also warm up both tests' code
        for (int d = 0; d < tests.length; ++d) {
            BouncingBalls counted = new BouncingBalls(tests[d]);
            ContactCounter counter = new ContactCounter();
            counted.world.addContactListener(counter);
            counted.run(countSteps);
            contactsPerStep[d] = (double) counter.count / countSteps;
            capHits[d] = counted.capHits();
        }
        BouncingBalls[] scenes = new BouncingBalls[tests.length];
        double[] nanos = new double[tests.length];
        double[] bytes = new double[tests.length];
        for (int d = 0; d < tests.length; ++d) {
            scenes[d] = new BouncingBalls(tests[d]);
            nanos[d] = Double.POSITIVE_INFINITY;
        }
        for (int pass = 0; pass < COST_PASSES; ++pass) {
            for (int d = 0; d < tests.length; ++d) {
                CostMeter.Measurement m = meter.measure(scenes[d], 100);
                if (m.nanosPerUnit() < nanos[d]) {
                    nanos[d] = m.nanosPerUnit();
                    bytes[d] = m.bytesPerUnit();
                }
            }
        }
        for (int d = 0; d < tests.length; ++d) {
            costs.add(new Cost(tests[d], nanos[d], bytes[d], contactsPerStep[d], capHits[d]));
        }
    }

    // ---- bounces ------------------------------------------------------------------------------

    /** Impact times and the highest step end after each. */
    private static final class BounceRecorder implements ContactListener, StepListener {
        final List<Double> times = new ArrayList<>();
        final List<Double> apexes = new ArrayList<>();
        private double apex = Double.NEGATIVE_INFINITY;

        @Override
        public void resolved(Contact contact, World world) {
            if (!times.isEmpty()) {
                apexes.add(apex);
            }
            apex = Double.NEGATIVE_INFINITY;
            times.add(contact.getTimeSeconds());
        }

        @Override
        public void afterStep(World world, float stepSeconds) {
            apex = Math.max(apex, world.getBody(0).getPosition().y);
        }
    }

    void runBounces() {
        double g = Gravity.STANDARD_G;
        double h0 = BOUNCE_HEIGHT_METRES;
        double e = BOUNCE_RESTITUTION;
        double t0 = Math.sqrt(2.0 * h0 / g);
        double[] idealTimes = new double[BOUNCE_IMPACTS + 1];
        idealTimes[0] = t0;
        for (int k = 1; k <= BOUNCE_IMPACTS; ++k) {
            idealTimes[k] = idealTimes[k - 1] + 2.0 * t0 * Math.pow(e, k);
        }
        for (Detection detection : new Detection[] {Detection.OVERLAP, Detection.SWEPT}) {
            double[] timeErrors = new double[bounceSteps.length];
            double[] apexErrors = new double[bounceSteps.length];
            for (int s = 0; s < bounceSteps.length; ++s) {
                float h = (float) bounceSteps[s];
                BounceRecorder recorder = drop(detection, h, idealTimes[BOUNCE_IMPACTS] + 1.0);
                for (int k = 1; k <= BOUNCE_IMPACTS; ++k) {
                    Impact impact = new Impact(detection, bounceSteps[s], k,
                            recorder.times.get(k - 1), idealTimes[k - 1],
                            recorder.apexes.get(k - 1), h0 * Math.pow(e, 2 * k));
                    impacts.add(impact);
                    timeErrors[s] = Math.max(timeErrors[s], Math.abs(impact.timeError()));
                    apexErrors[s] = Math.max(apexErrors[s], Math.abs(impact.apexError()));
                }
                bounceErrors.add(new BounceError(detection, bounceSteps[s], timeErrors[s],
                        apexErrors[s]));
            }
            bounceOrders.add(new BounceOrder(detection,
                    fittedOrder(bounceSteps, timeErrors), fittedOrder(bounceSteps, apexErrors)));
        }
    }

    /**
     * Fit {@code log(error) = p·log(h) + c} by least squares through every point and return p.
     * Unlike {@link OrderFit}, no point is left out for falling too little: where in its step
     * each impact falls changes with h, so the bounce errors fall with h in a zigzag around
     * their first-order trend, far above round-off.
     *
     * @param stepSeconds the step sizes (in seconds, &gt;0)
     * @param errors the errors (each &gt;0)
     * @return the order p
     */
    static double fittedOrder(double[] stepSeconds, double[] errors) {
        int n = stepSeconds.length;
        double sumX = 0.0;
        double sumY = 0.0;
        double sumXx = 0.0;
        double sumXy = 0.0;
        for (int i = 0; i < n; ++i) {
            double x = Math.log10(stepSeconds[i]);
            double y = Math.log10(errors[i]);
            sumX += x;
            sumY += y;
            sumXx += x * x;
            sumXy += x * y;
        }
        return (n * sumXy - sumX * sumY) / (n * sumXx - sumX * sumX);
    }

    private static BounceRecorder drop(Detection detection, float h, double untilSeconds) {
        World world = new World(1);
        world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, BOUNCE_HEIGHT_METRES, 0f), Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(BOUNCE_RESTITUTION, 0f, false),
                detection));
        BounceRecorder recorder = new BounceRecorder();
        world.addContactListener(recorder);
        world.addStepListener(recorder);
        while (world.getTimeSeconds() < untilSeconds
                && recorder.times.size() <= BOUNCE_IMPACTS) {
            world.step(h);
        }
        if (recorder.times.size() <= BOUNCE_IMPACTS) {
            throw new IllegalStateException("the " + detection + " ball at h = " + h
                    + " s made only " + recorder.times.size() + " impacts by t = "
                    + untilSeconds + " s");
        }
        return recorder;
    }
}

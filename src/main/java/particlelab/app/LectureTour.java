package particlelab.app;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.demo.DemoParticle;
import particlelab.demo.DemoState;
import particlelab.demo.HudNote;
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
import particlelab.view.TextFormat;
import particlelab.world.Fountain;

/**
 * Lecture 15 in slide order: one explicit list, like {@link DemoCatalog}. Each stop names its
 * slide as the lecture titles it, the demo that shows it, the {@code --set} values that put
 * the demo in the state the slide needs, and what to watch for: lines on the HUD written
 * from the demo's live numbers at each refresh (allocating nothing). {@code particle-lab tour}
 * walks them ({@link TourCommand}), PageDown and PageUp step through them in the window, and
 * {@code docs/lecturing.md} is checked against this list.
 */
public final class LectureTour {

    /** One slide of the lecture and the demo state it needs. */
    public static final class Stop {

        private final String slide;
        private final String demo;
        private final List<String> settings;
        private final HudNote watch;

        /**
         * Declare a stop.
         *
         * @param slide the slide's title as the lecture has it (not null, not empty)
         * @param demo the demo's command-line name, one of {@link DemoCatalog#names()}
         * @param watch writes the "what to watch for" lines from the demo's numbers (not null)
         * @param settings the demo's {@code --set NAME=VALUE} values, none for its defaults
         */
        Stop(String slide, String demo, HudNote watch, String... settings) {
            this.slide = slide;
            this.demo = demo;
            this.watch = watch;
            this.settings = List.of(settings);
        }

        /** @return the slide's title, e.g. "Collision Response" (not null) */
        public String getSlide() {
            return slide;
        }

        /** @return the demo's command-line name, e.g. "collisions" (not null) */
        public String getDemo() {
            return demo;
        }

        /** @return the demo's {@code NAME=VALUE} settings, in order (not null, unmodifiable) */
        public List<String> getSettings() {
            return settings;
        }

        /** @return what writes the "what to watch for" lines (not null) */
        public HudNote getWatch() {
            return watch;
        }

        /**
         * Write the stop as {@code tour --list} prints it, e.g. "6   Kinematics vs dynamics:
         * collisions --set preset=paddle": what follows the colon, after {@code particle-lab
         * demo}, opens the same state.
         *
         * @param number the stop's number (from 1)
         * @return the line (not null)
         */
        public String describe(int number) {
            StringBuilder text = new StringBuilder();
            text.append(number).append(number < 10 ? "   " : "  ").append(slide).append(": ")
                    .append(demo);
            for (String setting : settings) {
                text.append(" --set ").append(setting);
            }
            return text.toString();
        }
    }

    /** What every stop's first HUD line starts with. */
    public static final String WATCH = "Watch: ";

    /** HelloAiming's aims, in order, without the copy {@code values()} makes. */
    private static final HelloAimingDemo.Aim[] AIMS = HelloAimingDemo.Aim.values();

    /** The stops, in slide order. */
    private static final List<Stop> STOPS = List.of(
            new Stop("Collision Response", "targets", LectureTour::watchPhases),
            new Stop("Collision Response", "collisions", LectureTour::watchImpulse,
                    "preset=head-on", "e=0.8"),
            new Stop("Collision Resolution", "bounce", LectureTour::watchBounce),
            new Stop("Collision Resolution", "collisions", LectureTour::watchCradle,
                    "preset=cradle", "e=1"),
            new Stop("Collision Resolution: animation based vs physics based", "clip",
                    LectureTour::watchClip),
            new Stop("Kinematics vs dynamics", "collisions", LectureTour::watchPaddle,
                    "preset=paddle"),
            new Stop("Discrete particle motion", "uniform", LectureTour::watchUniform),
            new Stop("Example: gravitational pull", "pull", LectureTour::watchFall),
            new Stop("Example: pull + drag", "drag", LectureTour::watchDrag),
            new Stop("Example: pull + drag", "wind", LectureTour::watchWind),
            new Stop("Example: pull + drag + thrust", "thrust", LectureTour::watchThrust),
            new Stop("Simulation recipe: gravity, drag, thrust, spring pull", "spring",
                    LectureTour::watchSpring),
            new Stop("Rotation", "rotation", LectureTour::watchRotation, "omega=6"),
            new Stop("Rotation", "throw", LectureTour::watchThrow),
            new Stop("Rotation", "racket", LectureTour::watchRacket),
            new Stop("Accuracy of simulation", "pull", LectureTour::watchCoarseFall,
                    "h=1/10", "lane=rk4"),
            new Stop("Accuracy of simulation", "pull", LectureTour::watchRates, "rates=on"),
            new Stop("Targeting problem", "height", LectureTour::watchHeights),
            new Stop("HelloAiming", "aiming", LectureTour::watchAiming, "code=both",
                    "vx=21"),
            new Stop("Euler steps: advantages and disadvantages", "fountain",
                    LectureTour::watchFountain),
            new Stop("Euler steps: advantages and disadvantages", "tunnelling",
                    LectureTour::watchTunnelling),
            new Stop("If accuracy matters: cheat", "cheat", LectureTour::watchCheat,
                    "speed=900"),
            new Stop("Computer science approach: iterations", "iterate",
                    LectureTour::watchIterations, "strategy=bisection", "drag=quadratic"));

    /** The first stop on the pull demo (from 0): its fall at h = 1/60 s. */
    private static final int FALL_STOP = firstStopOf("pull");

    private LectureTour() {
    }

    /**
     * Access the stops in slide order.
     *
     * @return the stops (not null, unmodifiable)
     */
    public static List<Stop> stops() {
        return STOPS;
    }

    /**
     * Write a stop's HUD heading: "Tour 6/23: Kinematics vs dynamics (PageDown next, ...)".
     *
     * @param text where to append (not null, modified)
     * @param index the stop (from 0)
     * @return text
     */
    static StringBuilder appendHeading(StringBuilder text, int index) {
        return text.append("Tour ").append(index + 1).append('/').append(STOPS.size())
                .append(": ").append(STOPS.get(index).getSlide())
                .append("   (PageDown next, PageUp back)\n");
    }

    /**
     * Write a stop's note after the demo's title: "1/23 Collision Response".
     *
     * @param index the stop (from 0)
     * @return the note (not null, one line)
     */
    static String titleNote(int index) {
        return (index + 1) + "/" + STOPS.size() + " " + STOPS.get(index).getSlide();
    }

    /** @return the index of the first stop on a demo (from 0) */
    private static int firstStopOf(String demo) {
        for (int i = 0; i < STOPS.size(); ++i) {
            if (STOPS.get(i).getDemo().equals(demo)) {
                return i;
            }
        }
        throw new IllegalStateException("no tour stop on " + demo);
    }

    // ------------------------------------------------ what to watch for, per stop ----

    private static void watchPhases(DemoState demo, StringBuilder text) {
        TargetsDemo targets = (TargetsDemo) demo;
        text.append(WATCH).append("prologue ignores the gun's platform and the ghost pane,"
                + " collision bounces the shot (e = ");
        TextFormat.appendFixed(text, TargetsDemo.RESTITUTION, 1)
                .append("), epilogue: targets destroyed ").append(targets.countDestroyed())
                .append(", fragments spawned ").append(targets.countSpawned())
                .append(" by t = ");
        TextFormat.appendFixed(text, demo.getClock().getSimulatedSeconds(), 2)
                .append(" s (F fires)\n");
    }

    private static void watchBounce(DemoState demo, StringBuilder text) {
        BounceDemo bounce = (BounceDemo) demo;
        float e = bounce.getRestitution();
        text.append(WATCH).append("the ground's response v' = −e·v, e = ");
        TextFormat.appendFixed(text, e, 2).append(": each apex e² = ");
        TextFormat.appendFixed(text, e * e, 2).append(" times the one before; the left ball"
                + " is at y = ");
        TextFormat.appendFixed(text, demo.getParticles().get(0).getParticle().position.y, 2)
                .append(" m\n");
    }

    private static void watchImpulse(DemoState demo, StringBuilder text) {
        CollisionsDemo collisions = (CollisionsDemo) demo;
        text.append(WATCH);
        if (collisions.countImpactSteps() == 0) {
            text.append("the balls close in; the impulse j acts along n in one step\n");
            return;
        }
        text.append("momentum is kept, kinetic energy is not: lost ");
        TextFormat.appendFixed(text, collisions.getImpactEnergyBefore()
                - collisions.getImpactEnergyAfter(), 3).append(" J, and ½·μ·(1 − e²)·v_n² = ");
        TextFormat.appendFixed(text, collisions.getImpactPredictedLoss(), 3)
                .append(" J predicts it\n");
    }

    private static void watchCradle(DemoState demo, StringBuilder text) {
        CollisionsDemo collisions = (CollisionsDemo) demo;
        text.append(WATCH).append("contacts resolved worst first, one step at a time: ")
                .append(collisions.countImpactSteps()).append(" impact steps so far, kinetic"
                        + " energy now ");
        TextFormat.appendFixed(text, collisions.kineticEnergy(), 3)
                .append(" J (e = 1: it should stay)\n");
    }

    private static void watchClip(DemoState demo, StringBuilder text) {
        ClipResponseDemo clip = (ClipResponseDemo) demo;
        text.append(WATCH);
        if (!clip.hasHit(ClipResponseDemo.PHYSICS_LANE)
                || !clip.hasHit(ClipResponseDemo.CLIP_LANE)) {
            text.append("the rocket flies at both targets; Up/Down fire faster or slower\n");
            return;
        }
        text.append("KE after the impact: clip ");
        TextFormat.appendFixed(text, clip.energyAfter(ClipResponseDemo.CLIP_LANE), 2)
                .append(" J whatever the shot, physics ");
        TextFormat.appendFixed(text, clip.energyAfter(ClipResponseDemo.PHYSICS_LANE), 2)
                .append(" J (Up/Down: fire again faster or slower)\n");
    }

    private static void watchPaddle(DemoState demo, StringBuilder text) {
        CollisionsDemo collisions = (CollisionsDemo) demo;
        text.append(WATCH).append("the grey arrow is the paddle's -J, not applied (infinite"
                + " mass): the balls got |ΣJ| = ");
        TextFormat.appendFixed(text, collisions.paddleImpulseLength(), 2)
                .append(" kg m/s\n  and kinetic energy ");
        TextFormat.appendFixed(text, collisions.kineticEnergy(), 3)
                .append(" J, from 0: the scripted paddle (kinematics) does work no force"
                        + " accounts for\n");
    }

    private static void watchUniform(DemoState demo, StringBuilder text) {
        DemoParticle sphere = demo.getParticles().get(0);
        Vector3f position = sphere.getParticle().position;
        text.append(WATCH).append("P += h·V each step; at t = ");
        TextFormat.appendFixed(text, demo.getClock().getSimulatedSeconds(), 2)
                .append(" s the sphere is at x = ");
        TextFormat.appendFixed(text, position.x, 2).append(" m, a straight line\n");
    }

    private static void watchFall(DemoState demo, StringBuilder text) {
        DemoParticle ball = demo.getParticles().get(0);
        text.append(WATCH).append("V += h·g, then P += h·V: ");
        if (ball.hasLanded()) {
            // The flight is over: its numbers, not the resting ball's zero velocity.
            text.append("landed at x = ");
            TextFormat.appendFixed(text, ball.getLandingX(), 2).append(" m after ");
            TextFormat.appendFixed(text, ball.getLandingSeconds(), 2)
                    .append(" s; in flight vy fell by g·h each step and vx stayed as"
                            + " launched\n");
            return;
        }
        Vector3f velocity = ball.getParticle().velocity;
        text.append("vy is ");
        TextFormat.appendFixed(text, velocity.y, 2)
                .append(" m/s now, falling by g·h each step; vx stays ");
        TextFormat.appendFixed(text, velocity.x, 2).append(" m/s\n");
    }

    private static void watchDrag(DemoState demo, StringBuilder text) {
        List<DemoParticle> particles = demo.getParticles();
        text.append(WATCH).append("without drag ");
        appendFlight(text, particles.get(0)).append(", linear ");
        appendFlight(text, particles.get(1)).append(", quadratic ");
        appendFlight(text, particles.get(2)).append(landedAll(particles, 3)
                ? ": drag shortens the flight\n" : ": drag caps the speed\n");
    }

    private static void watchWind(DemoState demo, StringBuilder text) {
        List<DemoParticle> particles = demo.getParticles();
        text.append(WATCH).append("drag against moving air, F = b·(W − V), one more force:"
                + " still air ");
        appendFlight(text, particles.get(0)).append(", in the wind ");
        appendFlight(text, particles.get(1)).append('\n');
    }

    private static void watchThrust(DemoState demo, StringBuilder text) {
        List<DemoParticle> particles = demo.getParticles();
        text.append(WATCH).append("pull + drag ");
        appendFlight(text, particles.get(0)).append(", with thrust ");
        appendFlight(text, particles.get(1))
                .append(": a force is one more term in the sum\n");
    }

    /** A ball's |V| while it flies, where it landed once it has: "|V| 3.20 m/s", "x = ...". */
    private static StringBuilder appendFlight(StringBuilder text, DemoParticle particle) {
        if (particle.hasLanded()) {
            text.append("landed at x = ");
            return TextFormat.appendFixed(text, particle.getLandingX(), 2).append(" m");
        }
        text.append("|V| ");
        return TextFormat.appendFixed(text, particle.getParticle().velocity.length(), 2)
                .append(" m/s");
    }

    /** @return true if the first count particles have all landed */
    private static boolean landedAll(List<DemoParticle> particles, int count) {
        for (int i = 0; i < count; ++i) {
            if (!particles.get(i).hasLanded()) {
                return false;
            }
        }
        return true;
    }

    private static void watchSpring(DemoState demo, StringBuilder text) {
        SpringDemo spring = (SpringDemo) demo;
        double t = demo.getClock().getSimulatedSeconds();
        text.append(WATCH).append("one more force, the same step: blue at y = ");
        TextFormat.appendFixed(text, demo.getParticles().get(0).getParticle().position.y, 2)
                .append(" m, exact ");
        TextFormat.appendFixed(text, spring.exactHeight(0, t), 2).append(" m; h < 2/ω = ");
        TextFormat.appendFixed(text, spring.stableStepLimit(0), 3).append(" s (damped ");
        TextFormat.appendFixed(text, spring.stableStepLimit(1), 3)
                .append(" s): push h past it on the panel (F2)\n");
    }

    private static void watchRotation(DemoState demo, StringBuilder text) {
        RotationDemo rotation = (RotationDemo) demo;
        text.append(WATCH).append("R += h·[ω]×R is no rotation: plain Euler restarted ")
                .append(rotation.countPlainRestarts()).append(" times; the quaternion box"
                        + " lags the exact one by ");
        TextFormat.appendFixed(text, rotation.getLagRadians(2), 4).append(" rad\n");
    }

    private static void watchThrow(DemoState demo, StringBuilder text) {
        SpinThrowDemo spin = (SpinThrowDemo) demo;
        text.append(WATCH).append("translation and rotation stepped apart: the centre's"
                + " parabola, the box turned ");
        TextFormat.appendFixed(text, spin.getMeasuredAngle(), 2).append(" rad, the formula ");
        TextFormat.appendFixed(text, spin.formulaAngle(spin.getSpinSeconds()), 2)
                .append(" rad\n");
    }

    private static void watchRacket(DemoState demo, StringBuilder text) {
        TennisRacketDemo racket = (TennisRacketDemo) demo;
        // Degrees, as the demo's own line above says it: one unit for one angle on screen.
        text.append(WATCH).append("spin about the middle axis flips; flips so far: explicit"
                + " Euler ").append(racket.countFlips(0)).append(", implicit midpoint ")
                .append(racket.countFlips(1)).append("; the plates are ");
        TextFormat.appendFixed(text, Math.toDegrees(racket.angleBetweenRadians()), 1)
                .append("° apart\n");
    }

    private static void watchCoarseFall(DemoState demo, StringBuilder text) {
        DemoParticle ball = demo.getParticles().get(0);
        text.append(WATCH).append("h = ");
        TextFormat.appendFixed(text, demo.getClock().getStepSeconds(), 3).append(" s: ");
        if (ball.hasLanded()) {
            text.append("landed at x = ");
            TextFormat.appendFixed(text, ball.getLandingX(), 2)
                    .append(" m; compare with h = 1/60 s (stop ").append(FALL_STOP + 1)
                    .append(")\n");
        } else {
            text.append("the dots are the steps; the path between them is a guess\n");
        }
    }

    private static void watchRates(DemoState demo, StringBuilder text) {
        RateLanes rates = ((GravitationalPullDemo) demo).getRates();
        int last = RateLanes.RATES_HZ.length - 1;
        text.append(WATCH).append("raw tpf = 1/f: ");
        if (!rates.isOn() || rates.getRun(0) == null) {
            text.append("rate lanes off (--set rates=on)\n");
            return;
        }
        DemoParticle ball = demo.getParticles().get(0);
        if (ball.hasLanded() && rates.getRun(0).hasLanded() && rates.getRun(last).hasLanded()) {
            text.append((int) RateLanes.RATES_HZ[0]).append(" Hz lands at ");
            TextFormat.appendFixed(text, rates.getRun(0).getLanding().getX(), 2).append(" m, ")
                    .append((int) RateLanes.RATES_HZ[last]).append(" Hz at ");
            TextFormat.appendFixed(text, rates.getRun(last).getLanding().getX(), 2)
                    .append(" m; the fixed-step ball landed at x = ");
            TextFormat.appendFixed(text, ball.getLandingX(), 2).append(" m\n");
            return;
        }
        text.append((int) RateLanes.RATES_HZ[0]).append(" Hz has taken ")
                .append(rates.getRun(0).getSteps()).append(" steps, ")
                .append((int) RateLanes.RATES_HZ[last]).append(" Hz ")
                .append(rates.getRun(last).getSteps())
                .append(": each monitor steps its own path\n");
    }

    private static void watchHeights(DemoState demo, StringBuilder text) {
        AnyHeightDemo height = (AnyHeightDemo) demo;
        text.append(WATCH).append("the targeting problem at a fixed speed: two launch angles"
                + " reach the target, arriving direct ");
        appendArrival(text, height, false).append(", lob ");
        appendArrival(text, height, true).append('\n');
    }

    private static StringBuilder appendArrival(StringBuilder text, AnyHeightDemo height,
            boolean lob) {
        if (!height.hasArrived(lob)) {
            return text.append("(flying)");
        }
        return TextFormat.appendFixed(text, height.getArrivalHeight(lob), 2).append(" m");
    }

    private static void watchAiming(DemoState demo, StringBuilder text) {
        HelloAimingDemo aiming = (HelloAimingDemo) demo;
        text.append(WATCH);
        int landed = aiming.getLandedShotNumber();
        if (landed == 0) {
            text.append("vy = ");
            TextFormat.appendFixed(text, aiming.getVerticalSpeed(HelloAimingDemo.Aim.LECTURE), 2)
                    .append(" m/s from the lecture's formula, ");
            TextFormat.appendFixed(text, aiming.getVerticalSpeed(HelloAimingDemo.Aim.DISCRETE),
                    2).append(" m/s corrected; shot ").append(aiming.getShotNumber())
                    .append(" in flight, t = ");
            TextFormat.appendFixed(text, demo.getClock().getSimulatedSeconds(), 2)
                    .append(" s: which lands on the target?\n");
            return;
        }
        text.append("shot ").append(landed).append(" landed:");
        String separator = " ";
        for (HelloAimingDemo.Aim aim : AIMS) {
            if (aiming.getLandedShotNumber(aim) == landed) {
                text.append(separator).append(aim == HelloAimingDemo.Aim.LECTURE
                        ? "the lecture's aim at x = " : "the discrete correction at x = ");
                TextFormat.appendFixed(text, aiming.getLastLandingX(aim), 2).append(" m");
                separator = ", ";
            }
        }
        text.append('\n');
    }

    private static void watchFountain(DemoState demo, StringBuilder text) {
        Fountain fountain = ((FountainDemo) demo).getFountain();
        text.append(WATCH).append("an advantage: one cheap Euler step moves every particle, ")
                .append(fountain.countLive()).append(" in flight now, ")
                .append(fountain.countRecycledResting()).append(" come to rest and reused\n");
    }

    private static void watchTunnelling(DemoState demo, StringBuilder text) {
        TunnellingDemo tunnelling = (TunnellingDemo) demo;
        text.append(WATCH).append("a disadvantage: a step sees only where it ends; overlap"
                + " test hit ").append(tunnelling.countHits(false))
                .append(" of ").append(tunnelling.countShots(false)).append(", swept test ")
                .append(tunnelling.countHits(true)).append(" of ")
                .append(tunnelling.countShots(true)).append("; predicted miss chance ");
        TextFormat.appendFixed(text, 100.0 * tunnelling.predictedMissProbability(), 0)
                .append(" %\n");
    }

    private static void watchCheat(DemoState demo, StringBuilder text) {
        FastBulletsDemo cheat = (FastBulletsDemo) demo;
        text.append(WATCH).append("at ");
        TextFormat.appendFixed(text, cheat.getSpeed(), 0).append(" m/s the stepped shot drops ");
        TextFormat.appendFixed(text, cheat.getSteppedDrop(), 3).append(" m by the target: the"
                + " ray's straight line is ").append(cheat.isHit() ? "close enough" : "off")
                .append('\n');
    }

    private static void watchIterations(DemoState demo, StringBuilder text) {
        IterativeAimingDemo iterate = (IterativeAimingDemo) demo;
        int landed = iterate.countLanded();
        text.append(WATCH).append(iterate.getStrategy().cliName()).append(": ").append(landed)
                .append(landed == 1 ? " shot" : " shots").append(" landed so far; no formula,"
                        + " the simulation itself is the predictor\n");
    }
}

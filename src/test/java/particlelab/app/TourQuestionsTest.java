package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.aiming.Hitscan;
import particlelab.aiming.LaunchAngles;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.RateLanes;
import particlelab.lecture.AnyHeightDemo;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.IterativeAimingDemo;
import particlelab.lecture.SpinThrowDemo;
import particlelab.lecture.SpringDemo;
import particlelab.lecture.TargetsDemo;
import particlelab.lecture.TunnellingDemo;
import particlelab.physics.Gravity;
import particlelab.physics.SimulationClock;

/**
 * The tour's questions without a window: one entry per stop, two to four different answers
 * each, and every stop's state far from the line between two answers, checked with closed
 * forms ({@code NUMERICS.md}), so the right answer cannot pass for a wrong one through
 * round-off or a tolerance.
 */
class TourQuestionsTest {

    @Test
    void thereIsOneEntryPerStopAndEveryQuestionHasDifferentAnswers() {
        assertEquals(LectureTour.stops().size(), TourQuestions.size());
        for (int i = 0; i < TourQuestions.size(); ++i) {
            TourQuestion question = TourQuestions.forStop(i);
            if (question == null) {
                continue;
            }
            List<String> answers = question.getAnswers();
            assertTrue(answers.size() >= TourQuestion.MIN_ANSWERS
                    && answers.size() <= TourQuestion.MAX_ANSWERS, question.getText());
            assertEquals(answers.size(), new HashSet<>(answers).size(), question.getText());
            int right = question.answer(TourCommand.stateOf(i));
            assertTrue(right >= 0 && right < answers.size(), question.getText());
        }
    }

    @Test
    void aQuestionWithTwoEqualAnswersOrTooManyIsRefused() {
        TourQuestion.Rule rule = demo -> 0;
        TourQuestion.Outcome outcome = demo -> TourQuestion.UNDECIDED;
        assertThrows(IllegalArgumentException.class,
                () -> new TourQuestion("Same?", rule, outcome, "yes", "yes"));
        assertThrows(IllegalArgumentException.class,
                () -> new TourQuestion("Five?", rule, outcome, "a", "b", "c", "d", "e"));
        assertThrows(IllegalArgumentException.class,
                () -> new TourQuestion("One?", rule, outcome, "a"));
        assertThrows(IllegalArgumentException.class,
                () -> new TourQuestion("no question mark", rule, outcome, "a", "b"));
    }

    /**
     * The lecture's step lands exactly {@code vx·h} short of the continuous landing: at every
     * landing stop that is many times "on"'s tolerance, so "short" is never "on".
     */
    @Test
    void theLandingStopsLandFarShortOfOn() {
        int asked = 0;
        for (int i = 0; i < TourQuestions.size(); ++i) {
            TourQuestion question = TourQuestions.forStop(i);
            if (question == null || !question.getText().startsWith("Euler lands")) {
                continue;
            }
            ++asked;
            DemoParameters parameters = TourCommand.stateOf(i).getParameters();
            double vx = parameters.getValue("speed")
                    * Math.cos(Math.toRadians(parameters.getValue("angle")));
            double shortfall = vx * parameters.getValue("h");
            // Ten times the tolerance: float round-off (1e-5 m) cannot carry it across.
            assertTrue(shortfall > 10 * TourQuestions.ON_METRES,
                    "stop " + (i + 1) + ": " + shortfall);
            assertEquals("short", question.getAnswers().get(question.answer(
                    TourCommand.stateOf(i))), "stop " + (i + 1));
        }
        assertEquals(2, asked);
    }

    /** Plain Euler's det R grows by {@code 1 + (|ω|h)²} a step: 1.01¹⁰⁰ = 2.70 at stop 13. */
    @Test
    void theRotationStopsDeterminantIsFarAboveOne() {
        int stop = stopOf("After " + TourQuestions.ROTATION_STEPS + " ");
        DemoParameters parameters = TourCommand.stateOf(stop).getParameters();
        double wh = parameters.getValue("omega") * parameters.getValue("h");
        double det = Math.pow(1 + wh * wh, TourQuestions.ROTATION_STEPS);
        // The closed form and the stepped float product agree to about 1e-5 (100 roundings).
        assertTrue(det - 1 > 100 * TourQuestions.DET_AT_ONE, "det R " + det);
        assertEquals(0, TourQuestions.forStop(stop).answer(TourCommand.stateOf(stop)));
    }

    /**
     * The overlap test misses a random-phase shot with probability
     * {@code 1 − (2r + d)/(v·h)}: 0.55 at 40 m/s, so of 1000 shots (standard deviation 16)
     * neither none nor all is missed.
     */
    @Test
    void theTunnellingStopMissesSomeButNotAll() {
        int stop = stopOf("How many of the balls");
        DemoState demo = TourCommand.stateOf(stop);
        double travel = ((TunnellingDemo) demo).getSpeed() * demo.getParameters().getValue("h");
        double miss = 1 - (2 * TunnellingDemo.RADIUS + TunnellingDemo.THICKNESS) / travel;
        assertTrue(miss > 0.1 && miss < 0.9, "miss probability " + miss);
        assertEquals("some", TourQuestions.forStop(stop).getAnswers()
                .get(TourQuestions.forStop(stop).answer(demo)));
    }

    /** At 900 m/s the stepped shot drops about 1.6 cm by the disc, a thirtieth of its radius. */
    @Test
    void theCheatStopsShotDropsFarLessThanTheRadius() {
        int stop = stopOf("Does the stepped shot");
        DemoState demo = TourCommand.stateOf(stop);
        float speed = FastBulletsDemo.SPEEDS[(int) demo.getParameters().getValue("speed")];
        assertEquals(900f, speed);
        double drop = Hitscan.steppedDrop(Gravity.STANDARD_G, FastBulletsDemo.DISTANCE, speed,
                demo.getParameters().getValue("h"));
        assertTrue(drop < 0.1 * FastBulletsDemo.TARGET_RADIUS, "drop " + drop);
        assertEquals(0, TourQuestions.forStop(stop).answer(demo));
    }

    /** The impulse loses {@code ½·μ·(1 − e²)·v_n²}: 36 % of that at e = 0.8, none at e = 1. */
    @Test
    void theImpactStopsLoseEnergyBelowEOneAndKeepItAtOne() {
        // Stop 2, head-on at e = 0.8: lost; stop 4, the cradle at e = 1: kept.
        assertEquals(1, TourQuestions.forStop(1).answer(TourCommand.stateOf(1)));
        assertEquals(0, TourQuestions.forStop(3).answer(TourCommand.stateOf(3)));
    }

    /**
     * The drag stop's spheres, stepped without a window: linear drag lands 8.4 m out,
     * quadratic 10.6 m, gravity alone 20.2 m. The nearest two are 2 m apart, far more than
     * the step's own error (about vx·h = 0.17 m), so "linear drag" is no near thing.
     */
    @Test
    void theDragStopsNearestLandingIsMetresClearOfTheNext() {
        double[] landings = landings("Which sphere lands nearest", 3);
        double[] sorted = landings.clone();
        Arrays.sort(sorted);
        assertTrue(sorted[1] - sorted[0] > 1.0, Arrays.toString(landings));
        assertEquals(sorted[0], landings[answerTo("Which sphere lands nearest")]);
    }

    /** Likewise the thrust stop's two spheres: metres apart, the thruster the farther. */
    @Test
    void theThrustStopsFartherLandingIsMetresClearOfTheOther() {
        double[] landings = landings("Which sphere lands farther", 2);
        assertTrue(Math.abs(landings[1] - landings[0]) > 1.0, Arrays.toString(landings));
        assertEquals(landings[0] > landings[1] ? 0 : 1,
                answerTo("Which sphere lands farther"));
    }

    /**
     * The step {@code P += h·V} is exact for uniform motion: after 2 s the float sums of 120
     * steps stray at most 120 half-ulps of 8 m (6e-5 m) from the line, a sixteenth of "on"'s
     * millimetre, so "on" is no near thing and "behind" or "ahead" cannot be right.
     */
    @Test
    void theUniformStopsSphereIsOnTheLineWellInsideTheTolerance() {
        int stop = stopOf("After " + TourQuestions.UNIFORM_SECONDS + " s");
        DemoState demo = TourCommand.stateOf(stop);
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        while (demo.getClock().getSimulatedSeconds() < TourQuestions.UNIFORM_SECONDS) {
            demo.getRun().advancePhysics(1f / 60f);
        }
        com.jme3.math.Vector3f p = demo.getParticles().get(0).getParticle().position;
        com.jme3.math.Vector3f p0 = demo.getParticles().get(0)
                .copyLaunchPosition(new com.jme3.math.Vector3f());
        com.jme3.math.Vector3f v = demo.getParticles().get(0)
                .copyLaunchVelocity(new com.jme3.math.Vector3f());
        double t = demo.getClock().getSimulatedSeconds();
        double off = Math.hypot(p.x - (p0.x + v.x * t), p.y - (p0.y + v.y * t));
        assertTrue(off < TourQuestions.ON_LINE_METRES / 16, "off the line by " + off + " m");
        assertEquals(1, TourQuestions.forStop(stop).answer(TourCommand.stateOf(stop)));
        assertEquals(1, TourQuestions.forStop(stop).observe(demo));
    }

    /**
     * Issue 33's tour stop: the pull's rate lanes (30, 60, 144, 240 Hz), stepped without a
     * window. A level shot under raw tpf lands {@code vx·(1/f)} short of the parabola, so
     * 240 Hz lands farthest and each lane beyond the slower one by {@code vx·(1/f1 − 1/f2)}:
     * 0.17 m, 0.10 m, 0.03 m at vx = 10 m/s. The tolerance, 1 mm, is far above float
     * round-off of a 20 m landing (1e-5 m) and far below the smallest gap (0.03 m).
     */
    @Test
    void theRateStopsLanesLandByTheVxHLawAnd240HzFarthest() {
        String question = "Which monitor's lane";
        int stop = stopOf(question);
        DemoState demo = TourCommand.stateOf(stop);
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        RateLanes rates = ((GravitationalPullDemo) demo).getRates();
        for (int frame = 0; frame < 600; ++frame) {
            demo.getRun().advancePhysics(1f / 60f);
        }
        assertTrue(rates.isOn(), "the stop opens the lanes");
        DemoParameters parameters = demo.getParameters();
        double vx = parameters.getValue("speed")
                * Math.cos(Math.toRadians(parameters.getValue("angle")));
        for (int i = 1; i < RateLanes.RATES_HZ.length; ++i) {
            double gap = vx * (1.0 / RateLanes.RATES_HZ[i - 1] - 1.0 / RateLanes.RATES_HZ[i]);
            assertEquals(gap, rates.getRun(i).getLanding().getX()
                    - rates.getRun(i - 1).getLanding().getX(), 1e-3, "lane " + i);
        }
        int fastest = RateLanes.RATES_HZ.length - 1;
        assertEquals(fastest, TourQuestions.forStop(stop).observe(demo));
        assertEquals(fastest, answerTo(question));
    }

    /**
     * The wind stop's balls, stepped without a window: the headwind (−6 m/s) pulls the wind's
     * ball metres short of the still-air one, far more than the step's own error.
     */
    @Test
    void theWindStopsFartherLandingIsMetresClearOfTheOther() {
        double[] landings = landings("Which ball lands farther", 2);
        assertTrue(Math.abs(landings[1] - landings[0]) > 1.0, Arrays.toString(landings));
        assertEquals(landings[0] > landings[1] ? 0 : 1, answerTo("Which ball lands farther"));
    }

    /**
     * The undamped spring's step is stable while {@code h < 2/ω}: at the stop's h = 1/60 s and
     * ω = 12 /s that limit is ten times h, so "bounded" is no near thing; at h = 1/5 s it is
     * passed and the rule says the swing grows.
     */
    @Test
    void theSpringStopsStepIsFarInsideTheLimitAndAStepPastItGrows() {
        int stop = stopOf("At this step, does the undamped");
        DemoState demo = TourCommand.stateOf(stop);
        double omega = Math.sqrt(demo.getParameters().getValue("k") / SpringDemo.MASS_KG);
        double h = demo.getParameters().getValue("h");
        assertTrue(h < 0.2 * 2 / omega, "h " + h + ", 2/ω " + 2 / omega);
        assertEquals(0, TourQuestions.forStop(stop).answer(demo));
        DemoCommand.applySettings(demo, List.of("h=1/5"));
        assertEquals(1, TourQuestions.forStop(stop).answer(demo));
    }

    /**
     * Both arcs keep {@code vx = v·cos θ}: the direct arc's flight {@code S/(v·cos θ)} is the
     * shorter by more than a second at the height stop's target, so "direct" is no near thing.
     */
    @Test
    void theHeightStopsDirectArcArrivesSecondsFirst() {
        int stop = stopOf("Which arc reaches");
        AnyHeightDemo height = (AnyHeightDemo) TourCommand.stateOf(stop);
        LaunchAngles angles = LaunchAngles.solve(AnyHeightDemo.LAUNCH_SPEED,
                height.getTargetDistance(), height.getTargetHeight(), Gravity.STANDARD_G);
        double speed = AnyHeightDemo.LAUNCH_SPEED;
        double direct = height.getTargetDistance() / (speed * Math.cos(angles.getLowRadians()));
        double lob = height.getTargetDistance() / (speed * Math.cos(angles.getHighRadians()));
        assertTrue(lob - direct > 1.0, "direct " + direct + " s, lob " + lob + " s");
        assertEquals(0, TourQuestions.forStop(stop).answer(height));
    }

    /**
     * HelloAiming at vx = 21 m/s: the lecture's continuous formula lands about {@code vx·h}
     * (0.35 m) short, the discrete correction within a few centimetres (S/(vx·h) is not
     * whole, so its last step is interpolated): their misses differ by far more than
     * "the same"'s centimetre.
     */
    @Test
    void theAimingStopsCorrectionLandsFarNearer() {
        int stop = stopOf("Which aim lands nearer");
        DemoParameters parameters = TourCommand.stateOf(stop).getParameters();
        double shortfall = parameters.getValue("vx") * parameters.getValue("h");
        assertTrue(shortfall > 10 * TourQuestions.SAME_MISS_METRES, "vx·h " + shortfall);
        assertEquals(1, answerTo("Which aim lands nearer"));
    }

    /**
     * The iterate stop's search (bisection, quadratic drag), as the aim command runs it: the
     * count of shots, its answer, and the scene's own count once its round is over.
     */
    @Test
    void theIterateStopsSearchCountIsTheScenesCount() {
        int stop = stopOf("How many shots does the search");
        DemoState demo = TourCommand.stateOf(stop);
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        // A minute of frames: a search of a few shots of a few seconds each is over by then.
        for (int frame = 0; frame < 3600 && !((IterativeAimingDemo) demo).isRoundOver();
                ++frame) {
            demo.getRun().advancePhysics(1f / 60f);
        }
        IterativeAimingDemo iterate = (IterativeAimingDemo) demo;
        assertTrue(iterate.isRoundOver());
        assertEquals(iterate.getResult().getShots(), iterate.countLanded());
        assertEquals(TourQuestions.forStop(stop).answer(TourCommand.stateOf(stop)),
                TourQuestions.forStop(stop).observe(demo), "shots " + iterate.countLanded());
    }

    /**
     * The bounce stop (e = 0.9, the Box2D/Jolt threshold): the ball drops 4 m, hits at
     * {@code v0 = √(2·g·4)} = 8.85 m/s, each rebound e times the last, and rests at the first
     * impact slower than the threshold; the hops before it last {@code Σ 2·e^k·v0/g}. The
     * closed form's rest time, 15.2 s, is seconds clear of both 10 s and 30 s (the step moves
     * each impact by at most h, 21 impacts by 0.35 s), so "10 to 30 s" is no near thing.
     */
    @Test
    void theBounceStopsBallRestsSecondsClearOfBothBounds() {
        int stop = stopOf("With this e and threshold");
        BounceDemo bounce = (BounceDemo) TourCommand.stateOf(stop);
        double e = bounce.getRestitution();
        double g = Gravity.STANDARD_G;
        double v = Math.sqrt(2 * g * BounceDemo.DROP_HEIGHT);
        double rest = v / g;
        while (v >= bounce.getThresholdSpeed()) {
            v *= e;
            rest += 2 * v / g;
        }
        // The last hop added is the one the threshold stops: it is not flown.
        rest -= 2 * v / g;
        assertTrue(rest > TourQuestions.REST_SECONDS_BY[0] + 2
                && rest < TourQuestions.REST_SECONDS_BY[1] - 2, "rest at " + rest + " s");
        assertEquals(1, TourQuestions.forStop(stop).answer(bounce));
    }

    /**
     * The clip stop: at 12 m/s, e = 0.5, 1 kg on 2 kg, the head-on impulse leaves
     * {@code ½·1·144 − ½·(2/3)·0.75·144} = 36 J; the topple clip's first slopes, (−2, 1.2) and
     * (3, 0.5) m/s, carry {@code ½·1·5.44 + ½·2·9.25} = 11.97 J: three times apart.
     */
    @Test
    void theClipStopsPhysicsLaneKeepsThreeTimesTheClipsEnergy() {
        double physics = 0.5 * 144 - 0.5 * (2.0 / 3.0) * 0.75 * 144;
        double clip = 0.5 * 1 * (4 + 1.44) + 0.5 * 2 * (9 + 0.25);
        assertEquals(36.0, physics, 1e-12);
        assertTrue(physics > 2 * clip, physics + " J and " + clip + " J");
        assertEquals(0, answerTo("Which lane's pair"));
    }

    /**
     * The paddle stop: a ball at rest leaves an infinite-mass paddle at {@code (1+e)·u_n},
     * so the balls gain energy at e = 1 and even at e = 0.
     */
    @Test
    void thePaddleStopsBallsGainEnergyAtAnyE() {
        int stop = stopOf("In the paddle's hits");
        DemoState demo = TourCommand.stateOf(stop);
        assertEquals(2, TourQuestions.forStop(stop).answer(demo));
        DemoCommand.applySettings(demo, List.of("e=0"));
        assertEquals(2, TourQuestions.forStop(stop).answer(demo));
    }

    /**
     * The throw stop has no torque: ω stays ω0 and the exact rotation step turns by ω0·h
     * each step, θ = ω0·t to float round-off (1e-5 rad), "as far" within its 1e-3 rad. With
     * the key's torque the step runs {@code ½·(τ/I)·h·t} ahead, 0.019 rad after 1 s, nineteen
     * times the tolerance: "farther".
     */
    @Test
    void theThrowStopsBoxTurnsAsFarWithoutTorqueAndFartherWithIt() {
        int stop = stopOf("After " + TourQuestions.SPIN_SECONDS + " s, has the stepped box");
        SpinThrowDemo spin = (SpinThrowDemo) TourCommand.stateOf(stop);
        assertEquals(0f, spin.getTorque());
        assertEquals(1, TourQuestions.forStop(stop).answer(spin));
        spin.setTorqueChoice(1);
        double inertia = SpinThrowDemo.MASS_KG * (SpinThrowDemo.SIDES.x * SpinThrowDemo.SIDES.x
                + SpinThrowDemo.SIDES.y * SpinThrowDemo.SIDES.y) / 12.0;
        double gap = 0.5 * SpinThrowDemo.TORQUE / inertia
                * spin.getParameters().getValue("h") * TourQuestions.SPIN_SECONDS;
        assertTrue(gap > 10 * TourQuestions.SAME_ANGLE_RADIANS, "gap " + gap);
        assertEquals(2, TourQuestions.forStop(stop).answer(spin));
    }

    /**
     * The racket stop: both methods' bodies flip within a few seconds (steps 140 and 142 at
     * h = 1/60 s), far inside the question's 20 s, and with the gyroscopic term off neither
     * ever does.
     */
    @Test
    void theRacketStopsBodiesFlipEarlyAndNeverWithoutTheGyroscopicTerm() {
        int stop = stopOf("Spun near its middle axis");
        DemoState demo = TourCommand.stateOf(stop);
        float h = demo.getParameters().getValue("h");
        int limit = Math.round(TourQuestions.FLIP_SECONDS / h);
        assertTrue(TourQuestions.firstFlipStep(0, true, h) < limit / 4);
        assertTrue(TourQuestions.firstFlipStep(1, true, h) < limit / 4);
        assertEquals(0, TourQuestions.forStop(stop).answer(demo));
        assertEquals(Integer.MAX_VALUE, TourQuestions.firstFlipStep(0, false, h));
        assertEquals(Integer.MAX_VALUE, TourQuestions.firstFlipStep(1, false, h));
        DemoCommand.applySettings(demo, List.of("gyro=off"));
        assertEquals(1, TourQuestions.forStop(stop).answer(demo));
    }

    /**
     * The fountain stop: after 10 s the pool's live count has levelled off (what lands and
     * rests is reused as fast as it is emitted) near 89 % of it, far from both half and all.
     */
    @Test
    void theFountainStopsLiveShareIsFarFromHalfAndAll() {
        int stop = stopOf("After " + TourQuestions.FOUNTAIN_SECONDS + " s, how many");
        DemoState demo = TourCommand.stateOf(stop);
        int pool = demo.getRun().countSimulatedParticles();
        int live = TourQuestions.liveAfter(demo.getParameters().getValue("h"), pool);
        assertTrue(live > 0.6 * pool && live < 0.95 * pool, live + " of " + pool);
        assertEquals(1, TourQuestions.forStop(stop).answer(demo));
    }

    /**
     * The targets stop (aim 35° at 18 m/s from 1.2 m, the pane a ghost): the stepped shot's
     * samples lie exactly on the parabola launched with {@code vy − g·h/2} (NUMERICS.md),
     * its chords within {@code g·h²/8} (0.3 mm) of it. That path passes target 2's centre
     * 0.1 m and more inside the touching distance {@code r_shot + r_target} = 0.75 m, and
     * targets 1 and 3 more than a metre outside it, so "target 2" is no near thing; with the
     * pane solid the shot meets the pane first: "none".
     */
    @Test
    void theTargetsStopsShotHitsTargetTwoClearlyAndThePaneStopsIt() {
        int stop = stopOf("Which target does the shot hit");
        DemoState demo = TourCommand.stateOf(stop);
        DemoParameters parameters = demo.getParameters();
        double h = parameters.getValue("h");
        double g = Gravity.STANDARD_G;
        double radians = Math.toRadians(parameters.getValue("angle"));
        double vx = TargetsDemo.SHOT_SPEED * Math.cos(radians);
        double vy = TargetsDemo.SHOT_SPEED * Math.sin(radians) - 0.5 * g * h;
        double touch = TargetsDemo.SHOT_RADIUS + TargetsDemo.TARGET_RADIUS;
        double[] nearest = new double[TargetsDemo.TARGETS];
        Arrays.fill(nearest, Double.POSITIVE_INFINITY);
        com.jme3.math.Vector3f centre = new com.jme3.math.Vector3f();
        // Until it comes down to the ground: 1e-4 s apart, 1.5 mm of path.
        for (double t = 0; TargetsDemo.GUN_Y + vy * t - 0.5 * g * t * t > 0; t += 1e-4) {
            double x = vx * t;
            double y = TargetsDemo.GUN_Y + vy * t - 0.5 * g * t * t;
            for (int i = 0; i < nearest.length; ++i) {
                TargetsDemo.copyTargetCentre(i, centre);
                nearest[i] = Math.min(nearest[i], Math.hypot(x - centre.x, y - centre.y));
            }
        }
        assertTrue(nearest[1] < touch - 0.1, Arrays.toString(nearest));
        assertTrue(nearest[0] > touch + 1.0 && nearest[2] > touch + 1.0,
                Arrays.toString(nearest));
        assertEquals(1, TourQuestions.forStop(stop).answer(demo));
        DemoCommand.applySettings(demo, List.of("pane=solid"));
        assertEquals(3, TourQuestions.forStop(stop).answer(demo));
    }

    /**
     * Step a stop's demo without a window until its first spheres have landed.
     *
     * @return where each landed (m)
     */
    private static double[] landings(String questionStart, int count) {
        DemoState demo = TourCommand.stateOf(stopOf(questionStart));
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        // Ten seconds of frames: every sphere is down after a few.
        for (int frame = 0; frame < 600; ++frame) {
            demo.getRun().advancePhysics(1f / 60f);
        }
        double[] landings = new double[count];
        for (int i = 0; i < count; ++i) {
            assertTrue(demo.getParticles().get(i).hasLanded(), questionStart + " " + i);
            landings[i] = demo.getParticles().get(i).getLandingX();
        }
        return landings;
    }

    private static int answerTo(String questionStart) {
        int stop = stopOf(questionStart);
        return TourQuestions.forStop(stop).answer(TourCommand.stateOf(stop));
    }

    private static int stopOf(String questionStart) {
        for (int i = 0; i < TourQuestions.size(); ++i) {
            TourQuestion question = TourQuestions.forStop(i);
            if (question != null && question.getText().startsWith(questionStart)) {
                return i;
            }
        }
        throw new AssertionError("no question starts with " + questionStart);
    }
}

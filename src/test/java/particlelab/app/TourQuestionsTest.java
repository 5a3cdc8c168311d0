package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.aiming.Hitscan;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.lecture.FastBulletsDemo;
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
            demo.advancePhysics(1f / 60f);
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
     * Step a stop's demo without a window until its first spheres have landed.
     *
     * @return where each landed (m)
     */
    private static double[] landings(String questionStart, int count) {
        DemoState demo = TourCommand.stateOf(stopOf(questionStart));
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        // Ten seconds of frames: every sphere is down after a few.
        for (int frame = 0; frame < 600; ++frame) {
            demo.advancePhysics(1f / 60f);
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

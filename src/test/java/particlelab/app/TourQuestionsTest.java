package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.aiming.Hitscan;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.TunnellingDemo;
import particlelab.physics.Gravity;

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
            assertTrue(shortfall > 10 * TourQuestions.ON_METRES, "stop " + (i + 1) + ": " + shortfall);
            assertEquals("short", question.getAnswers().get(question.answer(
                    TourCommand.stateOf(i))), "stop " + (i + 1));
        }
        assertEquals(2, asked);
    }

    /** Plain Euler's det R grows by {@code 1 + (|ω|h)²} a step: 1.01¹⁰⁰ = 2.70 at stop 13. */
    @Test
    void theRotationStopsDeterminantIsFarAboveOne() {
        int stop = stopOf("After ");
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

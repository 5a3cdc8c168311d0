package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.demo.DemoState;
import particlelab.physics.SimulationClock;

/**
 * Issue 34 §1, predict then reveal: every stop with a question is opened in a real headless
 * window, its scene run until its own numbers show the answer, and that answer must be the one
 * {@code tour --questions} works out for the same state with the command-line tools' code
 * ({@link TourCommand#stateOf}). So the window's reveal and the printed key cannot disagree.
 */
class TourQuestionsHeadlessTest {

    /** The frames a scene gets to show its answer: 60 s at 60 frames a second. */
    private static final int MAX_FRAMES = 3600;
    private static final float TPF = 1f / 60f;
    /** The frames one call on the jME thread runs. */
    private static final int FRAMES_PER_CALL = 10;

    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void everyStopsSceneShowsTheAnswerTheCommandLineWorksOut() throws Exception {
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        int asked = 0;
        for (int i = 0; i < LectureTour.stops().size(); ++i) {
            TourQuestion question = TourQuestions.forStop(i);
            if (question == null) {
                continue;
            }
            ++asked;
            int index = i;
            int expected = question.answer(TourCommand.stateOf(i));
            harness.call(() -> {
                app.getTour().go(index);
                return true;
            });
            // The switch to the stop's demo happens in a frame's update.
            harness.awaitFrames(2);
            int observed = TourQuestion.UNDECIDED;
            int frames = 0;
            // A second of frames a call, so no call outlasts the harness's wait.
            while (observed == TourQuestion.UNDECIDED && frames < MAX_FRAMES) {
                observed = harness.call(() -> flyUntilShown(app.getSwitcher().getSelected(),
                        question));
                frames += FRAMES_PER_CALL;
            }
            if (observed != expected) {
                problems.add("stop " + (i + 1) + " \"" + question.getText() + "\": the scene"
                        + " showed " + (observed < 0 ? "nothing" : question.getAnswers()
                        .get(observed)) + " within " + frames + " frames, the command line "
                        + question.getAnswers().get(expected));
            }
        }
        harness.call(() -> {
            app.getTour().leave();
            return true;
        });
        assertEquals(List.of(), problems, asked + " stops asked");
    }

    /**
     * Run a second of frames, stopping at the first that shows the answer. Call on the jME
     * thread.
     */
    private static int flyUntilShown(DemoState demo, TourQuestion question) {
        // Setting the mode drops the clock's leftover time: at h = 1/10 s a frame of 1/60 s
        // would never make a step if it were set before every frame.
        if (demo.getClock().getMode() != SimulationClock.Mode.FIXED_STEP) {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        }
        demo.getClock().setPaused(false);
        for (int frame = 0; frame < FRAMES_PER_CALL; ++frame) {
            demo.update(TPF);
            int observed = question.observe(demo);
            if (observed != TourQuestion.UNDECIDED) {
                return observed;
            }
        }
        return TourQuestion.UNDECIDED;
    }
}

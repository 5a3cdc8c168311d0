package particlelab.app;

import com.jme3.input.KeyInput;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.HudNote;
import particlelab.demo.KeyBinding;
import particlelab.view.ScreenRect;

/**
 * Walks the {@link LectureTour} in the window: a stop selects its demo, puts every parameter
 * of it back to its default, applies the stop's settings (as {@code --set} does) and shows
 * the stop's heading and "what to watch for" under the demo's HUD, and its number and slide
 * after the demo's title ("1/23 Collision Response", in presentation mode too). PageDown and
 * PageUp go forward and back; F7 starts the tour at its first stop, or leaves it. The keys are
 * the application's, listed in every demo's help.
 *
 * <p>F4 asks the stop's question (issue 34, predict then reveal): the demo starts again and
 * freezes, the question is shown in large type ({@link QuestionOverlay}) and the digit keys 1
 * to 4 count the room's votes instead of choosing a demo; F4 again runs the scene until its
 * own numbers show the answer, then pauses and reveals it with the stop's watch lines and the
 * vote's split, and writes the votes CSV if {@code tour --votes} named one; F4 once more
 * closes it.
 */
final class TourGuide {

    /** The stop index while not touring. */
    static final int NOT_TOURING = -1;

    private final DemoSwitcher switcher;
    /** Per stop: its heading, then its watch lines. */
    private final List<HudNote> notes = new ArrayList<>();
    private final List<KeyBinding> bindings = new ArrayList<>();
    private int stop = NOT_TOURING;
    /** The question asked at this stop, or null. */
    private TourVote vote;
    /**
     * The stop's demo while its question is asked, found by name once, when asked: {@link
     * DemoCatalog#indexOf} makes a string per demo it passes, too much for {@link
     * #updateVote} to call every frame.
     */
    private DemoState voteDemo;
    /** True once F4 ran the scene of the question asked. */
    private boolean voteRunning;
    /** The answer the scene showed (from 0), once revealed. */
    private int observed = TourQuestion.UNDECIDED;
    /** Changes whenever the question's text does, for the overlay. */
    private int voteVersion;
    /** The reveal: the answer, the stop's watch lines then, the split (built once). */
    private final StringBuilder revealText = new StringBuilder();
    /** Where the votes go, or null for nowhere. */
    private VotesFile votesFile;

    /**
     * Create the guide.
     *
     * @param switcher the window's demos, in {@link DemoCatalog} order (not null)
     */
    TourGuide(DemoSwitcher switcher) {
        this.switcher = switcher;
        List<LectureTour.Stop> stops = LectureTour.stops();
        for (int i = 0; i < stops.size(); ++i) {
            int index = i;
            HudNote watch = stops.get(i).getWatch();
            notes.add((demo, text) -> {
                LectureTour.appendHeading(text, index);
                watch.append(demo, text);
            });
        }
        int count = stops.size();
        bindings.add(new KeyBinding(KeyInput.KEY_PGDN, "PageDown",
                "lecture tour: next stop (slide)",
                () -> go(stop < 0 ? 0 : Math.min(count - 1, stop + 1))));
        bindings.add(new KeyBinding(KeyInput.KEY_PGUP, "PageUp",
                "lecture tour: previous stop", () -> go(stop < 0 ? 0 : Math.max(0, stop - 1))));
        bindings.add(new KeyBinding(KeyInput.KEY_F7, "F7",
                "lecture tour: start at stop 1 (" + count + " stops, lecture 15) / leave it",
                () -> {
                    if (stop < 0) {
                        go(0);
                    } else {
                        leave();
                    }
                }));
        bindings.add(new KeyBinding(KeyInput.KEY_F4, "F4",
                "tour question: ask it (scene frozen, 1-4 vote) -> run the scene and reveal"
                        + " the answer -> close", this::advanceQuestion));
        switcher.setDigitFilter(this::takeDigit);
    }

    /**
     * Return the guide's keys, for the application's list.
     *
     * @return an unmodifiable list (not null)
     */
    List<KeyBinding> getBindings() {
        return Collections.unmodifiableList(bindings);
    }

    /** @return the stop shown (from 0), or {@link #NOT_TOURING} */
    int getStop() {
        return stop;
    }

    /**
     * Go to a stop: its demo, its state, its lines on the HUD.
     *
     * @param index the stop (from 0, less than the stops' count)
     * @throws UsageException if a stop's setting is refused (a test checks none is)
     */
    void go(int index) {
        List<LectureTour.Stop> stops = LectureTour.stops();
        if (index < 0 || index >= stops.size()) {
            throw new IllegalArgumentException("tour stop index must be from 0 to "
                    + (stops.size() - 1) + ", but was " + index);
        }
        if (switcher.getDemos().size() != DemoCatalog.names().size()) {
            // A window on a few demos (a test's) has not every stop's demo.
            switcher.getSelected().getDemoHud().showNotice("the lecture tour needs every demo: run"
                    + " particle-lab tour or particle-lab demo");
            return;
        }
        leave();
        LectureTour.Stop next = stops.get(index);
        int demoIndex = DemoCatalog.indexOf(next.getDemo());
        DemoState demo = switcher.getDemos().get(demoIndex);
        DemoParameters parameters = demo.getParameters();
        for (int i = 0; i < parameters.size(); ++i) {
            parameters.set(i, parameters.get(i).getDefault());
        }
        DemoCommand.applySettings(demo, next.getSettings());
        if (parameters.isStarted()) {
            // A launch value waits for the next launch: the stop starts from the launch.
            demo.restart();
        }
        // A restart keeps the launch before it as a faint path: at a stop, the stop before's
        // flights (another h, a lane switched off here) would be drawn as this stop's.
        demo.getWindow().clearKeptShots();
        demo.getDemoHud().setNote(notes.get(index));
        // The title names the stop in both modes: presentation mode shows no heading line.
        demo.getDemoHud().setTitleNote(LectureTour.titleNote(index));
        switcher.select(demoIndex);
        stop = index;
    }

    /**
     * Write the lecture's votes to a file (a row at each reveal).
     *
     * @param file the file, or null for none
     */
    void setVotesFile(VotesFile file) {
        votesFile = file;
    }

    /** @return the question asked at this stop, or null */
    TourVote getVote() {
        return vote;
    }

    /** @return true once the asked question's scene runs (or ran) */
    boolean isVoteRunning() {
        return voteRunning;
    }

    /**
     * Copy where the shown demo's scene is on the screen, for the reveal's layout.
     *
     * @param storeResult storage (not null, modified)
     * @return storeResult
     */
    ScreenRect getSceneRect(ScreenRect storeResult) {
        return switcher.getSelected().getWindow().copySceneRect(storeResult);
    }

    /** @return a number that changes whenever the question's text changes */
    int getVoteVersion() {
        return voteVersion;
    }

    /**
     * Write the question's large text: while the room votes, the question and the counts;
     * once revealed, the answer, the stop's watch lines as the scene showed them, the split.
     *
     * @param text where to append (not null, modified)
     * @return text
     */
    StringBuilder appendVote(StringBuilder text) {
        if (vote == null) {
            return text;
        }
        if (vote.isRevealed()) {
            return text.append(revealText);
        }
        vote.appendAsked(text);
        int answers = vote.getQuestion().getAnswers().size();
        if (voteRunning) {
            return text.append("the scene runs until it shows the answer...");
        }
        return text.append("keys 1-").append(answers).append(" count the votes (")
                .append(vote.countVotes()).append(" so far);  F4 runs the scene and reveals");
    }

    /**
     * F4: ask this stop's question, run its scene, or close the answer.
     */
    void advanceQuestion() {
        DemoState demo = switcher.getSelected();
        if (stop < 0) {
            demo.getDemoHud().showNotice("F4 asks a tour stop's question: start the tour with F7");
            return;
        }
        TourQuestion question = TourQuestions.forStop(stop);
        if (question == null) {
            demo.getDemoHud().showNotice("stop " + (stop + 1) + " has no question yet");
            return;
        }
        DemoState stopDemo = switcher.getDemos().get(DemoCatalog.indexOf(
                LectureTour.stops().get(stop).getDemo()));
        if (demo != stopDemo) {
            // PageDown and F4 in one frame: the stop's demo is shown from the next frame on.
            // Otherwise Tab or a digit switched away: the question is about the stop's scene,
            // and this demo has none of its parameters ("no parameter named e" closed the
            // window, issue 36).
            demo.getDemoHud().showNotice(switcher.isSwitchPending()
                    ? "the stop is still opening: press F4 again"
                    : "F4 asks stop " + (stop + 1) + "'s question in " + stopDemo.getTitle()
                            + ": go back to it first");
            return;
        }
        if (vote == null) {
            // Start the scene again and hold it at its start: nothing shown gives it away.
            demo.restart();
            demo.getClock().setPaused(true);
            vote = new TourVote(stop, question, question.answer(demo));
            voteDemo = stopDemo;
            voteRunning = false;
            observed = TourQuestion.UNDECIDED;
        } else if (!voteRunning) {
            voteRunning = true;
            demo.getClock().setPaused(false);
        } else if (vote.isRevealed()) {
            vote = null;
        } else {
            demo.getDemoHud().showNotice("the scene has not shown the answer yet");
            return;
        }
        ++voteVersion;
    }

    /**
     * Each frame: once the running scene shows the answer, pause it there, reveal, and write
     * the votes. Allocates nothing until the reveal.
     */
    void updateVote() {
        if (vote == null) {
            return;
        }
        DemoState demo = switcher.getSelected();
        if (demo != voteDemo) {
            // Another demo was chosen (Tab): the question is dropped.
            vote = null;
            ++voteVersion;
            return;
        }
        if (!voteRunning || vote.isRevealed()) {
            return;
        }
        observed = vote.getQuestion().observe(demo);
        if (observed == TourQuestion.UNDECIDED) {
            return;
        }
        demo.getClock().setPaused(true);
        vote.reveal();
        TourQuestion question = vote.getQuestion();
        int right = vote.getRight();
        revealText.setLength(0);
        revealText.append("Stop ").append(stop + 1).append(": ").append(question.getText())
                .append("   Answer: ").append(right + 1).append(' ')
                .append(question.getAnswers().get(right));
        if (observed != right) {
            revealText.append("  (the scene showed ").append(observed + 1).append(' ')
                    .append(question.getAnswers().get(observed)).append(')');
        }
        revealText.append('\n');
        LectureTour.stops().get(stop).getWatch().append(demo, revealText);
        vote.appendSplit(revealText);
        // The split's line ends with the keys: one line less over the window.
        revealText.setLength(revealText.length() - 1);
        revealText.append("    F4 closes, Space runs on");
        if (votesFile != null) {
            try {
                votesFile.record(vote);
            } catch (IOException e) {
                demo.getDemoHud().showNotice("votes not written: " + e.getMessage());
            }
        }
        ++voteVersion;
    }

    /**
     * A digit key while a question waits for votes: 1 to the answers' count votes, any other
     * digit does nothing (the demo keys wait until the answer is revealed).
     *
     * @return true if the digit was taken
     */
    private boolean takeDigit(int digit) {
        if (vote == null || vote.isRevealed() || voteRunning) {
            return vote != null && !vote.isRevealed();
        }
        if (!vote.vote(digit - 1)) {
            switcher.getSelected().getDemoHud().showNotice("keys 1-"
                    + vote.getQuestion().getAnswers().size()
                    + " vote while the question is open; F4 runs the scene");
            return true;
        }
        ++voteVersion;
        return true;
    }

    /** Leave the tour: the stop's lines go from its demo's HUD; the demo stays as it is. */
    void leave() {
        if (vote != null) {
            vote = null;
            ++voteVersion;
        }
        if (stop >= 0) {
            int demoIndex = DemoCatalog.indexOf(LectureTour.stops().get(stop).getDemo());
            switcher.getDemos().get(demoIndex).getDemoHud().setNote(null);
            switcher.getDemos().get(demoIndex).getDemoHud().setTitleNote(null);
        }
        stop = NOT_TOURING;
    }
}

package particlelab.app;

import java.util.List;
import particlelab.demo.DemoState;

/**
 * A tour stop's question for the room (issue 34, "predict, then reveal"): its text, two to
 * four answers, the rule that works out the right one from the stop's state with the project's
 * own physics code (what {@code tour --questions} prints, no window needed), and the outcome
 * read from the running demo's own numbers (what the room sees once the scene runs). A test
 * runs every stop headless and checks the two agree.
 */
public final class TourQuestion {

    /** Works out the right answer from the stop's state, without running the demo. */
    @FunctionalInterface
    public interface Rule {

        /**
         * Work out the right answer.
         *
         * @param demo the stop's demo with the stop's settings applied (not null; read only:
         *     its parameters and constants, not its scene, which may not exist yet)
         * @return the right answer's index (from 0)
         */
        int answer(DemoState demo);
    }

    /** Reads the answer off the running demo, from the numbers its HUD shows. */
    @FunctionalInterface
    public interface Outcome {

        /**
         * Read the answer the scene has shown so far, allocating nothing.
         *
         * @param demo the stop's running demo (not null, not modified)
         * @return the answer's index (from 0), or {@link #UNDECIDED} while the scene has not
         *     shown it yet
         */
        int observe(DemoState demo);
    }

    /** What {@link Outcome#observe} returns while the scene has not shown the answer yet. */
    public static final int UNDECIDED = -1;
    /** The fewest answers a question offers. */
    public static final int MIN_ANSWERS = 2;
    /** The most answers a question offers: keys 1 to 4 vote. */
    public static final int MAX_ANSWERS = 4;

    private final String text;
    private final List<String> answers;
    private final Rule rule;
    private final Outcome outcome;

    /**
     * Declare a question.
     *
     * @param text the question, one line ending in "?" (not null)
     * @param rule works out the right answer from the stop's state (not null)
     * @param outcome reads the answer off the running demo (not null)
     * @param answers two to four short answers, all different (not null)
     */
    TourQuestion(String text, Rule rule, Outcome outcome, String... answers) {
        if (text == null || !text.endsWith("?") || text.indexOf('\n') >= 0) {
            throw new IllegalArgumentException("a question must be one line ending in '?',"
                    + " but was " + text);
        }
        if (answers.length < MIN_ANSWERS || answers.length > MAX_ANSWERS) {
            throw new IllegalArgumentException("a question takes " + MIN_ANSWERS + " to "
                    + MAX_ANSWERS + " answers, but had " + answers.length);
        }
        if (List.of(answers).stream().distinct().count() != answers.length) {
            throw new IllegalArgumentException("the answers of \"" + text
                    + "\" must all differ, but were " + List.of(answers));
        }
        this.text = text;
        this.rule = rule;
        this.outcome = outcome;
        this.answers = List.of(answers);
    }

    /** @return the question, one line ending in "?" (not null) */
    public String getText() {
        return text;
    }

    /** @return the answers, in the order keys 1 to 4 vote for them (not null, unmodifiable) */
    public List<String> getAnswers() {
        return answers;
    }

    /**
     * Work out the right answer for the stop's state.
     *
     * @param demo the stop's demo with the stop's settings applied (not null)
     * @return the right answer's index (from 0, less than the answers' count)
     */
    public int answer(DemoState demo) {
        int index = rule.answer(demo);
        if (index < 0 || index >= answers.size()) {
            throw new IllegalStateException("the rule of \"" + text + "\" gave answer "
                    + index + ", not one of 0 to " + (answers.size() - 1));
        }
        return index;
    }

    /**
     * Read the answer off the running demo.
     *
     * @param demo the stop's running demo (not null)
     * @return the answer's index (from 0), or {@link #UNDECIDED}
     */
    public int observe(DemoState demo) {
        return outcome.observe(demo);
    }

    /**
     * Write the question as {@code tour --questions} prints it: "8   Euler lands short, on or
     * long of the exact landing? 1 short | 2 on | 3 long: 1 short".
     *
     * @param number the stop's number (from 1)
     * @param right the right answer's index (from 0)
     * @return the line (not null)
     */
    public String describe(int number, int right) {
        StringBuilder line = new StringBuilder();
        line.append(number).append(number < 10 ? "   " : "  ").append(text);
        for (int i = 0; i < answers.size(); ++i) {
            line.append(i == 0 ? " " : " | ").append(i + 1).append(' ').append(answers.get(i));
        }
        return line.append(": ").append(right + 1).append(' ').append(answers.get(right))
                .toString();
    }
}

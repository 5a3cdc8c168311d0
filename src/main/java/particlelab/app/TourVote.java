package particlelab.app;

import java.util.List;
import particlelab.view.TextFormat;

/**
 * One tour stop's vote (issue 34 §1, predict then reveal): the stop's question, the room's
 * count per answer, the answer that is right for the stop's state ({@code tour --questions}'
 * key), and whether the scene has shown it yet. Written as the large text the window shows
 * and as a row of the lecture's votes CSV. No jME: a test votes without a window.
 */
final class TourVote {

    /** The votes CSV's header: one row per revealed question. */
    static final String CSV_HEADER = "stop,question,answers,counts,correct";
    /** Between two answers, or two counts, in a CSV cell. */
    static final String CSV_SEPARATOR = "|";

    private final int stop;
    private final TourQuestion question;
    private final int right;
    private final int[] counts;
    private boolean revealed;

    /**
     * Open a vote.
     *
     * @param stop the stop (from 0)
     * @param question its question (not null)
     * @param right the right answer for the stop's state (from 0)
     */
    TourVote(int stop, TourQuestion question, int right) {
        this.stop = stop;
        this.question = question;
        this.right = right;
        this.counts = new int[question.getAnswers().size()];
    }

    /** @return the stop (from 0) */
    int getStop() {
        return stop;
    }

    /** @return the question (not null) */
    TourQuestion getQuestion() {
        return question;
    }

    /** @return the right answer's index (from 0) */
    int getRight() {
        return right;
    }

    /**
     * Count one vote, until the answer is revealed.
     *
     * @param answer the answer's index (from 0)
     * @return true if it was counted, false if there is no such answer or the vote is over
     */
    boolean vote(int answer) {
        if (revealed || answer < 0 || answer >= counts.length) {
            return false;
        }
        ++counts[answer];
        return true;
    }

    /**
     * Return one answer's votes.
     *
     * @param answer the answer's index (from 0)
     * @return the count (&ge;0)
     */
    int getCount(int answer) {
        return counts[answer];
    }

    /** @return the votes cast (&ge;0) */
    int countVotes() {
        int total = 0;
        for (int count : counts) {
            total += count;
        }
        return total;
    }

    /** The scene has shown the answer: the vote is over. */
    void reveal() {
        revealed = true;
    }

    /** @return true once the scene has shown the answer */
    boolean isRevealed() {
        return revealed;
    }

    /**
     * Write what the window shows while the room votes: the question, then each answer with
     * its key and its votes so far.
     *
     * @param text where to append (not null, modified)
     * @return text
     */
    StringBuilder appendAsked(StringBuilder text) {
        text.append("Stop ").append(stop + 1).append(": ").append(question.getText())
                .append('\n');
        List<String> answers = question.getAnswers();
        for (int i = 0; i < answers.size(); ++i) {
            text.append(i == 0 ? "" : "     ").append(i + 1).append("  ")
                    .append(answers.get(i)).append(":  ").append(counts[i]);
        }
        return text.append('\n');
    }

    /**
     * Write the split of the votes: each answer's count and share, the right one marked.
     *
     * @param text where to append (not null, modified)
     * @return text
     */
    StringBuilder appendSplit(StringBuilder text) {
        int total = countVotes();
        List<String> answers = question.getAnswers();
        text.append("the room (").append(total).append(total == 1 ? " vote):" : " votes):");
        for (int i = 0; i < answers.size(); ++i) {
            text.append(i == 0 ? "  " : "   ").append(i == right ? "[" : "").append(i + 1)
                    .append(' ').append(answers.get(i)).append(i == right ? "]" : "")
                    .append(' ').append(counts[i]).append(" (");
            TextFormat.appendFixed(text, total == 0 ? 0.0 : 100.0 * counts[i] / total, 0)
                    .append(" %)");
        }
        return text.append('\n');
    }

    /**
     * Write the vote as a row of the votes CSV ({@link #CSV_HEADER}): the stop's number, the
     * question, its answers and counts each joined by {@value #CSV_SEPARATOR}, the right
     * answer; a cell with a comma or a quote is quoted.
     *
     * @return the row, without a line break (not null)
     */
    String toCsvRow() {
        StringBuilder countsCell = new StringBuilder();
        for (int i = 0; i < counts.length; ++i) {
            countsCell.append(i == 0 ? "" : CSV_SEPARATOR).append(counts[i]);
        }
        return (stop + 1) + "," + csvCell(question.getText()) + ","
                + csvCell(String.join(CSV_SEPARATOR, question.getAnswers())) + ","
                + countsCell + "," + csvCell(question.getAnswers().get(right));
    }

    /** @return the cell, quoted (quotes doubled) if it holds a comma, a quote or a break */
    static String csvCell(String cell) {
        if (cell.indexOf(',') < 0 && cell.indexOf('"') < 0 && cell.indexOf('\n') < 0) {
            return cell;
        }
        return '"' + cell.replace("\"", "\"\"") + '"';
    }
}

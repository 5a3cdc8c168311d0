package particlelab.grading;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Runs each exercise's checks on a submission and prints the table: exercise, slide, points,
 * passed or failed, and for a failure one line naming the mistake; the last line is
 * {@code score: X/Y}. {@code gradle grade} runs it on the exercises, {@code -Psolutions} on the
 * reference solutions, {@code -Pexercise=N} on one exercise.
 */
public final class Grader {

    /** A check that has not returned after this long has failed (its thread is left behind). */
    static final long CHECK_LIMIT_MILLIS = 10_000L;
    /** What a stub throws; shown as it is. */
    static final String NOT_WRITTEN = "not written yet";

    /**
     * One check's outcome.
     *
     * @param exercise the exercise
     * @param check the check
     * @param mistake null when it passed, else one line naming the mistake
     */
    public record Result(Exercise exercise, Check check, String mistake) {
        /** @return whether the check passed */
        public boolean passed() {
            return mistake == null;
        }
    }

    private Grader() {
    }

    /**
     * The command: {@code Grader PACKAGE [EXERCISE]}.
     *
     * @param args the package graded and optionally one exercise's number
     */
    public static void main(String[] args) {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: Grader PACKAGE [EXERCISE NUMBER 1-" + Exercises.ALL.size()
                    + "]");
            System.exit(2);
        }
        int only = 0;
        if (args.length == 2) {
            only = parseExercise(args[1]);
            if (only == 0) {
                System.err.println("-Pexercise=" + args[1] + ": expected an exercise number"
                        + " from 1 to " + Exercises.ALL.size());
                System.exit(2);
            }
        }
        print(grade(new Submission(args[0]), only), System.out);
        // A student's check that never returned leaves a thread behind: end regardless.
        System.exit(0);
    }

    /**
     * Runs the checks.
     *
     * @param submission the classes graded
     * @param only an exercise's number, or 0 for all
     * @return every check's outcome, in order
     */
    public static List<Result> grade(Submission submission, int only) {
        return grade(submission, only, CHECK_LIMIT_MILLIS);
    }

    /** As {@link #grade(Submission, int)}, a check failing after {@code limitMillis} ms. */
    static List<Result> grade(Submission submission, int only, long limitMillis) {
        List<Result> results = new ArrayList<>();
        for (Exercise exercise : Exercises.ALL) {
            if (only != 0 && exercise.number() != only) {
                continue;
            }
            for (Check check : exercise.checks()) {
                results.add(new Result(exercise, check, run(check, submission, limitMillis)));
            }
        }
        return results;
    }

    /**
     * Prints the table and the score.
     *
     * @param results the outcomes, grouped by exercise
     * @param out where to print
     */
    public static void print(List<Result> results, PrintStream out) {
        out.println(" #  exercise       slide                    points  result");
        int score = 0;
        int total = 0;
        int i = 0;
        while (i < results.size()) {
            Exercise exercise = results.get(i).exercise();
            int points = 0;
            int max = 0;
            String firstMistake = null;
            for (; i < results.size() && results.get(i).exercise() == exercise; ++i) {
                Result result = results.get(i);
                ++max;
                if (result.passed()) {
                    ++points;
                } else if (firstMistake == null) {
                    firstMistake = result.mistake().equals(NOT_WRITTEN) ? NOT_WRITTEN
                            : result.check().name() + ": " + result.mistake();
                }
            }
            score += points;
            total += max;
            out.println(String.format(Locale.ROOT, "%2d  %-13s  %-24s %3d/%-3d %s",
                    exercise.number(), exercise.className(), exercise.slide(), points, max,
                    points == max ? "passed" : "failed"));
            if (firstMistake != null) {
                out.println("    " + firstMistake);
            }
        }
        out.println("score: " + score + "/" + total);
    }

    /** The check's mistake in one line, or null when it passed. */
    private static String run(Check check, Submission submission, long limitMillis) {
        String[] outcome = new String[1];
        Thread thread = new Thread(() -> outcome[0] = runHere(check, submission),
                "check " + check.name());
        thread.setDaemon(true);
        thread.start();
        try {
            thread.join(limitMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
        if (thread.isAlive()) {
            return "did not return within " + limitMillis / 1000.0 + " s: an endless loop?";
        }
        return outcome[0];
    }

    private static String runHere(Check check, Submission submission) {
        try {
            check.body().run(submission);
            return null;
        } catch (Mistake mistake) {
            return mistake.getMessage();
        } catch (UnsupportedOperationException e) {
            if (NOT_WRITTEN.equals(e.getMessage())) {
                return NOT_WRITTEN;
            }
            return thrown(e, submission);
        } catch (Throwable e) {
            return thrown(e, submission);
        }
    }

    /** "threw X: message (File.java:line)", the line the first in the submission's package. */
    private static String thrown(Throwable e, Submission submission) {
        Throwable cause = e;
        while (cause instanceof ReflectiveOperationException && cause.getCause() != null) {
            cause = cause.getCause();
        }
        StringBuilder line = new StringBuilder("threw ").append(cause.getClass().getSimpleName());
        if (cause.getMessage() != null) {
            line.append(": ").append(cause.getMessage());
        }
        String prefix = submission.getPackageName() + ".";
        for (StackTraceElement frame : cause.getStackTrace()) {
            if (frame.getClassName().startsWith(prefix)) {
                line.append(" (").append(frame.getFileName()).append(':')
                        .append(frame.getLineNumber()).append(')');
                break;
            }
        }
        return line.toString();
    }

    private static int parseExercise(String text) {
        try {
            int number = Integer.parseInt(text.trim());
            return number >= 1 && number <= Exercises.ALL.size() ? number : 0;
        } catch (NumberFormatException e) {
            return 0;
        }
    }
}

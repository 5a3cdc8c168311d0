package particlelab.grading;

/**
 * One graded test of an exercise, worth one point.
 *
 * @param name a short name, shown with a failure
 * @param body the test: returns when it passes, throws a {@link Mistake} when it fails
 */
public record Check(String name, Body body) {

    /** A check's test, run on a submission. */
    @FunctionalInterface
    public interface Body {
        /**
         * Runs the test.
         *
         * @param submission the classes graded (not null)
         * @throws Exception anything the student's code throws
         */
        void run(Submission submission) throws Exception;
    }
}

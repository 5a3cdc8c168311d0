package particlelab.grading;

/** A check's failure, named in the lecture's words; the grader prints its message alone. */
public final class Mistake extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /**
     * A failure.
     *
     * @param lectureWords one line naming the mistake (not null)
     */
    public Mistake(String lectureWords) {
        super(lectureWords, null, false, false);
    }
}

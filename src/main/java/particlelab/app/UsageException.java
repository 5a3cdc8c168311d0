package particlelab.app;

/**
 * A bad command line: an unknown option, a missing or malformed value, a value out of range, a
 * target out of reach. Its message is one line that names the option, the bad value and what is
 * allowed, e.g. {@code --mass: must be a finite number > 0, but was -1}; the command prints it
 * to stderr and exits with {@link #EXIT_CODE}, with no stack trace.
 */
public final class UsageException extends RuntimeException {

    /** The exit code of a command that stops on a bad command line. */
    public static final int EXIT_CODE = 2;

    private static final long serialVersionUID = 1L;

    /**
     * Create an exception.
     *
     * @param oneLineMessage what is wrong and what is allowed (not null, no line break)
     */
    public UsageException(String oneLineMessage) {
        super(oneLineMessage);
    }
}

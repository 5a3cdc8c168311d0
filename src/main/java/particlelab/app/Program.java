package particlelab.app;

/**
 * The launcher's name and its exit statuses, held once: every command, the help and the tests
 * read them here.
 */
public final class Program {

    /** The launcher's name, as the installed script calls it. */
    public static final String NAME = "particle-lab";
    /** Exit status: success. */
    public static final int OK = 0;
    /**
     * Exit status: the run could not finish: the window could not run (no display, no OpenGL,
     * a crash), the output could not be written (stdout closed or full), the report's
     * headless part failed, a replayed recording diverged ({@code demo --replay}), or a bug
     * (reported in one line).
     */
    public static final int FAILED = 1;
    /** Exit status: a bad command line, reported in one line on stderr; nothing is created. */
    public static final int USAGE = 2;

    private Program() {
    }
}

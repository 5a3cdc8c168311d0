package particlelab.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;

/**
 * What the window says when something throws on its render thread: one line naming the
 * exception, its message and the project's frame it came from, and the whole stack in a log
 * file of its own (a new file for each run, never one written before), whose path the line
 * names.
 */
final class CrashLog {

    /** A system property naming the logs' folder (unset: the system's temporary folder). */
    static final String FOLDER_PROPERTY = "particlelab.logs";
    /** The project's classes: the frame the line names is the first of these. */
    private static final String PROJECT_PACKAGE = "particlelab.";

    private CrashLog() {
    }

    /**
     * Describe a failure in one line: the exception's simple name, its message (on one line)
     * and the first stack frame in the project's own code (or the top frame if none is).
     *
     * @param failure the exception (not null)
     * @return the line, without the log's path (not null)
     */
    static String describe(Throwable failure) {
        StringBuilder line = new StringBuilder(failure.getClass().getSimpleName());
        String message = failure.getMessage();
        if (message != null && !message.trim().isEmpty()) {
            line.append(": ").append(message.trim().replace('\n', ' '));
        }
        StackTraceElement where = projectFrame(failure);
        if (where != null) {
            line.append(" at ").append(where);
        }
        return line.toString();
    }

    /**
     * Write a failure's whole stack to a new log file.
     *
     * @param context what failed, the log's first line (not null)
     * @param failure the exception (not null)
     * @return the new file, or null if none could be written
     */
    static Path write(String context, Throwable failure) {
        String folder = System.getProperty(FOLDER_PROPERTY, System.getProperty("java.io.tmpdir"));
        StringWriter text = new StringWriter();
        PrintWriter out = new PrintWriter(text);
        out.println(context);
        failure.printStackTrace(out);
        out.flush();
        try {
            // createTempFile makes a file that did not exist: no earlier run's log is replaced.
            Path log = Files.createTempFile(Paths.get(folder), "particle-lab-", ".log");
            Files.write(log, text.toString().getBytes(StandardCharsets.UTF_8));
            return log;
        } catch (IOException | RuntimeException unwritable) {
            return null;
        }
    }

    /**
     * The first frame in the project's code outside the window's loop, the top one if none,
     * or null if the stack is empty.
     */
    private static StackTraceElement projectFrame(Throwable failure) {
        StackTraceElement[] stack = failure.getStackTrace();
        for (StackTraceElement frame : stack) {
            // The window's own loop (ParticleLabApp.update) is on every frame's stack: it is
            // where the failure was caught, not where it came from.
            if (frame.getClassName().startsWith(PROJECT_PACKAGE)
                    && !frame.getClassName().equals(ParticleLabApp.class.getName())) {
                return frame;
            }
        }
        return stack.length == 0 ? null : stack[0];
    }
}

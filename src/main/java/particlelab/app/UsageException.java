package particlelab.app;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/**
 * A bad command line: an unknown option, a missing or malformed value, a value out of range, a
 * target out of reach. Its message is one line that names the option, the bad value and what is
 * allowed, e.g. {@code --mass: must be a finite number > 0, but was -1}; the command prints it
 * to stderr and exits with {@link Program#USAGE}, with no stack trace.
 */
public final class UsageException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /**
     * Create an exception.
     *
     * @param oneLineMessage what is wrong and what is allowed (not null, no line break)
     */
    public UsageException(String oneLineMessage) {
        super(oneLineMessage);
    }

    /**
     * Say in a few words why a file operation failed: the JDK's file exceptions carry only
     * the path as their message, and their class tells the reason.
     *
     * @param failure the failure (not null)
     * @return e.g. {@code "permission denied (/sys/x.png)"}, control characters escaped
     */
    static String reason(IOException failure) {
        String why;
        if (failure instanceof AccessDeniedException) {
            why = "permission denied";
        } else if (failure instanceof NoSuchFileException) {
            why = "no such file or folder";
        } else if (failure instanceof FileAlreadyExistsException) {
            why = "a file of that name is in the way";
        } else if (failure instanceof NotDirectoryException) {
            why = "not a folder";
        } else if (failure instanceof FileSystemException
                && ((FileSystemException) failure).getReason() != null) {
            why = ((FileSystemException) failure).getReason();
        } else {
            why = String.valueOf(failure.getMessage());
        }
        String where = failure instanceof FileSystemException
                ? ((FileSystemException) failure).getFile() : null;
        return Options.show(where == null ? why : why + " (" + where + ")");
    }
}

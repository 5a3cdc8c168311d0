package particlelab.app;

import java.io.IOException;
import java.nio.file.Path;
import particlelab.files.SafeFiles;

/**
 * The lecture's votes CSV ({@code tour --votes FILE}): one row per revealed question under
 * {@link TourVote#CSV_HEADER}, the whole file written again at each reveal, so it is complete
 * after every question. Under the project's file rules ({@link SafeFiles}): an existing file
 * is replaced only with {@code --force} (the command line checks before the window opens),
 * a symbolic link is never written through, and a file replaced by a link while the lecture
 * runs is refused then too.
 */
final class VotesFile {

    private final Path file;
    private final boolean force;
    private final StringBuilder rows = new StringBuilder();
    /** True once this run wrote the file: later writes replace its own file. */
    private boolean written;

    /**
     * Name the file.
     *
     * @param file where to write (not null; its folder exists)
     * @param force true if the user allowed an existing regular file to be replaced
     */
    VotesFile(Path file, boolean force) {
        this.file = file;
        this.force = force;
    }

    /** @return the file (not null) */
    Path getFile() {
        return file;
    }

    /**
     * Add a revealed vote's row and write the file.
     *
     * @param vote the vote (not null)
     * @throws IOException if the file cannot be written or is refused (the message says why)
     */
    void record(TourVote vote) throws IOException {
        rows.append(vote.toCsvRow()).append('\n');
        SafeFiles.write(file, TourVote.CSV_HEADER + "\n" + rows, force || written);
        written = true;
    }
}

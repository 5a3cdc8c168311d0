package particlelab.app;

import java.io.IOException;
import java.nio.file.Path;
import particlelab.files.SafeFiles;

/**
 * Creates the folders a command writes into, once its whole command line was accepted, and
 * proves new files can be made there before any work starts; when they cannot, the folders it
 * just created are removed again and the command line is refused with the true reason.
 */
final class OutputFolders {

    private OutputFolders() {
    }

    /**
     * Create a folder (and the missing ones above it) and check that new files can be created
     * in it.
     *
     * @param option the option that named it, for the message (not null)
     * @param folder the folder (not null; checked with {@link SafeFiles#folderRefusal})
     * @return the highest folder created, for {@link SafeFiles#removeCreated}, or null if the
     *     folder existed
     * @throws UsageException if it cannot be created or written, with nothing left behind
     */
    static Path create(String option, Path folder) {
        Path created;
        try {
            created = SafeFiles.createFolders(folder);
        } catch (IOException failure) {
            // The system's reason for a folder it refuses (ENOENT under /proc) can mislead:
            // ask the nearest existing folder whether it takes new entries at all.
            Path above = SafeFiles.nearestExisting(folder);
            String problem = above == null ? null : SafeFiles.probe(above);
            throw new UsageException(option + ": cannot create the folder "
                    + SafeFiles.printable(folder) + ": " + (problem == null
                            ? UsageException.reason(failure)
                            : SafeFiles.printable(above) + " is " + problem));
        } catch (SecurityException | UnsupportedOperationException failure) {
            throw new UsageException(option + ": cannot create the folder "
                    + SafeFiles.printable(folder));
        }
        String problem = SafeFiles.probe(folder);
        if (problem != null) {
            SafeFiles.removeCreated(folder, created);
            throw new UsageException(option + ": cannot write into "
                    + SafeFiles.printable(folder) + ": it is " + problem);
        }
        return created;
    }
}

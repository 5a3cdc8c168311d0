package particlelab.files;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * The rules for every file the app writes at a user's request ({@code demo --export} and
 * {@code --screenshot}, the E key's export, {@code report --out}), in one place:
 * <ul>
 * <li>A file is created new ({@link StandardOpenOption#CREATE_NEW}): the system refuses it if
 * anything is at that name, a symbolic link included (dangling or not), so nothing is ever
 * written through a link planted there, not even between a check and the write.</li>
 * <li>An existing regular file is replaced only when the user said so ({@value #FORCE}): it
 * is removed, then the file is created new.</li>
 * <li>A symbolic link, a folder, a device or a pipe at a file's name is never written, not even
 * with {@value #FORCE}.</li>
 * <li>The folder the user names may be, or lie under, a symbolic link: that is the user's
 * choice. What is inside it is looked at without following links.</li>
 * </ul>
 * Commands check their targets with {@link #refusal} before any work and create their folders
 * ({@link #createFolders}) only once the whole command line was accepted.
 */
public final class SafeFiles {

    /** The option by which a user allows existing regular files to be replaced. */
    public static final String FORCE = "--force";

    private static final String PROBE_PREFIX = ".particle-lab-probe";

    private SafeFiles() {
    }

    /**
     * Say why a file may not be written under these rules, without following a link at its
     * name and without changing anything.
     *
     * @param file the file to write (not null)
     * @param replace true if the user allowed an existing regular file to be replaced
     * @param instead what the user may do instead of {@value #FORCE}, e.g. {@code "choose
     *     another name"} (not null)
     * @return one sentence starting with the file's name, or null if it may be written
     */
    public static String refusal(Path file, boolean replace, String instead) {
        BasicFileAttributes attributes = attributesOrNull(file);
        if (attributes == null) {
            return null;
        }
        if (attributes.isSymbolicLink()) {
            return printable(file) + " is a symbolic link; files are never written through a"
                    + " link, not even with " + FORCE + ": remove it or " + instead;
        }
        if (!attributes.isRegularFile()) {
            return printable(file) + " exists and is " + kind(attributes) + ", which is never"
                    + " replaced; " + instead;
        }
        return replace ? null : printable(file) + " exists; use " + FORCE + " to replace it, or "
                + instead;
    }

    /**
     * Name a path in full in a one-line message: control characters (a line break, a terminal
     * escape in a file name) shown as four-digit Unicode escapes. Paths are not cut short, so
     * the user can find the file named.
     *
     * @param path the path (not null)
     * @return the text to print (not null, no control characters)
     */
    public static String printable(Path path) {
        String text = path.toString();
        StringBuilder result = new StringBuilder(text.length() + 16);
        for (int i = 0; i < text.length(); ++i) {
            char c = text.charAt(i);
            int type = Character.getType(c);
            if (Character.isISOControl(c) || type == Character.LINE_SEPARATOR
                    || type == Character.PARAGRAPH_SEPARATOR) {
                result.append(String.format("\\u%04x", (int) c));
            } else {
                result.append(c);
            }
        }
        return result.toString();
    }

    /**
     * Say what is at a path, without following a link there.
     *
     * @param path the path (not null)
     * @return {@code "a symbolic link"}, {@code "a folder"}, {@code "a regular file"},
     *     {@code "a device, pipe or socket"}, or null if nothing is there
     */
    public static String kind(Path path) {
        BasicFileAttributes attributes = attributesOrNull(path);
        return attributes == null ? null : kind(attributes);
    }

    /**
     * Say why a folder could not be made or used, without creating anything: it must be a
     * folder if it exists (a link to one is the user's choice), and the nearest part of its
     * path that exists must be a folder.
     *
     * @param folder the folder (not null)
     * @return one sentence naming the part in the way, or null if nothing is in the way
     */
    public static String folderRefusal(Path folder) {
        Path absolute = folder.toAbsolutePath();
        Path existing = nearestExisting(absolute);
        if (existing == null || Files.isDirectory(existing)) {
            return null;
        }
        return printable(existing.equals(absolute) ? folder : existing)
                + " is a file, not a folder";
    }

    /**
     * Create a folder and the missing ones above it.
     *
     * @param folder the folder (not null)
     * @return the highest folder created, for {@link #removeCreated}, or null if it existed
     * @throws IOException if one cannot be created (those created before are removed)
     */
    public static Path createFolders(Path folder) throws IOException {
        Path absolute = folder.toAbsolutePath();
        Path highest = null;
        for (Path missing = absolute; missing != null && !Files.exists(missing);
                missing = missing.getParent()) {
            highest = missing;
        }
        try {
            Files.createDirectories(absolute);
        } catch (IOException failure) {
            removeCreated(absolute, highest);
            throw failure;
        }
        return highest;
    }

    /**
     * Find the nearest part of a path that exists: the path itself or a folder above it.
     *
     * @param path the path (not null)
     * @return that part, absolute, or null if none exists
     */
    public static Path nearestExisting(Path path) {
        Path existing = path.toAbsolutePath();
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        return existing;
    }

    /**
     * Remove the folders {@link #createFolders} created, from the folder up to the highest,
     * so that a refused command leaves nothing behind. A folder something was written into
     * since is kept.
     *
     * @param folder the folder given to createFolders (not null)
     * @param highest what createFolders returned (null: nothing to remove)
     */
    public static void removeCreated(Path folder, Path highest) {
        if (highest == null) {
            return;
        }
        for (Path created = folder.toAbsolutePath(); created != null;
                created = created.getParent()) {
            try {
                Files.deleteIfExists(created);
            } catch (IOException notEmpty) {
                return;
            }
            if (created.equals(highest)) {
                return;
            }
        }
    }

    /**
     * Check that new files can be created in a folder, by creating a probe file and removing
     * it, and say the true reason when they cannot.
     *
     * @param folder an existing folder (not null)
     * @return why not, to follow "the folder is", e.g. {@code "not writable (permission
     *     denied)"}, or null if they can
     */
    public static String probe(Path folder) {
        try {
            Files.delete(Files.createTempFile(folder, PROBE_PREFIX, ".tmp"));
            return null;
        } catch (AccessDeniedException denied) {
            return "not writable (permission denied)";
        } catch (NoSuchFileException missing) {
            // Linux's /proc says "no such file" to every new name in a folder that exists.
            return Files.isDirectory(folder)
                    ? "not writable (the system lets no file be created in it)"
                    : "no longer there";
        } catch (FileSystemException failure) {
            return "not writable (" + (failure.getReason() != null ? failure.getReason()
                    : failure.getClass().getSimpleName()) + ")";
        } catch (IOException | SecurityException | UnsupportedOperationException failure) {
            return "not writable (" + failure.getMessage() + ")";
        }
    }

    /**
     * Open a file for writing under these rules.
     *
     * @param file the file (not null; its folder exists)
     * @param replace true if the user allowed an existing regular file to be replaced
     * @return the stream, to close after writing (not null)
     * @throws IOException if the file cannot be created, or is refused: its message then says
     *     why in one sentence ({@link #refusal})
     */
    public static OutputStream create(Path file, boolean replace) throws IOException {
        try {
            return Files.newOutputStream(file, StandardOpenOption.CREATE_NEW,
                    StandardOpenOption.WRITE);
        } catch (FileAlreadyExistsException taken) {
            String why = refusal(file, replace, "choose another name");
            if (why != null) {
                throw new FileSystemException(null, null, why);
            }
            // A regular file the user allowed to replace; a link planted since is refused.
            Files.delete(file);
            return Files.newOutputStream(file, StandardOpenOption.CREATE_NEW,
                    StandardOpenOption.WRITE);
        }
    }

    /**
     * Remove a regular file the user allowed to be replaced, so that it can then be created
     * new; a symbolic link, a folder or a device there is left alone and refused.
     *
     * @param file the file (not null)
     * @return true if a file was removed, false if nothing was there
     * @throws IOException if it cannot be removed or is refused (the message says why)
     */
    public static boolean removeToReplace(Path file) throws IOException {
        String why = refusal(file, true, "choose another folder");
        if (why != null) {
            throw new FileSystemException(null, null, why);
        }
        return Files.deleteIfExists(file);
    }

    /**
     * Write a whole file under these rules.
     *
     * @param file the file (not null; its folder exists)
     * @param bytes its content (not null)
     * @param replace true if the user allowed an existing regular file to be replaced
     * @throws IOException as {@link #create}
     */
    public static void write(Path file, byte[] bytes, boolean replace) throws IOException {
        try (OutputStream out = create(file, replace)) {
            out.write(bytes);
        }
    }

    /**
     * Write a whole text file, UTF-8, under these rules.
     *
     * @param file the file (not null; its folder exists)
     * @param text its content (not null)
     * @param replace true if the user allowed an existing regular file to be replaced
     * @throws IOException as {@link #create}
     */
    public static void write(Path file, CharSequence text, boolean replace)
            throws IOException {
        write(file, text.toString().getBytes(StandardCharsets.UTF_8), replace);
    }

    /**
     * Open a UTF-8 text file for writing under these rules.
     *
     * @param file the file (not null; its folder exists)
     * @param replace true if the user allowed an existing regular file to be replaced
     * @return the writer, to close after writing (not null)
     * @throws IOException as {@link #create}
     */
    public static Writer newWriter(Path file, boolean replace) throws IOException {
        return new BufferedWriter(new OutputStreamWriter(create(file, replace),
                StandardCharsets.UTF_8));
    }

    /**
     * Append UTF-8 text to a file the same command created (a report's {@code index.md},
     * which each section extends), created if missing; a symbolic link there is refused
     * ({@link LinkOption#NOFOLLOW_LINKS}).
     *
     * @param file the file (not null; its folder exists)
     * @param text what to append (not null)
     * @throws IOException if it cannot be written or is a link
     */
    public static void append(Path file, CharSequence text) throws IOException {
        if (Files.isSymbolicLink(file)) {
            throw new FileSystemException(null, null, refusal(file, true, "choose another"
                    + " folder"));
        }
        Files.write(file, text.toString().getBytes(StandardCharsets.UTF_8),
                StandardOpenOption.CREATE, StandardOpenOption.APPEND, StandardOpenOption.WRITE,
                LinkOption.NOFOLLOW_LINKS);
    }

    private static BasicFileAttributes attributesOrNull(Path path) {
        try {
            return Files.readAttributes(path, BasicFileAttributes.class,
                    LinkOption.NOFOLLOW_LINKS);
        } catch (IOException | SecurityException nothingThere) {
            return null;
        }
    }

    private static String kind(BasicFileAttributes attributes) {
        if (attributes.isSymbolicLink()) {
            return "a symbolic link";
        }
        if (attributes.isDirectory()) {
            return "a folder";
        }
        return attributes.isRegularFile() ? "a regular file" : "a device, pipe or socket";
    }
}

package particlelab.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The rules of {@link SafeFiles}, each with a planted file or a planted link. */
class SafeFilesTest {

    private static final String OLD = "old\n";
    private static final String NEW = "new\n";
    private static final String INSTEAD = "choose another name";

    @Test
    void aNewFileIsWritten(@TempDir Path folder) throws IOException {
        Path file = folder.resolve("a.csv");
        assertNull(SafeFiles.refusal(file, false, INSTEAD));
        SafeFiles.write(file, NEW, false);
        assertEquals(NEW, Files.readString(file));
    }

    @Test
    void anExistingFileIsReplacedOnlyWhenAllowed(@TempDir Path folder) throws IOException {
        Path file = Files.writeString(folder.resolve("a.csv"), OLD);
        String why = SafeFiles.refusal(file, false, INSTEAD);
        assertNotNull(why);
        assertTrue(why.startsWith(file + " exists; use --force"), why);
        IOException refused = assertThrows(IOException.class,
                () -> SafeFiles.write(file, NEW, false));
        assertTrue(refused.getMessage().contains("--force"), refused.getMessage());
        assertEquals(OLD, Files.readString(file));
        assertNull(SafeFiles.refusal(file, true, INSTEAD));
        SafeFiles.write(file, NEW, true);
        assertEquals(NEW, Files.readString(file));
    }

    @Test
    void aPlantedLinkIsNeverWrittenThroughEvenWhenReplacing(@TempDir Path folder)
            throws IOException {
        Path victim = Files.writeString(folder.resolve("victim"), OLD);
        Path link = Files.createSymbolicLink(folder.resolve("a.csv"), victim);
        for (boolean replace : new boolean[] {false, true}) {
            String why = SafeFiles.refusal(link, replace, INSTEAD);
            assertNotNull(why);
            assertTrue(why.contains("symbolic link"), why);
            assertThrows(IOException.class, () -> SafeFiles.write(link, NEW, replace));
            assertThrows(IOException.class, () -> SafeFiles.removeToReplace(link));
            assertThrows(IOException.class, () -> SafeFiles.append(link, NEW));
            assertEquals(OLD, Files.readString(victim));
            assertTrue(Files.isSymbolicLink(link));
        }
    }

    @Test
    void aDanglingLinkIsNotFollowedToCreateAFileElsewhere(@TempDir Path folder) {
        Path elsewhere = folder.resolve("elsewhere");
        Path link = folder.resolve("a.csv");
        try {
            Files.createSymbolicLink(link, elsewhere);
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        assertThrows(IOException.class, () -> SafeFiles.write(link, NEW, true));
        assertFalse(Files.exists(elsewhere));
    }

    @Test
    void aFolderAtTheNameIsNeverReplaced(@TempDir Path folder) throws IOException {
        Path inTheWay = Files.createDirectory(folder.resolve("a.png"));
        String why = SafeFiles.refusal(inTheWay, true, INSTEAD);
        assertNotNull(why);
        assertTrue(why.contains("a folder"), why);
        assertThrows(IOException.class, () -> SafeFiles.write(inTheWay, NEW, true));
        assertTrue(Files.isDirectory(inTheWay));
    }

    @Test
    void foldersAreCheckedWithoutCreatingThemAndRemovedWhenRefused(@TempDir Path temp)
            throws IOException {
        Path file = Files.writeString(temp.resolve("file"), OLD);
        assertNotNull(SafeFiles.folderRefusal(file));
        assertNotNull(SafeFiles.folderRefusal(file.resolve("below/deeper")));
        Path fresh = temp.resolve("new/deeper");
        assertNull(SafeFiles.folderRefusal(fresh));
        assertFalse(Files.exists(temp.resolve("new")), "a check created a folder");
        Path highest = SafeFiles.createFolders(fresh);
        assertEquals(temp.resolve("new").toAbsolutePath(), highest);
        assertNull(SafeFiles.probe(fresh));
        SafeFiles.removeCreated(fresh, highest);
        assertFalse(Files.exists(temp.resolve("new")));
        assertNull(SafeFiles.createFolders(temp), "nothing created for an existing folder");
    }

    @Test
    void appendingExtendsAFileTheCommandCreated(@TempDir Path folder) throws IOException {
        Path index = folder.resolve("index.md");
        SafeFiles.write(index, OLD, false);
        SafeFiles.append(index, NEW);
        assertEquals(OLD + NEW, Files.readString(index));
    }
}

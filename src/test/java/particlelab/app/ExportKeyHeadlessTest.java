package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.demo.DemoState;
import particlelab.demo.TrajectoryExport;
import particlelab.lecture.DragDemo;

/**
 * The E key's export ({@link ExportState}) in a headless application: each export gets a
 * folder it made itself, so a name taken by anything, a symbolic link planted there included,
 * is passed over, never written through.
 */
class ExportKeyHeadlessTest {

    /** Links are planted for this many seconds' folder names from now on. */
    private static final int PLANTED_SECONDS = 30;
    private static final DateTimeFormatter STAMP =
            DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");

    @Test
    void aFolderNameTakenByAPlantedLinkIsPassedOver(@TempDir Path temp) throws Exception {
        Path base = Files.createDirectory(temp.resolve("exports"));
        DemoState drag = new DragDemo();
        String name = TrajectoryExport.fileSafeName(drag.getTitle());
        // Dangling links at the names the next seconds' exports would take: following one
        // would make the folder (and write the CSVs) elsewhere.
        Path elsewhere = temp.resolve("elsewhere");
        LocalDateTime now = LocalDateTime.now();
        for (int s = -1; s < PLANTED_SECONDS; ++s) {
            Files.createSymbolicLink(base.resolve(name + "-" + now.plusSeconds(s).format(STAMP)),
                    elsewhere.resolve(Integer.toString(s)));
        }
        try (HeadlessHarness harness = HeadlessHarness.start(List.of(drag))) {
            ExportState export = new ExportState(harness.app().getSwitcher(), base);
            harness.call(() -> harness.app().getStateManager().attach(export));
            harness.awaitFrames(2);
            Path first = harness.call(export::exportNow);
            Path second = harness.call(export::exportNow);
            for (Path folder : List.of(first, second)) {
                assertFalse(Files.isSymbolicLink(folder), folder + " is a planted link");
                assertTrue(Files.isDirectory(folder), folder.toString());
                assertEquals(base, folder.getParent());
                assertTrue(Files.isRegularFile(folder.resolve("gravity-only.csv")),
                        "no CSV in " + folder);
                // the E key's export carries its settings too (issue 33)
                assertTrue(Files.isRegularFile(folder.resolve("parameters.csv")),
                        "no parameters.csv in " + folder);
            }
            assertNotEquals(first, second, "two exports shared a folder");
        }
        assertFalse(Files.exists(elsewhere), "an export followed a planted link");
    }
}

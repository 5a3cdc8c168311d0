package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.accuracy.ReportConfig;

/**
 * The report's physics share section: every demo of the catalogue, run headless on the tiny
 * sweep, gets a row in the CSV and in the table. No timing is checked, only that the times are
 * measurements (finite, the longest frame not below the mean) and that every frame simulated.
 */
class PhysicsShareTest {

    @TempDir
    static Path folder;
    private static PhysicsShare share;

    @BeforeAll
    static void measureEveryDemo() throws IOException {
        share = PhysicsShare.run(ReportConfig.Size.TINY);
        Files.write(folder.resolve("index.md"), "# report\n\n".getBytes(StandardCharsets.UTF_8));
        share.write(folder);
    }

    @Test
    void everyCatalogueDemoHasARowInCatalogueOrder() {
        List<String> names = new ArrayList<>();
        for (PhysicsShare.Row row : share.rows()) {
            names.add(row.name());
            assertTrue(Double.isFinite(row.meanMillis()) && row.meanMillis() > 0.0, row.name());
            assertTrue(row.maxMillis() >= row.meanMillis(), row.name());
            // a fixed step h equal to the frame time carries its leftover: one step a frame,
            // give or take one over the whole run, and a scene that is over is restarted
            assertEquals(1.0, row.stepsPerFrame(), 0.1, row.name());
            assertTrue(row.particles() >= 0, row.name());
        }
        assertEquals(DemoCatalog.names(), names);
    }

    @Test
    void csvHasItsFixedHeaderAndARowPerDemo() throws IOException {
        List<String> lines = Files.readAllLines(folder.resolve(PhysicsShare.CSV),
                StandardCharsets.UTF_8);
        assertEquals("demo,particles,frames,steps_per_frame,physics_ms_mean,physics_ms_max,"
                + "share_of_frame_mean,share_of_frame_max", lines.get(0));
        assertEquals(DemoCatalog.names().size(), lines.size() - 1);
        for (int i = 0; i < DemoCatalog.names().size(); ++i) {
            String[] cells = lines.get(i + 1).split(",");
            assertEquals(DemoCatalog.names().get(i), cells[0]);
            // share = time / (1000/60 ms), to the printed digits: the share is rounded to
            // 5e-7, the mean to 5e-6 ms, which is 3e-7 of 16.7 ms
            double mean = Double.parseDouble(cells[4]);
            double shareOfFrame = Double.parseDouble(cells[6]);
            assertEquals(mean / (1000.0 / 60.0), shareOfFrame, 1e-6, lines.get(i));
        }
    }

    @Test
    void indexHasTheSectionWithATableRowPerDemo() throws IOException {
        String index = new String(Files.readAllBytes(folder.resolve("index.md")),
                StandardCharsets.UTF_8);
        int start = index.indexOf(PhysicsShare.HEADING);
        assertTrue(start >= 0, index);
        String section = index.substring(start);
        assertTrue(section.contains("| demo | particles | steps per frame | physics ms per "
                + "frame: mean | max | share of 16.7 ms: mean | max |"), section);
        for (String name : DemoCatalog.names()) {
            assertTrue(section.contains(" (`" + name + "`) | "), "no row for " + name);
        }
    }
}

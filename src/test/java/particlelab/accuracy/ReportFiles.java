package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;

/** Checks that a report (or one of its sections) wrote the files it promises. */
final class ReportFiles {

    private ReportFiles() {
    }

    /**
     * Assert that every file exists and is not empty, and that every PNG among them is a
     * readable picture at least as wide as the report's charts.
     *
     * @param folder the report's folder
     * @param names the promised files, relative to the folder
     * @throws IOException if a file cannot be read
     */
    static void assertWritten(Path folder, List<String> names) throws IOException {
        for (String name : names) {
            Path file = folder.resolve(name);
            assertTrue(Files.isRegularFile(file), "missing " + name);
            assertTrue(Files.size(file) > 0, "empty " + name);
            if (name.endsWith(".png")) {
                BufferedImage image = ImageIO.read(file.toFile());
                assertNotNull(image, name + " is not a readable PNG");
                assertTrue(image.getWidth() >= Charts.WIDTH, name + " is too small");
            }
        }
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import org.junit.jupiter.api.Test;

/**
 * Each demo's page (docs/demos/NAME.md) names the source file of the demo it describes, the
 * class the catalogue creates for NAME, and that file exists: a reader goes from the page to
 * the code in one step.
 */
class DemoPagesSourceTest {

    @Test
    void everyDemoPageNamesItsSourceFile() throws IOException {
        for (DemoCatalog.Entry entry : DemoCatalog.entries()) {
            Path page = Paths.get("docs", "demos", entry.getName() + ".md");
            String source = "src/main/java/"
                    + entry.create().getClass().getName().replace('.', '/') + ".java";
            assertTrue(Files.isRegularFile(Paths.get(source)), source);
            String text = Files.readString(page, StandardCharsets.UTF_8);
            assertTrue(text.contains("Its source: `" + source + "`."), page + " should name "
                    + source);
        }
    }
}

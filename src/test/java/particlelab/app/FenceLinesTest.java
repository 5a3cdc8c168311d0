package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every code fence in the README and the docs is a plain fence line: three backticks, an
 * optional language word, nothing else. Under CommonMark a line such as "```` ``` text````"
 * opens no fence and closes none, so the rest of the page renders with code and prose
 * swapped (docs/cli.md had one); and each page's fences pair up.
 */
class FenceLinesTest {

    /** A plain fence: backticks at the line's start, an optional info word, nothing more. */
    private static final Pattern PLAIN_FENCE = Pattern.compile("```[A-Za-z0-9_+-]*");

    @Test
    void everyFenceIsAPlainFenceLineAndTheyPairUp() throws IOException {
        List<Path> pages = new ArrayList<>();
        pages.add(Paths.get("README.md"));
        try (Stream<Path> docs = Files.walk(Paths.get("docs"))) {
            docs.filter(path -> path.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        assertTrue(pages.size() > 10, "pages found: " + pages);
        for (Path page : pages) {
            List<String> lines = Files.readAllLines(page);
            int fences = 0;
            for (int i = 0; i < lines.size(); ++i) {
                String line = lines.get(i);
                if (!line.contains("```")) {
                    continue;
                }
                assertTrue(PLAIN_FENCE.matcher(line).matches(),
                        page + ":" + (i + 1) + " is not a plain fence line: " + line);
                ++fences;
            }
            assertEquals(0, fences % 2, page + ": an unclosed fence");
        }
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The pages' key and parameter tables cannot drift from the declarations: every block between
 * {@code <!-- keys:NAME -->} and {@code <!-- /keys -->} in README.md or a page under docs/ must
 * be what {@link KeyTables#block} writes for NAME (a demo's name, {@code shared},
 * {@code application} or {@code jme}), and every block between {@code <!-- params:NAME -->}
 * and {@code <!-- /params -->} what {@link KeyTables#parameterTable} writes for the demo NAME.
 * Every demo's page has both blocks.
 *
 * <p>After a key was added or renamed, rewrite every block in one command (docs/testing.md):
 * {@code PARTICLELAB_WRITE_DOCS=1 gradle --no-daemon test --tests ...KeyTablesTest} (a
 * Gradle daemon started earlier would not see the variable); the test then rewrites the pages
 * and passes; rerun it without the variable to check.
 */
class KeyTablesTest {

    /** The environment variable that makes this test rewrite the blocks. */
    static final String WRITE_DOCS = "PARTICLELAB_WRITE_DOCS";
    /** A block: its opening marker with the name, its body, its closing marker. */
    private static final Pattern BLOCK = Pattern.compile(
            "(<!-- (keys|params):([a-z]+) -->\\n)(.*?)(<!-- /\\2 -->)", Pattern.DOTALL);

    /**
     * Compare every marked block with what the generator writes now; with
     * {@value #WRITE_DOCS}=1, rewrite the stale ones instead of failing.
     *
     * @throws IOException if a page cannot be read or written
     */
    @Test
    void everyKeyBlockIsWhatTheBindingsWrite() throws IOException {
        boolean write = "1".equals(System.getenv(WRITE_DOCS));
        List<String> stale = new ArrayList<>();
        int blocks = 0;
        for (Path page : pages()) {
            String text = Files.readString(page, StandardCharsets.UTF_8);
            Matcher matcher = BLOCK.matcher(text);
            StringBuilder rewritten = new StringBuilder();
            while (matcher.find()) {
                ++blocks;
                String want = matcher.group(2).equals("keys")
                        ? KeyTables.block(matcher.group(3))
                        : KeyTables.parameterTable(matcher.group(3));
                if (!want.equals(matcher.group(4))) {
                    stale.add(page + ": " + matcher.group(2) + ":" + matcher.group(3)
                            + " should read\n" + want);
                }
                matcher.appendReplacement(rewritten, Matcher.quoteReplacement(
                        matcher.group(1) + want + matcher.group(5)));
            }
            matcher.appendTail(rewritten);
            if (write && !rewritten.toString().equals(text)) {
                Files.writeString(page, rewritten.toString(), StandardCharsets.UTF_8);
            }
        }
        assertTrue(blocks > 0, "the pages have key blocks");
        if (!write && !stale.isEmpty()) {
            fail(stale.size() + " key block(s) differ from the bindings; regenerate with "
                    + WRITE_DOCS + "=1 gradle --no-daemon test"
                    + " --tests 'particlelab.app.KeyTablesTest'\n"
                    + String.join("\n", stale));
        }
    }

    /**
     * Every demo of the catalogue has its page with its keys and its parameters.
     *
     * @throws IOException if a page cannot be read
     */
    @Test
    void everyDemoHasAPageWithItsKeyBlock() throws IOException {
        for (String name : DemoCatalog.names()) {
            Path page = Paths.get("docs", "demos", name + ".md");
            assertTrue(Files.isRegularFile(page), "the page of demo " + name);
            String text = Files.readString(page, StandardCharsets.UTF_8);
            for (String kind : new String[] {"keys", "params"}) {
                String marker = "<!-- " + kind + ":" + name + " -->";
                assertTrue(text.contains(marker), page + " has the block " + marker);
            }
        }
    }

    /** The generator reads the real bindings: known keys of each kind appear in its tables. */
    @Test
    void theTablesNameTheKeysTheBindingsDeclare() {
        // Spring adds none of its own; drag adds L (its comparison lane); Bounce adds Up
        // (restitution) among others; the shared table has pause on Space; the
        // application's has Tab; jME's has Esc.
        assertFalse(KeyTables.demoTable("spring").contains("| `"), "spring has no own keys");
        assertTrue(KeyTables.demoTable("drag").contains("| `L` | comparison lane"), "drag's L");
        assertTrue(KeyTables.demoTable("bounce").contains("| `Up`"), "bounce's Up");
        assertTrue(KeyTables.sharedTable().contains("| `Space` | pause"), "Space pauses");
        assertTrue(KeyTables.applicationTable().contains("| `Tab` | next demo"), "Tab");
        assertTrue(KeyTables.jmeKeys().contains("Esc  -  quit the app"), "Esc");
        assertEquals(KeyTables.demoTable("wind"), KeyTables.block("wind"));
        // Wind declares w after the shared h.
        assertTrue(KeyTables.parameterTable("wind").contains("| `h` |"), "h first");
        assertTrue(KeyTables.parameterTable("wind").contains("| `w` |"), "wind's w");
    }

    /**
     * List the pages whose blocks are checked: README.md and every Markdown page under docs/.
     *
     * @return the pages, README first (not null)
     * @throws IOException if docs/ cannot be listed
     */
    private static List<Path> pages() throws IOException {
        List<Path> pages = new ArrayList<>();
        pages.add(Paths.get("README.md"));
        try (Stream<Path> docs = Files.walk(Paths.get("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        return pages;
    }
}

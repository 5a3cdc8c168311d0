package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The student guide (docs/extending.md) compiles as written: its code blocks (the imports,
 * constructor, scene, key, parameter and presentation steps of the worked example, and the
 * catalogue step) are put together into classes and compiled against the project.
 */
class ExtendingGuideTest {

    private static final Path GUIDE = Paths.get("docs", "extending.md");
    /** What the guide leaves to WindDemo.java itself: the force, its fields and one helper. */
    private static final String SCAFFOLDING = String.join("\n",
            "    private static final Vector3f LAUNCH_VELOCITY = new Vector3f(10f, 10f, 0f);",
            "    private static final float WIND_STEP = 2f;",
            "    private final Vector3f windVelocity = new Vector3f(-6f, 0f, 0f);",
            "    private final Wind wind = new Wind();",
            "    private static final class Wind implements Force {",
            "        void setWindVelocity(Vector3f newVelocity) { }",
            "        @Override public String describe() { return \"\"; }",
            "    }",
            "    private void changeWind(float delta) { }",
            "");

    @TempDir
    Path classes;

    @Test
    void theWorkedExamplesBlocksCompile() throws IOException {
        List<String> blocks = blocks();
        String imports = find(blocks, "package particlelab.lecture;");
        StringBuilder source = new StringBuilder(imports)
                .append("public final class WindDemo extends DemoState {\n")
                .append(SCAFFOLDING)
                .append(find(blocks, "public WindDemo()"))
                .append(find(blocks, "@Override\nprotected void createScene()"))
                .append("@Override\nprotected void declareKeys() {\n")
                .append(find(blocks, "bindKey(")).append("}\n")
                .append("@Override\nprotected void declareParameters() {\n")
                .append(find(blocks, "declareParameter(")).append("}\n")
                .append(find(blocks, "@Override\nprotected void writePresentation("))
                .append("}\n");
        assertCompiles("particlelab/lecture/WindDemo.java", source.toString());
    }

    @Test
    void theCatalogueStepCompiles() throws IOException {
        String block = find(blocks(), "import particlelab.lecture.WindDemo;");
        StringBuilder imports = new StringBuilder();
        StringBuilder entries = new StringBuilder();
        for (String line : block.split("\n")) {
            (line.startsWith("import ") ? imports : entries).append(line).append('\n');
        }
        String list = entries.toString().strip();
        assertTrue(list.endsWith(","), "the catalogue line ends with a comma, as in the list");
        // Here it is the list's last entry (no comma); outside DemoCatalog, Entry is nested.
        String entry = list.substring(0, list.length() - 1)
                .replace("new Entry(", "new DemoCatalog.Entry(");
        String source = "package particlelab.app;\n" + imports
                + "import java.util.List;\n"
                + "final class GuideCatalogue {\n"
                + "    static final List<DemoCatalog.Entry> ENTRIES = List.of(\n"
                + entry + ");\n}\n";
        assertCompiles("particlelab/app/GuideCatalogue.java", source);
    }

    private void assertCompiles(String path, String source) {
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        assertNotNull(compiler, "a JDK's compiler");
        JavaFileObject file = new SimpleJavaFileObject(URI.create("string:///" + path),
                JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return source;
            }
        };
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        List<String> options = List.of("-proc:none", "-d", classes.toString(),
                "-classpath", System.getProperty("java.class.path"));
        boolean compiled = compiler.getTask(null, null, diagnostics, options, null,
                List.of(file)).call();
        assertTrue(compiled, () -> diagnostics.getDiagnostics() + "\n" + source);
        assertEquals(List.of(), errors(diagnostics));
    }

    private static List<String> errors(DiagnosticCollector<JavaFileObject> diagnostics) {
        List<String> errors = new ArrayList<>();
        diagnostics.getDiagnostics().forEach(d -> {
            if (d.getKind() == javax.tools.Diagnostic.Kind.ERROR) {
                errors.add(d.toString());
            }
        });
        return errors;
    }

    /** The guide's fenced blocks, each with a final newline. */
    private static List<String> blocks() throws IOException {
        List<String> blocks = new ArrayList<>();
        StringBuilder block = null;
        for (String line : Files.readAllLines(GUIDE)) {
            if (line.startsWith("```")) {
                if (block != null) {
                    blocks.add(block.toString());
                    block = null;
                } else {
                    block = new StringBuilder();
                }
            } else if (block != null) {
                block.append(line).append('\n');
            }
        }
        return blocks;
    }

    private static String find(List<String> blocks, String start) {
        for (String block : blocks) {
            if (block.startsWith(start)) {
                return block;
            }
        }
        throw new AssertionError("docs/extending.md has no code block starting " + start);
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * {@link DemoRun} is the demo's run without jME: it and every class of this project it uses,
 * directly or through another, import nothing of {@code com.jme3} but {@code com.jme3.math}.
 * Found by reading the sources: the imports of {@code particlelab} classes, and the names of
 * classes of the same package used in the code (comments and strings left out).
 */
class DemoRunSourceTest {

    private static final Path SOURCES = Paths.get("src/main/java");
    private static final Pattern IMPORT = Pattern.compile(
            "^import\\s+(static\\s+)?([\\w.]+?)(\\.\\*)?\\s*;", Pattern.MULTILINE);
    private static final Pattern IDENTIFIER = Pattern.compile("\\b[A-Z]\\w*\\b");
    /** Comments and string or character literals: no use of a class. */
    private static final Pattern NOT_CODE = Pattern.compile(
            "//[^\\n]*|/\\*.*?\\*/|\"(\\\\.|[^\"\\\\])*\"|'(\\\\.|[^'\\\\])*'", Pattern.DOTALL);

    @Test
    void runAndWhatItUsesImportNoJmeButMath() throws IOException {
        Set<String> closure = closureOf("particlelab.demo.DemoRun");
        List<String> problems = new ArrayList<>();
        for (String name : closure) {
            String source = Files.readString(fileOf(name));
            Matcher imports = IMPORT.matcher(source);
            while (imports.find()) {
                String imported = imports.group(2);
                if (imported.startsWith("com.jme3.") && !imported.startsWith("com.jme3.math.")) {
                    problems.add(name + " imports " + imported);
                }
            }
            String code = NOT_CODE.matcher(source).replaceAll(" ");
            Matcher qualified = Pattern.compile("\\bcom\\.jme3\\.(\\w+)").matcher(code);
            while (qualified.find()) {
                if (!qualified.group(1).equals("math")) {
                    problems.add(name + " names com.jme3." + qualified.group(1));
                }
            }
        }
        assertEquals(List.of(), problems, "the run's classes: " + closure);
        // The scan reaches what the run is made of, not only its own file.
        assertTrue(closure.containsAll(List.of("particlelab.demo.DemoParticle",
                "particlelab.demo.Replay", "particlelab.world.World",
                "particlelab.physics.SimulationClock")), closure.toString());
    }

    /** Every project class a class uses, directly or through others, itself included. */
    private static Set<String> closureOf(String start) throws IOException {
        Set<String> found = new TreeSet<>();
        Deque<String> toRead = new ArrayDeque<>();
        toRead.add(start);
        while (!toRead.isEmpty()) {
            String name = toRead.poll();
            if (!found.add(name)) {
                continue;
            }
            String source = Files.readString(fileOf(name));
            String packageName = name.substring(0, name.lastIndexOf('.'));
            Matcher imports = IMPORT.matcher(source);
            while (imports.find()) {
                String imported = imports.group(2);
                if (imports.group(1) != null) {
                    // A static import names a member: its class is the part before it.
                    imported = imported.substring(0, imported.lastIndexOf('.'));
                }
                if (imported.startsWith("particlelab.") && Files.exists(fileOf(imported))) {
                    toRead.add(imported);
                }
            }
            String code = NOT_CODE.matcher(source).replaceAll(" ");
            Matcher identifiers = IDENTIFIER.matcher(code);
            while (identifiers.find()) {
                String sibling = packageName + "." + identifiers.group();
                if (Files.exists(fileOf(sibling))) {
                    toRead.add(sibling);
                }
            }
        }
        return found;
    }

    private static Path fileOf(String className) {
        return SOURCES.resolve(className.replace('.', '/') + ".java");
    }
}

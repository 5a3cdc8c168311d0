package particlelab.lecture;

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
 * No demo builds views in {@code createScene()}: the scene is declared the first time the
 * world, the particles or the window need it, with or without an application, so a demo that
 * asked {@code getApplication()} there drew its walls only when the window came first. Its
 * own views go in {@code buildViews(Application)}, which only a window calls. Read from the
 * sources of the lecture's demos and the students' own demo.
 */
class CreateSceneSourceTest {

    private static final List<Path> FOLDERS = List.of(
            Paths.get("src/main/java/particlelab/lecture"),
            Paths.get("src/exercises/java/particlelab/exercises"),
            Paths.get("src/solutions/java/particlelab/solutions"));
    /** Comments and string or character literals, whose braces and words are no code. */
    private static final Pattern NOT_CODE = Pattern.compile(
            "//[^\\n]*|/\\*.*?\\*/|\"(\\\\.|[^\"\\\\])*\"|'(\\\\.|[^'\\\\])*'", Pattern.DOTALL);
    private static final String CREATE_SCENE = "void createScene() {";
    /** The catalogue has more demos than this; fewer found means the scan went wrong. */
    private static final int MIN_DEMOS = 15;

    @Test
    void noCreateSceneAsksForTheApplication() throws IOException {
        List<String> problems = new ArrayList<>();
        int scanned = 0;
        for (Path folder : FOLDERS) {
            if (!Files.isDirectory(folder)) {
                continue;
            }
            try (Stream<Path> files = Files.list(folder)) {
                for (Path file : (Iterable<Path>) files.sorted()::iterator) {
                    String code = NOT_CODE.matcher(Files.readString(file)).replaceAll(" ");
                    int start = code.indexOf(CREATE_SCENE);
                    if (start < 0) {
                        continue;
                    }
                    ++scanned;
                    String body = bodyFrom(code, start + CREATE_SCENE.length() - 1);
                    if (body.contains("getApplication(")) {
                        problems.add(file.getFileName() + ": createScene() calls"
                                + " getApplication(); build views in buildViews(Application)");
                    }
                }
            }
        }
        assertEquals(List.of(), problems);
        assertTrue(scanned >= MIN_DEMOS, "only " + scanned + " createScene() found");
    }

    /** The text of a block, from its opening brace to the matching closing one. */
    private static String bodyFrom(String code, int openBrace) {
        int depth = 0;
        for (int i = openBrace; i < code.length(); ++i) {
            char c = code.charAt(i);
            if (c == '{') {
                ++depth;
            } else if (c == '}' && --depth == 0) {
                return code.substring(openBrace, i + 1);
            }
        }
        throw new AssertionError("unbalanced braces after createScene()");
    }
}

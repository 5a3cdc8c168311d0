package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * One place interpolates a stepped flight's ground crossing. A crossing is a step's straight
 * segment swept against the plane {@code y = 0}, read at the sweep's fraction; the app's code
 * gets one from {@link Flight} (a particle flown outside a world) or from a world's ground rule
 * ({@code SurfaceRule.ground}, which the world interpolates; {@code world.GroundStop} keeps the
 * lecture's landings). Read from the sources of {@code src/main/java} (the exercises are the
 * students' own code), a class finds a crossing of its own in one of two ways this test
 * recognises, and only the classes named below may:
 * <ul>
 * <li>it sweeps the ground plane itself: it names {@code Plane.ground()};</li>
 * <li>it ends a flight at a height test of its own: it compares a position's y with zero
 * ({@code position.y < 0f}, {@code position[1] <= 0.0}).</li>
 * </ul>
 * Each allowed class must still show its pattern, so the list cannot outlive its reason.
 */
class GroundCrossingSourceTest {

    private static final Path MAIN = Paths.get("src/main/java/particlelab");
    /** Comments and string or character literals, whose words are no code. */
    private static final Pattern NOT_CODE = Pattern.compile(
            "//[^\\n]*|/\\*.*?\\*/|\"(\\\\.|[^\"\\\\])*\"|'(\\\\.|[^'\\\\])*'", Pattern.DOTALL);
    private static final Pattern GROUND_PLANE = Pattern.compile("\\bPlane\\s*\\.\\s*ground\\s*\\(");
    private static final Pattern HEIGHT_BELOW_ZERO = Pattern.compile(
            "\\b[pP]osition\\s*(\\.\\s*y\\b|\\[\\s*1\\s*\\])\\s*<=?\\s*0(\\.0*)?[fFdD]?\\b");
    /** The classes that may name the ground plane, and why. */
    private static final Map<String, String> MAY_SWEEP_THE_GROUND = Map.of(
            "world/SurfaceRule.java", "the world's ground rule, interpolated by the world",
            "aiming/Flight.java", "the one flight helper",
            "lecture/CollisionsDemo.java", "its box's floor is a world SurfaceRule",
            "app/TourQuestions.java", "stop 1's rule sweeps a shot against the targets"
                    + " scene's surfaces (the ground one of five) to name what it touches"
                    + " first; it finds no landing");
    /** The classes that may test a height against zero, and why. */
    private static final Map<String, String> MAY_TEST_THE_HEIGHT = Map.of(
            "reference/ExactPath.java", "the exact path's crossing, found by bisection on the"
                    + " closed form or RK4: no step is interpolated");
    /** The app has far more classes; fewer means the scan went wrong. */
    private static final int MIN_CLASSES = 200;

    @Test
    void onlyTheFlightHelperAndTheWorldFindAGroundCrossing() throws IOException {
        Map<String, String> code = readMainSources();
        assertTrue(code.size() >= MIN_CLASSES, "scanned only " + code.size() + " classes");
        List<String> problems = new ArrayList<>();
        check(code, GROUND_PLANE, MAY_SWEEP_THE_GROUND,
                "names Plane.ground(): fly with aiming/Flight, or stop at the world's ground"
                + " (world/GroundStop)", problems);
        check(code, HEIGHT_BELOW_ZERO, MAY_TEST_THE_HEIGHT,
                "ends a flight at a height test of its own: use aiming/Flight's swept ground"
                + " test", problems);
        assertEquals(List.of(), problems);
    }

    private static void check(Map<String, String> code, Pattern pattern,
            Map<String, String> allowed, String why, List<String> problems) {
        for (Map.Entry<String, String> source : code.entrySet()) {
            boolean found = pattern.matcher(source.getValue()).find();
            if (found && !allowed.containsKey(source.getKey())) {
                problems.add(source.getKey() + " " + why);
            } else if (!found && allowed.containsKey(source.getKey())) {
                problems.add(source.getKey() + " is allowed (" + allowed.get(source.getKey())
                        + ") but no longer shows " + pattern + ": take it off the list");
            }
        }
        for (String name : allowed.keySet()) {
            if (!code.containsKey(name)) {
                problems.add(name + " is allowed but does not exist: take it off the list");
            }
        }
    }

    /** Every main source, by its path under the root package, without comments or strings. */
    private static Map<String, String> readMainSources() throws IOException {
        Map<String, String> code = new TreeMap<>();
        try (Stream<Path> files = Files.walk(MAIN)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                if (file.toString().endsWith(".java")) {
                    String name = MAIN.relativize(file).toString().replace('\\', '/');
                    code.put(name, NOT_CODE.matcher(Files.readString(file)).replaceAll(" "));
                }
            }
        }
        return code;
    }
}

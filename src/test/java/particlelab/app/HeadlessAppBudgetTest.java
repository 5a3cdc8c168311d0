package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Issue 30: tests that check physics, numbers or text step a demo (or its {@code DemoRun}) in
 * plain JUnit; only what needs a renderer (layout, views, input, whole frames) boots the
 * headless application, and at most {@link #MAX_CLASSES} test classes do. A class boots it
 * when its code (comments and strings left out) calls {@link HeadlessHarness#start} or
 * {@link HeadlessHarness#perClass}. Read from the sources, so no class is loaded and no
 * application starts. docs/testing.md lists the classes and why each needs the app.
 */
class HeadlessAppBudgetTest {

    /** The most test classes that may boot the headless application (issue 30). */
    static final int MAX_CLASSES = 25;
    private static final Path TESTS = Paths.get("src", "test", "java");
    /** A boot: {@code HeadlessHarness.start(} or {@code HeadlessHarness.perClass(}. */
    private static final Pattern BOOT = Pattern.compile(
            "\\bHeadlessHarness\\s*\\.\\s*(start|perClass)\\s*\\(");
    /** The same methods imported statically, to be called by their bare names. */
    private static final Pattern STATIC_IMPORT = Pattern.compile(
            "import\\s+static\\s+particlelab\\.app\\.HeadlessHarness\\.(start|perClass|\\*)\\s*;");
    /** Comments and string or character literals: no call. */
    private static final Pattern NOT_CODE = Pattern.compile(
            "//[^\\n]*|/\\*.*?\\*/|\"(\\\\.|[^\"\\\\])*\"|'(\\\\.|[^'\\\\])*'", Pattern.DOTALL);

    @Test
    void atMostTwentyFiveTestClassesBootTheHeadlessApp() throws IOException {
        List<String> booting = classesBootingTheApp();
        // The scan finds what is known to boot the app: a scan that found nothing would pass.
        assertTrue(booting.contains("particlelab.app.FrameAllocationHeadlessTest"),
                "the scan missed FrameAllocationHeadlessTest: " + booting);
        assertTrue(booting.size() <= MAX_CLASSES, booting.size() + " test classes boot the"
                + " headless app, at most " + MAX_CLASSES + " may (issue 30; check physics,"
                + " numbers and text on a demo or its DemoRun in plain JUnit, or add the"
                + " method to one of these): " + String.join(", ", booting));
    }

    @Test
    void aBootIsACallInCodeNotInACommentOrAString() {
        assertTrue(boots("HeadlessHarness harness = HeadlessHarness.start(List.of(drag));"));
        assertTrue(boots("static final HeadlessHarness harness = HeadlessHarness.perClass(\n"
                + "        () -> demos);"));
        assertTrue(boots("import static particlelab.app.HeadlessHarness.start;\n"));
        assertTrue(!boots("HeadlessHarness.press(demo, \"F2\");"), "a static helper");
        assertTrue(!boots("// HeadlessHarness.start(demos) is not needed here"), "a comment");
        assertTrue(!boots("/** See {@code HeadlessHarness.perClass(...)}. */"), "a Javadoc");
        assertTrue(!boots("String s = \"HeadlessHarness.start(\";"), "a string");
    }

    /** @return the test classes whose code boots the app, by name, sorted */
    static List<String> classesBootingTheApp() throws IOException {
        TreeSet<String> found = new TreeSet<>();
        try (Stream<Path> walk = Files.walk(TESTS)) {
            for (Path file : walk.filter(p -> p.toString().endsWith(".java"))
                    .collect(Collectors.toList())) {
                String name = TESTS.relativize(file).toString().replace('\\', '/')
                        .replace('/', '.').replaceAll("\\.java$", "");
                if (name.equals(HeadlessHarness.class.getName())) {
                    continue;
                }
                if (boots(Files.readString(file, StandardCharsets.UTF_8))) {
                    found.add(name);
                }
            }
        }
        return List.copyOf(found);
    }

    /** @return true if this source text calls the harness's start or perClass in code */
    private static boolean boots(String source) {
        String code = NOT_CODE.matcher(source).replaceAll(" ");
        return BOOT.matcher(code).find() || STATIC_IMPORT.matcher(code).find();
    }
}

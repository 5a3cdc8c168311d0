package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;

/**
 * With no display at all, {@code particle-lab demo} says so in one line and exits with status
 * 1. The check runs the real launcher in a child JVM whose environment has neither
 * {@code DISPLAY} nor {@code WAYLAND_DISPLAY}, so it runs (and can fail) on a desktop as well
 * as on a headless machine. Linux only: elsewhere the app does not look for a display server.
 */
@EnabledOnOs(OS.LINUX)
class NoDisplayTest {

    /**
     * Long enough for a JVM to start and print one line on a loaded 2-core machine; a guard
     * against a child that opened a window after all, not a measurement.
     */
    private static final long CHILD_TIMEOUT_SECONDS = 120;

    @TempDir
    Path tempDir;

    @Test
    void withoutADisplayTheDemoCommandSaysSoInOneLineAndExitsWithStatusOne()
            throws IOException, InterruptedException {
        Path out = tempDir.resolve("stdout.txt");
        Path err = tempDir.resolve("stderr.txt");
        ProcessBuilder builder = new ProcessBuilder(javaExecutable(), "-cp", testClasspath(),
                Main.class.getName(), DemoCommand.NAME, "aiming", "--frames", "1");
        Map<String, String> environment = builder.environment();
        environment.remove("DISPLAY");
        environment.remove("WAYLAND_DISPLAY");
        builder.redirectOutput(out.toFile()).redirectError(err.toFile());
        Process child = builder.start();
        if (!child.waitFor(CHILD_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
            child.destroyForcibly();
            fail("the child launcher was still running after " + CHILD_TIMEOUT_SECONDS + " s");
        }
        List<String> errLines = Files.readAllLines(err, StandardCharsets.UTF_8);
        String report = "stderr: " + errLines + ", stdout: "
                + Files.readAllLines(out, StandardCharsets.UTF_8);
        assertEquals(Program.FAILED, child.exitValue(), report);
        assertEquals(1, errLines.size(), report);
        assertTrue(errLines.get(0).startsWith("particle-lab: cannot open the window: no display"),
                report);
    }

    /** @return the {@code java} of the JVM running the tests */
    private static String javaExecutable() {
        return Paths.get(System.getProperty("java.home"), "bin", "java").toString();
    }

    /**
     * The classpath of this test JVM, which holds the app, its libraries and the tests.
     *
     * @return the classpath (not empty)
     */
    private static String testClasspath() {
        String classpath = System.getProperty("java.class.path", "");
        String appClasses;
        try {
            appClasses = Paths.get(Main.class.getProtectionDomain().getCodeSource()
                    .getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException("cannot locate the app's classes", e);
        }
        assertTrue(List.of(classpath.split(File.pathSeparator)).contains(appClasses),
                "java.class.path of the test JVM does not hold the app's classes " + appClasses
                        + ": " + classpath);
        return classpath;
    }
}

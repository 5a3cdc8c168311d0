package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * One holder for the launcher's name and exit statuses ({@link Program}), and one template
 * for every command ({@link CommandSupport#execute}): read from the sources, so a command
 * that declares its own {@code OK} or spells "particle-lab" again fails here.
 */
class ProgramSourceTest {

    private static final Path APP = Paths.get("src", "main", "java", "particlelab", "app");
    /** A constant that looks like an exit status: OK, FAILED, USAGE, EXIT_CODE, ..._ERROR. */
    private static final Pattern STATUS_CONSTANT = Pattern.compile(
            "static final int (OK|USAGE|\\w*FAILED|EXIT\\w*|\\w*_ERROR)\\b");
    /** The launcher's name in a string literal: "particle-lab", "particle-lab ...". */
    private static final Pattern NAME_LITERAL = Pattern.compile("\"particle-lab[ :\"]");

    @Test
    void onlyProgramHoldsTheNameAndTheExitStatuses() throws IOException {
        List<String> found = new ArrayList<>();
        for (Path file : sources()) {
            if (file.getFileName().toString().equals("Program.java")) {
                continue;
            }
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            for (int i = 0; i < lines.size(); ++i) {
                String code = lines.get(i).trim();
                if (code.startsWith("*") || code.startsWith("/*") || code.startsWith("//")) {
                    continue;
                }
                if (STATUS_CONSTANT.matcher(code).find() || NAME_LITERAL.matcher(code).find()) {
                    found.add(file.getFileName() + ":" + (i + 1) + ": " + code);
                }
            }
        }
        assertEquals(List.of(), found, "exit statuses or the name held outside Program");
    }

    @Test
    void everyCommandRunsThroughTheOneTemplate() throws IOException {
        assertTrue(Commands.all().size() >= 10, Commands.all().toString());
        for (Command command : Commands.all()) {
            Path file = sources().stream().filter(path -> commandClass(path, command.name()))
                    .findFirst().orElseThrow(() -> new AssertionError("no source declares"
                            + " NAME = \"" + command.name() + "\""));
            String text = Files.readString(file, StandardCharsets.UTF_8);
            assertTrue(text.contains("CommandSupport.execute("), file.getFileName()
                    + " does not run through CommandSupport.execute");
            assertTrue(!text.contains("return Program.USAGE;"), file.getFileName()
                    + " reports a bad command line itself instead of the template");
        }
    }

    private static boolean commandClass(Path file, String name) {
        try {
            return Files.readString(file, StandardCharsets.UTF_8).contains(
                    "static final String NAME = \"" + name + "\";");
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    private static List<Path> sources() throws IOException {
        try (Stream<Path> walk = Files.list(APP)) {
            return walk.filter(path -> path.toString().endsWith(".java")).sorted()
                    .collect(Collectors.toList());
        }
    }
}

package particlelab;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The packages of the main code form no cycle (docs/architecture.md draws them as layers): a
 * package that uses another, by an import or a fully qualified name in code, is never used
 * back, directly or through others. The framework ({@code demo}) never names a demo
 * ({@code lecture}); only the launcher ({@code app}) uses the report ({@code accuracy}). Read
 * from the sources, so no class is loaded.
 */
class PackageCyclesTest {

    private static final Path MAIN = Paths.get("src", "main", "java", "particlelab");
    /** A use of another package: {@code particlelab.<package>.<Class>} in an import or code. */
    private static final Pattern USE = Pattern.compile("\\bparticlelab\\.([a-z]+)\\.[A-Z]");

    @Test
    void thePackagesOfTheMainCodeFormNoCycle() throws IOException {
        Map<String, Map<String, String>> uses = uses();
        assertTrue(uses.size() > 5, "found the packages: " + uses.keySet());
        List<String> cycle = findCycle(uses);
        assertEquals(List.of(), cycle, () -> "a cycle of packages: " + String.join(" -> ", cycle)
                + "; the first use of each: " + IntStream.range(1, cycle.size())
                .mapToObj(i -> uses.get(cycle.get(i - 1)).get(cycle.get(i)))
                .collect(Collectors.joining(", ")));
    }

    @Test
    void theFrameworkNamesNoDemo() throws IOException {
        assertEquals(null, uses().get("demo").get("lecture"),
                "the first class of demo that names a demo of lecture");
    }

    /**
     * The report ({@code accuracy}) is a leaf that only the launcher runs: the demos and the
     * framework use the reference steppers, exact paths and cost meter of {@code reference},
     * which never uses the report back.
     */
    @Test
    void noPackageButTheAppUsesTheReport() throws IOException {
        Map<String, String> users = new TreeMap<>();
        for (Map.Entry<String, Map<String, String>> from : uses().entrySet()) {
            String file = from.getValue().get("accuracy");
            if (file != null && !from.getKey().equals("app")) {
                users.put(from.getKey(), file);
            }
        }
        assertEquals(Map.of(), users, "packages that use the report, with their first file");
        assertTrue(uses().containsKey("reference"), "the reference package is scanned");
    }

    /** For each package, the packages it uses, each with the first file that does. */
    private static Map<String, Map<String, String>> uses() throws IOException {
        Map<String, Map<String, String>> uses = new TreeMap<>();
        List<Path> files;
        try (Stream<Path> walk = Files.walk(MAIN)) {
            files = walk.filter(path -> path.toString().endsWith(".java")).sorted()
                    .collect(Collectors.toList());
        }
        for (Path file : files) {
            Path relative = MAIN.relativize(file);
            if (relative.getNameCount() < 2) {
                continue;
            }
            String from = relative.getName(0).toString();
            Map<String, String> used = uses.computeIfAbsent(from, key -> new TreeMap<>());
            for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                String code = line.trim();
                if (code.startsWith("*") || code.startsWith("/*") || code.startsWith("//")
                        || code.startsWith("package ")) {
                    continue;
                }
                Matcher use = USE.matcher(code);
                while (use.find()) {
                    String to = use.group(1);
                    if (!to.equals(from)) {
                        used.putIfAbsent(to, relative.toString());
                    }
                }
            }
        }
        return uses;
    }

    /** A cycle as the packages along it, the first repeated at the end; empty if none. */
    private static List<String> findCycle(Map<String, Map<String, String>> uses) {
        TreeSet<String> done = new TreeSet<>();
        for (String start : uses.keySet()) {
            List<String> path = new ArrayList<>();
            List<String> cycle = visit(start, uses, path, done);
            if (!cycle.isEmpty()) {
                return cycle;
            }
        }
        return List.of();
    }

    private static List<String> visit(String from, Map<String, Map<String, String>> uses,
            List<String> path, TreeSet<String> done) {
        int at = path.indexOf(from);
        if (at >= 0) {
            List<String> cycle = new ArrayList<>(path.subList(at, path.size()));
            cycle.add(from);
            return cycle;
        }
        if (done.contains(from)) {
            return List.of();
        }
        path.add(from);
        for (String to : uses.getOrDefault(from, Map.of()).keySet()) {
            List<String> cycle = visit(to, uses, path, done);
            if (!cycle.isEmpty()) {
                return cycle;
            }
        }
        path.remove(path.size() - 1);
        done.add(from);
        return List.of();
    }
}

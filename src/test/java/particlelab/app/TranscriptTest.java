package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The pages' examples cannot go stale: every {@code $ particle-lab ...} line inside a fenced
 * block of README.md or a page under docs/ is run through {@link Main#run}, and what it prints
 * is compared with the lines the page shows under it (up to the next {@code $} line or the end
 * of the block). Stdout and stderr are compared together, as a terminal shows them.
 *
 * <p>What a page may write that is not the output to the letter, and how it is checked:
 * <ul>
 * <li>a line {@code ...} stands for any number of lines, none included;</li>
 * <li>{@code <measured>} inside a line stands for one figure that is measured and so varies
 * from run to run (a time, a count of distinct colours): any run of non-space characters;</li>
 * <li>{@code | tail -N} after the command keeps the last N lines of stdout, and
 * {@code > FILE} sends stdout away (only stderr is shown), as a shell would;</li>
 * <li>a command that opens a window ({@code demo} with {@code --frames}) needs a display, which
 * JUnit never has: it is listed by {@link #windowTranscripts} and run by CI's render smoke
 * test instead.</li>
 * </ul>
 */
class TranscriptTest {

    /** The prompt a page's command line starts with. */
    private static final String PROMPT = "$ particle-lab";
    /** A page's placeholder for one measured figure. */
    private static final String MEASURED = "<measured>";
    /** A page's line that stands for any number of output lines. */
    private static final String ELISION = "...";
    /** {@code | tail -N} at the end of a command. */
    private static final Pattern TAIL = Pattern.compile("\\s*\\|\\s*tail -(\\d+)$");
    /** {@code > FILE} at the end of a command. */
    private static final Pattern REDIRECT = Pattern.compile("\\s*>\\s*\\S+$");

    /**
     * One command line of a page and the output the page shows for it.
     *
     * @param page the page's path, relative to the project (for messages)
     * @param line the command's line number in the page (1-based)
     * @param command the words after {@code $ }, pipes and redirections included
     * @param expected the lines the page shows under it
     */
    record Transcript(String page, int line, String command, List<String> expected) {

        @Override
        public String toString() {
            return page + ":" + line + " $ " + command;
        }

        /** @return whether the command opens a window (and so needs a display) */
        boolean opensWindow() {
            List<String> words = Arrays.asList(command.split(" +"));
            return words.size() > 1 && words.get(1).equals(DemoCommand.NAME)
                    && words.contains("--frames");
        }
    }

    /**
     * Every transcript in the pages that runs without a window.
     *
     * @return the transcripts (not empty)
     * @throws IOException if a page cannot be read
     */
    static Stream<Transcript> transcripts() throws IOException {
        return all().stream().filter(t -> !t.opensWindow());
    }

    /**
     * Every transcript that opens a window: what render smoke must run.
     *
     * @return the transcripts
     * @throws IOException if a page cannot be read
     */
    static List<Transcript> windowTranscripts() throws IOException {
        List<Transcript> window = new ArrayList<>();
        for (Transcript transcript : all()) {
            if (transcript.opensWindow()) {
                window.add(transcript);
            }
        }
        return window;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("transcripts")
    void thePageShowsWhatTheCommandPrints(Transcript transcript) {
        String command = transcript.command();
        int tail = -1;
        Matcher tailMatch = TAIL.matcher(command);
        if (tailMatch.find()) {
            tail = Integer.parseInt(tailMatch.group(1));
            command = command.substring(0, tailMatch.start());
        }
        Matcher redirect = REDIRECT.matcher(command);
        boolean stdoutAway = redirect.find();
        if (stdoutAway) {
            command = command.substring(0, redirect.start());
        }
        assertFalse(command.contains("|") || command.contains(">") || command.contains("<"),
                transcript + ": only '| tail -N' and '> FILE' are understood");
        String[] words = command.trim().split(" +");
        CommandRun run = CommandRun.of(Arrays.copyOfRange(words, 1, words.length));
        List<String> out = stdoutAway ? List.of() : run.outLines();
        if (tail >= 0 && out.size() > tail) {
            out = out.subList(out.size() - tail, out.size());
        }
        List<String> err = run.errLines();
        List<String> outThenErr = new ArrayList<>(out);
        outThenErr.addAll(err);
        List<String> errThenOut = new ArrayList<>(err);
        errThenOut.addAll(out);
        if (!matches(transcript.expected(), outThenErr)
                && !matches(transcript.expected(), errThenOut)) {
            fail(transcript + " prints\n" + String.join("\n", outThenErr)
                    + "\nbut the page shows\n" + String.join("\n", transcript.expected()));
        }
    }

    @Test
    void thePagesHaveTranscriptsAndThePlaceholdersMatchOnlyWhatTheySay() throws IOException {
        assertTrue(transcripts().count() >= 20, "the pages' transcripts");
        assertTrue(matches(List.of("a", ELISION, "d"), List.of("a", "b", "c", "d")));
        assertTrue(matches(List.of("a", ELISION, "d"), List.of("a", "d")));
        assertFalse(matches(List.of("a", ELISION, "d"), List.of("a", "b")));
        assertTrue(matches(List.of("t=" + MEASURED + " ms"), List.of("t=1.25 ms")));
        assertFalse(matches(List.of("t=" + MEASURED + " ms"), List.of("t=1.25 s")));
        assertFalse(matches(List.of("t=" + MEASURED + " ms"), List.of("t= ms")));
        assertFalse(matches(List.of("x"), List.of("x", "y")));
    }

    @Test
    void everyWindowTranscriptIsOneTheRenderSmokeTestRuns() throws IOException {
        // CI's render smoke test runs them with .ci/window-transcripts.py, by the same rules.
        String smoke = Files.readString(Paths.get(".ci", "render-smoke"));
        String checker = Files.readString(Paths.get(".ci", "window-transcripts.py"));
        assertTrue(smoke.contains("window-transcripts.py"), "render-smoke runs the checker");
        assertTrue(checker.contains(MEASURED) && checker.contains("\"" + ELISION + "\""),
                "the checker knows the pages' placeholders");
        assertTrue(windowTranscripts().size() >= 1, "the pages show a window transcript");
    }

    /** Every fenced transcript of README.md and of the pages under docs/. */
    private static List<Transcript> all() throws IOException {
        List<Path> pages = new ArrayList<>();
        pages.add(Paths.get("README.md"));
        try (Stream<Path> docs = Files.walk(Paths.get("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(pages::add);
        }
        List<Transcript> found = new ArrayList<>();
        for (Path page : pages) {
            parse(page, Files.readAllLines(page), found);
        }
        return found;
    }

    private static void parse(Path page, List<String> lines, List<Transcript> found) {
        boolean fenced = false;
        Transcript open = null;
        for (int i = 0; i < lines.size(); ++i) {
            String line = lines.get(i);
            if (line.startsWith("```")) {
                fenced = !fenced;
                open = close(open, found);
            } else if (fenced && line.startsWith(PROMPT + " ")) {
                close(open, found);
                open = new Transcript(page.toString(), i + 1, line.substring(2),
                        new ArrayList<>());
            } else if (fenced && open != null) {
                open.expected().add(line);
            }
        }
        close(open, found);
    }

    /** Keep an open transcript, its trailing blank lines left out. */
    private static Transcript close(Transcript open, List<Transcript> found) {
        if (open != null) {
            List<String> expected = open.expected();
            while (!expected.isEmpty() && expected.get(expected.size() - 1).isBlank()) {
                expected.remove(expected.size() - 1);
            }
            found.add(open);
        }
        return null;
    }

    /** Whether the actual lines are what the page's lines describe (see the class Javadoc). */
    private static boolean matches(List<String> expected, List<String> actual) {
        return matchFrom(expected, 0, actual, 0);
    }

    private static boolean matchFrom(List<String> expected, int e, List<String> actual, int a) {
        if (e == expected.size()) {
            return a == actual.size();
        }
        if (expected.get(e).equals(ELISION)) {
            for (int skip = a; skip <= actual.size(); ++skip) {
                if (matchFrom(expected, e + 1, actual, skip)) {
                    return true;
                }
            }
            return false;
        }
        return a < actual.size() && lineMatches(expected.get(e), actual.get(a))
                && matchFrom(expected, e + 1, actual, a + 1);
    }

    private static boolean lineMatches(String expected, String actual) {
        if (!expected.contains(MEASURED)) {
            return expected.equals(actual);
        }
        StringBuilder regex = new StringBuilder();
        String[] parts = expected.split(Pattern.quote(MEASURED), -1);
        for (int i = 0; i < parts.length; ++i) {
            if (i > 0) {
                regex.append("\\S+");
            }
            regex.append(Pattern.quote(parts[i]));
        }
        return actual.matches(regex.toString());
    }
}

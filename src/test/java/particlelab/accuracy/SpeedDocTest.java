package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import particlelab.reference.CostMeter;


/**
 * {@code docs/speed.md} shows the report's side-by-side section as a full report wrote it:
 * the block between its two markers is read back into rows (the measured figures), and the
 * report's own table builder must write exactly that block from them, labels, targets,
 * verdicts, spread flags and text included. So the page can hold only figures a report
 * printed in that form, and it must be pasted anew when the section's form changes.
 */
class SpeedDocTest {

    static final String BEGIN = "<!-- pasted from a full report's index.md: begin -->";
    static final String END = "<!-- pasted from a full report's index.md: end -->";
    private static final ReportConfig FULL = ReportConfig.of(ReportConfig.Size.FULL);
    private static final Pattern SPREAD = Pattern.compile(
            "([0-9.]+) / \\*\\*([0-9.]+)\\*\\* / ([0-9.]+)×?");
    private static final Pattern ROUNDS = Pattern.compile("over (\\d+) rounds");
    /** The heading of the section on the one-particle rows' store order (issue 35 §3). */
    static final String PASTED_ONE_PARTICLE =
            "One particle: the store order, found in the machine code (issue 35 §3)";
    /** The heading of the section on the fountain against stepPacked (issue 35 §4). */
    static final String PASTED_FOUNTAIN =
            "The fountain's whole step against `stepPacked`, A/A-controlled (issue 35 §4)";

    @Test
    void speedPageShowsTheReportsSideBySideSectionAsTheReportWritesIt() throws IOException {
        String page = new String(Files.readAllBytes(Paths.get("docs", "speed.md")),
                StandardCharsets.UTF_8);
        int begin = page.indexOf(BEGIN);
        int end = page.indexOf(END);
        assertTrue(begin >= 0 && end > begin, "docs/speed.md has no pasted report section");
        String block = page.substring(begin + BEGIN.length(), end).trim() + "\n";
        List<SpeedSpreads.Line> lines = new ArrayList<>();
        List<SpeedSpreads.PeerRow> peers = new ArrayList<>();
        List<String> comparisons = new ArrayList<>();
        List<Integer> counts = new ArrayList<>();
        for (String row : block.split("\n")) {
            if (!row.startsWith("| ") || row.startsWith("| comparison ")
                    || row.startsWith("| N ")) {
                continue;
            }
            String[] cells = row.substring(2, row.length() - 2).split(" \\| ");
            if (cells.length == 6) {
                comparisons.add(cells[0]);
                lines.add(line(cells));
            } else {
                assertEquals(11, cells.length, row);
                counts.add(Integer.parseInt(cells[0]));
                peers.add(peer(cells));
            }
        }
        assertEquals(SpeedSpreads.comparisons(FULL), comparisons, "the full report's rows");
        List<Integer> expectedCounts = new ArrayList<>();
        for (int count : SpeedSpreads.peerCounts(FULL)) {
            expectedCounts.add(count);
        }
        assertEquals(expectedCounts, counts, "the full report's peer sizes");
        Matcher rounds = ROUNDS.matcher(block);
        assertTrue(rounds.find(), "no round count in the pasted section");
        StringBuilder rebuilt = new StringBuilder();
        SpeedSpreads.appendTables(rebuilt, lines, peers, Integer.parseInt(rounds.group(1)),
                FULL);
        String[] expected = (rebuilt.toString().trim() + "\n").split("\n", -1);
        String[] pasted = block.split("\n", -1);
        assertEquals(expected.length, pasted.length, "lines in the pasted block");
        for (int i = 0; i < pasted.length; ++i) {
            if (!expected[i].equals(pasted[i])) {
                assertOnlyTheVerdictDiffersAtTheBound(expected[i], pasted[i]);
            }
        }
    }

    @Test
    void everyRatioTheSectionStatesIsInThePastedRun() throws IOException {
        // The prose around the pasted block once kept figures its table had lost (2.40× and
        // 2.58× beside a table of 2.32× and 2.33×): each ratio the section states in words
        // ("2.3×", "1.8–2.0×", "1.6 times") must be a figure of the pasted run.
        String page = new String(Files.readAllBytes(Paths.get("docs", "speed.md")),
                StandardCharsets.UTF_8);
        int begin = page.indexOf(BEGIN);
        int end = page.indexOf(END);
        assertTrue(begin >= 0 && end > begin, "docs/speed.md has no pasted report section");
        int start = page.lastIndexOf("\n## ", begin);
        int stop = page.indexOf("\n## ", end);
        String block = page.substring(begin, end);
        String prose = page.substring(start, begin) + page.substring(end + END.length(), stop);
        List<String> stated = statedRatios(prose);
        assertTrue(stated.size() >= 4, "the section states too few ratios to check: " + stated);
        for (String ratio : stated) {
            assertTrue(Pattern.compile("(?<![0-9.])" + Pattern.quote(ratio) + "(?![0-9])")
                    .matcher(block).find(), ratio + "× is stated beside the pasted run but is "
                    + "not one of its figures");
        }
    }

    @Test
    void everyRatioOfTheIssue35SectionsIsInTheRunsPastedThere() throws IOException {
        // The sections on issue 35's one-particle and fountain rows state ratios in words
        // beside the runs they paste (in fenced blocks, as the tools printed them): each
        // ratio stated outside the blocks must be a figure of one of the section's blocks.
        String page = new String(Files.readAllBytes(Paths.get("docs", "speed.md")),
                StandardCharsets.UTF_8);
        for (String heading : new String[] {PASTED_ONE_PARTICLE, PASTED_FOUNTAIN}) {
            int start = page.indexOf("\n### " + heading);
            assertTrue(start >= 0, "docs/speed.md has no section " + heading);
            int stop = page.indexOf("\n## ", start + 1);
            int next = page.indexOf("\n### ", start + 1);
            String section = page.substring(start, next >= 0 && next < stop ? next : stop);
            String[] parts = section.split("\n```[a-z]*\n", -1);
            StringBuilder prose = new StringBuilder();
            StringBuilder runs = new StringBuilder();
            for (int i = 0; i < parts.length; ++i) {
                (i % 2 == 0 ? prose : runs).append(parts[i]).append('\n');
            }
            List<String> stated = statedRatios(prose.toString());
            assertTrue(stated.size() >= 4, heading + " states too few ratios: " + stated);
            assertTrue(runs.length() > 0, heading + " pastes no run");
            for (String ratio : stated) {
                assertTrue(Pattern.compile("(?<![0-9.])" + Pattern.quote(ratio)
                        + "(?![0-9])").matcher(runs).find(), ratio + "× is stated in "
                        + heading + " but is not a figure of the runs pasted there");
            }
        }
    }

    @Test
    void statedRatiosAreReadFromSignsWordsAndRanges() {
        assertEquals(List.of("2.3", "1.8", "2.0", "1.6", "1.3", "1.7", "4.1"),
                statedRatios("2.3× and 1.8–2.0× here, 1.6, 1.3 and 1.7 times; 4.1 times"));
    }

    /** The ratios a text states: "a×", "a–b×", "a times", "a, b and c times". */
    static List<String> statedRatios(String text) {
        List<String> ratios = new ArrayList<>();
        Matcher m = Pattern.compile("((?:[0-9]+(?:\\.[0-9]+)?(?:, | and |–))*[0-9]+"
                + "(?:\\.[0-9]+)?)(?:×| times)").matcher(text);
        while (m.find()) {
            for (String number : m.group(1).split(", | and |–")) {
                ratios.add(number);
            }
        }
        return ratios;
    }

    /**
     * The figures are pasted rounded (ratios of the peer table to 0.1), so a row whose
     * max ÷ min lies at the spread bound may be judged from the unrounded figures one way and
     * from the rounded ones the other: then only the last cell may differ, and the bound
     * must lie within the rounding of max ÷ min.
     */
    private static void assertOnlyTheVerdictDiffersAtTheBound(String expected, String pasted) {
        int cut = expected.lastIndexOf(" | ", expected.length() - 3);
        assertEquals(expected.substring(0, cut), pasted.substring(0, Math.min(cut,
                pasted.length())), "a pasted row differs from the report's form");
        boolean atBound = false;
        Matcher m = Pattern.compile("([0-9.]+) / \\*\\*[0-9.]+\\*\\* / ([0-9.]+)×?")
                .matcher(pasted);
        while (m.find()) {
            String low = m.group(1);
            String high = m.group(2);
            int decimals = low.length() - low.indexOf('.') - 1;
            double half = 0.5 * Math.pow(10, -decimals);
            double lo = Double.parseDouble(low);
            double hi = Double.parseDouble(high);
            atBound |= (hi - half) / (lo + half) <= SpeedSpreads.SPREAD_BOUND
                    && (hi + half) / (lo - half) > SpeedSpreads.SPREAD_BOUND;
        }
        assertTrue(atBound, "the verdict of this row disagrees with its figures: " + pasted);
    }

    /** A ratio row: comparison, collector, ratio, A/A, target, verdict. */
    private static SpeedSpreads.Line line(String[] cells) {
        boolean atMost = cells[4].startsWith("≤");
        double target = Double.parseDouble(cells[4].substring(2, cells[4].length() - 1));
        if (cells[2].equals("—")) {
            String failure = cells[5].substring("not measured: ".length());
            return new SpeedSpreads.Line(cells[0], cells[1], target, atMost, failure);
        }
        return new SpeedSpreads.Line(cells[0], cells[1], spread(cells[2]), spread(cells[3]),
                target, atMost, true);
    }

    /** A peer row of a full run: the run recorded its full collection ("judged" or not). */
    private static SpeedSpreads.PeerRow peer(String[] cells) {
        String[] emitterBytes = cells[7].split(" \\+ ");
        return new SpeedSpreads.PeerRow(Integer.parseInt(cells[0]), spread(cells[1]),
                spread(cells[2]), spread(cells[3]), spread(cells[4]), spread(cells[5]),
                spread(cells[6]), Double.parseDouble(emitterBytes[0]),
                Double.parseDouble(emitterBytes[1]), Double.parseDouble(cells[8]), true,
                !cells[10].equals(SpeedSpreads.NO_FULL_GC));
    }

    private static CostMeter.Spread spread(String cell) {
        Matcher m = SPREAD.matcher(cell);
        assertTrue(m.matches(), "not a spread: " + cell);
        return new CostMeter.Spread(Double.parseDouble(m.group(1)),
                Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3)));
    }
}

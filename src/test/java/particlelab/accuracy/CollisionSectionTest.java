package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.reference.CostMeter;
import particlelab.world.Detection;


/** The collision section's files and prose, written from a tiny study. */
class CollisionSectionTest {

    private static final String EARLIER = "# Speed against error\n\nearlier sections\n\n";

    @TempDir
    static Path shared;
    private static Path folder;
    private static CollisionStudy study;

    @BeforeAll
    static void writeTinySection() throws IOException {
        ReportConfig tiny = ReportConfig.of(ReportConfig.Size.TINY);
        study = CollisionStudy.run(tiny, new CostMeter(tiny.budget()));
        folder = shared.resolve("report");
        Files.createDirectories(folder);
        Files.write(folder.resolve("index.md"), EARLIER.getBytes(StandardCharsets.UTF_8));
        CollisionSection.write(study, folder);
    }

    @Test
    void writesEveryFileAndAppendsToIndex() throws IOException {
        ReportFiles.assertWritten(folder, CollisionSection.FILES);
        String index = read("index.md");
        assertTrue(index.startsWith(EARLIER), "the earlier sections were overwritten");
        assertTrue(index.contains(CollisionSection.HEADING + "\n"));
        assertTrue(index.contains("](" + CollisionSection.TUNNELLING_PLOT + ")"));
        assertTrue(index.contains("](" + CollisionSection.BOUNCE_PLOT + ")"));
        assertTrue(index.contains("`tunnelling.csv` (`" + CollisionSection.TUNNELLING_HEADER
                + "`)"), "the section does not state the tunnelling header");
    }

    @Test
    void csvHeadersAreExactlyAsDocumented() throws IOException {
        assertEquals("v_h_over_2r_plus_d,shots,overlap_misses,overlap_miss_rate,swept_misses,"
                + "predicted_miss_probability,overlap_low_95,overlap_high_95",
                lines("tunnelling.csv").get(0));
        assertEquals("detection,balls,ns_per_step,bytes_per_step,contacts_per_step,cap_hits,"
                + "cost_over_overlap", lines("collision_cost.csv").get(0));
        assertEquals("detection,h_s,impact,t_s,ideal_t_s,t_error_s,apex_m,ideal_apex_m,"
                + "apex_error_m", lines("bounce_error.csv").get(0));
    }

    @Test
    void csvRowsParseBackToTheStudy() throws IOException {
        List<String> tunnel = lines("tunnelling.csv");
        assertEquals(study.tunnels.size() + 1, tunnel.size());
        for (int i = 0; i < study.tunnels.size(); ++i) {
            CollisionStudy.Tunnel t = study.tunnels.get(i);
            String[] cells = tunnel.get(i + 1).split(",");
            assertEquals(t.travelRatio, Double.parseDouble(cells[0]));
            assertEquals(t.shots, Integer.parseInt(cells[1]));
            assertEquals(t.overlapMisses, Integer.parseInt(cells[2]));
            assertEquals(t.overlapRate(), Double.parseDouble(cells[3]));
            assertEquals(t.sweptMisses, Integer.parseInt(cells[4]));
            assertEquals(t.predicted, Double.parseDouble(cells[5]));
        }
        List<String> cost = lines("collision_cost.csv");
        assertEquals(3, cost.size());
        assertTrue(cost.get(1).startsWith("overlap," + CollisionStudy.COST_BALLS + ","));
        assertTrue(cost.get(2).startsWith("swept," + CollisionStudy.COST_BALLS + ","));
        assertEquals(1.0, Double.parseDouble(last(cost.get(1))));
        assertEquals(CollisionSection.cost(study, Detection.SWEPT).nanosPerStep
                / CollisionSection.cost(study, Detection.OVERLAP).nanosPerStep,
                Double.parseDouble(last(cost.get(2))));
        List<String> bounce = lines("bounce_error.csv");
        assertEquals(2 * CollisionStudy.bounceSteps().length * CollisionStudy.BOUNCE_IMPACTS + 1,
                bounce.size());
        for (int i = 0; i < study.impacts.size(); ++i) {
            CollisionStudy.Impact impact = study.impacts.get(i);
            String[] cells = bounce.get(i + 1).split(",");
            assertEquals(CollisionSection.name(impact.detection), cells[0]);
            assertEquals(impact.number, Integer.parseInt(cells[2]));
            assertEquals(impact.timeError(), Double.parseDouble(cells[5]));
            assertEquals(impact.apexError(), Double.parseDouble(cells[8]));
        }
    }

    @Test
    void sectionNumbersAreTheStudyResults() throws IOException {
        String index = read("index.md");
        List<String[]> rows = tableRows(index, "| v·h/(2r+D) |");
        assertEquals(study.tunnels.size(), rows.size());
        for (int i = 0; i < rows.size(); ++i) {
            CollisionStudy.Tunnel t = study.tunnels.get(i);
            String[] cells = rows.get(i);
            assertEquals(t.travelRatio, Double.parseDouble(cells[0]));
            assertEquals(t.predicted, Double.parseDouble(cells[2]), 5e-5);
            assertEquals(t.overlapMisses, Integer.parseInt(cells[3]));
            assertEquals(t.overlapRate(), Double.parseDouble(cells[4]), 5e-5);
            assertEquals(t.sweptMisses, Integer.parseInt(cells[7]));
        }
        List<String[]> costs = tableRows(index, "| detection | ns per world step |");
        assertEquals(2, costs.size());
        for (int i = 0; i < costs.size(); ++i) {
            CollisionStudy.Cost c = study.costs.get(i);
            assertEquals(CollisionSection.name(c.detection), costs.get(i)[0]);
            assertEquals(c.nanosPerStep, Double.parseDouble(costs.get(i)[1]), 0.5);
            assertEquals(c.capHits, Long.parseLong(costs.get(i)[4]));
        }
        List<String[]> errors = tableRows(index, "| h (s) |");
        // one row per step size, then the fitted orders
        assertEquals(CollisionStudy.bounceSteps().length + 1, errors.size());
        List<CollisionStudy.BounceError> overlap = CollisionSection.errors(study,
                Detection.OVERLAP);
        for (int i = 0; i < overlap.size(); ++i) {
            CollisionStudy.BounceError o = overlap.get(i);
            assertEquals("1/" + Math.round(1 / o.stepSeconds), errors.get(i)[0]);
            assertEquals(o.worstTimeError, Double.parseDouble(errors.get(i)[1]),
                    0.006 * o.worstTimeError);
            assertEquals(o.worstApexError, Double.parseDouble(errors.get(i)[2]),
                    0.006 * o.worstApexError);
        }
        String[] orders = errors.get(errors.size() - 1);
        CollisionStudy.BounceOrder o = CollisionSection.order(study, Detection.OVERLAP);
        CollisionStudy.BounceOrder s = CollisionSection.order(study, Detection.SWEPT);
        assertEquals(o.timeOrder, Double.parseDouble(orders[1]), 0.005);
        assertEquals(o.apexOrder, Double.parseDouble(orders[2]), 0.005);
        assertEquals(s.timeOrder, Double.parseDouble(orders[3]), 0.005);
        assertEquals(s.apexOrder, Double.parseDouble(orders[4]), 0.005);
    }

    @Test
    void theReportRunsTheSectionAfterItsOwn() throws IOException {
        Path report = shared.resolve("whole");
        new SpeedVsErrorReport(ReportConfig.of(ReportConfig.Size.TINY), report, null)
                .write(new PrintStream(new ByteArrayOutputStream(), true), false);
        for (String name : CollisionSection.FILES) {
            assertTrue(Files.isRegularFile(report.resolve(name)), "missing " + name);
        }
        String index = new String(Files.readAllBytes(report.resolve("index.md")),
                StandardCharsets.UTF_8);
        assertTrue(index.startsWith("# "), index.substring(0, 40));
        assertEquals(1, index.split(CollisionSection.HEADING, -1).length - 1);
    }

    /** The body rows of the markdown table whose header starts with {@code header}. */
    private static List<String[]> tableRows(String markdown, String header) {
        String[] lines = markdown.split("\n");
        List<String[]> rows = new ArrayList<>();
        for (int i = 0; i < lines.length; ++i) {
            if (!lines[i].startsWith(header)) {
                continue;
            }
            for (int k = i + 2; k < lines.length && lines[k].startsWith("|"); ++k) {
                String[] cells = lines[k].substring(1).split("\\|");
                for (int c = 0; c < cells.length; ++c) {
                    cells[c] = cells[c].trim();
                }
                rows.add(cells);
            }
            return rows;
        }
        throw new AssertionError("no table headed " + header);
    }

    private static String last(String csvRow) {
        return csvRow.substring(csvRow.lastIndexOf(',') + 1);
    }

    private static String read(String name) throws IOException {
        return new String(Files.readAllBytes(folder.resolve(name)), StandardCharsets.UTF_8);
    }

    private static List<String> lines(String name) throws IOException {
        return Files.readAllLines(folder.resolve(name), StandardCharsets.UTF_8);
    }
}

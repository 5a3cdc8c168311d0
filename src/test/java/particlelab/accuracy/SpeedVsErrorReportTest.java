package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.reference.CostMeter;
import particlelab.reference.Scheme;


/** The report's files, written by {@link SpeedVsErrorReport} on the tiny sweep. */
class SpeedVsErrorReportTest {

    /** One tiny report shared by the tests that read its files (about two seconds). */
    @TempDir
    static Path shared;
    private static Path folder;

    @BeforeAll
    static void writeTinyReport() throws IOException {
        folder = shared.resolve("report");
        write(folder, null);
    }

    @Test
    void tinyReportWritesEveryFileItPromises() throws IOException {
        ReportFiles.assertWritten(folder, SpeedVsErrorReport.FILES);
        String index = read("index.md");
        for (String name : SpeedVsErrorReport.FILES) {
            if (name.endsWith(".png")) {
                assertTrue(index.contains(name), "index.md does not show " + name);
            }
        }
    }

    @Test
    void theWorkPrecisionChartDrawsEachCostsSpreadAsABarThroughItsPoint() {
        CanonicalCase scene = CanonicalCase.all().get(0);
        Scheme scheme = Scheme.SEMI_IMPLICIT_EULER;
        List<WorkPrecisionStudy.Point> points = List.of(
                new WorkPrecisionStudy.Point(scene, scheme, 0.1, 40, 0.25,
                        new CostMeter.Spread(3.0, 4.0, 6.0)),
                new WorkPrecisionStudy.Point(scene, scheme, 0.01, 400, 0.0,
                        new CostMeter.Spread(3.5, 3.5, 3.5)));
        org.knowm.xchart.XYChart chart = SpeedVsErrorReport.workPrecisionChart(scene, points);
        java.util.Map<String, org.knowm.xchart.XYSeries> series = chart.getSeriesMap();
        // the line: the medians per simulated second (4 / 0.1 and 3.5 / 0.01, exact in double
        // up to one rounding each, hence 1e-9 relative)
        double[] lineX = series.get(scheme.shortLabel()).getXData();
        assertEquals(40.0, lineX[0], 40.0 * 1e-9);
        assertEquals(350.0, lineX[1], 350.0 * 1e-9);
        // a bar per point, min to max at the point's (floored) error, not in the legend
        org.knowm.xchart.XYSeries wide = series.get(scheme.shortLabel() + " spread 0");
        assertEquals(30.0, wide.getXData()[0], 30.0 * 1e-9);
        assertEquals(60.0, wide.getXData()[1], 60.0 * 1e-9);
        assertEquals(0.25, wide.getYData()[0]);
        assertEquals(0.25, wide.getYData()[1]);
        assertTrue(!wide.isShowInLegend());
        org.knowm.xchart.XYSeries exact = series.get(scheme.shortLabel() + " spread 1");
        assertEquals(Charts.LOG_FLOOR, exact.getYData()[0]);
        assertEquals(3, series.size());
    }

    @Test
    void ordersCsvHasItsFixedHeaderAndARowPerCaseAndStepper() throws IOException {
        List<String> lines = lines("orders.csv");
        assertEquals("case,stepper,measured_order,theoretical_order", lines.get(0));
        int expected = 0;
        for (CanonicalCase scene : CanonicalCase.all()) {
            for (Scheme scheme : Scheme.values()) {
                if (scheme.supports(scene.forces())) {
                    ++expected;
                    assertTrue(lines.contains(lines.stream().filter(l -> l.startsWith(
                            scene.id() + "," + scheme.id() + ",")).findFirst().orElse("?")),
                            "no row for " + scene.id() + ", " + scheme.id());
                }
            }
        }
        assertEquals(expected, lines.size() - 1);
        // even the tiny sweep (h down to 1/120 s) measures forward Euler's order on drag
        String row = lines.stream().filter(l -> l.startsWith("drag-0.5,forward-euler,"))
                .findFirst().orElseThrow(AssertionError::new);
        double measured = Double.parseDouble(row.split(",")[2]);
        assertEquals(1.0, measured, 0.15, row);
    }

    @Test
    void stabilityCsvHasItsFixedHeaderAndTheEulerLimit() throws IOException {
        List<String> lines = lines("stability.csv");
        assertEquals("stepper,b_over_m,max_stable_h,theory_h", lines.get(0));
        assertEquals(Scheme.values().length * ReportConfig.of(ReportConfig.Size.TINY)
                .linearRates().length, lines.size() - 1);
        String row = lines.stream().filter(l -> l.startsWith("forward-euler,10,"))
                .findFirst().orElseThrow(AssertionError::new);
        String[] cells = row.split(",");
        // 2m/b at b/m = 10 /s, to the bisection's tolerance (well inside 1%)
        assertEquals(0.2, Double.parseDouble(cells[2]), 0.002, row);
        assertEquals(0.2, Double.parseDouble(cells[3]), 1e-12, row);
    }

    @Test
    void benchmarksCsvHasItsFixedHeaderAndEveryRow() throws IOException {
        List<String> lines = lines("benchmarks.csv");
        assertEquals("benchmark,ns_per_particle_step,bytes_per_step", lines.get(0));
        BenchmarkTable table = BenchmarkTable.read(folder.resolve("benchmarks.csv"));
        for (Scheme scheme : Scheme.values()) {
            assertNotNull(table.find(scheme.id()), "no row for " + scheme.id());
        }
        BenchmarkTable.Row lecture = table.find(BenchmarkTable.LECTURE_STYLE);
        assertNotNull(lecture);
        assertNotNull(table.find(BenchmarkTable.PRIMITIVE_LOOP));
        assertNotNull(table.find(BenchmarkTable.bulkName(BenchmarkTable.BULK_BATCH, 1000)));
        // the lecture style replaces position and velocity with new Vector3fs every step:
        // at least two 24-byte objects, whatever escape analysis removes
        assertTrue(lecture.bytesPerStep() >= 40.0, "lecture style allocated "
                + lecture.bytesPerStep());
    }

    @Test
    void targetsTableHasARowPerMixAndParticleCountWithItsTargets() throws IOException {
        String index = read("index.md");
        int start = index.indexOf("### Speed targets for every force mix");
        assertTrue(start >= 0, "index.md has no targets table");
        String section = index.substring(start, index.indexOf("\n### ", start + 1));
        assertTrue(section.contains("](" + MixTargets.PLOT + ")"), section);
        assertTrue(section.contains("| objects ≤ 2× primitive | objects ≥ 5× faster than "
                + "lecture | batch ≤ 1.5× primitive |"), section);
        // the tiny sweep: N = 1 (one particle) and its one bulk count, 1000
        for (String mix : new String[] {"gravity", "linear", "quadratic", "thrust-linear"}) {
            for (int count : new int[] {1, 1000}) {
                String row = "\n| " + mix + " | " + count + " | ";
                assertTrue(section.contains(row), "no row" + row.trim() + " in " + section);
            }
        }
    }

    @Test
    void speedSectionShowsTheRatiosWithSpreadsAndTheEmitterPeer() throws IOException {
        String index = read("index.md");
        int start = index.indexOf("### Side by side, with spreads");
        assertTrue(start >= 0, "index.md has no side-by-side section");
        String section = index.substring(start, index.indexOf("\n### Why", start + 1));
        for (String comparison : SpeedSpreads.comparisons(ReportConfig.of(
                ReportConfig.Size.TINY))) {
            assertTrue(section.contains("\n| " + comparison + " | "), "no row " + comparison
                    + " in " + section);
        }
        // both collectors named, the tiny sweep saying why it has no child JVM
        assertTrue(section.contains("(child JVM, `-XX:+UseParallelGC`)"), section);
        assertTrue(section.contains("not measured: the tiny sweep starts no child JVM"),
                section);
        assertTrue(section.contains("exceeds 1.5 says \"too noisy: no verdict\""), section);
        assertTrue(section.contains("### jME's ParticleEmitter beside the fountain and "
                + "`stepPacked`"), section);
        Matcher peer = Pattern.compile("\n\\| 10000 \\| [0-9.]+ / \\*\\*[0-9.]+\\*\\* / "
                + "[0-9.]+ \\|").matcher(section);
        assertTrue(peer.find(), "no peer row at N = 10000 in " + section);
        // the emitter timed after one full collection (issue 35), and the section says so
        assertTrue(section.contains("then one full collection runs (`System.gc()`) before "
                + "the rounds start"), section);
        assertTrue(section.contains("What the batch form gains a jME user"), section);
    }

    @Test
    void jmhResultsReplaceTheInProcessBenchmarks(@TempDir Path temp) throws IOException {
        Path jmh = temp.resolve("jmh.csv");
        Files.write(jmh, ("benchmark,ns_per_particle_step,bytes_per_step\n"
                + "rk4,40.5,0.00\nbulk/shared-batch/1000,0.4,0.00\n")
                .getBytes(StandardCharsets.UTF_8));
        Path out = temp.resolve("report");
        write(out, jmh);
        BenchmarkTable table = BenchmarkTable.read(out.resolve("benchmarks.csv"));
        assertEquals(2, table.rows().size());
        assertEquals(40.5, table.find("rk4").nanosPerParticleStep(), 0.0);
        String index = new String(Files.readAllBytes(out.resolve("index.md")),
                StandardCharsets.UTF_8);
        assertTrue(index.contains("comes from JMH"), "index.md does not say the source");
    }

    @Test
    void stiffRecommendationPutsTheSixtiethSecondLimitAtOneHundredTwentyPerSecond()
            throws IOException {
        // h = 2m/b at h = 1/60 s means b/m = 2/h = 120 /s (the old prose said 60 /s)
        assertEquals(120.0, SpeedVsErrorReport.stiffRate(Scheme.SEMI_IMPLICIT_EULER,
                SpeedVsErrorReport.DEMO_STEP_SECONDS), 1e-9);
        String recommendations = recommendations();
        assertTrue(recommendations.contains("at b/m = 120 /s"), recommendations);
    }

    @Test
    void dragRecommendationBoundIsTheLargestErrorOfEveryLinearDragCase() throws IOException {
        // the old prose quoted one case's error as the bound, below another case's 0.702 m
        double largest = 0.0;
        String worst = null;
        for (String line : lines("work-precision.csv").subList(1,
                lines("work-precision.csv").size())) {
            String[] cells = line.split(",");
            boolean linearDrag = false;
            for (CanonicalCase scene : SpeedVsErrorReport.linearDragCases()) {
                linearDrag |= scene.id().equals(cells[0]);
            }
            double h = Double.parseDouble(cells[2]);
            if (linearDrag && cells[1].equals(Scheme.SEMI_IMPLICIT_EULER.id())
                    && Math.abs(h - SpeedVsErrorReport.DEMO_STEP_SECONDS) < 1e-12) {
                double error = Double.parseDouble(cells[4]);
                if (error > largest) {
                    largest = error;
                    worst = cells[0];
                }
            }
        }
        assertNotNull(worst, "no linear-drag case at h = 1/60 s");
        String bound = String.format(Locale.ROOT, "is at most %.3g m", largest);
        String recommendations = recommendations();
        assertTrue(recommendations.contains(bound), "expected '" + bound + "' in "
                + recommendations);
    }

    @Test
    void noRatioInTheReportSaysFasterForAFactorOfOneOrLess() throws IOException {
        String index = read("index.md");
        Matcher factor = Pattern.compile("([0-9.]+)× (faster|slower)").matcher(index);
        while (factor.find()) {
            assertTrue(Double.parseDouble(factor.group(1)) > 1.0,
                    "a ratio reads '" + factor.group() + "'");
        }
    }

    private static String recommendations() throws IOException {
        String index = read("index.md");
        int start = index.indexOf("## Recommendations");
        assertTrue(start >= 0, "index.md has no Recommendations");
        return index.substring(start);
    }

    private static void write(Path out, Path jmh) throws IOException {
        new SpeedVsErrorReport(ReportConfig.of(ReportConfig.Size.TINY), out, jmh)
                .write(new PrintStream(new ByteArrayOutputStream(), true), false);
    }

    private static String read(String name) throws IOException {
        return new String(Files.readAllBytes(folder.resolve(name)), StandardCharsets.UTF_8);
    }

    private static List<String> lines(String name) throws IOException {
        return Files.readAllLines(folder.resolve(name), StandardCharsets.UTF_8);
    }
}

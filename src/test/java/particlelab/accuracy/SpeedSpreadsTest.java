package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.reference.CostMeter;


/** The side-by-side section's verdicts, labels and child JVM, on fixed numbers. */
class SpeedSpreadsTest {

    private static final ReportConfig FULL = ReportConfig.of(ReportConfig.Size.FULL);

    @Test
    void aRowIsJudgedByItsMedianUnlessItsRoundsSpreadBeyondTheBound() {
        CostMeter.Spread steady = new CostMeter.Spread(1.5, 1.6, 1.7);
        assertEquals("met", line(steady, 2.0, true).verdict());
        assertEquals("**missed**", line(steady, 1.5, true).verdict());
        assertEquals("met", line(steady, 1.6, false).verdict(), "at least 1.6: met at 1.6");
        // max ÷ min = 3.1 / 2.0 > 1.5: no verdict, whatever the median says
        CostMeter.Spread noisy = new CostMeter.Spread(2.0, 2.1, 3.1);
        assertEquals(SpeedSpreads.TOO_NOISY, line(noisy, 5.0, true).verdict());
        assertEquals(SpeedSpreads.TOO_NOISY, line(noisy, 1.0, true).verdict());
        SpeedSpreads.Line failed = new SpeedSpreads.Line("x", "Parallel", null, 5.0, false,
                "the child JVM exited with 1 and no ratio");
        assertEquals("not measured: the child JVM exited with 1 and no ratio",
                failed.verdict());
    }

    @Test
    void aRowShowsItsSpreadAndTarget() {
        SpeedSpreads.Line row = new SpeedSpreads.Line(SpeedSpreads.LECTURE,
                "G1, default heap", new CostMeter.Spread(5.012, 5.5, 6.0), 5.0, false);
        assertEquals("| " + SpeedSpreads.LECTURE + " | G1, default heap | 5.01 / **5.50** / "
                + "6.00× | ≥ 5× | met |", row.row());
    }

    @Test
    void theChildJvmRunsTheProbeUnderTheParallelCollectorOnThisClassPath() {
        List<String> command = SpeedSpreads.childCommand(ReportConfig.of(
                ReportConfig.Size.QUICK));
        assertTrue(command.get(0).endsWith("java"), command.get(0));
        assertTrue(command.contains("-XX:+UseParallelGC"), command.toString());
        int cp = command.indexOf("-cp");
        assertTrue(cp > 0, command.toString());
        assertEquals(System.getProperty("java.class.path"), command.get(cp + 1));
        assertEquals(LectureCollectorProbe.class.getName(), command.get(cp + 2));
        assertEquals("QUICK", command.get(command.size() - 1));
        // this JVM's heap flags come along, so the two rows differ only in the collector
        assertTrue(command.containsAll(SpeedSpreads.heapFlags()));
    }

    @Test
    void theProbesLineIsParsedAndAnythingElseIgnored() {
        CostMeter.Spread spread = SpeedSpreads.parseProbe(
                "lecture-over-objects 2.7000 3.0100 3.3000 Parallel");
        assertEquals(2.7, spread.min(), 0.0);
        assertEquals(3.01, spread.median(), 0.0);
        assertEquals(3.3, spread.max(), 0.0);
        assertNull(SpeedSpreads.parseProbe("WARNING: something else"));
        assertNull(SpeedSpreads.parseProbe("lecture-over-objects a b c G1"));
    }

    @Test
    void collectorsAreNamedFromTheirBeans() {
        assertEquals("G1", SpeedSpreads.collectorName(List.of("G1 Young Generation",
                "G1 Concurrent GC", "G1 Old Generation")));
        assertEquals("Parallel", SpeedSpreads.collectorName(List.of("PS Scavenge",
                "PS MarkSweep")));
        assertEquals("Serial", SpeedSpreads.collectorName(List.of("Copy",
                "MarkSweepCompact")));
        assertEquals("G1, default heap", SpeedSpreads.collectorLabel("G1", List.of()));
        assertEquals("Parallel, `-Xms1g -Xmx1g`", SpeedSpreads.collectorLabel("Parallel",
                List.of("-Xms1g", "-Xmx1g")));
    }

    @Test
    void theFullSweepComparesEveryTargetAndEveryPeerSize() {
        List<String> names = SpeedSpreads.comparisons(FULL);
        assertEquals(List.of(SpeedSpreads.OBJECTS_LINEAR, SpeedSpreads.OBJECTS_GRAVITY,
                SpeedSpreads.LECTURE, SpeedSpreads.LECTURE, SpeedSpreads.BATCH + 1000,
                SpeedSpreads.BATCH + 10000, SpeedSpreads.BATCH + 100000,
                SpeedSpreads.BATCH + 1000000), names);
        assertEquals(List.of(10_000, 100_000, 1_000_000), toList(SpeedSpreads.peerCounts(FULL)));
        assertEquals(List.of(10_000, 100_000),
                toList(SpeedSpreads.peerCounts(ReportConfig.of(ReportConfig.Size.QUICK))));
    }

    @Test
    void theTablesStateTheBoundAndFlagANoisyPeerRow() {
        StringBuilder md = new StringBuilder();
        CostMeter.Spread one = new CostMeter.Spread(1.0, 1.0, 1.0);
        SpeedSpreads.PeerRow steady = new SpeedSpreads.PeerRow(10_000, one, one, one,
                new CostMeter.Spread(8.0, 8.5, 9.0), new CostMeter.Spread(1.2, 1.3, 1.4),
                132.4, 36.0, 60.0);
        SpeedSpreads.PeerRow noisy = new SpeedSpreads.PeerRow(100_000, one, one, one,
                new CostMeter.Spread(5.0, 8.5, 9.0), new CostMeter.Spread(1.2, 1.3, 1.4),
                132.4, 36.0, 60.0);
        SpeedSpreads.appendTables(md, List.of(line(one, 2.0, true)), List.of(steady, noisy),
                7, FULL);
        String text = md.toString();
        assertTrue(text.contains("A row whose max ÷ min exceeds 1.5 says \"too noisy: no "
                + "verdict\""), text);
        assertTrue(text.contains("over 7 rounds"), text);
        assertTrue(text.contains("| 10000 | 1.00 / **1.00** / 1.00 | 1.00 / **1.00** / 1.00 "
                + "| 1.00 / **1.00** / 1.00 | 8.0 / **8.5** / 9.0× | 1.2 / **1.3** / 1.4× "
                + "| 132 + 36 | 60 | 24 | judged |"), text);
        assertTrue(text.contains("| 100000 |") && text.contains("| too noisy: no verdict |"),
                text);
        assertTrue(text.contains("What the batch form gains a jME user"), text);
    }

    @Test
    void aQuickSweepsPeerRowsGiveNoVerdict() {
        // The quick sweep's rounds are too short to warm the peer scenes (its fountain at 10^4
        // read 6.83 ns against 1.81 in a full run), so even a steady row is not judged.
        StringBuilder md = new StringBuilder();
        CostMeter.Spread one = new CostMeter.Spread(1.0, 1.0, 1.0);
        SpeedSpreads.PeerRow quick = new SpeedSpreads.PeerRow(10_000, one, one, one, one, one,
                132.4, 36.0, 60.0, false, true);
        SpeedSpreads.appendTables(md, List.of(line(one, 2.0, true)), List.of(quick), 7,
                ReportConfig.of(ReportConfig.Size.QUICK));
        String text = md.toString();
        assertTrue(text.contains("| 24 | not warmed: no verdict |"), text);
        assertTrue(!text.contains("| judged |"), text);
        assertTrue(text.contains("run the full report to judge them"), text);
    }

    @Test
    void thePeerRowsAreTimedAfterAFullCollectionAndSaySo() {
        // Issue 35: the emitter's 10^5 row read 9.0 or 25.4 ns per particle before or after
        // one full collection, so the rows are timed after one, and a row without one is
        // not judged.
        assertTrue(SpeedSpreads.fullCollection(), "System.gc() ran no full collection here");
        StringBuilder md = new StringBuilder();
        CostMeter.Spread one = new CostMeter.Spread(1.0, 1.0, 1.0);
        SpeedSpreads.PeerRow uncollected = new SpeedSpreads.PeerRow(10_000, one, one, one, one,
                one, 132.4, 36.0, 60.0, true, false);
        SpeedSpreads.appendTables(md, List.of(line(one, 2.0, true)), List.of(uncollected), 7,
                FULL);
        String text = md.toString();
        assertTrue(text.contains("then one full collection runs (`System.gc()`) before the "
                + "rounds start"), text);
        assertTrue(text.contains("| 24 | no full GC before timing: no verdict |"), text);
        assertTrue(!text.contains("| judged |"), text);
    }

    private static SpeedSpreads.Line line(CostMeter.Spread spread, double target,
            boolean atMost) {
        return new SpeedSpreads.Line("x", "G1, default heap", spread, target, atMost);
    }

    private static List<Integer> toList(int[] values) {
        return java.util.Arrays.stream(values).boxed().collect(java.util.stream.Collectors
                .toList());
    }
}

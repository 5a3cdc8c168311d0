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
    /** A tight A/A pass: identical work read 0.98 to 1.02 in these rounds. */
    private static final CostMeter.Spread TIGHT_AA = new CostMeter.Spread(0.98, 1.0, 1.02);
    /**
     * Recorded, not timed here: {@code step(Particle, h)} (linear drag) against a second copy
     * of itself, a full report's budget (7 rounds of 60 ms, thread CPU time), JDK 17.0.15,
     * AMD EPYC host, load average 14.8 ...
     */
    private static final CostMeter.Spread RECORDED_AA =
            new CostMeter.Spread(0.9520, 0.9786, 1.0141);
    /** ... and, in the same rounds, a third copy flying twice per call: twice the work. */
    private static final CostMeter.Spread RECORDED_TWICE =
            new CostMeter.Spread(1.9248, 1.9802, 2.0110);

    @Test
    void aRowIsJudgedByItsMedianUnlessItsRoundsSpreadBeyondTheBound() {
        CostMeter.Spread steady = new CostMeter.Spread(1.5, 1.6, 1.7);
        assertEquals("met", line(steady, 2.0, true).verdict());
        assertEquals("**missed**", line(steady, 1.5, true).verdict());
        assertEquals("met", line(steady, 1.55, false).verdict(), "at least 1.55: met at 1.6");
        // max ÷ min = 3.1 / 2.0 > 1.5: no verdict, whatever the median says
        CostMeter.Spread noisy = new CostMeter.Spread(2.0, 2.1, 3.1);
        assertEquals(SpeedSpreads.TOO_NOISY, line(noisy, 5.0, true).verdict());
        assertEquals(SpeedSpreads.TOO_NOISY, line(noisy, 1.0, true).verdict());
        SpeedSpreads.Line failed = new SpeedSpreads.Line("x", "Parallel", 5.0, false,
                "the child JVM exited with 1 and no ratio");
        assertEquals("not measured: the child JVM exited with 1 and no ratio",
                failed.verdict());
    }

    @Test
    void aRowShowsItsSpreadItsAaPassAndTarget() {
        SpeedSpreads.Line row = new SpeedSpreads.Line(SpeedSpreads.LECTURE,
                "G1, default heap", new CostMeter.Spread(5.012, 5.7, 6.0), TIGHT_AA, 5.0,
                false, true);
        assertEquals("| " + SpeedSpreads.LECTURE + " | G1, default heap | 5.01 / **5.70** / "
                + "6.00× | 0.980 / **1.000** / 1.020× | ≥ 5× | met |", row.row());
    }

    @Test
    void anAaPairReadAsAComparisonGivesNoVerdict() {
        // The recorded A/A pass used as the row's own ratio: its median lies inside its band,
        // whatever the target, so neither "met" (≤ 2×) nor "missed" (≥ 5×) is said.
        assertEquals(SpeedSpreads.INSIDE_AA, new SpeedSpreads.Line("x", "G1", RECORDED_AA,
                RECORDED_AA, 2.0, true, true).verdict());
        assertEquals(SpeedSpreads.INSIDE_AA, new SpeedSpreads.Line("x", "G1", RECORDED_AA,
                RECORDED_AA, 5.0, false, true).verdict());
        // 1/0.952 = 1.050: identical work has no direction, so 1.04 is inside the band too
        assertEquals(SpeedSpreads.INSIDE_AA, new SpeedSpreads.Line("x", "G1",
                new CostMeter.Spread(1.03, 1.04, 1.05), RECORDED_AA, 2.0, true, true)
                .verdict());
    }

    @Test
    void aPathDoingTwiceTheWorkIsJudgedUnlessTheTargetIsWithinTheBand() {
        // Recorded: twice the work read 1.98× (1.92 to 2.01) beside an A/A band of 0.952 to
        // 1.050 (1/0.952): outside it, so the row is judged against a target away from it ...
        assertEquals("**missed**", new SpeedSpreads.Line("x", "G1", RECORDED_TWICE,
                RECORDED_AA, 1.5, true, true).verdict());
        assertEquals("met", new SpeedSpreads.Line("x", "G1", RECORDED_TWICE, RECORDED_AA,
                1.5, false, true).verdict());
        // ... but not against 2×: 1.98 / 2 = 0.99 lies inside the band, so a run as noisy as
        // its own A/A pass could read either side of the target
        assertEquals(SpeedSpreads.NEAR_TARGET, new SpeedSpreads.Line("x", "G1",
                RECORDED_TWICE, RECORDED_AA, 2.0, true, true).verdict());
    }

    @Test
    void aRowOfASweepTooShortToWarmGivesNoVerdict() {
        assertEquals(SpeedSpreads.NOT_WARMED, new SpeedSpreads.Line("x", "G1",
                RECORDED_TWICE, RECORDED_AA, 1.5, true, false).verdict());
        assertTrue(SpeedSpreads.isWarmed(FULL));
        assertTrue(!SpeedSpreads.isWarmed(ReportConfig.of(ReportConfig.Size.QUICK)));
        assertTrue(!SpeedSpreads.isWarmed(ReportConfig.of(ReportConfig.Size.TINY)));
        StringBuilder md = new StringBuilder();
        SpeedSpreads.appendTables(md, List.of(new SpeedSpreads.Line("x", "G1",
                RECORDED_TWICE, RECORDED_AA, 1.5, true, false)), List.of(), 5,
                ReportConfig.of(ReportConfig.Size.QUICK));
        String text = md.toString();
        assertTrue(text.contains("so every row says \"not warmed: no verdict\""), text);
        assertTrue(text.contains("| not warmed: no verdict |"), text);
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
    void theProbesLinesAreParsedAndAnythingElseIgnored() {
        CostMeter.Spread spread = SpeedSpreads.parseProbe(
                "lecture-over-objects 2.7000 3.0100 3.3000 Parallel", SpeedSpreads.PROBE_PREFIX);
        assertEquals(2.7, spread.min(), 0.0);
        assertEquals(3.01, spread.median(), 0.0);
        assertEquals(3.3, spread.max(), 0.0);
        CostMeter.Spread aa = SpeedSpreads.parseProbe("objects-over-objects 0.9700 1.0000 "
                + "1.0400", SpeedSpreads.PROBE_AA_PREFIX);
        assertEquals(0.97, aa.min(), 0.0);
        assertEquals(1.04, aa.max(), 0.0);
        assertNull(SpeedSpreads.parseProbe("objects-over-objects 0.97 1.0 1.04",
                SpeedSpreads.PROBE_PREFIX));
        assertNull(SpeedSpreads.parseProbe("WARNING: something else",
                SpeedSpreads.PROBE_PREFIX));
        assertNull(SpeedSpreads.parseProbe("lecture-over-objects a b c G1",
                SpeedSpreads.PROBE_PREFIX));
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
                TIGHT_AA, 132.4, 36.0, 60.0, true, true);
        SpeedSpreads.PeerRow noisy = new SpeedSpreads.PeerRow(100_000, one, one, one,
                new CostMeter.Spread(5.0, 8.5, 9.0), new CostMeter.Spread(1.2, 1.3, 1.4),
                TIGHT_AA, 132.4, 36.0, 60.0, true, true);
        // the emitter no slower than the fountain, within the A/A band of stepPacked
        SpeedSpreads.PeerRow alike = new SpeedSpreads.PeerRow(1_000_000, one, one, one,
                new CostMeter.Spread(8.0, 8.5, 9.0), new CostMeter.Spread(0.99, 1.01, 1.03),
                TIGHT_AA, 132.4, 36.0, 60.0, true, true);
        SpeedSpreads.appendTables(md, List.of(line(one, 2.0, true)),
                List.of(steady, noisy, alike), 7, FULL);
        String text = md.toString();
        assertTrue(text.contains("A row whose max ÷ min exceeds 1.5 says \"too noisy: no "
                + "verdict\""), text);
        assertTrue(text.contains("over 7 rounds"), text);
        assertTrue(text.contains("| 10000 | 1.00 / **1.00** / 1.00 | 1.00 / **1.00** / 1.00 "
                + "| 1.00 / **1.00** / 1.00 | 8.0 / **8.5** / 9.0× | 1.2 / **1.3** / 1.4× "
                + "| 0.980 / **1.000** / 1.020× | 132 + 36 | 60 | 24 | judged |"), text);
        assertTrue(text.contains("| 1000000 |") && text.contains("| 24 | inside the A/A band: "
                + "no verdict |"), text);
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
                TIGHT_AA, 132.4, 36.0, 60.0, false, true);
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
                one, TIGHT_AA, 132.4, 36.0, 60.0, true, false);
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
        return new SpeedSpreads.Line("x", "G1, default heap", spread, TIGHT_AA, target, atMost,
                true);
    }

    private static List<Integer> toList(int[] values) {
        return java.util.Arrays.stream(values).boxed().collect(java.util.stream.Collectors
                .toList());
    }
}

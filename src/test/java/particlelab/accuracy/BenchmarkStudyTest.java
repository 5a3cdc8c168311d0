package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.reference.CostMeter;
import particlelab.reference.Scheme;


/**
 * The benchmark rows the report promises: the old ones and one per force mix, path and N,
 * named exactly as the issue spells them. The quick sweep is run for real (on the tiny sweep's
 * short timing loop, so it takes seconds) and its {@code benchmarks.csv} read back. No timing
 * is checked.
 */
class BenchmarkStudyTest {

    /** The names, spelled out here rather than taken from the code under test. */
    private static final String[] MIXES = {"gravity", "linear", "quadratic", "thrust-linear"};
    private static final String[] SINGLE_PATHS = {"lecture-style", "shared-objects",
        "primitive-loop"};
    private static final String[] BULK_PATHS = {"lecture-style", "shared-objects",
        "shared-batch", "primitive-loop"};
    /** The quick sweep's particle counts. */
    private static final int[] QUICK_COUNTS = {1_000, 100_000};
    /** The full sweep's particle counts: every N the issue names. */
    private static final int[] FULL_COUNTS = {1_000, 10_000, 100_000, 1_000_000};

    @Test
    void quickSweepWritesEveryPromisedRowToTheCsv(@TempDir Path temp) throws IOException {
        ReportConfig quick = ReportConfig.of(ReportConfig.Size.QUICK);
        CostMeter shortMeter = new CostMeter(CostMeter.Budget.TINY);
        ProgressBar progress = new ProgressBar(new PrintStream(new ByteArrayOutputStream(),
                true), BenchmarkStudy.units(quick), false);
        BenchmarkStudy.run(quick, shortMeter, progress).write(temp.resolve("benchmarks.csv"));
        BenchmarkTable written = BenchmarkTable.read(temp.resolve("benchmarks.csv"));

        List<String> expected = promised(QUICK_COUNTS);
        List<String> names = new ArrayList<>();
        for (BenchmarkTable.Row row : written.rows()) {
            names.add(row.name());
            assertTrue(row.nanosPerParticleStep() > 0.0, row.name() + " has no time");
        }
        assertEquals(expected, names);
    }

    @Test
    void fullSweepPromisesEveryMixPathAndParticleCount() {
        assertEquals(promised(FULL_COUNTS),
                BenchmarkStudy.rowNames(ReportConfig.of(ReportConfig.Size.FULL)));
    }

    /** The old rows first (steppers, one-particle references, bulk kinds), then the mixes. */
    private static List<String> promised(int[] counts) {
        List<String> names = new ArrayList<>();
        for (Scheme scheme : Scheme.values()) {
            names.add(scheme.id());
        }
        names.add("lecture-style");
        names.add("primitive-loop");
        for (int count : counts) {
            for (String path : BULK_PATHS) {
                names.add("bulk/" + path + "/" + count);
            }
        }
        for (String mix : MIXES) {
            for (String path : SINGLE_PATHS) {
                names.add("single/" + mix + "/" + path);
            }
            for (int count : counts) {
                for (String path : BULK_PATHS) {
                    names.add("bulk/" + mix + "/" + path + "/" + count);
                    // the test JVM has the Vector API (build.gradle): gravity and linear drag
                    // add the batch's second form after the first
                    if (path.equals("shared-batch")
                            && (mix.equals("gravity") || mix.equals("linear"))) {
                        names.add("bulk/" + mix + "/shared-batch-vector/" + count);
                    }
                }
            }
        }
        return names;
    }
}

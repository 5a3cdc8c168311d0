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
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;


/** The rotation section's measurements, files and prose, written from a tiny-timed study. */
class RotationSectionTest {

    private static final String EARLIER = "# Speed against error\n\nearlier sections\n\n";
    /** Float's unit round-off, 2⁻²³. */
    private static final double EPS = Math.ulp(1f);

    @TempDir
    static Path shared;
    private static Path folder;
    private static RotationStudy study;

    @BeforeAll
    static void writeSection() throws IOException {
        ReportConfig tiny = ReportConfig.of(ReportConfig.Size.TINY);
        study = RotationStudy.run(new CostMeter(tiny.budget()));
        folder = shared.resolve("report");
        Files.createDirectories(folder);
        Files.write(folder.resolve("index.md"), EARLIER.getBytes(StandardCharsets.UTF_8));
        RotationSection.write(study, folder);
    }

    @Test
    void csvHeadersAreExact() throws IOException {
        assertEquals("method,h_s,steps,angle_error_rad,orthogonality_error,ns_per_step",
                lines("rotation_error.csv").get(0));
        assertEquals("method,h_s,steps,energy_drift,angular_momentum_drift",
                lines("racket_drift.csv").get(0));
    }

    @Test
    void sweepsTheFullStepRangeForEveryMethod() {
        assertEquals(1.0 / 15.0, study.steps[0], 1e-15);
        assertEquals(1.0 / 1920.0, study.steps[study.steps.length - 1], 1e-15);
        assertEquals(Orientation.values().length * study.steps.length, study.errors.size());
        assertEquals(Angular.values().length * study.steps.length, study.drifts.size());
        for (double nanos : study.nanosPerStep) {
            assertTrue(nanos > 0.0 && Double.isFinite(nanos), "cost " + nanos);
        }
    }

    @Test
    void fittedOrdersMatchTheory() {
        // The fit runs over h ≤ 1/120 s (|ω|h ≤ 0.053), where the next term of each error is
        // a factor of about |ω|h (or, for plain Euler's ‖RᵀR − I‖ = √2·((1+(|ω|h)²)ⁿ − 1),
        // about |ω|²h·t/2 ≤ 0.17) below the leading one; that bends the log-log slope by
        // well under 0.15 across the fitted range. Float round-off is excluded by the floor.
        assertEquals(2.0, study.order(Orientation.EULER, true), 0.15);
        assertEquals(1.0, study.order(Orientation.EULER, false), 0.15);
        assertEquals(1.0, study.order(Orientation.GRAM_SCHMIDT, true), 0.15);
        assertEquals(2.0, study.order(Orientation.POLAR, true), 0.15);
        assertEquals(2.0, study.order(Orientation.QUATERNION, true), 0.15);
        // every cure keeps R a rotation, and the exact step keeps the exact angle, to round-off
        assertTrue(Double.isNaN(study.order(Orientation.EXACT, true)));
        for (Orientation cured : new Orientation[] {Orientation.GRAM_SCHMIDT,
                Orientation.POLAR, Orientation.QUATERNION, Orientation.EXACT}) {
            assertTrue(Double.isNaN(study.order(cured, false)), cured.toString());
        }
    }

    /**
     * Issue 17: the angle error is a distance that wraps at π, so it ranks methods wrongly
     * once one lags by more than that. Over this sweep (|ω|h ≤ 2π/15 = 0.42, 1 s) nothing
     * comes close: polar lags at most 15·(0.42 − atan 0.42) = 0.33 rad. So the section may rank
     * by the angle error, which for the methods that turn about ω (plain Euler's nearest
     * rotation, polar, quaternion, exact) is the unwrapped lag itself, to float round-off
     * (10·n·EPS, rigid.SpinAngleTest). Gram–Schmidt's axis tilts off ω, so its distance
     * includes the tilt: at least its lag. Every error stays below π/2, far from the wrap.
     */
    @Test
    void angleErrorIsTheUnwrappedLagOverTheWholeSweep() {
        for (RotationStudy.OrientationError e : study.errors) {
            String what = e.method + " h = " + e.stepSeconds;
            assertTrue(e.angleError < Math.PI / 2.0, what + ": " + e.angleError);
            if (e.method == Orientation.GRAM_SCHMIDT) {
                assertTrue(e.angleError >= Math.abs(e.angleLag) - 10.0 * e.steps * EPS, what);
            } else {
                assertEquals(e.angleError, Math.abs(e.angleLag), 10.0 * e.steps * EPS, what);
            }
        }
    }

    @Test
    void plainEulerOrthogonalityErrorIsTheClosedForm() {
        // R_n = (I + h[ω]×)ⁿ: RᵀR − I has (1 + (|ω|h)²)ⁿ − 1 twice on the plane across ω.
        // Each float step rounds R's entries (relative EPS/2), so after n steps the error
        // carries up to about n·EPS of the stretch (≤ 11) in absolute terms.
        double omega = RotationStudy.OMEGA.length();
        for (RotationStudy.OrientationError e : study.errors(Orientation.EULER)) {
            double x = omega * (float) e.stepSeconds;
            double expected = Math.sqrt(2.0) * (Math.pow(1.0 + x * x, e.steps) - 1.0);
            assertEquals(expected, e.orthogonalityError, 20.0 * e.steps * EPS * (1 + expected),
                    "h = " + e.stepSeconds);
        }
    }

    @Test
    void midpointDriftIsRoundOffAndExplicitGainsEnergy() {
        for (int i = 0; i < study.steps.length; ++i) {
            RotationStudy.Drift explicit = study.drifts(Angular.EXPLICIT).get(i);
            RotationStudy.Drift midpoint = study.drifts(Angular.IMPLICIT_MIDPOINT).get(i);
            // Midpoint conserves E and |L| exactly; what is left is the float rounding of ω
            // (relative EPS/2 per component, so about EPS in E) once per step, which adds up
            // like a random walk: sqrt(n)·EPS, with a margin of 4.
            double bound = 4.0 * Math.sqrt(midpoint.steps) * EPS;
            assertTrue(Math.abs(midpoint.energyDrift) < bound, midpoint.energyDrift + " vs "
                    + bound);
            assertTrue(Math.abs(midpoint.momentumDrift) < bound, midpoint.momentumDrift
                    + " vs " + bound);
            // Explicit Euler adds h²·½·ω̇ᵀIω̇ > 0 to E every step: far above that bound.
            assertTrue(explicit.energyDrift > bound, "explicit " + explicit.energyDrift);
            assertTrue(explicit.momentumDrift > bound, "explicit " + explicit.momentumDrift);
        }
    }

    @Test
    void writesEveryFileAndAppendsToIndex() throws IOException {
        ReportFiles.assertWritten(folder, RotationSection.FILES);
        String index = read("index.md");
        assertTrue(index.startsWith(EARLIER), "the earlier sections were overwritten");
        assertTrue(index.contains(RotationSection.HEADING + "\n"));
        assertTrue(index.contains("](" + RotationSection.ERROR_PLOT + ")"));
        assertTrue(index.contains("`rotation_error.csv` (`" + RotationSection.ERROR_HEADER
                + "`)"));
        assertTrue(index.contains("`racket_drift.csv` (`" + RotationSection.DRIFT_HEADER
                + "`)"));
    }

    @Test
    void csvRowsParseBackToTheStudy() throws IOException {
        List<String> rows = lines("rotation_error.csv");
        assertEquals(study.errors.size() + 1, rows.size());
        for (int i = 0; i < study.errors.size(); ++i) {
            RotationStudy.OrientationError e = study.errors.get(i);
            String[] cells = rows.get(i + 1).split(",");
            assertEquals(RotationSection.name(e.method), cells[0]);
            assertEquals(e.stepSeconds, Double.parseDouble(cells[1]));
            assertEquals(e.steps, Integer.parseInt(cells[2]));
            assertEquals(e.angleError, Double.parseDouble(cells[3]));
            assertEquals(e.orthogonalityError, Double.parseDouble(cells[4]));
            assertEquals(study.nanosPerStep[e.method.ordinal()], Double.parseDouble(cells[5]));
        }
        rows = lines("racket_drift.csv");
        assertEquals(study.drifts.size() + 1, rows.size());
        for (int i = 0; i < study.drifts.size(); ++i) {
            RotationStudy.Drift d = study.drifts.get(i);
            String[] cells = rows.get(i + 1).split(",");
            assertEquals(RotationSection.name(d.method), cells[0]);
            assertEquals(d.steps, Integer.parseInt(cells[2]));
            assertEquals(d.energyDrift, Double.parseDouble(cells[3]));
            assertEquals(d.momentumDrift, Double.parseDouble(cells[4]));
        }
    }

    @Test
    void markdownTablesParseBackToTheStudy() throws IOException {
        String index = read("index.md");
        String section = index.substring(index.indexOf(RotationSection.HEADING));
        // the method table: one row per orientation method
        double exactNanos = study.nanosPerStep[Orientation.EXACT.ordinal()];
        for (Orientation method : Orientation.values()) {
            String[] cells = row(section, "| " + RotationSection.name(method) + " |");
            RotationStudy.OrientationError last =
                    study.errors(method).get(study.steps.length - 1);
            double nanos = study.nanosPerStep[method.ordinal()];
            // printed with 1 decimal, 2 decimals, 3 significant digits, 2 decimals
            assertEquals(nanos, Double.parseDouble(cells[1]), 0.05 + 1e-9);
            assertEquals(nanos / exactNanos, Double.parseDouble(cells[2]), 0.005 + 1e-9);
            assertEquals(last.angleError, Double.parseDouble(cells[3]),
                    0.005 * last.angleError);
            assertOrder(study.order(method, true), cells[4]);
            assertEquals(last.orthogonalityError, Double.parseDouble(cells[5]),
                    0.005 * last.orthogonalityError);
            assertOrder(study.order(method, false), cells[6]);
        }
        // the racket table: one row per step size
        List<RotationStudy.Drift> explicit = study.drifts(Angular.EXPLICIT);
        List<RotationStudy.Drift> midpoint = study.drifts(Angular.IMPLICIT_MIDPOINT);
        for (int i = 0; i < explicit.size(); ++i) {
            String[] cells = row(section,
                    "| 1/" + Math.round(1.0 / explicit.get(i).stepSeconds) + " |");
            double[] expected = {explicit.get(i).energyDrift, explicit.get(i).momentumDrift,
                midpoint.get(i).energyDrift, midpoint.get(i).momentumDrift};
            for (int c = 0; c < expected.length; ++c) {
                assertEquals(expected[c], Double.parseDouble(cells[c + 1]),
                        Math.abs(0.005 * expected[c]), "row " + i + " column " + c);
            }
        }
        assertTrue(section.contains(RotationSection.orientationSummary(study)));
        assertTrue(section.contains(RotationSection.racketSummary(study)));
    }

    @Test
    void theSectionAppearsOnceInATinyReport(@TempDir Path temp) throws IOException {
        Path out = temp.resolve("report");
        ByteArrayOutputStream progress = new ByteArrayOutputStream();
        new SpeedVsErrorReport(ReportConfig.of(ReportConfig.Size.TINY), out, null)
                .write(new PrintStream(progress, true, "UTF-8"), false);
        String index = new String(Files.readAllBytes(out.resolve("index.md")),
                StandardCharsets.UTF_8);
        int first = index.indexOf(RotationSection.HEADING);
        assertTrue(first >= 0, "no rotation section");
        assertEquals(first, index.lastIndexOf(RotationSection.HEADING), "section twice");
        assertTrue(first > index.indexOf(CollisionSection.HEADING), "after the collisions");
        for (String name : RotationSection.FILES) {
            assertTrue(SpeedVsErrorReport.FILES.contains(name), name + " not promised");
            assertTrue(Files.isRegularFile(out.resolve(name)), "missing " + name);
        }
    }

    private static void assertOrder(double order, String cell) {
        if (Double.isNaN(order)) {
            assertEquals("round-off", cell);
        } else {
            assertEquals(order, Double.parseDouble(cell), 0.005 + 1e-9);
        }
    }

    /** The cells of the table row that starts with {@code start}, trimmed. */
    private static String[] row(String markdown, String start) {
        int at = markdown.indexOf("\n" + start);
        assertTrue(at >= 0, "no row " + start);
        String line = markdown.substring(at + 1, markdown.indexOf('\n', at + 1));
        String[] raw = line.substring(1, line.length() - 1).split("\\|");
        String[] cells = new String[raw.length];
        for (int i = 0; i < raw.length; ++i) {
            cells[i] = raw[i].trim();
        }
        return cells;
    }

    private static String read(String name) throws IOException {
        return new String(Files.readAllBytes(folder.resolve(name)), StandardCharsets.UTF_8);
    }

    private static List<String> lines(String name) throws IOException {
        return new ArrayList<>(Files.readAllLines(folder.resolve(name), StandardCharsets.UTF_8));
    }
}

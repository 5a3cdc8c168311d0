package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.demo.DemoParameters;
import particlelab.demo.ParametersTable;
import particlelab.demo.TrajectoryRecord;
import particlelab.lecture.DragDemo;
import particlelab.lecture.FountainDemo;
import particlelab.lecture.IterativeAimingDemo;
import particlelab.lecture.RotationDemo;

/**
 * {@code particle-lab demo NAME --frames N --fixed-tpf H --export DIR}: each particle's CSV is
 * what {@code particle-lab trajectory} prints for the same launch, forces and h, byte for
 * byte, and a folder that cannot be written is refused in one line.
 */
class DemoExportTest {

    /** The demos' fixed step, 1/60 s, as --fixed-tpf and --tpf write it. */
    private static final String FRAME = "0.016666668";
    private static final String STEP = "1/60";
    /** 200 frames of 1/60 s: every ball of pull and drag has landed (2.04 s at most). */
    private static final String FRAMES = "200";

    @Test
    void theHeaderIsTheTrajectoryCommands() {
        assertEquals(TrajectoryCommand.HEADER, TrajectoryRecord.HEADER);
    }

    @Test
    void pullsCsvIsTheTrajectoryCommandsOutputBitForBit(@TempDir Path folder)
            throws IOException {
        CommandRun demo = CommandRun.of("demo", "pull", "--frames", FRAMES, "--fixed-tpf",
                FRAME, "--export", folder.toString());
        assertEquals(0, demo.code, demo.toString());
        Path csv = folder.resolve("ball.csv");
        // the ball's table and the energy ledger's (issue 32), a row for each of its rows,
        // then the settings (issue 33)
        assertEquals(List.of("csv " + csv + ": 123 rows",
                "csv " + folder.resolve("energy.csv") + ": 123 rows",
                parametersLine(folder, "pull")), demo.outLines());
        assertEquals("", demo.err);
        // The pull demo's launch: P0 = 0, V0 = (10, 10, 0) m/s, m = 1 kg, gravity only; its
        // last row is the step that came down through y = 0.
        CommandRun trajectory = CommandRun.of("trajectory", "--v0", "10,10,0", "--tpf", STEP,
                "--until-ground");
        assertEquals(0, trajectory.code, trajectory.toString());
        assertEquals(trajectory.out, read(csv));
    }

    @Test
    void dragsThreeCsvsAreTheTrajectoryCommandsOutputsBitForBit(@TempDir Path folder)
            throws IOException {
        CommandRun demo = CommandRun.of("demo", "drag", "--frames", FRAMES, "--fixed-tpf",
                FRAME, "--export", folder.toString());
        assertDragFilesMatchTrajectory(demo, folder, STEP, Float.toString(DragDemo.LINEAR_B),
                Float.toString(DragDemo.QUADRATIC_C));
    }

    @Test
    void dragsCsvsWithSetValuesAreTheTrajectoryCommandsWithTheSameOptions(
            @TempDir Path folder) throws IOException {
        // b, c and h from the command line: each ball's file is the trajectory command's
        // output with those coefficients and that step. At h = 1/30 s two frames of 1/60 s
        // make one step; 200 frames (3.3 s) outlast the longest flight (2.04 s).
        CommandRun demo = CommandRun.of("demo", "drag", "--set", "b=0.3", "--set", "c=0.02",
                "--set", "h=1/30", "--frames", FRAMES, "--fixed-tpf", FRAME, "--export",
                folder.toString());
        assertDragFilesMatchTrajectory(demo, folder, "1/30", "0.3", "0.02");
    }

    /** The drag demo's three files against trajectory with the same launch, force and h. */
    private static void assertDragFilesMatchTrajectory(CommandRun demo, Path folder,
            String step, String linearB, String quadraticC) throws IOException {
        assertEquals(0, demo.code, demo.toString());
        // three balls' tables, then the energy ledger's (issue 32), then the settings (33)
        assertEquals(5, demo.outLines().size(), demo.out);
        assertTrue(demo.outLines().get(3).startsWith("csv " + folder.resolve("energy.csv")),
                demo.out);
        assertEquals(parametersLine(folder, "drag"), demo.outLines().get(4));
        String[][] files = {
            {"gravity-only.csv"},
            {"linear-drag-f-b-v.csv", "--linear-drag", linearB},
            {"quadratic-drag-f-c-v-v.csv", "--quadratic-drag", quadraticC},
        };
        for (String[] file : files) {
            // The drag demo's launch, as in pull, and the one drag force of each ball.
            List<String> args = new ArrayList<>(List.of("trajectory", "--v0", "10,10,0",
                    "--tpf", step, "--until-ground"));
            args.addAll(Arrays.asList(file).subList(1, file.length));
            CommandRun trajectory = CommandRun.of(args.toArray(new String[0]));
            assertEquals(0, trajectory.code, trajectory.toString());
            assertEquals(trajectory.out, read(folder.resolve(file[0])), file[0]);
        }
    }

    /**
     * Issue 17, part 7: rotation, fountain and iterate have no free particle and wrote
     * nothing, silently. Now each writes its own table, with a header, one row per step (per
     * shot for iterate); a demo with nothing to write says so.
     */
    @Test
    void demosWithoutFreeParticlesWriteTheirOwnTables(@TempDir Path temp) throws IOException {
        String[][] cases = {
            {"rotation", RotationDemo.BOX_HEADER, "rotation-plain-euler.csv",
                "rotation-polar.csv", "rotation-quaternion.csv", "rotation-exact.csv"},
            {"fountain", FountainDemo.COUNTS_HEADER, "fountain-counts.csv"},
            {"iterate", IterativeAimingDemo.SHOTS_HEADER, "shots.csv"},
        };
        for (String[] c : cases) {
            Path folder = temp.resolve(c[0]);
            CommandRun run = CommandRun.of("demo", c[0], "--frames", "30", "--fixed-tpf",
                    FRAME, "--export", folder.toString());
            assertEquals(0, run.code, run.toString());
            // each table named, and the energy ledger's where the demo's world has bodies
            // (rotation's plates, iterate's shots; the fountain's points are no bodies),
            // then the settings (issue 33)
            boolean energy = !c[0].equals("fountain");
            assertEquals(c.length - 2 + (energy ? 1 : 0) + 1, run.outLines().size(),
                    run.toString());
            assertEquals(parametersLine(folder, c[0]),
                    run.outLines().get(run.outLines().size() - 1));
            assertEquals(energy, Files.exists(folder.resolve("energy.csv")), run.toString());
            for (int i = 2; i < c.length; ++i) {
                List<String> lines = Files.readAllLines(folder.resolve(c[i]));
                assertEquals(c[1], lines.get(0), c[i]);
                int columns = c[1].split(",").length;
                assertTrue(lines.size() > 1, c[i] + " has no row");
                for (String line : lines.subList(1, lines.size())) {
                    assertEquals(columns, line.split(",").length, c[i] + ": " + line);
                }
                if (!c[0].equals("iterate")) {
                    // one row per step: 30 frames of one fixed step h = 1/60 s each
                    assertEquals(31, lines.size(), c[i]);
                }
            }
        }
        // The racket records no table of its own: its plates' energy ledger (issue 32) is
        // all it writes, one row per step and the start's, with its settings (issue 33).
        CommandRun racket = CommandRun.of("demo", "racket", "--frames", "3", "--export",
                temp.resolve("racket").toString());
        assertEquals(0, racket.code, racket.toString());
        assertEquals(2, racket.outLines().size(), racket.toString());
        assertEquals(parametersLine(temp.resolve("racket"), "racket"),
                racket.outLines().get(1));
        assertTrue(racket.outLines().get(0).startsWith("csv "
                + temp.resolve("racket").resolve("energy.csv")), racket.toString());
        // Before its first step (h = 1/5 s, one frame of 1/60 s) it has nothing: it says so,
        // and writes no parameters.csv either (settings of no table).
        CommandRun early = CommandRun.of("demo", "racket", "--set", "h=1/5", "--frames", "1",
                "--fixed-tpf", FRAME, "--export", temp.resolve("early").toString());
        assertEquals(0, early.code, early.toString());
        assertEquals(List.of("csv: none; " + ExportRun.NOTHING_TO_EXPORT), early.outLines());
        assertFalse(Files.exists(temp.resolve("early").resolve("parameters.csv")));
    }

    /**
     * Issue 33: an export carries the settings that made it, parameters.csv (name, value,
     * unit), one row per parameter in the panel's order; each value, given back to --set,
     * is the same float (a choice by its name), so the table re-makes the run.
     */
    @Test
    void parametersCsvHoldsEachSettingAsSetReadsItBack(@TempDir Path folder)
            throws IOException {
        CommandRun demo = CommandRun.of("demo", "drag", "--set", "b=0.3", "--set", "h=1/30",
                "--set", "angle=33.3", "--set", "lane=rk4", "--frames", "20", "--fixed-tpf",
                FRAME, "--export", folder.toString());
        assertEquals(0, demo.code, demo.toString());
        List<String> lines = Files.readAllLines(folder.resolve("parameters.csv"),
                StandardCharsets.UTF_8);
        assertEquals(ParametersTable.HEADER, lines.get(0));
        DemoParameters declared = new DragDemo().getParameters();
        assertEquals(declared.size() + 1, lines.size(), lines.toString());
        assertTrue(lines.contains("b,0.3,N s/m"), lines.toString());
        // 1/30 as a float, written so that it reads back as that float
        assertTrue(lines.contains("h," + (float) (1.0 / 30.0) + ",s"), lines.toString());
        assertTrue(lines.contains("angle,33.3,deg"), lines.toString());
        assertTrue(lines.contains("lane,rk4,"), lines.toString());
        // Every row back through --set: a fresh demo takes each value, to the bit.
        DragDemo fresh = new DragDemo();
        List<String> settings = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] fields = line.split(",", -1);
            assertEquals(3, fields.length, line);
            assertEquals(declared.get(settings.size()).getName(), fields[0]);
            assertEquals(declared.get(settings.size()).getUnit(), fields[2]);
            settings.add(fields[0] + "=" + fields[1]);
        }
        DemoCommand.applySettings(fresh, settings);
        DemoParameters expected = new DragDemo().getParameters();
        for (int i = 0; i < expected.size(); ++i) {
            float wanted = expected.getValue(i);
            String name = expected.get(i).getName();
            if (name.equals("b")) {
                wanted = 0.3f;
            } else if (name.equals("h")) {
                wanted = (float) (1.0 / 30.0);
            } else if (name.equals("angle")) {
                wanted = 33.3f;
            } else if (name.equals("lane")) {
                wanted = expected.get(i).indexOfChoice("rk4");
            }
            assertEquals(Float.floatToRawIntBits(wanted),
                    Float.floatToRawIntBits(fresh.getParameters().getValue(i)), name);
        }
    }

    /** The listing's line for an export's parameters.csv: one row per declared parameter. */
    private static String parametersLine(Path folder, String demo) {
        int rows = DemoCatalog.entries().get(DemoCatalog.indexOf(demo)).create()
                .getParameters().size();
        return "csv " + folder.resolve("parameters.csv") + ": " + rows
                + (rows == 1 ? " row" : " rows");
    }

    @Test
    void aFolderThatCannotBeWrittenIsRefusedInOneLine(@TempDir Path folder) throws IOException {
        Path file = Files.writeString(folder.resolve("taken"), "x");
        CommandRun onFile = CommandRun.of("demo", "pull", "--frames", "3", "--export",
                file.toString());
        assertEquals(2, onFile.code, onFile.toString());
        assertEquals(1, onFile.errLines().size(), onFile.err);
        assertTrue(onFile.err.startsWith("particle-lab demo: --export: "), onFile.err);
        CommandRun underFile = CommandRun.of("demo", "pull", "--frames", "3", "--export",
                file.resolve("sub").toString());
        assertEquals(2, underFile.code, underFile.toString());
        assertEquals(1, underFile.errLines().size(), underFile.err);
        CommandRun noFrames = CommandRun.of("demo", "pull", "--export", folder.toString());
        assertEquals(2, noFrames.code, noFrames.toString());
        assertEquals(List.of("particle-lab demo: --export: needs --frames N, so the app knows"
                + " when to write the files"), noFrames.errLines());
    }

    @Test
    void aUiScaleOutOfRangeIsRefusedWithTheRange() {
        CommandRun run = CommandRun.of("demo", "pull", "--ui-scale", "5");
        assertEquals(2, run.code, run.toString());
        assertEquals(List.of("particle-lab demo: --ui-scale: must be from 0.5 to 2.0 (a factor"
                + " on the HUD's text size), but was 5.0"), run.errLines());
    }

    private static String read(Path file) throws IOException {
        return new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
    }
}

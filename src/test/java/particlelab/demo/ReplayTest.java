package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.Allocations;
import particlelab.app.DemoCatalog;
import particlelab.lecture.DragDemo;
import particlelab.lecture.FountainDemo;
import particlelab.physics.SimulationClock;
import particlelab.world.StateRing;

/**
 * The replay's clock side, in plain JUnit: the blend the views draw with is the accumulator's
 * leftover over h (1 when it must be the physics state), the ring keeps to its budget in the
 * largest demo, recording and stepping back allocate nothing, and the export writes the
 * recorded span while a recorded step is shown.
 */
class ReplayTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;

    @Test
    void theBlendIsTheLeftoverOverH() {
        DemoState demo = new DragDemo();
        Replay replay = demo.getRun().getReplay();
        demo.getRun().advancePhysics(1.37f * H);
        double leftover = demo.getClock().getLeftoverSeconds();
        // One step taken, 0.37 h left over (up to the float round-off of 1.37·h).
        assertEquals(1L, demo.getWorld().getStepCount());
        assertEquals(0.37, leftover / H, 1e-5);
        float alpha = replay.updateFrameBlend(false);
        assertEquals((float) (leftover / H), alpha);
        StringBuilder hud = new StringBuilder();
        replay.appendHudText(hud);
        assertTrue(hud.toString().contains("drawn: interpolated (α = 0.37); numbers: the last"
                + " step"), hud.toString());
        replay.toggleInterpolation();
        assertEquals(1f, replay.updateFrameBlend(false), "F6 off: the raw steps");
        hud.setLength(0);
        replay.appendHudText(hud);
        assertTrue(hud.toString().contains("drawn: raw steps"), hud.toString());
        replay.toggleInterpolation();
        assertEquals(1f, replay.updateFrameBlend(true), "the scene is over");
        demo.getClock().setPaused(true);
        assertEquals(1f, replay.updateFrameBlend(false), "paused: the physics state");
        demo.getClock().setPaused(false);
        demo.getClock().toggleMode();
        assertEquals(1f, replay.updateFrameBlend(false), "raw tpf: each frame is one step");
    }

    /**
     * The fountain's points draw the physics steps whatever F6 says: the stepping line must
     * not claim an interpolated picture there, and does elsewhere, the rotating boxes
     * (rotation, throw, racket) included: they blend their last two states.
     */
    @Test
    void aDemoWhoseViewsDrawRawStepsSaysSo() {
        for (String name : List.of("fountain", "rotation", "throw", "racket", "drag")) {
            DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
            demo.getRun().advancePhysics(1.37f * H);
            demo.getRun().getReplay().updateFrameBlend(demo.getRun().isSceneOver());
            String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
            boolean raw = name.equals("fountain");
            assertEquals(raw, hud.contains("drawn: raw steps (this demo's views)"),
                    name + ": " + hud);
            assertEquals(!raw, hud.contains("drawn: interpolated"), name + ": " + hud);
        }
    }

    @Test
    void theRingKeepsToItsBudgetInTheFountain() {
        DemoState demo = new FountainDemo();
        StateRing ring = demo.getRun().getStateRing();
        long most = 0L;
        for (int i = 0; i < 60; ++i) {
            demo.getRun().advancePhysics(H);
            most = Math.max(most, ring.getBytes());
        }
        assertTrue(most <= StateRing.DEFAULT_BUDGET_BYTES, most + " bytes");
        assertTrue(ring.getCapacity() >= 2 && ring.getCapacity() < 60, ring.getCapacity()
                + " steps: the budget, not the minute's cap, sizes the fountain's ring");
        assertEquals(ring.getCapacity(), ring.size());
        StringBuilder text = demo.getRun().getReplay().appendRing(new StringBuilder());
        assertTrue(text.toString().matches("ring: 0\\.\\d s of 60 steps/s, \\d\\d\\.\\d MB"),
                text.toString());
    }

    @Test
    void aSmallDemoKeepsAMinuteOverALongRun() {
        DemoState demo = new DragDemo();
        StateRing ring = demo.getRun().getStateRing();
        for (int i = 0; i < 2 * StateRing.DEFAULT_MAX_STEPS; ++i) {
            demo.getRun().advancePhysics(H);
            assertTrue(ring.getBytes() <= StateRing.DEFAULT_BUDGET_BYTES);
        }
        assertEquals(StateRing.DEFAULT_MAX_STEPS, ring.getCapacity());
        StringBuilder text = demo.getRun().getReplay().appendRing(new StringBuilder());
        assertTrue(text.toString().startsWith("ring: 60.0 s of 60 steps/s, "), text.toString());
    }

    @Test
    void recordingSteppingBackAndScrubbingAllocateNothing() {
        for (String name : List.of("drag", "targets", "collisions", "rotation", "tunnelling")) {
            DemoState demo = DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
            for (int i = 0; i < 600; ++i) {
                demo.getRun().advancePhysics(H);
            }
            Allocations.assertAllocatesNothing(name + ": steps recorded, back and forth",
                    () -> {
                        for (int i = 0; i < 30; ++i) {
                            demo.getReplayControls().stepBack();
                        }
                        demo.getReplayControls().scrubTo(0.5);
                        demo.getReplayControls().stepForward();
                        demo.getClock().setPaused(false);
                        for (int i = 0; i < 120; ++i) {
                            demo.getRun().advancePhysics(H);
                        }
                    });
        }
    }

    @Test
    void theExportWritesTheRecordedSpanWhileBehind(@TempDir Path folder) throws IOException {
        DemoState demo = new DragDemo();
        int[] sizes = new int[demo.getParticles().size()];
        for (int i = 0; i < 100; ++i) {
            demo.getRun().advancePhysics(H);
            if (i == 89) {
                for (int k = 0; k < sizes.length; ++k) {
                    sizes[k] = demo.getParticles().get(k).getRecord().size();
                }
            }
        }
        Path live = Files.createDirectory(folder.resolve("live"));
        List<TrajectoryExport.Written> atLiveEnd = TrajectoryExport.write(demo, live, false);
        for (TrajectoryExport.Written file : atLiveEnd) {
            assertFalse(file.getFile().toString().contains("-recorded"), "live: as before");
        }
        for (int i = 0; i < 10; ++i) {
            demo.getReplayControls().stepBack();
        }
        StateRing ring = demo.getRun().getStateRing();
        Path behind = Files.createDirectory(folder.resolve("behind"));
        List<TrajectoryExport.Written> written = TrajectoryExport.write(demo, behind, false);
        int spans = 0;
        int records = 0;
        DemoParticle first = demo.getParticles().get(0);
        for (TrajectoryExport.Written file : written) {
            List<String> lines = Files.readAllLines(file.getFile());
            if (file.getFile().getFileName().toString().equals(ParametersTable.NAME + ".csv")) {
                // The settings travel with every export, behind the live end too.
                assertEquals(ParametersTable.HEADER, lines.get(0));
                continue;
            }
            assertEquals(TrajectoryRecord.HEADER, lines.get(0));
            if (file.getFile().getFileName().toString().endsWith("-recorded.csv")) {
                ++spans;
                assertEquals(ring.size() + 1, lines.size(), "a row per entry of the ring");
            } else {
                // The particle's own record is the state shown's: as it was at step 90.
                assertEquals(sizes[records] + 1, lines.size(), file.describe());
                ++records;
            }
        }
        // A span per particle exported: the comparison lane's sphere is parked, not one.
        long exported = demo.getParticles().stream().filter(p -> !p.isParked()).count();
        assertEquals(exported, spans);
        // The span's row of the step shown is that state's record's last row, bit for bit.
        Path span = behind.resolve(TrajectoryExport.fileSafeName(first.getLabel())
                + "-recorded.csv");
        List<String> rows = Files.readAllLines(span);
        String shown = rows.get(1 + (int) (demo.getRun().getShownStep() - ring.getFirstIndex()));
        TrajectoryRecord record = first.getRecord();
        String expected = record.appendCsvRow(record.size() - 1, new StringBuilder())
                .toString();
        assertEquals(expected.substring(expected.indexOf(',')), shown.substring(
                shown.indexOf(',')), "x..vz of the step shown");
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.DragDemo;
import particlelab.lecture.SpringDemo;
import particlelab.lecture.UniformMotionDemo;

/**
 * The export's {@code energy.csv} (issue 32): the header of the columns each demo has, a row
 * per step since the reset with the start's row first, and its columns adding up (with the
 * HUD's ledger on, as a lecturer would have it).
 */
class EnergyExportTest {

    private static final float H = 1f / 60f;

    private static List<String> exported(DemoState demo, Path folder) throws IOException {
        demo.getParameters().set(EnergyPart.PARAMETER, 1f);
        for (int i = 0; i < 60; ++i) {
            demo.getRun().advancePhysics(H);
        }
        TrajectoryExport.write(demo, folder, false);
        Path file = folder.resolve("energy.csv");
        assertTrue(Files.isRegularFile(file), "energy.csv written");
        return Files.readAllLines(file);
    }

    @Test
    void eachDemoWritesTheColumnsItHas(@TempDir Path folder) throws IOException {
        Path drag = Files.createDirectory(folder.resolve("drag"));
        assertEquals("t,kinetic_J,potential_J,drag_loss_J,impact_loss_J,numerical_J",
                exported(new DragDemo(), drag).get(0));
        Path bounce = Files.createDirectory(folder.resolve("bounce"));
        assertEquals("t,kinetic_J,potential_J,impact_loss_J,numerical_J",
                exported(new BounceDemo(), bounce).get(0));
        Path spring = Files.createDirectory(folder.resolve("spring"));
        assertEquals("t,kinetic_J,potential_J,spring_J,drag_loss_J,numerical_J",
                exported(new SpringDemo(), spring).get(0));
        Path uniform = Files.createDirectory(folder.resolve("uniform"));
        assertEquals("t,kinetic_J,numerical_J", exported(new UniformMotionDemo(), uniform)
                .get(0));
    }

    @Test
    void theRowsStartAtTheResetAndAddUp(@TempDir Path folder) throws IOException {
        DemoState demo = new SpringDemo();
        List<String> lines = exported(demo, folder);
        // the start's row, then one per step: 60 frames of h
        assertEquals(1 + 1 + 60, lines.size());
        String[] first = lines.get(1).split(",");
        assertEquals("0", first[0]);
        assertEquals("0", first[first.length - 1], "no numerical energy at the start");
        double start = 0.0;
        for (int k = 1; k <= 3; ++k) {
            start += Double.parseDouble(first[k]);
        }
        for (int n = 1; n < lines.size(); ++n) {
            String[] cells = lines.get(n).split(",");
            double kinetic = Double.parseDouble(cells[1]);
            double potential = Double.parseDouble(cells[2]);
            double spring = Double.parseDouble(cells[3]);
            double drag = Double.parseDouble(cells[4]);
            double numerical = Double.parseDouble(cells[5]);
            // the file holds floats: 6e-8 of each of the values, about 1400 J at most
            assertEquals(start, kinetic + potential + spring + drag - numerical,
                    5 * 1400 * 6e-8, "row " + n);
        }
    }
}

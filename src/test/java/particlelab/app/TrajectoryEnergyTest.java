package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;

/**
 * {@code trajectory --energy} (issue 32): the ledger's columns after the state, and for
 * gravity alone the numerical column {@code m·g·h·(vy − vy0)/2}.
 */
class TrajectoryEnergyTest {

    private static CommandRun ok(String... args) {
        String[] full = new String[args.length + 1];
        full[0] = "trajectory";
        System.arraycopy(args, 0, full, 1, args.length);
        CommandRun run = CommandRun.of(full);
        assertEquals(0, run.code, run.toString());
        return run;
    }

    @Test
    void gravityAlonePrintsNumericalEqualToMghTimesVyChangeOverTwo() {
        float mass = 2f;
        float h = 0.05f;
        List<String> lines = ok("--p0", "0,10,0", "--v0", "3,4,0", "--mass", "2", "--tpf",
                "0.05", "--steps", "100", "--energy").outLines();
        assertEquals("t,x,y,z,vx,vy,vz,kinetic_J,potential_J,numerical_J", lines.get(0));
        assertEquals(1 + 101, lines.size());
        double vy0 = 4.0;
        double g = Gravity.STANDARD_G;
        for (int n = 0; n <= 100; ++n) {
            String[] cells = lines.get(1 + n).split(",");
            assertEquals(10, cells.length, lines.get(1 + n));
            double vy = Float.parseFloat(cells[5]);
            double expected = mass * g * h * (vy - vy0) / 2.0;
            // Printed as a float (6e-8 relative of the |value| < 25 J), computed from float
            // states: each step rounds y (|y| < 16 m, ulp 1.9e-6) and vy (|vy| < 50, ulp
            // 3.8e-6) once, moving the energy by m·(g·ulp(y) + |vy|·ulp(vy)) at most.
            double tolerance = 1e-6 + n * mass * (g * Math.ulp(16f) + 50.0 * Math.ulp(50f));
            assertEquals(expected, Float.parseFloat(cells[9]), tolerance, "row " + n);
            // and K + U is what the state says: ½m·|V|² + m·g·y
            double vx = Float.parseFloat(cells[4]);
            double y = Float.parseFloat(cells[2]);
            assertEquals(0.5 * mass * (vx * vx + vy * vy), Float.parseFloat(cells[7]),
                    1e-5 * 300.0);
            assertEquals(mass * g * y, Float.parseFloat(cells[8]), 1e-5 * 300.0);
        }
    }

    @Test
    void dragAndThrustAddTheirColumns() {
        List<String> lines = ok("--linear-drag", "0.1", "--thrust", "2", "--steps", "3",
                "--energy").outLines();
        assertEquals("t,x,y,z,vx,vy,vz,kinetic_J,potential_J,thrust_work_J,drag_loss_J,"
                + "numerical_J", lines.get(0));
        String[] first = lines.get(1).split(",");
        assertEquals("0.0", first[9], "no work before the first step");
        assertEquals("0.0", first[11]);
    }

    @Test
    void withoutTheFlagTheCsvIsUnchanged() {
        assertEquals("t,x,y,z,vx,vy,vz", ok("--steps", "1").outLines().get(0));
    }
}

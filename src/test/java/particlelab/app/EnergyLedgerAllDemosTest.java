package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.StepTable;
import particlelab.lecture.FountainDemo;
import particlelab.physics.EnergyLedger;
import particlelab.rigid.RigidBody;
import particlelab.world.Body;
import particlelab.world.StepListener;
import particlelab.world.World;
import particlelab.world.WorldEnergy;

/**
 * Every demo's energy ledger adds up at every step (issue 32): stepped headless, no display,
 * 400 frames of 1/60 s each, the columns checked after every step of the world.
 */
class EnergyLedgerAllDemosTest {

    private static final float TPF = 1f / 60f;
    private static final int FRAMES = 400;

    /** Checks the ledger after every step, and measures K itself. */
    private static final class Check implements StepListener {
        final WorldEnergy energy;
        final String name;
        int steps;
        double largest;
        double worstResidual;
        final com.jme3.math.Vector3f omega = new com.jme3.math.Vector3f();

        Check(WorldEnergy energy, String name) {
            this.energy = energy;
            this.name = name;
        }

        @Override
        public void afterStep(World world, float stepSeconds) {
            ++steps;
            EnergyLedger ledger = energy.getLedger();
            double[] columns = {ledger.getStartJoules(), ledger.getKineticJoules(),
                ledger.getPotentialJoules(), ledger.getSpringJoules(),
                ledger.getThrustWorkJoules(), ledger.getDragLossJoules(),
                ledger.getImpactLossJoules(), ledger.getScriptWorkJoules(),
                ledger.getNumericalJoules()};
            double scale = 0.0;
            for (double column : columns) {
                assertTrue(Double.isFinite(column), name + ": a column is not finite");
                scale = Math.max(scale, Math.abs(column));
            }
            largest = Math.max(largest, scale);
            // a column the demo does not export holds nothing, or the file would not add up
            for (int i = 0; i < EnergyLedger.NUMERICAL_COLUMN; ++i) {
                if ((energy.getColumns() & (1 << i)) == 0) {
                    assertEquals(0.0, ledger.getColumn(i), 0.0,
                            name + ": column " + i + " is not in the export but holds energy");
                }
            }
            double residual = ledger.getKineticJoules() + ledger.getPotentialJoules()
                    + ledger.getSpringJoules() - (ledger.getStartJoules()
                    + ledger.getThrustWorkJoules() - ledger.getDragLossJoules()
                    - ledger.getImpactLossJoules() + ledger.getScriptWorkJoules()
                    + ledger.getNumericalJoules());
            worstResidual = Math.max(worstResidual, Math.abs(residual));
            // doubles summed over a few dozen bodies and terms: 1e-12 of the largest column
            // is thousands of roundings of 1.1e-16
            assertEquals(0.0, residual, 1e-12 * Math.max(1.0, scale),
                    name + ": the columns do not add up at step " + steps);
            // the kinetic column is the bodies' ½m|V|² (+ ½ωᵀIω), measured here apart
            double kinetic = 0.0;
            for (int i = 0; i < world.countBodies(); ++i) {
                Body body = world.getBody(i);
                kinetic += 0.5 * body.getMass() * body.getVelocity().lengthSquared();
                RigidBody rigid = body.getRigidBody();
                if (rigid != null) {
                    kinetic += rigid.rotationalEnergy(omega);
                }
            }
            // lengthSquared is a float: 2^-22 of the sum
            assertEquals(kinetic, ledger.getKineticJoules(), 1e-6 * Math.max(1.0, kinetic),
                    name + ": kinetic at step " + steps);
        }
    }

    @Test
    void theColumnsAddUpAtEveryStepInEveryDemo() {
        StringBuilder seen = new StringBuilder();
        for (DemoCatalog.Entry entry : DemoCatalog.entries()) {
            DemoState demo = entry.create();
            World world = demo.getWorld();
            WorldEnergy energy = new WorldEnergy(world);
            Check check = new Check(energy, entry.getName());
            world.addStepListener(check);
            double startKinetic = energy.getLedger().getKineticJoules();
            for (int frame = 0; frame < FRAMES; ++frame) {
                demo.getRun().advancePhysics(TPF);
            }
            assertTrue(check.steps > 0, entry.getName() + " took no step");
            EnergyLedger ledger = energy.getLedger();
            if (entry.getName().equals("racket")) {
                // Nothing is put in or taken out: the start stays the plates' ½ωᵀIω, and
                // explicit Euler's rotation step gains energy, which only the numerical
                // column may hold (the demo's own HUD: 8 % of 16 J after 3.3 s).
                assertEquals(startKinetic, ledger.getStartJoules(), 1e-9 * startKinetic);
                assertTrue(ledger.getNumericalJoules() > 0.05 * startKinetic / 2,
                        "racket: numerical " + ledger.getNumericalJoules());
            }
            seen.append(String.format("%-11s steps %4d  largest %10.4g J  numerical %10.4g J"
                    + "  residual %.2g J%n", entry.getName(), check.steps, check.largest,
                    ledger.getNumericalJoules(), check.worstResidual));
        }
        System.out.print(seen);
    }

    /**
     * The fountain's particles are no bodies of its world: its ledger is its own, kept only
     * while switched on, and adds up in every row of its {@code energy.csv}.
     */
    @Test
    void theFountainKeepsANonzeroLedgerThatAddsUpInEveryRow() throws IOException {
        FountainDemo off = new FountainDemo();
        off.setParticleCount(2_000);
        for (int frame = 0; frame < 10; ++frame) {
            off.getRun().advancePhysics(TPF);
        }
        assertTrue(off.getFountain().getEnergy() == null && !off.getEnergyPart().hasLedger(),
                "off: no ledger kept, no cost");
        FountainDemo demo = new FountainDemo();
        demo.setParticleCount(20_000);
        demo.getParameters().set("energy", 1f);
        for (int frame = 0; frame < FRAMES; ++frame) {
            demo.getRun().advancePhysics(TPF);
        }
        assertTrue(demo.getEnergyPart().hasLedger(), "on: the fountain's own ledger");
        EnergyLedger ledger = demo.getFountain().getEnergy().getLedger();
        assertTrue(ledger.getKineticJoules() > 0.0 && ledger.getEmittedJoules() > 0.0
                && ledger.getRemovedJoules() > 0.0 && ledger.getImpactLossJoules() > 0.0
                && ledger.getDragLossJoules() > 0.0, "every column holds energy");
        StepTable table = demo.getEnergyPart().getTable();
        assertEquals("t,kinetic_J,potential_J,drag_loss_J,impact_loss_J,emitted_J,removed_J,"
                + "numerical_J", table.getHeader());
        StringWriter csv = new StringWriter();
        table.writeCsv(csv);
        String[] lines = csv.toString().split("\n");
        // the header, the start's row, a row per step
        assertEquals(2 + demo.getWorld().getStepCount(), lines.length);
        for (int row = 1; row < lines.length; ++row) {
            String[] cells = lines[row].split(",");
            double[] c = new double[cells.length];
            double scale = 0.0;
            for (int i = 1; i < cells.length; ++i) {
                c[i] = Double.parseDouble(cells[i]);
                scale = Math.max(scale, Math.abs(c[i]));
            }
            // K + U = emitted − drag − impact − removed + numerical (start 0: the pool
            // starts empty); the table keeps each value as a float, rounded by at most
            // 2^-24 of the largest (6e-8): seven of them, 4.2e-7, under 1e-6 of it (the
            // ledger's own double sums add up to 1e-14, world/FountainEnergyTest)
            double residual = c[1] + c[2] - (c[5] - c[3] - c[4] - c[6] + c[7]);
            assertEquals(0.0, residual, 1e-6 * Math.max(1.0, scale), "row " + row);
        }
    }
}

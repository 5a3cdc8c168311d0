package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.aiming.AimStrategy;
import particlelab.aiming.Duel;
import particlelab.aiming.ShotLog;
import particlelab.demo.Presentation;
import particlelab.demo.StepTable;
import particlelab.physics.SimulationClock;

/**
 * Issue 34 §3 in the iterate demo, in plain JUnit: {@code --set duel=on} makes the round the
 * believable player's, the duel's computer is the shots the scene flies, a scripted human's
 * keys aim and fire a sphere that lands where the duel's step says, the poll closes the round
 * with the next seed, and the export's {@code duel.csv} carries the row under its fixed
 * header.
 */
class IterativeAimingDuelTest {

    private static final float TPF = 1f / 60f;
    /**
     * The scene's sphere and the duel's simulator step the same floats; the scene's ground
     * stops it at its swept contact, the simulator interpolates the same crossing: they agree
     * to float rounding at 60 m (1 mm, as the iterate demo's own shots do).
     */
    private static final double SAME_LANDING_METRES = 1e-3;

    @Test
    void aScriptedHumanDuelsTheBelievablePlayerAndTheRoundIsExported() throws IOException {
        IterativeAimingDemo iterate = new IterativeAimingDemo();
        // As --set duel=on does: applied when the scene starts, at the first frame.
        iterate.getParameters().set("duel", 1f);
        iterate.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        iterate.getRun().advancePhysics(TPF);
        assertTrue(iterate.isDuelOn());
        assertEquals(AimStrategy.BELIEVABLE, iterate.getStrategy());
        assertSamePlan(iterate.getPlan(), iterate.getDuel().getComputerShots());

        // 45° at 25 m/s, then Right twenty times (27 m/s), then four more (27.4 m/s).
        assertEquals(45f, iterate.getDuelDegrees());
        assertEquals(25f, iterate.getDuelSpeed());
        int[] rightPresses = {0, 20, 4};
        for (int shot = 0; shot < rightPresses.length; ++shot) {
            for (int press = 0; press < rightPresses[shot]; ++press) {
                iterate.aimBy(0f, IterativeAimingDemo.DUEL_SPEED_STEP);
            }
            assertTrue(iterate.fireHuman(), "shot " + (shot + 1));
            assertFalse(iterate.fireHuman(), "not while it flies");
            flyUntilHumanLanded(iterate);
            double landed = iterate.getHumanSphere().getParticle().position.x;
            assertEquals(IterativeAimingDemo.TARGET_DISTANCE
                    + iterate.getDuel().getHumanMiss(shot), landed, SAME_LANDING_METRES);
        }
        assertEquals(27.4f, iterate.getDuelSpeed());
        assertTrue(iterate.getDuel().hasHumanHit());
        String hud = iterate.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("Duel, round 1 (seed 1): your aim 45.0° (Up/Down) at 27.4 m/s"),
                hud);
        assertTrue(hud.contains("felt fair? Y yes, B no"), hud);
        // Presenting: the aim on the slide's second formula line, the score as its readout.
        Presentation slide = iterate.getWindow().formatPresentation();
        String readout = slide.getReadout().toString();
        assertEquals(2, slide.countFormulaLines());
        assertTrue(slide.getFormulas().toString().endsWith("your aim 45.0° (Up/Down) at 27.4"
                + " m/s (Left/Right), F fires"), slide.getFormulas().toString());
        assertTrue(readout.startsWith("you: 3 shots, last -0.10 m;  computer: "), readout);
        assertTrue(readout.endsWith(";  fair? Y / B"), readout);

        assertTrue(iterate.poll(true));
        assertEquals(2L, iterate.getSeed(), "the next round plays the next seed");
        assertEquals(2, iterate.getDuel().getRound());
        assertEquals(0, iterate.getDuel().countHumanShots());
        assertSamePlan(iterate.getPlan(), iterate.getDuel().getComputerShots());
        assertFalse(iterate.poll(false), "round 2 is not over");

        List<StepTable> tables = new ArrayList<>();
        iterate.collectExportTables(tables);
        StepTable duel = tables.get(tables.size() - 1);
        assertEquals(IterativeAimingDemo.DUEL_TABLE, duel.getName());
        assertEquals(Duel.CSV_HEADER, duel.getHeader());
        StringWriter csv = new StringWriter();
        duel.writeCsv(csv);
        String[] lines = csv.toString().split(System.lineSeparator());
        assertEquals(2, lines.length, csv.toString());
        double[] row = iterate.getDuel().copyClosedRound(0);
        // round 1, seed 1, three shots, a hit, felt fair
        assertArrayEquals(new double[] {1, 1, 3, 1}, java.util.Arrays.copyOf(row, 4));
        assertEquals(1.0, row[9]);
        assertTrue(lines[1].startsWith("1,1,3,1,"), lines[1]);
        assertTrue(lines[1].endsWith(",1"), lines[1]);
    }

    @Test
    void anotherStrategyEndsTheDuelAndTheKeysThenOnlySaySo() {
        IterativeAimingDemo iterate = new IterativeAimingDemo();
        iterate.getRun().advancePhysics(TPF);
        iterate.getParameters().set("duel", 1f);
        assertTrue(iterate.isDuelOn());
        // strategy=secant: the third of lecture, bisection, secant, believable.
        iterate.getParameters().set("strategy", 2f);
        assertFalse(iterate.isDuelOn());
        assertEquals(0f, iterate.getParameters().getValue("duel"));
        assertFalse(iterate.fireHuman());
        assertTrue(iterate.getDemoHud().getNotice().contains("the duel is off"),
                iterate.getDemoHud().getNotice());
        assertFalse(iterate.poll(true));
        List<StepTable> tables = new ArrayList<>();
        iterate.collectExportTables(tables);
        assertEquals(1, tables.size(), "no duel table without a duel");
    }

    private static void flyUntilHumanLanded(IterativeAimingDemo iterate) {
        // Ten seconds of frames: a shot at up to 40 m/s lands within six.
        for (int frame = 0; frame < 600 && iterate.isHumanInAir(); ++frame) {
            iterate.getRun().advancePhysics(TPF);
        }
        assertFalse(iterate.isHumanInAir(), "the human's shot did not land within 10 s");
    }

    private static void assertSamePlan(ShotLog scene, ShotLog duel) {
        assertEquals(scene.size(), duel.size());
        for (int i = 0; i < scene.size(); ++i) {
            assertEquals(scene.getVerticalSpeed(i), duel.getVerticalSpeed(i), "shot " + (i + 1));
            assertEquals(scene.getLandingX(i), duel.getLandingX(i), "shot " + (i + 1));
        }
    }
}

package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Thrust;

class TrajectoryCommandTest {

    private static final float H = 1f / 60f;

    /** vx of CSV row n (0 = the initial state). */
    private static float velocityX(CommandRun run, int n) {
        return Float.parseFloat(run.outLines().get(1 + n).split(",")[4]);
    }

    private static CommandRun ok(String... args) {
        String[] full = new String[args.length + 1];
        full[0] = "trajectory";
        System.arraycopy(args, 0, full, 1, args.length);
        CommandRun run = CommandRun.of(full);
        assertEquals(0, run.code, run.toString());
        return run;
    }

    private static float[] row(String line) {
        String[] cells = line.split(",");
        assertEquals(7, cells.length, line);
        float[] values = new float[7];
        for (int i = 0; i < 7; ++i) {
            values[i] = Float.parseFloat(cells[i]);
        }
        return values;
    }

    @Test
    void printsTheExactHeaderAndOneRowPerStepPlusTheInitialState() {
        CommandRun run = ok("--steps", "10");
        List<String> lines = run.outLines();
        assertEquals("t,x,y,z,vx,vy,vz", lines.get(0));
        assertEquals(1 + 10 + 1, lines.size());
        assertEquals("", run.err);
        assertEquals(2, ok("--steps", "0").outLines().size(), "--steps 0: the initial row");
    }

    @Test
    void initialRowIsP0AndV0AtTimeZero() {
        List<String> lines = ok("--p0", "1,2.5,-3", "--v0=4,5,6e-3", "--steps", "1").outLines();
        assertEquals("0.0,1.0,2.5,-3.0,4.0,5.0,0.006", lines.get(1));
    }

    @Test
    void defaultLaunchIsTheLecturesExample() {
        assertEquals("0.0,0.0,0.0,0.0,10.0,10.0,0.0", ok("--steps", "1").outLines().get(1));
    }

    /**
     * With every force on, the rows are exactly the states of the shared integrator stepped
     * directly with the same forces (composed in the command's order: gravity, linear drag,
     * quadratic drag, thrust; float sums depend on order), printed so they read back as the
     * same floats, and t is n·h from the step count rounded to float.
     */
    @Test
    void rowsAreTheIntegratorsStatesExactly() {
        float step = 0.01f;
        int steps = 200;
        List<String> lines = ok("--p0", "0,1,0", "--v0", "3,4,5", "--mass", "2",
                "--linear-drag", "0.3", "--quadratic-drag", "0.05", "--thrust", "1.5",
                "--tpf", "0.01", "--steps", String.valueOf(steps)).outLines();
        ParticleIntegrator integrator = new ParticleIntegrator(
                new Gravity(new Vector3f(0f, -9.8f, 0f)), new LinearDrag(0.3f),
                new QuadraticDrag(0.05f), new Thrust(1.5f));
        Particle particle = new Particle(new Vector3f(0f, 1f, 0f), new Vector3f(3f, 4f, 5f), 2f);
        for (int n = 0; n <= steps; ++n) {
            if (n > 0) {
                integrator.step(particle, step);
            }
            float[] values = row(lines.get(n + 1));
            assertEquals((float) (n * (double) step), values[0], 0f, "t at step " + n);
            float[] expected = {particle.position.x, particle.position.y, particle.position.z,
                    particle.velocity.x, particle.velocity.y, particle.velocity.z};
            for (int i = 0; i < 6; ++i) {
                assertEquals(expected[i], values[i + 1], 0f, "column " + (i + 1) + " at " + n);
            }
        }
    }

    @Test
    void printedValuesRoundTripAsFloats() {
        for (String line : ok("--quadratic-drag", "0.01", "--steps", "50").outLines()
                .subList(1, 52)) {
            for (String cell : line.split(",")) {
                assertEquals(cell, Float.toString(Float.parseFloat(cell)));
            }
        }
    }

    /**
     * Gravity only: the lecture's step has the exact discrete solution
     * {@code y_n = n·h·vy − g·h²·n(n+1)/2} (docs/numerics.md), evaluated here in double with the
     * float h and g the command uses. The float run rounds y at each of n steps by at most
     * ulp(y)/2, and y stays below 8 m, so it may drift by up to n·ulp(8).
     */
    @Test
    void gravityOnlyFollowsTheExactDiscreteSolution() {
        int steps = 120;
        List<String> lines = ok("--steps", String.valueOf(steps)).outLines();
        double g = 9.8f;
        double h = H;
        for (int n = 0; n <= steps; ++n) {
            float[] values = row(lines.get(n + 1));
            double y = n * h * 10.0 - g * h * h * n * (n + 1) / 2.0;
            assertEquals(y, values[2], n * Math.ulp(8f), "y at step " + n);
            assertEquals(10.0 - g * h * n, values[5], n * Math.ulp(16f), "vy at step " + n);
        }
    }

    /**
     * The default launch (10, 10) m/s: by the exact discrete solution y_n < 0 first when
     * n + 1 > 2·vy/(g·h) = 122.45, at n = 122, not on the docs/numerics.md hazard of a sample at
     * y = 0 exactly. So 123 rows after the header, the last one below ground.
     */
    @Test
    void untilGroundStopsAtTheFirstRowBelowGroundAndIncludesIt() {
        List<String> lines = ok("--until-ground").outLines();
        assertEquals(1 + 123, lines.size());
        for (int i = 1; i < lines.size() - 1; ++i) {
            assertTrue(row(lines.get(i))[2] >= 0f, lines.get(i));
        }
        float[] last = row(lines.get(lines.size() - 1));
        assertTrue(last[2] < 0f);
        assertEquals((float) (122 * (double) H), last[0], 0f);
    }

    /** --duration takes T/h rounded to the nearest whole number of steps, at least 1. */
    @Test
    void durationRoundsToTheNearestWholeStep() {
        List<String> up = ok("--duration", "0.26", "--tpf", "0.1").outLines();
        assertEquals(1 + 3 + 1, up.size(), "2.6 steps round up to 3");
        assertEquals(0.3f, row(up.get(up.size() - 1))[0], 1e-7f);
        assertEquals(1 + 2 + 1, ok("--duration", "0.24", "--tpf", "0.1").outLines().size(),
                "2.4 steps round down to 2");
        // 1/(float)(1/60) = 59.9999973: a ceiling would still give 60, a floor 59.
        assertEquals(1 + 60 + 1, ok("--duration", "1", "--tpf", "1/60").outLines().size());
        assertEquals(1 + 1 + 1, ok("--duration", "0.01", "--tpf", "0.1").outLines().size(),
                "at least one step");
    }

    @Test
    void stepBeyondTheStabilityLimitWarnsAndCarriesOn() {
        // Linear drag b = 10, m = 1: sigma = lambda = 10 /s; the speed grows for h > 0.2 s,
        // the velocity reverses for h > 0.1 s.
        CommandRun diverging = ok("--linear-drag", "10", "--tpf", "0.25", "--steps", "5");
        assertEquals(1, diverging.errLines().size(), diverging.toString());
        assertEquals("warning: --tpf 0.25 s exceeds 2/sigma = 0.2 s at the initial state (drag"
                + " rate sigma = 10.0 /s): drag makes the speed grow every step: the Euler step"
                + " blows up; carrying on as asked", diverging.errLines().get(0));
        assertEquals(1 + 5 + 1, diverging.outLines().size());
        CommandRun reversing = ok("--linear-drag", "10", "--tpf", "0.15", "--steps", "5");
        assertEquals("warning: --tpf 0.15 s exceeds 1/sigma = 0.1 s at the initial state (drag"
                + " rate sigma = 10.0 /s): drag reverses the velocity every step but still"
                + " shrinks it; carrying on as asked", reversing.errLines().get(0));
        assertEquals("", ok("--linear-drag", "10", "--tpf", "0.05", "--steps", "5").err);
    }

    @Test
    void quadraticDragThatGrowsTheSpeedAtTheStartWarnsOfABlowUp() {
        // sigma = c·|V0|/m = 0.5·10/1 = 5 /s: h = 0.5 s > 2/sigma = 0.4 s, V1 = −1.5·V0, and
        // the factor only worsens from there.
        CommandRun run = ok("--v0", "10,0,0", "--g", "0,0,0", "--quadratic-drag", "0.5",
                "--tpf", "0.5", "--steps", "2");
        assertTrue(run.err.startsWith("warning: --tpf 0.5 s exceeds 2/sigma = 0.4 s"), run.err);
        assertTrue(run.err.contains("blows up"), run.err);
        assertTrue(Math.abs(velocityX(run, 2)) > Math.abs(velocityX(run, 1)), run.out);
    }

    @Test
    void quadraticDragThatReversesButDecaysDoesNotSayItBlowsUp() {
        // The case: c·h·|V0|/m = 1.5: V1 = −0.5·V0, after which c·h·|V|/m < 1 and the
        // speed only falls. The old check (h > 2/lambda = 0.1 s) said "will blow up".
        CommandRun run = ok("--steps", "6", "--quadratic-drag", "1", "--v0", "10,0,0", "--g",
                "0,0,0", "--tpf", "0.15");
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains("drag reverses the velocity every step but still shrinks"
                + " it"), run.err);
        assertTrue(!run.err.contains("blow"), run.err);
        for (int n = 1; n <= 6; ++n) {
            assertTrue(Math.abs(velocityX(run, n)) < Math.abs(velocityX(run, n - 1)),
                    "speed falls at step " + n + ": " + run.out);
        }
    }

    @Test
    void quadraticDragWithGravityIsCheckedAtTheTerminalSpeed() {
        // c = 0.1, m = 1, g = 9.8: v_t = sqrt(98) = 9.899 m/s, lambda there = 2g/v_t, the
        // limits v_t/g = 1.0102 s (settling) and v_t/(2g) = 0.5051 s (swinging). The start
        // at rest gives sigma = 0: only the terminal check can see these.
        CommandRun never = ok("--v0", "0,0,0", "--quadratic-drag", "0.1", "--tpf", "1.1",
                "--steps", "3");
        assertTrue(never.err.startsWith("warning: --tpf 1.1 s exceeds the stability limit"
                + " 2/lambda = 1.01015"), never.err);
        assertTrue(never.err.contains("at the terminal speed 9.89949"), never.err);
        assertTrue(never.err.contains("never settles"), never.err);
        CommandRun swings = ok("--v0", "0,0,0", "--quadratic-drag", "0.1", "--tpf", "0.7",
                "--steps", "3");
        assertTrue(swings.err.startsWith("warning: --tpf 0.7 s exceeds 1/lambda = 0.50507"),
                swings.err);
        assertTrue(!swings.err.contains("blow") && swings.err.contains("swings"), swings.err);
        assertEquals("", ok("--v0", "0,0,0", "--quadratic-drag", "0.1", "--tpf", "0.4",
                "--steps", "3").err);
    }

    @Test
    void hugeQuadraticDragFromRestStillWarns() {
        // c = 3e38: 2c overflows a float; the rate at rest was NaN, which silenced the check.
        CommandRun run = CommandRun.of("trajectory", "--quadratic-drag", "3e38", "--v0",
                "0,0,0", "--tpf", "0.1", "--steps", "1");
        assertTrue(run.err.startsWith("warning: --tpf 0.1 s exceeds the stability limit"),
                run.toString());
    }

    @Test
    void helpStatesTheLimitsTheWarningChecks() {
        String help = ok("--help").out.replaceAll("\\s+", " ");
        assertTrue(help.contains(CommandSupport.STABILITY_NOTE), help);
        // The old help gave quadratic drag's rate as c*|V0|/m, half the code's 2c*|V|/m.
        assertTrue(!help.contains("c*|V0|") && !help.contains("c·|V0|"), help);
    }

    @Test
    void aStepThatOverflowsIsOneErrorLineAndNoCsv() {
        // Each step multiplies V by 1 − k·h = −9: float overflows within 45 steps.
        CommandRun run = CommandRun.of("trajectory", "--linear-drag", "10", "--tpf", "1",
                "--steps", "1000");
        assertEquals(2, run.code);
        assertEquals("", run.out);
        // One line: the stability warning is left out of a run that failed.
        List<String> err = run.errLines();
        assertEquals(1, err.size(), run.toString());
        assertTrue(err.get(0).startsWith("particle-lab trajectory: --tpf: the Euler step of 1.0"
                + " s left the particle non-finite"), err.get(0));
    }

    @Test
    void untilGroundRefusesAStartBelowGroundAndAParticleThatNeverLands() {
        CommandRun below = CommandRun.of("trajectory", "--p0", "0,-1,0", "--until-ground");
        assertEquals(2, below.code);
        assertTrue(below.err.contains("--p0: with --until-ground the start must be at or above"
                + " the ground (y >= 0), but was 0.0,-1.0,0.0"), below.err);
        CommandRun never = CommandRun.of("trajectory", "--g", "0,0,0", "--until-ground");
        assertEquals(2, never.code);
        assertEquals(1, never.errLines().size());
        assertTrue(never.err.contains("--until-ground: the particle is still at y = "),
                never.err);
        assertEquals("", never.out);
    }

    @Test
    void onlyForcesWithNonZeroCoefficientsAreComposed() {
        assertEquals(0, CommandSupport.integrator(new Vector3f(), 0f, 0f, 0f).countForces());
        ParticleIntegrator drag = CommandSupport.integrator(new Vector3f(), 0f, 0.1f, 0f);
        assertEquals(1, drag.countForces());
        assertTrue(drag.getForce(0) instanceof QuadraticDrag);
        assertEquals(4, CommandSupport.integrator(new Vector3f(0f, -1f, 0f), 1f, 1f, 1f)
                .countForces());
    }
}

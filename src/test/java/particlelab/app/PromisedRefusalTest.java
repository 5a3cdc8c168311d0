package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.lecture.DragDemo;
import particlelab.physics.Particle;

/**
 * Issue 17's command lines that broke a promise of the help: internal errors (exit 1) where a
 * one-line refusal (exit 2) is promised, refusals that blamed the wrong option, a number
 * grammar that differed between options, and a collision that lost momentum in silence. Each
 * case failed before its fix.
 */
class PromisedRefusalTest {

    /** The spheres of {@code collide}, head on, 1 m apart, approaching at 2 m/s. */
    private static final String[] SPHERES = {"--p1", "0,0,0", "--p2", "3,0,0", "--v1",
        "1,0,0", "--v2", "-1,0,0", "--r1", "1", "--r2", "1", "--restitution", "1"};

    /** A mass below the float's normal range was an IllegalArgumentException from the world. */
    @Test
    void collideRefusesASubnormalMassAsTrajectoryAndAimDo() {
        for (String option : new String[] {"--m1", "--m2"}) {
            String other = "--m1".equals(option) ? "--m2" : "--m1";
            CommandRun run = assertRefused(option, collide(option, "1e-45", other, "1"));
            assertTrue(run.err.contains(String.valueOf(Particle.MIN_MASS_KG)), run.toString());
            assertRefused(option, collide(option, "1e-39", other, "1"));
        }
        assertEquals(0, CommandRun.of(collide("--m1", "1.2e-38", "--m2", "1")).code);
    }

    /** The discrete correction g*(S/vx + h)/2 overflowed the float the shot is fired with. */
    @Test
    void aDiscreteCorrectionBeyondTheFloatRangeIsRefusedNamingTheStep() {
        CommandRun run = assertRefused("--tpf", "aim", "--distance", "100", "--vx", "50",
                "--method", "discrete", "--tpf", "3.4e38");
        assertTrue(run.err.contains("at most 3600.0 s"), run.toString());
        assertRefused("--predict-tpf", "aim", "--distance", "100", "--vx", "50", "--method",
                "discrete", "--predict-tpf", "3.4e38");
        // h = 1000 s passes the length check; g*h/2 alone is then past the float range.
        run = assertRefused("--tpf", "aim", "--distance", "100", "--vx", "50", "--method",
                "discrete", "--g", "1e36", "--tpf", "1000");
        assertTrue(run.err.contains("beyond the float range"), run.toString());
        // g*S/(2*vx) = 3.4e38 still fits; the discrete vy, (1 + h*vx/S) times more, does not.
        run = assertRefused("--vx", "aim", "--distance", "100", "--vx", "50", "--method",
                "discrete", "--g", "3.4e38");
        assertTrue(run.err.contains("discrete correction"), run.toString());
        assertTrue(run.err.contains("--g"), run.toString());
    }

    /** A predictor step of 1e30 s flew one step and was reported as an unreachable target. */
    @Test
    void aPredictorStepLongerThanAFlightBlamesThePredictorStep() {
        CommandRun run = assertRefused("--predict-tpf", "aim", "--distance", "100", "--vx",
                "50", "--method", "discrete", "--predict-tpf", "1e30");
        assertTrue(run.err.startsWith("particle-lab aim: --predict-tpf: must be at most"),
                run.toString());
        assertFalse(run.err.contains("out of reach"), run.toString());
    }

    /**
     * The start offset (1 + phi)*v*h overflowed, and the swept contact's bounce of a shot at
     * 3.4e38 m/s threw NonFiniteStepException through the command.
     */
    @Test
    void tunnelShotsBeyondTheFloatRangeAreOneLine() {
        CommandRun run = assertRefused("--tpf", "tunnel", "--speed", "1", "--radius", "0.1",
                "--thickness", "0.1", "--detection", "overlap", "--shots", "10", "--tpf",
                "3.4e38");
        assertTrue(run.err.contains("beyond the float range"), run.toString());
        assertRefused("--speed", "tunnel", "--speed", "3.4e38", "--radius", "0.1",
                "--thickness", "0.1", "--detection", "swept", "--shots", "10");
        // The overlap test never sees such a shot, so it never bounces: every shot misses,
        // as predicted (probability 1).
        run = CommandRun.of("tunnel", "--speed", "3.4e38", "--radius", "0.1", "--thickness",
                "0.1", "--detection", "overlap", "--shots", "10");
        assertEquals(0, run.code, run.toString());
        assertEquals("10,0,10,1.0", run.outLines().get(1), run.toString());
    }

    /** The internal-error line cut the exception's message at 40 characters. */
    @Test
    void theInternalErrorLineGivesTheWholeReason() {
        String reason = "mass (kg) must be finite and > 0, at least 1.17549435E-38 so that 1/m"
                + " is a finite float, but was 1.0E-45";
        String line = Main.internalErrorLine(new IllegalArgumentException(reason + "\n"));
        assertEquals("particle-lab: internal error, please report it with the command line: "
                + "IllegalArgumentException: " + reason + "\\u000a", line);
    }

    /** {@code demo bogus --particles 5} complained about --particles, not the unknown demo. */
    @Test
    void anUnknownDemoIsNamedBeforeItsOptions() {
        CommandRun run = assertRefused("no demo named 'bogus'", "demo", "bogus", "--particles",
                "5");
        assertFalse(run.err.contains("--particles"), run.toString());
        assertRefused("no demo named 'bogus'", "demo", "--demo", "bogus", "--frames", "0");
    }

    /** {@code help aim x} printed the launcher's help and exited 0. */
    @Test
    void helpWithMoreThanOneWordIsOneLineAndExitTwo() {
        assertRefused("help: takes at most one command", "help", "aim", "x");
        assertRefused("help: takes at most one command", "help", "--bogus");
        assertEquals(0, CommandRun.of("help", "--help").code);
        assertEquals(0, CommandRun.of("help", "aim").code);
    }

    /**
     * {@code --set} read its value with Double.parseDouble, unlike every other option: a
     * suffix, hexadecimal, a space and other scripts' digits were numbers there.
     */
    @ParameterizedTest
    @ValueSource(strings = {"b=1f", "b=1d", "b=0x1p-4", "b= 0.1", "b=0.1 ", "b=\u0661",
        "b=\uff11", "b=1/\u0662", "b=Infinity", "b=1e39"})
    void setValuesHaveTheGrammarOfEveryOption(String setting) {
        UsageException refused = assertThrows(UsageException.class,
                () -> DemoCommand.applySettings(new DragDemo(), List.of(setting)));
        assertTrue(refused.getMessage().contains("must be NAME=VALUE"), refused.getMessage());
        // The same text given to an option is refused too.
        String value = setting.substring(2);
        CommandRun run = CommandRun.of("trajectory", "--steps", "1", "--mass", value);
        assertEquals(Program.USAGE, run.code, run.toString());
    }

    /** What --set documents still reads: decimals and fractions. */
    @Test
    void setStillTakesDecimalsAndFractions() {
        DragDemo drag = new DragDemo();
        DemoCommand.applySettings(drag, List.of("b=0.25", "h=1/10", "c=5e-2", "speed=+20"));
        assertEquals(0.25f, drag.getParameters().getValue("b"));
        assertEquals(0.1f, drag.getParameters().getValue("h"));
        assertEquals(0.05f, drag.getParameters().getValue("c"));
        assertEquals(20f, drag.getParameters().getValue("speed"));
    }

    /** --window took full-width and Arabic-Indic digits for pixels. */
    @ParameterizedTest
    @ValueSource(strings = {"\uff11\uff12\uff18\uff10x\uff17\uff12\uff10",
        "\u0661\u0662\u0668\u0660x\u0667\u0662\u0660", "1280x\u0667\u0662\u0660", "+1280x720"})
    void aWindowSizeHasAsciiDigitsOnly(String size) {
        UsageException refused = assertThrows(UsageException.class,
                () -> DemoCommand.parseWindow(size));
        assertTrue(refused.getMessage().startsWith("--window: must be WIDTHxHEIGHT"),
                refused.getMessage());
    }

    /**
     * m1 = 1e-30 kg against m2 = 1e30 kg, elastic, head on: sphere 1 leaves at -3 m/s (its
     * momentum changes by -4e-30 kg*m/s), and sphere 2's change +4e-60 m/s is far below the
     * resolution of -1 m/s (6e-8), so the float result loses the whole exchange. The help
     * promises momentum is conserved: one warning line says how much was lost.
     */
    @Test
    void collideWarnsWhenTheFloatVelocitiesLoseMomentum() {
        CommandRun run = CommandRun.of(collide("--m1", "1e-30", "--m2", "1e30"));
        assertEquals(0, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        // m1 is the float nearest 1e-30 (1.0000000031710769e-30), times the change of 4 m/s;
        // printed as a float, 4.0E-30.
        assertTrue(run.err.startsWith("warning: the float velocities after the impact lose"
                + " 4.0E-30 kg*m/s of momentum, 100.0% of the 4.0E-30 kg*m/s"), run.toString());
        assertEquals(2, run.outLines().size(), run.toString());
        // Masses alike: the velocities are exact in float (0 and 1 m/s swap), no warning.
        run = CommandRun.of(collide("--m1", "1", "--m2", "1"));
        assertEquals(0, run.code, run.toString());
        assertEquals("", run.err);
        // 1 kg against 1000 kg: sphere 2 changes by about 0.004 m/s, 1 in 1e4 of its speed,
        // so rounding loses about 1e-5 of the exchange, below the warning's 1e-3.
        run = CommandRun.of(collide("--m1", "1", "--m2", "1000"));
        assertEquals(0, run.code, run.toString());
        assertEquals("", run.err);
    }

    /**
     * hitscan --g 1e-45 printed drop_stepped -0.0: a subnormal g underflows in g*h. It is now
     * refused, as subnormal masses are; the smallest normal g runs and prints no -0.0.
     */
    @Test
    void hitscanRefusesASubnormalGravity() {
        CommandRun run = assertRefused("--g", "hitscan", "--distance", "100", "--speed", "100",
                "--g", "1e-45");
        assertTrue(run.err.contains(String.valueOf(Float.MIN_NORMAL)), run.toString());
        run = CommandRun.of("hitscan", "--distance", "100", "--speed", "100", "--g",
                String.valueOf(Float.MIN_NORMAL));
        assertEquals(0, run.code, run.toString());
        assertFalse(run.out.contains("-0.0"), run.toString());
    }

    private static String[] collide(String massOption, String mass, String otherOption,
            String otherMass) {
        String[] args = new String[5 + SPHERES.length];
        args[0] = CollideCommand.NAME;
        args[1] = massOption;
        args[2] = mass;
        args[3] = otherOption;
        args[4] = otherMass;
        System.arraycopy(SPHERES, 0, args, 5, SPHERES.length);
        return args;
    }

    private static CommandRun assertRefused(String named, String... args) {
        CommandRun run = CommandRun.of(args);
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals("", run.out, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.contains(named), run.toString());
        assertFalse(run.err.contains("Exception"), run.toString());
        assertFalse(run.err.contains("internal error"), run.toString());
        return run;
    }
}

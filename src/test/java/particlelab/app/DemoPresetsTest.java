package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.HelloAimingDemo;
import particlelab.lecture.IterativeAimingDemo;
import particlelab.lecture.RotationDemo;
import particlelab.lecture.TargetsDemo;
import particlelab.lecture.TennisRacketDemo;

/**
 * Issue 19, part 5: every state a slide needs is reachable before the window opens. For each
 * demo, the keys are pressed on one instance and the same state is set with
 * {@code --set NAME=VALUE} ({@link DemoCommand#applySettings}) on another; after the same
 * frames both show the same HUD text and the same parameter panel. Plain JUnit, no jME: the
 * demos' physics and HUD text run without a renderer.
 */
class DemoPresetsTest {

    /** The frame time both instances are fed (in seconds): the CI's fixed tpf. */
    private static final float TPF = 1f / 60f;
    /** Frames both instances run after the keys or the settings: 2 s, past a first impact. */
    private static final int FRAMES = 120;

    @Test
    void collisionPresetsMatchTheKey() {
        String[] names = {"glancing", "cradle", "paddle"};
        for (int presses = 1; presses <= names.length; ++presses) {
            String[] keys = new String[presses];
            Arrays.fill(keys, "P");
            assertSameState(CollisionsDemo::new, keys, "preset=" + names[presses - 1]);
        }
    }

    @Test
    void cheatSpeedMatchesTheKeys() {
        assertSameState(FastBulletsDemo::new, new String[] {"Up", "Up", "Up"}, "speed=100");
    }

    @Test
    void iterateStrategyDragInstantAndPredictorMatchTheKeys() {
        assertSameState(IterativeAimingDemo::new, new String[] {"G"}, "strategy=bisection");
        assertSameState(IterativeAimingDemo::new, new String[] {"G", "G"}, "strategy=secant");
        assertSameState(IterativeAimingDemo::new, new String[] {"L"}, "drag=quadratic");
        assertSameState(IterativeAimingDemo::new, new String[] {"I"}, "instant=on");
        assertSameState(IterativeAimingDemo::new, new String[] {"P"}, "predictor=mismatch");
    }

    @Test
    void rotationOmegaAndStepMatchTheKeys() {
        assertSameState(RotationDemo::new, new String[] {"Up"}, "omega=6");
        assertSameState(RotationDemo::new, new String[] {"Down", "Down"}, "omega=0.75");
        assertSameState(RotationDemo::new, new String[] {"Right"}, "h=1/30");
        assertSameState(RotationDemo::new, new String[] {"Left", "Left"}, "h=1/240");
    }

    @Test
    void bounceThresholdFixAndTestMatchTheKeys() {
        // Bounce starts at Box2D's threshold with the fix off: P wraps round to none.
        assertSameState(BounceDemo::new, new String[] {"P"}, "threshold=none");
        assertSameState(BounceDemo::new, new String[] {"P", "P"}, "threshold=cyclone");
        assertSameState(BounceDemo::new, new String[] {"F"}, "fix=on");
        assertSameState(BounceDemo::new, new String[] {"O"}, "detection=overlap");
    }

    @Test
    void racketMethodAndGyroscopicTermMatchTheKeys() {
        // Both rackets by default; I shows explicit Euler alone, then the midpoint alone.
        assertSameState(TennisRacketDemo::new, new String[] {"I"}, "method=explicit");
        assertSameState(TennisRacketDemo::new, new String[] {"I", "I"}, "method=midpoint");
        assertSameState(TennisRacketDemo::new, new String[] {"G"}, "gyro=off");
    }

    @Test
    void helloAimingAimsFiredMatchTheKeys() {
        // Both aims by default; L fires the lecture's alone, then the correction alone, then
        // both with the student's (the last choice, issue 31 §3).
        assertSameState(HelloAimingDemo::new, new String[] {"L"}, "aim=lecture");
        assertSameState(HelloAimingDemo::new, new String[] {"L", "L"}, "aim=discrete");
        assertSameState(HelloAimingDemo::new, new String[] {"L", "L", "L"}, "aim=student");
    }

    @Test
    void targetsAimAndPaneMatchTheKeys() {
        assertSameState(TargetsDemo::new, new String[] {"Up", "Up"}, "angle=40");
        assertSameState(TargetsDemo::new, new String[] {"Down"}, "angle=32.5");
        assertSameState(TargetsDemo::new, new String[] {"G"}, "pane=solid");
    }

    @Test
    void aWrongNameForAChoiceIsOneLineListingTheNames() {
        CommandRun run = CommandRun.of("demo", "collisions", "--set", "preset=sideways");
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        String line = run.errLines().get(0);
        assertTrue(line.startsWith("particle-lab demo: --set preset=sideways: sideways is not"
                + " one of the names of preset;"), line);
        assertTrue(line.contains("preset (collision preset) one of"
                + " head-on|glancing|cradle|paddle"), line);
        assertEquals("", run.out);
    }

    @Test
    void aNumberForAChoiceIsRefusedWithItsNames() {
        CommandRun run = CommandRun.of("demo", "iterate", "--set", "strategy=1");
        assertEquals(Program.USAGE, run.code, run.toString());
        assertTrue(run.err.contains("strategy (aiming strategy) one of"
                + " lecture|bisection|secant|believable"), run.toString());
        assertTrue(run.err.contains("instant (instant mode) one of off|on"), run.toString());
    }

    @Test
    void theHelpNamesEveryDemosChoices() {
        CommandRun run = CommandRun.of("demo", "--help");
        assertEquals(Program.OK, run.code, run.toString());
        String help = run.out.replaceAll("\\s+", " ");
        for (String named : new String[] {"preset=head-on|glancing|cradle|paddle",
            "strategy=lecture|bisection|secant|believable", "drag=linear|quadratic",
            "threshold=none|cyclone|box2d", "detection=swept|overlap",
            "method=explicit|midpoint|both", "aim=lecture|discrete|both", "speed=35|50|70"}) {
            assertTrue(help.contains(named), named + " in " + help);
        }
    }

    /**
     * Press keys on one new demo and give settings to another, run both the same frames, and
     * compare their HUD text and panel; the state must also differ from the default's, so a
     * key or a setting that did nothing fails.
     */
    private static void assertSameState(Supplier<DemoState> create, String[] keys,
            String... settings) {
        DemoState pressed = create.get();
        for (String key : keys) {
            press(pressed, key);
        }
        DemoState set = create.get();
        DemoCommand.applySettings(set, List.of(settings));
        DemoState untouched = create.get();
        String what = Arrays.toString(keys) + " vs " + Arrays.toString(settings);
        String expected = run(pressed);
        assertEquals(expected, run(set), what);
        assertEquals(panel(pressed), panel(set), what);
        assertNotEquals(panel(untouched), panel(set), what + ": the setting changed nothing");
        assertNotEquals(run(untouched), expected, what + ": the keys changed nothing");
    }

    /** Run the demo's physics for the frames and return its HUD text. */
    private static String run(DemoState demo) {
        for (int i = 0; i < FRAMES; ++i) {
            demo.getRun().advancePhysics(TPF);
        }
        return demo.getWindow().formatHud(new StringBuilder()).toString();
    }

    private static String panel(DemoState demo) {
        return demo.getParameters().formatPanel(new StringBuilder()).toString();
    }

    /**
     * Press the key with this label, as the window does: the demo's own, which come after the
     * shared controls (a demo's F is not the shared one).
     */
    private static void press(DemoState demo, String label) {
        List<KeyBinding> bindings = demo.getKeys().getBindings();
        for (int b = bindings.size() - 1; b >= 0; --b) {
            KeyBinding binding = bindings.get(b);
            for (int i = 0; i < binding.countKeys(); ++i) {
                if (binding.getKeyLabel(i).equals(label)) {
                    binding.press(i);
                    return;
                }
            }
        }
        throw new AssertionError(demo.getTitle() + " has no key " + label);
    }
}

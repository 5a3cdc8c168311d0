package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoRun;
import particlelab.demo.DemoState;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.DragDemo;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;

/**
 * {@code particle-lab demo NAME --set NAME=VALUE}: a bad setting is one line and exit 2,
 * before any window; a good one is the value the scene starts with.
 */
class DemoSetOptionTest {

    @Test
    void outOfRangeValueIsOneLineWithEveryRangeAndExitTwo() {
        CommandRun run = CommandRun.of("demo", "drag", "--set", "b=7");
        assertEquals(Program.USAGE, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        String line = run.errLines().get(0);
        assertTrue(line.startsWith("particle-lab demo: --set b=7: b = 7.0 is out of range;"
                + " the parameters are h (fixed step) from 1/240 s to 1/5 s"), line);
        assertTrue(line.contains("b (linear drag) from 0.00 N s/m to 5.00 N s/m"), line);
        assertTrue(line.contains("c (quadratic drag) from 0.000 kg/m to 0.500 kg/m"), line);
        assertEquals("", run.out);
    }

    @Test
    void unknownNameAndBadValueAreOneLineEach() {
        for (String setting : new String[] {"q=1", "b", "b=fast", "h=1/0", "b=NaN"}) {
            CommandRun run = CommandRun.of("demo", "drag", "--set", setting);
            assertEquals(Program.USAGE, run.code, run.toString());
            assertEquals(1, run.errLines().size(), run.toString());
            assertTrue(run.err.contains("the parameters are h (fixed step)"), run.toString());
        }
    }

    @Test
    void anUnknownNameIsNamedWhateverItsValue() {
        for (String setting : new String[] {"preset=x", "preset=1"}) {
            CommandRun run = CommandRun.of("demo", "drag", "--set", setting);
            assertEquals(Program.USAGE, run.code, run.toString());
            assertEquals(1, run.errLines().size(), run.toString());
            assertTrue(run.err.contains("--set " + setting + ": no parameter named preset;"),
                    run.toString());
        }
    }

    /**
     * Every {@code --set} reaches the physics, not only the first: a setter that restarts
     * the scene must not write its own copies of the other parameters back over those still
     * waiting. Read back from the ground response the lanes share.
     */
    @Test
    void bounceTakesEverySettingAndEAsGiven() {
        BounceDemo bounce = new BounceDemo();
        DemoCommand.applySettings(bounce, List.of("e=0.8", "threshold=cyclone", "fix=on",
                "detection=overlap"));
        bounce.getWorld();
        assertEquals(0.8f, bounce.getRestitution());
        assertEquals(ImpulseResponse.CYCLONE_THRESHOLD, bounce.getThresholdSpeed());
        assertTrue(bounce.isRestingFix());
        assertEquals(Detection.OVERLAP, bounce.getDetection());
        BounceDemo quarter = new BounceDemo();
        DemoCommand.applySettings(quarter, List.of("threshold=none", "e=0.75"));
        quarter.getWorld();
        assertEquals(0.75f, quarter.getRestitution(), "e is not rounded to tenths");
        assertEquals(0f, quarter.getThresholdSpeed());
        // live, after the start: 0.33 stays 0.33
        quarter.getParameters().set("e", 0.33f);
        assertEquals(0.33f, quarter.getRestitution());
        CollisionsDemo collisions = new CollisionsDemo();
        DemoCommand.applySettings(collisions, List.of("e=0.75", "preset=glancing"));
        collisions.getWorld();
        assertEquals(0.75f, collisions.getRestitution());
    }

    @Test
    void settingsAreRepeatableAndTakeFractions() throws Exception {
        DemoState drag = new DragDemo();
        DemoCommand.applySettings(drag, List.of("b=0.3", "h=1/10", "speed=20", "b=0.5"));
        assertEquals(0.5f, drag.getParameters().getValue("b"));
        assertEquals(0.1f, drag.getParameters().getValue("h"));
        assertEquals(20f, drag.getParameters().getValue("speed"));
        assertThrows(UsageException.class,
                () -> DemoCommand.applySettings(drag, List.of("angle=90")));
    }

    /**
     * The values a window's scene starts with: the settings are applied before the scene is
     * declared, as the demo command does; the scene, declared without jME (plain JUnit) as a
     * window's start declares it, takes them.
     */
    @Test
    void setValuesAreWhatTheSceneStartsWith() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        DemoState drag = demos.get(DemoCatalog.indexOf("drag"));
        DemoCommand.applySettings(drag, List.of("b=0.3", "h=1/10", "speed=20", "angle=30"));
        // The scene declared, as a window's start does first.
        DemoRun run = drag.getRun();
        assertEquals(0.1f, run.getClock().getStepSeconds());
        String integrator = run.getParticles().get(1).getIntegrator().describe();
        assertTrue(integrator.contains("0.3"), integrator);
        // 20·(cos 30°, sin 30°), computed in double and rounded to float once.
        Vector3f expected = new Vector3f((float) (20.0 * Math.cos(Math.toRadians(30f))),
                (float) (20.0 * Math.sin(Math.toRadians(30f))), 0f);
        assertEquals(expected, run.getParticles().get(0).copyLaunchVelocity(new Vector3f()));
        assertEquals(expected, run.getParticles().get(0).getParticle().velocity);
    }
}

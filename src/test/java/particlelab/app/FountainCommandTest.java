package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.system.JmeContext;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.lecture.FountainDemo;

/**
 * {@code demo fountain --particles N} and {@code demo NAME --profile}: the options are checked
 * before any window opens, and the profile line has the exact format.
 */
class FountainCommandTest {

    private static final float FRAME_SECONDS = 1f / 60f;
    private static final long TIMEOUT_SECONDS = 60;
    /** The line: {@code physics_ms_mean=X physics_ms_max=Y particles=P frames=N}. */
    private static final Pattern PROFILE = Pattern.compile("physics_ms_mean=(\\d+\\.\\d{3})"
            + " physics_ms_max=(\\d+\\.\\d{3}) particles=(\\d+) frames=(\\d+)");

    @Test
    void aParticleCountOutsideOneToAMillionIsOneLineAndExitTwo() {
        for (String bad : new String[] {"0", "-3", "1000001", "many", "1e5"}) {
            CommandRun run = CommandRun.of("demo", "fountain", "--particles", bad);
            assertEquals(2, run.code, run.toString());
            assertEquals(List.of("particle-lab demo: --particles: must be a whole number from 1"
                    + " to 1000000, but was " + bad), run.errLines(), run.toString());
            assertEquals("", run.out);
        }
    }

    @Test
    void aParticleCountForAnotherDemoIsRefused() {
        CommandRun run = CommandRun.of("demo", "drag", "--particles", "1000");
        assertEquals(2, run.code, run.toString());
        assertEquals(1, run.errLines().size(), run.toString());
        assertTrue(run.err.startsWith("particle-lab demo: --particles: only the demo fountain"
                + " has a particle count"), run.toString());
    }

    @Test
    void theHelpListsBothOptions() {
        CommandRun run = CommandRun.of("demo", "--help");
        assertEquals(0, run.code, run.toString());
        assertTrue(run.out.contains("--particles N"), run.out);
        assertTrue(run.out.contains("--profile"), run.out);
    }

    /**
     * What {@code demo fountain --frames 30 --fixed-tpf H --profile --particles 2000} does
     * after its window closes, run in jME's headless context (no display): the line counts
     * the 30 frames the demo ran and the 2000 particles each step moved.
     */
    @Test
    void theProfileLineCountsTheFramesAndParticlesOfTheRun() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        int index = DemoCatalog.indexOf("fountain");
        FountainDemo fountain = (FountainDemo) demos.get(index);
        fountain.setParticleCount(2000);
        ParticleLabApp app = new ParticleLabApp(demos, index, 30, null, FRAME_SECONDS);
        app.start(JmeContext.Type.Headless);
        try {
            assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "the app did not stop");
        } finally {
            app.stop(true);
        }
        String line = DemoCommand.profileLine(fountain);
        Matcher matcher = PROFILE.matcher(line);
        assertTrue(matcher.matches(), line);
        assertTrue(Double.parseDouble(matcher.group(1)) <= Double.parseDouble(matcher.group(2)),
                line);
        assertEquals("2000", matcher.group(3), line);
        assertEquals("30", matcher.group(4), line);
        // the frames measured are the frames simulated: one step of 1/60 s each
        assertEquals(30 * FRAME_SECONDS, fountain.getClock().getSimulatedSeconds(), 1e-5);
    }

    @Test
    void everyOtherDemoProfilesItsWorldsBodies() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        int index = DemoCatalog.indexOf("drag");
        ParticleLabApp app = new ParticleLabApp(demos, index, 5, null, FRAME_SECONDS);
        app.start(JmeContext.Type.Headless);
        try {
            assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "the app did not stop");
        } finally {
            app.stop(true);
        }
        Matcher matcher = PROFILE.matcher(DemoCommand.profileLine(demos.get(index)));
        assertTrue(matcher.matches());
        // the drag demo's three spheres
        assertEquals("3", matcher.group(3));
        assertEquals("5", matcher.group(4));
    }
}

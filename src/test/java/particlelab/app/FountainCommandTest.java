package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.system.JmeContext;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.demo.FrameTimes;
import particlelab.lecture.FountainDemo;

/**
 * {@code demo fountain --particles N} and {@code demo NAME --profile}: the options are checked
 * before any window opens, and the profile line has the exact format.
 */
class FountainCommandTest {

    private static final float FRAME_SECONDS = 1f / 60f;
    private static final long TIMEOUT_SECONDS = 60;
    /**
     * The line: {@code physics_ms_mean=X physics_ms_max=Y particles=P frames=N
     * frame_share_pct=S}, the fountain's with {@code mesh_ms_mean=M mesh_ms_max=K}.
     */
    private static final Pattern PROFILE = Pattern.compile("physics_ms_mean=(\\d+\\.\\d{3})"
            + " physics_ms_max=(\\d+\\.\\d{3}) particles=(\\d+) frames=(\\d+)"
            + " frame_share_pct=(\\d+\\.\\d)( mesh_ms_mean=(\\d+\\.\\d{3})"
            + " mesh_ms_max=(\\d+\\.\\d{3}))?");

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
        // the share is the mean's, of a 16.7 ms frame, to the line's own rounding
        assertEquals(100.0 * Double.parseDouble(matcher.group(1)) / (1000.0 / 60.0),
                Double.parseDouble(matcher.group(5)), 0.05 + 1e-9, line);
        // the fountain's mesh update was timed too (its frames ran with a renderer)
        assertTrue(matcher.group(6) != null, line);
        assertTrue(Double.parseDouble(matcher.group(7)) <= Double.parseDouble(matcher.group(8)),
                line);
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
        // the drag demo's three spheres and the comparison lane's (a body of the world even
        // while the lane is off, parked)
        assertEquals("4", matcher.group(3));
        assertEquals("5", matcher.group(4));
        // no mesh of points: no mesh figures
        assertEquals(null, matcher.group(6));
    }

    /**
     * The line from fake times: 3 frames of physics at 2.5, 2.6 and 2.7 ms (mean 2.6 ms, 15.6 %
     * of 16.667 ms) and of a mesh update at 1.0, 1.1 and 1.2 ms, for 10^6 particles.
     */
    @Test
    void theProfileLineHasTheShareOfTheFrameAndTheMeshTimes() {
        FrameTimes physics = new FrameTimes();
        FrameTimes mesh = new FrameTimes();
        for (int k = 0; k < 3; ++k) {
            physics.record(2_500_000L + 100_000L * k);
            mesh.record(1_000_000L + 100_000L * k);
        }
        assertEquals("physics_ms_mean=2.600 physics_ms_max=2.700 particles=1000000 frames=3"
                + " frame_share_pct=15.6 mesh_ms_mean=1.100 mesh_ms_max=1.200",
                DemoCommand.profileLine(physics, mesh, 1_000_000));
        assertEquals("physics_ms_mean=2.600 physics_ms_max=2.700 particles=3 frames=3"
                + " frame_share_pct=15.6", DemoCommand.profileLine(physics, null, 3));
    }
}

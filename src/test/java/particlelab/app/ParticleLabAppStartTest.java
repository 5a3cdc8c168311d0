package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.system.JmeContext;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import particlelab.demo.DemoState;

/**
 * What the window does first: the frames it counts; and that the export without a window,
 * which runs the same frames with no application at all, writes what the headless
 * application wrote.
 */
class ParticleLabAppStartTest {

    private static final float FRAME_SECONDS = 1f / 60f;
    private static final long TIMEOUT_SECONDS = 30;

    /**
     * {@code --frames 1 --screenshot} once saved a blank picture: frame 1 was counted (and
     * captured) before the demo had initialised. Now the one counted frame is one in which the
     * demo ran: its clock has taken its step of 1/60 s.
     */
    @Test
    void theFirstCountedFrameIsOneInWhichTheDemoRan() throws Exception {
        List<DemoState> demos = DemoCatalog.createAll();
        ParticleLabApp app = new ParticleLabApp(demos, 2, 1, null, FRAME_SECONDS);
        app.start(JmeContext.Type.Headless);
        try {
            assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "the app did not stop");
        } finally {
            app.stop(true);
        }
        assertEquals(1, app.countFrames());
        // one fixed step of 1/60 s per frame of 1/60 s
        assertEquals(FRAME_SECONDS, demos.get(2).getClock().getSimulatedSeconds(), 1e-6);
    }

    /**
     * {@code demo NAME --frames N --fixed-tpf H --export DIR} once ran the demo in jME's
     * headless application; now it runs the frames with no application
     * ({@link ExportRun#runFrames}). Both write the same files, byte for byte, for demos whose
     * frames do more than step: a relabelled shot (iterate, height), a new round once a frame
     * (targets), the demo's own tables (rotation), sounds and a graph (bounce), impulses
     * (collisions), a slide-code bullet (aiming), the plain flight (pull).
     */
    @Test
    void theExportWithoutAnApplicationWritesWhatTheHeadlessApplicationWrote(
            @TempDir Path folder) throws Exception {
        int frames = 150;
        for (String name : new String[] {"pull", "aiming", "iterate", "height", "bounce",
            "collisions", "targets", "rotation"}) {
            int index = DemoCatalog.indexOf(name);
            Path before = Files.createDirectories(folder.resolve(name + "-app"));
            List<DemoState> demos = DemoCatalog.createAll();
            ParticleLabApp app = new ParticleLabApp(demos, index, frames, null, FRAME_SECONDS);
            app.start(JmeContext.Type.Headless);
            try {
                assertTrue(app.awaitFinished(TIMEOUT_SECONDS), "the app did not stop");
            } finally {
                app.stop(true);
            }
            ByteArrayOutputStream sink = new ByteArrayOutputStream();
            PrintStream out = new PrintStream(sink, true, StandardCharsets.UTF_8);
            assertEquals(Program.OK, ExportRun.write(demos.get(index), before, false, out, out),
                    name + ": " + sink);
            Path after = Files.createDirectories(folder.resolve(name + "-run"));
            List<DemoState> fresh = DemoCatalog.createAll();
            assertEquals(Program.OK, ExportRun.runHeadless(fresh, index, frames, FRAME_SECONDS,
                    after, false, false, out, out), name + ": " + sink);
            assertFalse(fresh.get(index).isInitialized(), name + ": no application ran it");
            List<String> files = list(before);
            assertEquals(files, list(after), name);
            assertTrue(files.size() >= 2, name + ": " + files);
            for (String file : files) {
                assertEquals(new String(Files.readAllBytes(before.resolve(file)),
                        StandardCharsets.UTF_8), new String(Files.readAllBytes(
                                after.resolve(file)), StandardCharsets.UTF_8), name + ": " + file);
            }
        }
    }

    private static List<String> list(Path folder) throws IOException {
        List<String> names = new ArrayList<>();
        try (Stream<Path> entries = Files.list(folder)) {
            entries.forEach(entry -> names.add(entry.getFileName().toString()));
        }
        names.sort(null);
        return names;
    }
}

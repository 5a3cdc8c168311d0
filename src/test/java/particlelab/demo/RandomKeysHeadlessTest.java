package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;

/**
 * Issue 17: about 250 random keys on an 800x450 window killed the app (the body's band grew
 * with every line the keys added and never gave the room back, until the scene had none).
 * Here every catalogue demo, in a real headless jME application with the camera at 800x450,
 * takes a few hundred presses of its own keys (the shared controls and the demo's), drawn
 * from a seeded random sequence so every run presses the same ones, with frames of a fixed
 * 1/60 s between: nothing throws, and the scene, the panel and the graph still have their
 * rectangles inside the window at the end.
 */
class RandomKeysHeadlessTest {

    private static final float H = 1f / 60f;
    /** The keys: how many per demo, the frames after each, and the seed. */
    private static final int KEY_PRESSES = 300;
    private static final int FRAMES_PER_KEY = 2;
    private static final long SEED = 17L;
    private static final int WIDTH = 800;
    private static final int HEIGHT = 450;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @BeforeAll
    static void startApp() throws Exception {
        harness.call(() -> {
            harness.app().getCamera().resize(WIDTH, HEIGHT, true);
            return true;
        });
    }

    @Test
    void hundredsOfRandomKeysOnASmallWindowLeaveEveryDemoRunningAndLaidOut() throws Exception {
        List<String> problems = new ArrayList<>();
        for (DemoState demo : harness.app().getSwitcher().getDemos()) {
            problems.addAll(harness.call(() -> pressRandomKeys(demo)));
        }
        assertEquals(List.of(), problems);
    }

    /** Press a demo's own keys at random, seeded, with frames between; check at the end. */
    private static List<String> pressRandomKeys(DemoState demo) {
        List<String> problems = new ArrayList<>();
        Random random = new Random(SEED);
        List<KeyBinding> bindings = demo.getKeys().getBindings();
        String where = demo.getTitle() + " " + WIDTH + "x" + HEIGHT + " ";
        demo.getDemoHud().layOut(WIDTH, HEIGHT);
        int press = 0;
        try {
            for (; press < KEY_PRESSES; ++press) {
                KeyBinding binding = bindings.get(random.nextInt(bindings.size()));
                binding.press(random.nextInt(binding.countKeys()));
                for (int frame = 0; frame < FRAMES_PER_KEY; ++frame) {
                    demo.update(H);
                }
            }
            problems.addAll(SmallWindowHeadlessTest.checkViews(demo, WIDTH, HEIGHT,
                    demo.getParameterControls().isPanelVisible(),
                    demo.getExactGhosts().isGraphVisible(), where + "after the keys"));
        } catch (RuntimeException e) {
            problems.add(where + "press " + press + ": " + e);
        }
        return problems;
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.input.MouseInput;
import com.jme3.input.RawInputListener;
import com.jme3.input.event.MouseButtonEvent;
import com.jme3.input.event.MouseMotionEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.DemoCatalog;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;

/**
 * Issue 36: a careless user's input (keys, mouse drags, resizes, F2 and F8 in any order)
 * ended the window. Here every catalogue demo, in a real headless application, takes a seeded
 * random sequence of actions: its own and the application's keys (but E, which writes files,
 * and F11, which needs a display), resizes from 200x150 to 3840x2160, mouse drags, the panel
 * (F2) and presentation mode (F8), with whole frames of jME's loop between. Nothing may
 * throw, and the HUD shows no NaN or infinity. On a failure the message names the seed and
 * the actions up to it.
 *
 * <p>The budget is short in CI; the environment variable {@value #ACTIONS_VARIABLE} sets the
 * actions per demo for a long run (docs/testing.md).
 */
class RandomInputHeadlessTest {

    /** The environment variable that sets the actions per demo. */
    static final String ACTIONS_VARIABLE = "PARTICLELAB_RANDOM_ACTIONS";
    /** The actions per demo in CI: a few seconds in all on an idle machine. */
    private static final int DEFAULT_ACTIONS = 12;
    private static final long SEED = 36L;
    /** Actions per call on jME's thread, well within the harness's wait. */
    private static final int ACTIONS_PER_CALL = 4;
    private static final int FRAMES_PER_ACTION = 2;
    private static final int MIN_WIDTH = 200;
    private static final int MIN_HEIGHT = 150;
    private static final int MAX_WIDTH = 3840;
    private static final int MAX_HEIGHT = 2160;
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> DemoCatalog.createAll());

    @Test
    void everyDemoSurvivesASeededRandomSequenceOfInput() throws Exception {
        String budget = System.getenv(ACTIONS_VARIABLE);
        int actions = budget == null ? DEFAULT_ACTIONS : parseActions(budget);
        ParticleLabApp app = harness.app();
        List<String> problems = new ArrayList<>();
        int count = app.getSwitcher().getDemos().size();
        for (int index = 0; index < count && problems.isEmpty(); ++index) {
            int chosen = index;
            Random random = new Random(SEED + index);
            List<String> done = new ArrayList<>();
            harness.call(() -> {
                app.getSwitcher().select(chosen);
                return true;
            });
            harness.awaitFrames(FRAMES_PER_ACTION);
            for (int first = 0; first < actions && problems.isEmpty();
                    first += ACTIONS_PER_CALL) {
                int last = Math.min(actions, first + ACTIONS_PER_CALL);
                int from = first;
                String problem = harness.call(() -> act(random, from, last, done));
                if (!problem.isEmpty()) {
                    problems.add("seed " + (SEED + chosen) + ", demo " + chosen + ": "
                            + problem + "\nafter " + done);
                }
            }
        }
        harness.call(() -> {
            app.getWindowControls().setPresenting(false);
            app.reshape(ParticleLabApp.WIDTH, ParticleLabApp.HEIGHT);
            return true;
        });
        assertEquals(List.of(), problems);
    }

    /** Run actions [from, to) of the sequence; return "" or what went wrong. */
    private static String act(Random random, int from, int to, List<String> done) {
        ParticleLabApp app = harness.app();
        for (int action = from; action < to; ++action) {
            DemoState demo = app.getSwitcher().getSelected();
            String what;
            int kind = random.nextInt(10);
            if (kind < 5) {
                List<KeyBinding> keys = new ArrayList<>(demo.getBindings());
                keys.addAll(app.getSwitcher().getBindings());
                KeyBinding key = keys.get(random.nextInt(keys.size()));
                int which = random.nextInt(key.countKeys());
                what = "key " + key.getKeyLabel(which);
                if (!key.getKeyLabel(which).equals("E")
                        && !key.getKeyLabel(which).equals("F11")) {
                    key.press(which);
                }
            } else if (kind < 7) {
                int width = MIN_WIDTH + random.nextInt(MAX_WIDTH - MIN_WIDTH + 1);
                int height = MIN_HEIGHT + random.nextInt(MAX_HEIGHT - MIN_HEIGHT + 1);
                what = "resize " + width + "x" + height;
                app.reshape(width, height);
            } else if (kind < 8) {
                int width = app.getCamera().getWidth();
                int height = app.getCamera().getHeight();
                int x = random.nextInt(width);
                int y = random.nextInt(height);
                int toX = random.nextInt(width);
                int toY = random.nextInt(height);
                what = "drag " + x + "," + y + " to " + toX + "," + toY;
                // The mouse's picking (app.PickInput, not visible here) as jME feeds it.
                RawInputListener mouse = (RawInputListener) app.getStateManager()
                        .getState(pickInputClass());
                mouse.onMouseButtonEvent(new MouseButtonEvent(MouseInput.BUTTON_LEFT, true,
                        x, y));
                mouse.onMouseMotionEvent(new MouseMotionEvent(toX, toY, toX - x, toY - y, 0,
                        0));
                mouse.onMouseButtonEvent(new MouseButtonEvent(MouseInput.BUTTON_LEFT, false,
                        toX, toY));
            } else if (kind < 9) {
                what = "F8";
                app.getWindowControls().setPresenting(!app.getWindowControls().isPresenting());
            } else {
                what = "F2";
                HeadlessHarness.press(demo, "F2");
            }
            done.add(what);
            try {
                for (int frame = 0; frame < FRAMES_PER_ACTION; ++frame) {
                    SmallPanelHeadlessTest.frame(app);
                }
            } catch (RuntimeException e) {
                return what + ": " + e;
            }
            if (app.getRecovered() != null) {
                return what + ": " + app.getRecovered();
            }
            String hud = app.getSwitcher().getSelected().getHud().getBodyText();
            if (hud.contains("NaN") || hud.contains("Infinity")) {
                return what + ": the HUD shows " + hud;
            }
        }
        return "";
    }

    private static int parseActions(String budget) {
        try {
            int actions = Integer.parseInt(budget.trim());
            if (actions > 0) {
                return actions;
            }
        } catch (NumberFormatException e) {
            // Refused below, with the value.
        }
        throw new IllegalArgumentException(ACTIONS_VARIABLE + " must be a whole number > 0,"
                + " but was \"" + budget + "\"");
    }

    @SuppressWarnings("unchecked")
    private static Class<com.jme3.app.state.AppState> pickInputClass() {
        try {
            return (Class<com.jme3.app.state.AppState>) Class.forName(
                    "particlelab.app.PickInput");
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(e);
        }
    }
}

package particlelab.app;

import com.jme3.input.InputManager;
import com.jme3.scene.Node;
import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import java.lang.reflect.Field;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import particlelab.demo.DemoState;

/**
 * A real {@link ParticleLabApp} in jME's headless context, for tests. Its timer reports a
 * frame time of 0, so jME's own loop never advances a simulation: tests drive the demos
 * themselves, with a fixed tpf, inside {@link #call} (on the jME thread), and get the same
 * numbers on every run.
 */
public final class HeadlessHarness implements AutoCloseable {

    private static final long TIMEOUT_SECONDS = 30;
    /** The headless loop's frame rate cap, so it does not spin a core. */
    private static final int FRAME_RATE = 60;

    private final ParticleLabApp app;

    private HeadlessHarness(ParticleLabApp app) {
        this.app = app;
    }

    /**
     * Start the application on the catalogue's demos and wait until they are initialised.
     *
     * @param demos the demos (not null)
     * @return the running harness (not null)
     * @throws Exception if it does not start
     */
    public static HeadlessHarness start(List<DemoState> demos) throws Exception {
        ParticleLabApp app = new ParticleLabApp(demos, 0, 0, null, 0f);
        AppSettings settings = ParticleLabApp.createSettings(0f);
        settings.setFrameRate(FRAME_RATE);
        app.setSettings(settings);
        app.start(JmeContext.Type.Headless);
        HeadlessHarness harness = new HeadlessHarness(app);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_SECONDS);
        while (!harness.call(() -> allInitialized(app))) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("demos not initialised in time");
            }
            Thread.sleep(10);
        }
        return harness;
    }

    /**
     * Access the application.
     *
     * @return the live app (not null)
     */
    public ParticleLabApp app() {
        return app;
    }

    /**
     * Run code on the jME thread and wait for its result.
     *
     * @param <T> the result type
     * @param task the code (not null)
     * @return its result
     * @throws Exception if it throws or times out
     */
    public <T> T call(Callable<T> task) throws Exception {
        return app.enqueue(task).get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
    }

    /**
     * Let jME's loop run a few frames (state switches happen in a frame's update).
     *
     * @param frames how many (&ge;1)
     * @throws Exception if the app stopped
     */
    public void awaitFrames(int frames) throws Exception {
        int target = call(app::countFrames) + frames;
        while (call(app::countFrames) < target) {
            Thread.sleep(5);
        }
    }

    /**
     * Count the scene and GUI children, input mappings and listeners: what a demo must
     * leave behind unchanged when it is disabled. Call on the jME thread.
     *
     * @param app the application (not null)
     * @return {rootChildren, guiChildren, mappings, listeners}
     */
    public static int[] countLeftovers(ParticleLabApp app) {
        Node root = (Node) app.getViewPort().getScenes().get(0);
        Node gui = (Node) app.getGuiViewPort().getScenes().get(0);
        InputManager input = app.getInputManager();
        Map<?, ?> mappings = (Map<?, ?>) read(input, "mappings");
        int listeners = 0;
        for (Object mapping : mappings.values()) {
            listeners += ((List<?>) read(mapping, "listeners")).size();
        }
        return new int[] {root.getQuantity(), gui.getQuantity(), mappings.size(), listeners};
    }

    @Override
    public void close() {
        app.stop(true);
    }

    private static boolean allInitialized(ParticleLabApp app) {
        List<DemoState> demos = app.getSwitcher().getDemos();
        for (DemoState demo : demos) {
            if (!demo.isInitialized()) {
                return false;
            }
        }
        return app.getSwitcher().getSelected().isEnabled();
    }

    private static Object read(Object owner, String fieldName) {
        try {
            Field field = owner.getClass().getDeclaredField(fieldName);
            field.setAccessible(true);
            return field.get(owner);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot read jME's " + fieldName, e);
        }
    }
}

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
import java.util.function.Supplier;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.physics.SimulationClock;

/**
 * A real {@link ParticleLabApp} in jME's headless context, for tests. Its timer reports a
 * frame time of 0, so jME's own loop never advances a simulation: tests drive the demos
 * themselves, with a fixed tpf, inside {@link #call} (on the jME thread), and get the same
 * numbers on every run.
 *
 * <p>One application for a whole test class is a JUnit extension, started before the class's
 * {@code @BeforeAll} methods and stopped after its {@code @AfterAll} ones:
 * <pre>{@code
 * @RegisterExtension
 * static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(drag));
 * }</pre>
 * One for a single test: {@code try (HeadlessHarness harness = HeadlessHarness.start(...))}.
 */
public final class HeadlessHarness implements AutoCloseable, BeforeAllCallback,
        AfterAllCallback {

    private static final long TIMEOUT_SECONDS = 30;
    /** The headless loop's frame rate cap, so it does not spin a core. */
    private static final int FRAME_RATE = 60;

    /** Makes the demos when the class starts (null: started at once, by {@link #start}). */
    private final Supplier<List<DemoState>> demos;
    /** The running application (null before the class starts). */
    private ParticleLabApp app;

    private HeadlessHarness(Supplier<List<DemoState>> demos) {
        this.demos = demos;
    }

    /**
     * Prepare an application for a test class, registered with {@code @RegisterExtension} on
     * a static field: it starts on the demos before the class's tests and stops after them.
     *
     * @param demos makes the demos, called once when the class starts (not null)
     * @return the harness, not started yet (not null)
     */
    public static HeadlessHarness perClass(Supplier<List<DemoState>> demos) {
        if (demos == null) {
            throw new IllegalArgumentException("the demos' supplier must not be null");
        }
        return new HeadlessHarness(demos);
    }

    /**
     * Start the application on the catalogue's demos and wait until they are initialised.
     *
     * @param demos the demos (not null)
     * @return the running harness (not null)
     * @throws Exception if it does not start
     */
    public static HeadlessHarness start(List<DemoState> demos) throws Exception {
        HeadlessHarness harness = new HeadlessHarness(null);
        harness.launch(demos);
        return harness;
    }

    /**
     * Access the application.
     *
     * @return the live app (not null)
     */
    public ParticleLabApp app() {
        if (app == null) {
            throw new IllegalStateException("the headless application has not started");
        }
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
        return app().enqueue(task).get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
    }

    /**
     * Let jME's loop run a few frames (state switches happen in a frame's update).
     *
     * @param frames how many (&ge;1)
     * @throws Exception if the app stopped
     */
    public void awaitFrames(int frames) throws Exception {
        int target = call(app()::countFrames) + frames;
        while (call(app()::countFrames) < target) {
            Thread.sleep(5);
        }
    }

    /**
     * Run frames of a demo at a fixed tpf, in fixed-step mode with the clock running. Call on
     * the jME thread.
     *
     * @param demo the demo (attached, not null)
     * @param frames how many (&ge;0)
     * @param tpf each frame's time (in seconds, &ge;0)
     */
    public static void fly(DemoState demo, int frames, float tpf) {
        demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
        demo.getClock().setPaused(false);
        for (int i = 0; i < frames; ++i) {
            demo.update(tpf);
        }
    }

    /**
     * Press the first key of a demo's binding shown with a label, as a key press does.
     *
     * @param demo the demo (not null)
     * @param keyLabel the label the help shows, e.g. {@code "F2"} (not null)
     * @throws IllegalStateException if no binding has that label
     */
    public static void press(DemoState demo, String keyLabel) {
        for (KeyBinding binding : demo.getKeys().getBindings()) {
            if (keyLabel.equals(binding.getKeyLabel())) {
                binding.press(0);
                return;
            }
        }
        throw new IllegalStateException(demo.getTitle() + " has no " + keyLabel);
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
    public void beforeAll(ExtensionContext context) throws Exception {
        if (demos == null || app != null) {
            throw new IllegalStateException("register a harness made by perClass, once");
        }
        launch(demos.get());
    }

    @Override
    public void afterAll(ExtensionContext context) {
        close();
    }

    @Override
    public void close() {
        if (app != null) {
            // After a failure the jME thread has ended: waiting for it to stop would hang.
            if (app.getFailure() == null) {
                app.stop(true);
            }
            app = null;
        }
    }

    /** Start the application on the demos and wait until they are initialised. */
    private void launch(List<DemoState> demoStates) throws Exception {
        ParticleLabApp started = new ParticleLabApp(demoStates, 0, 0, null, 0f);
        AppSettings settings = ParticleLabApp.createSettings(0f);
        settings.setFrameRate(FRAME_RATE);
        started.setSettings(settings);
        started.start(JmeContext.Type.Headless);
        app = started;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_SECONDS);
        while (!call(() -> allInitialized(started))) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("demos not initialised in time");
            }
            Thread.sleep(10);
        }
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

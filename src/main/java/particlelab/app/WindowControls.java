package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.KeyInput;
import com.jme3.renderer.Camera;
import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import java.util.List;
import org.lwjgl.glfw.GLFW;
import org.lwjgl.glfw.GLFWVidMode;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.view.HudScale;

/**
 * The window for a lecture hall: keeps the shown demo laid out for the window's size and the
 * user's HUD factor, and owns the keys that change them, F11 fullscreen and {@code [ ]} the
 * HUD's size. The window is resizable; each frame the demo on screen is laid out again if the
 * window's size (the camera's, which jME resizes on every reshape) or the factor differs
 * from its last layout, so a resize, a switch to a demo laid out for another size, and the
 * keys all take effect on the next frame, outside jME's input and reshape callbacks.
 *
 * <p>Fullscreen: jME's way, new settings and {@link Application#restart()}, which recreates
 * the window and its OpenGL context and keeps every AppState, so the demos carry on where
 * they were. Fullscreen takes the primary monitor's current video mode; leaving it restores
 * the last windowed size.
 */
public final class WindowControls extends BaseAppState {

    private final DemoSwitcher switcher;
    private final List<KeyBinding> bindings;
    private float uiFactor = 1f;
    /** Presentation mode, for every demo shown. */
    private boolean presenting;
    /** The demo last put in {@link #presenting}'s mode, and that mode. */
    private DemoState presentedDemo;
    private boolean presentedMode;
    private boolean fullscreenRequested;
    private int windowedWidth;
    private int windowedHeight;

    /**
     * Create the controls, with the HUD factor 1.
     *
     * @param switcher the demos, one of them shown (not null)
     */
    public WindowControls(DemoSwitcher switcher) {
        this.switcher = switcher;
        StringBuilder larger = new StringBuilder("larger HUD text (factor up to x");
        larger.append(HudScale.MAX_FACTOR).append(", for a projector)");
        StringBuilder smaller = new StringBuilder("smaller HUD text (factor down to x");
        smaller.append(HudScale.MIN_FACTOR).append(')');
        this.bindings = List.of(
                new KeyBinding(KeyInput.KEY_F11, "F11", "fullscreen <-> window",
                        () -> fullscreenRequested = true),
                new KeyBinding(KeyInput.KEY_F10, "F10", larger.toString(),
                        () -> changeFactor(1)),
                new KeyBinding(KeyInput.KEY_F9, "F9", smaller.toString(),
                        () -> changeFactor(-1)),
                new KeyBinding(KeyInput.KEY_F8, "F8", "presentation mode (large slide) <->"
                        + " full HUD",
                        () -> presenting = !switcher.getSelected().getDemoHud().isPresenting()));
    }

    /**
     * Return the keys, for the switcher to map and every demo's help to list.
     *
     * @return an unmodifiable list (not null)
     */
    public List<KeyBinding> getBindings() {
        return bindings;
    }

    /**
     * Return the user's HUD factor.
     *
     * @return the factor (from {@link HudScale#MIN_FACTOR} to {@link HudScale#MAX_FACTOR})
     */
    public float getUiFactor() {
        return uiFactor;
    }

    /**
     * Set the user's HUD factor; the demo on screen is laid out for it on the next update.
     *
     * @param factor the factor (from {@link HudScale#MIN_FACTOR} to
     *     {@link HudScale#MAX_FACTOR})
     */
    public void setUiFactor(float factor) {
        HudScale.checkFactor(factor, "HUD scale factor");
        uiFactor = factor;
    }

    /**
     * Return whether the window is in presentation mode.
     *
     * @return true if presenting
     */
    public boolean isPresenting() {
        return presenting;
    }

    /**
     * Switch presentation mode on or off for every demo; the demo on screen follows on the
     * next update, and each demo switched to after it.
     *
     * @param on true for presentation mode
     */
    public void setPresenting(boolean on) {
        presenting = on;
    }

    /**
     * Ask for fullscreen if windowed, or the window if fullscreen; done on the next update.
     */
    public void requestFullscreenToggle() {
        fullscreenRequested = true;
    }

    @Override
    protected void initialize(Application app) {
    }

    @Override
    protected void cleanup(Application app) {
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }

    @Override
    public void update(float tpf) {
        if (fullscreenRequested) {
            fullscreenRequested = false;
            toggleFullscreen();
        }
        DemoState demo = switcher.getSelected();
        if (demo.isInitialized() && (demo != presentedDemo || presenting != presentedMode)) {
            // A new demo on screen (Tab, digits, a tour stop) or F8: the demo takes the mode.
            demo.getDemoHud().setPresenting(presenting);
            presentedDemo = demo;
            presentedMode = presenting;
        }
        Camera camera = getApplication().getCamera();
        int width = camera.getWidth();
        int height = camera.getHeight();
        if (demo.isInitialized() && width > 0 && height > 0
                && !demo.getDemoHud().isLaidOutFor(width, height, uiFactor)) {
            demo.getDemoHud().layOut(width, height, uiFactor);
        }
    }

    private void changeFactor(int steps) {
        float next = HudScale.step(uiFactor, steps);
        DemoState demo = switcher.getSelected();
        if (next == uiFactor) {
            demo.getDemoHud().showNotice("HUD factor x" + uiFactor + " is the "
                    + (steps > 0 ? "largest" : "smallest") + " (" + HudScale.MIN_FACTOR + " to "
                    + HudScale.MAX_FACTOR + ")");
            return;
        }
        uiFactor = next;
        demo.getDemoHud().showNotice("HUD factor x" + uiFactor);
    }

    private void toggleFullscreen() {
        Application app = getApplication();
        JmeContext context = app.getContext();
        DemoState demo = switcher.getSelected();
        if (context.getType() != JmeContext.Type.Display) {
            demo.getDemoHud().showNotice("fullscreen needs a window (this run has none)");
            return;
        }
        AppSettings settings = new AppSettings(false);
        settings.copyFrom(context.getSettings());
        if (settings.isFullscreen()) {
            settings.setFullscreen(false);
            settings.setResolution(windowedWidth, windowedHeight);
        } else {
            windowedWidth = app.getCamera().getWidth();
            windowedHeight = app.getCamera().getHeight();
            GLFWVidMode mode = GLFW.glfwGetVideoMode(GLFW.glfwGetPrimaryMonitor());
            if (mode == null) {
                demo.getDemoHud().showNotice("fullscreen: no monitor found");
                return;
            }
            settings.setResolution(mode.width(), mode.height());
            settings.setFrequency(mode.refreshRate());
            settings.setFullscreen(true);
        }
        app.setSettings(settings);
        app.restart();
    }
}

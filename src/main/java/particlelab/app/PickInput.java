package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.CameraInput;
import com.jme3.input.InputManager;
import com.jme3.input.MouseInput;
import com.jme3.input.RawInputListener;
import com.jme3.input.controls.MouseButtonTrigger;
import com.jme3.input.event.JoyAxisEvent;
import com.jme3.input.event.JoyButtonEvent;
import com.jme3.input.event.KeyInputEvent;
import com.jme3.input.event.MouseButtonEvent;
import com.jme3.input.event.MouseMotionEvent;
import com.jme3.input.event.TouchEvent;
import particlelab.demo.DemoState;
import particlelab.demo.DragControl;

/**
 * The window's mouse on the bodies of the demo shown: the left button picks a body or an
 * arrow tip and drags it ({@link DragControl}), the right button turns the camera. jME's fly
 * camera turns with the left button; at initialisation this state moves that to the right
 * one (the footer and the help say so), so the left button is free for picking.
 *
 * <p>A press the HUD takes is not a pick: the parameter panel's (Lemur consumes the clicks on
 * its buttons and sliders, and a press anywhere on the panel is left to it) and any press
 * while the help covers the scene. A press that picks a grip, and the moves and release of
 * its drag, are consumed, so nothing behind them reacts.
 */
final class PickInput extends BaseAppState implements RawInputListener {

    private final DemoSwitcher switcher;
    /** The demo whose body was pressed on, while the button is down; else null. */
    private DemoState pressed;

    /**
     * Create the input.
     *
     * @param switcher says which demo is shown (not null)
     */
    PickInput(DemoSwitcher switcher) {
        this.switcher = switcher;
    }

    /**
     * Press the left button at a screen point, as the mouse does: pick in the demo shown,
     * unless the HUD takes the point.
     *
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @return true if a grip was taken hold of or a click target took the press (the event
     *     is then consumed)
     */
    boolean press(float screenX, float screenY) {
        DemoState demo = switcher.getSelected();
        pressed = null;
        if (!demo.isInitialized() || demo.getWindow().isHudAt(screenX, screenY)) {
            return false;
        }
        demo.getWindow().getDragControl().press(getApplication().getCamera(), screenX, screenY);
        if (demo.getWindow().getDragControl().wasClickTaken()) {
            // a step dot chose the lens's step: nothing to drag, nothing behind to react
            return true;
        }
        if (demo.getWindow().getDragControl().getHeld() == null) {
            return false;
        }
        pressed = demo;
        return true;
    }

    /**
     * Move the mouse with the left button down, as the mouse does.
     *
     * @param screenX the point's x (in pixels)
     * @param screenY the point's y (in pixels)
     * @return true if a grip is held (the event is then consumed)
     */
    boolean move(float screenX, float screenY) {
        if (pressed == null) {
            return false;
        }
        pressed.getWindow().getDragControl().move(getApplication().getCamera(), screenX, screenY);
        return true;
    }

    /**
     * Release the left button, as the mouse does.
     *
     * @return true if a grip was held (the event is then consumed)
     */
    boolean release() {
        if (pressed == null) {
            return false;
        }
        pressed.getWindow().getDragControl().release();
        pressed = null;
        return true;
    }

    @Override
    protected void initialize(Application app) {
        // jME's fly camera maps its drag-to-turn to the left button when its state starts,
        // which is before this one (attached earlier): move it to the right button.
        InputManager input = app.getInputManager();
        if (input.hasMapping(CameraInput.FLYCAM_ROTATEDRAG)) {
            input.deleteTrigger(CameraInput.FLYCAM_ROTATEDRAG,
                    new MouseButtonTrigger(MouseInput.BUTTON_LEFT));
            input.addMapping(CameraInput.FLYCAM_ROTATEDRAG,
                    new MouseButtonTrigger(MouseInput.BUTTON_RIGHT));
        }
    }

    @Override
    protected void cleanup(Application app) {
    }

    @Override
    protected void onEnable() {
        getApplication().getInputManager().addRawInputListener(this);
    }

    @Override
    protected void onDisable() {
        getApplication().getInputManager().removeRawInputListener(this);
    }

    @Override
    public void onMouseButtonEvent(MouseButtonEvent event) {
        if (event.getButtonIndex() != MouseInput.BUTTON_LEFT) {
            return;
        }
        boolean taken;
        if (event.isPressed()) {
            taken = !event.isConsumed() && press(event.getX(), event.getY());
        } else {
            taken = release();
        }
        if (taken) {
            event.setConsumed();
        }
    }

    @Override
    public void onMouseMotionEvent(MouseMotionEvent event) {
        if (move(event.getX(), event.getY())) {
            event.setConsumed();
        }
    }

    @Override
    public void beginInput() {
    }

    @Override
    public void endInput() {
    }

    @Override
    public void onJoyAxisEvent(JoyAxisEvent event) {
    }

    @Override
    public void onJoyButtonEvent(JoyButtonEvent event) {
    }

    @Override
    public void onKeyEvent(KeyInputEvent event) {
    }

    @Override
    public void onTouchEvent(TouchEvent event) {
    }
}

package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.DebugKeysAppState;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.controls.KeyTrigger;
import java.io.PrintStream;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.StateHash;

/**
 * The C key: print the command line that reproduces the state on screen ({@link StateShare}),
 * so a lecturer hands it to a student, and say on the HUD that it was printed, with the
 * state's step and hash and whether the command, re-run, gives the same bits. jME's own use
 * of C (print the camera's position) is taken off the key when this state starts.
 */
final class ShareKey extends BaseAppState {

    /** The key's description, for the help and the pages. */
    static final String DESCRIPTION = "print this state as a command line (terminal)";

    private final DemoSwitcher switcher;
    private final PrintStream out;
    private final KeyBinding binding;

    /**
     * Create the key.
     *
     * @param switcher the demos, one of them shown (not null)
     * @param out where the command goes (not null)
     */
    ShareKey(DemoSwitcher switcher, PrintStream out) {
        this.switcher = switcher;
        this.out = out;
        this.binding = new KeyBinding(KeyInput.KEY_C, "C", DESCRIPTION, this::share);
    }

    /** @return the binding, for the switcher to map and the help to list (not null) */
    KeyBinding getBinding() {
        return binding;
    }

    /**
     * Print the command of the state shown and say so on the HUD. Call on the jME thread.
     *
     * @return the share printed (not null)
     */
    StateShare share() {
        DemoState demo = switcher.getSelected();
        StateShare share = StateShare.of(demo);
        out.println(share.command);
        out.println(share.stateLine());
        out.flush();
        demo.showNotice("C: command printed to the terminal (step " + share.steps + ", hash "
                + StateHash.hex(share.hash).substring(0, 8) + "...; "
                + (share.reproduces() ? "re-run: same bits)"
                        : share.checked ? "not this state: it came from a drag or a key)"
                                : "not re-run to check)"));
        return share;
    }

    @Override
    protected void initialize(Application app) {
        InputManager input = app.getInputManager();
        if (input.hasMapping(DebugKeysAppState.INPUT_MAPPING_CAMERA_POS)) {
            // jME's C prints the camera's position; the mapping stays (its state deletes it
            // at the end), without the key.
            input.deleteTrigger(DebugKeysAppState.INPUT_MAPPING_CAMERA_POS,
                    new KeyTrigger(KeyInput.KEY_C));
        }
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
}

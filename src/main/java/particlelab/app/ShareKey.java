package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.DebugKeysAppState;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.InputManager;
import com.jme3.input.KeyInput;
import com.jme3.input.controls.KeyTrigger;
import java.io.PrintStream;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.StateHash;

/**
 * The C key: print the command line that reproduces the state on screen ({@link StateShare}),
 * so a lecturer hands it to a student, and say on the HUD that it was printed, with the
 * state's step and hash and whether the command, re-run, gives the same bits. The command is
 * printed at once; the re-run that checks it (a headless run of the same steps, seconds for a
 * long state) happens on a thread of its own, so the window goes on meanwhile, and its verdict
 * comes to the terminal and the HUD when it is known. jME's own use of C (print the camera's
 * position) is taken off the key when this state starts.
 */
final class ShareKey extends BaseAppState {

    /** The key's description, for the help and the pages. */
    static final String DESCRIPTION = "print this state as a command line (terminal)";

    private final DemoSwitcher switcher;
    private final PrintStream out;
    private final Executor checks;
    private final KeyBinding binding;

    /**
     * Create the key; each check runs on a daemon thread of its own.
     *
     * @param switcher the demos, one of them shown (not null)
     * @param out where the command goes (not null)
     */
    ShareKey(DemoSwitcher switcher, PrintStream out) {
        this(switcher, out, ShareKey::checkAside);
    }

    /**
     * Create the key with the executor its checks run on (a test holds them back).
     *
     * @param switcher the demos, one of them shown (not null)
     * @param out where the command goes (not null)
     * @param checks runs each re-run that checks a command, off the jME thread (not null)
     */
    ShareKey(DemoSwitcher switcher, PrintStream out, Executor checks) {
        this.switcher = switcher;
        this.out = out;
        this.checks = checks;
        this.binding = new KeyBinding(KeyInput.KEY_C, "C", DESCRIPTION, this::share);
    }

    /** @return the binding, for the switcher to map and the help to list (not null) */
    KeyBinding getBinding() {
        return binding;
    }

    /**
     * Print the command of the state shown and say so on the HUD, then check it aside. Call
     * on the jME thread; it returns before the check.
     *
     * @return the share once checked, completed on the jME thread after its line is printed
     *     and the HUD says the verdict (not null)
     */
    CompletableFuture<StateShare> share() {
        DemoState demo = switcher.getSelected();
        StateShare.Capture capture = StateShare.capture(demo);
        out.println(capture.command);
        out.flush();
        String head = "C: command printed to the terminal (step " + capture.steps + ", hash "
                + StateHash.hex(capture.hash).substring(0, 8) + "...; ";
        demo.getDemoHud().showNotice(head + "re-running it to check...)");
        CompletableFuture<StateShare> done = new CompletableFuture<>();
        Application app = getApplication();
        checks.execute(() -> {
            StateShare checked;
            try {
                checked = capture.check();
            } catch (RuntimeException failure) {
                // the state line says the re-run failed; the window goes on
                checked = capture.unchecked();
            }
            StateShare share = checked;
            Runnable report = () -> {
                out.println(share.stateLine());
                out.flush();
                demo.getDemoHud().showNotice(head + verdict(share));
                done.complete(share);
            };
            if (app == null) {
                report.run();
            } else {
                app.enqueue(report);
            }
        });
        return done;
    }

    /** The HUD's words for a check's outcome. */
    private static String verdict(StateShare share) {
        return share.reproduces() ? "re-run: same bits)"
                : share.checked ? "not this state: it came from a drag or a key)"
                        : "not re-run to check)";
    }

    /** Run a check on a daemon thread of its own, so it never holds the window open. */
    private static void checkAside(Runnable check) {
        Thread thread = new Thread(check, Program.NAME + " C-key check");
        thread.setDaemon(true);
        thread.start();
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

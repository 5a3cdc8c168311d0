package particlelab.demo;

import com.jme3.input.KeyInput;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * The controls every demo shares, declared once per demo: help, pause, single step, the
 * replay's keys, reset, pause at contact, stepping mode, hitch, time scale, arrows, step
 * dots, the ghosts and the graph, and the parameter panel's keys. The footer, the help and
 * the HUD's key hints are all written from these bindings, so renaming a key here renames
 * it everywhere.
 */
final class SharedKeys {

    private SharedKeys() {
    }

    /**
     * Declare the shared controls of a demo, after its scene was declared.
     *
     * @param demo the demo whose views and replay the keys work (not null)
     * @param keys where the bindings go (not null, modified)
     * @param run the demo's run: clock, contact pause, hitch (not null)
     * @param scene the demo's scene: arrows and dots (not null)
     * @param ghosts the demo's exact ghosts (not null)
     * @param hudWriter names the time keys in the HUD (not null, modified)
     * @param parameterControls the panel, which adds its keys (not null)
     */
    static void declare(DemoState demo, DemoKeys keys, DemoRun run, DemoScene scene,
            ExactGhosts ghosts, HudWriter hudWriter, ParameterControls parameterControls) {
        SimulationClock clock = run.getClock();
        keys.addShared(new KeyBinding(KeyInput.KEY_H, "H", "show / hide this help",
                () -> demo.getWindow().getHud().setHelpVisible(
                        !demo.getWindow().getHud().isHelpVisible()))
                .withSummary("help"));
        KeyBinding pause = keys.addShared(new KeyBinding(KeyInput.KEY_SPACE, "Space",
                "pause / resume the simulation (the camera keeps moving)",
                () -> clock.setPaused(!clock.isPaused())).withSummary("pause"));
        KeyBinding step = keys.addShared(new KeyBinding(KeyInput.KEY_N, "N",
                "single step of h (pauses first)", run::singleStep).withSummary("step"));
        // The replay's keys: Home steps back one recorded step, End forward (a new step at
        // the live end), F6 switches the interpolated drawing off and on.
        keys.addShared(new KeyBinding(KeyInput.KEY_HOME, "Home",
                "step back one recorded step (pauses; Space goes on from there)",
                () -> demo.getReplayControls().stepBack()));
        keys.addShared(new KeyBinding(KeyInput.KEY_END, "End",
                "step forward one recorded step (at the end: like N)",
                () -> demo.getReplayControls().stepForward()));
        keys.addShared(new KeyBinding(KeyInput.KEY_F6, "F6",
                "drawn: interpolated <-> raw steps",
                () -> demo.getReplayControls().setInterpolating(
                        !demo.getReplayControls().isInterpolating())));
        KeyBinding reset = keys.addShared(new KeyBinding(KeyInput.KEY_R, "R",
                "reset: launch again, reframe the camera", demo.getWindow()::restartAndReframe)
                .withSummary("reset"));
        ContactPause contactPause = run.getContactPause();
        KeyBinding atContact = keys.addShared(new KeyBinding(KeyInput.KEY_RETURN, "Enter",
                // one help row at 1280x720: a wrapped row pushed the help under 16 px
                "pause at the next contact (again: the one after; waiting: cancel)",
                contactPause::press));
        contactPause.setKeys(atContact, pause);
        keys.addShared(new KeyBinding(KeyInput.KEY_T, "T",
                "stepping: raw tpf (the lecture's loop) <-> fixed step h", clock::toggleMode));
        StringBuilder hitch = new StringBuilder("inject one ");
        TextFormat.appendFixed(hitch, DemoRun.HITCH_SECONDS, 1).append(" s frame (a hitch)");
        keys.addShared(new KeyBinding(KeyInput.KEY_K, "K", hitch.toString(), run::injectHitch));
        StringBuilder up = new StringBuilder("time scale x2, up to ");
        HudWriter.appendScale(up, SimulationClock.MAX_TIME_SCALE)
                .append(" (the HUD shows the speed reached)");
        KeyBinding faster = keys.addShared(new KeyBinding(
                new int[] {KeyInput.KEY_EQUALS, KeyInput.KEY_ADD}, new String[] {"+", "keypad +"},
                up.toString(), null, key -> run.scaleTime(DemoRun.TIME_SCALE_FACTOR)));
        StringBuilder down = new StringBuilder("time scale /2, down to ");
        HudWriter.appendScale(down, SimulationClock.MIN_TIME_SCALE);
        KeyBinding slower = keys.addShared(new KeyBinding(
                new int[] {KeyInput.KEY_MINUS, KeyInput.KEY_SUBTRACT},
                new String[] {"-", "keypad -"}, down.toString(), null,
                key -> run.scaleTime(1f / DemoRun.TIME_SCALE_FACTOR)));
        KeyBinding realTime = keys.addShared(new KeyBinding(KeyInput.KEY_X, "X",
                "time scale back to x1 (real time)", () -> clock.setTimeScale(1f)));
        keys.addShared(new KeyBinding(KeyInput.KEY_V, "V", "show / hide velocity arrows",
                scene::toggleArrows));
        keys.addShared(new KeyBinding(KeyInput.KEY_U, "U",
                "show / hide the step dots (one per step)",
                scene::toggleDots));
        if (ghosts.isEnabled()) {
            keys.addShared(new KeyBinding(KeyInput.KEY_G, "G",
                    "show / hide the exact ghosts (the continuous paths, faint)",
                    ghosts::toggleGhosts));
            keys.addShared(new KeyBinding(KeyInput.KEY_Y, "Y",
                    "show / hide the live graph: height and speed against time",
                    demo.getWindow()::toggleGraph));
        }
        hudWriter.setTimeKeys(pause, step, reset, faster, slower, realTime);
        parameterControls.declareKeys(keys, demo.getWindow()::relayOutPanel);
    }
}

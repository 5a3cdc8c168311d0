package particlelab.app;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.ParametersTable;
import particlelab.demo.StateHash;
import particlelab.lecture.FountainDemo;
import particlelab.world.Fountain;

/**
 * A demo's state as a command line to hand to a student (issue 33): {@code particle-lab demo
 * NAME --frames K --fixed-tpf H --set NAME=VALUE ...} opens the window on the same demo with
 * the same settings and runs it K steps of h, to the same bits. What it holds:
 * <ul>
 * <li>the parameters whose value in the scene differs from the declared default, each written
 * as {@code --set} reads it back to the same float ({@link ParametersTable#valueText}); a
 * launch dragged by its arrow is the speed and angle parameters, so it is among them;
 * <li>the time, as steps: K = the world's steps since the scene's last start (its launch or a
 * reset), and {@code --fixed-tpf H} with H = h, the clock's step, so each frame takes exactly
 * one step of h (the fixed-step clock's leftover stays zero). Decision: time is given as
 * frames of h, not as seconds, so the count is exact; a state at its launch (no step yet)
 * has no {@code --frames}.
 * </ul>
 * The command is checked before it is given: a new demo of the same kind takes the settings
 * as {@code --set} does and runs K frames of h without a window and without a jME
 * application, as the command does, and its {@link StateHash} is compared with the state's. A state
 * reached with inputs no command line carries (a drag of a body's position, a key that fired
 * or relaunched mid-run, raw or varying frame times) differs, and the second line says so
 * rather than claim the command reproduces it.
 */
final class StateShare {

    /** The option that prints the command at the end of a run. */
    static final String PRINT_COMMAND = "--print-command";
    /**
     * The most steps re-run to check a command: ten minutes at 60 Hz (the re-run takes about
     * as long as the state's steps take headless); past it the line says the check was not
     * made.
     */
    static final long MAX_CHECKED_STEPS = 36_000L;

    /** The command line that reproduces the state (not null). */
    final String command;
    /** The world's steps since the scene's start (&ge;0). */
    final long steps;
    /** The simulated time of the state (in seconds). */
    final double seconds;
    /** The state's hash ({@link StateHash}). */
    final long hash;
    /** Whether the command was re-run to check it. */
    final boolean checked;
    /** The hash the command's run gives (meaningful when {@link #checked}). */
    final long commandHash;

    private StateShare(String command, long steps, double seconds, long hash, boolean checked,
            long commandHash) {
        this.command = command;
        this.steps = steps;
        this.seconds = seconds;
        this.hash = hash;
        this.checked = checked;
        this.commandHash = commandHash;
    }

    /**
     * Write the command line of the state a demo shows, and check it by re-running it (both
     * on the calling thread).
     *
     * @param demo the demo (not null, one of the catalogue's kinds, initialised or stepped)
     * @return the share (not null)
     */
    static StateShare of(DemoState demo) {
        return capture(demo).check();
    }

    /**
     * Write the command line of the state a demo shows, without re-running it: what the
     * check needs is copied, so {@link Capture#check} may run on another thread while the
     * demo goes on (the window's C key does, so the window never waits for the re-run).
     *
     * @param demo the demo (not null, one of the catalogue's kinds, initialised or stepped)
     * @return the command and the state's hash, not yet checked (not null)
     */
    static Capture capture(DemoState demo) {
        int index = catalogIndex(demo);
        String name = DemoCatalog.names().get(index);
        List<String> settings = settingsOf(demo);
        long steps = demo.getWorld().getStepCount();
        float stepSeconds = demo.getClock().getStepSeconds();
        int particles = demo instanceof FountainDemo
                ? ((FountainDemo) demo).getParticleCount() : Fountain.DEFAULT_PARTICLES;
        StringBuilder command = new StringBuilder(Program.NAME).append(' ')
                .append(DemoCommand.NAME).append(' ').append(name);
        if (steps > 0L) {
            command.append(" --frames ").append(steps).append(" --fixed-tpf ")
                    .append(Float.toString(stepSeconds));
        }
        if (particles != Fountain.DEFAULT_PARTICLES) {
            command.append(" --particles ").append(particles);
        }
        for (String setting : settings) {
            command.append(" --set ").append(setting);
        }
        return new Capture(command.toString(), steps, demo.getWorld().getTimeSeconds(),
                StateHash.of(demo), index, particles, settings, stepSeconds);
    }

    /**
     * Write the settings of a demo's scene that differ from the declared defaults, each as
     * {@code --set} reads it back to the same float.
     *
     * @param demo the demo (not null)
     * @return new NAME=VALUE texts, in the panel's order (not null)
     */
    static List<String> settingsOf(DemoState demo) {
        List<String> settings = new ArrayList<>();
        DemoParameters parameters = demo.getParameters();
        for (int i = 0; i < parameters.size(); ++i) {
            DemoParameter parameter = parameters.get(i);
            float value = parameters.getValueInScene(i);
            if (Float.floatToRawIntBits(value)
                    != Float.floatToRawIntBits(parameter.getDefault())) {
                settings.add(parameter.getName() + "="
                        + ParametersTable.valueText(parameter, value));
            }
        }
        return settings;
    }

    /**
     * A state's command line and hash, taken on the demo's thread, and what re-running the
     * command needs; nothing of the live demo.
     */
    static final class Capture {

        /** The command line that reproduces the state (not null). */
        final String command;
        /** The world's steps since the scene's start (&ge;0). */
        final long steps;
        /** The hash of the state ({@link StateHash}). */
        final long hash;
        private final double seconds;
        private final int index;
        private final int particles;
        private final List<String> settings;
        private final float stepSeconds;

        private Capture(String command, long steps, double seconds, long hash, int index,
                int particles, List<String> settings, float stepSeconds) {
            this.command = command;
            this.steps = steps;
            this.seconds = seconds;
            this.hash = hash;
            this.index = index;
            this.particles = particles;
            this.settings = List.copyOf(settings);
            this.stepSeconds = stepSeconds;
        }

        /**
         * Re-run the command (in a new demo, its frames as the window runs them, without a
         * jME application) and compare the hashes. Any thread may call it.
         *
         * @return the share, checked unless the command has more than
         *     {@link #MAX_CHECKED_STEPS} steps or its run failed (not null)
         */
        StateShare check() {
            Long rerunHash = steps <= MAX_CHECKED_STEPS
                    ? rerun(index, particles, settings, steps, stepSeconds) : null;
            boolean checked = rerunHash != null;
            return new StateShare(command, steps, seconds, hash, checked,
                    checked ? rerunHash : 0L);
        }

        /** @return the share as when its re-run failed: not checked (not null) */
        StateShare unchecked() {
            return new StateShare(command, steps, seconds, hash, false, 0L);
        }
    }

    /** @return true if the command was re-run and gave the same state, bit for bit */
    boolean reproduces() {
        return checked && commandHash == hash;
    }

    /**
     * Write the line under the command: the state's step, time and hash, and whether the
     * command gives it.
     *
     * @return the line (not null)
     */
    String stateLine() {
        StringBuilder line = new StringBuilder("state: step ").append(steps).append(", t = ")
                .append(String.format(Locale.ROOT, "%.4f", seconds)).append(" s, hash ")
                .append(StateHash.hex(hash));
        if (!checked) {
            return line.append(steps > MAX_CHECKED_STEPS ? "; not re-run to check (more than "
                    + MAX_CHECKED_STEPS + " steps)" : "; the re-run to check it failed")
                    .toString();
        }
        if (reproduces()) {
            return line.append("; the command re-run gives the same bits").toString();
        }
        return line.append("; the command gives hash ").append(StateHash.hex(commandHash))
                .append(": this state came from inputs a command line does not carry (a drag"
                        + " of a body, a key mid-run, raw or varying frame times)")
                .toString();
    }

    /**
     * Re-run a command's settings and frames in a new demo as the command does: its frames
     * as the window runs them ({@link ExportRun#runFrames}: the demo's own update, so what a
     * demo does once a frame besides its steps, the targets demo's new round, happens too),
     * without a jME application. Its hash, or null if it failed.
     */
    private static Long rerun(int index, int particles, List<String> settings, long steps,
            float stepSeconds) {
        DemoState fresh = DemoCatalog.entries().get(index).create(particles);
        DemoCommand.applySettings(fresh, settings);
        if (steps == 0L) {
            // the scene declared and started, no step taken (a frame of 0 s takes none)
            fresh.getRun().advancePhysics(0f);
            return StateHash.of(fresh);
        }
        try {
            ExportRun.runFrames(fresh, (int) steps, stepSeconds);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            return null;
        } catch (RuntimeException failure) {
            return null;
        }
        return StateHash.of(fresh);
    }

    /** The demo's place in the catalogue, by its class. */
    private static int catalogIndex(DemoState demo) {
        int index = DemoCatalog.indexOfDemo(demo);
        if (index < 0) {
            throw new IllegalArgumentException("not a demo of the catalogue: "
                    + demo.getTitle());
        }
        return index;
    }
}

package particlelab.app;

import com.jme3.system.JmeContext;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import particlelab.demo.DemoState;
import particlelab.demo.TrajectoryExport;
import particlelab.files.SafeFiles;

/**
 * {@code particle-lab demo NAME --frames N [--fixed-tpf H] --export DIR}, and
 * {@code --print-command} (the command line of the end state, {@link StateShare}): run a demo
 * for N
 * frames and write every particle's trajectory to {@code DIR/<particle>.csv}, listing the
 * files on stdout, one line each ({@code csv FILE: ROWS rows}).
 *
 * <p>Decision: an export with no {@code --screenshot} needs no window, and no jME application
 * at all: the demo runs its N frames here ({@link #runFrames}), each the demo's own update with
 * the frame time (its steps and what it does once a frame), with no view built, so it works on
 * a machine without a display and writes the files the window would. There is no PNG: nothing
 * is drawn. With {@code --screenshot FILE} the window opens as usual (a display is needed) and
 * the PNG is written there; the CSV files are written when the window closes.
 *
 * <p>Existing files: a folder holding {@code .csv} files is refused before the demo runs
 * unless {@value SafeFiles#FORCE} is given, and every file is created new by the rules of
 * {@link SafeFiles}, so a symbolic link planted in the folder is never written through.
 */
final class ExportRun {

    /** The option's name, for messages. */
    static final String EXPORT = "--export";
    /** Why an export wrote no file, on stdout and on the HUD. */
    static final String NOTHING_TO_EXPORT = "this demo records no trajectory or table";
    private static final long NANOS_PER_SECOND = 1_000_000_000L;

    private ExportRun() {
    }

    /**
     * Check, before anything runs and without creating anything, that the CSV files may be
     * written into a folder: it is a folder or can be made one (nothing above it is a file),
     * and no {@code .csv} file in it is in the way. The export names its files after the
     * particles, whose labels a demo may change while it runs, so every {@code .csv} name in
     * the folder counts as one it may write: an existing regular file is refused unless
     * {@code replace}; a symbolic link, a folder, a device is always refused. The folder
     * itself may be a link: the user named it.
     *
     * @param text the folder as given (not null)
     * @param replace true if {@value SafeFiles#FORCE} was given
     * @return the folder (not null), to create with {@link OutputFolders#create}
     * @throws UsageException if it is a file, under a file, or holds a CSV in the way
     */
    static Path checkFolder(String text, boolean replace) {
        String shown = Options.show(text);
        Path folder;
        try {
            folder = Paths.get(text);
        } catch (InvalidPathException bad) {
            throw new UsageException(EXPORT + ": not a valid path, but was " + shown);
        }
        String blocked = SafeFiles.folderRefusal(folder);
        if (blocked != null) {
            throw new UsageException(EXPORT + ": cannot write into "
                    + SafeFiles.printable(folder) + ": " + blocked);
        }
        if (!Files.isDirectory(folder)) {
            return folder;
        }
        List<Path> csvFiles = new ArrayList<>();
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(folder, "*.csv")) {
            for (Path entry : entries) {
                csvFiles.add(entry);
            }
        } catch (IOException | SecurityException failure) {
            throw new UsageException(EXPORT + ": cannot read the folder " + shown + ": "
                    + (failure instanceof IOException
                            ? UsageException.reason((IOException) failure) : "not allowed"));
        }
        Collections.sort(csvFiles);
        for (Path csv : csvFiles) {
            String why = SafeFiles.refusal(csv, replace, "choose an empty folder");
            if (why != null) {
                throw new UsageException(EXPORT + ": " + why);
            }
        }
        return folder;
    }

    /**
     * Run a demo without a window for a number of frames ({@link #runFrames}), then export it.
     *
     * @param demos the demos (not null, not empty)
     * @param index the demo to run
     * @param frames how many frames (&gt;0)
     * @param fixedTpf the fixed frame time (in seconds), or NaN for the real clock
     * @param folder where to write (checked by {@link #checkFolder}, created), or null for
     *     no export ({@value StateShare#PRINT_COMMAND} alone)
     * @param replace true if existing regular files may be replaced
     * @param printCommand true to print the command line of the end state
     *     ({@value StateShare#PRINT_COMMAND}) after the export
     * @param out where the listing goes (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int runHeadless(List<DemoState> demos, int index, int frames, float fixedTpf,
            Path folder, boolean replace, boolean printCommand, PrintStream out,
            PrintStream err) {
        return runHeadless(demos, index, frames, fixedTpf, folder, replace, printCommand, null,
                out, err);
    }

    /**
     * Run a demo without a window, as above; with something to set up on an application
     * before it starts (a recording's state, which hears the application's input and frames),
     * in jME's headless context instead.
     *
     * @param demos the demos (not null, not empty)
     * @param index the demo to run
     * @param frames how many frames (&gt;0)
     * @param fixedTpf the fixed frame time (in seconds), or NaN for the real clock
     * @param folder where to write, or null for no export
     * @param replace true if existing regular files may be replaced
     * @param printCommand true to print the command line of the end state
     * @param beforeStart run on the application before it starts, or null for none (and no
     *     application)
     * @param out where the listing goes (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int runHeadless(List<DemoState> demos, int index, int frames, float fixedTpf,
            Path folder, boolean replace, boolean printCommand,
            Consumer<ParticleLabApp> beforeStart, PrintStream out, PrintStream err) {
        if (beforeStart != null) {
            return runInHeadlessApp(demos, index, frames, fixedTpf, folder, replace,
                    printCommand, beforeStart, out, err);
        }
        DemoState demo = demos.get(index);
        try {
            runFrames(demo, frames, fixedTpf);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println(Program.NAME + ": interrupted");
            return Program.FAILED;
        } catch (RuntimeException failure) {
            Path log = CrashLog.write("the demo failed, exporting " + demo.getTitle(), failure);
            err.println(Program.NAME + ": the demo failed: " + CrashLog.describe(failure)
                    + (log == null ? "" : "; the full stack is in " + log));
            return Program.FAILED;
        }
        int status = folder == null ? Program.OK : write(demo, folder, replace, out, err);
        if (status == Program.OK && printCommand) {
            printCommand(demo, out);
        }
        return status;
    }

    /** {@link #runHeadless} in jME's headless context, with the set-up before it starts. */
    private static int runInHeadlessApp(List<DemoState> demos, int index, int frames,
            float fixedTpf, Path folder, boolean replace, boolean printCommand,
            Consumer<ParticleLabApp> beforeStart, PrintStream out, PrintStream err) {
        DemoCommand.quietLogs();
        ParticleLabApp app = new ParticleLabApp(demos, index, frames, null, fixedTpf, false);
        beforeStart.accept(app);
        app.start(JmeContext.Type.Headless);
        try {
            app.awaitFinished(Long.MAX_VALUE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            app.stop();
            err.println(Program.NAME + ": interrupted");
            return Program.FAILED;
        }
        if (app.getFailure() != null) {
            err.println(Program.NAME + ": the demo failed: " + app.getFailure());
            return Program.FAILED;
        }
        DemoState demo = app.getSwitcher().getSelected();
        int status = folder == null ? Program.OK : write(demo, folder, replace, out, err);
        if (status == Program.OK && printCommand) {
            printCommand(demo, out);
        }
        return status;
    }

    /**
     * Run a demo's frames as the window runs them, without a jME application: each frame is
     * the demo's {@link DemoState#update} with the frame time (the clock's steps, what the
     * demo and its parts do once a frame); no view, HUD or panel is built, so none is drawn.
     * With a fixed frame time every frame gets it; with the real clock the frames are paced at
     * the window's {@value ParticleLabApp#REAL_CLOCK_FRAME_RATE} a second, each given the time
     * since the one before.
     *
     * @param demo the demo, never attached to an application (not null)
     * @param frames how many frames (&ge;0)
     * @param fixedTpf the fixed frame time (in seconds, finite, &gt;0), or NaN for the real clock
     * @throws InterruptedException if interrupted while pacing the real clock
     */
    static void runFrames(DemoState demo, int frames, float fixedTpf)
            throws InterruptedException {
        // The scene declared first, as the window's initialisation does: a demo's update may
        // read its particles before its physics runs (height's labels).
        demo.getRun();
        long previous = System.nanoTime();
        for (int frame = 0; frame < frames; ++frame) {
            float tpf = fixedTpf;
            if (Float.isNaN(fixedTpf)) {
                long due = previous + NANOS_PER_SECOND
                        / ParticleLabApp.REAL_CLOCK_FRAME_RATE;
                for (long wait = due - System.nanoTime(); wait > 0L;
                        wait = due - System.nanoTime()) {
                    TimeUnit.NANOSECONDS.sleep(wait);
                }
                long now = System.nanoTime();
                tpf = (float) ((now - previous) / (double) NANOS_PER_SECOND);
                previous = now;
            }
            demo.update(tpf);
        }
    }

    /**
     * Print the command line that reproduces a demo's state, and the line on its state
     * ({@link StateShare}).
     *
     * @param demo the demo, its application stopped (not null)
     * @param out where the lines go (not null)
     */
    static void printCommand(DemoState demo, PrintStream out) {
        StateShare share = StateShare.of(demo);
        out.println(share.command);
        out.println(share.stateLine());
    }

    /**
     * Export a demo whose application has stopped, listing the files.
     *
     * @param demo the demo (not null)
     * @param folder where to write (not null, exists)
     * @param replace true if existing regular files may be replaced
     * @param out where the listing goes (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int write(DemoState demo, Path folder, boolean replace, PrintStream out,
            PrintStream err) {
        try {
            List<TrajectoryExport.Written> files = TrajectoryExport.write(demo, folder, replace);
            for (TrajectoryExport.Written file : files) {
                out.println("csv " + file.describe());
            }
            if (files.isEmpty()) {
                out.println("csv: none; " + NOTHING_TO_EXPORT);
            }
        } catch (IOException failure) {
            err.println(Program.NAME + ": the export to " + SafeFiles.printable(folder)
                    + " failed: " + UsageException.reason(failure));
            return Program.FAILED;
        }
        return Program.OK;
    }
}

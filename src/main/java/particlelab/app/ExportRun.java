package particlelab.app;

import com.jme3.system.JmeContext;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import particlelab.demo.DemoState;
import particlelab.demo.TrajectoryExport;

/**
 * {@code particle-lab demo NAME --frames N [--fixed-tpf H] --export DIR}: run a demo for N
 * frames and write every particle's trajectory to {@code DIR/<particle>.csv}, listing the
 * files on stdout, one line each ({@code csv FILE: ROWS rows}).
 *
 * <p>Decision: an export with no {@code --screenshot} needs no window. The demo runs in jME's
 * headless context (the same demo, clock and steps as in the window, only nothing is drawn),
 * so it works on a machine without a display, and there is no PNG: a headless context has no
 * frame to read back. With {@code --screenshot FILE} the window opens as usual (a display is
 * needed) and the PNG is written there; the CSV files are written when the window closes.
 */
final class ExportRun {

    /** The option's name, for messages. */
    static final String EXPORT = "--export";

    private ExportRun() {
    }

    /**
     * Check, before anything runs, that the CSV files can be written into a folder: it is
     * created if missing (with those above it), and a probe file is created and deleted.
     *
     * @param text the folder as given (not null)
     * @return the folder (not null)
     * @throws UsageException if it is a file, under a file, or not writable
     */
    static Path checkFolder(String text) {
        String shown = Options.show(text);
        Path folder;
        try {
            folder = Paths.get(text);
        } catch (InvalidPathException bad) {
            throw new UsageException(EXPORT + ": not a valid path, but was " + shown);
        }
        if (Files.exists(folder) && !Files.isDirectory(folder)) {
            throw new UsageException(EXPORT + ": " + shown + " is a file; give a folder");
        }
        try {
            Files.createDirectories(folder);
            Path probe = Files.createTempFile(folder, ".particle-lab-probe", ".csv");
            Files.delete(probe);
        } catch (IOException failure) {
            throw new UsageException(EXPORT + ": cannot write into " + shown + ": "
                    + UsageException.reason(failure));
        } catch (SecurityException | UnsupportedOperationException failure) {
            throw new UsageException(EXPORT + ": cannot write into " + shown);
        }
        return folder;
    }

    /**
     * Run a demo without a window for a number of frames, then export it.
     *
     * @param demos the demos (not null, not empty)
     * @param index the demo to run
     * @param frames how many frames (&gt;0)
     * @param fixedTpf the fixed frame time (in seconds), or NaN for the real clock
     * @param folder where to write (checked by {@link #checkFolder})
     * @param out where the listing goes (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int runHeadless(List<DemoState> demos, int index, int frames, float fixedTpf,
            Path folder, PrintStream out, PrintStream err) {
        DemoCommand.quietLogs();
        ParticleLabApp app = new ParticleLabApp(demos, index, frames, null, fixedTpf, false);
        app.start(JmeContext.Type.Headless);
        try {
            app.awaitFinished(Long.MAX_VALUE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            app.stop();
            err.println("particle-lab: interrupted");
            return DemoCommand.FAILED;
        }
        if (app.getFailure() != null) {
            err.println("particle-lab: the demo failed: " + app.getFailure());
            return DemoCommand.FAILED;
        }
        return write(app.getSwitcher().getSelected(), folder, out, err);
    }

    /**
     * Export a demo whose application has stopped, listing the files.
     *
     * @param demo the demo (not null)
     * @param folder where to write (not null)
     * @param out where the listing goes (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int write(DemoState demo, Path folder, PrintStream out, PrintStream err) {
        try {
            for (TrajectoryExport.Written file : TrajectoryExport.write(demo, folder)) {
                out.println("csv " + file.describe());
            }
        } catch (IOException failure) {
            err.println("particle-lab: the export to " + Options.show(folder.toString())
                    + " failed: " + UsageException.reason(failure));
            return DemoCommand.FAILED;
        }
        return DemoCommand.OK;
    }
}

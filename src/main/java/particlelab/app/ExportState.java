package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.KeyInput;
import com.jme3.system.JmeContext;
import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.demo.TrajectoryExport;

/**
 * Carries out the export a demo asks for ({@link particlelab.demo.DemoKeys#requestExport()}:
 * the E key, or a panel's button): the current trajectories, one CSV per particle
 * ({@link TrajectoryExport}), and a PNG screenshot of the frame, into a new folder
 * {@code particle-lab-export/<demo>-<yyyyMMdd-HHmmss>/} under the working folder. The
 * CSV files are written at once; the screenshot is the frame that finishes rendering next;
 * then the HUD names the folder. Without a window (jME's headless context) there is no frame
 * to read back, and the notice says the PNG was skipped.
 */
public final class ExportState extends BaseAppState {

    /** Where exports go, under the working folder. */
    public static final Path BASE_FOLDER = Paths.get("particle-lab-export");
    /** The screenshot's file name in an export's folder. */
    public static final String SCREENSHOT_NAME = "screenshot.png";
    /** How many folders of the same second it tries before giving up. */
    private static final int MAX_COPIES = 1000;
    private static final DateTimeFormatter STAMP =
            DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");

    private final DemoSwitcher switcher;
    private final Path baseFolder;
    private final KeyBinding binding;
    private ScreenshotCapture capture;
    private DemoState capturedDemo;
    private String pendingNotice;

    /**
     * Create the export.
     *
     * @param switcher the demos, one of them shown (not null)
     * @param baseFolder where each export's folder is made (not null)
     */
    public ExportState(DemoSwitcher switcher, Path baseFolder) {
        this.switcher = switcher;
        this.baseFolder = baseFolder;
        this.binding = new KeyBinding(KeyInput.KEY_E, "E", "export: trajectories (CSV)"
                + " and a screenshot into " + baseFolder + "/<demo>-<date-time>/",
                () -> switcher.getSelected().getKeys().requestExport());
    }

    /**
     * Return the export key, for the switcher to map and every demo's help to list.
     *
     * @return the binding (not null)
     */
    public KeyBinding getBinding() {
        return binding;
    }

    /**
     * Write the shown demo's trajectories into a new folder now (the PNG follows with the
     * next frame), as the E key does. Call on the jME thread.
     *
     * @return the folder (not null)
     * @throws IOException if it cannot be written
     */
    public Path exportNow() throws IOException {
        DemoState demo = switcher.getSelected();
        Path folder = newFolder(demo);
        List<TrajectoryExport.Written> files = TrajectoryExport.write(demo, folder, false);
        String what = files.isEmpty() ? "no CSV (" + ExportRun.NOTHING_TO_EXPORT + ")"
                : files.size() + (files.size() == 1 ? " CSV" : " CSVs");
        if (getApplication().getContext().getType() == JmeContext.Type.Headless) {
            demo.getDemoHud().showNotice("exported " + what + " to " + folder
                    + " (no window: no PNG)");
            return folder;
        }
        removeCapture();
        capture = new ScreenshotCapture(folder.resolve(SCREENSHOT_NAME).toFile());
        capturedDemo = demo;
        pendingNotice = "exported " + what + " + " + SCREENSHOT_NAME + " to " + folder;
        getApplication().getGuiViewPort().addProcessor(capture);
        capture.request();
        return folder;
    }

    @Override
    protected void initialize(Application app) {
    }

    @Override
    protected void cleanup(Application app) {
        removeCapture();
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }

    @Override
    public void update(float tpf) {
        if (capture != null && (capture.isWritten() || capture.getFailure() != null)) {
            capturedDemo.getDemoHud().showNotice(capture.isWritten() ? pendingNotice
                    : pendingNotice.replace(" + " + SCREENSHOT_NAME, "") + "; the PNG failed: "
                            + UsageException.reason(capture.getFailure()));
            removeCapture();
        }
        DemoState demo = switcher.getSelected();
        if (demo.isInitialized() && demo.getKeys().takeExportRequest()) {
            try {
                exportNow();
            } catch (IOException | RuntimeException failure) {
                demo.getDemoHud().showNotice("export failed: " + oneLine(failure));
            }
        }
    }

    /**
     * Make a folder no one else has written into: created here ({@code mkdir}, which fails on
     * any name taken, a symbolic link included), so its files are new by construction.
     */
    private Path newFolder(DemoState demo) throws IOException {
        String name = TrajectoryExport.fileSafeName(demo.getTitle()) + "-"
                + LocalDateTime.now().format(STAMP);
        Files.createDirectories(baseFolder);
        for (int copy = 1; ; ++copy) {
            Path folder = baseFolder.resolve(copy == 1 ? name : name + "-" + copy);
            try {
                return Files.createDirectory(folder);
            } catch (FileAlreadyExistsException taken) {
                if (copy == MAX_COPIES) {
                    throw taken;
                }
            }
        }
    }

    private void removeCapture() {
        if (capture != null) {
            getApplication().getGuiViewPort().removeProcessor(capture);
            capture = null;
            capturedDemo = null;
        }
    }

    private static String oneLine(Exception failure) {
        String message = failure instanceof IOException
                ? UsageException.reason((IOException) failure) : failure.getMessage();
        return message == null ? failure.getClass().getSimpleName()
                : message.replace('\n', ' ');
    }
}

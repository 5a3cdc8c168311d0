package particlelab.app;

import com.jme3.app.DebugKeysAppState;
import com.jme3.app.FlyCamAppState;
import com.jme3.app.SimpleApplication;
import com.jme3.app.StatsAppState;
import com.jme3.audio.AudioListenerState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.RenderManager;
import com.jme3.system.AppSettings;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import particlelab.demo.DemoState;
import particlelab.demo.KeyBinding;
import particlelab.view.ParameterPanel;

/**
 * The Particle Lab window: a jME {@link SimpleApplication} hosting the lecture demos, one
 * enabled at a time (see {@link DemoSwitcher}).
 *
 * <p>Audio: jME's OpenAL start throws on a machine without a sound card, so the launcher asks
 * {@link AudioProbe} first and, when there is no device, starts the window without an audio
 * renderer (and without jME's audio listener state), noting it only in a hidden log line.
 * No demo plays sound yet; later demos (collision effects) can.
 *
 * <p>Options for scripted runs: quit after a number of frames, save the last frame as a PNG,
 * and feed a constant frame time ({@link FixedTimer}) so the picture is reproducible.
 */
public final class ParticleLabApp extends SimpleApplication {

    /** The window's size (in pixels). */
    public static final int WIDTH = 1280;
    public static final int HEIGHT = 720;
    /** A system property "WIDTHxHEIGHT" that overrides the window's size (set by --window). */
    public static final String WINDOW_SIZE_PROPERTY = "particlelab.window";
    /** The system property naming the tour's votes CSV ({@code tour --votes FILE}). */
    public static final String VOTES_PROPERTY = "particlelab.votes";
    /** The system property "true" when the votes CSV may replace a regular file. */
    public static final String VOTES_FORCE_PROPERTY = "particlelab.votes.force";
    /** The frame rate the window keeps to with the real clock (frames per second). */
    public static final int REAL_CLOCK_FRAME_RATE = 60;
    /** The window's title. */
    public static final String TITLE = "Particle Lab - game particle physics, lecture demos";
    private static final ColorRGBA BACKGROUND = new ColorRGBA(0.07f, 0.08f, 0.11f, 1f);
    private static final Logger LOGGER = Logger.getLogger(ParticleLabApp.class.getName());

    private final DemoSwitcher switcher;
    private final WindowControls windowControls;
    private final TourGuide tour;
    /** The tour question's large text (F4). */
    private final QuestionOverlay questionOverlay;
    private final ExportState export;
    /** The C key: the command line of the state shown (issue 33). */
    private final ShareKey shareKey;
    /** Gives Lemur's globals back to an application running before this one started. */
    private Runnable lemurRelease = () -> { };
    /** The left mouse button on the bodies; it moves the camera's turning to the right. */
    private final PickInput pickInput;
    private final int frameLimit;
    private final ScreenshotCapture capture;
    private final CountDownLatch finished = new CountDownLatch(1);
    private int frames;
    private volatile String failure;
    /** The line of the failure the demo recovered from, or null while none was. */
    private volatile String recovered;

    /**
     * Create the application.
     *
     * @param demos the demos, in menu order (not null, not empty)
     * @param firstDemo the index of the demo to open on (&ge;0, &lt;demos.size())
     * @param frameLimit quit after this many frames (&gt;0), or 0 to run until closed
     * @param screenshot where to save the last frame as a PNG, or null for none; needs a
     *     frame limit
     * @param fixedFrameSeconds a constant frame time to feed the demos (in seconds, &ge;0),
     *     or NaN to use the real clock
     */
    public ParticleLabApp(List<DemoState> demos, int firstDemo, int frameLimit,
            File screenshot, float fixedFrameSeconds) {
        this(demos, firstDemo, frameLimit, screenshot, fixedFrameSeconds, false);
    }

    /**
     * Create the application, with or without audio.
     *
     * @param demos the demos, in menu order (not null, not empty)
     * @param firstDemo the index of the demo to open on (&ge;0, &lt;demos.size())
     * @param frameLimit quit after this many frames (&gt;0), or 0 to run until closed
     * @param screenshot where to save the last frame as a PNG, or null for none; needs a
     *     frame limit
     * @param fixedFrameSeconds a constant frame time to feed the demos (in seconds, &ge;0),
     *     or NaN to use the real clock
     * @param audio true to start OpenAL audio (only when {@link AudioProbe} found a device)
     */
    public ParticleLabApp(List<DemoState> demos, int firstDemo, int frameLimit,
            File screenshot, float fixedFrameSeconds, boolean audio) {
        super(new FlyCamAppState(), new DebugKeysAppState(), new StatsAppState());
        if (audio) {
            stateManager.attach(new AudioListenerState());
        }
        if (frameLimit < 0) {
            throw new IllegalArgumentException("frame limit must be >= 0, but was "
                    + frameLimit);
        }
        if (screenshot != null && frameLimit == 0) {
            throw new IllegalArgumentException("a screenshot needs a frame limit (--frames N)");
        }
        this.switcher = new DemoSwitcher(demos, firstDemo);
        this.windowControls = new WindowControls(switcher);
        this.export = new ExportState(switcher, ExportState.BASE_FOLDER);
        List<KeyBinding> windowKeys = new ArrayList<>(windowControls.getBindings());
        windowKeys.add(export.getBinding());
        this.shareKey = new ShareKey(switcher, System.out);
        windowKeys.add(shareKey.getBinding());
        this.pickInput = new PickInput(switcher);
        this.tour = new TourGuide(switcher);
        windowKeys.addAll(tour.getBindings());
        this.questionOverlay = new QuestionOverlay(tour);
        String votes = System.getProperty(VOTES_PROPERTY);
        if (votes != null) {
            tour.setVotesFile(new VotesFile(java.nio.file.Paths.get(votes),
                    Boolean.getBoolean(VOTES_FORCE_PROPERTY)));
        }
        switcher.addBindings(windowKeys);
        this.frameLimit = frameLimit;
        this.capture = screenshot == null ? null : new ScreenshotCapture(screenshot);
        if (!Float.isNaN(fixedFrameSeconds)) {
            setTimer(new FixedTimer(fixedFrameSeconds));
        }
        setShowSettings(false);
        AppSettings settings = createSettings(fixedFrameSeconds);
        if (audio) {
            settings.setAudioRenderer(AppSettings.LWJGL_OPENAL);
        }
        setSettings(settings);
    }

    /**
     * Create the settings every run uses: the window size and title, no audio (the
     * constructor adds it when asked), and a frame
     * rate cap of 60 Hz (none with a fixed frame time, so scripted runs finish quickly).
     *
     * @param fixedFrameSeconds the fixed frame time, or NaN
     * @return new settings (not null)
     */
    public static AppSettings createSettings(float fixedFrameSeconds) {
        AppSettings settings = new AppSettings(true);
        settings.setResolution(WIDTH, HEIGHT);
        String size = System.getProperty(WINDOW_SIZE_PROPERTY);
        if (size != null) {
            int[] window = DemoCommand.parseWindow(size);
            settings.setResolution(window[0], window[1]);
        }
        settings.setTitle(TITLE);
        // A lecture hall's window: resized by hand or fullscreen (F11), laid out again each time.
        settings.setResizable(true);
        settings.setAudioRenderer(null);
        settings.setVSync(false);
        settings.setFrameRate(Float.isNaN(fixedFrameSeconds) ? REAL_CLOCK_FRAME_RATE : -1);
        settings.setSamples(4);
        // Colours as written (a dark background, bright particles): no sRGB conversion.
        settings.setGammaCorrection(false);
        return settings;
    }

    /**
     * Access the demo switcher.
     *
     * @return the live switcher (not null)
     */
    public DemoSwitcher getSwitcher() {
        return switcher;
    }

    /**
     * Access the window's controls: the HUD factor, fullscreen.
     *
     * @return the live controls (not null)
     */
    public WindowControls getWindowControls() {
        return windowControls;
    }

    /**
     * Access the lecture tour's guide: which stop is shown, PageDown and PageUp.
     *
     * @return the live guide (not null)
     */
    TourGuide getTour() {
        return tour;
    }

    /**
     * Access the tour question's large text.
     *
     * @return the overlay (not null)
     */
    QuestionOverlay getQuestionOverlay() {
        return questionOverlay;
    }

    /**
     * Access the mouse's picking and dragging of the bodies.
     *
     * @return the live input (not null)
     */
    PickInput getPickInput() {
        return pickInput;
    }

    /**
     * Access the export (the E key's).
     *
     * @return the live export (not null)
     */
    public ExportState getExport() {
        return export;
    }

    /**
     * Access the C key's share of the state shown.
     *
     * @return the live key (not null)
     */
    ShareKey getShareKey() {
        return shareKey;
    }

    /**
     * Wait until the application has stopped (or failed to start).
     *
     * @param timeoutSeconds the longest wait (in seconds, &gt;0)
     * @return true if it stopped within the wait
     * @throws InterruptedException if interrupted while waiting
     */
    public boolean awaitFinished(long timeoutSeconds) throws InterruptedException {
        return finished.await(timeoutSeconds, TimeUnit.SECONDS);
    }

    /**
     * Return why the application could not run, if it could not.
     *
     * @return a one-line reason, or null if it ran
     */
    public String getFailure() {
        return failure;
    }

    /**
     * Return the failure the window recovered from by restarting the demo, if one was.
     *
     * @return the line shown on the HUD, or null if nothing failed yet
     */
    public String getRecovered() {
        return recovered;
    }

    /**
     * Access the screenshot capture.
     *
     * @return the capture, or null if no screenshot was asked for
     */
    public ScreenshotCapture getCapture() {
        return capture;
    }

    /**
     * Return how many frames have been updated.
     *
     * @return the count (&ge;0)
     */
    public int countFrames() {
        return frames;
    }

    @Override
    public void simpleInitApp() {
        setDisplayFps(false);
        setDisplayStatView(false);
        setPauseOnLostFocus(false);
        viewPort.setBackgroundColor(BACKGROUND);
        if (flyCam != null) {
            // Turned by dragging, with the right button (PickInput moves it there): the left
            // button picks and drags the bodies.
            flyCam.setDragToRotate(true);
            flyCam.setMoveSpeed(15f);
            flyCam.setZoomSpeed(5f);
        }
        if (capture != null) {
            guiViewPort.addProcessor(capture);
        }
        // Lemur (the parameter panel's buttons and sliders) is set up once per application;
        // an application run inside another gives it its Lemur back when it ends (destroy).
        lemurRelease = ParameterPanel.initializeLemur(this);
        stateManager.attach(switcher);
        stateManager.attach(windowControls);
        stateManager.attach(export);
        stateManager.attach(shareKey);
        stateManager.attach(pickInput);
        stateManager.attach(questionOverlay);
    }

    @Override
    public void simpleUpdate(float tpf) {
        if (!switcher.getSelected().isInitialized()) {
            // The demo initialises on the frame after it is attached: until then the frame is
            // blank, so it neither counts nor is captured.
            return;
        }
        ++frames;
        if (frames == frameLimit && capture != null) {
            capture.request();
        }
    }

    @Override
    public void simpleRender(RenderManager renderManager) {
        if (frameLimit > 0 && frames >= frameLimit) {
            stop();
        }
    }

    /**
     * Run a frame. The first exception a frame throws does not close the window: its stack
     * goes to a log file, the demo shown restarts and says so on the HUD; a second one goes
     * on to jME, whose loop ends the window through {@link #handleError}.
     */
    @Override
    public void update() {
        try {
            super.update();
        } catch (RuntimeException frameFailure) {
            // Before the first frame (the demos initialising) there is no running demo to
            // restart, and a demo half initialised would only fail again.
            if (recovered != null || frames == 0 || !switcher.getSelected().isInitialized()) {
                throw frameFailure;
            }
            recover(frameFailure);
        }
    }

    @Override
    public void handleError(String errorMessage, Throwable cause) {
        // One line for the user, naming the exception and where in the project it came
        // from; the whole stack goes to a log file of this run's (jME's own handler would
        // print it).
        String reason = "";
        if (cause != null) {
            Path log = CrashLog.write(errorMessage, cause);
            reason = ": " + CrashLog.describe(cause) + (log == null ? ""
                    : "; the full stack is in " + log);
        }
        failure = errorMessage + reason;
        stop();
        lemurRelease.run();
        finished.countDown();
    }

    /** Log a frame's failure, restart the demo shown and say so on its HUD. */
    private void recover(RuntimeException frameFailure) {
        DemoState demo = switcher.getSelected();
        double seconds = demo.getClock().getSimulatedSeconds();
        String line = CrashLog.describe(frameFailure);
        Path log = CrashLog.write("recovered from, at t = " + seconds + " s in "
                + demo.getTitle(), frameFailure);
        recovered = "recovered from " + line + " at t = "
                + String.format(Locale.ROOT, "%.2f", seconds) + " s; see "
                + (log == null ? "(no log could be written)" : log.toString());
        LOGGER.log(Level.WARNING, recovered);
        demo.restart();
        demo.getDemoHud().showNotice(recovered);
    }

    @Override
    public void destroy() {
        try {
            super.destroy();
        } catch (RuntimeException tidyFailure) {
            if (failure == null) {
                throw tidyFailure;
            }
            // jME's failure handler destroys the application after handleError: a second
            // exception from tidying up after the first would escape that handler (the JVM
            // prints "thrown from the UncaughtExceptionHandler") and hide the first reason.
            LOGGER.log(Level.FINE, "tidying up after a failure failed too", tidyFailure);
        } finally {
            // Before the latch: a window waiting for this run finds its own Lemur again.
            lemurRelease.run();
            finished.countDown();
        }
    }
}

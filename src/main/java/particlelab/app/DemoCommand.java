package particlelab.app;

import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.lwjgl.glfw.GLFW;
import particlelab.demo.DemoParameter;
import particlelab.demo.DemoParameters;
import particlelab.demo.DemoState;
import particlelab.demo.FrameTimes;
import particlelab.files.SafeFiles;
import particlelab.lecture.FountainDemo;
import particlelab.view.HudLayout;
import particlelab.view.HudScale;
import particlelab.world.Fountain;

/**
 * {@code particle-lab demo [NAME] [options]}: open the window on a demo.
 *
 * <pre>
 *   particle-lab demo --list
 *   particle-lab demo aiming
 *   particle-lab demo drag --frames 120 --fixed-tpf 0.016666668 --screenshot drag.png
 *   particle-lab demo drag --set b=0.3 --set h=1/10
 * </pre>
 *
 * Exit status: 0 when the window ran (and the screenshot was written), 1 when it could not
 * run (no display, no OpenGL, a crash), 2 for a usage error.
 */
public final class DemoCommand {

    /** Set to true by the build's run task, so advice can mention the Gradle daemon. */
    static final String GRADLE_RUN_PROPERTY = "particlelab.gradleRun";

    /** The subcommand's name. */
    public static final String NAME = "demo";
    /** The command as its error lines name it. */
    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String DEMO = "--demo";
    private static final String LIST = "--list";
    private static final String FRAMES = "--frames";
    private static final String SCREENSHOT = "--screenshot";
    private static final String FIXED_TPF = "--fixed-tpf";
    private static final float MAX_FIXED_TPF = 1f;
    private static final String WINDOW = "--window";
    private static final String UI_SCALE = "--ui-scale";
    /** Open the window in presentation mode (F8 in the window). */
    static final String PRESENT = "--present";
    private static final String SET = "--set";
    private static final String PARTICLES = "--particles";
    private static final double MILLIS_PER_SECOND = 1000.0;
    private static final String PROFILE = "--profile";
    private static final String RECORD = "--record";
    /**
     * The window sizes --window accepts (in pixels): from the smallest the HUD is laid out
     * for without overlaps (lines hidden, "window too small" said in the window) to 8K.
     */
    private static final int MIN_WINDOW_WIDTH = HudLayout.MIN_WIDTH;
    private static final int MIN_WINDOW_HEIGHT = HudLayout.MIN_HEIGHT;
    private static final int MAX_WINDOW_SIDE = 7680;
    /** Kept so the level set on jME's loggers is not lost to garbage collection. */
    private static final Logger JME_LOGGER = Logger.getLogger("com.jme3");
    private static final Logger WINDOW_LOGGER = Logger.getLogger("com.jme3.system.lwjgl");
    /** Lemur (the panel) logs its version and build date at INFO on every start. */
    private static final Logger LEMUR_LOGGER = Logger.getLogger("com.simsilica.lemur");
    private static final Logger ASSET_CONFIG_LOGGER =
            Logger.getLogger("com.jme3.asset.AssetConfig");

    private DemoCommand() {
    }

    /**
     * Run the command from a shell.
     *
     * @param args the arguments after {@code demo}
     */
    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /**
     * Run the command.
     *
     * @param args the arguments after {@code demo} (not null)
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status: {@link Program#OK}, {@link Program#FAILED} or
     *     {@link Program#USAGE}
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        // "particle-lab demo aiming ...": the demo's name may come first, without --demo.
        boolean named = args.length > 0 && !args[0].startsWith("-");
        String first = named ? args[0] : null;
        String[] optionArgs = named ? Arrays.copyOfRange(args, 1, args.length) : args;
        return CommandSupport.execute(COMMAND, declareOptions(), optionArgs, out, err,
                options -> {
                    if (options.has(LIST)) {
                        for (String demo : DemoCatalog.names()) {
                            out.println(demo);
                        }
                        return Program.OK;
                    }
                    return open(Request.parse(first, options), out, err);
                });
    }

    /**
     * Open the window (or run the export headless) on an accepted command line: the demos
     * are made, the settings applied, and only then are the folders made; a run that failed
     * leaves no folder it made.
     *
     * @throws UsageException for a bad setting or a folder that cannot be made
     */
    private static int open(Request request, PrintStream out, PrintStream err) {
        if (request.replay != null) {
            return Replayer.run(request.name, request.replay, out, err);
        }
        int index = request.name == null ? 0 : DemoCatalog.indexOf(request.name);
        List<DemoState> demos = DemoCatalog.createAll(request.particles);
        applySettings(demos.get(index), request.settings);
        // The whole command line was accepted: only now are the folders made.
        Path exportFolder = request.exportFolder;
        Path shotFolder = request.screenshot == null ? null
                : request.screenshot.toPath().toAbsolutePath().getParent();
        Path recordFolder = request.record == null ? null
                : Paths.get(request.record).toAbsolutePath().getParent();
        Path createdForExport = null;
        Path createdForShot = null;
        Path createdForRecord = null;
        try {
            if (exportFolder != null) {
                createdForExport = OutputFolders.create(ExportRun.EXPORT, exportFolder);
            }
            if (shotFolder != null) {
                createdForShot = OutputFolders.create(SCREENSHOT, shotFolder);
            }
            if (recordFolder != null) {
                createdForRecord = OutputFolders.create(RECORD, recordFolder);
            }
        } catch (UsageException e) {
            SafeFiles.removeCreated(exportFolder, createdForExport);
            if (shotFolder != null) {
                SafeFiles.removeCreated(shotFolder, createdForShot);
            }
            throw e;
        }
        Recorder[] recorder = new Recorder[1];
        Writer[] recordWriter = new Writer[1];
        Consumer<ParticleLabApp> beforeStart = null;
        if (request.record != null) {
            Writer writer;
            try {
                writer = SafeFiles.newWriter(Paths.get(request.record), request.force);
            } catch (IOException failure) {
                err.println(Program.NAME + ": " + RECORD + ": cannot write "
                        + Options.show(request.record) + ": " + UsageException.reason(failure));
                return Program.FAILED;
            }
            recordWriter[0] = writer;
            String name = DemoCatalog.names().get(index);
            int particles = request.particles == Fountain.DEFAULT_PARTICLES ? 0
                    : request.particles;
            beforeStart = app -> {
                recorder[0] = new Recorder(app.getSwitcher(), demos.get(index), name,
                        particles, writer);
                app.getStateManager().attach(recorder[0]);
            };
        }
        if (request.window != null) {
            System.setProperty(ParticleLabApp.WINDOW_SIZE_PROPERTY,
                    request.window[0] + "x" + request.window[1]);
        }
        // an export or a printed command after N frames needs no window (unless a PNG is asked)
        // a recording of N frames needs no window either
        int status = (exportFolder != null || (request.printCommand || request.record != null)
                && request.frames > 0) && request.screenshot == null
                ? ExportRun.runHeadless(demos, index, request.frames, request.fixedTpf,
                        exportFolder, request.force, request.printCommand, beforeStart, out,
                        err)
                : openWindow(demos, index, TourGuide.NOT_TOURING, request.frames,
                        request.screenshot, request.fixedTpf, request.uiScale, request.present,
                        exportFolder, request.force, request.printCommand, beforeStart, out,
                        err);
        if (request.record != null && (recorder[0] == null || !recorder[0].hasStarted())) {
            // the run never started (no display, say): no empty recording is left behind
            try {
                recordWriter[0].close();
                Files.deleteIfExists(Paths.get(request.record));
            } catch (IOException leftBehind) {
                err.println(Program.NAME + ": " + RECORD + ": could not remove the empty "
                        + Options.showWhole(request.record) + ": "
                        + UsageException.reason(leftBehind));
            }
            recorder[0] = null;
        }
        if (recorder[0] != null) {
            recorder[0].finish("the run ended");
            if (recorder[0].getFailure() != null) {
                err.println(Program.NAME + ": " + RECORD + ": writing "
                        + Options.show(request.record) + " failed: "
                        + UsageException.reason(recorder[0].getFailure()));
                status = status == Program.OK ? Program.FAILED : status;
            } else if (status == Program.OK) {
                out.println("recorded " + recorder[0].countSteps() + " steps to "
                        + Options.showWhole(request.record));
            }
        }
        if (status != Program.OK) {
            // A run that failed (no display, say) leaves no empty folder it made.
            SafeFiles.removeCreated(exportFolder, createdForExport);
            if (shotFolder != null) {
                SafeFiles.removeCreated(shotFolder, createdForShot);
            }
            if (recordFolder != null) {
                SafeFiles.removeCreated(recordFolder, createdForRecord);
            }
        }
        if (status == Program.OK && request.profile) {
            out.println(profileLine(demos.get(index)));
        }
        return status;
    }

    /** A command line of {@code demo}, checked whole before anything is made. */
    private static final class Request {
        String name;
        int frames;
        File screenshot;
        float fixedTpf;
        int[] window;
        Path exportFolder;
        boolean force;
        float uiScale;
        boolean present;
        List<String> settings;
        int particles;
        boolean profile;
        boolean printCommand;
        String record;
        String replay;

        /**
         * Read and check the options, the demo first (its options mean nothing without it).
         *
         * @param first the demo named before the options, or null
         * @param options the parsed options (not null)
         * @return the request (not null)
         * @throws UsageException naming the first bad option
         */
        static Request parse(String first, Options options) {
            Request request = new Request();
            if (first != null && options.has(DEMO)) {
                throw new UsageException(DEMO + ": the demo was already named "
                        + Options.show(first) + "; give it once");
            }
            request.name = options.string(DEMO, first);
            if (request.name != null && DemoCatalog.indexOf(request.name) < 0) {
                throw new UsageException(unknownDemo(request.name));
            }
            request.replay = options.string(Replayer.REPLAY, null);
            if (request.replay != null) {
                for (String other : new String[] {RECORD, FRAMES, FIXED_TPF, SET, PARTICLES,
                    SCREENSHOT, ExportRun.EXPORT, StateShare.PRINT_COMMAND, SafeFiles.FORCE,
                    PRESENT, WINDOW, UI_SCALE, PROFILE}) {
                    if (options.has(other)) {
                        throw new UsageException(Replayer.REPLAY + ": the recording holds the"
                                + " demo's settings, frames and inputs, and the replay runs"
                                + " without a window; " + other + " cannot be given with it");
                    }
                }
                return request;
            }
            request.frames = options.intInRange(FRAMES, 0, 1, Integer.MAX_VALUE);
            String file = options.string(SCREENSHOT, null);
            request.screenshot = file == null ? null : new File(file);
            request.fixedTpf = options.has(FIXED_TPF) ? options.positiveFloat(FIXED_TPF)
                    : Float.NaN;
            if (request.fixedTpf > MAX_FIXED_TPF) {
                throw new UsageException(FIXED_TPF + ": must be at most " + MAX_FIXED_TPF
                        + " s, but was " + request.fixedTpf);
            }
            request.window = parseWindow(options.string(WINDOW, null));
            request.uiScale = parseUiScale(options);
            request.present = options.has(PRESENT);
            boolean export = options.has(ExportRun.EXPORT);
            if (request.present && export && file == null) {
                throw new UsageException(PRESENT + ": shows the window in presentation mode,"
                        + " but " + ExportRun.EXPORT + " without " + SCREENSHOT + " runs with"
                        + " no window; add " + SCREENSHOT + " FILE or drop " + PRESENT);
            }
            if (export && request.frames == 0) {
                throw new UsageException(ExportRun.EXPORT + ": needs " + FRAMES + " N, so the"
                        + " app knows when to write the files");
            }
            request.settings = options.strings(SET);
            if (file != null && request.frames == 0) {
                throw new UsageException(SCREENSHOT + ": needs " + FRAMES + " N, so the app"
                        + " knows which frame to save");
            }
            request.force = options.has(SafeFiles.FORCE);
            request.record = options.string(RECORD, null);
            if (request.force && file == null && !export && request.record == null) {
                throw new UsageException(SafeFiles.FORCE + ": replaces the files of "
                        + SCREENSHOT + ", " + ExportRun.EXPORT + " or " + RECORD
                        + "; give one of them");
            }
            if (file != null) {
                checkScreenshotPath(file, request.force);
            }
            if (request.record != null) {
                checkOutputFile(RECORD, "run.txt", request.record, request.force);
            }
            if (export) {
                request.exportFolder = ExportRun.checkFolder(
                        options.string(ExportRun.EXPORT, null), request.force);
            }
            request.particles = options.intInRange(PARTICLES, Fountain.DEFAULT_PARTICLES, 1,
                    Fountain.MAX_PARTICLES);
            String counted = DemoCatalog.nameWithParticleCount();
            if (options.has(PARTICLES)
                    && DemoCatalog.indexOf(request.name) != DemoCatalog.indexOf(counted)) {
                throw new UsageException(PARTICLES + ": only the demo " + counted
                        + " has a particle count; give it as: demo " + counted + " "
                        + PARTICLES + " N");
            }
            request.profile = options.has(PROFILE);
            request.printCommand = options.has(StateShare.PRINT_COMMAND);
            return request;
        }
    }

    /** Word the refusal of a demo name that is not in the catalog. */
    private static String unknownDemo(String name) {
        return "no demo named '" + Options.show(name) + "'; the demos are "
                + String.join(", ", DemoCatalog.names());
    }

    /** Read --ui-scale: the user's factor on the HUD scale, 1 when not given. */
    static float parseUiScale(Options options) {
        float factor = options.positiveFloat(UI_SCALE, 1f);
        if (!(factor >= HudScale.MIN_FACTOR && factor <= HudScale.MAX_FACTOR)) {
            throw new UsageException(UI_SCALE + ": must be from " + HudScale.MIN_FACTOR + " to "
                    + HudScale.MAX_FACTOR + " (a factor on the HUD's text size), but was "
                    + factor);
        }
        return factor;
    }

    /**
     * Write the line that confirms a screenshot: its whole path (the file the user asked
     * for, to be found again; control characters made visible), then what it holds.
     *
     * @param path the screenshot's path as given (not null)
     * @param statistics its size and colours (not null)
     * @return the line (not null)
     */
    static String writtenLine(String path, String statistics) {
        return "screenshot " + Options.showWhole(path) + ": " + statistics;
    }

    /**
     * Set a demo's parameters from {@code --set NAME=VALUE} values, before its scene starts.
     * A value is a number or a fraction such as {@code 1/60}, or for a named state (a
     * {@link particlelab.demo.DemoParameter#choice choice}) one of its names.
     *
     * @param demo the demo (not null, not initialised yet)
     * @param settings each {@code NAME=VALUE} given, in order (not null)
     * @throws UsageException naming the setting and listing the demo's parameters and
     *     ranges if a name is unknown, a value is not a number or out of its range
     */
    static void applySettings(DemoState demo, List<String> settings) {
        DemoParameters parameters = demo.getParameters();
        for (String setting : settings) {
            int equals = setting.indexOf('=');
            String name = equals < 0 ? setting : setting.substring(0, equals);
            String text = equals < 0 ? "" : setting.substring(equals + 1);
            int index = parameters.indexOf(name);
            String shown = SET + " " + Options.show(setting) + ": ";
            if (equals >= 0 && index < 0) {
                // The name is wrong whatever the value: say so before judging the value.
                throw new UsageException(shown + "no parameter named " + Options.show(name)
                        + "; " + parameters.describeAll());
            }
            if (equals >= 0 && index >= 0 && parameters.get(index).isChoice()) {
                // A named state (a preset, a strategy): its value is one of its names.
                int choice = parameters.get(index).indexOfChoice(text);
                if (choice < 0) {
                    throw new UsageException(shown + Options.show(text) + " is not one of"
                            + " the names of " + name + "; " + parameters.describeAll());
                }
                parameters.set(index, choice);
                continue;
            }
            // The grammar of every numeric option; an infinite value is no number either.
            float value = equals < 0 ? Float.NaN : Options.number(text);
            if (equals < 0 || !Float.isFinite(value)) {
                throw new UsageException(shown + "must be NAME=VALUE with a number, a fraction"
                        + " such as 1/60 or one of a choice's names; "
                        + parameters.describeAll());
            }
            try {
                parameters.set(name, value);
            } catch (IllegalArgumentException refused) {
                throw new UsageException(shown + refused.getMessage());
            }
        }
    }

    /**
     * Write the line {@code --profile} prints at exit, for the demo the window opened on:
     * {@code physics_ms_mean=X physics_ms_max=Y particles=P frames=N frame_share_pct=S}, the
     * wall time of each frame's simulation steps (the clock's steps of the demo's world and
     * every hook in them, the fountain's packed particles included) over the N frames the demo
     * ran, the particles each step moved, and the mean's share of a 16.7 ms frame (in
     * percent); the fountain adds {@code mesh_ms_mean=M mesh_ms_max=K}, its copy of the pool
     * into the points' mesh per frame.
     *
     * @param demo the demo (not null)
     * @return the line, without a line end (not null)
     */
    static String profileLine(DemoState demo) {
        FrameTimes mesh = demo instanceof FountainDemo ? ((FountainDemo) demo).getMeshTimes()
                : null;
        return profileLine(demo.getRun().getPhysicsTimes(), mesh,
                demo.getRun().countSimulatedParticles());
    }

    /**
     * {@link #profileLine(DemoState)} from the times themselves.
     *
     * @param physics the physics' times per frame (not null)
     * @param mesh the mesh update's times per frame (null: a demo without one)
     * @param particles the particles each step moved (&ge;0)
     * @return the line, without a line end (not null)
     */
    static String profileLine(FrameTimes physics, FrameTimes mesh, int particles) {
        double budgetMillis = FountainDemo.FRAME_BUDGET_SECONDS * MILLIS_PER_SECOND;
        String line = physics.formatProfile(particles) + String.format(Locale.ROOT,
                " frame_share_pct=%.1f", 100.0 * physics.meanMillis() / budgetMillis);
        if (mesh == null) {
            return line;
        }
        return line + String.format(Locale.ROOT, " mesh_ms_mean=%.3f mesh_ms_max=%.3f",
                mesh.meanMillis(), mesh.maxMillis());
    }

    /**
     * Check, before the window opens and without creating anything, that the screenshot may
     * be written there ({@link SafeFiles}): nothing at the path, or a regular file and
     * {@code replace}; never a symbolic link, a folder or a device; nothing above it a file.
     * The folder is created and tried with a probe file once the whole command line was
     * accepted ({@link OutputFolders#create}).
     *
     * @param text the path as given (not null)
     * @param replace true if {@value SafeFiles#FORCE} was given
     * @throws UsageException if the PNG may not be written there
     */
    static void checkScreenshotPath(String text, boolean replace) {
        checkOutputFile(SCREENSHOT, "shot.png", text, replace);
    }

    /**
     * Check, as {@link #checkScreenshotPath} does, that a file an option names may be
     * written there.
     *
     * @param option the option, for messages (not null)
     * @param example a file name to suggest when a folder was given (not null)
     * @param text the path as given (not null)
     * @param replace true if {@value SafeFiles#FORCE} was given
     * @throws UsageException if the file may not be written there
     */
    static void checkOutputFile(String option, String example, String text, boolean replace) {
        String shown = Options.show(text);
        Path path;
        try {
            path = Paths.get(text).toAbsolutePath();
        } catch (InvalidPathException bad) {
            throw new UsageException(option + ": not a valid path, but was " + shown);
        }
        if (Files.isDirectory(path, LinkOption.NOFOLLOW_LINKS)) {
            throw new UsageException(option + ": " + shown + " is a folder; give a file"
                    + " name such as " + Options.show(path.resolve(example).toString()));
        }
        String refused = SafeFiles.refusal(Paths.get(text), replace, "choose another name");
        if (refused != null) {
            throw new UsageException(option + ": " + refused);
        }
        String blocked = path.getParent() == null ? null
                : SafeFiles.folderRefusal(path.getParent());
        if (blocked != null) {
            throw new UsageException(option + ": cannot write " + shown + ": "
                    + blocked);
        }
    }

    /**
     * Read a window size such as {@code 1920x1080}.
     *
     * @param value the option's value, or null if not given
     * @return {width, height} in pixels, or null if not given
     * @throws UsageException if it is not WIDTHxHEIGHT within the sizes accepted
     */
    static int[] parseWindow(String value) {
        if (value == null) {
            return null;
        }
        String problem = WINDOW + ": must be WIDTHxHEIGHT in pixels, from " + MIN_WINDOW_WIDTH
                + "x" + MIN_WINDOW_HEIGHT + " to " + MAX_WINDOW_SIDE + "x" + MAX_WINDOW_SIDE
                + ", e.g. 1920x1080, but was " + Options.show(value);
        int x = value.indexOf('x');
        if (x < 1 || x > 4 || value.length() - x - 1 < 1 || value.length() - x - 1 > 4
                || !isDigits(value.substring(0, x)) || !isDigits(value.substring(x + 1))) {
            throw new UsageException(problem);
        }
        int width = Integer.parseInt(value.substring(0, x));
        int height = Integer.parseInt(value.substring(x + 1));
        if (width < MIN_WINDOW_WIDTH || height < MIN_WINDOW_HEIGHT || width > MAX_WINDOW_SIDE
                || height > MAX_WINDOW_SIDE) {
            throw new UsageException(problem);
        }
        return new int[] {width, height};
    }

    /**
     * Declare the command's options, for parsing and for its help.
     *
     * @return new options (not null)
     */
    static Options declareOptions() {
        return new Options(Program.NAME + " " + NAME + " [NAME]",
                "Open the window on one of the lecture's demos (NAME or --demo NAME;"
                        + " default: the first).")
                .value(DEMO, "NAME", "the demo to open on; see --list")
                .flag(LIST, "print the demo names, one per line, and exit")
                .value(FRAMES, "N", "quit after N frames (N >= 1); default: run until closed")
                .value(SCREENSHOT, "FILE", "save the last frame as a PNG (needs --frames);"
                        + " checked before the window opens: an existing FILE is refused"
                        + " (replaced with " + SafeFiles.FORCE + "), and so are a symbolic"
                        + " link, a folder or a device there, a path under a file or an"
                        + " unwritable place")
                .value(FIXED_TPF, "H", "feed every frame the same time H seconds"
                        + " (0 < H <= 1), so a run and its screenshot are reproducible")
                .value(WINDOW, "WxH", "open the window at W x H pixels (default 1280x720);"
                        + " it can be resized, and F11 makes it fullscreen")
                .value(UI_SCALE, "S", "make the HUD's text S times the size that suits the"
                        + " window (" + HudScale.MIN_FACTOR + " <= S <= " + HudScale.MAX_FACTOR
                        + ", default 1; the F9 and F10 keys change it by "
                        + HudScale.FACTOR_STEP + ")")
                .flag(PRESENT, "open in presentation mode: the scene large, the HUD reduced to"
                        + " the demo's title, its formula lines and readout in large type;"
                        + " F8 gives the full HUD back (and presentation mode again), and it"
                        + " stays on across demos")
                .value(ExportRun.EXPORT, "DIR", "after the last frame (needs --frames), write"
                        + " every particle's trajectory since its launch as DIR/<particle>.csv"
                        + " (the header and numbers of particle-lab trajectory), or the demo's"
                        + " own table (rotation, fountain, iterate), the settings beside"
                        + " them as DIR/parameters.csv (name,value,unit), and list the files;"
                        + " without --screenshot it runs without a window (no display needed,"
                        + " no PNG). A DIR holding .csv files is refused (they are replaced"
                        + " with " + SafeFiles.FORCE + "), and a symbolic link named .csv in"
                        + " it always is")
                .flag(StateShare.PRINT_COMMAND, "at the end, print the command line that"
                        + " reproduces the state shown: particle-lab demo NAME --frames K"
                        + " --fixed-tpf H --set ..., K steps of h with the parameters that"
                        + " differ from the defaults; the next line gives the state's hash and"
                        + " whether the command, re-run, gives the same bits (the C key does"
                        + " the same in the window); with --frames and no --screenshot it runs"
                        + " without a window")
                .value(RECORD, "FILE", "write a recording of the run: the settings, each"
                        + " frame's time, the demo's keys, the panel's sliders and the drags,"
                        + " and the state's hash once a simulated second (plain text); an"
                        + " existing FILE is refused (replaced with " + SafeFiles.FORCE
                        + "), a symbolic link always is; with --frames and no --screenshot it"
                        + " runs without a window; switching demos ends it")
                .value(Replayer.REPLAY, "FILE", "replay a recording without a window and"
                        + " print 'replayed N steps: identical', or 'DIVERGED at step K: ...'"
                        + " with exit status 1 at the first hash that differs; a damaged"
                        + " line, another version or another demo is refused (exit status 2)")
                .flag(SafeFiles.FORCE, "let " + SCREENSHOT + ", " + ExportRun.EXPORT
                        + " and " + RECORD + " replace existing regular files; a symbolic"
                        + " link is never written through, not even with it")
                .repeatable(SET, "NAME=VALUE", "set one of the demo's parameters before it"
                        + " starts, e.g. b=0.3 or h=1/10, or a named state such as"
                        + " preset=glancing (repeatable); the panel (F2) lists them, a wrong"
                        + " name or value lists them with their ranges and names")
                .value(PARTICLES, "N", "demo fountain only: how many particles it steps,"
                        + " 1 to " + Fountain.MAX_PARTICLES + " (default "
                        + Fountain.DEFAULT_PARTICLES + ")")
                .flag(PROFILE, "at exit, print one line: physics_ms_mean=X physics_ms_max=Y"
                        + " particles=P frames=N frame_share_pct=S, the wall time of each"
                        + " frame's simulation steps of the demo the window opened on and its"
                        + " share of a 16.7 ms frame (the fountain adds mesh_ms_mean=M"
                        + " mesh_ms_max=K)")
                .note(describeChoices())
                .note("Exit status: 0 when the window ran, 1 when it could not (no display,"
                        + " no OpenGL) or a replay diverged, 2 on a bad command line.");
    }

    /**
     * Write the demos' named states for the help: what {@code --set} accepts besides
     * numbers, e.g. "collisions: preset=head-on|glancing|cradle|paddle". Read from the
     * demos' declarations (no scene is built), so it cannot drift from them.
     *
     * @return one paragraph (not null)
     */
    static String describeChoices() {
        StringBuilder text = new StringBuilder("Named states for --set (the lecture's"
                + " presets):");
        List<DemoState> demos = DemoCatalog.createAll();
        List<String> names = DemoCatalog.names();
        for (int d = 0; d < demos.size(); ++d) {
            DemoParameters parameters = demos.get(d).getParameters();
            String separator = " " + names.get(d) + ": ";
            for (int i = 0; i < parameters.size(); ++i) {
                DemoParameter parameter = parameters.get(i);
                if (!parameter.isChoice()) {
                    continue;
                }
                text.append(separator).append(parameter.getName()).append('=');
                for (int c = 0; c < parameter.countChoices(); ++c) {
                    text.append(c == 0 ? "" : "|").append(parameter.getChoice(c));
                }
                separator = ", ";
            }
            if (!separator.startsWith(" " + names.get(d))) {
                text.append(';');
            }
        }
        text.setLength(text.length() - 1);
        return text.append('.').toString();
    }

    /**
     * Open the window and wait until it closes.
     *
     * @param demos the demos (not null, not empty)
     * @param index the demo to open on
     * @param frames the frame limit, 0 for none
     * @param screenshot the PNG to write, or null
     * @param fixedTpf the fixed frame time, or NaN
     * @param uiScale the user's factor on the HUD scale
     * @param exportFolder where to export the trajectories when the window closes, or null
     * @param replace true if the screenshot and the export may replace existing files
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int openWindow(List<DemoState> demos, int index, int frames, File screenshot,
            float fixedTpf, float uiScale, Path exportFolder, boolean replace, PrintStream out,
            PrintStream err) {
        return openWindow(demos, index, TourGuide.NOT_TOURING, frames, screenshot, fixedTpf,
                uiScale, false, exportFolder, replace, out, err);
    }

    /**
     * Open the window, on a demo or on a stop of the lecture tour, and wait until it closes.
     *
     * @param demos the demos, in {@link DemoCatalog} order for a tour (not null, not empty)
     * @param index the demo to open on (a tour stop's demo)
     * @param tourStop the tour stop to open on (from 0), or
     *     {@link TourGuide#NOT_TOURING}
     * @param frames the frame limit, 0 for none
     * @param screenshot the PNG to write, or null
     * @param fixedTpf the fixed frame time, or NaN
     * @param uiScale the user's factor on the HUD scale
     * @param present true to open in presentation mode ({@code --present})
     * @param exportFolder where to export the trajectories when the window closes, or null
     * @param replace true if the screenshot and the export may replace existing files
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int openWindow(List<DemoState> demos, int index, int tourStop, int frames,
            File screenshot, float fixedTpf, float uiScale, boolean present, Path exportFolder,
            boolean replace, PrintStream out, PrintStream err) {
        return openWindow(demos, index, tourStop, frames, screenshot, fixedTpf, uiScale,
                present, exportFolder, replace, false, out, err);
    }

    /**
     * Open the window, as above, and when it closes print the command line of the state the
     * demo on screen shows ({@value StateShare#PRINT_COMMAND}).
     *
     * @param demos the demos, in {@link DemoCatalog} order for a tour (not null, not empty)
     * @param index the demo to open on (a tour stop's demo)
     * @param tourStop the tour stop to open on (from 0), or
     *     {@link TourGuide#NOT_TOURING}
     * @param frames the frame limit, 0 for none
     * @param screenshot the PNG to write, or null
     * @param fixedTpf the fixed frame time, or NaN
     * @param uiScale the user's factor on the HUD scale
     * @param present true to open in presentation mode ({@code --present})
     * @param exportFolder where to export the trajectories when the window closes, or null
     * @param replace true if the screenshot and the export may replace existing files
     * @param printCommand true to print the state's command line when the window closes
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int openWindow(List<DemoState> demos, int index, int tourStop, int frames,
            File screenshot, float fixedTpf, float uiScale, boolean present, Path exportFolder,
            boolean replace, boolean printCommand, PrintStream out, PrintStream err) {
        return openWindow(demos, index, tourStop, frames, screenshot, fixedTpf, uiScale,
                present, exportFolder, replace, printCommand, null, out, err);
    }

    /**
     * Open the window, as above, with something set up on the application before it starts
     * (a recording's state).
     *
     * @param demos the demos, in {@link DemoCatalog} order for a tour (not null, not empty)
     * @param index the demo to open on (a tour stop's demo)
     * @param tourStop the tour stop to open on (from 0), or
     *     {@link TourGuide#NOT_TOURING}
     * @param frames the frame limit, 0 for none
     * @param screenshot the PNG to write, or null
     * @param fixedTpf the fixed frame time, or NaN
     * @param uiScale the user's factor on the HUD scale
     * @param present true to open in presentation mode ({@code --present})
     * @param exportFolder where to export the trajectories when the window closes, or null
     * @param replace true if the screenshot and the export may replace existing files
     * @param printCommand true to print the state's command line when the window closes
     * @param beforeStart run on the application before it starts, or null
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int openWindow(List<DemoState> demos, int index, int tourStop, int frames,
            File screenshot, float fixedTpf, float uiScale, boolean present, Path exportFolder,
            boolean replace, boolean printCommand, Consumer<ParticleLabApp> beforeStart,
            PrintStream out, PrintStream err) {
        String noDisplay = checkDisplay();
        if (noDisplay != null) {
            err.println(Program.NAME + ": cannot open the window: " + noDisplay);
            return Program.FAILED;
        }
        quietLogs();
        if (isBlank(System.getenv("WAYLAND_DISPLAY"))) {
            // GLFW would try Wayland first and print an error about XDG_RUNTIME_DIR.
            GLFW.glfwInitHint(GLFW.GLFW_PLATFORM, GLFW.GLFW_PLATFORM_X11);
        }
        String noAudio = AudioProbe.findProblem();
        if (noAudio != null) {
            AudioProbe.noteSilentStart(noAudio);
        }
        ParticleLabApp app = new ParticleLabApp(demos, index, frames, screenshot, fixedTpf,
                noAudio == null);
        app.getWindowControls().setUiFactor(uiScale);
        app.getWindowControls().setPresenting(present);
        if (tourStop != TourGuide.NOT_TOURING) {
            // index is the stop's demo, so the window opens on it.
            app.getTour().go(tourStop);
        }
        if (app.getCapture() != null) {
            app.getCapture().setReplace(replace);
        }
        if (beforeStart != null) {
            beforeStart.accept(app);
        }
        app.start();
        try {
            app.awaitFinished(Long.MAX_VALUE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            app.stop();
            err.println(Program.NAME + ": interrupted");
            return Program.FAILED;
        }
        if (app.getFailure() != null) {
            err.println(Program.NAME + ": cannot run the window: " + app.getFailure());
            return Program.FAILED;
        }
        ScreenshotCapture capture = app.getCapture();
        if (capture != null) {
            if (!capture.isWritten()) {
                err.println(Program.NAME + ": the screenshot "
                        + Options.showWhole(screenshot.toString()) + " was not written"
                        + (capture.getFailure() == null ? ""
                                : ": " + UsageException.reason(capture.getFailure())));
                return Program.FAILED;
            }
            out.println(writtenLine(screenshot.toString(), capture.getStatistics()));
        }
        if (exportFolder != null) {
            int status = ExportRun.write(app.getSwitcher().getSelected(), exportFolder, replace,
                    out, err);
            if (status != Program.OK) {
                return status;
            }
        }
        if (printCommand) {
            ExportRun.printCommand(app.getSwitcher().getSelected(), out);
        }
        return Program.OK;
    }

    /**
     * Keep jME's logs to what matters for a run, window or not: its warnings, no banner, and
     * no window failure (ParticleLabApp.handleError reports it in one line).
     */
    static void quietLogs() {
        // ImageIO writes the screenshot; no AWT window is ever opened.
        System.setProperty("java.awt.headless", "true");
        JME_LOGGER.setLevel(Level.WARNING);
        LEMUR_LOGGER.setLevel(Level.WARNING);
        // Window failures reach ParticleLabApp.handleError and are reported in one line.
        WINDOW_LOGGER.setLevel(Level.OFF);
        // jME's asset config names optional loaders (Ogre, glTF, Ogg) that no demo uses.
        ASSET_CONFIG_LOGGER.setLevel(Level.SEVERE);
    }

    /**
     * Check that a display is there to open a window on (X11 or Wayland on Linux).
     *
     * @return why not, or null if there seems to be one
     */
    static String checkDisplay() {
        String os = System.getProperty("os.name", "").toLowerCase();
        if (!os.contains("linux")) {
            return null;
        }
        if (isBlank(System.getenv("DISPLAY")) && isBlank(System.getenv("WAYLAND_DISPLAY"))) {
            String why = "no display (neither DISPLAY nor WAYLAND_DISPLAY is set); on a machine"
                    + " without a screen run it under xvfb-run -a -s \"-screen 0 1280x720x24\"";
            if (Boolean.getBoolean(GRADLE_RUN_PROPERTY)) {
                // A Gradle daemon keeps the environment of the shell that started it.
                why += "; under gradle run, a Gradle daemon started without a display may"
                        + " be in use: run gradle --stop, then try again";
            }
            return why;
        }
        return null;
    }

    /** ASCII digits only, as every whole-number option reads them (no sign here). */
    private static boolean isDigits(String text) {
        return !text.startsWith("+") && !text.startsWith("-") && Options.isWhole(text);
    }

    private static boolean isBlank(String value) {
        return value == null || value.isBlank();
    }
}

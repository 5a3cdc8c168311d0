package particlelab.app;

import java.io.File;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import particlelab.demo.DemoState;
import particlelab.files.SafeFiles;
import particlelab.view.HudScale;

/**
 * {@code particle-lab tour [options]}: walk lecture 15 slide by slide ({@link LectureTour}).
 * Each stop opens its demo in the state the slide needs and shows what to watch for on the
 * HUD; PageDown and PageUp go forward and back, F7 leaves the tour (and starts it from any
 * demo window).
 *
 * <pre>
 *   particle-lab tour --list
 *   particle-lab tour
 *   particle-lab tour --stop 3 --frames 120 --fixed-tpf 0.016666668 --screenshot stop3.png
 * </pre>
 *
 * Exit status: 0 when the window ran (and the screenshot was written), 1 when it could not
 * run (no display, no OpenGL), 2 for a usage error.
 */
public final class TourCommand {

    /** The subcommand's name. */
    public static final String NAME = "tour";
    /** The command as its error lines name it. */
    private static final String COMMAND = Program.NAME + " " + NAME;
    private static final String LIST = "--list";
    private static final String QUESTIONS = "--questions";
    private static final String STOP = "--stop";
    private static final String FRAMES = "--frames";
    private static final String SCREENSHOT = "--screenshot";
    private static final String FIXED_TPF = "--fixed-tpf";
    private static final float MAX_FIXED_TPF = 1f;
    private static final String WINDOW = "--window";
    private static final String UI_SCALE = "--ui-scale";
    private static final String PRESENT = DemoCommand.PRESENT;
    private static final String VOTES = "--votes";

    private TourCommand() {
    }

    /**
     * Declare the command's options, for parsing and for its help.
     *
     * @return new options (not null)
     */
    static Options options() {
        int count = LectureTour.stops().size();
        return new Options(Program.NAME + " " + NAME,
                "Walk lecture 15 slide by slide: each stop opens the slide's demo in the state"
                        + " it needs and shows what to watch for on the HUD; PageDown and"
                        + " PageUp go forward and back, F7 leaves the tour.")
                .flag(LIST, "print the stops (number, slide, demo and settings) and exit")
                .flag(QUESTIONS, "print each stop's question for the room, its answers"
                        + " (numbered as keys 1 to 4) and, after the colon, the one that is"
                        + " right for the stop's state, worked out by the command-line tools'"
                        + " code; one stop a line, then exit")
                .value(STOP, "N", "open on stop N, 1 to " + count + " (default 1)")
                .value(FRAMES, "N", "quit after N frames (N >= 1); default: run until closed")
                .value(SCREENSHOT, "FILE", "save the last frame as a PNG (needs --frames);"
                        + " an existing FILE is refused (replaced with " + SafeFiles.FORCE
                        + ")")
                .value(FIXED_TPF, "H", "feed every frame the same time H seconds"
                        + " (0 < H <= 1), so a run and its screenshot are reproducible")
                .value(WINDOW, "WxH", "open the window at W x H pixels (default 1280x720)")
                .value(UI_SCALE, "S", "make the HUD's text S times the size that suits the"
                        + " window (" + HudScale.MIN_FACTOR + " <= S <= " + HudScale.MAX_FACTOR
                        + ", default 1)")
                .flag(PRESENT, "run the tour in presentation mode: the scene large, the HUD"
                        + " reduced to the demo's title, its formula lines and readout in large"
                        + " type; it stays on from stop to stop, F8 gives the full HUD back")
                .value(VOTES, "FILE", "write the room's votes (F4 at a stop) to FILE, a CSV"
                        + " with one row per revealed question: " + TourVote.CSV_HEADER
                        + "; its folder must exist; an existing FILE is refused (replaced with "
                        + SafeFiles.FORCE + ")")
                .flag(SafeFiles.FORCE, "let " + SCREENSHOT + " and " + VOTES + " replace an"
                        + " existing regular file")
                .note("Exit status: 0 when the window ran, 1 when it could not (no display,"
                        + " no OpenGL), 2 on a bad command line.");
    }

    /**
     * Run the command.
     *
     * @param args the arguments after {@code tour} (not null)
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int run(String[] args, PrintStream out, PrintStream err) {
        return CommandSupport.execute(COMMAND, options(), args, out, err, options -> {
            List<LectureTour.Stop> stops = LectureTour.stops();
            if (options.has(LIST)) {
                for (int i = 0; i < stops.size(); ++i) {
                    out.println(stops.get(i).describe(i + 1));
                }
                return Program.OK;
            }
            if (options.has(QUESTIONS)) {
                printQuestions(out);
                return Program.OK;
            }
            return open(options, stops, out, err);
        });
    }

    /**
     * Open the window on a stop, once the whole command line is accepted; a run that failed
     * leaves no folder it made.
     *
     * @throws UsageException naming the first bad option, or a folder that cannot be made
     */
    private static int open(Options options, List<LectureTour.Stop> stops, PrintStream out,
            PrintStream err) {
        int stop = options.intInRange(STOP, 1, 1, stops.size()) - 1;
        int frames = options.intInRange(FRAMES, 0, 1, Integer.MAX_VALUE);
        String file = options.string(SCREENSHOT, null);
        File screenshot = file == null ? null : new File(file);
        float fixedTpf = options.has(FIXED_TPF) ? options.positiveFloat(FIXED_TPF) : Float.NaN;
        if (fixedTpf > MAX_FIXED_TPF) {
            throw new UsageException(FIXED_TPF + ": must be at most " + MAX_FIXED_TPF
                    + " s, but was " + fixedTpf);
        }
        int[] window = DemoCommand.parseWindow(options.string(WINDOW, null));
        float uiScale = DemoCommand.parseUiScale(options);
        if (screenshot != null && frames == 0) {
            throw new UsageException(SCREENSHOT + ": needs " + FRAMES + " N, so the app"
                    + " knows which frame to save");
        }
        boolean force = options.has(SafeFiles.FORCE);
        String votes = options.string(VOTES, null);
        if (force && screenshot == null && votes == null) {
            throw new UsageException(SafeFiles.FORCE + ": replaces the file of "
                    + SCREENSHOT + " or " + VOTES + "; give one");
        }
        if (screenshot != null) {
            DemoCommand.checkScreenshotPath(file, force);
        }
        if (votes != null) {
            checkVotesPath(votes, force);
        }
        Path shotFolder = screenshot == null ? null
                : screenshot.toPath().toAbsolutePath().getParent();
        Path created = shotFolder == null ? null : OutputFolders.create(SCREENSHOT, shotFolder);
        if (window != null) {
            System.setProperty(ParticleLabApp.WINDOW_SIZE_PROPERTY, window[0] + "x" + window[1]);
        }
        if (votes != null) {
            System.setProperty(ParticleLabApp.VOTES_PROPERTY, votes);
            System.setProperty(ParticleLabApp.VOTES_FORCE_PROPERTY, Boolean.toString(force));
        }
        List<DemoState> demos = DemoCatalog.createAll();
        int demoIndex = DemoCatalog.indexOf(stops.get(stop).getDemo());
        int status = DemoCommand.openWindow(demos, demoIndex, stop, frames, screenshot,
                fixedTpf, uiScale, options.has(PRESENT), null, force, out, err);
        if (status != Program.OK && shotFolder != null) {
            SafeFiles.removeCreated(shotFolder, created);
        }
        return status;
    }

    /**
     * Check the votes file before the window opens, creating nothing: its folder must exist,
     * the file must not be a link or a folder, and an existing file needs --force.
     *
     * @param text the option's value (not null)
     * @param replace true with --force
     * @throws UsageException naming the value and what is allowed
     */
    static void checkVotesPath(String text, boolean replace) {
        String shown = Options.show(text);
        Path path;
        try {
            path = Paths.get(text).toAbsolutePath();
        } catch (InvalidPathException bad) {
            throw new UsageException(VOTES + ": not a valid path, but was " + shown);
        }
        if (Files.isDirectory(path, LinkOption.NOFOLLOW_LINKS)) {
            throw new UsageException(VOTES + ": " + shown + " is a folder; give a file name"
                    + " such as " + Options.show(path.resolve("votes.csv").toString()));
        }
        String refused = SafeFiles.refusal(Paths.get(text), replace, "choose another name");
        if (refused != null) {
            throw new UsageException(VOTES + ": " + refused);
        }
        Path folder = path.getParent();
        if (folder == null || !Files.isDirectory(folder)) {
            throw new UsageException(VOTES + ": the folder of " + shown + " must exist (no"
                    + " folder is created for it)");
        }
    }

    /**
     * Print every stop's question and its right answer for the stop's state: the stop's demo
     * with its parameters at their defaults and the stop's settings applied, as the window's
     * tour puts it (no scene is built).
     */
    private static void printQuestions(PrintStream out) {
        List<LectureTour.Stop> stops = LectureTour.stops();
        for (int i = 0; i < stops.size(); ++i) {
            TourQuestion question = TourQuestions.forStop(i);
            if (question == null) {
                out.println((i + 1) + (i < 9 ? "   " : "  ") + "(no question yet)");
                continue;
            }
            out.println(question.describe(i + 1, question.answer(stateOf(i))));
        }
    }

    /**
     * Put a fresh copy of a stop's demo in the stop's state, without building its scene.
     *
     * @param stop the stop (from 0)
     * @return the demo, its parameters at their defaults and the stop's settings applied
     */
    static DemoState stateOf(int stop) {
        LectureTour.Stop next = LectureTour.stops().get(stop);
        DemoState demo = DemoCatalog.createAll().get(DemoCatalog.indexOf(next.getDemo()));
        DemoCommand.applySettings(demo, next.getSettings());
        return demo;
    }
}

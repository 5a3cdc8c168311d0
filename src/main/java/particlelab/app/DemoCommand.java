package particlelab.app;

import java.io.File;
import java.io.PrintStream;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.lwjgl.glfw.GLFW;
import particlelab.demo.DemoState;

/**
 * {@code particle-lab demo [NAME] [options]}: open the window on a demo.
 *
 * <pre>
 *   particle-lab demo --list
 *   particle-lab demo aiming
 *   particle-lab demo drag --frames 120 --fixed-tpf 0.016666668 --screenshot drag.png
 * </pre>
 *
 * Exit status: 0 when the window ran (and the screenshot was written), 1 when it could not
 * run (no display, no OpenGL, a crash), 2 for a usage error.
 */
public final class DemoCommand {

    /** Exit status: success. */
    public static final int OK = 0;
    /** Exit status: the window could not run. */
    public static final int FAILED = 1;
    /** Exit status: bad command line. */
    public static final int USAGE = 2;

    private static final String HELP = String.join("\n",
            "usage: particle-lab demo [NAME] [options]",
            "  NAME                the demo to open on (see --list; default: the first)",
            "  --demo NAME         the same, as an option",
            "  --list              print the demo names, one per line, and exit",
            "  --frames N          quit after N frames (N >= 1)",
            "  --screenshot FILE   save the last frame as a PNG (needs --frames)",
            "  --fixed-tpf H       feed every frame the same time H seconds (0 < H <= 1),",
            "                      so a run and its screenshot are reproducible",
            "  --help              print this help");
    /** Kept so the level set on jME's loggers is not lost to garbage collection. */
    private static final Logger JME_LOGGER = Logger.getLogger("com.jme3");
    private static final Logger WINDOW_LOGGER = Logger.getLogger("com.jme3.system.lwjgl");
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
     * @return the exit status: {@link #OK}, {@link #FAILED} or {@link #USAGE}
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        String name = null;
        int frames = 0;
        File screenshot = null;
        float fixedTpf = Float.NaN;
        try {
            for (int i = 0; i < args.length; ++i) {
                String arg = args[i];
                switch (arg) {
                    case "--help":
                    case "-h":
                        out.println(HELP);
                        return OK;
                    case "--list":
                        for (String demo : DemoCatalog.names()) {
                            out.println(demo);
                        }
                        return OK;
                    case "--demo":
                        name = value(args, ++i, arg);
                        break;
                    case "--frames":
                        frames = parseFrames(value(args, ++i, arg));
                        break;
                    case "--screenshot":
                        screenshot = new File(value(args, ++i, arg));
                        break;
                    case "--fixed-tpf":
                        fixedTpf = parseTpf(value(args, ++i, arg));
                        break;
                    default:
                        if (arg.startsWith("-") || name != null) {
                            throw new IllegalArgumentException("unknown argument '" + arg
                                    + "'");
                        }
                        name = arg;
                        break;
                }
            }
            if (screenshot != null && frames == 0) {
                throw new IllegalArgumentException("--screenshot needs --frames N, so the"
                        + " app knows which frame to save");
            }
        } catch (IllegalArgumentException e) {
            err.println("particle-lab demo: " + e.getMessage());
            err.println("try 'particle-lab demo --help'");
            return USAGE;
        }
        int index = name == null ? 0 : DemoCatalog.indexOf(name);
        if (index < 0) {
            err.println("particle-lab demo: no demo named '" + name + "'; the demos are "
                    + String.join(", ", DemoCatalog.names()));
            return USAGE;
        }
        return openWindow(DemoCatalog.createAll(), index, frames, screenshot, fixedTpf, out,
                err);
    }

    /**
     * Open the window and wait until it closes.
     *
     * @param demos the demos (not null, not empty)
     * @param index the demo to open on
     * @param frames the frame limit, 0 for none
     * @param screenshot the PNG to write, or null
     * @param fixedTpf the fixed frame time, or NaN
     * @param out where results go (not null)
     * @param err where errors go (not null)
     * @return the exit status
     */
    static int openWindow(List<DemoState> demos, int index, int frames, File screenshot,
            float fixedTpf, PrintStream out, PrintStream err) {
        String noDisplay = checkDisplay();
        if (noDisplay != null) {
            err.println("particle-lab: cannot open the window: " + noDisplay);
            return FAILED;
        }
        // ImageIO writes the screenshot; no AWT window is ever opened.
        System.setProperty("java.awt.headless", "true");
        JME_LOGGER.setLevel(Level.WARNING);
        // Window failures reach ParticleLabApp.handleError and are reported in one line.
        WINDOW_LOGGER.setLevel(Level.OFF);
        // jME's asset config names optional loaders (Ogre, glTF, Ogg) that no demo uses.
        ASSET_CONFIG_LOGGER.setLevel(Level.SEVERE);
        if (isBlank(System.getenv("WAYLAND_DISPLAY"))) {
            // GLFW would try Wayland first and print an error about XDG_RUNTIME_DIR.
            GLFW.glfwInitHint(GLFW.GLFW_PLATFORM, GLFW.GLFW_PLATFORM_X11);
        }
        ParticleLabApp app = new ParticleLabApp(demos, index, frames, screenshot, fixedTpf);
        app.start();
        try {
            app.awaitFinished(Long.MAX_VALUE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            app.stop();
            err.println("particle-lab: interrupted");
            return FAILED;
        }
        if (app.getFailure() != null) {
            err.println("particle-lab: cannot run the window: " + app.getFailure());
            return FAILED;
        }
        ScreenshotCapture capture = app.getCapture();
        if (capture != null) {
            if (!capture.isWritten()) {
                err.println("particle-lab: the screenshot " + screenshot + " was not written"
                        + (capture.getFailure() == null ? ""
                                : ": " + capture.getFailure().getMessage()));
                return FAILED;
            }
            out.println("screenshot " + screenshot + ": " + capture.getStatistics());
        }
        return OK;
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
            return "no display (neither DISPLAY nor WAYLAND_DISPLAY is set); on a machine"
                    + " without a screen run it under xvfb-run -a -s \"-screen 0 1280x720x24\"";
        }
        return null;
    }

    private static boolean isBlank(String value) {
        return value == null || value.isBlank();
    }

    private static String value(String[] args, int index, String option) {
        if (index >= args.length) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return args[index];
    }

    private static int parseFrames(String text) {
        try {
            int frames = Integer.parseInt(text);
            if (frames >= 1) {
                return frames;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException("--frames must be a whole number >= 1, but was '"
                + text + "'");
    }

    private static float parseTpf(String text) {
        try {
            float tpf = Float.parseFloat(text);
            if (tpf > 0f && tpf <= 1f) {
                return tpf;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException("--fixed-tpf must be a time in seconds, > 0 and"
                + " <= 1, but was '" + text + "'");
    }
}

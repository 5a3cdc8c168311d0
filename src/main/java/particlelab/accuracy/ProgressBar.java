package particlelab.accuracy;

import java.io.PrintStream;

/**
 * A console progress bar for the report: {@code [#######.............]  35%  stability map}.
 * On a terminal it redraws one line at every change; otherwise (Gradle, a test, a pipe) it
 * prints a new line only at every tenth of the work, so logs stay short.
 */
public final class ProgressBar {

    private static final int WIDTH = 30;

    private final PrintStream out;
    private final int total;
    private final boolean redraw;
    private int done;
    private int lastTenth = -1;
    private String phase = "";

    /**
     * Create a bar.
     *
     * @param out where to draw (not null)
     * @param total the number of units of work (&gt;0)
     * @param redraw true to redraw one line with carriage returns (a terminal)
     */
    public ProgressBar(PrintStream out, int total, boolean redraw) {
        this.out = out;
        this.total = Math.max(1, total);
        this.redraw = redraw;
    }

    /**
     * Name the phase now running and draw the bar.
     *
     * @param newPhase a few words (not null)
     */
    public void phase(String newPhase) {
        phase = newPhase;
        draw(false);
    }

    /**
     * Count one unit of work done and draw the bar.
     */
    public void advance() {
        done = Math.min(total, done + 1);
        draw(false);
    }

    /**
     * Fill the bar and end its line.
     */
    public void finish() {
        done = total;
        phase = "done";
        draw(true);
        if (redraw) {
            out.println();
        }
        out.flush();
    }

    private void draw(boolean force) {
        int tenth = 10 * done / total;
        if (!redraw && !force && tenth == lastTenth) {
            return;
        }
        lastTenth = tenth;
        int filled = WIDTH * done / total;
        StringBuilder line = new StringBuilder(WIDTH + 40);
        line.append('[');
        for (int i = 0; i < WIDTH; ++i) {
            line.append(i < filled ? '#' : '.');
        }
        line.append("] ").append(String.format("%3d%%", 100 * done / total)).append("  ")
                .append(phase);
        if (redraw) {
            out.print("\r" + line + "        ");
        } else {
            out.println(line);
        }
        out.flush();
    }
}

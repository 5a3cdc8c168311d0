package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Node;
import java.util.List;

/**
 * The derivative lens's graph (issue 32 §2): V_x and V_y of the followed sphere's steps
 * against t, each a curve in its colour, the chosen step marked by a vertical line and a dot
 * on each curve, and under the plot the slope of each curve at the chosen step, as the caller
 * computed it from the plotted points there ({@code −g} for V_y under gravity alone). The
 * slope lines are set in their curve's colour, so they are the legend too.
 *
 * <p>{@link #plot} writes the curves into one preallocated mesh of thin quads
 * ({@link StripCanvas.Quads}: lines of a pixel are lost on a projector) and the text into
 * {@link HudText}s rewritten in place: nothing is allocated per frame. {@link #layOut}
 * measures text; call it when the rectangle or the text size changes.
 */
public final class LensGraph {

    /** The most points a curve holds. */
    public static final int CAPACITY = 1024;
    /** V_x's colour, and its slope line's. */
    public static final ColorRGBA X_COLOR = new ColorRGBA(0.35f, 0.85f, 1f, 1f);
    /** V_y's colour, and its slope line's. */
    public static final ColorRGBA Y_COLOR = new ColorRGBA(1f, 0.5f, 0.8f, 1f);
    private static final ColorRGBA FRAME = new ColorRGBA(0.45f, 0.5f, 0.6f, 1f);
    private static final ColorRGBA TEXT = new ColorRGBA(0.85f, 0.9f, 1f, 1f);
    private static final ColorRGBA MARKER = new ColorRGBA(1f, 1f, 1f, 1f);
    /** Padding inside the graph, as a fraction of the text size. */
    private static final float PADDING = 0.4f;
    /** The plot's height asked for, in text lines. */
    private static final float PLOT_LINES = 7f;
    /**
     * The least plot height, in text lines: a rectangle lower than asked for takes it from
     * the plot first, down to this, before the text shrinks.
     */
    private static final float MIN_PLOT_LINES = 2.5f;
    /** The text rows: the title, the time axis and the two slopes. */
    private static final int TEXT_ROWS = 4;
    /** A curve's thickness, as a fraction of the text size. */
    private static final float CURVE_THICKNESS = 0.13f;
    /** The frame's and the marker's thickness, as a fraction of the text size. */
    private static final float LINE_THICKNESS = 0.07f;
    /** A chosen step's dot's half side, as a fraction of the text size. */
    private static final float DOT_HALF_SIDE = 0.2f;
    /** The widest texts the layout keeps room for. */
    private static final String WIDEST_TITLE = "V (m/s) against t, step 99999";
    private static final String WIDEST_SLOPE = "slope of V_y: -999.999 m/s\u00b2";
    private static final String WIDEST_AXIS = "-1500";
    /** How far the axis reaches past the largest value, so no curve runs on the frame. */
    private static final double HEADROOM = 1.1;
    /** The slopes' decimals: 3, so that g = 9.800 shows to the millimetre per second². */
    private static final int SLOPE_DECIMALS = 3;
    /** The quads: each curve's segments and chosen dot, the frame's 4 sides, zero, marker. */
    private static final int CURVE_QUADS = CAPACITY - 1;
    private static final int X_DOT = 2 * CURVE_QUADS;
    private static final int Y_DOT = X_DOT + 1;
    private static final int FRAME_QUADS = Y_DOT + 1;
    private static final int ZERO_QUAD = FRAME_QUADS + 4;
    private static final int MARKER_QUAD = ZERO_QUAD + 1;
    private static final int QUADS = MARKER_QUAD + 1;
    /** Where an unused quad goes: off the screen. */
    private static final float HIDDEN = StripCanvas.HIDDEN;

    private final TextMeasure measure;
    private final StripCanvas canvas;
    private final StripCanvas.Quads quads;
    private final HudText title;
    private final HudText top;
    private final HudText bottom;
    private final HudText timeAxis;
    private final HudText slopeX;
    private final HudText slopeY;
    private final HudText[] texts;
    private final StringBuilder line = new StringBuilder(48);
    private final ScreenRect area = new ScreenRect();
    private float textSize = 1f;
    private boolean laidOut;
    /** The plot's box, relative to the graph's bottom left (pixels). */
    private float plotLeft;
    private float plotBottom;
    private float plotWidth;
    private float plotHeight;
    /** The slopes last plotted (m/s²). */
    private double shownSlopeX = Double.NaN;
    private double shownSlopeY = Double.NaN;

    /**
     * Create the graph, empty and laid out nowhere.
     *
     * @param assetManager loads the materials (not null)
     * @param font the labels' font (not null)
     */
    public LensGraph(AssetManager assetManager, BitmapFont font) {
        measure = TextMeasure.of(font);
        canvas = new StripCanvas(assetManager, "lens graph");
        quads = canvas.addQuads("lens graph curves", QUADS);
        for (int q = 0; q < QUADS; ++q) {
            quads.color(q, q < CURVE_QUADS || q == X_DOT ? X_COLOR
                    : q < X_DOT || q == Y_DOT ? Y_COLOR : q == MARKER_QUAD ? MARKER : FRAME);
        }

        title = canvas.addText(font, TEXT);
        top = canvas.addText(font, TEXT);
        bottom = canvas.addText(font, TEXT);
        timeAxis = canvas.addText(font, TEXT);
        slopeX = canvas.addText(font, X_COLOR);
        slopeY = canvas.addText(font, Y_COLOR);
        texts = new HudText[] {title, top, bottom, timeAxis, slopeX, slopeY};
        layOut(new ScreenRect(), 1f);
    }

    /** @return the node to attach to the GUI scene (live, not null) */
    public Node getNode() {
        return canvas.getNode();
    }

    /**
     * Show or hide the graph.
     *
     * @param visible true to show it
     */
    public void setVisible(boolean visible) {
        canvas.setVisible(visible);
    }

    /** @return true if shown */
    public boolean isVisible() {
        return canvas.isVisible();
    }

    /**
     * The width the graph needs at a text size: its widest line and the paddings.
     *
     * @param size the text size (in pixels, &gt;0)
     * @return the width (in pixels)
     */
    public float widthFor(float size) {
        return Math.max(measure.width(WIDEST_TITLE, size), measure.width(WIDEST_SLOPE, size))
                + 2f * PADDING * size;
    }

    /**
     * The height the graph needs at a text size: its text rows, the plot and the paddings.
     *
     * @param size the text size (in pixels, &gt;0)
     * @return the height (in pixels)
     */
    public float heightFor(float size) {
        return (TEXT_ROWS + PLOT_LINES) * measure.lineHeight(size) + 3f * PADDING * size;
    }

    /**
     * Fit the graph into a rectangle of the screen, its text at the size given: a rectangle
     * lower than {@link #heightFor} takes the room from the plot, down to a plot of
     * {@value #MIN_PLOT_LINES} lines; only a rectangle too narrow or lower still shrinks the
     * text.
     *
     * @param rect the rectangle (in pixels, not null, not modified; empty: nothing drawn)
     * @param size the text's largest size (in pixels, &gt;0)
     */
    public void layOut(ScreenRect rect, float size) {
        area.set(rect);
        if (rect.isEmpty()) {
            laidOut = false;
            canvas.getNode().setLocalTranslation(HIDDEN, HIDDEN, 0f);
            canvas.hideBackground();
            return;
        }
        laidOut = true;
        float leastHeight = heightFor(size)
                - (PLOT_LINES - MIN_PLOT_LINES) * measure.lineHeight(size);
        float fit = size * Math.min(1f, Math.min(rect.getWidth() / widthFor(size),
                rect.getHeight() / leastHeight));
        textSize = Math.max(1f, fit);
        float pad = PADDING * textSize;
        float lineHeight = measure.lineHeight(textSize);
        canvas.getNode().setLocalTranslation(rect.getX(), rect.getY(), 0f);
        canvas.placeBackground(0f, 0f, rect.getWidth(), rect.getHeight());
        for (HudText text : texts) {
            text.setSize(textSize);
        }
        float rowTop = rect.getHeight() - pad;
        title.setLocalTranslation(pad, rowTop, 1f);
        plotLeft = pad + measure.width(WIDEST_AXIS, textSize) + pad;
        plotWidth = Math.max(1f, rect.getWidth() - plotLeft - pad);
        float plotTop = rowTop - lineHeight - 0.5f * pad;
        plotBottom = pad + 3f * lineHeight + 0.5f * pad;
        plotHeight = Math.max(1f, plotTop - plotBottom);
        top.setLocalTranslation(pad, plotTop, 1f);
        bottom.setLocalTranslation(pad, plotBottom + lineHeight, 1f);
        timeAxis.setLocalTranslation(plotLeft, plotBottom - 0.25f * pad, 1f);
        slopeX.setLocalTranslation(pad, pad + 2f * lineHeight, 1f);
        slopeY.setLocalTranslation(pad, pad + lineHeight, 1f);
    }

    /**
     * Draw the points: V_x and V_y against t, the chosen step marked, its slopes written.
     * Allocates nothing (the labels' text only when longer than any before).
     *
     * @param times the points' times (in seconds, not null, ascending)
     * @param velocityX the points' V_x (in m/s, not null)
     * @param velocityY the points' V_y (in m/s, not null)
     * @param count how many points (from 0 to {@link #CAPACITY})
     * @param chosen the chosen step's place among the points (from 0, &lt; count; or -1)
     * @param stepNumber the chosen step's number, for the title
     * @param slopeOfX V_x's slope at the chosen step (in m/s², from the points)
     * @param slopeOfY V_y's slope at the chosen step (in m/s², from the points)
     */
    public void plot(double[] times, float[] velocityX, float[] velocityY, int count,
            int chosen, long stepNumber, double slopeOfX, double slopeOfY) {
        if (count < 0 || count > CAPACITY) {
            throw new IllegalArgumentException("count must be from 0 to " + CAPACITY
                    + ", but was " + count);
        }
        line.setLength(0);
        title.setText(line.append("V (m/s) against t, step ").append(stepNumber));
        shownSlopeX = slopeOfX;
        shownSlopeY = slopeOfY;
        setSlope(slopeX, "slope of V_x: ", slopeOfX);
        setSlope(slopeY, "slope of V_y: ", slopeOfY);
        if (!laidOut || count < 1) {
            for (int q = 0; q < QUADS; ++q) {
                quads.hide(q);
            }
            quads.upload();
            return;
        }
        double low = 0.0;
        double high = 0.0;
        for (int i = 0; i < count; ++i) {
            low = Math.min(low, Math.min(velocityX[i], velocityY[i]));
            high = Math.max(high, Math.max(velocityX[i], velocityY[i]));
        }
        double axisHigh = high > 0.0 ? StripCanvas.roundUp(HEADROOM * high) : 0.0;
        double axisLow = low < 0.0 ? -StripCanvas.roundUp(HEADROOM * -low) : 0.0;
        if (axisHigh == axisLow) {
            axisHigh = 1.0;
        }
        double start = times[0];
        double span = Math.max(times[count - 1] - start, 1e-9);
        line.setLength(0);
        top.setText(TextFormat.appendFixed(line, axisHigh, 0));
        line.setLength(0);
        bottom.setText(TextFormat.appendFixed(line, axisLow, 0));
        line.setLength(0);
        line.append("t from ");
        TextFormat.appendFixed(line, start, 2).append(" to ");
        timeAxis.setText(TextFormat.appendFixed(line, times[count - 1], 2).append(" s"));

        float curve = 0.5f * CURVE_THICKNESS * textSize;
        for (int i = 0; i < CURVE_QUADS; ++i) {
            if (i + 1 < count) {
                float x0 = xOf(times[i], start, span);
                float x1 = xOf(times[i + 1], start, span);
                quads.writeSegment(i, x0, yOf(velocityX[i], axisLow, axisHigh), x1,
                        yOf(velocityX[i + 1], axisLow, axisHigh), curve);
                quads.writeSegment(CURVE_QUADS + i, x0, yOf(velocityY[i], axisLow, axisHigh), x1,
                        yOf(velocityY[i + 1], axisLow, axisHigh), curve);
            } else {
                quads.hide(i);
                quads.hide(CURVE_QUADS + i);
            }
        }
        float thin = 0.5f * LINE_THICKNESS * textSize;
        float right = plotLeft + plotWidth;
        float plotTop = plotBottom + plotHeight;
        quads.write(FRAME_QUADS, plotLeft - thin, plotBottom - thin, right + thin,
                plotBottom + thin);
        quads.write(FRAME_QUADS + 1, plotLeft - thin, plotTop - thin, right + thin,
                plotTop + thin);
        quads.write(FRAME_QUADS + 2, plotLeft - thin, plotBottom, plotLeft + thin, plotTop);
        quads.write(FRAME_QUADS + 3, right - thin, plotBottom, right + thin, plotTop);
        float zero = yOf(0f, axisLow, axisHigh);
        quads.write(ZERO_QUAD, plotLeft, zero - thin, right, zero + thin);
        if (chosen >= 0 && chosen < count) {
            float x = xOf(times[chosen], start, span);
            float dot = DOT_HALF_SIDE * textSize;
            quads.write(MARKER_QUAD, x - thin, plotBottom, x + thin, plotTop);
            float vx = yOf(velocityX[chosen], axisLow, axisHigh);
            float vy = yOf(velocityY[chosen], axisLow, axisHigh);
            quads.write(X_DOT, x - dot, vx - dot, x + dot, vx + dot);
            quads.write(Y_DOT, x - dot, vy - dot, x + dot, vy + dot);
        } else {
            quads.hide(MARKER_QUAD);
            quads.hide(X_DOT);
            quads.hide(Y_DOT);
        }
        quads.upload();
    }

    /** @return the text size of the last layout (in pixels) */
    public float getTextSize() {
        return textSize;
    }

    /** @return the V_y slope last plotted (in m/s²) */
    public double getShownSlopeY() {
        return shownSlopeY;
    }

    /** @return the V_x slope last plotted (in m/s²) */
    public double getShownSlopeX() {
        return shownSlopeX;
    }

    /** @return the V_y slope's line as shown (allocates: for tests) */
    public String getSlopeYText() {
        return slopeY.getText();
    }

    /** @return the V_x slope's line as shown (allocates: for tests) */
    public String getSlopeXText() {
        return slopeX.getText();
    }

    /** @return the rectangle of the last layout (live, do not modify; empty: none) */
    public ScreenRect getArea() {
        return area;
    }

    /**
     * Add the screen rectangle of each text shown, for tests of overlaps: each line's
     * measured width and height at its place.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        if (!laidOut || !isVisible()) {
            return storeResult;
        }
        for (HudText text : texts) {
            float width = measure.width(text.getChars(), textSize);
            float height = measure.lineHeight(textSize) * text.getLineCount();
            float x = area.getX() + text.getLocalTranslation().x;
            float topY = area.getY() + text.getLocalTranslation().y;
            storeResult.add(new ScreenRect(x, topY - height, width, height));
        }
        return storeResult;
    }

    private void setSlope(HudText text, String name, double slope) {
        line.setLength(0);
        line.append(name);
        if (Double.isFinite(slope)) {
            TextFormat.appendFixed(line, slope, SLOPE_DECIMALS).append(" m/s\u00b2");
        } else {
            line.append('-');
        }
        text.setText(line);
    }

    private float xOf(double time, double start, double span) {
        return plotLeft + (float) ((time - start) / span) * plotWidth;
    }

    private float yOf(float value, double low, double high) {
        double fraction = (value - low) / (high - low);
        return plotBottom + (float) Math.max(0.0, Math.min(1.0, fraction)) * plotHeight;
    }
}

package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.math.ColorRGBA;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;

/**
 * The energy ledger drawn as bars, for the HUD's ledger strip ({@link HudLayout#getLedger}):
 * a title line, then one row per column, its name, a horizontal bar from a zero line in the
 * middle (to the right for energy held or put in, to the left for energy taken or lost) and
 * its value. Each row has its colour; the caller gives the numerical column its own.
 *
 * <p>The bars' scale is the caller's ({@link #setFullScale}): a full half-bar is that many
 * joules, so a scale that does not change from frame to frame draws bars that do not jitter
 * ({@link #roundUp} gives a round number to keep). A value beyond it is drawn to the edge.
 *
 * <p>{@link #refresh} writes the bars into one preallocated mesh of quads
 * ({@link StripCanvas.Quads}) and the values into {@link HudText}s rewritten in place:
 * nothing is allocated per frame. {@link #layOut}
 * measures text and may allocate; call it when the strip or the text size changes.
 */
public final class EnergyBars {

    /** Padding inside the strip and between its columns, as a fraction of the text size. */
    private static final float PADDING = 0.4f;
    /** A row's height, as a multiple of a line's height. */
    private static final float ROW_SPACING = 1.1f;
    /** A bar's thickness, as a fraction of a line's height. */
    private static final float BAR_THICKNESS = 0.6f;
    /** The bars' area's width at text size 19 (in pixels), scaled with the text. */
    private static final float MIN_BAR_WIDTH_PER_TEXT_PIXEL = 220f / 19f;
    /** The widest title the layout keeps room for: a new scale lays nothing out again. */
    private static final String WIDEST_TITLE = "energy (J), ends at \u00b100000";
    /** The widest value the layout keeps room for. */
    private static final String WIDEST_VALUE = "-00000.00";
    /** The zero line's half width, as a fraction of the text size. */
    private static final float AXIS_HALF_WIDTH = 0.06f;
    private static final ColorRGBA TEXT = new ColorRGBA(0.85f, 0.9f, 1f, 1f);
    private static final ColorRGBA AXIS = new ColorRGBA(0.7f, 0.75f, 0.85f, 1f);
    /** Where an unused quad goes: off the screen. */
    private static final float HIDDEN = StripCanvas.HIDDEN;

    private final int maxRows;
    private final TextMeasure measure;
    private final StripCanvas canvas;
    /** One quad per row and one for the zero line. */
    private final StripCanvas.Quads quads;
    private final HudText title;
    private final HudText[] names;
    private final HudText[] values;
    private final StringBuilder valueText = new StringBuilder(24);
    private final double[] joules;
    private final ColorRGBA[] rowColors;
    /** The colour each bar's vertices hold now (compared by reference). */
    private final ColorRGBA[] writtenColors;
    private int rows;
    private double fullScale = 1.0;
    /** The laid-out geometry (pixels, relative to the strip's bottom left). */
    private final ScreenRect area = new ScreenRect();
    private float textSize = 1f;
    private float rowHeight;
    private float barLeft;
    private float barRight;
    private float firstRowTop;
    private int rowsShown;
    private boolean laidOut;

    /**
     * Create the bars, empty.
     *
     * @param assetManager loads the materials (not null)
     * @param font the labels' font (not null)
     * @param maxRows the most rows shown (&gt;0)
     */
    public EnergyBars(AssetManager assetManager, BitmapFont font, int maxRows) {
        if (maxRows <= 0) {
            throw new IllegalArgumentException("maxRows must be > 0, but was " + maxRows);
        }
        this.maxRows = maxRows;
        measure = TextMeasure.of(font);
        joules = new double[maxRows];
        rowColors = new ColorRGBA[maxRows];
        writtenColors = new ColorRGBA[maxRows];
        canvas = new StripCanvas(assetManager, "energy bars");
        quads = canvas.addQuads("energy bars", maxRows + 1);
        for (int q = 0; q <= maxRows; ++q) {
            writeColor(q, q == maxRows ? AXIS : TEXT);
        }

        title = canvas.addText(font, TEXT);
        names = new HudText[maxRows];
        values = new HudText[maxRows];
        for (int i = 0; i < maxRows; ++i) {
            names[i] = canvas.addText(font, TEXT);
            values[i] = canvas.addText(font, TEXT);
        }
        layOut(new ScreenRect(), 1f, "");
    }

    /**
     * The round number at or above a value: 1, 1.5, 2, 3, 4, 5, 6 or 8 times a power of ten.
     *
     * @param value the value (finite; &le;0 gives 1)
     * @return the round number (&ge;value, &gt;0)
     */
    public static double roundUp(double value) {
        return StripCanvas.roundUp(value);
    }

    /** @return the node to attach to the GUI scene (live, not null) */
    public Node getNode() {
        return canvas.getNode();
    }

    /**
     * Show or hide the bars.
     *
     * @param visible true to show them
     */
    public void setVisible(boolean visible) {
        canvas.setVisible(visible);
    }

    /** @return true if shown */
    public boolean isVisible() {
        return canvas.isVisible();
    }

    /**
     * Set the title line. Allocates nothing unless the text is longer than any before.
     *
     * @param text the title (not null, copied)
     */
    public void setTitle(CharSequence text) {
        title.setText(text);
    }

    /**
     * Set how many rows are shown; the layout keeps room for {@code maxRows}.
     *
     * @param count the rows (from 0 to maxRows)
     */
    public void setRowCount(int count) {
        if (count < 0 || count > maxRows) {
            throw new IllegalArgumentException("rows must be from 0 to " + maxRows
                    + ", but was " + count);
        }
        rows = count;
    }

    /**
     * Set one row: its name, its value and its colour. Allocates nothing.
     *
     * @param row the row (from 0, &lt; the row count)
     * @param name the name (not null, copied)
     * @param value the bar's signed value (in joules: right of zero if &gt;0)
     * @param color the bar's colour (not null, kept: pass a constant)
     */
    public void setRow(int row, CharSequence name, double value, ColorRGBA color) {
        if (row < 0 || row >= rows) {
            throw new IllegalArgumentException("row must be from 0 to " + (rows - 1)
                    + " (the row count is " + rows + ", at most " + maxRows + "), but was "
                    + row);
        }
        names[row].setText(name);
        joules[row] = value;
        rowColors[row] = color;
        valueText.setLength(0);
        // a small value (the numerical column, often) keeps its digits
        TextFormat.appendFixed(valueText, value, value != 0.0 && Math.abs(value) < 1.0 ? 4 : 2);
        values[row].setText(valueText);
    }

    /**
     * Set the scale: how many joules a full half-bar shows.
     *
     * @param joulesPerHalfBar the scale (in joules, finite, &gt;0)
     */
    public void setFullScale(double joulesPerHalfBar) {
        if (!(joulesPerHalfBar > 0.0) || Double.isInfinite(joulesPerHalfBar)) {
            throw new IllegalArgumentException("scale must be finite and > 0, but was "
                    + joulesPerHalfBar);
        }
        fullScale = joulesPerHalfBar;
    }

    /** @return how many rows are set */
    public int getRowCount() {
        return rows;
    }

    /** @return how many joules a full half-bar shows */
    public double getFullScale() {
        return fullScale;
    }

    /**
     * The width the strip needs at a text size: the widest name, the bars' least width and
     * the widest value, with the paddings.
     *
     * @param widestName the widest row name (not null)
     * @param size the text size (in pixels, &gt;0)
     * @return the width (in pixels)
     */
    public float widthFor(CharSequence widestName, float size) {
        return measure.width(widestName, size) + MIN_BAR_WIDTH_PER_TEXT_PIXEL * size
                + measure.width(WIDEST_VALUE, size) + 4f * PADDING * size;
    }

    /**
     * The height the strip needs at a text size for a number of rows and the title.
     *
     * @param rowCount the rows (&ge;0)
     * @param size the text size (in pixels, &gt;0)
     * @return the height (in pixels)
     */
    public float heightFor(int rowCount, float size) {
        return (rowCount + 1) * ROW_SPACING * measure.lineHeight(size) + 2f * PADDING * size;
    }

    /**
     * Fit the bars into a rectangle of the screen: the text at the size given, shrunk if
     * the rows or the widest name would not fit; rows that do not fit even so are hidden
     * from the second last up (the last row, the numerical one, stays).
     *
     * @param strip the strip (in pixels, not null, not modified; empty: nothing is drawn)
     * @param size the text's largest size (in pixels, &gt;0)
     * @param widestName the widest row name, for the layout (not null)
     */
    public void layOut(ScreenRect strip, float size, CharSequence widestName) {
        area.set(strip);
        if (strip.isEmpty()) {
            laidOut = false;
            canvas.getNode().setLocalTranslation(HIDDEN, HIDDEN, 0f);
            canvas.hideBackground();
            return;
        }
        laidOut = true;
        float wide = Math.max(widthFor(widestName, size),
                measure.width(WIDEST_TITLE, size) + 2f * PADDING * size);
        float fit = size * Math.min(1f, Math.min(strip.getWidth() / wide,
                strip.getHeight() / heightFor(rows, size)));
        textSize = Math.max(1f, fit);
        float pad = PADDING * textSize;
        rowHeight = ROW_SPACING * measure.lineHeight(textSize);
        barLeft = pad + measure.width(widestName, textSize) + pad;
        barRight = Math.max(barLeft, strip.getWidth() - pad
                - measure.width(WIDEST_VALUE, textSize) - pad);
        firstRowTop = strip.getHeight() - pad - rowHeight;
        rowsShown = Math.max(0, Math.min(rows, (int) Math.floor(firstRowTop / rowHeight)));
        canvas.getNode().setLocalTranslation(strip.getX(), strip.getY(), 0f);
        canvas.placeBackground(0f, 0f, strip.getWidth(), strip.getHeight());
        title.setSize(textSize);
        title.setLocalTranslation(pad, strip.getHeight() - pad, 1f);
        for (int i = 0; i < maxRows; ++i) {
            names[i].setSize(textSize);
            values[i].setSize(textSize);
        }
    }

    /**
     * Draw the rows as set: the bars, names and values. Allocates nothing.
     */
    public void refresh() {
        float pad = PADDING * textSize;
        float zero = 0.5f * (barLeft + barRight);
        float half = 0.5f * (barRight - barLeft);
        float thickness = BAR_THICKNESS * measure.lineHeight(textSize);
        for (int i = 0; i < maxRows; ++i) {
            int slot = slotOf(i);
            if (!laidOut || slot < 0) {
                quads.hide(i);
                names[i].setCullHint(Spatial.CullHint.Always);
                values[i].setCullHint(Spatial.CullHint.Always);
                continue;
            }
            float top = firstRowTop - slot * rowHeight;
            names[i].setCullHint(Spatial.CullHint.Inherit);
            values[i].setCullHint(Spatial.CullHint.Inherit);
            names[i].setLocalTranslation(pad, top, 1f);
            values[i].setLocalTranslation(barRight + pad, top, 1f);
            float middle = top - 0.5f * rowHeight;
            float fraction = (float) Math.max(-1.0, Math.min(1.0, joules[i] / fullScale));
            float end = zero + fraction * half;
            if (joules[i] != 0.0 && Math.abs(end - zero) < 1f) {
                // a value too small for a pixel still shows a sliver on its side
                end = zero + Math.signum(fraction);
            }
            quads.write(i, Math.min(zero, end), middle - 0.5f * thickness, Math.max(zero, end),
                    middle + 0.5f * thickness);
            if (writtenColors[i] != rowColors[i] && rowColors[i] != null) {
                writeColor(i, rowColors[i]);
            }
        }
        if (laidOut && rows > 0) {
            float axis = AXIS_HALF_WIDTH * textSize;
            float bottom = firstRowTop - rowsShown * rowHeight;
            quads.write(maxRows, zero - axis, bottom, zero + axis, firstRowTop);
        } else {
            quads.hide(maxRows);
        }
        quads.uploadWithColors();
    }

    /** @return the text size of the last layout (in pixels) */
    public float getTextSize() {
        return textSize;
    }

    /** @return how many rows the last layout and row count show */
    public int countRowsShown() {
        return rowsShown;
    }

    /** @return the value of a row as set (in joules) */
    public double getValue(int row) {
        return joules[row];
    }

    /** @return the text of a row's name (allocates: for tests) */
    public String getName(int row) {
        return names[row].getText();
    }

    /** @return the title's text (allocates: for tests) */
    public String getTitle() {
        return title.getText();
    }

    /**
     * The place of a row among those shown: the first rows while they fit, the last row
     * always (the numerical column).
     *
     * @return its slot from the top (from 0), or -1 if hidden
     */
    private int slotOf(int row) {
        if (row >= rows || rowsShown == 0) {
            return -1;
        }
        if (row == rows - 1) {
            return rowsShown - 1;
        }
        return row < rowsShown - 1 ? row : -1;
    }

    private void writeColor(int quad, ColorRGBA color) {
        quads.color(quad, color);
        if (quad < maxRows) {
            writtenColors[quad] = color;
        }
    }
}

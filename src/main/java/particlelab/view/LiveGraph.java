package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;
import java.util.List;

/**
 * A small live graph for the HUD's graph slot: height y and speed |V| against time, side by
 * side, one pair of curves per particle in its colour: the Euler particle solid, its exact
 * ghost dashed.
 *
 * <p>The samples live in a bounded buffer that always holds the whole flight since the last
 * {@link #clear}: one sample per recorded step until it is full, then every other sample is
 * dropped and only every second step is recorded, and so on (the time axis keeps starting at
 * 0). The axes run from 0 (or the lowest height) to a round number above the largest value
 * (1, 1.5, 2, 3, 4, 5, 6 or 8 times a power of ten), and only grow until the next clear.
 *
 * <p>The curves end at the graph's end sample: the newest offered ({@link #record}), kept or
 * skipped by the thinning, or the one of a recorded step shown after a step back
 * ({@link #showEnd}): then only the samples before its time are drawn, so the curves end at
 * the step shown; the later samples stay in the buffer for a step forward, and the next
 * {@link #record} drops those at or after its time (that future is gone).
 * {@link #refresh} writes the curves into preallocated line meshes; only a change of an axis's
 * range sets the labels' text ({@link HudText}s, rewritten in place).
 */
public final class LiveGraph {

    /** How many samples the graph keeps (a power of two, so halving stays exact). */
    public static final int CAPACITY = 256;
    /** Values per sample and particle: Euler y, Euler |V|, exact y, exact |V|. */
    private static final int VALUES = 4;
    private static final int PANELS = 2;
    private static final int KINDS = 2;
    private static final int FLOATS_PER_VERTEX = 3;
    /** A dash of the exact curve, and the gap after it (in pixels at text size 19). */
    private static final float DASH_PIXELS_PER_TEXT_PIXEL = 6f / 19f;
    /** Where an unused segment goes: off the screen. */
    private static final float HIDDEN = StripCanvas.HIDDEN;
    /** Padding inside the graph, as a fraction of the text size. */
    private static final float PADDING = 0.4f;
    private static final ColorRGBA FRAME = new ColorRGBA(0.45f, 0.5f, 0.6f, 1f);
    private static final ColorRGBA TEXT = new ColorRGBA(0.85f, 0.9f, 1f, 1f);
    /** How far the exact curve's colour is mixed toward white. */
    private static final float EXACT_LIGHTEN = 0.35f;
    /** The widest label the layout must fit into a panel, measured at layout. */
    private static final String WIDEST_LABEL = "speed |V| (m/s): 0 to 500";
    private static final String LEGEND = "solid Euler, dashed exact";
    /** The legend of a graph whose particles have no exact ghost: only solid curves. */
    static final String LEGEND_EULER_ONLY = "Euler (no exact path)";
    /** The labels' size, as a fraction of the scene labels' size. */
    private static final float TEXT_SHRINK = 0.85f;

    private final int series;
    private final TextMeasure measure;
    private final StripCanvas canvas;
    private final Geometry frame;
    private final FloatBuffer framePositions;
    private final VertexBuffer frameBuffer;
    private final FloatBuffer curvePositions;
    private final VertexBuffer curveBuffer;
    private final HudText[] labels = new HudText[4];
    private final StringBuilder labelText = new StringBuilder(64);
    private final ScreenRect[] labelRects = new ScreenRect[4];

    /** The samples: times (s), and VALUES values per particle per sample. */
    private final float[] times = new float[CAPACITY];
    private final float[] values;
    private int count;
    /** The end sample: its time (s) and values (as one sample of {@link #values}). */
    private float endTime;
    private final float[] endValues;
    private boolean hasEnd;
    /** Which flight the buffer holds: counted up by every {@link #clear}. */
    private int flight;
    /** The end shown is of another flight than the buffer's: no buffered sample is drawn. */
    private boolean endOfOtherFlight;
    /** Record every stride-th sample offered; the rest are skipped. */
    private int stride = 1;
    private int skipped;
    /** The data's extent since the last clear. */
    private float maxTime;
    private float minHeight;
    private float maxHeight;
    private float maxSpeed;
    /** The axes' ranges the labels show (NaN: not set yet). */
    private float axisTime = Float.NaN;
    private float axisLow = Float.NaN;
    private float axisHigh = Float.NaN;
    private float axisSpeed = Float.NaN;
    private boolean changed = true;
    /** True once a recorded sample holds an exact value, since the last {@link #clear()}. */
    private boolean exactSeen;
    /** The legend's text now: {@link #LEGEND} or {@link #LEGEND_EULER_ONLY}. */
    private String shownLegend;
    private boolean laidOut;
    private int labelChanges;
    /** The plots' boxes on the screen (pixels): left, bottom, width, height per panel. */
    private final float[] plotLeft = new float[PANELS];
    private float plotBottom;
    private float plotWidth;
    private float plotHeight;
    private float dashPixels = 6f;

    /**
     * Create a graph for some particles.
     *
     * @param assetManager loads the materials (not null)
     * @param font the labels' font (not null)
     * @param colors each particle's colour, in order (not null, at least one, not modified)
     */
    public LiveGraph(AssetManager assetManager, BitmapFont font, ColorRGBA[] colors) {
        if (colors == null || colors.length == 0) {
            throw new IllegalArgumentException("a graph needs at least one particle's colour");
        }
        series = colors.length;
        measure = TextMeasure.of(font);
        values = new float[CAPACITY * series * VALUES];
        endValues = new float[series * VALUES];
        canvas = new StripCanvas(assetManager, "live graph");
        Node node = canvas.getNode();

        // Two boxes: 4 segments each.
        framePositions = BufferUtils.createFloatBuffer(PANELS * 8 * FLOATS_PER_VERTEX);
        Mesh frameMesh = new Mesh();
        frameMesh.setMode(Mesh.Mode.Lines);
        frameMesh.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_VERTEX, framePositions);
        frameBuffer = frameMesh.getBuffer(VertexBuffer.Type.Position);
        Material frameColor = canvas.newUnshaded();
        frameColor.setColor("Color", FRAME);
        frame = new Geometry("live graph frame", frameMesh);
        frame.setMaterial(frameColor);
        frame.setQueueBucket(RenderQueue.Bucket.Gui);
        frame.setCullHint(Spatial.CullHint.Never);
        node.attachChild(frame);

        int vertices = segmentCount() * 2;
        curvePositions = BufferUtils.createFloatBuffer(vertices * FLOATS_PER_VERTEX);
        FloatBuffer curveColors = BufferUtils.createFloatBuffer(vertices * 4);
        for (int panel = 0; panel < PANELS; ++panel) {
            for (int particle = 0; particle < series; ++particle) {
                for (int kind = 0; kind < KINDS; ++kind) {
                    ColorRGBA c = colors[particle];
                    float lift = kind == 0 ? 0f : EXACT_LIGHTEN;
                    for (int v = 0; v < CAPACITY * 2; ++v) {
                        curveColors.put(c.r + lift * (1f - c.r)).put(c.g + lift * (1f - c.g))
                                .put(c.b + lift * (1f - c.b)).put(1f);
                    }
                }
            }
        }
        curveColors.flip();
        Mesh curveMesh = new Mesh();
        curveMesh.setMode(Mesh.Mode.Lines);
        curveMesh.setBuffer(VertexBuffer.Type.Position, FLOATS_PER_VERTEX, curvePositions);
        curveMesh.setBuffer(VertexBuffer.Type.Color, 4, curveColors);
        curveMesh.setStreamed();
        curveBuffer = curveMesh.getBuffer(VertexBuffer.Type.Position);
        Material lines = canvas.newUnshaded();
        lines.setBoolean("VertexColor", true);
        Geometry curves = new Geometry("live graph curves", curveMesh);
        curves.setMaterial(lines);
        curves.setQueueBucket(RenderQueue.Bucket.Gui);
        curves.setCullHint(Spatial.CullHint.Never);
        node.attachChild(curves);

        for (int i = 0; i < labels.length; ++i) {
            labels[i] = canvas.addText(font, TEXT);
            labelRects[i] = new ScreenRect();
        }
        shownLegend = LEGEND;
        labels[3].setText(LEGEND);
        clear();
    }

    /**
     * Access the node to attach to the GUI scene.
     *
     * @return the live node (not null)
     */
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

    /**
     * Test whether the graph is shown.
     *
     * @return true if shown
     */
    public boolean isVisible() {
        return canvas.isVisible();
    }

    /**
     * Forget every sample: a new flight starts at t = 0.
     */
    public void clear() {
        count = 0;
        ++flight;
        hasEnd = false;
        endOfOtherFlight = false;
        stride = 1;
        skipped = 0;
        maxTime = 0f;
        minHeight = 0f;
        maxHeight = 0f;
        maxSpeed = 0f;
        exactSeen = false;
        changed = true;
    }

    /**
     * Return how many samples the graph holds.
     *
     * @return the count (from 0 to {@link #CAPACITY})
     */
    public int size() {
        return count;
    }

    /**
     * Offer one sample of every particle: the curves end at it; it is kept in the buffer or
     * skipped as the buffer's thinning says. Buffered samples at or after its time are
     * dropped first (a step back, and a new step from there). Allocates nothing.
     *
     * @param seconds the time since the flight started (in seconds)
     * @param eulerHeights each particle's y (in metres, not null, one per particle)
     * @param eulerSpeeds each particle's |V| (in m/s, not null, one per particle)
     * @param exactHeights each exact ghost's y (in metres, not null, one per particle; NaN:
     *     not drawn)
     * @param exactSpeeds each exact ghost's |V| (in m/s, not null, one per particle; NaN: not
     *     drawn)
     */
    public void record(float seconds, float[] eulerHeights, float[] eulerSpeeds,
            float[] exactHeights, float[] exactSpeeds) {
        while (count > 0 && times[count - 1] >= seconds) {
            // Samples of a future dropped by a step back and a new step from there.
            --count;
        }
        setEnd(seconds, eulerHeights, eulerSpeeds, exactHeights, exactSpeeds);
        endOfOtherFlight = false;
        changed = true;
        if (count > 0 && skipped < stride - 1) {
            ++skipped;
            return;
        }
        skipped = 0;
        if (count == CAPACITY) {
            thin();
        }
        times[count] = seconds;
        int base = count * series * VALUES;
        for (int i = 0; i < series; ++i) {
            int at = base + i * VALUES;
            values[at] = eulerHeights[i];
            values[at + 1] = eulerSpeeds[i];
            values[at + 2] = exactHeights[i];
            values[at + 3] = exactSpeeds[i];
            exactSeen |= !Float.isNaN(exactHeights[i]) || !Float.isNaN(exactSpeeds[i]);
        }
        maxTime = Math.max(maxTime, seconds);
        ++count;
        changed = true;
    }

    /**
     * End the curves at a recorded step's sample, shown after a step back or forward: only
     * the buffered samples before its time are drawn (none if they are of another flight),
     * then this one. Keeps the buffer. Allocates nothing.
     *
     * @param flightNumber the {@link #getFlight()} the sample was taken in
     * @param seconds the sample's time since its flight started (in seconds)
     * @param eulerHeights each particle's y (in metres, not null, one per particle)
     * @param eulerSpeeds each particle's |V| (in m/s, not null, one per particle)
     * @param exactHeights each exact ghost's y (in metres, not null, one per particle; NaN:
     *     not drawn)
     * @param exactSpeeds each exact ghost's |V| (in m/s, not null, one per particle; NaN: not
     *     drawn)
     */
    public void showEnd(int flightNumber, float seconds, float[] eulerHeights,
            float[] eulerSpeeds, float[] exactHeights, float[] exactSpeeds) {
        setEnd(seconds, eulerHeights, eulerSpeeds, exactHeights, exactSpeeds);
        endOfOtherFlight = flightNumber != flight;
        changed = true;
    }

    /**
     * Return which flight the buffer holds: a number counted up by every {@link #clear}.
     *
     * @return the number
     */
    public int getFlight() {
        return flight;
    }

    /**
     * Count the samples the curves are drawn through: the buffered ones before the end
     * sample's time, and the end sample.
     *
     * @return the count (0 before the first sample, else from 1 to {@link #CAPACITY} + 1)
     */
    public int countDrawn() {
        return hasEnd ? countBeforeEnd() + 1 : 0;
    }

    /**
     * Return the time of the sample the curves end at.
     *
     * @return the time (in seconds; NaN before the first sample)
     */
    public float getEndTime() {
        return hasEnd ? endTime : Float.NaN;
    }

    /**
     * Return one value of the sample the curves end at.
     *
     * @param particle the particle (from 0)
     * @param exact true for the exact ghost, false for the Euler particle
     * @param speed true for |V| (m/s), false for y (m)
     * @return the value (NaN before the first sample)
     */
    public float getEndValue(int particle, boolean exact, boolean speed) {
        if (!hasEnd) {
            return Float.NaN;
        }
        return endValues[particle * VALUES + (exact ? 2 : 0) + (speed ? 1 : 0)];
    }

    /**
     * Return one recorded value.
     *
     * @param sample the sample (from 0 to {@code size() − 1})
     * @param particle the particle (from 0)
     * @param exact true for the exact ghost, false for the Euler particle
     * @param speed true for |V| (m/s), false for y (m)
     * @return the value
     */
    public float getValue(int sample, int particle, boolean exact, boolean speed) {
        return values[(sample * series + particle) * VALUES + (exact ? 2 : 0) + (speed ? 1 : 0)];
    }

    /**
     * Return one sample's time.
     *
     * @param sample the sample (from 0 to {@code size() − 1})
     * @return the time (in seconds)
     */
    public float getTime(int sample) {
        return times[sample];
    }

    /**
     * Count the times an axis label's text was set (a few times a flight).
     *
     * @return the count since the graph was created (&ge;0)
     */
    public int countLabelChanges() {
        return labelChanges;
    }

    /**
     * Fit the graph into a rectangle of the screen: two panels side by side, a label above
     * and below each, the text shrunk if a label would not fit its panel.
     *
     * @param area the graph's rectangle (in pixels, not null, not modified; empty: nothing is
     *     drawn)
     * @param textSize the labels' largest text size (in pixels, &gt;0)
     */
    public void layOut(ScreenRect area, float textSize) {
        if (area.isEmpty()) {
            laidOut = false;
            canvas.getNode().setLocalTranslation(0f, 0f, 0f);
            canvas.hideBackground();
            for (int i = 0; i < labels.length; ++i) {
                labelRects[i].set(0f, 0f, 0f, 0f);
            }
            return;
        }
        float largest = TEXT_SHRINK * textSize;
        float pad = PADDING * largest;
        float panelWidth = (area.getWidth() - (PANELS + 1) * pad) / PANELS;
        float size = largest * Math.min(1f, panelWidth / measure.width(WIDEST_LABEL, largest));
        float lineHeight = measure.lineHeight(size);
        pad = PADDING * size;
        panelWidth = (area.getWidth() - (PANELS + 1) * pad) / PANELS;
        canvas.placeBackground(area.getX(), area.getY(), area.getWidth(), area.getHeight());
        plotBottom = area.getY() + pad + lineHeight + pad;
        plotHeight = area.getTop() - pad - lineHeight - pad - plotBottom;
        plotWidth = panelWidth;
        for (int panel = 0; panel < PANELS; ++panel) {
            plotLeft[panel] = area.getX() + pad + panel * (panelWidth + pad);
        }
        for (int i = 0; i < labels.length; ++i) {
            int panel = i % PANELS;
            boolean top = i < PANELS;
            labels[i].setSize(size);
            float y = top ? area.getTop() - pad : area.getY() + pad + lineHeight;
            labels[i].setLocalTranslation(plotLeft[panel], y, 3f);
        }
        dashPixels = DASH_PIXELS_PER_TEXT_PIXEL * size;
        writeFrame();
        laidOut = plotWidth > 0f && plotHeight > 0f;
        axisTime = Float.NaN;
        changed = true;
    }

    /**
     * Copy the labels' rectangles into a list, for tests of the layout; none while hidden.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        if (!laidOut || !isVisible()) {
            return storeResult;
        }
        for (int i = 0; i < labels.length; ++i) {
            HudText label = labels[i];
            if (label.getChars().length() == 0) {
                continue;
            }
            storeResult.add(new ScreenRect(label.getLocalTranslation().x,
                    label.getLocalTranslation().y - label.getLineCount() * label.getLineHeight(),
                    measure.width(label.getChars(), label.getSize()),
                    label.getLineCount() * label.getLineHeight()));
        }
        return storeResult;
    }

    /**
     * Read the legend shown now.
     *
     * @return {@link #LEGEND_EULER_ONLY} if no sample since the last clear had an exact value
     */
    String getLegend() {
        return labels[3].getChars().toString();
    }

    /**
     * Write the curves into their mesh if samples came since the last refresh. Allocates
     * nothing, except when an axis's range grows (the labels' text is set then).
     */
    public void refresh() {
        if (!changed || !laidOut) {
            return;
        }
        changed = false;
        // The legend promises a dashed exact curve only where one is drawn.
        String legend = exactSeen ? LEGEND : LEGEND_EULER_ONLY;
        if (legend != shownLegend) {
            shownLegend = legend;
            labels[3].setText(legend);
        }
        updateAxes();
        int buffered = countBeforeEnd();
        int points = countDrawn();
        int segment = 0;
        for (int panel = 0; panel < PANELS; ++panel) {
            boolean speed = panel == 1;
            float low = speed ? 0f : axisLow;
            float high = speed ? axisSpeed : axisHigh;
            for (int particle = 0; particle < series; ++particle) {
                for (int kind = 0; kind < KINDS; ++kind) {
                    boolean exact = kind == 1;
                    float dash = 0f;
                    for (int s = 0; s < CAPACITY; ++s, ++segment) {
                        if (s + 1 >= points) {
                            writeSegment(segment, HIDDEN, HIDDEN, HIDDEN, HIDDEN);
                            continue;
                        }
                        float x0 = screenX(panel, drawnTime(s, buffered));
                        float x1 = screenX(panel, drawnTime(s + 1, buffered));
                        float y0 = screenY(drawnValue(s, buffered, particle, exact, speed),
                                low, high);
                        float y1 = screenY(drawnValue(s + 1, buffered, particle, exact, speed),
                                low, high);
                        boolean drawn = (!exact || ((int) (dash / dashPixels) & 1) == 0)
                                && !Float.isNaN(y0) && !Float.isNaN(y1);
                        if (exact) {
                            dash += (float) Math.hypot(x1 - x0, y1 - y0);
                        }
                        if (drawn) {
                            writeSegment(segment, x0, y0, x1, y1);
                        } else {
                            writeSegment(segment, HIDDEN, HIDDEN, HIDDEN, HIDDEN);
                        }
                    }
                }
            }
        }
        curvePositions.rewind();
        curveBuffer.updateData(curvePositions);
    }

    /** Make a sample the end, and widen the extent to it. */
    private void setEnd(float seconds, float[] eulerHeights, float[] eulerSpeeds,
            float[] exactHeights, float[] exactSpeeds) {
        endTime = seconds;
        hasEnd = true;
        for (int i = 0; i < series; ++i) {
            int at = i * VALUES;
            endValues[at] = eulerHeights[i];
            endValues[at + 1] = eulerSpeeds[i];
            endValues[at + 2] = exactHeights[i];
            endValues[at + 3] = exactSpeeds[i];
            minHeight = extent(minHeight, eulerHeights[i], exactHeights[i], false);
            maxHeight = extent(maxHeight, eulerHeights[i], exactHeights[i], true);
            maxSpeed = extent(maxSpeed, eulerSpeeds[i], exactSpeeds[i], true);
        }
        maxTime = Math.max(maxTime, seconds);
    }

    /** Count the buffered samples drawn: those before the end's time, of the end's flight. */
    private int countBeforeEnd() {
        if (endOfOtherFlight) {
            return 0;
        }
        int n = count;
        while (n > 0 && times[n - 1] >= endTime) {
            --n;
        }
        return n;
    }

    /** The time of the i-th point drawn: a buffered sample's, or the end's. */
    private float drawnTime(int point, int buffered) {
        return point < buffered ? times[point] : endTime;
    }

    /** A value of the i-th point drawn: a buffered sample's, or the end's. */
    private float drawnValue(int point, int buffered, int particle, boolean exact,
            boolean speed) {
        if (point < buffered) {
            return getValue(point, particle, exact, speed);
        }
        return getEndValue(particle, exact, speed);
    }

    /** Widen an extent to two values, leaving out NaN (a value the graph does not draw). */
    private static float extent(float current, float a, float b, boolean largest) {
        float result = current;
        if (!Float.isNaN(a)) {
            result = largest ? Math.max(result, a) : Math.min(result, a);
        }
        if (!Float.isNaN(b)) {
            result = largest ? Math.max(result, b) : Math.min(result, b);
        }
        return result;
    }

    /** Keep every other sample: the buffer holds the same flight at half the rate. */
    private void thin() {
        int perSample = series * VALUES;
        for (int j = 0; j < CAPACITY / 2; ++j) {
            times[j] = times[2 * j];
            System.arraycopy(values, 2 * j * perSample, values, j * perSample, perSample);
        }
        count = CAPACITY / 2;
        stride *= 2;
    }

    /** Set the axes' ranges from the data's extent; set the labels only if one changed. */
    private void updateAxes() {
        float time = roundUp(Math.max(maxTime, 1f));
        float high = roundUp(Math.max(maxHeight, 1f));
        float low = minHeight < 0f ? -roundUp(-minHeight) : 0f;
        float speed = roundUp(Math.max(maxSpeed, 1f));
        if (time == axisTime && high == axisHigh && low == axisLow && speed == axisSpeed) {
            return;
        }
        if (high != axisHigh || low != axisLow) {
            labelText.setLength(0);
            labelText.append("height y (m): ");
            appendEnd(labelText, low).append(" to ");
            appendEnd(labelText, high);
            labels[0].setText(labelText);
            ++labelChanges;
        }
        if (speed != axisSpeed) {
            labelText.setLength(0);
            labelText.append("speed |V| (m/s): 0 to ");
            appendEnd(labelText, speed);
            labels[1].setText(labelText);
            ++labelChanges;
        }
        if (time != axisTime) {
            labelText.setLength(0);
            labelText.append("time t (s): 0 to ");
            appendEnd(labelText, time);
            labels[2].setText(labelText);
            ++labelChanges;
        }
        axisTime = time;
        axisHigh = high;
        axisLow = low;
        axisSpeed = speed;
    }

    /**
     * Return the smallest round number at least a value: 1, 1.5, 2, 3, 4, 5, 6 or 8 times a
     * power of ten.
     *
     * @param value the value (&gt;0)
     * @return the round number
     */
    static float roundUp(float value) {
        return (float) StripCanvas.roundUp(value);
    }

    /** A range's end as a label shows it: a decimal only where it has one (1.5). */
    private static StringBuilder appendEnd(StringBuilder text, float value) {
        boolean whole = value == Math.rint(value);
        return TextFormat.appendFixed(text, value, whole ? 0 : 1);
    }

    private float screenX(int panel, float seconds) {
        return plotLeft[panel] + plotWidth * seconds / axisTime;
    }

    private float screenY(float value, float low, float high) {
        return plotBottom + plotHeight * (value - low) / (high - low);
    }

    private void writeSegment(int segment, float x0, float y0, float x1, float y1) {
        int out = segment * 2 * FLOATS_PER_VERTEX;
        curvePositions.put(out, x0).put(out + 1, y0).put(out + 2, 2f);
        curvePositions.put(out + 3, x1).put(out + 4, y1).put(out + 5, 2f);
    }

    private void writeFrame() {
        framePositions.clear();
        for (int panel = 0; panel < PANELS; ++panel) {
            float left = plotLeft[panel];
            float right = left + plotWidth;
            float top = plotBottom + plotHeight;
            line(left, plotBottom, right, plotBottom);
            line(right, plotBottom, right, top);
            line(right, top, left, top);
            line(left, top, left, plotBottom);
        }
        framePositions.flip();
        frameBuffer.updateData(framePositions);
    }

    private void line(float x0, float y0, float x1, float y1) {
        framePositions.put(x0).put(y0).put(1f).put(x1).put(y1).put(1f);
    }

    private int segmentCount() {
        return PANELS * series * KINDS * CAPACITY;
    }
}

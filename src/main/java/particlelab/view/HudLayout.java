package particlelab.view;

import java.util.ArrayList;
import java.util.List;

/**
 * Where the HUD's text goes on a window of a given size: pure arithmetic on the window's size
 * and the text's measured size, so it is tested without rendering. Top to bottom: the title,
 * the body (equations and live numbers), then the scene down to the window's bottom edge: the
 * warning band is drawn over its sky (kept even when empty, so the scene does not jump when a
 * warning comes and goes) and the footer on its ground, below {@link #getSceneFloor()}. Two
 * optional slots: a side panel down the right edge, between the title and the footer (the
 * body, warning and scene then stay left of it), a graph in the scene's top right corner,
 * below the warning band, and the energy ledger's strip down the scene's right edge, from
 * below the warning band to the footer's top (the scene then stays left of it, so no body
 * flies under it).
 * Each is asked for by its size at HUD scale 1 and is empty when not asked for. The
 * help overlay covers everything below the title and is set in columns, its first section (the
 * demo's own keys) first; it shrinks its text until every column fits the window.
 *
 * <p>Text wider than the window is wrapped at spaces, continuation lines indented, a number
 * kept on one line with its unit. The body keeps the most lines it has needed so far
 * ({@link #getBodyLinesNeeded()}), so that the numbers changing from one refresh to the next
 * never move the scene.
 *
 * <h2>A small window</h2>
 * At any size the layout gives every view a rectangle inside the window, and the scene at
 * least {@value #MIN_SCENE_SHARE} of the window's height; it never throws for a size &gt; 0.
 * Text too large for the window gives way in this order:
 * <ol>
 * <li>the text shrinks: {@link HudScale#layOut} lowers the HUD scale, down to
 * {@link HudScale#MIN_SCALE}, while this layout reports {@link #isTooSmall()};</li>
 * <li>at the smallest scale, HUD lines are hidden, least important first: the footer's key
 * summary gives its place to one line "window too small (WxH): HUD lines hidden" (the help
 * still lists every key), then the warning band's second line, then the body's lines from
 * its end (the equations at its top stay longest), and last the warning band's first
 * line;</li>
 * <li>the help overlay, at its smallest text, keeps the columns that fit and ends with
 * "{@value #HELP_CUT_LINE}".</li>
 * </ol>
 * {@link #getBodyLines()} and {@link #getWarningLines()} say how many lines each band shows;
 * the text beyond is not drawn. The simulation is not touched: a small window only shows less.
 * From {@value #MIN_WIDTH}x{@value #MIN_HEIGHT} up no two texts overlap; below that the scene
 * still gets a rectangle inside the window (at least one pixel high), over the title if need
 * be.
 */
public final class HudLayout {

    /** Text sizes at HUD scale 1 (in pixels). */
    public static final float TITLE_SIZE = 32f;
    public static final float BODY_SIZE = 21f;
    public static final float WARNING_SIZE = 22f;
    public static final float FOOTER_SIZE = 19f;
    public static final float HELP_SIZE = 21f;
    /**
     * Presentation mode's text, the title, the formula lines and the readout (pixels at scale
     * 1): twice the body's, so it stays at least twice the full HUD's body at the same factor
     * (the full HUD's shrinks on a crowded window, this one rarely needs to).
     */
    public static final float PRESENT_SIZE = 2f * BODY_SIZE;
    /** Scene labels: grid distances, particle and post labels (pixels at scale 1). */
    public static final float SCENE_LABEL_SIZE = 19f;
    /** The smallest help text the shrinking goes to (pixels at scale 1). */
    public static final float MIN_HELP_SIZE = 11f;
    /** The space between the window's edge and any text (pixels at scale 1). */
    public static final float MARGIN = 14f;
    /** How many lines the warning band holds. */
    public static final int WARNING_LINES = 2;
    /** The window size at which the HUD scale is 1 (in pixels). */
    public static final float REFERENCE_WIDTH = 1280f;
    public static final float REFERENCE_HEIGHT = 720f;
    /** The HUD scale's range: text stays legible and leaves room for the scene. */
    public static final float MIN_SCALE = 0.75f;
    public static final float MAX_SCALE = 4f;
    /** The least share of the window's height the scene gets, at any size. */
    public static final float MIN_SCENE_SHARE = 0.4f;
    /**
     * The least share of the window's height a slide leaves the scene (presentation mode):
     * where the title and every formula row would take more, the formula rows beyond are
     * hidden, the second formula line's first, at least one row kept, and the footer says so
     * (issue 29 §3: the hall command, {@code --ui-scale 1.25} at 1920x1080, left the scene
     * 62-70 % of the window with two or three formula rows of 79 px type).
     */
    public static final float PRESENT_SCENE_SHARE = 0.75f;
    /**
     * The least a slide's title shrinks to, to stay on one row (a fraction of {@link
     * #PRESENT_SIZE}): a tour stop's title, the demo's and the stop's names, took two or three
     * rows of the hall command's 79 px type.
     */
    public static final float MIN_PRESENT_TITLE_FRACTION = 0.7f;
    /** The footer's note on a slide whose formula rows were cut to leave the scene its share. */
    public static final String FORMULAS_CUT_NOTE = "     formulas cut to fit (F8: all)";
    /** The smallest window laid out with no text over another (in pixels). */
    public static final int MIN_WIDTH = 200;
    public static final int MIN_HEIGHT = 150;
    /** The last help line when the window cannot hold the whole help. */
    public static final String HELP_CUT_LINE = "(window too small: more help hidden)";
    private static final String CONTINUATION = "    ";
    /** Scratch for {@link #wrapLine}: a group moved down to the next line. */
    private final StringBuilder spill = new StringBuilder(128);
    /** The longest word a wrap keeps with the number before it, as its unit (characters). */
    private static final int MAX_UNIT_CHARS = 5;
    /** The space above and below the body (in body line heights). */
    private static final float BAND_SPACE = 0.2f;
    /** Presentation mode's space below the title and the formulas (in its line heights). */
    private static final float PRESENT_BAND_SPACE = 0.1f;
    private static final float HELP_SHRINK = 0.98f;
    /** The most columns the help is set in. */
    private static final int MAX_HELP_COLUMNS = 5;
    /** The largest share of the window's width the side panel takes. */
    private static final float MAX_PANEL_SHARE = 0.4f;
    /** The largest share of the scene's width and height the graph takes. */
    private static final float MAX_GRAPH_SHARE = 0.45f;
    /** The largest share of the width left of the side panel the ledger's strip takes. */
    private static final float MAX_LEDGER_SHARE = 0.35f;
    /** The least a view's rectangle is high, however small the window (in pixels). */
    private static final float MIN_VIEW_PIXELS = 1f;

    private final TextMeasure measure;
    private final ScreenRect window = new ScreenRect();
    private final ScreenRect title = new ScreenRect();
    private final ScreenRect body = new ScreenRect();
    private final ScreenRect warning = new ScreenRect();
    private final ScreenRect footer = new ScreenRect();
    /** Presentation mode's readout, above the footer on the scene's ground (empty if not). */
    private final ScreenRect readout = new ScreenRect();
    private final ScreenRect scene = new ScreenRect();
    private final ScreenRect helpPanel = new ScreenRect();
    private final ScreenRect sidePanel = new ScreenRect();
    private final ScreenRect graph = new ScreenRect();
    private final ScreenRect ledger = new ScreenRect();
    private final List<ScreenRect> helpColumns = new ArrayList<>();
    private final List<String> helpColumnTexts = new ArrayList<>();
    private float scale = 1f;
    private float helpSize = HELP_SIZE;
    /**
     * What the help's columns were last laid out for: its text, its panel's width and height
     * and the HUD scale (the help depends on nothing else). A body that grew a line, a new
     * footer or title re-lays the HUD out, but not the help, which at a small window tries
     * every size from {@link #HELP_SIZE} down in up to {@value #MAX_HELP_COLUMNS} column
     * counts (about 160 flows of every help line: most of a small window's layout time).
     */
    private String helpLaidOutText;
    /**
     * The help text of the last layout: its columns are laid out when first asked for (the
     * help is shown on request, and a HUD laid out again at every resize need not flow it).
     */
    private String helpToLayOut = "";
    private float helpLaidOutWidth = -1f;
    private float helpLaidOutHeight = -1f;
    private float helpLaidOutScale = -1f;
    /** How many times the help was flowed into columns (for tests of the layout's work). */
    private int helpFlows;
    /** The most lines the body has needed so far, wrapped. */
    private int bodyLinesNeeded = 1;
    /** The lines the body band shows: all it needs, or fewer on a small window. */
    private int bodyLines = 1;
    /** The lines the warning band holds. */
    private int warningLines = WARNING_LINES;
    /** True when the window cannot hold every HUD line (some are hidden). */
    private boolean tooSmall;
    private String titleText = "";
    private String footerText = "";
    /** The side panel's width at HUD scale 1 (pixels; 0: no panel). */
    private float panelWidth;
    /** The side panel's own scale ({@link #getPanelScale}). */
    private float panelScale = 1f;
    /** The graph's size at HUD scale 1 (pixels; 0: no graph). */
    private float graphWidth;
    private float graphHeight;
    /** The ledger strip's size at HUD scale 1 (pixels; 0: no strip). */
    private float ledgerWidth;
    private float ledgerHeight;
    /** How high above the window's bottom the scene's ground must reach (in pixels). */
    private float sceneFloor;
    /** True when laid out for presentation mode ({@link #layOutPresentation}). */
    private boolean presenting;
    /** The slide's title size (pixels): the presentation size, less where it is too wide. */
    private float presentTitleSize;
    /** Presentation mode: the readout, wrapped, and the most lines it has needed so far. */
    private String readoutText = "";
    private int readoutLinesNeeded = 1;
    /** The lines the readout shows (0 when a small window hides it). */
    private int readoutLines = 1;
    /** The user's factor on the scale that suits the window ({@code --ui-scale}, F9/F10). */
    private float userFactor = 1f;

    /**
     * Create a layout.
     *
     * @param measure measures text as it will be drawn (not null)
     */
    public HudLayout(TextMeasure measure) {
        if (measure == null) {
            throw new IllegalArgumentException("measure must not be null");
        }
        this.measure = measure;
    }

    /**
     * Return the HUD scale that suits a window: 1 at 1280x720, growing with the window's
     * smaller relative side, within [{@value #MIN_SCALE}, {@value #MAX_SCALE}].
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @return the scale
     */
    public static float scaleFor(float width, float height) {
        float fit = Math.min(width / REFERENCE_WIDTH, height / REFERENCE_HEIGHT);
        return Math.max(MIN_SCALE, Math.min(MAX_SCALE, fit));
    }

    /**
     * Lay the HUD out on a window.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param hudScale the text scale ({@link #scaleFor} suits the window; &gt;0)
     * @param titleLine the title (not null)
     * @param bodyText the body as it is now (not null); the band keeps at least as many lines
     *     as it had before
     * @param footerLine the footer (not null)
     * @param helpText the help overlay's text: sections separated by blank lines (not null)
     */
    public void layOut(float width, float height, float hudScale, CharSequence titleLine,
            CharSequence bodyText, CharSequence footerLine, CharSequence helpText) {
        if (!(width > 0f && height > 0f && hudScale > 0f)) {
            throw new IllegalArgumentException("window " + width + "x" + height + " and scale "
                    + hudScale + " must all be > 0");
        }
        presenting = false;
        window.set(0f, 0f, width, height);
        scale = hudScale;
        readout.set(0f, 0f, 0f, 0f);
        readoutText = "";
        float margin = getMargin();
        float gap = 0.5f * margin;
        float titleWidth = Math.max(1f, width - 2f * margin);

        titleText = wrap(titleLine, getTitleSize(), titleWidth);
        float titleHeight = countLines(titleText) * measure.lineHeight(getTitleSize());
        title.set(margin, height - margin - titleHeight,
                measure.width(titleText, getTitleSize()), titleHeight);

        panelScale = panelScaleFor(width, height, hudScale);
        float panelPixels = panelWidth <= 0f ? 0f
                : Math.min(panelWidth * panelScale, MAX_PANEL_SHARE * width);
        float leftWidth = width - panelPixels;
        float textWidth = Math.max(1f, leftWidth - 2f * margin);

        float bodyLineHeight = measure.lineHeight(getBodySize());
        float warningLineHeight = measure.lineHeight(getWarningSize());
        float footerLineHeight = measure.lineHeight(getFooterSize());
        bodyLinesNeeded = Math.max(bodyLinesNeeded,
                countLines(wrap(bodyText, getBodySize(), textWidth)));
        String keys = wrap(footerLine, getFooterSize(), titleWidth);
        // Room for the body, the warning band and the footer: the window less the margins,
        // the title, the spaces around the body, the gaps around the scene and the scene's
        // least share.
        float room = height - 2f * margin - titleHeight - 2f * BAND_SPACE * bodyLineHeight
                - 2f * gap - MIN_SCENE_SHARE * height;
        float needed = bodyLinesNeeded * bodyLineHeight + WARNING_LINES * warningLineHeight
                + countLines(keys) * footerLineHeight;
        tooSmall = needed > room;
        if (tooSmall) {
            footerText = wrap(tooSmallLine(width, height, "HUD lines hidden"),
                    getFooterSize(), titleWidth);
            float left = room - countLines(footerText) * footerLineHeight;
            warningLines = left >= warningLineHeight ? 1 : 0;
            left -= warningLines * warningLineHeight;
            bodyLines = Math.max(0, Math.min(bodyLinesNeeded,
                    (int) Math.floor(left / bodyLineHeight)));
            left -= bodyLines * bodyLineHeight;
            while (warningLines > 0 && warningLines < WARNING_LINES
                    && left >= warningLineHeight) {
                ++warningLines;
                left -= warningLineHeight;
            }
        } else {
            footerText = keys;
            bodyLines = bodyLinesNeeded;
            warningLines = WARNING_LINES;
        }

        float bodyTop = title.getY() - BAND_SPACE * bodyLineHeight;
        body.set(margin, bodyTop - bodyLines * bodyLineHeight, textWidth,
                bodyLines * bodyLineHeight);
        float warningHeight = warningLines * warningLineHeight;
        warning.set(margin, body.getY() - BAND_SPACE * bodyLineHeight - warningHeight, textWidth,
                warningHeight);
        float footerHeight = countLines(footerText) * footerLineHeight;
        footer.set(margin, margin, measure.width(footerText, getFooterSize()), footerHeight);

        // The scene reaches from the window's bottom edge (the footer is drawn on its ground,
        // above sceneFloor) up to the body: the warning band is drawn over its sky, so no
        // empty strip is kept between the HUD and the scene. Below the smallest window the
        // texts cannot all fit: the scene still gets a rectangle of at least a pixel.
        sceneFloor = footer.getTop() + gap;
        float sceneHeight = Math.max(MIN_VIEW_PIXELS, warning.getTop());
        float ledgerPixels = placeLedger(leftWidth, warning.getY() - gap, margin);
        scene.set(0f, 0f, Math.max(MIN_VIEW_PIXELS, leftWidth - ledgerPixels),
                Math.min(sceneHeight, height));
        if (panelPixels > 0f) {
            float panelBottom = footer.getTop() + gap;
            sidePanel.set(leftWidth, panelBottom, panelPixels - margin,
                    title.getY() - gap - panelBottom);
        } else {
            sidePanel.set(0f, 0f, 0f, 0f);
        }
        if (graphWidth > 0f && graphHeight > 0f) {
            float graphW = Math.min(graphWidth * scale, MAX_GRAPH_SHARE * scene.getWidth());
            float graphH = Math.min(graphHeight * scale, MAX_GRAPH_SHARE * scene.getHeight());
            float graphTop = Math.min(scene.getTop(), warning.getY() - gap);
            graphH = Math.max(0f, Math.min(graphH, graphTop - sceneFloor));
            graph.set(scene.getRight() - margin - graphW, graphTop - graphH, graphW, graphH);
        } else {
            graph.set(0f, 0f, 0f, 0f);
        }
        helpToLayOut = helpText.toString();
    }

    /**
     * Lay presentation mode out on a window (F8, {@code --present}): the scene large, the text
     * reduced to the title and the slide's formula lines at the top, and its readout above a
     * one-line footer on the scene's ground, all at {@link #PRESENT_SIZE} but the footer. No
     * warning band, no side panel (the graph keeps its slot in the scene's corner). The
     * {@link #getBody()} band holds the formula lines, at {@link #getBodySize()} (the
     * presentation size while so laid out). On a window too small for every line at the
     * smallest scale, lines go in this order: the second formula line, the first, then the
     * readout; the footer then says the window is too small. Every rectangle stays inside
     * the window.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param hudScale the text scale ({@link #scaleFor} suits the window; &gt;0)
     * @param titleLine the title (not null)
     * @param formulaText the slide's formula lines (not null); the band keeps at least as many
     *     lines as it had before
     * @param readoutLine the slide's readout (not null); likewise
     * @param footerLine the footer, one short line (not null)
     * @param helpText the help overlay's text, as for {@link #layOut} (not null)
     */
    public void layOutPresentation(float width, float height, float hudScale,
            CharSequence titleLine, CharSequence formulaText, CharSequence readoutLine,
            CharSequence footerLine, CharSequence helpText) {
        if (!(width > 0f && height > 0f && hudScale > 0f)) {
            throw new IllegalArgumentException("window " + width + "x" + height + " and scale "
                    + hudScale + " must all be > 0");
        }
        presenting = true;
        window.set(0f, 0f, width, height);
        scale = hudScale;
        float margin = getMargin();
        float gap = 0.5f * margin;
        float textWidth = Math.max(1f, width - 2f * margin);
        float size = getBodySize();
        float lineHeight = measure.lineHeight(size);
        float footerLineHeight = measure.lineHeight(getFooterSize());

        // The title on one row where a smaller size down to the least fraction does it.
        presentTitleSize = PRESENT_SIZE * scale;
        float titleWidth = measure.width(titleLine, presentTitleSize);
        if (titleWidth > textWidth) {
            presentTitleSize = Math.max(MIN_PRESENT_TITLE_FRACTION * presentTitleSize,
                    presentTitleSize * textWidth / titleWidth);
        }
        titleText = wrap(titleLine, getTitleSize(), textWidth);
        float titleHeight = countLines(titleText) * measure.lineHeight(getTitleSize());
        bodyLinesNeeded = Math.max(bodyLinesNeeded,
                countLines(wrap(formulaText, size, textWidth)));
        readoutText = wrap(readoutLine, size, textWidth);
        readoutLinesNeeded = Math.max(readoutLinesNeeded, countLines(readoutText));
        String keys = wrap(footerLine, getFooterSize(), textWidth);
        float room = height - 2f * margin - titleHeight - 2f * PRESENT_BAND_SPACE * lineHeight
                - 2f * gap - MIN_SCENE_SHARE * height;
        float needed = (bodyLinesNeeded + readoutLinesNeeded) * lineHeight
                + countLines(keys) * footerLineHeight;
        tooSmall = needed > room;
        if (tooSmall) {
            footerText = wrap(tooSmallLine(width, height, "lines hidden"), getFooterSize(),
                    textWidth);
            float left = room - countLines(footerText) * footerLineHeight;
            readoutLines = Math.max(0, Math.min(readoutLinesNeeded,
                    (int) Math.floor(left / lineHeight)));
            left -= readoutLines * lineHeight;
            bodyLines = Math.max(0, Math.min(bodyLinesNeeded,
                    (int) Math.floor(left / lineHeight)));
        } else {
            footerText = keys;
            readoutLines = readoutLinesNeeded;
            bodyLines = bodyLinesNeeded;
        }
        // The scene's share: the title and the formula rows above it take at most the rest
        // of the height; rows beyond are hidden from the end, one always kept.
        float top = margin + titleHeight + 2f * PRESENT_BAND_SPACE * lineHeight;
        float most = (1f - PRESENT_SCENE_SHARE) * height;
        int shown = bodyLines;
        while (bodyLines > 1 && top + bodyLines * lineHeight > most) {
            --bodyLines;
        }
        if (!tooSmall && bodyLines < shown) {
            footerText = wrap(keys + FORMULAS_CUT_NOTE, getFooterSize(), textWidth);
        }
        warningLines = 0;

        title.set(margin, height - margin - titleHeight,
                measure.width(titleText, getTitleSize()), titleHeight);
        float bodyTop = title.getY() - PRESENT_BAND_SPACE * lineHeight;
        body.set(margin, bodyTop - bodyLines * lineHeight, textWidth, bodyLines * lineHeight);
        warning.set(margin, body.getY() - PRESENT_BAND_SPACE * lineHeight, textWidth, 0f);
        float footerHeight = countLines(footerText) * footerLineHeight;
        footer.set(margin, margin, measure.width(footerText, getFooterSize()), footerHeight);
        float readoutHeight = readoutLines * lineHeight;
        // The whole width: the readout's numbers change every frame, its strip does not.
        readout.set(margin, readoutHeight > 0f ? footer.getTop() + gap : footer.getTop(),
                readoutLines == 0 ? 0f : textWidth, readoutHeight);

        sceneFloor = readout.getTop() + gap;
        float ledgerPixels = placeLedger(width, warning.getY() - gap, margin);
        scene.set(0f, 0f, Math.max(MIN_VIEW_PIXELS, width - ledgerPixels),
                Math.min(height, Math.max(MIN_VIEW_PIXELS, warning.getTop())));
        sidePanel.set(0f, 0f, 0f, 0f);
        if (graphWidth > 0f && graphHeight > 0f) {
            float graphW = Math.min(graphWidth * scale, MAX_GRAPH_SHARE * scene.getWidth());
            float graphH = Math.min(graphHeight * scale, MAX_GRAPH_SHARE * scene.getHeight());
            float graphTop = Math.min(scene.getTop(), warning.getY() - gap);
            graphH = Math.max(0f, Math.min(graphH, graphTop - sceneFloor));
            graph.set(scene.getRight() - margin - graphW, graphTop - graphH, graphW, graphH);
        } else {
            graph.set(0f, 0f, 0f, 0f);
        }
        helpToLayOut = helpText.toString();
    }

    /**
     * Say which user's factor the next layouts serve, so that the footer of a window too
     * small for the text names the factor asked for and the one the window allowed.
     *
     * @param factor the user's factor on the scale that suits the window (&gt;0)
     */
    public void setUserFactor(float factor) {
        if (!(factor > 0f && factor < Float.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("user factor must be finite and > 0, but was "
                    + factor);
        }
        userFactor = factor;
    }

    /**
     * Ask for a side panel, or none; it takes effect at the next {@link #layOut}.
     *
     * @param widthAtScaleOne the panel's width at HUD scale 1 (in pixels, &ge;0; 0: no panel);
     *     the layout gives it at most {@value #MAX_PANEL_SHARE} of the window's width
     */
    public void setPanelWidth(float widthAtScaleOne) {
        if (!(widthAtScaleOne >= 0f && widthAtScaleOne < Float.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("panel width " + widthAtScaleOne
                    + " must be finite and >= 0");
        }
        panelWidth = widthAtScaleOne;
    }

    /**
     * Ask for a graph in the scene's top right corner, or none; it takes effect at the next
     * {@link #layOut}.
     *
     * @param widthAtScaleOne the graph's width at HUD scale 1 (in pixels, &ge;0; 0: no graph)
     * @param heightAtScaleOne its height at HUD scale 1 (in pixels, &ge;0; 0: no graph); the
     *     layout gives it at most {@value #MAX_GRAPH_SHARE} of the scene's width and height
     */
    public void setGraphSize(float widthAtScaleOne, float heightAtScaleOne) {
        if (!(widthAtScaleOne >= 0f && widthAtScaleOne < Float.POSITIVE_INFINITY
                && heightAtScaleOne >= 0f && heightAtScaleOne < Float.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("graph size " + widthAtScaleOne + "x"
                    + heightAtScaleOne + " must be finite and >= 0");
        }
        graphWidth = widthAtScaleOne;
        graphHeight = heightAtScaleOne;
    }

    /**
     * Ask for the energy ledger's strip down the scene's right edge, or none; it takes effect
     * at the next {@link #layOut} or {@link #layOutPresentation}.
     *
     * @param widthAtScaleOne the strip's width at HUD scale 1 (in pixels, &ge;0; 0: none); the
     *     layout gives it at most {@value #MAX_LEDGER_SHARE} of the width left of the panel
     * @param heightAtScaleOne its height at HUD scale 1 (in pixels, &ge;0; 0: none); the
     *     layout gives it at most the height from the footer's top to below the warning band
     */
    public void setLedgerSize(float widthAtScaleOne, float heightAtScaleOne) {
        if (!(widthAtScaleOne >= 0f && widthAtScaleOne < Float.POSITIVE_INFINITY
                && heightAtScaleOne >= 0f && heightAtScaleOne < Float.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("ledger size " + widthAtScaleOne + "x"
                    + heightAtScaleOne + " must be finite and >= 0");
        }
        ledgerWidth = widthAtScaleOne;
        ledgerHeight = heightAtScaleOne;
    }

    /**
     * Forget how many lines the body has needed so far, so that the next {@link #layOut}
     * sizes its band for the body as it is: for a new window size or HUD scale, where the old
     * count (wrapped for another width or text size) means nothing.
     */
    public void forgetBodyLines() {
        bodyLinesNeeded = 1;
        readoutLinesNeeded = 1;
    }

    /**
     * Test whether the window is too small for every HUD line at this scale: then the footer
     * says so and some lines are hidden (see the class's Javadoc).
     *
     * @return true if lines are hidden
     */
    public boolean isTooSmall() {
        return tooSmall;
    }

    /**
     * Return the first lines of a text, for a band that holds only so many.
     *
     * @param text the text (not null)
     * @param maxLines how many lines to keep (&ge;0)
     * @return its first maxLines lines, or all of it if it has no more (not null, new)
     */
    public static CharSequence firstLines(CharSequence text, int maxLines) {
        return firstLines(text, maxLines, new StringBuilder(text.length())).toString();
    }

    /**
     * Copy the first lines of a text into storeResult, allocating nothing once it is large
     * enough (what the HUD does every refresh).
     *
     * @param text the text (not null, not modified)
     * @param maxLines how many lines to keep (&ge;0)
     * @param storeResult storage for the lines kept (not null, cleared and modified)
     * @return storeResult
     */
    public static StringBuilder firstLines(CharSequence text, int maxLines,
            StringBuilder storeResult) {
        storeResult.setLength(0);
        int lines = 0;
        for (int i = 0; i < text.length() && maxLines > 0; ++i) {
            char c = text.charAt(i);
            if (c == '\n' && ++lines >= maxLines) {
                break;
            }
            storeResult.append(c);
        }
        return storeResult;
    }

    /**
     * Count the lines of a text.
     *
     * @param text the text (not null)
     * @return one more than its newlines (&ge;1)
     */
    public static int countLines(CharSequence text) {
        int lines = 1;
        for (int i = 0; i < text.length(); ++i) {
            if (text.charAt(i) == '\n') {
                ++lines;
            }
        }
        return lines;
    }

    /** @return the side panel (live, do not modify; empty when none was asked for) */
    public ScreenRect getSidePanel() {
        return sidePanel;
    }

    /** @return the graph's rectangle (live, do not modify; empty when none was asked for) */
    public ScreenRect getGraph() {
        return graph;
    }

    /**
     * @return the energy ledger's strip (live, do not modify; empty when none was asked for
     *     or the window leaves it no room)
     */
    public ScreenRect getLedger() {
        return ledger;
    }

    /**
     * Wrap a text to a width with the font of this layout: each line wider than the width is
     * broken at spaces, its continuation lines indented.
     *
     * @param text the text (not null)
     * @param size the text size (in pixels, &gt;0)
     * @param maxWidth the widest a line may be (in pixels, &gt;0)
     * @return the wrapped text (not null)
     */
    public String wrap(CharSequence text, float size, float maxWidth) {
        if (measure.width(text, size) <= maxWidth) {
            return text.toString();
        }
        return wrap(text, size, maxWidth, new StringBuilder(),
                new StringBuilder(text.length() + 16)).toString();
    }

    /**
     * Wrap a text like {@link #wrap(CharSequence, float, float)}, into a builder: allocates
     * nothing once the builders have held texts this long (a HUD refreshed every frame).
     *
     * @param text the text (not null, not modified, not one of the builders)
     * @param size the text size (in pixels, &gt;0)
     * @param maxWidth the widest a line may be (in pixels, &gt;0)
     * @param line scratch for one line (not null, modified)
     * @param storeResult storage for the wrapped text (not null, cleared and modified)
     * @return storeResult
     */
    public StringBuilder wrap(CharSequence text, float size, float maxWidth, StringBuilder line,
            StringBuilder storeResult) {
        storeResult.setLength(0);
        int start = 0;
        int length = text.length();
        while (start <= length) {
            int end = start;
            while (end < length && text.charAt(end) != '\n') {
                ++end;
            }
            wrapLine(text, start, end, size, maxWidth, line, storeResult);
            if (end < length) {
                storeResult.append('\n');
            }
            start = end + 1;
        }
        return storeResult;
    }

    /**
     * Return the side panel's scale: the HUD's, but never below what puts the panel's text
     * at {@link ParameterPanel#MIN_TEXT_PIXELS} where the window suits that ({@link
     * #scaleFor} reaches it: 1280x720 and up). The body's band may shrink the HUD's scale to
     * fit its lines; the panel has a column of its own and keeps its text legible.
     *
     * @return the scale (&gt;0)
     */
    public float getPanelScale() {
        return panelScale;
    }

    /**
     * Return the side panel's scale for a window and a HUD scale (see {@link
     * #getPanelScale}).
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param hudScale the HUD's scale (&gt;0)
     * @return the scale (&gt;0)
     */
    public static float panelScaleFor(float width, float height, float hudScale) {
        float legible = ParameterPanel.MIN_TEXT_PIXELS / ParameterPanel.TEXT_SIZE;
        return Math.max(hudScale, Math.min(legible, scaleFor(width, height)));
    }

    /** @return the HUD scale in use */
    public float getScale() {
        return scale;
    }

    /** @return the space kept from the window's edges (in pixels) */
    public float getMargin() {
        return MARGIN * scale;
    }

    /**
     * @return the title's text size (in pixels; when presenting the presentation size, or
     *     down to {@value #MIN_PRESENT_TITLE_FRACTION} of it where that keeps it on one row)
     */
    public float getTitleSize() {
        return presenting ? presentTitleSize : TITLE_SIZE * scale;
    }

    /**
     * @return the body's text size (in pixels; when presenting, the formula lines' and the
     *     readout's, the presentation size)
     */
    public float getBodySize() {
        return (presenting ? PRESENT_SIZE : BODY_SIZE) * scale;
    }

    /** @return true if laid out for presentation mode ({@link #layOutPresentation}) */
    public boolean isPresenting() {
        return presenting;
    }

    /** @return presentation mode's readout (live, do not modify; empty if not presenting) */
    public ScreenRect getReadout() {
        return readout;
    }

    /** @return how many lines the readout shows (0 if hidden or not presenting) */
    public int getReadoutLines() {
        return presenting ? readoutLines : 0;
    }

    /** @return the most lines the readout has needed so far, wrapped */
    public int getReadoutLinesNeeded() {
        return readoutLinesNeeded;
    }

    /** @return the warning's text size (in pixels) */
    public float getWarningSize() {
        return WARNING_SIZE * scale;
    }

    /** @return the footer's text size (in pixels) */
    public float getFooterSize() {
        return FOOTER_SIZE * scale;
    }

    /** @return the scene labels' text size (in pixels) */
    public float getSceneLabelSize() {
        return SCENE_LABEL_SIZE * scale;
    }

    /** @return the help's text size after shrinking to fit (in pixels) */
    public float getHelpSize() {
        layOutHelp(helpToLayOut);
        return helpSize;
    }

    /** @return how many body lines the body band shows (fewer than needed when too small) */
    public int getBodyLines() {
        return bodyLines;
    }

    /** @return the most lines the body has needed so far, wrapped to the band's width */
    public int getBodyLinesNeeded() {
        return bodyLinesNeeded;
    }

    /** @return how many lines the warning band holds (fewer than 2 when too small) */
    public int getWarningLines() {
        return warningLines;
    }

    /** @return the title, wrapped (not null) */
    public String getTitleText() {
        return titleText;
    }

    /** @return the footer, wrapped (not null) */
    public String getFooterText() {
        return footerText;
    }

    /** @return the whole window (live, do not modify) */
    public ScreenRect getWindow() {
        return window;
    }

    /** @return the title's rectangle (live, do not modify) */
    public ScreenRect getTitle() {
        return title;
    }

    /** @return the body band (live, do not modify) */
    public ScreenRect getBody() {
        return body;
    }

    /** @return the warning band (live, do not modify) */
    public ScreenRect getWarning() {
        return warning;
    }

    /** @return the footer's rectangle (live, do not modify) */
    public ScreenRect getFooter() {
        return footer;
    }

    /**
     * @return the area left to the scene, from the window's bottom edge (the footer is drawn
     *     on its ground) up to the warning band's top (the band is drawn over its sky; live)
     */
    public ScreenRect getScene() {
        return scene;
    }

    /**
     * Return how high above the scene's bottom edge its content must begin: the footer is
     * drawn on the scene's ground below this line.
     *
     * @return the height above the window's bottom edge (in pixels, &ge;0)
     */
    public float getSceneFloor() {
        return sceneFloor;
    }

    /** @return the help panel's background: the window below the title (live) */
    public ScreenRect getHelpPanel() {
        layOutHelp(helpToLayOut);
        return helpPanel;
    }

    /** @return the help's columns, in reading order (live, do not modify) */
    public List<ScreenRect> getHelpColumns() {
        layOutHelp(helpToLayOut);
        return helpColumns;
    }

    /**
     * Count the help's flows into columns so far: the work its layout did (each wraps every
     * help line at one size and column width).
     *
     * @return the count since creation (&ge;0)
     */
    int countHelpFlows() {
        return helpFlows;
    }

    /** @return the text of each help column, in reading order (live, do not modify) */
    public List<String> getHelpColumnTexts() {
        layOutHelp(helpToLayOut);
        return helpColumnTexts;
    }

    /**
     * Place the ledger's strip at the right of the width left of the side panel, its top
     * under the warning band, no lower than the scene's floor (above the footer). Call once
     * the footer and {@link #sceneFloor} are set.
     *
     * @param leftWidth the width left of the side panel (in pixels)
     * @param top the strip's highest top (in pixels)
     * @param margin the HUD's margin (in pixels)
     * @return the width the scene gives up (in pixels, &ge;0)
     */
    private float placeLedger(float leftWidth, float top, float margin) {
        if (!(ledgerWidth > 0f && ledgerHeight > 0f)) {
            ledger.set(0f, 0f, 0f, 0f);
            return 0f;
        }
        float pixels = Math.min(ledgerWidth * scale, MAX_LEDGER_SHARE * leftWidth);
        float stripWidth = Math.max(0f, pixels - margin);
        float stripHeight = Math.max(0f, Math.min(ledgerHeight * scale, top - sceneFloor));
        if (stripWidth <= 0f || stripHeight <= 0f) {
            ledger.set(0f, 0f, 0f, 0f);
            return 0f;
        }
        ledger.set(leftWidth - pixels, top - stripHeight, stripWidth, stripHeight);
        return pixels;
    }

    /**
     * Set the help in columns across the window's width, at the largest size that fits the
     * panel: at each size, one column, then two, up to {@value #MAX_HELP_COLUMNS} equal
     * columns, each line wrapped to its column's width.
     */
    private void layOutHelp(CharSequence helpText) {
        float margin = getMargin();
        helpPanel.set(0f, 0f, window.getWidth(), title.getY() - 0.3f * margin);
        if (helpPanel.getWidth() == helpLaidOutWidth && helpPanel.getHeight() == helpLaidOutHeight
                && scale == helpLaidOutScale && helpLaidOutText != null
                && TextFormat.sameText(helpText, helpLaidOutText)) {
            return;
        }
        helpLaidOutText = helpText.toString();
        helpLaidOutWidth = helpPanel.getWidth();
        helpLaidOutHeight = helpPanel.getHeight();
        helpLaidOutScale = scale;
        List<List<String>> sections = splitSections(helpText);
        float innerWidth = helpPanel.getWidth() - 2f * margin;
        float innerHeight = helpPanel.getHeight() - 2f * margin;
        float minSize = MIN_HELP_SIZE * Math.min(1f, scale);
        float size = HELP_SIZE * scale;
        boolean fits = flowHelpInColumns(sections, size, innerWidth, innerHeight);
        while (!fits && size > minSize) {
            size = Math.max(minSize, size * HELP_SHRINK);
            fits = flowHelpInColumns(sections, size, innerWidth, innerHeight);
        }
        helpSize = size;
        if (!fits) {
            flowHelp(sections, size, innerWidth, innerHeight, innerWidth);
            keepFittingColumns(size, helpPanel.getX() + margin + innerWidth);
        }
    }

    /**
     * Flow the sections at one size into the fewest equal columns that hold them.
     *
     * @return true if some count of columns fits the panel
     */
    private boolean flowHelpInColumns(List<List<String>> sections, float size,
            float innerWidth, float innerHeight) {
        float space = 2f * getMargin();
        // Wrapping never joins lines, and a column holds at most maxLines: when the help's
        // own lines need more than the most columns, no flow at this size fits (the quick
        // answer for a small window, where the sizes down to the smallest all fail).
        int maxLines = Math.max(1, (int) Math.floor(innerHeight / measure.lineHeight(size)));
        int lines = 0;
        for (int i = 0; i < sections.size(); ++i) {
            lines += sections.get(i).size();
        }
        if (lines > MAX_HELP_COLUMNS * maxLines) {
            return false;
        }
        for (int count = 1; count <= MAX_HELP_COLUMNS; ++count) {
            float columnWidth = (innerWidth - (count - 1) * space) / count;
            if (columnWidth < 1f) {
                break;
            }
            if (flowHelp(sections, size, innerWidth, innerHeight, columnWidth)
                    && helpColumns.size() <= count) {
                return true;
            }
        }
        return false;
    }

    /**
     * At the smallest help text, keep the columns that end left of a limit (at least the
     * first); if some had to go, the last one kept ends with {@value #HELP_CUT_LINE}
     * instead of its last line.
     */
    private void keepFittingColumns(float size, float right) {
        int kept = 1;
        while (kept < helpColumns.size() && helpColumns.get(kept).getRight() <= right) {
            ++kept;
        }
        if (kept == helpColumns.size()) {
            return;
        }
        while (helpColumns.size() > kept) {
            helpColumns.remove(helpColumns.size() - 1);
            helpColumnTexts.remove(helpColumnTexts.size() - 1);
        }
        String text = helpColumnTexts.get(kept - 1);
        int lastLine = text.lastIndexOf('\n');
        String cut = (lastLine < 0 ? "" : text.substring(0, lastLine + 1)) + HELP_CUT_LINE;
        helpColumnTexts.set(kept - 1, cut);
        ScreenRect column = helpColumns.get(kept - 1);
        float height = countLines(cut) * measure.lineHeight(size);
        column.set(column.getX(), column.getTop() - height, measure.width(cut, size), height);
    }

    /**
     * Flow the sections into columns at one size.
     *
     * @return true if every column fits the panel
     */
    private boolean flowHelp(List<List<String>> sections, float size, float innerWidth,
            float innerHeight, float columnWidth) {
        ++helpFlows;
        helpColumns.clear();
        helpColumnTexts.clear();
        float margin = getMargin();
        float lineHeight = measure.lineHeight(size);
        int maxLines = Math.max(1, (int) Math.floor(innerHeight / lineHeight));
        List<List<String>> columns = new ArrayList<>();
        List<String> column = new ArrayList<>();
        columns.add(column);
        for (List<String> given : sections) {
            // A line wider than the panel (a narrow window) is wrapped, like the body.
            List<String> section = new ArrayList<>();
            for (String line : given) {
                section.addAll(List.of(wrap(line, size, columnWidth).split("\n", -1)));
            }
            int needed = section.size() + (column.isEmpty() ? 0 : 1);
            if (!column.isEmpty() && column.size() + needed > maxLines
                    && section.size() <= maxLines) {
                column = new ArrayList<>();
                columns.add(column);
            }
            if (!column.isEmpty()) {
                column.add("");
            }
            for (String line : section) {
                if (column.size() >= maxLines) {
                    column = new ArrayList<>();
                    columns.add(column);
                }
                column.add(line);
            }
        }
        float left = helpPanel.getX() + margin;
        float top = helpPanel.getTop() - margin;
        boolean fits = true;
        for (List<String> lines : columns) {
            String text = String.join("\n", lines);
            float width = measure.width(text, size);
            float height = lines.size() * lineHeight;
            ScreenRect rect = new ScreenRect(left, top - height, width, height);
            helpColumns.add(rect);
            helpColumnTexts.add(text);
            left += Math.max(width, columnWidth < innerWidth ? columnWidth : 0f) + 2f * margin;
            fits &= rect.getRight() <= helpPanel.getX() + margin + innerWidth
                    && height <= innerHeight;
        }
        return fits;
    }

    private static List<List<String>> splitSections(CharSequence helpText) {
        List<List<String>> sections = new ArrayList<>();
        List<String> section = new ArrayList<>();
        for (String line : helpText.toString().split("\n", -1)) {
            if (line.isBlank()) {
                if (!section.isEmpty()) {
                    sections.add(section);
                    section = new ArrayList<>();
                }
            } else {
                section.add(line);
            }
        }
        if (!section.isEmpty()) {
            sections.add(section);
        }
        return sections;
    }

    /** Wrap the line text[from, to) into out, at spaces; line is scratch. */
    private void wrapLine(CharSequence text, int from, int to, float size, float maxWidth,
            StringBuilder line, StringBuilder out) {
        line.setLength(0);
        line.append(text, from, to);
        if (measure.width(line, size) <= maxWidth) {
            out.append(line);
            return;
        }
        line.setLength(0);
        int i = from;
        while (i < to) {
            // One word with the spaces before it.
            int wordStart = i;
            while (wordStart < to && text.charAt(wordStart) == ' ') {
                ++wordStart;
            }
            int wordEnd = wordEnd(text, wordStart, to);
            // A number keeps its unit: "10.57 m" moves down whole, no lone "m" below.
            if (wordEnd > wordStart && Character.isDigit(text.charAt(wordEnd - 1))
                    && wordEnd + 1 < to && text.charAt(wordEnd) == ' '
                    && isUnit(text, wordEnd + 1, wordEnd(text, wordEnd + 1, to))) {
                wordEnd = wordEnd(text, wordEnd + 1, to);
            }
            int kept = line.length();
            boolean hasWord = hasWord(line);
            line.append(text, i, wordEnd);
            if (hasWord && measure.width(line, size) > maxWidth) {
                line.setLength(kept);
                // A line's groups stand three spaces apart ("2 collision: impulse j, e =
                // 0.6"): break at the last such gap when the rest fits, so a group (a phase,
                // a readout) moves down whole rather than split before its last word.
                int gap = lastGroupGap(line);
                if (gap > 0) {
                    int rest = gap;
                    while (line.charAt(rest) == ' ') {
                        ++rest;
                    }
                    spill.setLength(0);
                    spill.append(CONTINUATION).append(line, rest, kept).append(text, i, wordEnd);
                    if (measure.width(spill, size) <= maxWidth) {
                        line.setLength(gap);
                        out.append(line).append('\n');
                        line.setLength(0);
                        line.append(spill);
                        i = wordEnd;
                        continue;
                    }
                }
                out.append(line).append('\n');
                line.setLength(0);
                line.append(CONTINUATION).append(text, wordStart, wordEnd);
            }
            i = wordEnd;
        }
        out.append(line);
    }

    /** @return the end of the word that starts at from (the next space, or to) */
    private static int wordEnd(CharSequence text, int from, int to) {
        int end = from;
        while (end < to && text.charAt(end) != ' ') {
            ++end;
        }
        return end;
    }

    /**
     * @return true if text[from, to) reads as a unit after a number: 1 to
     *     {@value #MAX_UNIT_CHARS} characters, no digit, no '=' (m, m/s², kg/m, N·s, %)
     */
    private static boolean isUnit(CharSequence text, int from, int to) {
        if (to <= from || to - from > MAX_UNIT_CHARS) {
            return false;
        }
        for (int i = from; i < to; ++i) {
            char c = text.charAt(i);
            if (Character.isDigit(c) || c == '=') {
                return false;
            }
        }
        return true;
    }

    /**
     * Find where the last gap of three or more spaces after a word starts in a line.
     *
     * @param line the line so far (not null)
     * @return the gap's first index, or -1 if the line has no such gap after a word
     */
    private static int lastGroupGap(CharSequence line) {
        int end = line.length();
        // the gap must end before the line does: trailing spaces are no group's gap
        while (end > 0 && line.charAt(end - 1) == ' ') {
            --end;
        }
        for (int i = end - 1; i >= 3; --i) {
            if (line.charAt(i) == ' ' && line.charAt(i - 1) == ' ' && line.charAt(i - 2) == ' ') {
                int start = i - 2;
                while (start > 0 && line.charAt(start - 1) == ' ') {
                    --start;
                }
                for (int k = 0; k < start; ++k) {
                    if (line.charAt(k) != ' ') {
                        return start;
                    }
                }
                return -1;
            }
        }
        return -1;
    }

    private static boolean hasWord(CharSequence line) {
        for (int i = 0; i < line.length(); ++i) {
            if (line.charAt(i) != ' ') {
                return true;
            }
        }
        return false;
    }

    /**
     * The footer of a window too small for every line: the window's size, what was hidden,
     * and, when the text is smaller than the user's factor asked (the scale was lowered to
     * fit, or clamped), that factor and the one the window got, both relative to the scale
     * that suits the window.
     */
    private String tooSmallLine(float width, float height, String hidden) {
        String size = "window too small (" + Math.round(width) + "x" + Math.round(height) + ")";
        float got = scale / scaleFor(width, height);
        // One decimal, as printed: a reduction that rounds away is not named.
        long asked10 = Math.round(10.0 * userFactor);
        long got10 = Math.round(10.0 * got);
        if (got10 >= asked10) {
            return size + ": " + hidden;
        }
        return "text x" + asked10 / 10 + "." + asked10 % 10 + " reduced to x" + got10 / 10
                + "." + got10 % 10 + ": " + size + ", " + hidden;
    }
}

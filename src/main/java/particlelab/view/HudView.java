package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Quad;
import java.util.ArrayList;
import java.util.List;

/**
 * The screen-space text of a demo: a title, a body (equations and live numbers), a warning
 * line, a footer with the main keys, and a help panel shown on request. Where each goes is
 * decided by a {@link HudLayout} from the window's size and the text's measured size, so no
 * text covers another at any window size; text wider than the window is wrapped.
 *
 * <p>Every text is a {@link HudText}, whose mesh is rewritten in place: a new body or warning
 * allocates nothing (jME's {@code BitmapText} built new glyph quads on each change), so the
 * HUD may be refreshed every frame. Callers rebuild their text into a reused
 * {@link StringBuilder}; {@link #setBody} compares before it sets. A text wider than the
 * window is wrapped, into reused builders.
 */
public final class HudView {

    private static final ColorRGBA TITLE_COLOR = new ColorRGBA(1f, 0.93f, 0.6f, 1f);
    private static final ColorRGBA BODY_COLOR = new ColorRGBA(0.88f, 0.92f, 1f, 1f);
    private static final ColorRGBA WARNING_COLOR = new ColorRGBA(1f, 0.42f, 0.3f, 1f);
    private static final ColorRGBA FOOTER_COLOR = new ColorRGBA(0.7f, 0.76f, 0.86f, 1f);
    /** The help panel hides the scene and the HUD below the title (opaque). */
    private static final ColorRGBA PANEL_COLOR = new ColorRGBA(0.02f, 0.03f, 0.06f, 1f);
    /** Behind the top band: hides grid lines and trails that reach above the scene's area. */
    private static final ColorRGBA BACKDROP_COLOR = new ColorRGBA(0.07f, 0.08f, 0.11f, 0.92f);

    private final Node node = new Node("HUD");
    private final Geometry backdrop;
    private final BitmapFont font;
    private final TextMeasure measure;
    private final HudLayout layout;
    private final HudText title;
    private final HudText body;
    private final HudText warning;
    private final HudText footer;
    /** Presentation mode's readout (empty in the full HUD). */
    private final HudText readout;
    private final Node helpPanel = new Node("help panel");
    private final List<HudText> helpColumns = new ArrayList<>();
    private final Geometry helpBackground;
    private float screenWidth;
    private float screenHeight;
    private float scale;
    /** Scratch for wrapping: one line, the text wrapped, and its lines that fit a band. */
    private final StringBuilder wrapLine = new StringBuilder(256);
    private final StringBuilder wrapped = new StringBuilder(2048);
    private final StringBuilder cut = new StringBuilder(2048);
    /** The body and the warning as given, unwrapped and whole (the bands may show less). */
    private final StringBuilder bodySource = new StringBuilder(2048);
    private final StringBuilder warningSource = new StringBuilder(256);
    /** Presentation mode's readout as given. */
    private final StringBuilder readoutSource = new StringBuilder(128);
    /** True in presentation mode: the body holds the slide's formula lines. */
    private boolean presenting;
    /** How many lines the last {@link #setWrapped} wrapped its text to, before any cut. */
    private int wrappedLines;
    /** How many lines the body's text wrapped to when last set, before any cut. */
    private int bodyWrappedLines;
    private String titleSource = "";
    private String footerSource = "";
    private String helpSource = "";
    private boolean layoutChanged;
    private int textChanges;

    /**
     * Create the HUD for a screen, at the HUD scale that suits it
     * ({@link HudLayout#scaleFor}).
     *
     * @param assetManager loads materials (not null)
     * @param font the font (not null)
     * @param screenWidth the screen's width (in pixels, &gt;0)
     * @param screenHeight the screen's height (in pixels, &gt;0)
     */
    public HudView(AssetManager assetManager, BitmapFont font, int screenWidth,
            int screenHeight) {
        this.font = font;
        this.measure = TextMeasure.of(font);
        this.layout = new HudLayout(measure);
        title = text(font, TITLE_COLOR);
        body = text(font, BODY_COLOR);
        footer = text(font, FOOTER_COLOR);
        warning = text(font, WARNING_COLOR);
        readout = text(font, TITLE_COLOR);
        node.attachChild(title);
        node.attachChild(readout);
        node.attachChild(body);
        node.attachChild(footer);
        node.attachChild(warning);

        Material shade = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        shade.setColor("Color", BACKDROP_COLOR);
        shade.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        backdrop = new Geometry("HUD backdrop", new Quad(1f, 1f));
        backdrop.setMaterial(shade);
        backdrop.setQueueBucket(RenderQueue.Bucket.Gui);
        node.attachChild(backdrop);

        Material panel = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        panel.setColor("Color", PANEL_COLOR);
        panel.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        helpBackground = new Geometry("help background", new Quad(1f, 1f));
        helpBackground.setMaterial(panel);
        helpBackground.setQueueBucket(RenderQueue.Bucket.Gui);
        helpPanel.attachChild(helpBackground);
        helpPanel.setCullHint(Spatial.CullHint.Always);
        node.attachChild(helpPanel);
        layOut(screenWidth, screenHeight, HudLayout.scaleFor(screenWidth, screenHeight));
    }

    /**
     * Lay the HUD out again, for a window of another size or another HUD scale.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param hudScale the text scale (&gt;0; {@link HudLayout#scaleFor} suits the window)
     */
    public void layOut(float width, float height, float hudScale) {
        screenWidth = width;
        screenHeight = height;
        scale = hudScale;
        relayOut();
    }

    /**
     * Lay the HUD out again, like {@link #layOut}, with the body's band sized for the body as
     * it is now rather than for the most lines it needed before (at another size or scale).
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param hudScale the text scale (&gt;0)
     */
    public void layOutAfresh(float width, float height, float hudScale) {
        layOut(width, height, hudScale);
        // Twice: the second pass sizes the body's band for the body as wrapped by the first.
        layout.forgetBodyLines();
        relayOut();
        layout.forgetBodyLines();
        relayOut();
    }

    /**
     * Return how many lines the body's text needs now, wrapped to the band's width: fewer
     * than {@link HudLayout#getBodyLinesNeeded()} when the band is kept for lines the body
     * needed before.
     *
     * @return the count (&ge;0)
     */
    public int getBodyLinesWrapped() {
        return bodyWrappedLines;
    }

    /**
     * Access the layout: where each text block goes, and the area left to the scene.
     *
     * @return the live layout (not null, do not modify)
     */
    public HudLayout getLayout() {
        return layout;
    }

    /**
     * Test, and forget, whether the layout changed since the last call (the body grew a line
     * the band had no room for), so the scene must be laid out again.
     *
     * @return true if it changed
     */
    public boolean takeLayoutChange() {
        boolean changed = layoutChanged;
        layoutChanged = false;
        return changed;
    }

    /**
     * Copy the screen rectangle of every HUD text shown into a list, for tests of the layout:
     * the title, body, warning and footer (and in presentation mode the readout), or with
     * the help shown, the title and the help's
     * columns (the panel hides the rest).
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        storeResult.add(rectOf(title));
        if (isHelpVisible()) {
            for (HudText column : helpColumns) {
                storeResult.add(rectOf(column));
            }
        } else {
            storeResult.add(rectOf(body));
            storeResult.add(rectOf(warning));
            storeResult.add(rectOf(footer));
            if (presenting) {
                storeResult.add(rectOf(readout));
            }
        }
        return storeResult;
    }

    /**
     * Access the node to attach to the GUI scene.
     *
     * @return the live node (not null)
     */
    public Node getNode() {
        return node;
    }

    /**
     * Show a title.
     *
     * @param text the title (not null)
     */
    public void setTitle(CharSequence text) {
        if (!TextFormat.sameText(text, titleSource)) {
            titleSource = text.toString();
            relayOut();
        }
    }

    /**
     * Show the body text, if it differs from what is shown.
     *
     * @param text the lines (not null, not modified)
     * @return true if the text changed
     */
    public boolean setBody(CharSequence text) {
        if (TextFormat.sameText(text, bodySource)) {
            return false;
        }
        bodySource.setLength(0);
        bodySource.append(text);
        boolean changed = setWrapped(body, bodySource, layout.getBodySize(),
                layout.getBodyLines());
        bodyWrappedLines = wrappedLines;
        if (wrappedLines > layout.getBodyLinesNeeded()) {
            relayOut();
            layoutChanged = true;
        }
        return changed;
    }

    /**
     * Switch between the full HUD and presentation mode: the title, the slide's formula lines
     * (in the body's place) and its readout in large type, a one-line footer, no warning
     * ({@link HudLayout#layOutPresentation}). The caller lays the HUD out again (the scale
     * that suits the window differs) and sets the body, the footer and the readout for the
     * mode.
     *
     * @param on true for presentation mode
     */
    public void setPresenting(boolean on) {
        if (on == presenting) {
            return;
        }
        presenting = on;
        bodySource.setLength(0);
        readoutSource.setLength(0);
        relayOut();
        layoutChanged = true;
    }

    /** @return true in presentation mode */
    public boolean isPresenting() {
        return presenting;
    }

    /**
     * Show presentation mode's readout, if it differs from what is shown (one line, wrapped
     * if wider than the window). Allocates nothing once the scratch builders are large enough.
     *
     * @param text the readout (not null, not modified)
     * @return true if the text changed
     */
    public boolean setReadout(CharSequence text) {
        if (TextFormat.sameText(text, readoutSource)) {
            return false;
        }
        readoutSource.setLength(0);
        readoutSource.append(text);
        boolean changed = setWrapped(readout, readoutSource, layout.getBodySize(),
                layout.getReadoutLines());
        if (presenting && wrappedLines > layout.getReadoutLinesNeeded()) {
            relayOut();
            layoutChanged = true;
        }
        return changed;
    }

    /**
     * Return the readout shown (presentation mode).
     *
     * @return the text, empty if none (not null)
     */
    public String getReadoutText() {
        return readout.getText();
    }

    /**
     * Show a warning line, or none.
     *
     * @param text the warning, empty for none (not null, not modified)
     * @return true if the text changed
     */
    public boolean setWarning(CharSequence text) {
        if (TextFormat.sameText(text, warningSource)) {
            return false;
        }
        warningSource.setLength(0);
        warningSource.append(text);
        return setWrapped(warning, warningSource, layout.getWarningSize(),
                layout.getWarningLines());
    }

    /**
     * Show the footer line.
     *
     * @param text the footer (not null)
     */
    public void setFooter(CharSequence text) {
        if (!TextFormat.sameText(text, footerSource)) {
            footerSource = text.toString();
            relayOut();
        }
    }

    /**
     * Set the help panel's text: it covers the window below the title, in as many columns as
     * it needs, its text shrunk until every column fits.
     *
     * @param text the help: sections separated by blank lines, the demo's own keys first
     *     (not null)
     */
    public void setHelp(CharSequence text) {
        helpSource = text.toString();
        relayOut();
    }

    /**
     * Show or hide the help panel.
     *
     * @param visible true to show it
     */
    public void setHelpVisible(boolean visible) {
        if (visible && !isHelpVisible()) {
            placeHelp();
        }
        helpPanel.setCullHint(visible ? Spatial.CullHint.Inherit : Spatial.CullHint.Always);
    }

    /**
     * Test whether the help panel is shown.
     *
     * @return true if shown
     */
    public boolean isHelpVisible() {
        return helpPanel.getCullHint() != Spatial.CullHint.Always;
    }

    /**
     * Return the text shown in the title.
     *
     * @return the text (not null)
     */
    public String getTitleText() {
        return title.getText();
    }

    /**
     * Return the footer shown.
     *
     * @return the text (not null)
     */
    public String getFooterText() {
        return footer.getText();
    }

    /**
     * Return the text shown in the body.
     *
     * @return the text (not null)
     */
    public String getBodyText() {
        return body.getText();
    }

    /**
     * Return the warning shown, as one line (without the breaks it was wrapped at).
     *
     * @return the text, empty if none (not null)
     */
    public String getWarningText() {
        return warningSource.toString();
    }

    /**
     * Return the help panel's text.
     *
     * @return the text (not null)
     */
    public String getHelpText() {
        return helpSource;
    }

    /**
     * Return the help as shown, one text per column, in reading order.
     *
     * @return a new list (not null)
     */
    public List<String> getHelpColumnTexts() {
        placeHelp();
        List<String> texts = new ArrayList<>();
        for (HudText column : helpColumns) {
            texts.add(column.getText());
        }
        return texts;
    }

    /**
     * Count how often a text actually changed (each rewrites its glyphs).
     *
     * @return the count since creation (&ge;0)
     */
    public int countTextChanges() {
        return textChanges;
    }

    private void relayOut() {
        if (presenting) {
            layout.layOutPresentation(screenWidth, screenHeight, scale, titleSource,
                    bodySource, readoutSource, footerSource, helpSource);
        } else {
            layout.layOut(screenWidth, screenHeight, scale, titleSource, bodySource,
                    footerSource, helpSource);
        }
        place(title, layout.getTitle(), layout.getTitleSize(), 1f);
        set(title, layout.getTitleText());
        place(body, layout.getBody(), layout.getBodySize(), 1f);
        place(warning, layout.getWarning(), layout.getWarningSize(), 1f);
        place(footer, layout.getFooter(), layout.getFooterSize(), 1f);
        set(footer, layout.getFooterText());
        // Text set before this layout was wrapped for the old width: wrap it again.
        setWrapped(body, bodySource, layout.getBodySize(), layout.getBodyLines());
        setWrapped(warning, warningSource, layout.getWarningSize(), layout.getWarningLines());
        place(readout, layout.getReadout(), layout.getBodySize(), 1f);
        setWrapped(readout, readoutSource, layout.getBodySize(), layout.getReadoutLines());

        ScreenRect scene = layout.getScene();
        backdrop.setLocalScale(screenWidth, screenHeight - scene.getTop(), 1f);
        backdrop.setLocalTranslation(0f, scene.getTop(), 0f);

        if (isHelpVisible()) {
            placeHelp();
        }
    }

    /**
     * Lay the help's columns out (the layout flows them when first asked since the last
     * layout) and place them: when the help is shown, and at every layout while it is.
     */
    private void placeHelp() {
        ScreenRect panel = layout.getHelpPanel();
        helpBackground.setLocalScale(panel.getWidth(), panel.getHeight(), 1f);
        helpBackground.setLocalTranslation(panel.getX(), panel.getY(), 2f);
        List<ScreenRect> rects = layout.getHelpColumns();
        List<String> texts = layout.getHelpColumnTexts();
        while (helpColumns.size() < rects.size()) {
            HudText column = text(font, BODY_COLOR);
            helpColumns.add(column);
            helpPanel.attachChild(column);
        }
        while (helpColumns.size() > rects.size()) {
            helpColumns.remove(helpColumns.size() - 1).removeFromParent();
        }
        for (int i = 0; i < rects.size(); ++i) {
            place(helpColumns.get(i), rects.get(i), layout.getHelpSize(), 3f);
            set(helpColumns.get(i), texts.get(i));
        }
    }

    /**
     * Set a text wrapped to the body's width and cut to a band's lines, if that differs from
     * what is shown; {@link #wrappedLines} counts the lines before the cut. Allocates nothing
     * once the scratch builders are large enough.
     */
    private boolean setWrapped(HudText target, CharSequence text, float size, int maxLines) {
        float maxWidth = layout.getBody().getWidth();
        CharSequence shown = measure.width(text, size) <= maxWidth ? text
                : layout.wrap(text, size, maxWidth, wrapLine, wrapped);
        wrappedLines = HudLayout.countLines(shown);
        return set(target, HudLayout.firstLines(shown, maxLines, cut));
    }

    private static void place(HudText text, ScreenRect where, float size, float z) {
        text.setSize(size);
        text.setLocalTranslation(where.getX(), where.getTop(), z);
    }

    private ScreenRect rectOf(HudText text) {
        // The text's own measure: its top-left corner, its widest line, its lines.
        return new ScreenRect(text.getLocalTranslation().x,
                text.getLocalTranslation().y - text.getLineCount() * text.getLineHeight(),
                measure.width(text.getChars(), text.getSize()),
                text.getChars().length() == 0 ? 0f
                        : text.getLineCount() * text.getLineHeight());
    }

    private boolean set(HudText target, CharSequence text) {
        if (!target.setText(text)) {
            return false;
        }
        ++textChanges;
        return true;
    }

    private static HudText text(BitmapFont font, ColorRGBA color) {
        return new HudText(font, color);
    }
}

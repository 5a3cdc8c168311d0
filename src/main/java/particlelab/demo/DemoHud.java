package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.input.KeyInput;
import particlelab.view.HudScale;
import particlelab.view.HudView;

/**
 * A demo's HUD beside its base class: the title line, the body text rebuilt in reused
 * {@link StringBuilder}s (every frame by default, or less often), the band the body takes
 * and the scene's area that follows it, the window size and the user's factor it was laid
 * out for, a tour stop's note, and presentation mode (the slide instead of the body, its
 * footer), and the short notices the HUD shows for a few seconds. The demo writes the lines
 * ({@link DemoWindow#formatHud}, {@link DemoWindow#formatPresentation}); this class decides
 * when and lays them out. The application reaches it through {@link DemoState#getDemoHud()}.
 */
public final class DemoHud {

    /** Between the title and its note. */
    private static final String TITLE_NOTE_GAP = "      ";

    private final DemoState demo;
    private final DemoScene scene;
    private final DemoKeys keys;
    private final ParameterControls parameterControls;
    private final StepWarnings warnings;
    private final HudWriter hudWriter;
    private final String title;
    private final StringBuilder hudText = new StringBuilder(2048);
    private final StringBuilder warningText = new StringBuilder(256);
    private final StringBuilder titleText = new StringBuilder(64);
    /** Presentation mode's slide, written every frame while presenting. */
    private final Presentation presentation = new Presentation();
    private HudView hud;
    /** True in presentation mode: the scene large, the HUD reduced to the slide. */
    private boolean presenting;
    /** The demo's place in the catalogue, shown before the title (0: none). */
    private int catalogNumber;
    /** A short note after the title, or null. */
    private String titleNote;
    /** Lines after the demo's own on the HUD (a tour stop's), or null. */
    private HudNote note;
    private float ageSeconds;
    /** How often the HUD text is rebuilt (in seconds of frame time, 0: every frame). */
    private float refreshSeconds = DemoState.HUD_REFRESH_SECONDS;
    private boolean dirty = true;
    /** Lay the HUD out afresh at the next refresh: its note (a tour stop's lines) changed. */
    private boolean afresh;
    /** How long the body has needed fewer lines than its band keeps (seconds of frame time). */
    private float slackSeconds;
    /** The window size (pixels) and the user's HUD scale factor of the last layout. */
    private int laidOutWidth;
    private int laidOutHeight;
    private float uiScale = 1f;

    /**
     * Create the HUD of a demo; its view comes with {@link #build}.
     *
     * @param demo the demo that writes the lines (not null)
     * @param title the demo's title (not null)
     * @param scene the scene whose area follows the HUD's band (not null)
     * @param keys the demo's keys, for the footer (not null)
     * @param parameterControls the panel, whose state the slide's footer names (not null)
     * @param warnings the step warnings shown under the body (not null)
     * @param hudWriter the lines every demo shows, the notice among them (not null)
     */
    DemoHud(DemoState demo, String title, DemoScene scene, DemoKeys keys,
            ParameterControls parameterControls, StepWarnings warnings, HudWriter hudWriter) {
        this.demo = demo;
        this.title = title;
        this.scene = scene;
        this.keys = keys;
        this.parameterControls = parameterControls;
        this.warnings = warnings;
        this.hudWriter = hudWriter;
        titleText.append(title);
    }

    /**
     * Create the view for a window of a size, with the title.
     *
     * @param assets the asset manager (not null)
     * @param font the HUD's font (not null)
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @return the new view (not null)
     */
    HudView build(AssetManager assets, BitmapFont font, int width, int height) {
        hud = new HudView(assets, font, width, height);
        laidOutWidth = width;
        laidOutHeight = height;
        hud.setTitle(titleText);
        return hud;
    }

    /**
     * The first layout, once the footer, help and panel are there: the body's lines size the
     * HUD's band, and the band the scene's area; on a small window the text shrinks first,
     * then lines are hidden (HudScale, HudLayout).
     */
    void layOutFirst() {
        hud.setBody(demo.getWindow().formatHud(hudText));
        HudScale.layOut(hud, laidOutWidth, laidOutHeight, uiScale, true);
        hud.takeLayoutChange();
        layOutScene();
    }

    /** @return the view (null before {@link #build}) */
    HudView getView() {
        return hud;
    }

    /** Rebuild the HUD's text at the next frame. */
    void markDirty() {
        dirty = true;
    }

    /** @param text a short notice for the HUD, shown a few seconds (one non-empty line) */
    public void showNotice(String text) {
        hudWriter.showNotice(text);
        markDirty();
    }

    /** @return the notice on the HUD now, or null if none is up */
    public String getNotice() {
        return hudWriter.getNotice();
    }

    /** @param number the demo's place in the catalogue (&ge;1) */
    public void setCatalogNumber(int number) {
        catalogNumber = number;
        showTitle();
    }

    /** @param newNote one short line after the title, or null (else refused) */
    public void setTitleNote(String newNote) {
        if (newNote != null && (newNote.isEmpty() || newNote.indexOf('\n') >= 0)) {
            throw new IllegalArgumentException("a title note must be null or one non-empty"
                    + " line, but was \"" + newNote + "\"");
        }
        titleNote = newNote;
        showTitle();
    }

    /** @return the note after the title, or null */
    public String getTitleNote() {
        return titleNote;
    }

    /** @param seconds how often the text is rebuilt (s, finite, &ge;0; else refused) */
    public void setRefreshSeconds(float seconds) {
        if (!(seconds >= 0f) || Float.isInfinite(seconds)) {
            throw new IllegalArgumentException("HUD refresh interval (s) must be finite and"
                    + " >= 0, but was " + seconds);
        }
        refreshSeconds = seconds;
    }

    /**
     * Show lines after the demo's own, or none.
     *
     * @param newNote writes the lines, or null
     */
    public void setNote(HudNote newNote) {
        note = newNote;
        dirty = true;
        // Another stop's lines: the band is sized for them, not for the lines before.
        afresh = true;
        if (hud != null && presenting) {
            // On a tour stop the footer names the tour's keys too.
            hud.setFooter(buildPresentationFooter());
        }
    }

    /** @return the lines after the demo's own, or null */
    public HudNote getNote() {
        return note;
    }

    /** @return the slide presentation mode shows (live) */
    Presentation getSlide() {
        return presentation;
    }

    /**
     * Switch presentation mode; before the view exists it is remembered.
     *
     * @param on true for presentation mode
     */
    public void setPresenting(boolean on) {
        if (on == presenting) {
            return;
        }
        presenting = on;
        if (hud != null) {
            applyPresentation();
        }
    }

    /** @return true in presentation mode */
    public boolean isPresenting() {
        return presenting;
    }

    /**
     * Lay the HUD and the scene's texts out for a window, at the HUD scale that suits it.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     */
    public void layOut(int width, int height) {
        layOut(width, height, 1f);
    }

    /**
     * Lay the HUD out for a window, at the user's factor, and the scene's texts with it;
     * frame the camera if the window has that size.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param userScale the user's factor on the HUD scale
     */
    public void layOut(int width, int height, float userScale) {
        // A new size or factor sizes the body's band afresh: the lines the old width or text
        // size needed mean nothing now (a band grown on a small window would stay grown).
        boolean fresh = userScale != uiScale || width != laidOutWidth
                || height != laidOutHeight;
        HudScale.layOut(hud, width, height, userScale, fresh);
        laidOutWidth = width;
        laidOutHeight = height;
        uiScale = userScale;
        hud.takeLayoutChange();
        layOutScene();
        scene.updateViews();
        if (demo.isEnabled() && demo.getApplication().getCamera().getWidth() == width
                && demo.getApplication().getCamera().getHeight() == height) {
            demo.frameCamera();
        }
    }

    /**
     * After a slot came or went: the same window, at the user's factor in use. The window is
     * the one last laid out for, not the camera's: a layout for another size (a test's, or
     * one asked for before the camera follows) is kept, and the window controls lay the
     * camera's size out at the next frame when it differs.
     */
    void layOutAgain() {
        layOut(laidOutWidth, laidOutHeight, uiScale);
    }

    /**
     * Test whether the last layout was for this window size and HUD factor.
     *
     * @param width the window's width (in pixels)
     * @param height the window's height (in pixels)
     * @param userScale the user's factor on the HUD scale
     * @return true if a layout with these would change nothing
     */
    public boolean isLaidOutFor(int width, int height, float userScale) {
        return width == laidOutWidth && height == laidOutHeight && userScale == uiScale;
    }

    /**
     * Once a frame: rebuild the text if due (every frame by default) and keep the band fitted
     * to it. Allocates nothing unless it lays out.
     *
     * @param tpf the frame time (in seconds, &ge;0)
     */
    void update(float tpf) {
        ageSeconds += tpf;
        if (dirty || ageSeconds >= refreshSeconds) {
            float sinceRefresh = ageSeconds;
            ageSeconds = 0f;
            dirty = false;
            writeBody();
            hud.setWarning(warnings.format(warningText));
            fitBand(sinceRefresh);
        }
    }

    /** After the panel came or went: the slide's footer names it, then a new layout. */
    void panelMoved() {
        if (presenting) {
            // The slide has no panel: the footer says where F2's panel is.
            hud.setFooter(buildPresentationFooter());
        }
        parameterControls.requestSlot(hud.getLayout());
        layOutAgain();
    }

    /**
     * Lay the HUD out for the mode now chosen: presentation's slide or the full HUD, its
     * footer, the scale that suits the window for it, and the scene for the new area.
     */
    void applyPresentation() {
        hud.setPresenting(presenting);
        hud.setFooter(presenting ? buildPresentationFooter() : keys.buildFooter());
        writeBody();
        HudScale.layOut(hud, laidOutWidth, laidOutHeight, uiScale, true);
        hud.takeLayoutChange();
        layOutScene();
        scene.updateViews();
        if (demo.isEnabled()) {
            demo.frameCamera();
        }
        dirty = true;
    }

    /** The scene's area follows the HUD's layout, then the demo's parts lay out for it. */
    private void layOutScene() {
        scene.layOut(hud.getLayout());
        demo.layOutParts(hud.getLayout());
    }

    /** The slide's formulas and readout while presenting, else the full body. */
    private void writeBody() {
        if (presenting) {
            demo.getWindow().formatPresentation();
            hud.setBody(presentation.getFormulas());
            hud.setReadout(presentation.getReadout());
        } else {
            hud.setBody(demo.getWindow().formatHud(hudText));
        }
    }

    /**
     * Keep the HUD's body band fitted to the body after a refresh. A body grown past its band
     * is laid out again at the scale that suits the window, shrunk while the window cannot
     * hold every line ({@link HudScale#layOut}), so lines are hidden only when even the
     * smallest text does not fit. A new note, or a body needing fewer lines than the band for
     * {@link DemoState#HUD_BAND_KEEP_SECONDS}, lays it out afresh: the band and the text size
     * follow the body as it is now, not the most it ever needed. Allocates only when it lays
     * out.
     *
     * @param sinceRefresh the frame time since the last refresh (in seconds, &ge;0)
     */
    private void fitBand(float sinceRefresh) {
        boolean grew = hud.takeLayoutChange();
        if (hud.getBodyLinesWrapped() < hud.getLayout().getBodyLinesNeeded()) {
            slackSeconds += sinceRefresh;
        } else {
            slackSeconds = 0f;
        }
        boolean fresh = afresh || slackSeconds >= DemoState.HUD_BAND_KEEP_SECONDS;
        if (!grew && !fresh) {
            return;
        }
        afresh = false;
        slackSeconds = 0f;
        HudScale.layOut(hud, laidOutWidth, laidOutHeight, uiScale, fresh);
        hud.takeLayoutChange();
        // The band grew or shrank: the scene's area follows it.
        layOutScene();
        demo.frameCamera();
    }

    /**
     * Presentation mode's footer, one short line: the key back to the full HUD and, on a
     * tour stop, the tour's keys (both the application's, found by their keys).
     */
    private String buildPresentationFooter() {
        StringBuilder footer = new StringBuilder();
        appendApplicationKey(footer, KeyInput.KEY_F8, "full HUD");
        if (note != null) {
            appendApplicationKey(footer, KeyInput.KEY_PGDN, "next stop");
            appendApplicationKey(footer, KeyInput.KEY_PGUP, "previous stop");
        }
        if (parameterControls.isPanelVisible()) {
            footer.append("     F2  panel open: it shows in the full HUD (F8)");
        }
        return footer.toString();
    }

    /** Append an application key's label and what it does here, if the application has it. */
    private void appendApplicationKey(StringBuilder footer, int keyCode, String what) {
        KeyBinding binding = keys.findApplicationKey(keyCode);
        if (binding != null) {
            footer.append(footer.length() == 0 ? "" : "     ")
                    .append(binding.getKeyLabel()).append("  ").append(what);
        }
    }

    /** The title line: the catalogue number, the title, and the note if there is one. */
    private void showTitle() {
        titleText.setLength(0);
        if (catalogNumber > 0) {
            titleText.append(catalogNumber).append(".  ");
        }
        titleText.append(title);
        if (titleNote != null) {
            titleText.append(TITLE_NOTE_GAP).append(titleNote);
        }
        if (hud != null) {
            hud.setTitle(titleText);
        }
    }
}

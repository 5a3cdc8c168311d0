package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Quad;

/**
 * The screen-space text of a demo: a title, a body (equations and live numbers), a warning
 * line, a footer with the main keys, and a help panel shown on request. Sized for a projector.
 *
 * <p>Text is only handed to jME when it differs from what is shown: {@code BitmapText.setText}
 * copies the text into a new String and rebuilds its glyph quads, so each change allocates.
 * Callers therefore rebuild their text into a reused {@link StringBuilder}, at a bounded rate,
 * and {@link #setBody} compares before it sets.
 */
public final class HudView {

    /** Text sizes (in pixels). */
    private static final float TITLE_SIZE = 32f;
    private static final float BODY_SIZE = 21f;
    private static final float FOOTER_SIZE = 19f;
    private static final float MARGIN = 14f;
    private static final ColorRGBA TITLE_COLOR = new ColorRGBA(1f, 0.93f, 0.6f, 1f);
    private static final ColorRGBA BODY_COLOR = new ColorRGBA(0.88f, 0.92f, 1f, 1f);
    private static final ColorRGBA WARNING_COLOR = new ColorRGBA(1f, 0.42f, 0.3f, 1f);
    private static final ColorRGBA FOOTER_COLOR = new ColorRGBA(0.7f, 0.76f, 0.86f, 1f);
    private static final ColorRGBA PANEL_COLOR = new ColorRGBA(0.02f, 0.03f, 0.06f, 0.88f);

    private final Node node = new Node("HUD");
    private final BitmapText title;
    private final BitmapText body;
    private final BitmapText warning;
    private final BitmapText footer;
    private final Node helpPanel = new Node("help panel");
    private final BitmapText helpText;
    private final Geometry helpBackground;
    private final float screenWidth;
    private final float screenHeight;
    private int textChanges;

    /**
     * Create the HUD for a screen.
     *
     * @param assetManager loads materials (not null)
     * @param font the font (not null)
     * @param screenWidth the screen's width (in pixels, &gt;0)
     * @param screenHeight the screen's height (in pixels, &gt;0)
     */
    public HudView(AssetManager assetManager, BitmapFont font, int screenWidth,
            int screenHeight) {
        this.screenWidth = screenWidth;
        this.screenHeight = screenHeight;
        title = text(font, TITLE_SIZE, TITLE_COLOR);
        title.setLocalTranslation(MARGIN, screenHeight - MARGIN, 1f);
        body = text(font, BODY_SIZE, BODY_COLOR);
        body.setLocalTranslation(MARGIN, screenHeight - MARGIN - TITLE_SIZE * 1.3f, 1f);
        footer = text(font, FOOTER_SIZE, FOOTER_COLOR);
        footer.setLocalTranslation(MARGIN, MARGIN + FOOTER_SIZE, 1f);
        warning = text(font, BODY_SIZE * 1.15f, WARNING_COLOR);
        warning.setLocalTranslation(MARGIN, MARGIN + FOOTER_SIZE * 3.4f, 1f);
        node.attachChild(title);
        node.attachChild(body);
        node.attachChild(footer);
        node.attachChild(warning);

        Material panel = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        panel.setColor("Color", PANEL_COLOR);
        panel.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        helpBackground = new Geometry("help background", new Quad(1f, 1f));
        helpBackground.setMaterial(panel);
        helpBackground.setQueueBucket(RenderQueue.Bucket.Gui);
        helpText = text(font, BODY_SIZE, BODY_COLOR);
        helpPanel.attachChild(helpBackground);
        helpPanel.attachChild(helpText);
        helpPanel.setCullHint(Spatial.CullHint.Always);
        node.attachChild(helpPanel);
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
        set(title, text);
    }

    /**
     * Show the body text, if it differs from what is shown.
     *
     * @param text the lines (not null, not modified)
     * @return true if the text changed
     */
    public boolean setBody(CharSequence text) {
        return set(body, text);
    }

    /**
     * Show a warning line, or none.
     *
     * @param text the warning, empty for none (not null, not modified)
     * @return true if the text changed
     */
    public boolean setWarning(CharSequence text) {
        return set(warning, text);
    }

    /**
     * Show the footer line.
     *
     * @param text the footer (not null)
     */
    public void setFooter(CharSequence text) {
        set(footer, text);
    }

    /**
     * Set the help panel's text and size the panel to it, centred on the screen.
     *
     * @param text the help lines (not null)
     */
    public void setHelp(CharSequence text) {
        set(helpText, text);
        float width = helpText.getLineWidth() + 2f * MARGIN;
        float height = helpText.getHeight() + 2f * MARGIN;
        float left = Math.max(0f, (screenWidth - width) / 2f);
        float bottom = Math.max(0f, (screenHeight - height) / 2f);
        helpBackground.setLocalScale(width, height, 1f);
        helpBackground.setLocalTranslation(left, bottom, 2f);
        helpText.setLocalTranslation(left + MARGIN, bottom + height - MARGIN, 3f);
    }

    /**
     * Show or hide the help panel.
     *
     * @param visible true to show it
     */
    public void setHelpVisible(boolean visible) {
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
     * Return the text shown in the body.
     *
     * @return the text (not null)
     */
    public String getBodyText() {
        return body.getText();
    }

    /**
     * Return the warning shown.
     *
     * @return the text, empty if none (not null)
     */
    public String getWarningText() {
        return warning.getText();
    }

    /**
     * Return the help panel's text.
     *
     * @return the text (not null)
     */
    public String getHelpText() {
        return helpText.getText();
    }

    /**
     * Count how often a text was actually handed to jME (each such change allocates).
     *
     * @return the count since creation (&ge;0)
     */
    public int countTextChanges() {
        return textChanges;
    }

    private boolean set(BitmapText target, CharSequence text) {
        if (TextFormat.sameText(text, target.getText())) {
            return false;
        }
        target.setText(text);
        ++textChanges;
        return true;
    }

    private static BitmapText text(BitmapFont font, float size, ColorRGBA color) {
        BitmapText text = new BitmapText(font);
        text.setSize(size);
        text.setColor(color);
        text.setText("");
        return text;
    }
}

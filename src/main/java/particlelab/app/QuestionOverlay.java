package particlelab.app;

import com.jme3.app.Application;
import com.jme3.app.SimpleApplication;
import com.jme3.app.state.BaseAppState;
import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.font.LineWrapMode;
import com.jme3.font.Rectangle;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Quad;
import particlelab.view.HudFont;
import particlelab.view.ScreenRect;

/**
 * The tour question's large text (issue 34, predict then reveal), over the frozen scene in
 * both HUD modes: the question and the room's counts while it votes, then the answer with the
 * stop's watch lines and the split ({@link TourGuide#appendVote}). Its type is a fixed share
 * of the window's height, so it reads the same from the back of the hall at 640x360 and at
 * 3840x2160; a text too tall for the window is set smaller until it fits. The answer, once
 * revealed, is set smaller ({@link #REVEAL_TYPE_SHARE}) in a compact box at the window's
 * top, over the HUD's band rather than the scene: each line unwrapped where the window is
 * wide enough (the vote's split on one line from 1280x720 up) and the box at most
 * {@link #REVEAL_SCENE_SHARE} of the scene's height, so the bodies that show the answer stay
 * in view. Rebuilt only when the text or the window's size changes: a frame allocates
 * nothing.
 */
final class QuestionOverlay extends BaseAppState {

    /** The type's height as a share of the window's height (1/18: 40 px at 720 px). */
    static final float TYPE_SHARE = 1f / 18f;
    /** The smallest type (px): below it the text is not readable at all. */
    static final float MIN_TYPE_PX = 14f;
    /** The text box's width as a share of the window's width. */
    static final float WIDTH_SHARE = 0.9f;
    /** The most of the window's height the box may take. */
    static final float HEIGHT_SHARE = 0.9f;
    /**
     * The revealed answer's type as a share of the window's height (1/40: 18 px at 720 px,
     * 27 px at 1080 px), before it is set smaller to fit.
     */
    static final float REVEAL_TYPE_SHARE = 1f / 40f;
    /** The most of the scene's height the revealed answer's box may take. */
    static final float REVEAL_SCENE_SHARE = 0.25f;
    /** How much smaller each try at fitting sets the type. */
    private static final float SHRINK = 0.9f;
    private static final ColorRGBA BACKDROP = new ColorRGBA(0.02f, 0.02f, 0.04f, 1f);
    /** The overlay's depth in the GUI: in front of the HUD's text and panels. */
    private static final float FRONT_Z = 100f;
    private static final ColorRGBA TEXT_COLOR = new ColorRGBA(1f, 0.95f, 0.6f, 1f);

    private final TourGuide tour;
    private final Node node = new Node("tour question");
    private final StringBuilder text = new StringBuilder();
    private BitmapText label;
    private Geometry backdrop;
    private Node guiNode;
    private BitmapFont font;
    private final ScreenRect sceneRect = new ScreenRect();
    private boolean shownRevealed;
    private int shownVersion = -1;
    private int shownWidth;
    private int shownHeight;
    /** The type size the last layout chose (px), for tests. */
    private float typePx;

    /**
     * Create the overlay.
     *
     * @param tour the guide whose question it shows (not null)
     */
    QuestionOverlay(TourGuide tour) {
        this.tour = tour;
    }

    /** @return true while a question is shown */
    boolean isShowing() {
        return node.getParent() != null;
    }

    /** @return the text shown (not null; empty while none is) */
    String getShownText() {
        return label == null || !isShowing() ? "" : label.getText();
    }

    /** @return the type size of the text shown (px) */
    float getTypePx() {
        return typePx;
    }

    /** @return the text's label, for layout tests (null before initialisation) */
    BitmapText getLabel() {
        return label;
    }

    /** @return the backdrop behind the text (null before initialisation) */
    Geometry getBackdrop() {
        return backdrop;
    }

    @Override
    protected void initialize(Application app) {
        guiNode = ((SimpleApplication) app).getGuiNode();
        font = HudFont.load(app.getAssetManager());
        label = new BitmapText(font);
        label.setColor(TEXT_COLOR);
        label.setLineWrapMode(LineWrapMode.Word);
        Material material = new Material(app.getAssetManager(),
                "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", BACKDROP);
        material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        backdrop = new Geometry("tour question backdrop", new Quad(1f, 1f));
        backdrop.setMaterial(material);
        backdrop.setQueueBucket(RenderQueue.Bucket.Gui);
        node.attachChild(backdrop);
        node.attachChild(label);
        node.setLocalTranslation(0f, 0f, FRONT_Z);
    }

    @Override
    protected void cleanup(Application app) {
        node.removeFromParent();
    }

    @Override
    protected void onEnable() {
        // Attached in update, while a question is asked.
    }

    @Override
    protected void onDisable() {
        node.removeFromParent();
    }

    @Override
    public void update(float tpf) {
        tour.updateVote();
        if (tour.getVote() == null) {
            if (isShowing()) {
                node.removeFromParent();
            }
            return;
        }
        int width = getApplication().getCamera().getWidth();
        int height = getApplication().getCamera().getHeight();
        if (tour.getVoteVersion() != shownVersion || width != shownWidth
                || height != shownHeight) {
            shownVersion = tour.getVoteVersion();
            shownWidth = width;
            shownHeight = height;
            text.setLength(0);
            tour.appendVote(text);
            label.setText(text);
            shownRevealed = tour.getVote().isRevealed();
            if (shownRevealed) {
                layoutReveal(width, height, tour.getSceneRect(sceneRect));
            } else {
                layout(width, height);
            }
        }
        if (!isShowing()) {
            guiNode.attachChild(node);
        }
    }

    /** Size the type to the window, shrinking it until the text fits, and centre the box. */
    private void layout(int width, int height) {
        float boxWidth = WIDTH_SHARE * width;
        float size = Math.max(MIN_TYPE_PX, TYPE_SHARE * height);
        float textHeight;
        do {
            label.setSize(size);
            label.setBox(new Rectangle(0f, 0f, boxWidth, 0f));
            // Centred within the box: alignment needs the box first.
            label.setAlignment(BitmapFont.Align.Center);
            textHeight = label.getHeight();
            if (textHeight <= HEIGHT_SHARE * height || size <= MIN_TYPE_PX) {
                break;
            }
            size = Math.max(MIN_TYPE_PX, size * SHRINK);
        } while (true);
        typePx = size;
        float margin = 0.5f * size;
        float left = 0.5f * (width - boxWidth);
        // In the upper part of the window, the frozen scene's ground below it.
        float top = Math.min(height - margin, 0.5f * (height + textHeight) + 0.25f * height);
        label.setBox(new Rectangle(0f, 0f, boxWidth, textHeight));
        label.setLocalTranslation(left, top, 1f);
        backdrop.setLocalScale(boxWidth + 2f * margin, textHeight + 2f * margin, 1f);
        backdrop.setLocalTranslation(left - margin, top - textHeight - margin, 0f);
    }

    /**
     * Lay the revealed answer out: at the window's top, its type the share of the height,
     * set smaller (down to {@link #MIN_TYPE_PX}) while a line would wrap or the box would be
     * taller than {@link #REVEAL_SCENE_SHARE} of the scene.
     *
     * @param scene the scene's rectangle on the screen (empty if unknown)
     */
    private void layoutReveal(int width, int height, ScreenRect scene) {
        float boxWidth = WIDTH_SHARE * width;
        float sceneHeight = scene.isEmpty() ? height : scene.getHeight();
        int lines = 1;
        for (int i = 0; i < text.length(); ++i) {
            if (text.charAt(i) == '\n') {
                ++lines;
            }
        }
        float size = Math.max(MIN_TYPE_PX, REVEAL_TYPE_SHARE * height);
        float lineHeight;
        while (true) {
            float scale = size / font.getCharSet().getRenderedSize();
            lineHeight = font.getCharSet().getLineHeight() * scale;
            boolean fits = widestLine() * scale <= boxWidth
                    && lines * lineHeight + size <= REVEAL_SCENE_SHARE * sceneHeight;
            if (fits || size <= MIN_TYPE_PX) {
                break;
            }
            size = Math.max(MIN_TYPE_PX, size * SHRINK);
        }
        typePx = size;
        label.setSize(size);
        label.setBox(new Rectangle(0f, 0f, boxWidth, 0f));
        label.setAlignment(BitmapFont.Align.Center);
        float textHeight = label.getHeight();
        float margin = 0.5f * size;
        float left = 0.5f * (width - boxWidth);
        float top = height - margin;
        label.setBox(new Rectangle(0f, 0f, boxWidth, textHeight));
        label.setLocalTranslation(left, top, 1f);
        // The window's whole width: no end of the HUD line under it peeks out beside it.
        backdrop.setLocalScale(width, textHeight + 2f * margin, 1f);
        backdrop.setLocalTranslation(0f, top - textHeight - margin, 0f);
    }

    /** @return the widest line of the text at the font's rendered size (px) */
    private float widestLine() {
        float widest = 0f;
        int start = 0;
        for (int i = 0; i <= text.length(); ++i) {
            if (i == text.length() || text.charAt(i) == '\n') {
                widest = Math.max(widest, font.getLineWidth(text.subSequence(start, i)));
                start = i + 1;
            }
        }
        return widest;
    }

    /** @return true if the answer shown is the revealed one (laid out compact) */
    boolean isShowingReveal() {
        return isShowing() && shownRevealed;
    }
}

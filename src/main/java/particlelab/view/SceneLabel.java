package particlelab.view;

import com.jme3.font.BitmapFont;
import com.jme3.font.BitmapText;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Spatial;

/**
 * A text standing in the scene's plane at a fixed point: a distance mark of the grid or the
 * name of a post. Its size is given in pixels, so it reads the same at every zoom; where it
 * goes is decided in pixels ({@link #preferredRect}) and then applied in metres through the
 * {@link PlaneView} ({@link #apply}).
 */
public final class SceneLabel {

    /** Where the text sits relative to its point. */
    public enum Anchor {
        /** Centred below the point (the marks along the ground). */
        BELOW,
        /** Right of and above the point (the marks up the left edge). */
        ABOVE_RIGHT,
        /** Centred above the point (a post's name). */
        ABOVE,
        /**
         * Right of and just above the point, close to it: the name of a post at its foot,
         * kept near the post, clear of what lands beyond it.
         */
        FOOT_RIGHT
    }

    /** The gap between the point and the text (as a fraction of the text size). */
    private static final float GAP_FRACTION = 0.4f;
    /** The gap between a post and its name at its foot (as a fraction of the text size). */
    private static final float FOOT_GAP_FRACTION = 0.15f;

    private final BitmapText text;
    private final float pointX;
    private final float pointY;
    private final Anchor anchor;
    private final ScreenRect rect = new ScreenRect();
    private boolean visible = true;
    /** True while something drawn in front of the scene's texts (a sphere) covers the place. */
    private boolean covered;

    /**
     * Create a label.
     *
     * @param font the font (not null)
     * @param label the text, one line (not null)
     * @param color its colour (not null, not modified)
     * @param pointX the point's x in the plane (in metres)
     * @param pointY the point's y in the plane (in metres)
     * @param anchor where the text sits relative to the point (not null)
     */
    public SceneLabel(BitmapFont font, String label, ColorRGBA color, float pointX,
            float pointY, Anchor anchor) {
        this.text = new BitmapText(font);
        text.setColor(color.clone());
        text.setText(label);
        text.setQueueBucket(RenderQueue.Bucket.Transparent);
        this.pointX = pointX;
        this.pointY = pointY;
        this.anchor = anchor;
    }

    /**
     * Access the text, to attach it to the scene.
     *
     * @return the live text (not null)
     */
    public BitmapText getText() {
        return text;
    }

    /**
     * Compute where the text would go on the screen, before any collision is resolved.
     *
     * @param view the plane's mapping (not null, not modified)
     * @param measure measures the text (not null)
     * @param size the text size (in pixels, &gt;0)
     * @param storeResult storage for the rectangle (not null, modified)
     * @return storeResult
     */
    public ScreenRect preferredRect(PlaneView view, TextMeasure measure, float size,
            ScreenRect storeResult) {
        float width = measure.width(text.getText(), size);
        float height = measure.lineHeight(size);
        float gap = GAP_FRACTION * size;
        float x = view.screenX(pointX);
        float y = view.screenY(pointY);
        switch (anchor) {
            case BELOW:
                return storeResult.set(x - width / 2f, y - gap - height, width, height);
            case ABOVE_RIGHT:
                return storeResult.set(x + gap, y + gap, width, height);
            case FOOT_RIGHT:
                float footGap = FOOT_GAP_FRACTION * size;
                return storeResult.set(x + footGap, y + footGap, width, height);
            default:
                return storeResult.set(x - width / 2f, y + gap, width, height);
        }
    }

    /**
     * Put the text where a rectangle says, or hide it.
     *
     * @param view the plane's mapping (not null, not modified)
     * @param size the text size (in pixels, &gt;0)
     * @param where its rectangle on the screen (in pixels, not null, copied)
     * @param show false to hide the text
     */
    public void apply(PlaneView view, float size, ScreenRect where, boolean show) {
        rect.set(where);
        visible = show;
        text.setSize(size / view.getPixelsPerMetre());
        // Over a plate, if its layout lays one under it (a post's name over a trail).
        text.setLocalTranslation(view.planeX(where.getX()), view.planeY(where.getTop()),
                ParticleView.LABEL_Z);
        showIfFree();
    }

    /**
     * Hide the text while something moving covers its place (a sphere on it), and show it
     * again when it moves off; the place stays as {@link #apply} put it. Allocates nothing.
     *
     * @param isCovered true while covered
     */
    public void setCovered(boolean isCovered) {
        if (isCovered != covered) {
            covered = isCovered;
            showIfFree();
        }
    }

    /**
     * Access the rectangle the text was last put in.
     *
     * @return the live rectangle (in pixels, do not modify)
     */
    public ScreenRect getRect() {
        return rect;
    }

    /**
     * Test whether the text is shown.
     *
     * @return true unless the layout hid it or something covers it
     */
    public boolean isVisible() {
        return visible && !covered;
    }

    /**
     * Test whether the layout placed the text (it may still be covered for a while).
     *
     * @return true unless the layout hid it
     */
    public boolean isPlaced() {
        return visible;
    }

    private void showIfFree() {
        text.setCullHint(visible && !covered ? Spatial.CullHint.Inherit
                : Spatial.CullHint.Always);
    }
}

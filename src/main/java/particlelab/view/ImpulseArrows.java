package particlelab.view;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;

/**
 * Impulse arrows at contacts, each with its label: an arrow as long as the impulse times a
 * fixed scale (metres per N·s), in one colour when the impulse was applied to its body and
 * in grey when it was not (a kinematic body's: infinite mass, nothing changes). A fixed pool
 * of arrows and labels made at construction; {@link #show} and {@link #hide} rewrite them in
 * place and allocate nothing.
 */
public final class ImpulseArrows {

    /** The arrows' colour when the impulse was applied. */
    public static final ColorRGBA APPLIED_COLOR = new ColorRGBA(1f, 0.85f, 0.2f, 1f);
    /** The arrows' colour when it was not (a kinematic body). */
    public static final ColorRGBA NOT_APPLIED_COLOR = new ColorRGBA(0.7f, 0.7f, 0.75f, 1f);
    /** The gap between an arrow's tip and its label (as a fraction of the label size). */
    private static final float LABEL_GAP = 0.3f;

    private final Node node = new Node("impulse arrows");
    private final VelocityArrow[] applied;
    private final VelocityArrow[] notApplied;
    private final HudText[] labels;
    private final BitmapFont font;
    private final float metresPerNewtonSecond;
    /** Scratch: an arrow's tip (m). */
    private final Vector3f tip = new Vector3f();

    /**
     * Create a pool of arrows, all hidden.
     *
     * @param assetManager loads the material (not null)
     * @param font the labels' font, one page (not null)
     * @param count how many arrows (&gt;0)
     * @param metresPerNewtonSecond an arrow's length per N·s of impulse (in m/(N·s), &gt;0)
     * @param shaftWidthMetres the shafts' width (in metres, &gt;0)
     */
    public ImpulseArrows(AssetManager assetManager, BitmapFont font, int count,
            float metresPerNewtonSecond, float shaftWidthMetres) {
        if (count <= 0 || !(metresPerNewtonSecond > 0f) || !(shaftWidthMetres > 0f)) {
            throw new IllegalArgumentException("impulse arrows need count > 0, scale > 0 and"
                    + " width > 0, but were " + count + ", " + metresPerNewtonSecond + ", "
                    + shaftWidthMetres);
        }
        this.font = font;
        this.metresPerNewtonSecond = metresPerNewtonSecond;
        Material unshaded = new Material(assetManager, "Common/MatDefs/Misc/Unshaded.j3md");
        applied = new VelocityArrow[count];
        notApplied = new VelocityArrow[count];
        labels = new HudText[count];
        for (int i = 0; i < count; ++i) {
            applied[i] = new VelocityArrow("impulse " + i, shaftWidthMetres,
                    metresPerNewtonSecond, APPLIED_COLOR, unshaded);
            // Not applied: a thinner grey arrow, so it reads as a ghost of the real one.
            notApplied[i] = new VelocityArrow("impulse not applied " + i,
                    0.5f * shaftWidthMetres, metresPerNewtonSecond, NOT_APPLIED_COLOR,
                    unshaded);
            labels[i] = new HudText(font, ColorRGBA.White);
            labels[i].setQueueBucket(RenderQueue.Bucket.Transparent);
            labels[i].setCullHint(Spatial.CullHint.Always);
            node.attachChild(applied[i].getGeometry());
            node.attachChild(notApplied[i].getGeometry());
            node.attachChild(labels[i]);
        }
    }

    /**
     * Access the node holding every arrow and label, to attach to the scene.
     *
     * @return the live node (not null)
     */
    public Node getNode() {
        return node;
    }

    /** @return how many arrows the pool holds (&gt;0) */
    public int size() {
        return applied.length;
    }

    /** @return an arrow's length per N·s (in m/(N·s), &gt;0) */
    public float getMetresPerNewtonSecond() {
        return metresPerNewtonSecond;
    }

    /**
     * Show one arrow: from a point along an impulse, with its label beyond the tip.
     *
     * @param index which arrow (0 to {@link #size()} - 1)
     * @param start where it starts, the contact point (in metres, not null, not modified)
     * @param impulse the impulse (in N·s, not null, not modified)
     * @param wasApplied true if the impulse changed its body's velocity (finite mass)
     * @param label the label, one line (not null, not modified)
     * @param labelSizeMetres the label's text size (in metres, &gt;0)
     */
    public void show(int index, Vector3f start, Vector3f impulse, boolean wasApplied,
            CharSequence label, float labelSizeMetres) {
        VelocityArrow shown = wasApplied ? applied[index] : notApplied[index];
        VelocityArrow other = wasApplied ? notApplied[index] : applied[index];
        other.getGeometry().setCullHint(Spatial.CullHint.Always);
        shown.update(start, impulse);
        HudText text = labels[index];
        text.setText(label);
        if (text.getSize() != labelSizeMetres) {
            text.setSize(labelSizeMetres);
        }
        text.setColor(wasApplied ? APPLIED_COLOR : NOT_APPLIED_COLOR);
        tip.set(impulse).multLocal(metresPerNewtonSecond).addLocal(start);
        float gap = LABEL_GAP * labelSizeMetres;
        float width = font.getLineWidth(label) * labelSizeMetres
                / font.getCharSet().getRenderedSize();
        // Beyond the tip: to its right for an arrow pointing right, else to its left; the
        // text's top half a line above the tip, so the tip points at its middle.
        float x = impulse.x >= 0f ? tip.x + gap : tip.x - gap - width;
        float y = tip.y + 0.5f * text.getLineHeight();
        text.setLocalTranslation(x, y, start.z + 0.02f);
        text.setCullHint(Spatial.CullHint.Inherit);
    }

    /**
     * Hide one arrow and its label.
     *
     * @param index which arrow (0 to {@link #size()} - 1)
     */
    public void hide(int index) {
        applied[index].getGeometry().setCullHint(Spatial.CullHint.Always);
        notApplied[index].getGeometry().setCullHint(Spatial.CullHint.Always);
        labels[index].setCullHint(Spatial.CullHint.Always);
    }
}

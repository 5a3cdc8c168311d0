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
 * fixed scale (metres per N·s), shortened only to keep its tip above the ground band
 * ({@link #lengthScale}), in one colour when the impulse was applied to its body and in grey
 * when it was not (a kinematic body's: infinite mass, nothing changes); its label where the
 * caller's layout put it ({@link CalloutLayout}). A fixed pool
 * of arrows and labels made at construction; {@link #show} and {@link #hide} rewrite them in
 * place and allocate nothing.
 */
public final class ImpulseArrows {

    /** The arrows' colour when the impulse was applied. */
    public static final ColorRGBA APPLIED_COLOR = new ColorRGBA(1f, 0.85f, 0.2f, 1f);
    /** The arrows' colour when it was not (a kinematic body). */
    public static final ColorRGBA NOT_APPLIED_COLOR = new ColorRGBA(0.7f, 0.7f, 0.75f, 1f);
    private final Node node = new Node("impulse arrows");
    private final VelocityArrow[] applied;
    private final VelocityArrow[] notApplied;
    private final HudText[] labels;
    private final float metresPerNewtonSecond;

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
     * Return how much of its full length an arrow may draw so that its tip stays above a
     * floor (the ground band's top): 1 when the tip is above it anyway, else the share that
     * ends the arrow on the floor, {@code s = (y0 − floor)/(−J_y·k)} with k the metres per
     * N·s. The label still gives the whole impulse.
     *
     * @param startY where the arrow starts (in metres, &ge; floorY)
     * @param impulseY the impulse's y (in N·s)
     * @param metresPerNewtonSecond the arrows' scale k (in m/(N·s), &gt;0)
     * @param floorY the lowest the tip may go (in metres)
     * @return s (from 0 to 1)
     */
    public static float lengthScale(float startY, float impulseY, float metresPerNewtonSecond,
            float floorY) {
        float drop = -impulseY * metresPerNewtonSecond;
        float room = startY - floorY;
        if (!(drop > room)) {
            return 1f;
        }
        return Math.max(0f, room / drop);
    }

    /**
     * Show one arrow from a point along an impulse (drawn at the pool's scale), and its label
     * at a place given, or no label.
     *
     * @param index which arrow (0 to {@link #size()} - 1)
     * @param start where it starts, the contact point (in metres, not null, not modified)
     * @param impulse the impulse as drawn (in N·s, not null, not modified; shortened by the
     *     caller where {@link #lengthScale} says)
     * @param wasApplied true if the impulse changed its body's velocity (finite mass)
     * @param label the label, one line (not null, not modified; empty: no label)
     * @param labelSizeMetres the label's text size (in metres, &gt;0)
     * @param labelLeft the label's left edge (in metres)
     * @param labelTop the label's top (in metres)
     */
    public void show(int index, Vector3f start, Vector3f impulse, boolean wasApplied,
            CharSequence label, float labelSizeMetres, float labelLeft, float labelTop) {
        VelocityArrow shown = wasApplied ? applied[index] : notApplied[index];
        VelocityArrow other = wasApplied ? notApplied[index] : applied[index];
        other.getGeometry().setCullHint(Spatial.CullHint.Always);
        shown.update(start, impulse);
        HudText text = labels[index];
        if (label.length() == 0) {
            text.setCullHint(Spatial.CullHint.Always);
            return;
        }
        text.setText(label);
        if (text.getSize() != labelSizeMetres) {
            text.setSize(labelSizeMetres);
        }
        text.setColor(wasApplied ? APPLIED_COLOR : NOT_APPLIED_COLOR);
        text.setLocalTranslation(labelLeft, labelTop, start.z + 0.02f);
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

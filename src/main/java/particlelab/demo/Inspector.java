package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.shape.Quad;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Spring;
import particlelab.physics.Thrust;
import particlelab.view.HudLayout;
import particlelab.view.HudText;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.view.TextMeasure;

/**
 * The picked body's numbers in a small box in the scene's top right corner, below the warning
 * band (and below the live graph, when it is up; the grid's height marks run down the left
 * edge, and most launches fly from the left): its label, P, V, |V|, the mass and each
 * force of its integrator by name with its value now, {@code F = F_push + m·g_field} (in
 * newtons). The text is rebuilt every frame into a reused {@link StringBuilder} and shown in
 * a {@link HudText}, so an open inspector allocates nothing; the force names are looked up
 * once, when a body is picked.
 */
final class Inspector {

    /** Decimals of the numbers shown. */
    private static final int DECIMALS = 2;
    /** The padding around the text inside the box (in text heights). */
    private static final float PADDING = 0.3f;
    /** The box's colour: the window's background, mostly opaque, so grid lines fade. */
    private static final ColorRGBA BOX_COLOR = new ColorRGBA(0.07f, 0.08f, 0.11f, 0.85f);
    private static final ColorRGBA TEXT_COLOR = new ColorRGBA(1f, 0.95f, 0.7f, 1f);

    private final Node node = new Node("inspector");
    private final StringBuilder text = new StringBuilder(512);
    private final ScreenRect rect = new ScreenRect();
    private HudText label;
    private Geometry box;
    private TextMeasure measure;
    /** The particle whose numbers are shown, or null. */
    private DemoParticle shown;
    /** Its forces' names, looked up when it was picked. */
    private String[] forceNames = new String[0];
    /** Scratch: one force's push and field acceleration (N, m/s²). */
    private final Vector3f push = new Vector3f();
    private final Vector3f field = new Vector3f();

    /**
     * Build the text and its box, hidden. Call once, at initialisation.
     *
     * @param assets loads the box's material (not null)
     * @param font the HUD's font (not null)
     */
    void build(AssetManager assets, BitmapFont font) {
        measure = TextMeasure.of(font);
        label = new HudText(font, TEXT_COLOR);
        Material material = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setColor("Color", BOX_COLOR);
        material.getAdditionalRenderState().setBlendMode(RenderState.BlendMode.Alpha);
        box = new Geometry("inspector box", new Quad(1f, 1f));
        box.setMaterial(material);
        box.setQueueBucket(RenderQueue.Bucket.Gui);
        node.attachChild(box);
        node.attachChild(label);
        node.setCullHint(Spatial.CullHint.Always);
    }

    /** @return the node to attach to the GUI (not null) */
    Node getNode() {
        return node;
    }

    /**
     * Write a particle's numbers, as the box shows them. Allocates nothing once the force
     * names were looked up ({@link #show}).
     *
     * @param storeResult where to write (not null, cleared and modified)
     * @param particle the particle (not null)
     * @return storeResult
     */
    StringBuilder format(StringBuilder storeResult, DemoParticle particle) {
        storeResult.setLength(0);
        Particle state = particle.getParticle();
        storeResult.append(particle.getLabel()).append('\n');
        storeResult.append("P = (");
        TextFormat.appendFixed(storeResult, state.position.x, DECIMALS).append(", ");
        TextFormat.appendFixed(storeResult, state.position.y, DECIMALS).append(") m\n");
        storeResult.append("V = (");
        TextFormat.appendFixed(storeResult, state.velocity.x, DECIMALS).append(", ");
        TextFormat.appendFixed(storeResult, state.velocity.y, DECIMALS).append(") m/s   |V| = ");
        TextFormat.appendFixed(storeResult, state.velocity.length(), DECIMALS).append(" m/s\n");
        storeResult.append("m = ");
        TextFormat.appendFixed(storeResult, state.getMass(), DECIMALS).append(" kg");
        if (particle.isHeld()) {
            storeResult.append("   (held: not stepped)");
        }
        ParticleIntegrator integrator = particle.getIntegrator();
        if (integrator.countForces() == 0) {
            storeResult.append("\nno force");
        }
        for (int i = 0; i < integrator.countForces(); ++i) {
            Force force = integrator.getForce(i);
            push.zero();
            field.zero();
            force.addForce(state, push);
            force.addFieldAcceleration(state, field);
            push.scaleAdd(state.getMass(), field, push);
            storeResult.append('\n').append(i < forceNames.length ? forceNames[i] : "force")
                    .append("  F = (");
            TextFormat.appendFixed(storeResult, push.x, DECIMALS).append(", ");
            TextFormat.appendFixed(storeResult, push.y, DECIMALS).append(") N");
        }
        return storeResult;
    }

    /**
     * Show a particle's numbers, or close the box: looks the force names up when the
     * particle changes (may allocate then).
     *
     * @param particle the picked particle, or null to close
     */
    void show(DemoParticle particle) {
        if (particle == shown) {
            return;
        }
        shown = particle;
        if (particle != null) {
            ParticleIntegrator integrator = particle.getIntegrator();
            forceNames = new String[integrator.countForces()];
            for (int i = 0; i < forceNames.length; ++i) {
                forceNames[i] = nameOf(integrator.getForce(i));
            }
        }
    }

    /** @return the particle shown, or null */
    DemoParticle getShown() {
        return shown;
    }

    /**
     * Rewrite and place the box: once a frame. Hidden while nothing is picked or the help is
     * up. Allocates nothing.
     *
     * @param layout the HUD's layout (not null, not modified)
     * @param helpVisible whether the help overlay covers the scene
     */
    void update(HudLayout layout, boolean helpVisible) {
        if (label == null) {
            return;
        }
        if (shown == null || helpVisible) {
            node.setCullHint(Spatial.CullHint.Always);
            rect.set(0f, 0f, 0f, 0f);
            return;
        }
        node.setCullHint(Spatial.CullHint.Inherit);
        float size = layout.getSceneLabelSize();
        label.setSize(size);
        label.setText(format(text, shown));
        float margin = layout.getMargin();
        // Below the warning band, or below the live graph when it is up.
        ScreenRect above = layout.getGraph().isEmpty() ? layout.getWarning() : layout.getGraph();
        float top = above.getY() - 0.5f * margin;
        float width = measure.width(label.getChars(), size);
        float height = label.getLineCount() * label.getLineHeight();
        float pad = PADDING * size;
        rect.set(layout.getScene().getRight() - margin - pad - width, top - height, width,
                height);
        label.setLocalTranslation(rect.getX(), top, 1f);
        box.setLocalTranslation(rect.getX() - pad, rect.getY() - pad, 0.5f);
        box.setLocalScale(width + 2f * pad, height + 2f * pad, 1f);
    }

    /**
     * Copy the text's rectangle, as last placed.
     *
     * @return the live rectangle (empty when hidden; do not modify)
     */
    ScreenRect getRect() {
        return rect;
    }

    /**
     * Name a force for the box: by its kind, or its class's name.
     *
     * @param force the force (not null)
     * @return the name (not null)
     */
    static String nameOf(Force force) {
        if (force instanceof Gravity) {
            return "gravity m g";
        } else if (force instanceof LinearDrag) {
            return "linear drag -b V";
        } else if (force instanceof QuadraticDrag) {
            return "quadratic drag -c |V| V";
        } else if (force instanceof Thrust) {
            return "thrust";
        } else if (force instanceof Spring) {
            return "spring";
        }
        String name = force.getClass().getSimpleName();
        return name.isEmpty() ? "force" : name;
    }
}

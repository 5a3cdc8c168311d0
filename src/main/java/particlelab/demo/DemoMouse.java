package particlelab.demo;

import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.scene.Node;
import java.util.List;
import particlelab.view.HudView;
import particlelab.view.ParameterPanel;
import particlelab.view.ScreenRect;

/**
 * The mouse on a demo's bodies, beside its base class: the declared drags and the picked body
 * ({@link DragControl}), the inspector box that shows the picked body's numbers
 * ({@link Inspector}), and whether the HUD takes the mouse at a point instead (the help
 * overlay, the parameter panel), so that a press there picks nothing behind it. The
 * application's pick input asks {@link DemoWindow#isHudAt} first, then hands the press to the
 * drag control. Once a frame the inspector follows the pick; it allocates nothing.
 */
final class DemoMouse {

    private final DragControl drags;
    private final Inspector inspector = new Inspector();
    /** Scratch: the panel's rectangle (in pixels). */
    private final ScreenRect panelRect = new ScreenRect();

    /**
     * Create the mouse of a demo; its inspector's view comes with {@link #build}.
     *
     * @param drags the demo's drag control (not null)
     */
    DemoMouse(DragControl drags) {
        this.drags = drags;
    }

    /** @return the demo's drag control: pick, drag, release (live, not null) */
    DragControl getDrags() {
        return drags;
    }

    /**
     * Build the inspector's box on the HUD, and tell the drags the spheres' size. Call once,
     * at initialisation, after the HUD and the scene were built.
     *
     * @param assets the asset manager (not null)
     * @param font the HUD's font (not null)
     * @param hudNode the HUD's node, where the box goes (not null, modified)
     * @param sphereRadiusMetres the particles' drawn radius (in metres, &gt;0)
     */
    void build(AssetManager assets, BitmapFont font, Node hudNode, float sphereRadiusMetres) {
        inspector.build(assets, font);
        hudNode.attachChild(inspector.getNode());
        drags.setSphereRadius(sphereRadiusMetres);
    }

    /**
     * Test whether the HUD takes the mouse at a screen point: the help overlay (it covers the
     * scene) or the parameter panel.
     *
     * @param hud the demo's HUD, or null before initialisation (then the HUD takes it)
     * @param panel the parameter panel (not null)
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @return true if the HUD is there
     */
    boolean isHudAt(HudView hud, ParameterPanel panel, float screenX, float screenY) {
        if (hud == null || hud.isHelpVisible()) {
            return true;
        }
        panel.copyRect(panelRect);
        return !panelRect.isEmpty() && panelRect.contains(screenX, screenY);
    }

    /**
     * Write the inspector's text for the picked body, as its box shows it.
     *
     * @param storeResult where to write (not null, cleared and modified)
     * @return storeResult, empty when nothing is picked
     */
    StringBuilder formatInspector(StringBuilder storeResult) {
        DemoParticle picked = drags.getPicked();
        inspector.show(picked);
        if (picked == null) {
            storeResult.setLength(0);
            return storeResult;
        }
        return inspector.format(storeResult, picked);
    }

    /** @return the inspector's text rectangle as last placed (live, empty while closed) */
    ScreenRect getInspectorRect() {
        return inspector.getRect();
    }

    /**
     * Add a copy of the inspector's text rectangle to a list, if it is open: for the tests
     * of overlaps.
     *
     * @param storeResult where to add it (not null, modified)
     */
    void copyTextRects(List<ScreenRect> storeResult) {
        if (!inspector.getRect().isEmpty()) {
            storeResult.add(new ScreenRect().set(inspector.getRect()));
        }
    }

    /**
     * Once a frame: the inspector shows the picked body, placed for the HUD's layout.
     * Allocates nothing.
     *
     * @param hud the demo's HUD (not null)
     */
    void update(HudView hud) {
        inspector.show(drags.getPicked());
        inspector.update(hud.getLayout(), hud.isHelpVisible());
    }
}

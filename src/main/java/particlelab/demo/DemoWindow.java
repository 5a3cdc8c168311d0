package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.scene.Node;
import java.util.ArrayList;
import java.util.List;
import particlelab.view.BodyViews;
import particlelab.view.HudFont;
import particlelab.view.HudView;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;

/**
 * What a demo shows, beside its base class: the HUD's text and the slide, written from the
 * demo's numbers (with or without a window); in a window its views built once (the demo's and
 * its parts' own, the scene, the ghosts, the HUD, the mouse's texts, the panel), attached and
 * detached with the demo, moved after each frame's physics and after a launch or a reset, and
 * the HUD, panel and mouse updated; and the screen rectangles a test checks.
 * {@link DemoState} calls it from jME's lifecycle; without a window (a test, an export) no
 * view is built and a frame is only physics. The application reaches it through
 * {@link DemoState#getWindow()}.
 */
public final class DemoWindow {

    private final DemoState demo;
    private final DemoRun run;
    private final DemoScene scene;
    private final SceneFraming framing;
    private final ExactGhosts ghosts;
    private final DemoKeys keys;
    private final ParameterControls parameterControls;
    private final DemoParts parts;
    private final DemoHud demoHud;
    private final DemoMouse mouse;
    private final HudWriter hudWriter;
    private final Node sceneNode;
    private final KeyMappings keyMappings;
    private Node guiRoot;
    private Node sceneRoot;
    /** The parameters' version the equations were written for. */
    private int equationsVersion;

    /**
     * Gather the pieces a demo shows in a window; nothing is built until {@link #build}.
     *
     * @param demo the demo, its title set (not null)
     * @param run its run (not null)
     * @param scene its scene (not null)
     * @param framing its camera's frame (not null)
     * @param ghosts its exact ghosts (not null)
     * @param keys its keys (not null)
     * @param parameterControls its parameters' panel (not null)
     * @param parts its parts (not null)
     * @param demoHud its HUD (not null)
     * @param mouse its mouse on the bodies (not null)
     * @param hudWriter the lines every demo shows (not null)
     * @param sceneNode the node of its scene (not null)
     */
    DemoWindow(DemoState demo, DemoRun run, DemoScene scene, SceneFraming framing,
            ExactGhosts ghosts, DemoKeys keys, ParameterControls parameterControls,
            DemoParts parts, DemoHud demoHud, DemoMouse mouse, HudWriter hudWriter,
            Node sceneNode) {
        this.demo = demo;
        this.run = run;
        this.scene = scene;
        this.framing = framing;
        this.ghosts = ghosts;
        this.keys = keys;
        this.parameterControls = parameterControls;
        this.parts = parts;
        this.demoHud = demoHud;
        this.mouse = mouse;
        this.hudWriter = hudWriter;
        this.sceneNode = sceneNode;
        this.keyMappings = new KeyMappings("particlelab/" + demo.getTitle() + "/",
                demoHud::markDirty);
        // The HUD's lines read the warnings, contact pause, ghosts and replay; the ring keeps
        // what the ghosts and kept shots show beside the simulation's state.
        hudWriter.setWarnings(run.getWarnings());
        hudWriter.setContactPause(run.getContactPause());
        hudWriter.setGhosts(ghosts);
        hudWriter.setReplay(run.getReplay());
        parameterControls.setReplay(run.getReplay());
        run.addViewRecord(ghosts);
        run.addViewRecord(parameterControls.keptShotsRecord());
    }

    /**
     * Advance the demo by one frame: the physics ({@link DemoRun#advancePhysics}), then the
     * demo's and its parts' frame hooks ({@code afterFrame}), then the views in a window (none
     * without one): {@link DemoState#update} without the HUD. Allocates nothing.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    public void advance(float tpf) {
        run.advancePhysics(tpf);
        Replay replay = run.getReplay();
        // This frame's blend, for the demo's own views in afterFrame (getDrawBlend).
        replay.updateFrameBlend(run.isSceneOver());
        parts.afterFrame();
        run.getWorld().getImpacts().clear();
        drawFrame(replay.updateFrameBlend(run.isSceneOver()), tpf);
    }

    /**
     * @return the blend the views draw with this frame, {@code α = leftover / h} between the
     *     last two physics states, or 1 (interpolation off, raw tpf, paused, replaying): for
     *     a demo's own views in its {@code afterFrame}
     */
    public float getDrawBlend() {
        return run.getReplay().getFrameBlend();
    }

    /**
     * Say that the demo's own views draw the raw physics steps, not the interpolated picture
     * of F6 (the fountain's points, the rotating boxes), so the HUD's stepping line says so.
     * Call from the demo's {@code createScene()}.
     */
    public void drawsRawSteps() {
        run.getReplay().drawsRawSteps();
    }

    /** @return the HUD (live, null before initialisation) */
    public HudView getHud() {
        return demoHud.getView();
    }

    /**
     * @param particle one of the demo's particles (not null)
     * @return its view: sphere, label, trail, arrow (live; null before a window built it)
     */
    public ParticleView getView(DemoParticle particle) {
        return scene.viewOf(particle);
    }

    /** @return the mapping of the scene's plane to the window, as last laid out (live) */
    public PlaneView getPlaneView() {
        return scene.getPlaneView();
    }

    /** @return the mouse's control of the bodies: pick, drag, release (live, not null) */
    public DragControl getDragControl() {
        return mouse.getDrags();
    }

    /**
     * Frame less than the whole region: up to a height (e.g. the apex of the shot in the
     * air), at most the region's top. Call from the demo's {@code createScene()} or later;
     * the camera is reframed at once.
     *
     * @param topMetres the top edge to frame (in metres, finite, &gt;0)
     */
    public void setViewTop(float topMetres) {
        framing.setTop(topMetres);
    }

    /**
     * Write the HUD's body text: the lines every demo shows, the demo's own, its parts', then
     * the note (a tour stop's). Allocates nothing.
     *
     * @param storeResult storage for the text (not null, cleared and modified)
     * @return storeResult
     */
    public StringBuilder formatHud(StringBuilder storeResult) {
        hudWriter.write(storeResult, run.isSceneOver());
        parts.writeHudLines(storeResult);
        HudNote note = demoHud.getNote();
        if (note != null) {
            int length = storeResult.length();
            if (length > 0 && storeResult.charAt(length - 1) != '\n') {
                // A demo's last line without its newline: the note starts a line of its own.
                storeResult.append('\n');
            }
            note.append(demo, storeResult);
        }
        return storeResult;
    }

    /**
     * Write the slide presentation mode shows now, the demo's then its parts'. Allocates
     * nothing.
     *
     * @return the slide (live: rewritten by the next call or frame)
     */
    public Presentation formatPresentation() {
        Presentation slide = demoHud.getSlide();
        slide.clear();
        parts.writePresentation(slide);
        return slide;
    }

    /**
     * Write the slide of a demo that writes none of its own: the first equation line and the
     * first particle's speed. Allocates nothing.
     *
     * @param slide where to write (not null, emptied)
     */
    void writeDefaultSlide(Presentation slide) {
        String equations = hudWriter.getEquations();
        int end = equations.indexOf('\n');
        slide.formula().append(equations, 0, end < 0 ? equations.length() : end);
        List<DemoParticle> particles = run.getParticles();
        if (!particles.isEmpty()) {
            DemoParticle first = particles.get(0);
            TextFormat.appendFixed(slide.readout().append(first.getLabel()).append(":  |V| = "),
                    first.getParticle().velocity.length(), 2).append(" m/s");
        }
    }

    /**
     * Write the equations of a demo that describes none of its own: the Euler step, then
     * each particle's forces, one line each.
     *
     * @param text where to append (not null, modified)
     */
    void describeForces(StringBuilder text) {
        text.append("Euler step: a = g + F/m,  V += h·a,  P += h·V\n");
        List<DemoParticle> particles = run.getParticles();
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            text.append(particle.getLabel()).append(":  ")
                    .append(particle.getIntegrator().describe()).append('\n');
        }
    }

    /**
     * Copy the rectangle the scene is drawn into on the screen, as last laid out.
     *
     * @param storeResult storage for the rectangle (in pixels, not null, modified)
     * @return storeResult
     */
    public ScreenRect copySceneRect(ScreenRect storeResult) {
        return scene.copyDrawnRect(demoHud.getView().getLayout().getScene(), storeResult);
    }

    /**
     * Make a demo's own spheres (beyond its particles: the targets' platform) obstacles for
     * the particles' labels, which keep off them as off the particles' spheres.
     *
     * @param spheres the spheres, read each frame as last drawn (alias kept; null for none)
     */
    public void setLabelObstacles(BodyViews spheres) {
        scene.setObstacleSpheres(spheres);
    }

    /**
     * Copy the screen rectangle of every text shown, HUD and scene (left out while the help
     * hides it), into a list: what a test checks for overlaps.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        HudView hud = demoHud.getView();
        hud.copyTextRects(storeResult);
        if (!hud.isHelpVisible()) {
            scene.copyTextRects(storeResult);
            ghosts.copyTextRects(storeResult);
            mouse.copyTextRects(storeResult);
        }
        return storeResult;
    }

    /**
     * Test whether the HUD takes the mouse at a screen point (the help, the panel), so that
     * a press there picks no body behind it.
     *
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @return true if the HUD is there
     */
    public boolean isHudAt(float screenX, float screenY) {
        return mouse.isHudAt(demoHud.getView(), parameterControls.getPanel(), screenX,
                screenY);
    }

    /**
     * @param storeResult where to add every post's screen rectangle (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyPostRects(List<ScreenRect> storeResult) {
        return scene.copyPostRects(storeResult);
    }

    /**
     * @param storeResult where to add every post name's screen rectangle, in the posts'
     *     order (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyPostLabelRects(List<ScreenRect> storeResult) {
        return scene.copyPostLabelRects(storeResult);
    }

    /**
     * Build every view, once, after the scene was declared: the demo's and its parts' own
     * first, then the shared ones, the HUD with its footer, equations and help, the mouse's
     * texts and the panel; then lay them out for the window.
     *
     * @param app the application (not null)
     */
    void build(Application app) {
        parts.buildViews(app);
        AssetManager assets = app.getAssetManager();
        BitmapFont font = HudFont.load(assets);
        framing.frameLaunches();
        scene.build(assets, font, sceneNode);
        run.getWorld().addStepListener(scene.getTrailWriter());
        ghosts.build(assets, font, sceneNode, run.getWorld(), scene);
        int width = app.getCamera().getWidth();
        int height = app.getCamera().getHeight();
        HudView hud = demoHud.build(assets, font, width, height);
        mouse.build(assets, font, hud.getNode(), scene.getSphereRadius());
        hud.setFooter(keys.buildFooter());
        demo.refreshEquations();
        hud.setHelp(keys.buildHelp(demo.getTitle()));
        // The parameter panel with its buttons (pause, step, reset, fire, export, next demo).
        List<String> labels = new ArrayList<>();
        List<Runnable> actions = new ArrayList<>();
        keys.listPanelButtons(labels, actions,
                () -> run.getClock().setPaused(!run.getClock().isPaused()), run::singleStep,
                this::restartAndReframe, keys::requestExport);
        parameterControls.build(app, font, hud.getLayout(), run.getParticles(), scene,
                scene.getSphereRadius(), sceneNode, labels, actions);
        equationsVersion = demo.getParameters().getVersion();
        // The side panel's slot narrows the HUD's body: lay it out again.
        hud.layOut(width, height, hud.getLayout().getScale());
        demoHud.layOutFirst();
        sceneRoot = (Node) app.getViewPort().getScenes().get(0);
        guiRoot = (Node) app.getGuiViewPort().getScenes().get(0);
        scene.updateViews();
        if (demoHud.isPresenting()) {
            demoHud.applyPresentation();
        }
    }

    /** Forget the views: the trails stop listening, the scene's node is emptied. */
    void cleanup() {
        run.getWorld().removeStepListener(scene.getTrailWriter());
        sceneNode.detachAllChildren();
    }

    /**
     * Attach the views and map the keys, as the demo is enabled.
     *
     * @param app the application (not null)
     */
    void attach(Application app) {
        sceneRoot.attachChild(sceneNode);
        guiRoot.attachChild(demoHud.getView().getNode());
        guiRoot.attachChild(ghosts.getGraphNode());
        guiRoot.attachChild(parameterControls.getPanel().getNode());
        keyMappings.map(app.getInputManager(), keys.copyMapped());
        framing.frameCamera();
        demoHud.markDirty();
    }

    /**
     * Detach the views and unmap the keys, as the demo is disabled.
     *
     * @param app the application (not null)
     */
    void detach(Application app) {
        if (demoHud.getView() == null) {
            // Cleaned up without having been initialised (another state failed first, and
            // jME tidies up every attached state): attach never ran, nothing to undo.
            return;
        }
        keyMappings.unmap(app.getInputManager());
        sceneNode.removeFromParent();
        demoHud.getView().getNode().removeFromParent();
        ghosts.getGraphNode().removeFromParent();
        parameterControls.getPanel().getNode().removeFromParent();
    }

    /**
     * Move the views to this frame's physics (none without a window) and age the HUD's
     * warnings and notice. Allocates nothing.
     *
     * @param drawBlend the blend between the last two physics states to draw (0 to 1)
     * @param tpf the frame time (in seconds, &ge;0)
     */
    void drawFrame(float drawBlend, float tpf) {
        scene.setDrawBlend(drawBlend);
        HudView hud = demoHud.getView();
        if (hud != null) {
            scene.updateViews();
            ghosts.updateViews(hud.getLayout(), hud.isHelpVisible());
        }
        run.getWarnings().age(tpf);
        hudWriter.age(tpf);
    }

    /**
     * Update the HUD, the panel and the mouse's texts after a frame (the equations first, if
     * a parameter changed them); nothing without a window.
     *
     * @param tpf the frame time (in seconds, &ge;0)
     */
    void update(float tpf) {
        if (equationsVersion != demo.getParameters().getVersion()) {
            // A value reached the scene: the equations' numbers follow it.
            equationsVersion = demo.getParameters().getVersion();
            demo.refreshEquations();
        }
        HudView hud = demoHud.getView();
        if (hud == null) {
            return;
        }
        demoHud.update(tpf);
        parameterControls.update(hud.getLayout());
        mouse.update(hud);
    }

    /** After the run put every particle back: their trails and ghosts start again. */
    void particlesRestarted() {
        List<DemoParticle> particles = run.getParticles();
        for (int i = 0; i < particles.size(); ++i) {
            scene.restartTrail(particles.get(i));
        }
        ghosts.restartAll();
    }

    /** After a reset: the camera frames the launches (not during a drag), the HUD follows. */
    void restarted() {
        if (!mouse.getDrags().isDragging()) {
            // During a drag the camera holds still, so the grip stays under the mouse.
            framing.frameLaunches();
        }
        demoHud.markDirty();
    }

    /**
     * Forget the faint paths of earlier launches (the kept shots) and their legend: a tour
     * stop starts with none, so no path of the stop before (another h, a lane since switched
     * off) is drawn beside this stop's. Allocates nothing.
     */
    public void clearKeptShots() {
        parameterControls.clearShots();
    }

    /** @return how many earlier launches are drawn as kept shots now (&ge;0) */
    public int countKeptShots() {
        return parameterControls.countHeldShots();
    }

    /**
     * After one particle was launched again: its trail and ghost start again, the camera
     * frames the launches, the HUD follows.
     *
     * @param particle the particle (not null)
     */
    void launched(DemoParticle particle) {
        scene.restartTrail(particle);
        ghosts.restart(particle.index);
        framing.frameLaunches();
        demoHud.markDirty();
    }

    /** After the panel came or went: the HUD and the scene get the window's width back. */
    void relayOutPanel() {
        demoHud.panelMoved();
    }

    /** Show or hide the live graph, and lay out again for its slot. */
    void toggleGraph() {
        ghosts.toggleGraph(demoHud.getView().getLayout());
        demoHud.layOutAgain();
    }

    /** The R key and the panel's Reset: restart, and frame the camera afresh. */
    void restartAndReframe() {
        run.restart();
        framing.frameCamera();
    }
}

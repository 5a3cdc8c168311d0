package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import java.util.List;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.HudLayout;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * The one base class of every demo: a thin jME {@link BaseAppState} over the demo's run. A
 * demo declares its particles and their forces, its keys, parameters and HUD lines in the
 * hooks below; this class keeps the jME lifecycle, those hooks and one-line forwarders to the
 * pieces beside it, which own the rest.
 *
 * <h2>Writing a demo</h2>
 * {@link #createScene()} (required) calls {@link #addParticle} once per particle, with an
 * integrator holding its forces, and {@link #setView} for the region; it may call
 * {@link #showExactGhosts()}, add a rule to {@link #getWorld()} for collisions and parts with
 * {@link #addPart} (in the constructor). Optional: {@link #buildViews} (the demo's own views,
 * only in a window), {@link #declareKeys()}, {@link #declareParameters()},
 * {@link #declareDraggables()}, {@link #writeHudLines} (numbers with {@link TextFormat}: it
 * allocates nothing), {@link #writePresentation} (the slide of F8), {@link #beforeStep},
 * {@link #afterStep}, {@link #afterFrame} and {@link #onRestart()}.
 *
 * <h2>Once per frame</h2>
 * {@link #update} hands the frame time to the run ({@link DemoRun}: the
 * {@link SimulationClock} decides the steps, the demo's {@link World} takes each, every
 * particle moved by its own {@link ParticleIntegrator}, then the contacts of its rules).
 * Nothing else moves a particle; the demo and its parts hear each step ({@link StepListener}).
 * Then, in a window ({@link DemoWindow}), the views read the particles and the HUD text is
 * rebuilt in a reused {@link StringBuilder}; a whole frame allocates nothing.
 *
 * <h2>Beside it</h2>
 * This class's own members are what a demo writes and calls: the hooks, the tools, the
 * scene's parts ({@link #getWorld()}, {@link #getClock()}, {@link #getParticles()},
 * {@link #getParameters()}, {@link #getSceneNode()}, {@link #restart()}) and the jME
 * lifecycle (at most 46, {@code DemoStateSourceTest}). The rest is the owners', reached from
 * the demo: {@link #getRun()} ({@link DemoRun}: the physics, no jME; a frame's steps, a
 * simulation beside the world, the count of particles simulated), {@link #getWindow()}
 * ({@link DemoWindow}: a frame with its views, a particle's view, the HUD's view, the plane's
 * mapping, the mouse's drags, the blend the views draw with, the frame's top, the HUD's text
 * and slide), {@link #getDemoHud()} ({@link DemoHud}: notices, notes, layout, presentation
 * mode), {@link #getKeys()} ({@link DemoKeys}: the bindings, the application's keys, a key
 * group, the fire key, the help) and {@link #getReplayControls()} (step back and forward,
 * F6). Behind them: {@code DemoScene} and {@code SceneFraming} (region, grid, posts, particle
 * views, camera), {@code HudWriter}, {@code SharedKeys}, {@code ParameterControls} (the panel,
 * the kept shots), {@code DemoMouse}, {@code ExactGhosts}, and the {@link DemoPart}s.
 */
public abstract class DemoState extends BaseAppState {

    /** The frame time injected by the hitch key (in seconds). */
    public static final float HITCH_SECONDS = DemoRun.HITCH_SECONDS;
    /** How often the HUD text is rebuilt by default (s of frame time): 0, every frame. */
    public static final float HUD_REFRESH_SECONDS = 0f;
    /**
     * How long the body's band is kept for more lines than the body needs now (s of frame
     * time): numbers changing width do not move the scene, one crowded stretch (a slow
     * frame's warning, a tour stop's lines) does not shrink or cut the HUD for good.
     */
    public static final float HUD_BAND_KEEP_SECONDS = 2f;
    /** A slower HUD refresh ({@link DemoHud#setRefreshSeconds}): 10 Hz (s). */
    public static final float SLOW_HUD_REFRESH_SECONDS = 0.1f;

    private final String title;
    /** What the run tells the demo and its parts at fixed moments of a step and a reset. */
    private final DemoRun.Hooks runHooks = new DemoRun.Hooks() {
        @Override
        public void prepare() {
            ensureScene();
        }

        @Override
        public void beforeStep(float stepSeconds) {
            parts.beforeStep(stepSeconds);
        }

        @Override
        public void afterStep(float stepSeconds) {
            ghosts.afterStep(stepSeconds);
            parts.afterStep(stepSeconds);
        }

        @Override
        public void beforeRestart() {
            parameterControls.beforeLaunch();
        }

        @Override
        public void particlesRestarted() {
            window.particlesRestarted();
        }

        @Override
        public void restarted() {
            parts.onRestart();
            window.restarted();
        }

        @Override
        public void changed() {
            demoHud.markDirty();
        }
    };
    /** The run: clock, world, particles, restart, recovery, the replay ring (no jME). */
    private final DemoRun run = new DemoRun(runHooks);
    private final SimulationClock clock = run.getClock();
    private final World world = run.getWorld();
    private final List<DemoParticle> particles = run.getParticles();
    private final DemoScene scene = new DemoScene(particles);
    private final SceneFraming framing = new SceneFraming(this, scene, particles, clock);
    private final ExactGhosts ghosts = new ExactGhosts(particles);
    private final DemoKeys keys = new DemoKeys(this::ensureScene);
    private final ParameterControls parameterControls =
            new ParameterControls(run.getParameterValues());
    private final HudWriter hudWriter = new HudWriter(clock, particles);
    /** The demo's hooks, then its parts' ({@link #addPart}), at each moment. */
    private final DemoParts parts = new DemoParts(this);
    /** Where the energy goes (issue 32): every demo's first part, its world's ledger. */
    private final EnergyPart energyPart = addPart(new EnergyPart());
    private final Replay replay = run.getReplay();
    private final Node sceneNode;
    /** The HUD: title, body, band, layout, note and presentation mode. */
    private final DemoHud demoHud;
    private final ReplayControls replayControls;
    /** The views, HUD, panel and keys in a window (built only when one comes). */
    private final DemoWindow window;
    /** Scratch: a particle's launch position (m). */
    private final Vector3f launchPosition = new Vector3f();
    /** The mouse on the bodies: the declared drags, the picked body, its inspector. */
    private final DemoMouse mouse = new DemoMouse(new DragControl(particles, clock,
            this::restart, framing::frameLaunches, scene::areArrowsVisible));

    private boolean sceneCreated;
    /** Inside {@link #createScene()}: the scene is being declared, not yet complete. */
    private boolean creatingScene;
    private boolean parametersDeclared;

    /**
     * Create a demo.
     *
     * @param title the name shown in the HUD and the demo list (not null, not empty)
     */
    protected DemoState(String title) {
        if (title == null || title.isEmpty()) {
            throw new IllegalArgumentException("demo title must be a non-empty text");
        }
        this.title = title;
        this.sceneNode = new Node(title + " scene");
        this.demoHud = new DemoHud(this, title, scene, keys, parameterControls,
                run.getWarnings(), hudWriter);
        this.replayControls = new ReplayControls(run, scene, hudWriter, demoHud);
        this.window = new DemoWindow(this, run, scene, framing, ghosts, keys, parameterControls,
                parts, demoHud, mouse, hudWriter, sceneNode);
    }

    // ---------------------------------------------------------------- hooks for a demo ----

    /**
     * Declare the particles ({@link #addParticle}) and the view ({@link #setView}). Called once,
     * the first time the world, the particles or the window need the scene: so a demo's
     * physics runs without jME. Create no jME object here (the views come from the
     * declarations, later; a demo's own views from {@link #buildViews}).
     */
    protected abstract void createScene();

    /**
     * Build the demo's own views (walls, curves, a point cloud, sounds) and attach them to
     * {@link #getSceneNode()}. Called once, only in a window, after {@link #createScene()} and
     * before the shared views. The default builds none.
     *
     * @param app the application whose assets, audio and camera the views use (not null)
     */
    protected void buildViews(Application app) {
    }

    /**
     * Declare the demo's own keys with {@link #bindKey}. Called once, after
     * {@link #createScene()}. The default declares none.
     */
    protected void declareKeys() {
    }

    /**
     * Declare the numbers the user may change with {@link #declareParameter} (launch, mass,
     * g, coefficients). Called once, before or after the scene is created: declare only, the
     * setters may touch the particles. The default declares none (h is every demo's).
     */
    protected void declareParameters() {
    }

    /**
     * Declare what the mouse may drag with {@link #declareDraggable} (a launch, a ball, a
     * target); the help's "Mouse" section is written from them. Called once, after
     * {@link #declareKeys()}. The default declares nothing (a click still inspects).
     */
    protected void declareDraggables() {
    }

    /**
     * Describe the equations the demo runs, with their numbers, one line each, for the top of
     * the HUD. Called by {@link #refreshEquations()}: may allocate. The default lists each
     * particle's forces.
     *
     * @param text where to append (not null, modified)
     */
    protected void describeEquations(StringBuilder text) {
        window.describeForces(text);
    }

    /**
     * Append the demo's own HUD lines, each ending in a newline. Called every frame: append
     * with {@link TextFormat} and constant strings, so nothing is allocated.
     *
     * @param text where to append (not null, modified)
     */
    protected void writeHudLines(StringBuilder text) {
    }

    /**
     * Write the slide presentation mode shows (F8, {@code --present}): one or two formula
     * lines with their live numbers ({@link Presentation#formula()}) and the one readout the
     * slide is about ({@link Presentation#readout()}), from the numbers the HUD lines show.
     * Called every frame while presenting: allocate nothing. The default shows the first
     * equation line and the first particle's speed.
     *
     * @param slide where to write (not null, emptied before the call)
     */
    protected void writePresentation(Presentation slide) {
        window.writeDefaultSlide(slide);
    }

    /**
     * Act at the start of a step, before anything moves: the place to relaunch a shot that
     * {@link #afterStep} found due. The default does nothing.
     *
     * @param stepSeconds h of the step about to be taken (in seconds, &gt;0)
     */
    protected void beforeStep(float stepSeconds) {
    }

    /**
     * React to one simulation step, after every particle moved: observe it (counters,
     * readouts, what is due next); move nothing, the world did all the moving (see
     * {@link particlelab.world.StepListener}). The default does nothing.
     *
     * @param stepSeconds h of the step just taken (in seconds, &gt;0)
     */
    protected void afterStep(float stepSeconds) {
    }

    /**
     * React to one frame, after its steps and before the views move (sounds, flashes; the
     * world's impacts are cleared after it). Allocate nothing. The default does nothing.
     */
    protected void afterFrame() {
    }

    /**
     * React to a new fixed step h (the {@code h} parameter), once the clock steps with it:
     * recompute what was derived from h (an aim, a planned round). Called as the scene starts
     * and at every later change. The default does nothing.
     *
     * @param stepSeconds the new h (in seconds, &gt;0)
     */
    protected void onStepChanged(float stepSeconds) {
    }

    /**
     * React to a reset, after the particles went back to their launch states and the clock
     * to zero. The default does nothing.
     */
    protected void onRestart() {
    }

    /**
     * Add the demo's own tables to an export, beside its particles' trajectories (the
     * rotation boxes per step, the fountain's counts, the aimer's shots); may allocate. The
     * default adds none.
     *
     * @param storeResult where to add them (not null, modified)
     */
    public void collectExportTables(List<StepTable> storeResult) {
    }

    // ------------------------------------------------------- tools for createScene etc. ----

    /**
     * Add a particle to the scene. Call from {@link #createScene()}.
     *
     * @param label its label, shown next to it and in the HUD (not null)
     * @param color its colour (not null, not modified)
     * @param position its launch position (in metres, finite, not null, not modified)
     * @param velocity its launch velocity (in m/s, finite, not null, not modified)
     * @param massKg its mass (in kilograms, finite, &gt;0)
     * @param integrator the integrator holding the forces that act on it (not null)
     * @return the new demo particle, e.g. to call {@link DemoParticle#stopAtGround()}
     */
    protected DemoParticle addParticle(String label, ColorRGBA color, Vector3f position,
            Vector3f velocity, float massKg, ParticleIntegrator integrator) {
        if (sceneCreated) {
            throw new IllegalStateException("add particles in createScene(), not later");
        }
        if (label == null || color == null || integrator == null) {
            throw new IllegalArgumentException("label, color and integrator must not be null");
        }
        return run.addParticle(label, color, position, velocity, massKg, integrator);
    }

    /**
     * Choose the region of the x-y plane the camera frames, the grid and the sphere size.
     *
     * @param xMin the left edge (in metres)
     * @param xMax the right edge (in metres, &gt;xMin)
     * @param yMax the top edge (in metres, &gt;0); the ground band below y = 0 is added
     * @param gridSpacingMetres the distance between grid lines (in metres, &gt;0)
     * @param labelEvery a distance mark every this many grid lines (&ge;1)
     * @param sphereRadiusMetres the particles' radius as drawn (in metres, &gt;0)
     */
    protected void setView(float xMin, float xMax, float yMax, float gridSpacingMetres,
            int labelEvery, float sphereRadiusMetres) {
        scene.setRegion(xMin, xMax, yMax, gridSpacingMetres, labelEvery, sphereRadiusMetres);
    }

    /**
     * Add a labelled post standing on the ground, such as a gun or a target. Call from
     * {@link #createScene()}.
     *
     * @param label the text above the post (not null)
     * @param x where it stands (in metres)
     * @param heightMetres how tall it is (in metres, &gt;0)
     * @param color its colour (not null, not modified)
     */
    protected void addMarker(String label, float x, float heightMetres, ColorRGBA color) {
        scene.addMarker(label, x, heightMetres, color);
    }

    /**
     * Add a labelled post as {@link #addMarker} does, its name right of its foot: for a post
     * a body rests on (a ledge), whose top the body and its trail cover.
     *
     * @param label the text beside the post's foot (not null)
     * @param x where it stands (in metres)
     * @param heightMetres how tall it is (in metres, &gt;0)
     * @param color its colour (not null, not modified)
     */
    protected void addMarkerNamedAtFoot(String label, float x, float heightMetres,
            ColorRGBA color) {
        scene.addMarker(label, x, heightMetres, color, true);
    }

    /**
     * Declare a key. Call from {@link #declareKeys()}.
     *
     * @param keyCode the key, a {@link KeyInput} code, not used by jME, the app or the shared
     *     controls
     * @param keyLabel the key as printed for the help overlay (not null)
     * @param description what it does (not null)
     * @param action run once per press, on the jME thread (not null)
     * @return the binding, e.g. to name its key in a HUD line (not null)
     */
    protected KeyBinding bindKey(int keyCode, String keyLabel, String description,
            Runnable action) {
        return keys.addOwn(keyCode, keyLabel, description, action);
    }

    /**
     * Declare a parameter. Call from {@link #declareParameters()}.
     *
     * @param parameter the declaration, its name not declared yet (not null)
     * @return parameter
     */
    protected DemoParameter declareParameter(DemoParameter parameter) {
        return parameterControls.getParameters().add(parameter);
    }

    /**
     * Declare a thing the mouse may drag. Call from {@link #declareDraggables()}.
     *
     * @param draggable the declaration, its particles the demo's (not null)
     * @return draggable
     */
    protected Draggable declareDraggable(Draggable draggable) {
        return mouse.getDrags().add(draggable);
    }

    /**
     * Declare state of the demo's own that its steps change and its next step reads (impact
     * counts, a recorder, a batch beside the world), so a step back and a replay give the
     * same bits. Call in {@link #createScene()}.
     *
     * @param record writes and reads the state (not null)
     */
    protected void addStateRecord(StateRecord record) {
        run.addStateRecord(record);
    }

    /**
     * Add a part with hooks of its own ({@link DemoPart}, e.g. a {@link ComparisonLane}),
     * each called right after the demo's hook of the same name. Call from the constructor or
     * a field initialiser.
     *
     * @param <P> the part's type
     * @param part the part, not added yet (not null; its {@link DemoPart#attach} is called)
     * @return part
     */
    protected <P extends DemoPart> P addPart(P part) {
        if (part == null) {
            throw new IllegalArgumentException("demo part must not be null");
        }
        if (parametersDeclared || sceneCreated || creatingScene) {
            throw new IllegalStateException("add parts in the demo's constructor, before its"
                    + " parameters and scene are declared");
        }
        parts.add(part);
        return part;
    }

    /**
     * Launch a particle again from its launch position with a new velocity: release it,
     * forget its landing and clear its trail.
     *
     * @param particle the particle (one of this demo's, not null)
     * @param velocity the launch velocity (in m/s, finite, not null, not modified)
     */
    protected void launch(DemoParticle particle, Vector3f velocity) {
        parameterControls.beforeLaunch();
        particle.copyLaunchPosition(launchPosition);
        particle.setLaunch(launchPosition, velocity);
        particle.restart();
        replay.stateChanged();
        window.launched(particle);
    }

    /**
     * Change the label shown next to a particle and in the HUD, e.g. to a shot's result once
     * it landed; its glyphs are rewritten in place (build the String on such events only).
     *
     * @param particle the particle (one of this demo's, not null)
     * @param label the new label, one line (not null)
     */
    protected void relabel(DemoParticle particle, String label) {
        particle.setLabel(label);
        scene.relabel(particle);
    }

    /**
     * Show each particle's exact ghost (its continuous path under the same forces, faint,
     * until its first contact), the readouts Euler against exact and the live graph key.
     * Call from {@link #createScene()}.
     */
    protected void showExactGhosts() {
        ghosts.enable();
    }

    /** Start with the velocity arrows hidden (fast balls); the V key still shows them. */
    protected void hideArrowsAtStart() {
        if (scene.areArrowsVisible()) {
            scene.toggleArrows();
        }
    }

    /** Rebuild the equations shown in the HUD, after a demo changed a coefficient. */
    protected void refreshEquations() {
        StringBuilder text = new StringBuilder();
        describeEquations(text);
        hudWriter.setEquations(text.toString());
        demoHud.markDirty();
    }

    // ----------------------------------------------------------------------- public API ----

    /** @return the demo's name, shown in the HUD and the demo list (not null) */
    public String getTitle() {
        return title;
    }

    /** @return the node holding the demo's scene, for extra geometry (live, not null) */
    public Node getSceneNode() {
        return sceneNode;
    }

    /** @return the energy ledger's part (issue 32): ledger, HUD lines, export (not null) */
    public EnergyPart getEnergyPart() {
        return energyPart;
    }

    /**
     * Access the demo's parameters (h, the demo's own, its parts'), declared at the first
     * call: {@code --set} changes them before the window opens, the panel after.
     *
     * @return the live parameters (not null)
     */
    public DemoParameters getParameters() {
        if (!parametersDeclared) {
            parametersDeclared = true;
            parameterControls.declareShared(this::applyFixedStep);
            parts.declareParameters(parameterControls.getParameters());
        }
        return parameterControls.getParameters();
    }

    /** @return the world that steps the particles: rules, listeners (live, not null) */
    public World getWorld() {
        ensureScene();
        return world;
    }

    /** @return the run: clock, world, particles, restart, ring, no jME (live, declared) */
    public DemoRun getRun() {
        ensureScene();
        return run;
    }

    /** @return the stepping clock: pause, single step, scale, raw or fixed (live, not null) */
    public SimulationClock getClock() {
        return clock;
    }

    /** @return the particles in the order added (unmodifiable, live, not null) */
    public List<DemoParticle> getParticles() {
        ensureScene();
        return particles;
    }

    /**
     * Put every particle back to its launch state and the clock to zero ({@link DemoRun#restart}
     * says when); keeps the stepping mode, time scale, pause and camera.
     */
    public void restart() {
        run.restart();
    }

    /**
     * @return the views in a window: built, attached, the rectangles shown; a frame's
     *     {@code advance} (live; the scene declared)
     */
    public DemoWindow getWindow() {
        ensureScene();
        return window;
    }

    /** @return the HUD's controls: notices, title, notes, layout, presentation mode (live) */
    public DemoHud getDemoHud() {
        return demoHud;
    }

    /**
     * @return the keys: the bindings, the application's, a key group, the fire key, the help,
     *     the demos by number, an export asked for (live)
     */
    public DemoKeys getKeys() {
        return keys;
    }

    /** @return step back, step forward, the timeline, F6 (live; the scene declared) */
    public ReplayControls getReplayControls() {
        ensureScene();
        return replayControls;
    }

    // ------------------------------------------------------------- framework overrides ----

    @Override
    protected void initialize(Application app) {
        ensureScene();
        window.build(app);
    }

    @Override
    protected void cleanup(Application app) {
        window.cleanup();
    }

    @Override
    protected void onEnable() {
        window.attach(getApplication());
    }

    @Override
    protected void onDisable() {
        window.detach(getApplication());
    }

    @Override
    public void update(float tpf) {
        window.advance(tpf);
        window.update(tpf);
    }

    // ------------------------------------------------- for this package and its tests ----

    /** @return the mouse on the bodies: drags, the picked body, its inspector (live) */
    DemoMouse getMouse() {
        return mouse;
    }

    /** @return the exact ghosts, readouts and live graph (live; inactive unless shown) */
    ExactGhosts getExactGhosts() {
        return ghosts;
    }

    /** @return the parameters' panel and kept shots (live) */
    ParameterControls getParameterControls() {
        return parameterControls;
    }

    /** @param text where to append the demo's own HUD lines, then its parts' (modified) */
    void writeOwnHudLines(StringBuilder text) {
        parts.writeHudLines(text);
    }

    /** @param layout the HUD's new layout, which the scene's area followed: the parts' turn */
    void layOutParts(HudLayout layout) {
        parts.layOut(layout);
    }

    /** Frame the scene's region with the application's camera. */
    void frameCamera() {
        framing.frameCamera();
    }

    // ---------------------------------------------------------------- private helpers ----

    /**
     * Declare the scene the first time anything needs it: the particles and the parts'
     * records, then the parameters, keys and draggables; no jME application needed (the views
     * come later, in {@link #initialize}, if a window comes).
     */
    private void ensureScene() {
        if (sceneCreated || creatingScene) {
            return;
        }
        creatingScene = true;
        createScene();
        parts.addStateRecords(run);
        creatingScene = false;
        sceneCreated = true;
        getParameters().start();
        SharedKeys.declare(this, keys, run, scene, ghosts, hudWriter, parameterControls);
        parts.declareKeysAndDraggables();
        keys.setDraggables(mouse.getDrags().getDraggables());
    }

    /** The h parameter's setter: the clock's step, then the demo's own values from h. */
    private void applyFixedStep(float stepSeconds) {
        clock.setStepSeconds(stepSeconds);
        if (sceneCreated) {
            onStepChanged(stepSeconds);
        }
    }
}

package particlelab.demo;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.asset.AssetManager;
import com.jme3.font.BitmapFont;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import java.util.ArrayList;
import java.util.List;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.HudFont;
import particlelab.view.HudLayout;
import particlelab.view.HudScale;
import particlelab.view.HudView;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.world.StateRecord;
import particlelab.world.StateRing;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * The one base class of every demo. A demo declares its particles and their forces, its keys
 * and its HUD lines; this class keeps the jME lifecycle, the authoring hooks and one-line
 * forwarders to the pieces beside it, which own the rest.
 *
 * <h2>Writing a demo</h2>
 * <ul>
 * <li>{@link #createScene()} (required): call {@link #addParticle} once per particle, with an
 * integrator holding the forces that act on it, and {@link #setView} to frame the region the
 * demo plays in.</li>
 * <li>{@link #showExactGhosts()} (optional, in {@code createScene()}): each particle's exact
 * path beside it, readouts Euler against exact, and the live graph.</li>
 * <li>{@link #buildViews(Application)} (optional): the demo's own views, beyond the
 * particles (walls, curves, sounds), built only in a window, after {@code createScene()}.</li>
 * <li>{@link #declareKeys()}: call {@link #bindKey} for each key the demo adds.</li>
 * <li>{@link #declareParameters()}: call {@link #declareParameter} for each number the user
 * may change (the panel, its keys and {@code --set} are built from them).</li>
 * <li>{@link #writeHudLines(StringBuilder)}: append the demo's own HUD lines (use
 * {@link TextFormat} for numbers: it allocates nothing).</li>
 * <li>{@link #writePresentation(Presentation)}: the slide presentation mode shows (F8,
 * {@code --present}): one or two formula lines with their live numbers and the one readout
 * the slide is about, from the demo's own numbers.</li>
 * <li>{@link #afterStep(float)} and {@link #onRestart()}: react to each step, and to a
 * reset.</li>
 * <li>{@link #addPart(DemoPart)} (in the constructor): a piece with hooks of its own, such as
 * a {@link ComparisonLane}; the demo calls the part's hooks after its own, so it forwards
 * none of them.</li>
 * <li>Collisions: add a rule to {@link #getWorld()} ({@link World#addRule}, e.g. a
 * {@code SurfaceRule} for the ground with an {@code ImpulseResponse}) and a
 * {@code ContactListener} for the prologue and epilogue.</li>
 * </ul>
 *
 * <h2>Once per frame</h2>
 * {@link #update} hands the frame time to the run ({@link DemoRun}: the
 * {@link SimulationClock} decides the steps, the demo's {@link World} takes each: every
 * particle moved by its own integrator, {@link ParticleIntegrator#step}, the lecture's Euler
 * step, then the contacts of its rules). Nothing else moves a particle. The demo and its parts
 * hear each step ({@link StepListener}: the warnings before it; after it the lecture's stop
 * at the ground, the trails and {@link #afterStep}). Then the views read the particles, and
 * the HUD text is rebuilt in a reused {@link StringBuilder} (every frame, or see
 * {@link #setHudRefreshSeconds}), so its numbers are those of the picture; a whole frame
 * allocates nothing (FrameAllocationHeadlessTest). A step that blows up resets the scene and
 * says why; once every particle has landed the clock stops until a launch or a reset.
 *
 * <h2>Beside it</h2>
 * {@code DemoRun} (the physics, without jME), {@code DemoScene} (region, grid, posts, lights,
 * particle views), {@code SceneFraming} (the camera's frame of the launches), {@code DemoHud}
 * (HUD, layout, presentation mode), {@code HudWriter} (the lines every demo shows),
 * {@code DemoKeys} and {@code SharedKeys} (the bindings, the help, the panel's buttons),
 * {@code ParameterControls} (the parameters' panel, the kept shots), {@code ReplayControls}
 * (step back, timeline, F6), {@code DemoMouse} (drags, picking, the inspector),
 * {@code ExactGhosts}, and the demo's {@link DemoPart}s (the energy ledger first).
 */
public abstract class DemoState extends BaseAppState {

    /** The frame time injected by the hitch key (in seconds). */
    public static final float HITCH_SECONDS = DemoRun.HITCH_SECONDS;
    /**
     * How often the HUD text is rebuilt by default (in seconds of frame time): 0, every frame,
     * so the HUD's numbers are those of the picture they are drawn on.
     */
    public static final float HUD_REFRESH_SECONDS = 0f;
    /**
     * How long the body's band is kept for more lines than the body needs now (in seconds of
     * frame time): long enough that numbers changing width from one refresh to the next do
     * not move the scene, short enough that one crowded stretch (a slow frame's warning, a
     * tour stop's long lines) does not shrink or cut the HUD for good.
     */
    public static final float HUD_BAND_KEEP_SECONDS = 2f;
    /** A slower HUD refresh a demo may choose ({@link #setHudRefreshSeconds}): 10 Hz (s). */
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
            for (int i = 0; i < particles.size(); ++i) {
                scene.restartTrail(particles.get(i));
            }
            ghosts.restartAll();
        }

        @Override
        public void restarted() {
            parts.onRestart();
            if (!mouse.getDrags().isDragging()) {
                // During a drag the camera holds still, so the grip stays under the mouse.
                framing.frameLaunches();
            }
            demoHud.markDirty();
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
    private final DemoKeys keys = new DemoKeys();
    private final KeyMappings keyMappings;
    private final ParameterControls parameterControls =
            new ParameterControls(run.getParameterValues());
    private final HudWriter hudWriter = new HudWriter(clock, particles);
    private final StepWarnings warnings = run.getWarnings();
    /** The demo's hooks, then its parts' ({@link #addPart}), at each moment. */
    private final DemoParts parts = new DemoParts(this);
    /** Where the energy goes (issue 32): every demo's first part, its world's ledger. */
    private final EnergyPart energyPart = addPart(new EnergyPart());
    private final Replay replay = run.getReplay();
    private final Node sceneNode;
    /** The HUD: title, body, band, layout, note and presentation mode. */
    private final DemoHud demoHud;
    private final ReplayControls replayControls;
    /** Scratch: a particle's launch position (m). */
    private final Vector3f launchPosition = new Vector3f();
    /** The mouse on the bodies: the declared drags, the picked body, its inspector. */
    private final DemoMouse mouse = new DemoMouse(new DragControl(particles, clock,
            this::restart, framing::frameLaunches, scene::areArrowsVisible));

    private boolean sceneCreated;
    /** Inside {@link #createScene()}: the scene is being declared, not yet complete. */
    private boolean creatingScene;
    private Node guiRoot;
    private Node sceneRoot;
    private String helpText = "";
    /** An export asked for (key or button), for the application to carry out. */
    private boolean exportRequested;
    private boolean parametersDeclared;
    /** The parameters' version the equations were written for. */
    private int equationsVersion;

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
        this.keyMappings = new KeyMappings("particlelab/" + title + "/", this::markHudDirty);
        this.demoHud = new DemoHud(this, title, scene, keys, parameterControls, warnings);
        this.replayControls = new ReplayControls(run, scene, hudWriter, demoHud);
        hudWriter.setWarnings(warnings);
        hudWriter.setContactPause(run.getContactPause());
        hudWriter.setGhosts(ghosts);
        run.addViewRecord(ghosts);
        run.addViewRecord(parameterControls.keptShotsRecord());
        hudWriter.setReplay(replay);
        parameterControls.setReplay(replay);
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
     * Build the demo's own views, those the shared ones do not draw (walls, curves, a point
     * cloud, bodies beyond the particles, sounds), and attach them to {@link #getSceneNode()}.
     * Called once, only in a window: at initialisation, after {@link #createScene()} and
     * before the shared views (grid, posts, particles) are built. The default builds none.
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
     * Declare the numbers the user may change with {@link #declareParameter}: launch speed
     * and angle, mass, g, the force coefficients. Called once, before the scene is created
     * (by {@code --set}) or after it: declare only, do not touch the particles here (the
     * setters may). The default declares none; the fixed step h is declared for every demo.
     */
    protected void declareParameters() {
    }

    /**
     * Declare what the mouse may drag: call {@link #declareDraggable} for each (a launch's
     * position and velocity, a ball, a target). The help's "Mouse" section and the pages'
     * mouse table are written from them. Called once, after {@link #declareKeys()}. The
     * default declares nothing: a click on a sphere still shows it in the inspector.
     */
    protected void declareDraggables() {
    }

    /**
     * Describe the equations the demo runs, with their current numbers, one line each; shown
     * at the top of the HUD. Called at initialisation and by {@link #refreshEquations()}, so
     * it may allocate. The default prints each particle's forces.
     *
     * @param text where to append (not null, modified)
     */
    protected void describeEquations(StringBuilder text) {
        text.append("Euler step: a = g + F/m,  V += h·a,  P += h·V\n");
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            text.append(particle.getLabel()).append(":  ")
                    .append(particle.getIntegrator().describe()).append('\n');
        }
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
     * Write the slide presentation mode shows (F8, {@code --present}) beside the title: one
     * or two key formula lines with their live numbers ({@link Presentation#formula()}) and
     * the one readout the slide is about ({@link Presentation#readout()}), each one line, in
     * large type. Write them from the same numbers the HUD lines show, so the two agree on
     * every frame. Called every frame while presenting: append with {@link TextFormat} and
     * constant strings, so nothing is allocated. The default shows the first equation line
     * and the first particle's speed; every catalogue demo writes its own.
     *
     * @param slide where to write (not null, emptied before the call)
     */
    protected void writePresentation(Presentation slide) {
        String equations = hudWriter.getEquations();
        int end = equations.indexOf('\n');
        slide.formula().append(equations, 0, end < 0 ? equations.length() : end);
        if (!particles.isEmpty()) {
            DemoParticle first = particles.get(0);
            TextFormat.appendFixed(slide.readout().append(first.getLabel()).append(":  |V| = "),
                    first.getParticle().velocity.length(), 2).append(" m/s");
        }
    }

    /**
     * Act at the start of a step, before anything moves: the place to relaunch a shot that
     * {@link #afterStep} found due (a new launch is a restart of the body, done before the
     * step as a script moves a kinematic body). The default does nothing.
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
     * React to one frame, after the clock's steps and before the views move: play the
     * frame's sounds, show its flashes. The world's impact queue is cleared after it. Called
     * once a frame; must allocate nothing. The default does nothing.
     */
    protected void afterFrame() {
    }

    /**
     * React to a new fixed step h (the {@code h} parameter: {@code --set}, the panel, a
     * preset), once the clock steps with it: recompute whatever was derived from h (an aim,
     * a planned round). Called once as the scene starts, with the h {@code --set} chose
     * (the scene was built before the parameters applied), and at every later change. The
     * default does nothing.
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
     * Add the demo's own tables to an export, beside its particles' trajectories: what a demo
     * with no free particle has to show (the rotation boxes per step, the fountain's counts,
     * the aimer's shots). Called on the jME thread, or after the application stopped; may
     * allocate. The default adds none.
     *
     * @param storeResult where to add them (not null, modified)
     */
    public void collectExportTables(List<StepTable> storeResult) {
    }

    /**
     * Count the particles this demo simulates, for the report's physics share and
     * {@code demo --profile}: by default its world's bodies or its declared particles,
     * whichever are more. A demo that steps more of its own (a packed batch) overrides this.
     *
     * @return the count (&ge;0)
     */
    public int countSimulatedParticles() {
        return Math.max(particles.size(), world.countBodies());
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
     * Append a particle's state for a slide ({@link #writePresentation}) as its HUD line shows
     * it on the same frame: its speed while it flies ("11.84 m/s"), where it landed once it
     * has ("x = 9.81 m", the HUD's landing x). Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param particle one of the demo's particles (not null)
     * @return text
     */
    protected static StringBuilder appendSpeedOrLanding(StringBuilder text,
            DemoParticle particle) {
        if (particle.hasLanded()) {
            return TextFormat.appendFixed(text.append("x = "), particle.getLandingX(), 2)
                    .append(" m");
        }
        return TextFormat.appendFixed(text, particle.getParticle().velocity.length(), 2)
                .append(" m/s");
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
     * Frame less than the whole region: up to a height (e.g. the apex of the shot in the
     * air), at most the region's top. Call from {@link #createScene()} or later; the camera
     * is reframed at once.
     *
     * @param topMetres the top edge to frame (in metres, finite, &gt;0)
     */
    protected void setViewTop(float topMetres) {
        framing.setTop(topMetres);
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
     * Add a labelled post as {@link #addMarker}, its name right of its foot: for a post a
     * body rests on (a ledge), whose top the body and its trail cover.
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

    /** @param binding the demo's key that fires or launches: the panel's Fire (not null) */
    protected void setFireKey(KeyBinding binding) {
        keys.setFireKey(binding);
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
     * Add a simulation beside the demo's world, stepped right after it with every step of the
     * same clock: a second world (Bounce's other detection lane) or a packed batch (the
     * fountain). Its listeners observe, they move nothing. Call in {@link #createScene()}.
     *
     * @param simulation what takes each step (not null)
     */
    protected void addSimulation(SimulationClock.Stepper simulation) {
        run.addSimulation(simulation);
    }

    /**
     * Declare state of the demo's own that its steps change and its next step reads (impact
     * counts, kept-shot records, a recorder, a batch beside the world), so a step back and a
     * replay give the same bits: the ring records it after every step with the world's
     * (see {@code Replay}). Call in {@link #createScene()}.
     *
     * @param record writes and reads the state (not null)
     */
    protected void addStateRecord(StateRecord record) {
        run.addStateRecord(record);
    }

    /**
     * Add a part with hooks of its own ({@link DemoPart}, e.g. a {@link ComparisonLane}):
     * from now on the demo calls each of the part's hooks right after its own hook of the
     * same name, so the demo forwards none of them. Call from the demo's constructor or a
     * field initialiser, before the parameters are declared.
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
        scene.restartTrail(particle);
        ghosts.restart(particle.index);
        framing.frameLaunches();
        replay.stateChanged();
        demoHud.markDirty();
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
     * Show each particle's exact ghost (its continuous path from the same launch under the
     * same forces, drawn faint), the HUD's readouts Euler against exact and the live graph
     * key; a ghost stops for good at its particle's first resolved contact. Call from
     * {@link #createScene()}.
     */
    protected void showExactGhosts() {
        ghosts.enable();
    }

    /**
     * Say that this demo's own views draw the raw physics steps, not the interpolated picture
     * of F6 (the fountain's points, the rotating boxes), so the HUD's stepping line says so.
     */
    protected void drawsRawSteps() {
        replay.drawsRawSteps();
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

    /**
     * Return the blend the views draw with this frame: {@code α = leftover / h} between the
     * last two physics states, or 1 (the physics state) with interpolation off, in raw tpf,
     * paused or while replaying ({@link particlelab.world.Body#copyDrawnPosition}).
     *
     * @return α (0 to 1)
     */
    protected float getDrawBlend() {
        return replay.getFrameBlend();
    }

    // ----------------------------------------------------------------------- public API ----

    /** @return the demo's name, shown in the HUD and the demo list (not null) */
    public String getTitle() {
        return title;
    }

    /**
     * Access the view of one of the demo's particles (its sphere, label, trail and arrow).
     *
     * @param particle one of this demo's particles (not null)
     * @return the live view, or null before the views are built (no window yet, or none)
     */
    public ParticleView getView(DemoParticle particle) {
        return scene.viewOf(particle);
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
     * Access the demo's parameters (the shared step h, then the demo's own, then its parts'),
     * declared at the first call: {@code --set} changes them before the window opens, the
     * panel after.
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

    /** @return every key the demo responds to: shared, then the demo's (a new list) */
    public List<KeyBinding> getBindings() {
        ensureScene();
        return keys.copyMapped();
    }

    /** @return the help overlay's text, from the bindings (empty before initialisation) */
    public String getHelpText() {
        return helpText;
    }

    /** @return the HUD (live, null before initialisation) */
    public HudView getHud() {
        return demoHud.getView();
    }

    /** @return the mouse's control of the bodies: pick, drag, release (live, not null) */
    public DragControl getDragControl() {
        ensureScene();
        return mouse.getDrags();
    }

    /** @return the mapping of the scene's plane to the window, as last laid out (live) */
    public PlaneView getPlaneView() {
        return scene.getPlaneView();
    }

    /** @return the wall time of each frame's simulation steps (live record, not null) */
    public FrameTimes getPhysicsTimes() {
        return run.getPhysicsTimes();
    }

    /** @return the count of steps that blew up (and reset the scene) since creation */
    public int countBlowUps() {
        return run.countBlowUps();
    }

    /** @return true once every particle has landed: the clock stops until a launch or reset */
    public boolean isSceneOver() {
        return run.isSceneOver();
    }

    /** @return true if velocity arrows are shown */
    public boolean areArrowsVisible() {
        return scene.areArrowsVisible();
    }

    /** @param number the demo's place in the catalogue, shown before the title (&ge;1) */
    public void setCatalogNumber(int number) {
        demoHud.setCatalogNumber(number);
    }

    /**
     * Show a short note after the title ("typed 1_"), or none; lays the title out again.
     *
     * @param note one non-empty line, or null for none
     */
    public void setTitleNote(String note) {
        demoHud.setTitleNote(note);
    }

    /** @return the note shown after the title, or null if none */
    public String getTitleNote() {
        return demoHud.getTitleNote();
    }

    /**
     * Tell the demo the keys the application handles, for its help, footer and panel; the
     * demo may not bind them. Call before initialisation.
     *
     * @param bindings the application's keys (not null, copied)
     */
    public void setApplicationBindings(List<KeyBinding> bindings) {
        keys.setApplication(bindings);
        demoHud.setApplicationBindings(bindings);
    }

    /** @param titles the demos in catalogue order, for the help (not null, copied) */
    public void setDemoTitles(List<String> titles) {
        keys.setDemoTitles(titles);
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
     * Lay the HUD and the scene's texts out for a window of a size, at the HUD scale that
     * suits it times the user's factor ({@link HudScale#layOut}), and frame the camera for it
     * if it has that size. Call on the jME thread, after initialisation.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     * @param userScale the user's factor on the HUD scale (from {@link HudScale#MIN_FACTOR}
     *     to {@link HudScale#MAX_FACTOR}; 1: the scale that suits the window)
     */
    public void layOut(int width, int height, float userScale) {
        demoHud.layOut(width, height, userScale);
    }

    /**
     * @param width the window's width (in pixels)
     * @param height the window's height (in pixels)
     * @param userScale the user's factor on the HUD scale
     * @return true if {@link #layOut(int, int, float)} with these would change nothing
     */
    public boolean isLaidOutFor(int width, int height, float userScale) {
        return demoHud.isLaidOutFor(width, height, userScale);
    }

    /**
     * Choose how often the HUD text is rebuilt: every frame by default
     * ({@link #HUD_REFRESH_SECONDS}), or less often ({@link #SLOW_HUD_REFRESH_SECONDS}).
     *
     * @param seconds the interval (in seconds of frame time, finite, &ge;0; 0: every frame)
     */
    public void setHudRefreshSeconds(float seconds) {
        demoHud.setRefreshSeconds(seconds);
    }

    /**
     * Switch presentation mode (F8, {@code --present}) on or off: the scene large, the HUD
     * reduced to the title and the slide ({@link #writePresentation}). Before initialisation
     * it is remembered and applied when the window comes.
     *
     * @param on true for presentation mode
     */
    public void setPresenting(boolean on) {
        demoHud.setPresenting(on);
    }

    /** @return true in presentation mode */
    public boolean isPresenting() {
        return demoHud.isPresenting();
    }

    /** @param newNote writes lines after the demo's own (a tour stop's), or null for none */
    public void setNote(HudNote newNote) {
        demoHud.setNote(newNote);
    }

    /** @return the lines shown after the demo's own, or null if none */
    public HudNote getNote() {
        return demoHud.getNote();
    }

    /** @param text a short notice for the HUD, shown a few seconds (one non-empty line) */
    public void showNotice(String text) {
        hudWriter.showNotice(text);
        demoHud.markDirty();
    }

    /** @return the notice on the HUD now, or null if none is up */
    public String getNotice() {
        return hudWriter.getNotice();
    }

    /**
     * Rebuild the HUD's body text into storeResult, without allocating: the lines every demo
     * shows, the demo's own, its parts', then the note.
     *
     * @param storeResult storage for the text (not null, cleared and modified)
     * @return storeResult
     */
    public StringBuilder formatHud(StringBuilder storeResult) {
        ensureScene();
        hudWriter.write(storeResult, isSceneOver());
        writeOwnHudLines(storeResult);
        HudNote note = demoHud.getNote();
        if (note != null) {
            int length = storeResult.length();
            if (length > 0 && storeResult.charAt(length - 1) != '\n') {
                // A demo's last line without its newline: the note starts a line of its own.
                storeResult.append('\n');
            }
            note.append(this, storeResult);
        }
        return storeResult;
    }

    /**
     * Write the slide presentation mode shows now, the demo's then its parts', without
     * allocating (the same numbers as {@link #formatHud}).
     *
     * @return the slide (live: rewritten by the next call or frame)
     */
    public Presentation formatPresentation() {
        ensureScene();
        Presentation slide = demoHud.getSlide();
        slide.clear();
        parts.writePresentation(slide);
        return slide;
    }

    /**
     * Copy the rectangle the scene is drawn into on the screen, as last laid out.
     *
     * @param storeResult storage for the rectangle (in pixels, not null, modified)
     * @return storeResult
     */
    public ScreenRect copySceneRect(ScreenRect storeResult) {
        return scene.copyDrawnRect(getHud().getLayout().getScene(), storeResult);
    }

    /**
     * Copy the screen rectangle of every text shown, HUD and scene (left out while the help
     * hides it), into a list: what a test checks for overlaps.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        getHud().copyTextRects(storeResult);
        if (!getHud().isHelpVisible()) {
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
        return mouse.isHudAt(getHud(), parameterControls.getPanel(), screenX, screenY);
    }

    /**
     * @param storeResult where to write the picked body's inspector text (cleared, modified)
     * @return storeResult, empty when nothing is picked
     */
    public StringBuilder formatInspector(StringBuilder storeResult) {
        return mouse.formatInspector(storeResult);
    }

    /** Ask for an export of the trajectories (key, panel), carried out by the application. */
    public void requestExport() {
        exportRequested = true;
    }

    /** @return true if an export was asked for since the last call, which forgets it */
    public boolean takeExportRequest() {
        boolean requested = exportRequested;
        exportRequested = false;
        return requested;
    }

    /**
     * Put every particle back to its launch state and the clock to zero ({@link DemoRun}
     * says when; from {@link #afterStep} it is done once the frame's steps are over);
     * keeps the stepping mode, time scale, pause and camera. Allocates nothing unless the
     * launches reach beyond the region framed so far (the grid is built again).
     */
    public void restart() {
        run.restart();
    }

    /** Make the next frame last {@link #HITCH_SECONDS}, as if the game had stalled. */
    public void injectHitch() {
        run.injectHitch();
    }

    /**
     * Advance the simulation by one frame and move the views: the allocation-free part of
     * {@link #update}, without the HUD.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    public void advance(float tpf) {
        advancePhysics(tpf);
        // This frame's blend, for the demo's own views in afterFrame (getDrawBlend).
        replay.updateFrameBlend(isSceneOver());
        parts.afterFrame();
        world.getImpacts().clear();
        scene.setDrawBlend(replay.updateFrameBlend(isSceneOver()));
        scene.updateViews();
        ghosts.updateViews(getHud().getLayout(), getHud().isHelpVisible());
        warnings.age(tpf);
        hudWriter.age(tpf);
    }

    /**
     * Advance the physics by one frame and touch no view ({@link DemoRun#advancePhysics}):
     * what a test drives without a jME application.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    public void advancePhysics(float tpf) {
        run.advancePhysics(tpf);
    }

    // ------------------------------------------ step back, replay, timeline (issue 21) ----

    /** @return false if the ring holds no earlier step (see {@link ReplayControls}) */
    public boolean stepBack() {
        ensureScene();
        return replayControls.stepBack();
    }

    /** Step forward: the ring's next state while behind the live end, else a step of h. */
    public void stepForward() {
        ensureScene();
        replayControls.stepForward();
    }

    /** @param fraction the timeline's place to show: 0 the oldest step held, 1 the newest */
    public void scrubTo(double fraction) {
        ensureScene();
        replayControls.scrubTo(fraction);
    }

    /** @return true while a recorded step, not the live end, is shown */
    public boolean isReplaying() {
        return replay.isBehind();
    }

    /** @return true if the views blend the last two physics states (F6 switches) */
    public boolean isInterpolating() {
        return replay.isInterpolating();
    }

    /** @param newInterpolating true to draw between the last two states, false raw (F6) */
    public void setInterpolating(boolean newInterpolating) {
        replayControls.setInterpolating(newInterpolating);
    }

    /** @return the ring of recorded states: steps back, timeline, span export (live) */
    public StateRing getStateRing() {
        return replay.getRing();
    }

    /** @return the number of the ring entry shown: the newest while live */
    public long getShownStep() {
        return replay.getShownIndex();
    }

    // ------------------------------------------------------------- framework overrides ----

    @Override
    protected void initialize(Application app) {
        ensureScene();
        parts.buildViews(app);
        AssetManager assets = app.getAssetManager();
        BitmapFont font = HudFont.load(assets);

        framing.frameLaunches();
        scene.build(assets, font, sceneNode);
        world.addStepListener(scene.getTrailWriter());
        ghosts.build(assets, font, sceneNode, world, scene);
        HudView hud = demoHud.build(assets, font, app.getCamera().getWidth(),
                app.getCamera().getHeight());
        mouse.build(assets, font, hud.getNode(), scene.getSphereRadius());
        hud.setFooter(keys.buildFooter());
        refreshEquations();
        helpText = keys.buildHelp(title);
        hud.setHelp(helpText);
        buildPanel(app, font);
        demoHud.layOutFirst();
        sceneRoot = (Node) app.getViewPort().getScenes().get(0);
        guiRoot = (Node) app.getGuiViewPort().getScenes().get(0);
        scene.updateViews();
        if (demoHud.isPresenting()) {
            demoHud.applyPresentation();
        }
    }

    @Override
    protected void cleanup(Application app) {
        world.removeStepListener(scene.getTrailWriter());
        sceneNode.detachAllChildren();
    }

    @Override
    protected void onEnable() {
        sceneRoot.attachChild(sceneNode);
        guiRoot.attachChild(getHud().getNode());
        guiRoot.attachChild(ghosts.getGraphNode());
        guiRoot.attachChild(parameterControls.getPanel().getNode());
        keyMappings.map(getApplication().getInputManager(), getBindings());
        frameCamera();
        demoHud.markDirty();
    }

    @Override
    protected void onDisable() {
        if (getHud() == null) {
            // Cleaned up without having been initialised (another state failed first, and
            // jME tidies up every attached state): onEnable never ran, nothing to undo.
            return;
        }
        keyMappings.unmap(getApplication().getInputManager());
        sceneNode.removeFromParent();
        getHud().getNode().removeFromParent();
        ghosts.getGraphNode().removeFromParent();
        parameterControls.getPanel().getNode().removeFromParent();
    }

    @Override
    public void update(float tpf) {
        advance(tpf);
        if (equationsVersion != getParameters().getVersion()) {
            // A value reached the scene: the equations' numbers follow it.
            equationsVersion = getParameters().getVersion();
            refreshEquations();
        }
        demoHud.update(tpf);
        HudView hud = demoHud.getView();
        parameterControls.update(hud.getLayout());
        mouse.update(hud);
    }

    // ------------------------------------------------- for this package and its tests ----

    /** @return the inspector's text rectangle as last placed (live, empty while closed) */
    ScreenRect getInspectorRect() {
        return mouse.getInspectorRect();
    }

    /** @return the exact ghosts, readouts and live graph (live; inactive unless shown) */
    ExactGhosts getExactGhosts() {
        return ghosts;
    }

    /** @return the parameters' panel and kept shots (live) */
    ParameterControls getParameterControls() {
        return parameterControls;
    }

    /** @return the demo's replay: the ring, the step shown, the blend (live) */
    Replay getReplay() {
        return replay;
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

    /** @param text where to append the demo's own HUD lines, then its parts' (modified) */
    void writeOwnHudLines(StringBuilder text) {
        parts.writeHudLines(text);
    }

    /** @param layout the HUD's new layout, which the scene's area followed: the parts' turn */
    void layOutParts(HudLayout layout) {
        parts.layOut(layout);
    }

    /** After the panel came or went: the HUD and the scene get the window's width back. */
    void relayOutPanel() {
        demoHud.panelMoved();
    }

    /** Show or hide the live graph, and lay out again for its slot. */
    void toggleGraph() {
        ghosts.toggleGraph(getHud().getLayout());
        demoHud.layOutAgain();
    }

    /** The R key and the panel's Reset: restart, and frame the camera afresh. */
    void restartAndReframe() {
        restart();
        frameCamera();
    }

    /** Frame the scene's region with the application's camera. */
    void frameCamera() {
        framing.frameCamera();
    }

    // ---------------------------------------------------------------- private helpers ----

    /** The parameter panel with its buttons (pause, step, reset, fire, export, next demo). */
    private void buildPanel(Application app, BitmapFont font) {
        List<String> labels = new ArrayList<>();
        List<Runnable> actions = new ArrayList<>();
        keys.listPanelButtons(labels, actions, () -> clock.setPaused(!clock.isPaused()),
                run::singleStep, this::restartAndReframe, this::requestExport);
        parameterControls.build(app, font, getHud().getLayout(), particles, scene,
                scene.getSphereRadius(), sceneNode, labels, actions);
        equationsVersion = getParameters().getVersion();
        // The side panel's slot narrows the HUD's body: lay it out again.
        getHud().layOut(app.getCamera().getWidth(), app.getCamera().getHeight(),
                getHud().getLayout().getScale());
    }

    private void markHudDirty() {
        demoHud.markDirty();
    }

    /**
     * Declare the scene the first time anything needs it (the world, the particles, the HUD's
     * text or the window): the particles and the parts' records, then the parameters, the
     * keys and the draggables. So a demo's physics steps with no jME application at all; the
     * views are built later, by {@link #initialize}, if a window comes.
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

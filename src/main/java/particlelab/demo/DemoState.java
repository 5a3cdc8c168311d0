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
import java.util.Collections;
import java.util.List;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.HudFont;
import particlelab.view.HudScale;
import particlelab.view.HudView;
import particlelab.view.ParticleView;
import particlelab.view.PlaneView;
import particlelab.view.ScreenRect;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.ContactListener;
import particlelab.world.StateRecord;
import particlelab.world.StateRing;
import particlelab.world.StateSlab;
import particlelab.world.StepListener;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * The one base class of every demo. A demo declares its particles and their forces, its keys
 * and its HUD lines; this class owns the rest: the lifecycle, the stepping clock, the shared
 * keys, the views (spheres, trails, velocity arrows, distance grid, camera) and the HUD.
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
 * {@link #update} hands the frame time to the {@link SimulationClock}, which decides the steps
 * (pause, single step, time scale, raw tpf or fixed h); the demo's {@link World} takes each
 * step: it moves every particle with its own integrator ({@link ParticleIntegrator#step}, the
 * lecture's Euler step), then detects, resolves and propagates the contacts of its rules.
 * Nothing else moves a particle. This class hears each step as a {@link StepListener}: the
 * stability warnings look at the particles before it, and after it the lecture's stop at the
 * ground, the trails and the demo's {@link #afterStep} hook run. Then the views read the
 * particles. None of this allocates; the HUD text is rebuilt in a reused
 * {@link StringBuilder} every frame, after the frame's steps and views, so its numbers are
 * those of the picture (or less often, see {@link #setHudRefreshSeconds}), and shown in
 * {@code HudText}s, whose glyph meshes are rewritten in place, so a whole frame allocates
 * nothing (FrameAllocationHeadlessTest).
 *
 * <p>If a step blows up (the integrator refuses a non-finite result), the demo resets its
 * scene and shows why, instead of crashing the window. Once every particle has landed the
 * scene is over: the clock stops, so {@code t} stays at the last landing's step, until a
 * launch or a reset.
 *
 * <h2>Inside</h2>
 * This class coordinates; the details live in small classes of this package:
 * {@code DemoScene} (the region, grid, posts, lights and particle views), {@code DemoKeys}
 * (the bindings, their checks and the help text), {@code HudWriter} (the HUD lines every demo
 * shows), {@code StepWarnings} (the stability, hitch and blow-up warning) and
 * {@code ParameterControls} (the declared parameters, their panel and the kept shots).
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
    /** What the run tells the demo at fixed moments of a step and a reset. */
    private final DemoRun.Hooks runHooks = new DemoRun.Hooks() {
        @Override
        public void prepare() {
            ensureScene();
        }

        @Override
        public void beforeStep(float stepSeconds) {
            DemoState.this.beforeStep(stepSeconds);
            for (int i = 0; i < parts.size(); ++i) {
                parts.get(i).beforeStep(stepSeconds);
            }
        }

        @Override
        public void afterStep(float stepSeconds) {
            ghosts.afterStep(stepSeconds);
            DemoState.this.afterStep(stepSeconds);
            for (int i = 0; i < parts.size(); ++i) {
                parts.get(i).afterStep(stepSeconds);
            }
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
            onRestart();
            for (int i = 0; i < parts.size(); ++i) {
                parts.get(i).onRestart();
            }
            if (!drags.isDragging()) {
                // During a drag the camera holds still, so the grip stays under the mouse.
                frameLaunches();
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
    private final ExactGhosts ghosts = new ExactGhosts(particles);
    private final DemoKeys keys = new DemoKeys();
    private final KeyMappings keyMappings;
    private final ParameterControls parameterControls =
            new ParameterControls(run.getParameterValues());
    private final HudWriter hudWriter = new HudWriter(clock, particles);
    private final StepWarnings warnings = run.getWarnings();
    /** Pause at the next contact the world resolves (its key, its HUD line). */
    private final ContactPause contactPause = run.getContactPause();
    /** The demo's parts ({@link #addPart}), whose hooks follow the demo's own. */
    private final List<DemoPart> parts = new ArrayList<>();
    /** Where the energy goes (issue 32): every demo's first part, its world's ledger. */
    private final EnergyPart energyPart = addPart(new EnergyPart());
    private final Replay replay = run.getReplay();
    private final Node sceneNode;
    /** The HUD: title, body, band, layout, note and presentation mode. */
    private final DemoHud demoHud;
    /** Scratch: a particle's launch position (m). */
    private final Vector3f launchPosition = new Vector3f();
    /** What the launches reach, for the camera to frame. */
    private final LaunchReach reach = new LaunchReach();
    /** The mouse on the bodies: the declared drags and the picked body; its inspector. */
    private final DragControl drags = new DragControl(particles, clock, this::restart,
            this::frameLaunches, scene::areArrowsVisible);
    private final Inspector inspector = new Inspector();

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
    private KeyBinding fireKey;
    private List<KeyBinding> applicationBindings = Collections.emptyList();

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
        hudWriter.setWarnings(warnings);
        hudWriter.setContactPause(contactPause);
        hudWriter.setGhosts(ghosts);
        run.addViewRecord(ghosts);
        run.addViewRecord(new StateRecord() {
            @Override
            public int countStateInts() {
                return 1;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putInt(parameterControls.countKeptShots());
            }

            @Override
            public void readState(StateSlab slab) {
                parameterControls.showKeptShotsUpTo(slab.getInt());
            }
        });
        replay.setTrails(new Replay.TrailWalk() {
            @Override
            public void undone(DemoParticle particle) {
                scene.undoTrailStep(particle);
            }

            @Override
            public void redone(DemoParticle particle) {
                scene.redoTrailStep(particle);
            }
        });
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

    // ------------------------------------------------------- tools for createScene etc. ----

    /**
     * Add a particle to the scene.
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
     * has ("x = 9.81 m", the HUD's landing x, which is the range Euler gives for a launch
     * from x = 0). Allocates nothing.
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
        scene.setFrameTop(topMetres);
        if (getHud() != null) {
            scene.layOut(getHud().getLayout());
            if (isEnabled()) {
                frameCamera();
            }
        }
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
     * Add a labelled post standing on the ground, its name right of its foot: for a post a
     * body rests on (a ledge), whose top the body and its trail cover. Call from
     * {@link #createScene()}.
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
     * Access the view of one of the demo's particles (its sphere, label, trail and arrow),
     * for a demo that draws a particle its own way. Views exist only in a window.
     *
     * @param particle one of this demo's particles (not null)
     * @return the live view, or null before the views are built (no window yet, or none)
     */
    public ParticleView getView(DemoParticle particle) {
        return scene.viewOf(particle);
    }

    /**
     * Add a simulation beside the demo's world, stepped right after it with every step of the
     * same clock: a second world (Bounce's other detection lane) or a packed batch (the
     * fountain). Not inside the world's step: its listeners observe, they move nothing. Call
     * in {@link #createScene()}.
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
     * Access the energy ledger's part (issue 32): the ledger, its HUD lines and its export.
     *
     * @return the part (not null)
     */
    public EnergyPart getEnergyPart() {
        return energyPart;
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
        if (parts.contains(part)) {
            throw new IllegalArgumentException("demo part " + part + " was added already");
        }
        parts.add(part);
        part.attach(this);
        return part;
    }

    /**
     * Return the blend the views draw with this frame: {@code α = leftover / h} between the
     * last two physics states, or 1 (the physics state) with interpolation off, in raw tpf,
     * paused or while replaying. For a demo that draws bodies of its own
     * ({@link particlelab.world.Body#copyDrawnPosition}).
     *
     * @return α (0 to 1)
     */
    protected float getDrawBlend() {
        return replay.getFrameBlend();
    }

    // ------------------------------------------------- the mouse: drags and inspector ----

    /**
     * Declare what the mouse may drag: call {@link #declareDraggable} for each (a launch's
     * position and velocity, a ball, a target). The help's "Mouse" section and the pages'
     * mouse table are written from them. Called once, after {@link #declareKeys()}. The
     * default declares nothing: a click on a sphere still shows it in the inspector.
     */
    protected void declareDraggables() {
    }

    /**
     * Declare a thing the mouse may drag. Call from {@link #declareDraggables()}.
     *
     * @param draggable the declaration, its particles the demo's (not null)
     * @return draggable
     */
    protected Draggable declareDraggable(Draggable draggable) {
        return drags.add(draggable);
    }

    /**
     * Access the mouse's control of the bodies (pick, drag, release), for the application's
     * mouse input and for tests.
     *
     * @return the live control (not null)
     */
    public DragControl getDragControl() {
        ensureScene();
        return drags;
    }

    /**
     * Test whether the HUD takes the mouse at a screen point, so that a press there must not
     * pick a body behind it: the help overlay (it covers the scene) or the parameter panel.
     *
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @return true if the HUD is there
     */
    public boolean isHudAt(float screenX, float screenY) {
        if (getHud() == null || getHud().isHelpVisible()) {
            return true;
        }
        ScreenRect panel = parameterControls.getPanel().copyRect(new ScreenRect());
        return !panel.isEmpty() && panel.contains(screenX, screenY);
    }

    /**
     * Access the inspector's text rectangle, as last placed, for tests of this package.
     *
     * @return the live rectangle (empty while closed; do not modify)
     */
    ScreenRect getInspectorRect() {
        return inspector.getRect();
    }

    /**
     * Write the inspector's text for the picked body, as its box shows it.
     *
     * @param storeResult where to write (not null, cleared and modified)
     * @return storeResult, empty when nothing is picked
     */
    public StringBuilder formatInspector(StringBuilder storeResult) {
        DemoParticle picked = drags.getPicked();
        inspector.show(picked);
        if (picked == null) {
            storeResult.setLength(0);
            return storeResult;
        }
        return inspector.format(storeResult, picked);
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
     * Name the key that fires or launches, so the panel gets a Fire button for it.
     *
     * @param binding one of the demo's bindings (not null)
     */
    protected void setFireKey(KeyBinding binding) {
        fireKey = binding;
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
        frameLaunches();
        replay.stateChanged();
        demoHud.markDirty();
    }

    /**
     * Change the label shown next to a particle and in the HUD, e.g. to a shot's result once
     * it landed. The label's glyphs are rewritten in place; the label String is the caller's
     * (build it on such events, not every frame).
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
     * same forces, drawn faint), the HUD's readouts Euler against exact (apex, range, flight
     * time, the live distance) and the live graph key. Meant for particles that fly free (and
     * may stop at the ground): a ghost stops for good at its particle's first resolved
     * contact. Call from {@link #createScene()}.
     */
    protected void showExactGhosts() {
        ghosts.enable();
    }

    /**
     * Say that this demo's own views draw the raw physics steps, not the interpolated picture
     * of F6 (the fountain's points, the rotating boxes), so the HUD's stepping line says so.
     * Call from the constructor or {@link #createScene()}.
     */
    protected void drawsRawSteps() {
        replay.drawsRawSteps();
    }

    /**
     * Start with the velocity arrows hidden (for fast balls, whose arrows would leave the
     * scene); the V key still shows them. Call from {@link #createScene()}.
     */
    protected void hideArrowsAtStart() {
        if (scene.areArrowsVisible()) {
            scene.toggleArrows();
        }
    }

    /**
     * Rebuild the equations shown in the HUD, after a demo changed a coefficient.
     */
    protected void refreshEquations() {
        StringBuilder text = new StringBuilder();
        describeEquations(text);
        hudWriter.setEquations(text.toString());
        demoHud.markDirty();
    }

    /**
     * Access the node holding the demo's scene, to attach extra geometry (targets, markers).
     *
     * @return the live node (not null)
     */
    public Node getSceneNode() {
        return sceneNode;
    }

    // ----------------------------------------------------------------------- public API ----

    /**
     * Return the demo's name.
     *
     * @return the title (not null)
     */
    public String getTitle() {
        return title;
    }

    /**
     * Set the number shown before the title, the demo's place in the catalogue.
     *
     * @param number the number (&ge;1)
     */
    public void setCatalogNumber(int number) {
        demoHud.setCatalogNumber(number);
    }

    /**
     * Show a short note after the title, or none: what the application is in the middle of,
     * e.g. a demo number being typed ("typed 1_"). Not meant for every frame (the title is
     * laid out again).
     *
     * @param note one short line, or null for none
     */
    public void setTitleNote(String note) {
        if (note != null && (note.isEmpty() || note.indexOf('\n') >= 0)) {
            throw new IllegalArgumentException("a title note must be null or one non-empty"
                    + " line, but was \"" + note + "\"");
        }
        demoHud.setTitleNote(note);
    }

    /**
     * Return the note shown after the title.
     *
     * @return the note, or null if none
     */
    public String getTitleNote() {
        return demoHud.getTitleNote();
    }

    /**
     * Tell the demo about keys the application handles (choosing demos), so that its help
     * overlay and footer list them too and the demo may not bind them. Call before the demo
     * is initialised.
     *
     * @param bindings the application's keys (not null, copied)
     */
    public void setApplicationBindings(List<KeyBinding> bindings) {
        keys.setApplication(bindings);
        applicationBindings = new ArrayList<>(bindings);
        demoHud.setApplicationBindings(bindings);
    }

    /**
     * Tell the demo the application's demos, so that its help overlay lists them by the
     * numbers the digit keys reach. Call before the demo is initialised.
     *
     * @param titles the demos' titles in catalogue order, demo 1 first (not null, copied)
     */
    public void setDemoTitles(List<String> titles) {
        keys.setDemoTitles(titles);
    }

    /**
     * Access the demo's parameters (the shared step h, then the demo's own), declared at the
     * first call: {@code --set} changes them before the window opens, the panel after.
     *
     * @return the live parameters (not null)
     */
    public DemoParameters getParameters() {
        if (!parametersDeclared) {
            parametersDeclared = true;
            parameterControls.declareShared(this::applyFixedStep);
            declareParameters();
            for (int i = 0; i < parts.size(); ++i) {
                parts.get(i).declareParameters(parameterControls.getParameters());
            }
        }
        return parameterControls.getParameters();
    }

    /**
     * Access the world that steps the demo's particles: add collision rules and contact or
     * step listeners to it in {@link #createScene()}.
     *
     * @return the live world (not null)
     */
    public World getWorld() {
        ensureScene();
        return world;
    }

    /**
     * Access the demo's run: the clock, the world, the particles, restart and the replay
     * ring, without jME (what a physics test steps).
     *
     * @return the live run (not null; its scene declared)
     */
    public DemoRun getRun() {
        ensureScene();
        return run;
    }

    /**
     * Access the stepping clock: pause, single step, time scale, raw tpf or fixed step.
     *
     * @return the live clock (not null)
     */
    public SimulationClock getClock() {
        return clock;
    }

    /**
     * Access the particles in the order they were added.
     *
     * @return an unmodifiable live list (not null)
     */
    public List<DemoParticle> getParticles() {
        ensureScene();
        return particles;
    }

    /**
     * Count the particles this demo simulates, for the report's physics share and
     * {@code demo --profile}: by default its world's bodies or its declared particles,
     * whichever are more. A demo that steps more of
     * its own (a packed batch) overrides this.
     *
     * @return the count (&ge;0)
     */
    public int countSimulatedParticles() {
        return Math.max(particles.size(), world.countBodies());
    }

    /**
     * Return every key the demo responds to: the shared controls, then the demo's own.
     *
     * @return a new list (not null)
     */
    public List<KeyBinding> getBindings() {
        ensureScene();
        return keys.copyMapped();
    }

    /**
     * Return the help overlay's text, generated from the bindings.
     *
     * @return the text (not null, empty before initialisation)
     */
    public String getHelpText() {
        return helpText;
    }

    /**
     * Access the HUD.
     *
     * @return the live HUD (null before initialisation)
     */
    public HudView getHud() {
        return demoHud.getView();
    }

    /**
     * Test whether velocity arrows are shown.
     *
     * @return true if shown
     */
    public boolean areArrowsVisible() {
        return scene.areArrowsVisible();
    }

    /**
     * Lay the HUD and the scene's texts out for a window of a size, at the HUD scale that
     * suits it, and frame the camera for it if it has that size. Call on the jME thread,
     * after initialisation.
     *
     * @param width the window's width (in pixels, &gt;0)
     * @param height the window's height (in pixels, &gt;0)
     */
    public void layOut(int width, int height) {
        layOut(width, height, 1f);
    }

    /**
     * Lay the HUD and the scene's texts out for a window of a size, at the HUD scale that
     * suits it times the user's factor ({@link HudScale#layOut}: a larger factor always gives
     * larger text; lines are hidden where the window cannot hold them), and frame the camera
     * for it if it has that size. Call on the jME thread, after initialisation.
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
     * Test whether the last layout was for this window size and HUD factor.
     *
     * @param width the window's width (in pixels)
     * @param height the window's height (in pixels)
     * @param userScale the user's factor on the HUD scale
     * @return true if {@link #layOut(int, int, float)} with these would change nothing
     */
    public boolean isLaidOutFor(int width, int height, float userScale) {
        return demoHud.isLaidOutFor(width, height, userScale);
    }

    /**
     * Ask for the current trajectories to be exported (the export key, or a panel's button):
     * the application writes them, with a screenshot, at the end of the frame and names the
     * folder on the HUD. Without an application that carries it out (a test), nothing happens.
     */
    public void requestExport() {
        exportRequested = true;
    }

    /**
     * Test, and forget, whether an export was asked for since the last call: for the
     * application that carries it out.
     *
     * @return true if asked for
     */
    public boolean takeExportRequest() {
        boolean requested = exportRequested;
        exportRequested = false;
        return requested;
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
     * Copy the screen rectangle of every post of the scene (targets, a gun) into a list: what
     * a test checks particle labels against.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyPostRects(List<ScreenRect> storeResult) {
        return scene.copyPostRects(storeResult);
    }

    /**
     * Copy the screen rectangle of every post's name, for tests of the layout.
     *
     * @param storeResult where to add them, in the posts' order (not null, modified)
     * @return storeResult
     */
    List<ScreenRect> copyPostLabelRects(List<ScreenRect> storeResult) {
        return scene.copyPostLabelRects(storeResult);
    }

    /**
     * Copy the rectangle the scene (its grid, ground and bodies) is drawn into on the screen,
     * as last laid out: the region the camera frames, widened to the scene area's shape.
     *
     * @param storeResult storage for the rectangle (in pixels, not null, modified)
     * @return storeResult
     */
    public ScreenRect copySceneRect(ScreenRect storeResult) {
        return scene.copyDrawnRect(getHud().getLayout().getScene(), storeResult);
    }

    /**
     * Copy the screen rectangle of every text shown, HUD and scene, into a list: what a test
     * checks for overlaps. The scene's texts are left out while the help hides them.
     *
     * @param storeResult where to add them (not null, modified)
     * @return storeResult
     */
    public List<ScreenRect> copyTextRects(List<ScreenRect> storeResult) {
        getHud().copyTextRects(storeResult);
        if (!getHud().isHelpVisible()) {
            scene.copyTextRects(storeResult);
            ghosts.copyTextRects(storeResult);
            if (!inspector.getRect().isEmpty()) {
                storeResult.add(new ScreenRect().set(inspector.getRect()));
            }
        }
        return storeResult;
    }

    /**
     * Access the mapping of the scene's plane to the window, as last laid out.
     *
     * @return the live mapping (not null, do not modify)
     */
    public PlaneView getPlaneView() {
        return scene.getPlaneView();
    }

    /**
     * Access the exact ghosts, readouts and live graph, for tests.
     *
     * @return the live ghosts (not null; inactive unless the demo showed them)
     */
    ExactGhosts getExactGhosts() {
        return ghosts;
    }

    /**
     * Count the steps that blew up (and reset the scene) since the demo was created.
     *
     * @return the count (&ge;0)
     */
    public int countBlowUps() {
        return run.countBlowUps();
    }

    /**
     * Put every particle back to its launch state and the clock to zero; keeps the stepping
     * mode, time scale and pause, and the camera. Allocates nothing, so a demo may call it
     * from {@link #afterStep}: there it is recorded and done once the frame's steps are over
     * (the rest of them do nothing), so the clock is never reset in the middle of its own
     * step and {@code t} reads 0 with every particle at its launch point. The R key also
     * reframes the camera. The launches are flown ahead to frame what they reach; only when
     * that goes beyond the region framed so far (new parameters) is the grid built again,
     * which allocates, and the camera reframed.
     */
    public void restart() {
        run.restart();
    }

    /**
     * Test whether the scene is over: every particle has landed, so nothing moves and the
     * clock is stopped until a launch or a reset.
     *
     * @return true if over
     */
    public boolean isSceneOver() {
        return run.isSceneOver();
    }

    /**
     * Show a short notice on the HUD for a few seconds, e.g. why a key did nothing.
     *
     * @param text the notice, one line (not null, not empty)
     */
    public void showNotice(String text) {
        if (text == null || text.isEmpty() || text.indexOf('\n') >= 0) {
            throw new IllegalArgumentException("a notice must be one non-empty line, but was "
                    + (text == null ? "null" : "\"" + text + "\""));
        }
        hudWriter.showNotice(text);
        demoHud.markDirty();
    }

    /**
     * Return the notice on the HUD now.
     *
     * @return the notice, or null if none is up
     */
    public String getNotice() {
        return hudWriter.getNotice();
    }

    /**
     * Choose how often the HUD text is rebuilt and handed to the screen: every frame by
     * default ({@link #HUD_REFRESH_SECONDS}, 0), so the numbers match the picture, or less
     * often, e.g. {@link #SLOW_HUD_REFRESH_SECONDS}. Either way a frame allocates nothing.
     *
     * @param seconds the interval (in seconds of frame time, finite, &ge;0; 0: every frame)
     */
    public void setHudRefreshSeconds(float seconds) {
        if (!(seconds >= 0f) || Float.isInfinite(seconds)) {
            throw new IllegalArgumentException("HUD refresh interval (s) must be finite and"
                    + " >= 0, but was " + seconds);
        }
        demoHud.setRefreshSeconds(seconds);
    }

    /**
     * Make the next frame last {@link #HITCH_SECONDS}, as if the game had stalled: in raw-tpf
     * mode that is one long Euler step; in fixed-step mode the clock clamps it.
     */
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
        afterFrame();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).afterFrame();
        }
        world.getImpacts().clear();
        scene.setDrawBlend(replay.updateFrameBlend(isSceneOver()));
        scene.updateViews();
        ghosts.updateViews(getHud().getLayout(), getHud().isHelpVisible());
        warnings.age(tpf);
        hudWriter.age(tpf);
    }

    /**
     * Advance the simulation by one frame and nothing else: the hitch, the clock's steps of
     * the world, a blow-up's recovery and a restart asked for inside a step. Touches no view,
     * so a test drives a demo's physics with it and no jME application; {@link #advance} is
     * this plus the views.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    public void advancePhysics(float tpf) {
        run.advancePhysics(tpf);
    }

    /**
     * Access the wall time each frame's simulation steps took ({@link #advance}: the clock,
     * the world's steps and every hook inside them), measured with {@link System#nanoTime}.
     *
     * @return the live record (not null)
     */
    public FrameTimes getPhysicsTimes() {
        return run.getPhysicsTimes();
    }

    /**
     * Rebuild the HUD's body text into storeResult, without allocating.
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
     * Switch presentation mode on or off: the scene large (at least 75 % of the window), the
     * HUD reduced to the title, the slide's formula lines and its readout in large type
     * ({@link #writePresentation}), and a footer saying which key gives the full HUD back.
     * The application's F8 and {@code --present} call it, and keep it on across demos and
     * tour stops. Before initialisation it is remembered and applied when the window comes.
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

    /**
     * Write the slide presentation mode shows now, without allocating: what the HUD shows
     * each frame while presenting (for tests: the same numbers as {@link #formatHud}).
     *
     * @return the slide (live: rewritten by the next call or frame)
     */
    public Presentation formatPresentation() {
        ensureScene();
        Presentation slide = demoHud.getSlide();
        slide.clear();
        writePresentation(slide);
        return slide;
    }

    /**
     * Show lines after the demo's own on its HUD, e.g. a tour stop's "what to watch for".
     *
     * @param newNote writes the lines from the demo's numbers, or null for none
     */
    public void setNote(HudNote newNote) {
        demoHud.setNote(newNote);
    }

    /** @return the lines shown after the demo's own, or null if none */
    public HudNote getNote() {
        return demoHud.getNote();
    }

    // ------------------------------------------ step back, replay, timeline (issue 21) ----

    /**
     * Step back one recorded step: the ring's previous state is put back and the clock
     * paused. Allocates nothing.
     *
     * @return false if the ring holds no earlier step
     */
    public boolean stepBack() {
        ensureScene();
        boolean done = replay.stepBack();
        if (!done) {
            showNotice("no earlier step recorded (the ring starts at the last reset)");
        }
        demoHud.markDirty();
        return done;
    }

    /**
     * Step forward one step: the ring's next state while behind the live end, else a new
     * step of h like N. Allocates nothing.
     */
    public void stepForward() {
        ensureScene();
        if (!replay.stepForward()) {
            singleStep();
        }
        demoHud.markDirty();
    }

    /**
     * Show a recorded step by its place on the timeline, pausing first (the panel's slider).
     *
     * @param fraction 0 for the oldest step the ring holds, 1 for the newest (clamped)
     */
    public void scrubTo(double fraction) {
        ensureScene();
        replay.scrub(fraction);
        demoHud.markDirty();
    }

    /**
     * Test whether a recorded step, not the live end, is shown.
     *
     * @return true while behind the live end
     */
    public boolean isReplaying() {
        return replay.isBehind();
    }

    /**
     * Test whether the views blend the last two physics states (F6 switches).
     *
     * @return true if interpolating
     */
    public boolean isInterpolating() {
        return replay.isInterpolating();
    }

    /**
     * Draw the bodies between their last two physics states, or at the raw steps (what F6
     * switches).
     *
     * @param newInterpolating true to interpolate
     */
    public void setInterpolating(boolean newInterpolating) {
        if (newInterpolating != replay.isInterpolating()) {
            replay.toggleInterpolation();
            demoHud.markDirty();
        }
    }

    /**
     * Access the ring of recorded states (steps back, the timeline, the span export).
     *
     * @return the live ring (not null)
     */
    public StateRing getStateRing() {
        return replay.getRing();
    }

    /**
     * Return the ring entry shown: the newest while live.
     *
     * @return the entry's number
     */
    public long getShownStep() {
        return replay.getShownIndex();
    }

    /** @return the demo's replay: the ring, the step shown, the blend (for this package) */
    Replay getReplay() {
        return replay;
    }

    /**
     * Append the lines the demo writes itself, below the lines every demo shows: its own
     * ({@link #writeHudLines}), then its parts', in the order added.
     *
     * @param text where to append (not null, modified)
     */
    void writeOwnHudLines(StringBuilder text) {
        writeHudLines(text);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).writeHudLines(text);
        }
    }

    // ------------------------------------------------------------- framework overrides ----

    @Override
    protected void initialize(Application app) {
        ensureScene();
        buildViews(app);
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).buildViews(app);
        }
        AssetManager assets = app.getAssetManager();
        BitmapFont font = HudFont.load(assets);

        frameLaunches();
        scene.build(assets, font, sceneNode);
        world.addStepListener(scene.getTrailWriter());
        ghosts.build(assets, font, sceneNode, world, scene);
        HudView hud = demoHud.build(assets, font, app.getCamera().getWidth(),
                app.getCamera().getHeight());
        inspector.build(assets, font);
        hud.getNode().attachChild(inspector.getNode());
        drags.setSphereRadius(scene.getSphereRadius());
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
        inspector.show(drags.getPicked());
        inspector.update(hud.getLayout(), hud.isHelpVisible());
    }

    // ---------------------------------------------------------------- private helpers ----

    /** @return the parameters' panel and kept shots (for tests of this package) */
    ParameterControls getParameterControls() {
        return parameterControls;
    }

    /** The parameter panel and its buttons: pause, step, reset, fire, export, next demo. */
    private void buildPanel(Application app, BitmapFont font) {
        List<String> labels = new ArrayList<>(List.of("Pause", "Step", "Reset"));
        List<Runnable> actions = new ArrayList<>(List.of(
                () -> clock.setPaused(!clock.isPaused()), this::singleStep,
                this::restartAndReframe));
        if (fireKey != null) {
            labels.add("Fire");
            actions.add(() -> fireKey.press(0));
        }
        labels.add("Export");
        actions.add(this::requestExport);
        for (int i = 0; i < applicationBindings.size(); ++i) {
            KeyBinding binding = applicationBindings.get(i);
            if (binding.getKeyCode(0) == KeyInput.KEY_TAB) {
                labels.add("Next demo");
                actions.add(() -> binding.press(0));
            }
        }
        parameterControls.build(app, font, getHud().getLayout(), particles, scene,
                scene.getSphereRadius(), sceneNode, labels, actions);
        equationsVersion = getParameters().getVersion();
        // The side panel's slot narrows the HUD's body: lay it out again.
        getHud().layOut(app.getCamera().getWidth(), app.getCamera().getHeight(),
                getHud().getLayout().getScale());
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

    private void markHudDirty() {
        demoHud.markDirty();
    }

    /** The R key and the panel's Reset: restart, and frame the camera afresh. */
    void restartAndReframe() {
        restart();
        frameCamera();
    }

    private void singleStep() {
        run.singleStep();
    }

    /** Frame the scene's region with the application's camera. */
    void frameCamera() {
        scene.frame(getApplication().getCamera());
    }

    /**
     * Frame the region the launches reach, beyond the declared one if they go further: each
     * particle that stops at the ground and is in flight is flown ahead with its own
     * integrator and h ({@code LaunchReach}), so the frame follows the launch speed, angle,
     * g and coefficients the particle has now. At every launch and reset.
     */
    private void frameLaunches() {
        reach.clear();
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.stopsAtGround() && !particle.isHeld() && !particle.isParked()) {
                reach.include(particle, clock.getStepSeconds());
            }
        }
        if (scene.frameReach(reach) && getHud() != null) {
            scene.layOut(getHud().getLayout());
            scene.updateViews();
            if (isEnabled()) {
                frameCamera();
            }
        }
    }

    /**
     * Declare the scene the first time anything needs it (the world, the particles, the HUD's
     * text or the window): the particles, then the parameters and the keys. So a new demo's
     * {@code getWorld().step(h)} steps its physics with no jME application at all; the views
     * are built later, by {@link #initialize}, if a window comes.
     */
    private void ensureScene() {
        if (sceneCreated || creatingScene) {
            return;
        }
        creatingScene = true;
        createScene();
        creatingScene = false;
        sceneCreated = true;
        getParameters().start();
        SharedKeys.declare(this, keys, run, scene, ghosts, hudWriter, parameterControls);
        declareKeys();
        for (int i = 0; i < parts.size(); ++i) {
            parts.get(i).declareKeys();
        }
        declareDraggables();
        keys.setDraggables(drags.getDraggables());
    }

    /** The h parameter's setter: the clock's step, then the demo's own values from h. */
    private void applyFixedStep(float stepSeconds) {
        clock.setStepSeconds(stepSeconds);
        if (sceneCreated) {
            onStepChanged(stepSeconds);
        }
    }
}

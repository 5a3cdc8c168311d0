package particlelab.lecture;

import com.jme3.app.Application;
import com.jme3.input.KeyInput;
import com.jme3.math.ColorRGBA;
import com.jme3.renderer.RenderManager;
import java.util.List;
import particlelab.demo.DemoState;
import particlelab.demo.EnergyPart;
import particlelab.demo.FrameTimes;
import particlelab.demo.Presentation;
import particlelab.demo.StepTable;
import particlelab.physics.EnergyLedger;
import particlelab.view.PointCloudView;
import particlelab.view.TextFormat;
import particlelab.world.Fountain;
import particlelab.world.FountainEnergy;
import particlelab.world.GroundBounce;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * Demo "fountain": many particles. A fountain of water and a display of fireworks, 10^5
 * particles by default ({@code demo fountain --particles N}, up to 10^6), all moved by the
 * shared Euler step in its batch form ({@code ParticleBatch.stepPacked}: packed float
 * arrays, no object per particle) and drawn as one mesh of points whose buffers are rewritten
 * in place every frame. Builds upon drag (every particle has gravity and linear drag), bounce
 * (the ground's restitution e, applied in one packed loop) and targets (an epilogue that
 * spawns fragments: here a shell bursts into stars and a star into sparks, after Cyclone's
 * fireworks demo).
 *
 * <p>The demo declares no particle of its own ({@link #addParticle} would make an object, a
 * sphere and a label for each): it steps its {@link Fountain} from {@link #afterStep}, so the
 * clock drives it like any other demo (pause, single step, time scale, fixed h or raw tpf),
 * and copies the pool into the mesh in {@link #afterFrame}.
 *
 * <p>What to watch for: the HUD's physics milliseconds per frame against the render's, and
 * their share of the 16.7 ms a frame has at 60 frames per second; how many particles are in
 * flight, and how many came to rest and went back to the pool. Up/Down change e: with e near
 * 1 the drops bounce long and the pool runs short of free particles.
 */
public final class FountainDemo extends DemoState {

    /** The frame budget at 60 frames per second (in seconds). */
    public static final float FRAME_BUDGET_SECONDS = 1f / 60f;
    /** What Up/Down add to or take from e. */
    public static final float RESTITUTION_STEP = 0.1f;
    /** How large a point is drawn in a window up to 720 pixels high (in pixels). */
    public static final float POINT_SIZE_PIXELS = 2f;
    /** The window height up to which points are {@link #POINT_SIZE_PIXELS} (in pixels). */
    private static final float POINT_SIZE_HEIGHT = 720f;
    /**
     * How bright water is drawn with the default pool (0 to 1): the colours of overlapping
     * points add up. A pool k times larger is drawn 1/√k as bright, so the spray neither
     * saturates at 10^6 nor fades at 10^3.
     */
    private static final float WATER_BRIGHTNESS = 0.15f;
    /** The export's table of counts per step (file name without .csv). */
    public static final String COUNTS_TABLE = "fountain-counts";
    /** Its header: the time, the particles in flight (all, then by kind), those recycled. */
    public static final String COUNTS_HEADER = "t_s,in_flight,water,shells,stars,sparks,"
            + "recycled_at_rest,recycled_left_region,recycled_burnt";
    private static final float MILLIS_PER_SECOND = 1000f;
    private static final float GRAMS_PER_KG = 1000f;

    private int particleCount = Fountain.DEFAULT_PARTICLES;
    private float waterBrightness = WATER_BRIGHTNESS;
    private Fountain fountain;
    private PointCloudView points;
    /** The window height the points' size was set for (pixels; 0: none yet). */
    private int pointSizeHeight;
    /** Writes the pool into the points' mesh each frame (null without an application). */
    private FountainPoints meshUpdate;
    private final FrameTimes renderTimes = new FrameTimes();
    /** The mesh update's wall time per frame ({@link FountainPoints#update}). */
    private final FrameTimes meshTimes = new FrameTimes();
    private final FrameTimes frameTimes = new FrameTimes();
    private long renderStartNanos = -1L;
    private long lastUpdateNanos = -1L;
    /** The fountain's counts after each step, for the export. */
    private final StepTable counts = new StepTable(COUNTS_TABLE, COUNTS_HEADER,
            StepTable.DEFAULT_CAPACITY);
    /** The time simulated since the last reset (in seconds). */
    private double simulatedSeconds;
    /** The particles' energy ledger, made when first wanted (null before). */
    private FountainEnergy energy;

    /** Create the demo with {@link Fountain#DEFAULT_PARTICLES}. */
    public FountainDemo() {
        super("Fountain");
        // the pool is no body of the world: the ledger is the fountain's, kept while wanted
        getEnergyPart().useOwnLedger(new EnergyPart.OwnLedger() {
            @Override
            public void keep(boolean keeping) {
                if (keeping && energy == null) {
                    energy = new FountainEnergy(fountain);
                }
                fountain.setEnergy(keeping ? energy : null);
            }

            @Override
            public EnergyLedger getLedger() {
                return fountain == null || fountain.getEnergy() == null ? null
                        : fountain.getEnergy().getLedger();
            }

            @Override
            public int getColumns() {
                return FountainEnergy.COLUMNS;
            }
        });
    }

    /**
     * Choose the pool size. Call before the demo is initialised.
     *
     * @param particles how many particles (from 1 to {@link Fountain#MAX_PARTICLES})
     */
    public void setParticleCount(int particles) {
        if (fountain != null) {
            throw new IllegalStateException("set the particle count before the demo starts");
        }
        if (particles < 1 || particles > Fountain.MAX_PARTICLES) {
            throw new IllegalArgumentException("fountain particle count must be from 1 to "
                    + Fountain.MAX_PARTICLES + ", but was " + particles);
        }
        particleCount = particles;
    }

    /**
     * Return the pool size ({@code --particles}), for a command line that reproduces a run.
     *
     * @return how many particles (from 1 to {@link Fountain#MAX_PARTICLES})
     */
    public int getParticleCount() {
        return particleCount;
    }

    /**
     * Access the fountain.
     *
     * @return the live fountain (null before initialisation)
     */
    public Fountain getFountain() {
        return fountain;
    }

    /**
     * Access the render times: per frame, from this demo's {@link #render} to its
     * {@link #postRender}, which is jME's render pass on the CPU (culling, the buffers'
     * upload, the draw calls), without the swap of the window's buffers.
     *
     * @return the live record (not null)
     */
    public FrameTimes getRenderTimes() {
        return renderTimes;
    }

    /**
     * Access the mesh update's times: per frame, the copy of the pool into the points' mesh
     * ({@link FountainPoints#update}), wall time; none without an application.
     *
     * @return the live record (not null)
     */
    public FrameTimes getMeshTimes() {
        return meshTimes;
    }

    /**
     * Write the HUD's line of the frame's shares: the physics' mean milliseconds per frame
     * and their share of a {@link #FRAME_BUDGET_SECONDS} frame, then the mesh update's and
     * the render pass's milliseconds and the frame's, e.g. {@code physics 2.60 ms/frame = 16% of
     * a 16.7 ms frame;  mesh 1.10 + render 0.40 ms;  frame 16.7 ms (60 fps)}.
     *
     * @param text where to append the line and its line end (not null, modified)
     * @param physicsMillis the physics' mean per frame (in ms, &ge;0)
     * @param meshMillis the mesh update's mean per frame (in ms, &ge;0)
     * @param renderMillis the render pass's mean per frame (in ms, &ge;0)
     * @param frameMillis the time between two frames (in ms, &ge;0; 0: not known yet)
     */
    public static void appendShareLine(StringBuilder text, double physicsMillis,
            double meshMillis, double renderMillis, double frameMillis) {
        double budget = FRAME_BUDGET_SECONDS * MILLIS_PER_SECOND;
        text.append("physics ");
        TextFormat.appendFixed(text, physicsMillis, 2).append(" ms/frame = ");
        TextFormat.appendFixed(text, 100.0 * physicsMillis / budget, 0).append("% of a ");
        TextFormat.appendFixed(text, budget, 1).append(" ms frame;  mesh ");
        TextFormat.appendFixed(text, meshMillis, 2).append(" + render ");
        TextFormat.appendFixed(text, renderMillis, 2).append(" ms;  frame ");
        TextFormat.appendFixed(text, frameMillis, 1).append(" ms (");
        TextFormat.appendFixed(text, frameMillis > 0.0 ? MILLIS_PER_SECOND / frameMillis : 0.0,
                0).append(" fps)\n");
    }

    @Override
    protected void createScene() {
        getWindow().drawsRawSteps(); // its own views draw the physics steps, not the blend
        fountain = new Fountain(particleCount);
        // The packed particles are a simulation beside the world, stepped by the same clock.
        getRun().addSimulation(this::stepFountain, fountain.getCapacity());
        addStateRecord(fountain);
        addStateRecord(countsState());
        waterBrightness = (float) Math.min(1.0, WATER_BRIGHTNESS
                * Math.sqrt((double) Fountain.DEFAULT_PARTICLES / particleCount));
        setView(-Fountain.REGION_HALF_WIDTH + 2f, Fountain.REGION_HALF_WIDTH - 2f, 28f, 2f, 5,
                0.3f);
        addMarker("nozzle", 0f, 0.4f, new ColorRGBA(0.4f, 0.6f, 1f, 1f));
        addMarker("shells", -Fountain.LAUNCHER_X, 0.6f, ColorRGBA.Orange);
        addMarker("shells", Fountain.LAUNCHER_X, 0.6f, ColorRGBA.Orange);
    }

    /** The pool drawn as one mesh of points. */
    @Override
    protected void buildViews(Application app) {
        points = new PointCloudView(app.getAssetManager(), "fountain", particleCount,
                POINT_SIZE_PIXELS, Fountain.REGION_TOP);
        getSceneNode().attachChild(points.getGeometry());
        meshUpdate = new FountainPoints(points.getPoints(), waterBrightness);
    }

    @Override
    protected void declareKeys() {
        StringBuilder up = new StringBuilder("ground restitution e + ");
        TextFormat.appendFixed(up, RESTITUTION_STEP, 1).append(" (up to 1)");
        bindKey(KeyInput.KEY_UP, "Up", up.toString(), () -> changeRestitution(1f));
        StringBuilder down = new StringBuilder("ground restitution e - ");
        TextFormat.appendFixed(down, RESTITUTION_STEP, 1).append(" (down to 0)");
        bindKey(KeyInput.KEY_DOWN, "Down", down.toString(), () -> changeRestitution(-1f));
        bindKey(KeyInput.KEY_F, "F", "fireworks on / off (shells in flight still burst)",
                () -> fountain.setFireworks(!fountain.isFireworks()));
    }

    @Override
    protected void describeEquations(StringBuilder text) {
        // linear drag's factor 1 - h*b/m stays above -1 for h < 2m/b (docs/numerics.md)
        // which of the batch's two forms runs (README, "The Vector API, opt-in")
        text.append(fountain.getIntegrator().batch().isVectorBatch()
                ? "batch Euler step (stepPacked, Vector API): "
                : "batch Euler step (stepPacked, scalar): ");
        text.append("V = (1 − h·b/m)·V + h·g,  P += h·V;  stable for h < 2m/b = ");
        TextFormat.appendFixed(text, 2f * Fountain.MASS_KG / Fountain.DRAG_B, 1)
                .append(" s\n");
        text.append(fountain.getIntegrator().describe()).append(", m = ");
        TextFormat.appendFixed(text, Fountain.MASS_KG * GRAMS_PER_KG, 0).append(" g;  ground");
        GroundBounce ground = fountain.getGround();
        text.append(" y = r = ");
        TextFormat.appendFixed(text, ground.getRadius(), 2).append(" m, e = ");
        TextFormat.appendFixed(text, ground.getRestitution(), 1)
                .append(", Cyclone's resting fix\n");
    }

    @Override
    protected void writeHudLines(StringBuilder text) {
        text.append("particles: ").append(fountain.countLive()).append(" in flight (stepped) of ")
                .append(fountain.getCapacity()).append(": water ")
                .append(fountain.countLive(Fountain.WATER)).append(", shells ")
                .append(fountain.countLive(Fountain.SHELL)).append(", stars ")
                .append(fountain.countLive(Fountain.STAR)).append(", sparks ")
                .append(fountain.countLive(Fountain.SPARK))
                .append(fountain.isFireworks() ? "" : " (fireworks off)").append('\n');
        text.append("recycled: ").append(fountain.countRecycledResting())
                .append(" at rest, ").append(fountain.countRecycledLeaving())
                .append(" left the region, ").append(fountain.countRecycledBurnt())
                .append(" fireworks burnt out\n");
        appendShareLine(text, getRun().getPhysicsTimes().recentMeanMillis(),
                meshTimes.recentMeanMillis(), renderTimes.recentMeanMillis(),
                frameTimes.recentMeanMillis());
    }

    /**
     * Add the fountain's counts per step to an export ({@value #COUNTS_TABLE}.csv): it has
     * no particle of its own to trace, and its 10^5 pooled ones come and go.
     *
     * @param storeResult where to add the table (not null, modified)
     */
    @Override
    public void collectExportTables(List<StepTable> storeResult) {
        storeResult.add(counts);
    }

    /** The fountain's step beside the world, then its counts for the export. */
    private void stepFountain(float stepSeconds) {
        fountain.step(stepSeconds);
        getEnergyPart().ownStepped();
        simulatedSeconds += stepSeconds;
        counts.startRow().put(simulatedSeconds).put(fountain.countLive())
                .put(fountain.countLive(Fountain.WATER)).put(fountain.countLive(Fountain.SHELL))
                .put(fountain.countLive(Fountain.STAR)).put(fountain.countLive(Fountain.SPARK))
                .put(fountain.countRecycledResting()).put(fountain.countRecycledLeaving())
                .put(fountain.countRecycledBurnt());
    }

    /**
     * How large the points are drawn in a window of a height: {@link #POINT_SIZE_PIXELS} up
     * to 720 pixels, growing with the height beyond, so that on a lecture hall's 4K
     * projector a point covers as much of the picture as at 720p.
     *
     * @param heightPixels the window's height (in pixels)
     * @return the point size (in pixels, &ge;{@link #POINT_SIZE_PIXELS})
     */
    public static float pointSizeFor(int heightPixels) {
        return POINT_SIZE_PIXELS * Math.max(1f, heightPixels / POINT_SIZE_HEIGHT);
    }

    /** The points' size on the screen now (pixels; 0 without a window), for tests. */
    float drawnPointSize() {
        return points == null ? 0f : points.getPointSize();
    }

    @Override
    protected void afterFrame() {
        if (meshUpdate == null) {
            return;
        }
        int height = getApplication().getCamera().getHeight();
        if (height != pointSizeHeight) {
            // points as large in a 4K window as at 720p: one change a resize, not a frame
            points.setPointSize(pointSizeFor(height));
            pointSizeHeight = height;
        }
        long start = System.nanoTime();
        meshUpdate.update(fountain);
        meshTimes.record(System.nanoTime() - start);
    }

    @Override
    protected void onRestart() {
        if (fountain != null) {
            fountain.reset();
        }
        counts.clear();
        simulatedSeconds = 0.0;
    }

    @Override
    public void update(float tpf) {
        long now = System.nanoTime();
        if (lastUpdateNanos >= 0L) {
            frameTimes.record(now - lastUpdateNanos);
        }
        lastUpdateNanos = now;
        super.update(tpf);
    }

    @Override
    public void render(RenderManager renderManager) {
        renderStartNanos = System.nanoTime();
    }

    @Override
    public void postRender() {
        if (renderStartNanos >= 0L) {
            renderTimes.record(System.nanoTime() - renderStartNanos);
            renderStartNanos = -1L;
        }
    }

    @Override
    protected void onDisable() {
        super.onDisable();
        lastUpdateNanos = -1L;
        renderStartNanos = -1L;
    }

    private void changeRestitution(float sign) {
        GroundBounce ground = fountain.getGround();
        // whole steps of e, so that ten presses reach 0 or 1 exactly
        float steps = Math.round(ground.getRestitution() / RESTITUTION_STEP) + sign;
        ground.setRestitution(Math.max(0f, Math.min(1f, steps * RESTITUTION_STEP)));
        StringBuilder notice = new StringBuilder("ground restitution e = ");
        TextFormat.appendFixed(notice, ground.getRestitution(), 1);
        getDemoHud().showNotice(notice.toString());
        refreshEquations();
    }

    /** The demo's own state, for the ring: its clock and its counts table's length. */
    private StateRecord countsState() {
        return new StateRecord() {
            @Override
            public int countStateInts() {
                return 2 + 3;
            }

            @Override
            public void writeState(StateSlab slab) {
                slab.putDouble(simulatedSeconds);
                counts.writeState(slab);
            }

            @Override
            public void readState(StateSlab slab) {
                simulatedSeconds = slab.getDouble();
                counts.readState(slab);
            }
        };
    }

    /** The slide: the batch's Euler step and its limit; how many particles fly. */
    @Override
    protected void writePresentation(Presentation slide) {
        TextFormat.appendFixed(slide.formula()
                .append("V = (1 − h·b/m)·V + h·g,  P += h·V;   h < 2m/b = "),
                2f * Fountain.MASS_KG / Fountain.DRAG_B, 1).append(" s");
        slide.readout().append("particles: ").append(fountain.countLive())
                .append(" in flight of ").append(fountain.getCapacity());
    }
}

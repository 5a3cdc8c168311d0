package particlelab.demo;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.BooleanSupplier;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.world.Body;
import particlelab.world.GroundStop;
import particlelab.world.StateRecord;
import particlelab.world.StateRing;
import particlelab.world.StateSlab;
import particlelab.world.StepListener;
import particlelab.world.World;

/**
 * A demo's run, without jME: the clock, the world, the particles and the simulations beside
 * it, the parameters' values, restart, recovery from a blow-up, the physics time of each
 * frame, and the replay ring with the demo's whole state. What a {@link DemoState} shows and
 * the keys it takes live in the state; what moves lives here, so a test steps a demo's
 * physics in plain JUnit ({@link #advancePhysics}) with no application, no window and no
 * scene graph. This class and what it uses of its own import nothing of {@code com.jme3} but
 * {@code com.jme3.math} (DemoRunSourceTest).
 *
 * <p>Once a frame {@link #advancePhysics} hands the frame time to the {@link SimulationClock},
 * which decides the steps; the {@link World} takes each one: it moves every particle with its
 * own integrator, then detects, resolves and propagates the contacts of its rules. The run
 * hears each step as a {@link StepListener}: the stability warnings look at the particles
 * before it, and after it the export rows and the demo's hooks ({@link Hooks}) run. The
 * lecture's stop at the ground is the world's {@link GroundStop}. After every step the ring
 * records the whole state.
 */
public final class DemoRun {

    /** What the time scale keys multiply or divide by. */
    static final float TIME_SCALE_FACTOR = 2f;
    /** The frame time injected by the hitch key (in seconds). */
    static final float HITCH_SECONDS = 0.5f;

    /** What the run tells its demo, at fixed moments of a step and a reset. */
    interface Hooks {
        /** Declare the scene if not yet declared: before any step or reset. */
        void prepare();

        /**
         * At the start of a step, before anything moves: the demo's and its parts' hooks.
         *
         * @param stepSeconds h of the step (in seconds, &gt;0)
         */
        void beforeStep(float stepSeconds);

        /**
         * After the world's step and the export rows: the ghosts, the demo's and its parts'
         * hooks.
         *
         * @param stepSeconds h of the step (in seconds, &gt;0)
         */
        void afterStep(float stepSeconds);

        /** Before a reset puts the particles back: keep the shot, apply waiting values. */
        void beforeRestart();

        /** Once the world and the particles were put back: the trails and the ghosts. */
        void particlesRestarted();

        /** At the end of a reset: the demo's and its parts' hooks, the camera, the HUD. */
        void restarted();

        /** Something the HUD shows changed (a warning came or went). */
        void changed();
    }

    private final Hooks hooks;
    private final SimulationClock clock = new SimulationClock();
    private final World world = new World();
    /**
     * The lecture's stop at the ground, for the particles told to
     * {@link DemoParticle#stopAtGround}: it joins the world with the first of them.
     */
    private final GroundStop groundStop = new GroundStop(world);
    private final List<DemoParticle> particles = new ArrayList<>();
    private final List<DemoParticle> particlesView = Collections.unmodifiableList(particles);
    /** The values of the demo's parameters (their panel is the view's). */
    private final DemoParameters parameters = new DemoParameters();
    private final StepWarnings warnings;
    /** Pause at the next contact the world resolves (its key, its HUD line). */
    private final ContactPause contactPause = new ContactPause(clock, particles);
    private final SimulationClock.Stepper stepper = this::stepWorld;
    /** Simulations beside the world (a second world, a packed batch), stepped after it. */
    private final List<SimulationClock.Stepper> simulations = new ArrayList<>();
    /** Per frame: the wall time of the clock's steps (for the HUD and --profile). */
    private final FrameTimes physicsTimes = new FrameTimes();
    /** What a demo declared as its own state, and the simulations beside that have one. */
    private final List<StateRecord> stateRecords = new ArrayList<>();
    /** What the views show of the state (the ghosts, the kept shots), recorded last. */
    private final List<StateRecord> viewRecords = new ArrayList<>();
    /**
     * The demo's whole state, one ring entry: t and each particle's P and V first (what the
     * export of the recorded span reads), then the world, the ground stop's landings, each
     * particle's own counters, the declared records in the order declared, and what the views
     * show of the state (the exact ghosts, how many shots were kept), so a step back shows
     * them as they were.
     */
    private final StateRecord wholeState = new StateRecord() {
        @Override
        public int countStateInts() {
            int ints = 2 + particles.size() * (6 + DemoParticle.STATE_INTS)
                    + world.countStateInts() + groundStop.countStateInts();
            for (int i = 0; i < stateRecords.size(); ++i) {
                ints += stateRecords.get(i).countStateInts();
            }
            for (int i = 0; i < viewRecords.size(); ++i) {
                ints += viewRecords.get(i).countStateInts();
            }
            return ints;
        }

        @Override
        public void writeState(StateSlab slab) {
            slab.putDouble(world.getTimeSeconds());
            for (int i = 0; i < particles.size(); ++i) {
                slab.putVector(particles.get(i).getParticle().position);
                slab.putVector(particles.get(i).getParticle().velocity);
            }
            world.writeState(slab);
            groundStop.writeState(slab);
            for (int i = 0; i < particles.size(); ++i) {
                particles.get(i).writeState(slab);
            }
            for (int i = 0; i < stateRecords.size(); ++i) {
                stateRecords.get(i).writeState(slab);
            }
            for (int i = 0; i < viewRecords.size(); ++i) {
                viewRecords.get(i).writeState(slab);
            }
        }

        @Override
        public void readState(StateSlab slab) {
            slab.getDouble();
            for (int i = 0; i < 6 * particles.size(); ++i) {
                slab.getFloat();
            }
            world.readState(slab);
            groundStop.readState(slab);
            for (int i = 0; i < particles.size(); ++i) {
                particles.get(i).readState(slab);
            }
            for (int i = 0; i < stateRecords.size(); ++i) {
                stateRecords.get(i).readState(slab);
            }
            for (int i = 0; i < viewRecords.size(); ++i) {
                viewRecords.get(i).readState(slab);
            }
        }
    };
    private final Replay replay = new Replay(new StateRing(), wholeState, clock, world,
            particles);
    private final StepListener stepListener = new StepListener() {
        @Override
        public void beforeStep(World stepping, float stepSeconds) {
            contactPause.beforeStep();
            hooks.beforeStep(stepSeconds);
            observeParticles(stepSeconds);
        }

        @Override
        public void afterStep(World stepping, float stepSeconds) {
            finishStep(stepSeconds);
        }
    };
    /** Motions beside the particles that the scene's end waits for (a part's own flights). */
    private final List<BooleanSupplier> motionsBeside = new ArrayList<>();
    private float pendingHitchSeconds;
    private int blowUps;
    /** The most particles a simulation beside the world steps ({@link #addSimulation}). */
    private int simulationParticles;
    /** A restart asked for inside a step: done once the frame's steps are over. */
    private boolean restartRequested;

    /**
     * Create the run of a demo.
     *
     * @param hooks what the run tells the demo (not null)
     */
    DemoRun(Hooks hooks) {
        if (hooks == null) {
            throw new IllegalArgumentException("run hooks must not be null");
        }
        this.hooks = hooks;
        this.warnings = new StepWarnings(clock, hooks::changed);
        world.addStepListener(stepListener);
        world.addContactListener(contactPause);
    }

    /**
     * Add a particle to the world, as a body with its integrator.
     *
     * @param label its label (not null)
     * @param color its colour (not null, not modified)
     * @param position its launch position (in metres, finite, not null, not modified)
     * @param velocity its launch velocity (in m/s, finite, not null, not modified)
     * @param massKg its mass (in kilograms, finite, &gt;0)
     * @param integrator the integrator holding the forces that act on it (not null)
     * @return the new demo particle (not null)
     */
    DemoParticle addParticle(String label, ColorRGBA color, Vector3f position,
            Vector3f velocity, float massKg, ParticleIntegrator integrator) {
        Body body = world.addBody(integrator, position, velocity, massKg, 0f);
        DemoParticle particle = new DemoParticle(particles.size(), label, color, body,
                groundStop);
        particles.add(particle);
        return particle;
    }

    /**
     * Add a simulation beside the world, stepped right after it with every step of the same
     * clock: a second world or a packed batch (the fountain); one that is a
     * {@link StateRecord} goes into the ring with the world. Its listeners observe, they move
     * nothing. Call in the demo's {@code createScene()}.
     *
     * @param simulation what takes each step (not null)
     */
    public void addSimulation(SimulationClock.Stepper simulation) {
        addSimulation(simulation, 0);
    }

    /**
     * Add a simulation beside the world as {@link #addSimulation(SimulationClock.Stepper)}
     * does, that steps particles of its own (no bodies of the world): the count
     * {@link #countSimulatedParticles} reports.
     *
     * @param simulation what takes each step (not null)
     * @param particleCount how many particles it steps (&ge;0)
     */
    public void addSimulation(SimulationClock.Stepper simulation, int particleCount) {
        if (simulation == null) {
            throw new IllegalArgumentException("simulation must be a stepper, but was null");
        }
        if (particleCount < 0) {
            throw new IllegalArgumentException("a simulation's particle count must be >= 0,"
                    + " but was " + particleCount);
        }
        simulations.add(simulation);
        simulationParticles = Math.max(simulationParticles, particleCount);
        if (simulation instanceof StateRecord) {
            stateRecords.add((StateRecord) simulation);
        }
    }

    /**
     * Declare state of the demo's own that its steps change and its next step reads.
     *
     * @param record writes and reads the state (not null)
     */
    void addStateRecord(StateRecord record) {
        if (record == null) {
            throw new IllegalArgumentException("state record must not be null");
        }
        stateRecords.add(record);
    }

    /**
     * Declare state the views show of the run (the ghosts, the kept shots), recorded after
     * the demo's own.
     *
     * @param record writes and reads the state (not null)
     */
    void addViewRecord(StateRecord record) {
        viewRecords.add(record);
    }

    /**
     * Make the scene's end wait for a motion beside the particles, such as a part's flights
     * drawn without bodies of their own (the rate lanes): the scene is not over while it
     * says it still moves.
     *
     * @param stillMoving true while the motion goes on (not null; called every frame, must
     *     allocate nothing)
     */
    public void waitForMotion(BooleanSupplier stillMoving) {
        if (stillMoving == null) {
            throw new IllegalArgumentException("motion to wait for must not be null");
        }
        motionsBeside.add(stillMoving);
    }

    /**
     * Count the particles this run simulates ({@code demo --profile}, the report, the tour):
     * the world's bodies, the demo's particles or a simulation's beside the world, whichever
     * are more.
     *
     * @return the count (&ge;0)
     */
    public int countSimulatedParticles() {
        return Math.max(Math.max(particles.size(), world.countBodies()), simulationParticles);
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
     * Access the world that steps the particles.
     *
     * @return the live world (not null)
     */
    public World getWorld() {
        return world;
    }

    /**
     * Access the lecture's stop at the ground: the landings of the particles that stop there.
     *
     * @return the live stop (not null; on the world once a particle stops at the ground)
     */
    public GroundStop getGroundStop() {
        return groundStop;
    }

    /**
     * Access the particles in the order they were added.
     *
     * @return an unmodifiable live list (not null)
     */
    public List<DemoParticle> getParticles() {
        return particlesView;
    }

    /**
     * Access the values of the parameters, as declared so far (the demo declares them).
     *
     * @return the live parameters (not null)
     */
    DemoParameters getParameterValues() {
        return parameters;
    }

    /** @return the stability, hitch and blow-up warnings (live, not null) */
    StepWarnings getWarnings() {
        return warnings;
    }

    /** @return the pause at the next contact (live, not null) */
    ContactPause getContactPause() {
        return contactPause;
    }

    /** @return the replay: the ring, the step shown, the blend (live, not null) */
    Replay getReplay() {
        return replay;
    }

    /**
     * Count the ints at the end of a ring entry that hold what the views show of the state
     * (the exact ghosts, the kept shots), not the simulation: a run without views has fewer,
     * so a comparison of two runs' simulations leaves them out ({@link StateHash}).
     *
     * @return the count (&ge;0)
     */
    public int countViewStateInts() {
        int ints = 0;
        for (int i = 0; i < viewRecords.size(); ++i) {
            ints += viewRecords.get(i).countStateInts();
        }
        return ints;
    }

    /**
     * Access the ring of recorded states (steps back, the timeline, the span export).
     *
     * @return the live ring (not null)
     */
    public StateRing getStateRing() {
        return replay.getRing();
    }

    /** @return true while a recorded step, not the live end, is shown */
    public boolean isReplaying() {
        return replay.isBehind();
    }

    /** @return the number of the ring entry shown: the newest while live */
    public long getShownStep() {
        return replay.getShownIndex();
    }

    /**
     * Access the wall time each frame's simulation steps took, measured with
     * {@link System#nanoTime}.
     *
     * @return the live record (not null)
     */
    public FrameTimes getPhysicsTimes() {
        return physicsTimes;
    }

    /**
     * Count the steps that blew up (and reset the scene) since the run was created.
     *
     * @return the count (&ge;0)
     */
    public int countBlowUps() {
        return blowUps;
    }

    /**
     * Test whether the scene is over: every particle has landed and no motion beside them
     * ({@link #waitForMotion}) still moves, so nothing moves and the clock is stopped until a
     * launch or a reset.
     *
     * @return true if over
     */
    public boolean isSceneOver() {
        if (particles.isEmpty()) {
            return false;
        }
        for (int i = 0; i < particles.size(); ++i) {
            if (!particles.get(i).hasLanded()) {
                return false;
            }
        }
        for (int i = 0; i < motionsBeside.size(); ++i) {
            if (motionsBeside.get(i).getAsBoolean()) {
                return false;
            }
        }
        return true;
    }

    /**
     * Put every particle back to its launch state and the clock to zero (see
     * {@link DemoState#restart()}). Inside a step it is recorded and done once the frame's
     * steps are over. Allocates nothing.
     */
    public void restart() {
        hooks.prepare();
        if (world.isStepping()) {
            restartRequested = true;
            return;
        }
        restartRequested = false;
        hooks.beforeRestart();
        world.restart();
        for (int i = 0; i < particles.size(); ++i) {
            particles.get(i).restart();
        }
        hooks.particlesRestarted();
        clock.reset();
        replay.clear();
        warnings.clear();
        contactPause.restart();
        hooks.restarted();
    }

    /**
     * Make the next frame last {@link #HITCH_SECONDS}, as if the game had stalled.
     */
    public void injectHitch() {
        pendingHitchSeconds = HITCH_SECONDS;
        warnings.hitchInjected();
    }

    /** Pause, and take one step of h at the next frame. */
    public void singleStep() {
        clock.setPaused(true);
        clock.requestSingleStep();
    }

    /**
     * Multiply the time scale, within the clock's bounds.
     *
     * @param factor the factor (finite, &gt;0)
     */
    public void scaleTime(float factor) {
        float scale = clock.getTimeScale() * factor;
        scale = Math.max(SimulationClock.MIN_TIME_SCALE,
                Math.min(SimulationClock.MAX_TIME_SCALE, scale));
        clock.setTimeScale(scale);
    }

    /**
     * Advance the simulation by one frame and nothing else: the hitch, the clock's steps of
     * the world, a blow-up's recovery and a restart asked for inside a step. Touches no view.
     *
     * @param tpf the frame time (in seconds, finite, &ge;0)
     */
    public void advancePhysics(float tpf) {
        hooks.prepare();
        float frameSeconds = tpf;
        if (pendingHitchSeconds > 0f) {
            frameSeconds = pendingHitchSeconds;
            pendingHitchSeconds = 0f;
            warnings.hitchApplied(frameSeconds);
        }
        long physicsStart = System.nanoTime();
        if (!isSceneOver()) {
            try {
                clock.advance(frameSeconds, stepper);
            } catch (NonFiniteStepException blowUp) {
                ++blowUps;
                restart();
                warnings.blewUp();
            }
            if (restartRequested) {
                restart();
            }
        }
        physicsTimes.record(System.nanoTime() - physicsStart);
    }

    /**
     * One step of h of the world: the clock's stepper. After a restart was requested in this
     * frame the remaining steps do nothing; the restart follows them.
     */
    private void stepWorld(float stepSeconds) {
        if (restartRequested) {
            return;
        }
        replay.beforeStep();
        world.step(stepSeconds);
        for (int i = 0; i < simulations.size(); ++i) {
            simulations.get(i).step(stepSeconds);
        }
        if (!restartRequested) {
            replay.afterStep(stepSeconds);
        }
    }

    /** Before the world moves anything: which particles it steps, and what h does to them. */
    private void observeParticles(float stepSeconds) {
        warnings.beginStep(stepSeconds);
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle demoParticle = particles.get(i);
            demoParticle.steppedThisStep = !demoParticle.isHeld();
            if (demoParticle.steppedThisStep) {
                demoParticle.getRecord().begin(demoParticle.getParticle());
                warnings.observe(demoParticle.getLabel(), demoParticle.getForcesNow(),
                        demoParticle.getParticle());
            }
        }
    }

    /**
     * After the world's step: the export's rows, the demo's hooks. The trails are the view's:
     * the scene's own listener writes them.
     */
    private void finishStep(float stepSeconds) {
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle demoParticle = particles.get(i);
            if (!demoParticle.steppedThisStep) {
                continue;
            }
            // The export's row: the stepped state, the landing step's as the Euler step left
            // it below the ground (what `trajectory --until-ground` prints last).
            demoParticle.getRecord().add(demoParticle.getSteppedState(), stepSeconds);
        }
        hooks.afterStep(stepSeconds);
        warnings.endStep();
    }
}

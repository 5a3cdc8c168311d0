package particlelab.accuracy;

import com.jme3.effect.ParticleEmitter;
import com.jme3.effect.ParticleMesh;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.VertexBuffer;
import java.lang.management.ManagementFactory;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;
import particlelab.world.Fountain;

/**
 * The report's peer comparison at one N: jME's own {@link ParticleEmitter} (headless: a
 * {@code Point} mesh, gravity, a life long enough that all N stay alive, none spawned), the
 * fountain's whole step ({@link Fountain#step}) in full flow, and the bare batch step
 * ({@code stepPacked}, gravity + the fountain's linear drag, the scalar form) of the same N,
 * each a frame of h = {@value #FRAME_SECONDS} s. Also the bytes per particle each holds.
 *
 * <p>The work differs: the emitter also interpolates colour and size, turns and bounds its
 * particles but has no drag, no bounce and no finiteness check; the fountain bounces, recycles
 * and launches; the bare step only integrates.
 */
final class PeerScenes {

    /** The frame (s). */
    static final float FRAME_SECONDS = 1f / 60f;
    /** The fountain's steps before timing: the pool fills and flows. */
    static final int FLOW_STEPS = 600;
    /** The emitter relaunches and the bare step restarts from its copy this often (frames). */
    static final int FRAMES_PER_RELAUNCH = 600;
    /** jME's gravity (m/s², subtracted from V each frame). */
    static final float GRAVITY = 9.81f;
    /** The emitter's particles' life (s): longer than any run, so none dies. */
    static final float LIFE_SECONDS = 1e7f;

    private final int count;
    private final Node root = new Node("peer");
    private final ParticleEmitter emitter;
    private final Fountain fountain;
    private final ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
            new LinearDrag(Fountain.DRAG_B));
    private final float[] startPositions;
    private final float[] startVelocities;
    private final float[] positions;
    private final float[] velocities;
    /** A second copy of the packed state, for the A/A pass ({@link #packedStepAgain}). */
    private final float[] positionsAgain;
    private final float[] velocitiesAgain;
    private final ParticleIntegrator integratorAgain = new ParticleIntegrator(new Gravity(),
            new LinearDrag(Fountain.DRAG_B));
    /** Heap allocated by building and filling the emitter, per particle (B; NaN: unknown). */
    private final double emitterHeapBytes;
    /** The emitter's mesh buffers, per particle (B, direct memory). */
    private final double emitterDirectBytes;
    /** Heap allocated by building the fountain, per particle (B; NaN: unknown). */
    private final double fountainHeapBytes;
    private int emitterFrames;
    private int packedSteps;
    private int packedStepsAgain;

    /**
     * Build the three at one N.
     *
     * @param count N (&ge;1, at most {@link Fountain#MAX_PARTICLES})
     */
    PeerScenes(int count) {
        if (count < 1 || count > Fountain.MAX_PARTICLES) {
            throw new IllegalArgumentException("peer particle count must be in 1.."
                    + Fountain.MAX_PARTICLES + ", but was " + count);
        }
        this.count = count;
        long before = allocatedBytes();
        emitter = new ParticleEmitter("jme", ParticleMesh.Type.Point, count);
        emitter.setGravity(0f, GRAVITY, 0f);
        emitter.setLowLife(LIFE_SECONDS);
        emitter.setHighLife(LIFE_SECONDS);
        emitter.setParticlesPerSec(0f);
        emitter.getParticleInfluencer().setInitialVelocity(new Vector3f(0f, 14f, 0f));
        emitter.getParticleInfluencer().setVelocityVariation(0.25f);
        root.attachChild(emitter);
        emitter.emitAllParticles();
        emitterHeapBytes = perParticle(before, allocatedBytes());
        long direct = 0;
        for (VertexBuffer buffer : emitter.getMesh().getBufferList()) {
            if (buffer.getData() != null) {
                direct += (long) buffer.getData().capacity()
                        * buffer.getFormat().getComponentSize();
            }
        }
        emitterDirectBytes = (double) direct / count;
        before = allocatedBytes();
        fountain = new Fountain(count);
        fountainHeapBytes = perParticle(before, allocatedBytes());
        for (int i = 0; i < FLOW_STEPS; ++i) {
            fountain.step(FRAME_SECONDS);
        }
        integrator.batch().setVectorBatch(false);
        startPositions = planar(fountain.getPositions(), count);
        startVelocities = planar(fountain.getVelocities(), count);
        positions = startPositions.clone();
        velocities = startVelocities.clone();
        integratorAgain.batch().setVectorBatch(false);
        positionsAgain = startPositions.clone();
        velocitiesAgain = startVelocities.clone();
    }

    /**
     * One frame of jME's emitter: its logical update (the control: life, gravity, position,
     * colour, size, angle, bounds) and the geometric state.
     *
     * @return something the caller must consume
     */
    Object emitterFrame() {
        if (++emitterFrames == FRAMES_PER_RELAUNCH) {
            emitterFrames = 0;
            emitter.killAllParticles();
            emitter.emitAllParticles();
        }
        root.updateLogicalState(FRAME_SECONDS);
        root.updateGeometricState();
        return emitter;
    }

    /**
     * One whole step of the fountain.
     *
     * @return something the caller must consume
     */
    Object fountainStep() {
        fountain.step(FRAME_SECONDS);
        return fountain;
    }

    /**
     * One bare batch step of all N, from the fountain's state in flow.
     *
     * @return something the caller must consume
     */
    Object packedStep() {
        if (++packedSteps == FRAMES_PER_RELAUNCH) {
            packedSteps = 0;
            System.arraycopy(startPositions, 0, positions, 0, positions.length);
            System.arraycopy(startVelocities, 0, velocities, 0, velocities.length);
        }
        integrator.batch().stepPacked(positions, velocities, count, Fountain.MASS_KG,
                FRAME_SECONDS);
        return positions;
    }

    /**
     * {@link #packedStep} on a second copy of the same state with an integrator of its own:
     * the same work, timed beside the first as the peer rows' A/A pass.
     *
     * @return something the caller must consume
     */
    Object packedStepAgain() {
        if (++packedStepsAgain == FRAMES_PER_RELAUNCH) {
            packedStepsAgain = 0;
            System.arraycopy(startPositions, 0, positionsAgain, 0, positionsAgain.length);
            System.arraycopy(startVelocities, 0, velocitiesAgain, 0, velocitiesAgain.length);
        }
        integratorAgain.batch().stepPacked(positionsAgain, velocitiesAgain, count,
                Fountain.MASS_KG, FRAME_SECONDS);
        return positionsAgain;
    }

    /** @return N */
    int count() {
        return count;
    }

    /** @return heap per particle allocated to build and fill the emitter (B; NaN: unknown) */
    double emitterHeapBytes() {
        return emitterHeapBytes;
    }

    /** @return the emitter's mesh buffers per particle (B of direct memory) */
    double emitterDirectBytes() {
        return emitterDirectBytes;
    }

    /** @return heap per particle allocated to build the fountain (B; NaN: unknown) */
    double fountainHeapBytes() {
        return fountainHeapBytes;
    }

    /** @return the packed state's bytes per particle: P and V, three floats each */
    static double packedBytes() {
        return 6.0 * Float.BYTES;
    }

    /** The first N of each axis of a pool's planar arrays (stride = capacity = N here). */
    private static float[] planar(float[] pool, int count) {
        float[] copy = new float[3 * count];
        System.arraycopy(pool, 0, copy, 0, copy.length);
        return copy;
    }

    private double perParticle(long before, long after) {
        return before < 0 ? Double.NaN : (double) (after - before) / count;
    }

    private static long allocatedBytes() {
        java.lang.management.ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        if (threads instanceof com.sun.management.ThreadMXBean) {
            return ((com.sun.management.ThreadMXBean) threads).getCurrentThreadAllocatedBytes();
        }
        return -1;
    }
}

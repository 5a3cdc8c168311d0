package particlelab.accuracy;

import com.jme3.math.Vector3f;
import java.util.Arrays;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleBatch;
import particlelab.physics.ParticleIntegrator;

/**
 * The many-particle benchmark scene, shared by the report's in-process timing and the JMH
 * benchmarks so both measure the same thing: N particles of 1 kg under gravity and one
 * {@link ForceMix} (by default {@link ForceMix#LINEAR}, b/m = {@link #LINEAR_RATE}), each
 * launched at a slightly different velocity, held four ways — lecture-style objects,
 * {@link Particle} objects, and packed planar arrays shared by the integrator's batch form and
 * the primitive loop. Each step method advances all N by one step of {@link #STEP_SECONDS} and
 * allocates nothing except the lecture style's own garbage.
 *
 * <p>Each of the three storages is relaunched after every {@value #STEPS_PER_LAUNCH} of its own
 * steps (from copies of the launch state), so the scene is periodic and no velocity ever decays
 * far: left alone, the horizontal velocities {@code vx·(1 − k·h)ⁿ} become subnormal floats after
 * about 10<sup>4</sup> steps, where x86 arithmetic is 30–40× slower, and a measurement at small
 * N takes far more steps than that. A relaunch costs about one step of all N, once per
 * {@value #STEPS_PER_LAUNCH}. The other mixes stay normal over a flight too: quadratic drag
 * slows vx at most at c·|V|/m ≤ 0.02·36 = 0.72 /s, so after {@value #STEPS_PER_LAUNCH} steps
 * vx ≥ 20·(1 − 0.012)¹⁰⁰⁰ ≈ 1e-4 m/s; with thrust σ = (b − k/|V|)/m ≤ b/m, slower than linear
 * drag alone.
 */
public final class BulkScene {

    /** The drag rate b/m (in 1/s). */
    public static final float LINEAR_RATE = 0.5f;
    /** The step h (in seconds). */
    public static final float STEP_SECONDS = 1f / 60f;
    /** Steps of one storage between relaunches (after them the slowest vx is 5e-3 m/s). */
    public static final int STEPS_PER_LAUNCH = 1000;

    private final ForceMix mix;
    private final int count;
    private final LectureStyleParticle[] lecture;
    private final Particle[] objects;
    private final float[] positions;
    private final float[] velocities;
    /** The launch velocities, planar like {@link #velocities}. */
    private final float[] launchVelocities;
    private int lectureSteps;
    private int objectSteps;
    /** Steps of the packed arrays, by the batch form and the primitive loop together. */
    private int packedSteps;
    private final ParticleIntegrator integrator;
    /** The same forces, the batch on the Vector API; null where that form does not exist. */
    private final ParticleIntegrator vectorIntegrator;
    private final Vector3f gravity = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    private final float[] gravityPerAxis = {0f, -Gravity.STANDARD_G, 0f};

    /**
     * Launch the particles under gravity and linear drag b/m = {@link #LINEAR_RATE}.
     *
     * @param count N (&ge;1)
     */
    public BulkScene(int count) {
        this(ForceMix.LINEAR, count);
    }

    /**
     * Launch the particles under gravity and a force mix.
     *
     * @param mix the forces (not null)
     * @param count N (&ge;1)
     */
    public BulkScene(ForceMix mix, int count) {
        if (mix == null) {
            throw new IllegalArgumentException("force mix must not be null");
        }
        if (count < 1) {
            throw new IllegalArgumentException("particle count must be >= 1, but was " + count);
        }
        this.mix = mix;
        this.count = count;
        integrator = mix.integrator();
        // the batch path as the app runs it by default: the scalar passes (the Vector API
        // only where the JVM was started with it, timed apart)
        integrator.batch().setVectorBatch(false);
        if (mix.hasVectorBatch() && ParticleBatch.isVectorApiAvailable()) {
            vectorIntegrator = mix.integrator();
            vectorIntegrator.batch().setVectorBatch(true);
        } else {
            vectorIntegrator = null;
        }
        lecture = new LectureStyleParticle[count];
        objects = new Particle[count];
        positions = new float[3 * count];
        velocities = new float[3 * count];
        launchVelocities = new float[3 * count];
        for (int i = 0; i < count; ++i) {
            launchVelocities[i] = 20f + i % 7;
            launchVelocities[count + i] = 30f + i % 11;
            launchVelocities[2 * count + i] = i % 5;
            lecture[i] = new LectureStyleParticle(new Vector3f(), new Vector3f(), 1f);
            objects[i] = new Particle(new Vector3f(), new Vector3f(), 1f);
        }
        relaunchLectureStyle();
        relaunchObjects();
        relaunchPacked();
    }

    /**
     * Step every lecture-style particle once (allocating, as on the slides).
     *
     * @return something the caller must consume, so the work is not optimised away
     */
    public Object stepLectureStyle() {
        if (lectureSteps == STEPS_PER_LAUNCH) {
            relaunchLectureStyle();
        }
        ++lectureSteps;
        for (int i = 0; i < count; ++i) {
            lecture[i].step(gravity, mix, STEP_SECONDS);
        }
        return lecture;
    }

    /**
     * Step every {@link Particle} once through the shared integrator's array form,
     * {@code step(Particle[], h)}.
     *
     * @return something the caller must consume
     */
    public Object stepSharedObjects() {
        if (objectSteps == STEPS_PER_LAUNCH) {
            relaunchObjects();
        }
        ++objectSteps;
        integrator.step(objects, STEP_SECONDS);
        return objects;
    }

    /**
     * Step every {@link Particle} once through the shared integrator, one call of
     * {@code step(Particle, h)} each, as a world steps its bodies. Shares the objects and their
     * relaunch schedule with {@link #stepSharedObjects()}.
     *
     * @return something the caller must consume
     */
    public Object stepSharedEach() {
        if (objectSteps == STEPS_PER_LAUNCH) {
            relaunchObjects();
        }
        ++objectSteps;
        for (int i = 0; i < count; ++i) {
            integrator.step(objects[i], STEP_SECONDS);
        }
        return objects;
    }

    /**
     * Step every {@link Particle} once as {@link #stepSharedEach()} does, asking before each
     * step for its stability regime as the demos' warnings do: the step plus its bookkeeping.
     *
     * @return the worst regime's ordinal, so the question is not dropped
     */
    public int stepSharedEachWithRegime() {
        if (objectSteps == STEPS_PER_LAUNCH) {
            relaunchObjects();
        }
        ++objectSteps;
        int worst = 0;
        for (int i = 0; i < count; ++i) {
            worst = Math.max(worst, integrator.regime(objects[i], STEP_SECONDS).ordinal());
            integrator.step(objects[i], STEP_SECONDS);
        }
        return worst;
    }

    /**
     * Step the packed arrays once with the integrator's batch form.
     *
     * @return something the caller must consume
     */
    public Object stepSharedBatch() {
        relaunchPackedIfDue();
        integrator.batch().stepPacked(positions, velocities, count, 1f, STEP_SECONDS);
        return positions;
    }

    /**
     * Tell whether {@link #stepSharedBatchVector} can run: the mix has a Vector API form
     * ({@link ForceMix#hasVectorBatch}) and this JVM has the Vector API.
     *
     * @return true if it can
     */
    public boolean hasVectorBatch() {
        return vectorIntegrator != null;
    }

    /**
     * Step the packed arrays once with the integrator's batch form on the Vector API.
     *
     * @return something the caller must consume
     * @throws IllegalStateException if {@link #hasVectorBatch()} is false
     */
    public Object stepSharedBatchVector() {
        if (vectorIntegrator == null) {
            throw new IllegalStateException("no Vector API form of the batch for "
                    + mix.id() + (ParticleBatch.isVectorApiAvailable() ? ""
                    : " in a JVM started without --add-modules=jdk.incubator.vector"));
        }
        relaunchPackedIfDue();
        vectorIntegrator.batch().stepPacked(positions, velocities, count, 1f, STEP_SECONDS);
        return positions;
    }

    /**
     * Step the packed arrays once with the hand-written primitive loop.
     *
     * @return something the caller must consume
     */
    public Object stepPrimitiveLoop() {
        relaunchPackedIfDue();
        PrimitiveLoop.step(positions, velocities, count, gravityPerAxis, mix, STEP_SECONDS);
        return positions;
    }

    /**
     * Return the scene's forces.
     *
     * @return the mix (not null)
     */
    public ForceMix mix() {
        return mix;
    }

    /**
     * Return the number of particles.
     *
     * @return N (&ge;1)
     */
    public int count() {
        return count;
    }

    /**
     * Copy the lecture-style particles' state, for tests.
     *
     * @param storeResult planar P then planar V (length &ge; 6·N, modified)
     */
    void copyLectureStyle(float[] storeResult) {
        for (int i = 0; i < count; ++i) {
            store(lecture[i].position, lecture[i].velocity, i, storeResult);
        }
    }

    /**
     * Copy the Particle objects' state, for tests.
     *
     * @param storeResult planar P then planar V (length &ge; 6·N, modified)
     */
    void copyObjects(float[] storeResult) {
        for (int i = 0; i < count; ++i) {
            store(objects[i].position, objects[i].velocity, i, storeResult);
        }
    }

    /**
     * Copy the packed arrays, for tests.
     *
     * @param storeResult planar P then planar V (length &ge; 6·N, modified)
     */
    void copyPacked(float[] storeResult) {
        System.arraycopy(positions, 0, storeResult, 0, 3 * count);
        System.arraycopy(velocities, 0, storeResult, 3 * count, 3 * count);
    }

    private void store(Vector3f position, Vector3f velocity, int i, float[] storeResult) {
        storeResult[i] = position.x;
        storeResult[count + i] = position.y;
        storeResult[2 * count + i] = position.z;
        storeResult[3 * count + i] = velocity.x;
        storeResult[4 * count + i] = velocity.y;
        storeResult[5 * count + i] = velocity.z;
    }

    private void relaunchLectureStyle() {
        for (int i = 0; i < count; ++i) {
            // the style replaces both vectors every step, so these are the last step's own
            lecture[i].position.set(0f, 0f, 0f);
            lecture[i].velocity.set(launchVelocities[i], launchVelocities[count + i],
                    launchVelocities[2 * count + i]);
        }
        lectureSteps = 0;
    }

    private void relaunchObjects() {
        for (int i = 0; i < count; ++i) {
            objects[i].position.set(0f, 0f, 0f);
            objects[i].velocity.set(launchVelocities[i], launchVelocities[count + i],
                    launchVelocities[2 * count + i]);
        }
        objectSteps = 0;
    }

    private void relaunchPackedIfDue() {
        if (packedSteps == STEPS_PER_LAUNCH) {
            relaunchPacked();
        }
        ++packedSteps;
    }

    private void relaunchPacked() {
        Arrays.fill(positions, 0f);
        System.arraycopy(launchVelocities, 0, velocities, 0, velocities.length);
        packedSteps = 0;
    }
}

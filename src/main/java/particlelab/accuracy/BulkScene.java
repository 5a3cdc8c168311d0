package particlelab.accuracy;

import com.jme3.math.Vector3f;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * The many-particle benchmark scene, shared by the report's in-process timing and the JMH
 * benchmarks so both measure the same thing: N particles of 1 kg under gravity and linear drag
 * (b/m = {@link #LINEAR_RATE}), each launched at a slightly different velocity, held four ways —
 * lecture-style objects, {@link Particle} objects, and packed planar arrays shared by the
 * integrator's batch form and the primitive loop. Each step method advances all N by one step
 * of {@link #STEP_SECONDS} and allocates nothing except the lecture style's own garbage.
 */
public final class BulkScene {

    /** The drag rate b/m (in 1/s). */
    public static final float LINEAR_RATE = 0.5f;
    /** The step h (in seconds). */
    public static final float STEP_SECONDS = 1f / 60f;

    private final int count;
    private final LectureStyleParticle[] lecture;
    private final Particle[] objects;
    private final float[] positions;
    private final float[] velocities;
    private final ParticleIntegrator integrator =
            new ParticleIntegrator(new Gravity(), new LinearDrag(LINEAR_RATE));
    private final Vector3f gravity = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    private final float[] gravityPerAxis = {0f, -Gravity.STANDARD_G, 0f};

    /**
     * Launch the particles.
     *
     * @param count N (&ge;1)
     */
    public BulkScene(int count) {
        if (count < 1) {
            throw new IllegalArgumentException("particle count must be >= 1, but was " + count);
        }
        this.count = count;
        lecture = new LectureStyleParticle[count];
        objects = new Particle[count];
        positions = new float[3 * count];
        velocities = new float[3 * count];
        for (int i = 0; i < count; ++i) {
            Vector3f velocity = new Vector3f(20f + i % 7, 30f + i % 11, i % 5);
            lecture[i] = new LectureStyleParticle(new Vector3f(), velocity, 1f);
            objects[i] = new Particle(new Vector3f(), velocity, 1f);
            velocities[i] = velocity.x;
            velocities[count + i] = velocity.y;
            velocities[2 * count + i] = velocity.z;
        }
    }

    /**
     * Step every lecture-style particle once (allocating, as on the slides).
     *
     * @return something the caller must consume, so the work is not optimised away
     */
    public Object stepLectureStyle() {
        for (int i = 0; i < count; ++i) {
            lecture[i].step(gravity, LINEAR_RATE, STEP_SECONDS);
        }
        return lecture;
    }

    /**
     * Step every {@link Particle} once through the shared integrator.
     *
     * @return something the caller must consume
     */
    public Object stepSharedObjects() {
        integrator.step(objects, STEP_SECONDS);
        return objects;
    }

    /**
     * Step the packed arrays once with the integrator's batch form.
     *
     * @return something the caller must consume
     */
    public Object stepSharedBatch() {
        integrator.stepPacked(positions, velocities, count, 1f, STEP_SECONDS);
        return positions;
    }

    /**
     * Step the packed arrays once with the hand-written primitive loop.
     *
     * @return something the caller must consume
     */
    public Object stepPrimitiveLoop() {
        PrimitiveLoop.step(positions, velocities, count, gravityPerAxis, LINEAR_RATE,
                STEP_SECONDS);
        return positions;
    }
}

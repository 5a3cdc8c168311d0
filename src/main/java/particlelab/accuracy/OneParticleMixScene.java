package particlelab.accuracy;

import com.jme3.math.Vector3f;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * One particle under a {@link ForceMix}, shared by the report's in-process timing and the JMH
 * benchmarks: the rows {@code single/<mix>/<path>}. Three paths fly the same launch: the
 * lecture's allocating style, a {@link Particle} through the shared integrator's
 * {@code step(Particle, h)} (the call every demo's world makes per body), and the hand-written
 * primitive loop. Each flight relaunches from the origin at V = (20, 30, 4) m/s and takes
 * {@value #STEPS_PER_LAUNCH} dependent steps of {@link BulkScene#STEP_SECONDS}, so this is the
 * latency of one step.
 *
 * <p>No flight is long enough to decay into subnormal floats: the fastest decay, quadratic
 * drag at c·|V|/m ≤ 0.72 /s, leaves vz ≥ 4·(1 − 0.012)¹⁰⁰⁰ ≈ 2e-5 m/s after a flight.
 */
public final class OneParticleMixScene {

    /** Steps per flight: each {@code fly} call relaunches and then takes this many. */
    public static final int STEPS_PER_LAUNCH = 1000;
    /** The launch velocity (m/s), per axis. */
    private static final float LAUNCH_X = 20f;
    private static final float LAUNCH_Y = 30f;
    private static final float LAUNCH_Z = 4f;

    private static final float STEP_SECONDS = BulkScene.STEP_SECONDS;

    private final ForceMix mix;
    private final ParticleIntegrator integrator;
    private final Particle particle = new Particle();
    private final LectureStyleParticle lecture =
            new LectureStyleParticle(new Vector3f(), new Vector3f(), ForceMix.MASS_KG);
    private final Vector3f gravity = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    private final float[] gravityPerAxis = {0f, -Gravity.STANDARD_G, 0f};
    private final float[] position = new float[3];
    private final float[] velocity = new float[3];

    /**
     * Create the scene.
     *
     * @param mix the forces (not null)
     */
    public OneParticleMixScene(ForceMix mix) {
        if (mix == null) {
            throw new IllegalArgumentException("force mix must not be null");
        }
        this.mix = mix;
        this.integrator = mix.integrator();
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
     * Relaunch the lecture-style particle and fly it the slides' way (allocating).
     *
     * @return the particle after the flight (live)
     */
    public LectureStyleParticle flyLectureStyle() {
        // the style replaces both vectors every step, so these are the last flight's own
        lecture.position.set(0f, 0f, 0f);
        lecture.velocity.set(LAUNCH_X, LAUNCH_Y, LAUNCH_Z);
        for (int n = 0; n < STEPS_PER_LAUNCH; ++n) {
            lecture.step(gravity, mix, STEP_SECONDS);
        }
        return lecture;
    }

    /**
     * Relaunch the {@link Particle} and fly it through the shared integrator.
     *
     * @return the particle after the flight (live)
     */
    public Particle flySharedObjects() {
        particle.position.set(0f, 0f, 0f);
        particle.velocity.set(LAUNCH_X, LAUNCH_Y, LAUNCH_Z);
        for (int n = 0; n < STEPS_PER_LAUNCH; ++n) {
            integrator.step(particle, STEP_SECONDS);
        }
        return particle;
    }

    /**
     * Relaunch the {@link Particle} and fly it through the shared integrator, asking before
     * every step for its stability regime as the demos' warnings do: the step plus its
     * bookkeeping.
     *
     * @return the worst regime's ordinal over the flight, so the question is not dropped
     */
    public int flySharedWithRegime() {
        particle.position.set(0f, 0f, 0f);
        particle.velocity.set(LAUNCH_X, LAUNCH_Y, LAUNCH_Z);
        int worst = 0;
        for (int n = 0; n < STEPS_PER_LAUNCH; ++n) {
            worst = Math.max(worst, integrator.regime(particle, STEP_SECONDS).ordinal());
            integrator.step(particle, STEP_SECONDS);
        }
        return worst;
    }

    /**
     * Relaunch the primitive loop's particle and fly it.
     *
     * @return its position after the flight (live, length 3; the velocity follows in
     *     {@link #primitiveVelocity()})
     */
    public float[] flyPrimitiveLoop() {
        position[0] = 0f;
        position[1] = 0f;
        position[2] = 0f;
        velocity[0] = LAUNCH_X;
        velocity[1] = LAUNCH_Y;
        velocity[2] = LAUNCH_Z;
        PrimitiveLoop.stepOne(position, velocity, gravityPerAxis, mix, STEP_SECONDS,
                STEPS_PER_LAUNCH);
        return position;
    }

    /**
     * Access the primitive loop's velocity after the last {@link #flyPrimitiveLoop()}.
     *
     * @return V (in m/s, live, length 3)
     */
    float[] primitiveVelocity() {
        return velocity;
    }
}

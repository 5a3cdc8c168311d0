package particlelab.accuracy;

import com.jme3.math.Vector3f;
import particlelab.physics.Gravity;
import particlelab.reference.ForceModel;
import particlelab.reference.MotionState;
import particlelab.reference.Stepper;


/**
 * The one-particle benchmark scene, shared by the report's in-process timing and the JMH
 * benchmarks so both measure the same thing: one particle of 1 kg under gravity and linear drag
 * (b/m = {@link #LINEAR_RATE}), stepped by h = {@link #STEP_SECONDS}, as a reference stepper's
 * double state, as a lecture-style particle and as the primitive loop's float arrays.
 *
 * <p>Every {@code fly} call relaunches the particle from the canonical launch and then takes
 * {@link #STEPS_PER_LAUNCH} steps, so no measurement ever runs one flight for longer than that.
 * This matters: under drag the horizontal velocity decays as {@code vx·(1 − k·h)ⁿ} and, left
 * alone, becomes a subnormal float after about 10<sup>4</sup> steps (a subnormal double after
 * about 10<sup>5</sup>), where x86 arithmetic is 30–40× slower. After
 * {@value #STEPS_PER_LAUNCH} steps it is still about 5e-3 m/s. Relaunching costs six stores per
 * {@value #STEPS_PER_LAUNCH} steps.
 */
public final class OneParticleScene {

    /** The drag rate k = b/m (in 1/s). */
    public static final float LINEAR_RATE = 0.5f;
    /** The step h (in seconds). */
    public static final double STEP_SECONDS = 1.0 / 60.0;
    /** Steps per flight: each {@code fly} call relaunches and then takes this many. */
    public static final int STEPS_PER_LAUNCH = 1000;

    private static final float STEP_FLOAT = (float) STEP_SECONDS;

    private final ForceModel forces =
            ForceModel.perUnitMass(CanonicalCase.G, LINEAR_RATE, 0.0, 0.0);
    private final MotionState launch = CanonicalCase.launch();
    private final MotionState state = new MotionState();
    private final LectureStyleParticle lecture = new LectureStyleParticle(new Vector3f(),
            new Vector3f(), 1f);
    private final Vector3f gravity = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
    private final float[] gravityPerAxis = {0f, -Gravity.STANDARD_G, 0f};
    private final float[] position = new float[3];
    private final float[] velocity = new float[3];

    /**
     * Return the scene's forces, for creating the steppers to fly.
     *
     * @return the forces (not null, immutable)
     */
    public ForceModel forces() {
        return forces;
    }

    /**
     * Relaunch the particle and fly it with a stepper.
     *
     * @param stepper a stepper created for {@link #forces()} (not null)
     * @return the state after the flight (live, overwritten by the next call)
     */
    public MotionState fly(Stepper stepper) {
        state.set(launch);
        stepper.advance(state, STEP_SECONDS, STEPS_PER_LAUNCH);
        return state;
    }

    /**
     * Relaunch the lecture-style particle and fly it the slides' way (allocating).
     *
     * @return the particle after the flight (live)
     */
    public LectureStyleParticle flyLectureStyle() {
        // the style replaces both vectors every step, so these are the last step's own
        lecture.position.set((float) launch.position[0], (float) launch.position[1],
                (float) launch.position[2]);
        lecture.velocity.set((float) launch.velocity[0], (float) launch.velocity[1],
                (float) launch.velocity[2]);
        for (int n = 0; n < STEPS_PER_LAUNCH; ++n) {
            lecture.step(gravity, LINEAR_RATE, STEP_FLOAT);
        }
        return lecture;
    }

    /**
     * Relaunch the primitive loop's particle and fly it.
     *
     * @return its position after the flight (live, length 3; the velocity follows in
     *     {@link #primitiveVelocity()})
     */
    public float[] flyPrimitiveLoop() {
        for (int axis = 0; axis < 3; ++axis) {
            position[axis] = (float) launch.position[axis];
            velocity[axis] = (float) launch.velocity[axis];
        }
        PrimitiveLoop.stepOne(position, velocity, gravityPerAxis, LINEAR_RATE, STEP_FLOAT,
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

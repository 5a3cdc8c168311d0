package particlelab.aiming;

import com.jme3.math.Vector3f;
import particlelab.physics.Validate;

/**
 * HelloAiming's bullet as the lecture slide's update writes it, transcribed literally: every
 * frame a new velocity and a new position from jME's allocating {@code mult}/{@code add}, with
 * the frame's raw {@code tpf}, and the bullet moved only while {@code y >= 0}.
 *
 * <pre>
 *   if (bullet.getLocalTranslation().y &gt;= 0) {
 *       velocity = velocity.add(gravity.mult(tpf));
 *       bullet.setLocalTranslation(bullet.getLocalTranslation().add(velocity.mult(tpf)));
 *   }
 * </pre>
 *
 * Here {@link #position} stands for the spatial's local translation (this package has no
 * scene graph). Under gravity alone this is the same arithmetic as the shared integrator's
 * semi-implicit Euler step ({@code V ← V + h·g}, then {@code P ← P + h·V}): {@code g·tpf}
 * and {@code tpf·g} are the same float product, {@code V·1 + h·g} with no drag is
 * {@code V + h·g}, so while it flies its positions equal the integrator's bit for bit. It
 * differs at the ground: the test comes before the step, so the bullet stops only after a
 * step has taken it below {@code y = 0}, at the first sample with {@code y < 0}, where the
 * shared recipe stops it at the crossing interpolated inside that step.
 *
 * <p>Kept as the slide's reference, not as the project's style: {@link #update} allocates
 * {@value #VECTORS_PER_STEP} vectors per step and replaces the fields with them, which is
 * why they are not final.
 */
public final class SlideCodeBullet {

    /** The slide's lines, one string per code line, as the demo's HUD shows them. */
    public static final String[] LISTING = {
        "if (bullet.getLocalTranslation().y >= 0) {",
        "    velocity = velocity.add(gravity.mult(tpf));",
        "    bullet.setLocalTranslation("
                + "bullet.getLocalTranslation().add(velocity.mult(tpf))); }"};
    /**
     * The new {@code Vector3f} each moving step makes: {@code gravity.mult},
     * {@code velocity.add}, {@code velocity.mult} and {@code getLocalTranslation().add}.
     */
    public static final int VECTORS_PER_STEP = 4;

    /** The bullet's translation P (in metres; replaced by a new vector every step). */
    public Vector3f position = new Vector3f();
    /** Its velocity V (in m/s; replaced by a new vector every step). */
    public Vector3f velocity = new Vector3f();
    /** The steps it moved since the launch. */
    private int steps;

    /**
     * Put the bullet at a launch state.
     *
     * @param launchPosition P (in metres, not null, copied)
     * @param launchVelocity V (in m/s, not null, copied)
     */
    public void launch(Vector3f launchPosition, Vector3f launchVelocity) {
        position.set(Validate.notNull(launchPosition, "launchPosition"));
        velocity.set(Validate.notNull(launchVelocity, "launchVelocity"));
        steps = 0;
    }

    /**
     * The slide's update for one frame: move the bullet if it is not below the ground.
     *
     * @param gravity g (in m/s², not null, not modified)
     * @param tpf the frame's time (in seconds, raw: whatever the frame took)
     * @return true if the bullet moved
     */
    public boolean update(Vector3f gravity, float tpf) {
        Validate.notNull(gravity, "gravity");
        if (position.y >= 0) {
            velocity = velocity.add(gravity.mult(tpf));
            position = position.add(velocity.mult(tpf));
            ++steps;
            return true;
        }
        return false;
    }

    /**
     * Test whether the slide's test has stopped the bullet: a step took it below the ground.
     *
     * @return true once {@code y < 0}
     */
    public boolean isStopped() {
        return !(position.y >= 0);
    }

    /**
     * Return the steps the bullet moved since its launch.
     *
     * @return the count (&ge;0)
     */
    public int getSteps() {
        return steps;
    }

    /**
     * Set the step count, for a replay that restores the bullet.
     *
     * @param newSteps the count (&ge;0)
     */
    public void setSteps(int newSteps) {
        if (newSteps < 0) {
            throw new IllegalArgumentException("steps must be >= 0, but was " + newSteps);
        }
        steps = newSteps;
    }
}

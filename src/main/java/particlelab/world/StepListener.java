package particlelab.world;

/**
 * Hears the boundaries of each {@link World#step}: before anything moves and after the
 * epilogue. Scripts move kinematic bodies in {@link #beforeStep}; trails, warnings and a
 * demo's own hook read the finished step in {@link #afterStep}. Implementations should
 * allocate nothing.
 *
 * <p><b>The rule: {@code afterStep} observes; it moves nothing.</b> Every motion of a scene
 * happens inside {@link World#step}: the integrator moves the bodies (and turns those with a
 * rotation part), the collision rules and their responses change them at contacts, the
 * lecture's ground stop among them. A listener that set a position, a velocity or an
 * orientation after the step would move a body that no contact, log or listener saw move.
 * A relaunch (a new shot) is a restart of the body, not motion, and is asked for the same way.
 */
public interface StepListener {

    /**
     * Called at the start of a step, with the state at the start of the step.
     *
     * @param world the world (not null)
     * @param stepSeconds h (in seconds, &gt;0)
     */
    default void beforeStep(World world, float stepSeconds) {
    }

    /**
     * Called at the end of a step, after the epilogue and after destroyed bodies are gone.
     *
     * @param world the world (not null)
     * @param stepSeconds h (in seconds, &gt;0)
     */
    default void afterStep(World world, float stepSeconds) {
    }
}

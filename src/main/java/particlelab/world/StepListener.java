package particlelab.world;

/**
 * Hears the boundaries of each {@link World#step}: before anything moves and after the
 * epilogue. Scripts move kinematic bodies in {@link #beforeStep}; trails, warnings and a
 * demo's own hook read the finished step in {@link #afterStep}. Implementations should
 * allocate nothing.
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

package particlelab.physics;

/**
 * Thrown by {@link ParticleIntegrator} when a step would leave a particle with a NaN or
 * infinite component: the step was far beyond the stability limit, or the numbers overflowed
 * the float range. The particles keep their last finite state (see each method's contract).
 *
 * <p>A subclass of {@link IllegalStateException}, so older code that catches that still
 * compiles; catch this type by name to mean "the step blew up" and nothing else.
 */
public final class NonFiniteStepException extends IllegalStateException {

    private static final long serialVersionUID = 1L;

    /**
     * Create an exception.
     *
     * @param oneLineMessage the step, the state and why it failed (not null, no line break)
     */
    public NonFiniteStepException(String oneLineMessage) {
        super(oneLineMessage);
    }
}

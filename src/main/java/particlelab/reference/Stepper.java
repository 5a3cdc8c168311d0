package particlelab.reference;

/**
 * One stepping method bound to one scene's forces: it advances a {@link MotionState} by steps
 * of h and allocates nothing while doing so. Instances keep scratch space, so they are not
 * thread-safe; create one per thread with {@link Scheme#create}.
 */
public interface Stepper {

    /**
     * Return which method this is.
     *
     * @return the scheme (not null)
     */
    Scheme scheme();

    /**
     * Advance the state by one step.
     *
     * @param state the state to advance (not null, modified)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     */
    void step(MotionState state, double stepSeconds);

    /**
     * Advance the state by several steps of the same size. Each implementation has its own
     * loop, so a timing loop that calls it sees one method per stepper (no megamorphic call).
     *
     * @param state the state to advance (not null, modified)
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @param steps how many steps (&ge;0)
     */
    void advance(MotionState state, double stepSeconds, int steps);
}

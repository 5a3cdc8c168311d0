package particlelab.world;

/**
 * A part of a simulation whose state a {@link StateRing} records after every step and puts
 * back on a step back: everything its next step reads and that a step changes. A
 * {@link World} is one (its bodies, the alive set, its counters); a demo with counters of its
 * own declares them as another. Writing and reading go in the same order, and the state read
 * back must make the next step give the same bits as it did the first time.
 */
public interface StateRecord {

    /**
     * Count the ints {@link #writeState} writes now (it may grow as the simulation grows, for
     * instance when a body is spawned for the first time).
     *
     * @return the count (&ge;0)
     */
    int countStateInts();

    /**
     * Write the state. Allocates nothing.
     *
     * @param slab where to write, from its cursor on (not null, modified)
     */
    void writeState(StateSlab slab);

    /**
     * Put back a state written by {@link #writeState}, in the same order. Must not be called
     * inside a step.
     *
     * @param slab where to read, from its cursor on (not null, modified)
     */
    void readState(StateSlab slab);
}

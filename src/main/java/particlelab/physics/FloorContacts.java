package particlelab.physics;

/**
 * What a batch step that finds a floor hands on, block by block
 * ({@link ParticleBatch#stepPackedFindingFloor(float[], float[], int, int, float, float,
 * float, int[], float[], FloorContacts)}): the particles of one block found at or below the
 * floor, right after that block's step, while its positions and velocities are still in the
 * processor's cache, so that a ground's rule can be applied to them there rather than in a
 * pass afterwards that reads each one from memory again.
 */
@FunctionalInterface
public interface FloorContacts {

    /**
     * Take the particles of one block found at or below the floor.
     *
     * @param found their indices, increasing, at found[from] to found[to − 1] (the entries
     *     before from were handed on already: the receiver may write over them)
     * @param velocityYBefore each one's vy before the step, at the same places (in m/s)
     * @param from the first of this block's (&ge;0)
     * @param to one past the last (&gt;from)
     */
    void take(int[] found, float[] velocityYBefore, int from, int to);
}

package particlelab.physics;

/**
 * The overlap test of many particles against a floor at once: which of a run of heights are
 * at or below a given one ({@code y ≤ floor}, which is {@code d = floor − y ≥ 0} in double
 * too, since floats convert exactly). It serves the ground's contact test
 * ({@code particlelab.world.GroundBounce}) and the batch step that finds the contacts while
 * each block of particles is still in the cache
 * ({@link ParticleBatch#stepPackedFindingFloor}).
 *
 * <p>Contacts are rare (about one particle in seventy in the fountain), so the test runs
 * over groups of {@value #GROUP} heights without a branch (an or of the comparisons, which
 * the compiler can do several at a time) and only a group holding one is looked at one by
 * one: the indices come out in increasing order, as from one test per height. A NaN is never
 * at or below anything. Allocates nothing.
 */
public final class HeightScan {

    /** The heights tested together before each is looked at. */
    private static final int GROUP = 8;

    private HeightScan() {
    }

    /**
     * Append the index of every height at or below the floor.
     *
     * @param heights the heights (in metres, not modified)
     * @param start the first to test (&ge;0)
     * @param length how many (&ge;0, start + length at most heights.length)
     * @param floorMetres the floor (in metres)
     * @param firstIndex the index to store for heights[start] (the others follow on)
     * @param storeIndices where to append (modified from storeAt on; room for every one
     *     found)
     * @param storeAt how many are stored already: where the first found goes
     * @return how many are stored now: storeAt plus those found
     */
    public static int findAtOrBelow(float[] heights, int start, int length, float floorMetres,
            int firstIndex, int[] storeIndices, int storeAt) {
        int found = storeAt;
        int end = start + length;
        int i = start;
        for (; i + GROUP <= end; i += GROUP) {
            int any = 0;
            for (int k = 0; k < GROUP; ++k) {
                any |= heights[i + k] <= floorMetres ? 1 : 0;
            }
            if (any != 0) {
                for (int k = 0; k < GROUP; ++k) {
                    if (heights[i + k] <= floorMetres) {
                        storeIndices[found++] = firstIndex + (i - start) + k;
                    }
                }
            }
        }
        for (; i < end; ++i) {
            if (heights[i] <= floorMetres) {
                storeIndices[found++] = firstIndex + (i - start);
            }
        }
        return found;
    }
}

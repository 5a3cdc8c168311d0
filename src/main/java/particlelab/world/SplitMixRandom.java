package particlelab.world;

/**
 * A seeded random sequence whose state can be recorded, for a simulation whose steps draw
 * random numbers (a step back must draw them again): SplitMix64, the generator of
 * {@link java.util.SplittableRandom} ({@code seed += γ}, then Stafford's mix of the seed), so
 * the same seed gives the same doubles as {@code new SplittableRandom(seed).nextDouble()}.
 */
public final class SplitMixRandom {

    /** The increment γ: 2^64 over the golden ratio, odd. */
    private static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;
    private static final long MIX_1 = 0xbf58476d1ce4e5b9L;
    private static final long MIX_2 = 0x94d049bb133111ebL;
    /** A double's 53 bits of fraction: the top ones of a long are kept. */
    private static final int DOUBLE_SHIFT = 11;
    private static final double DOUBLE_UNIT = 0x1.0p-53;

    private long seed;

    /**
     * Start a sequence.
     *
     * @param newSeed the seed (any; as {@code new SplittableRandom(seed)})
     */
    public SplitMixRandom(long newSeed) {
        seed = newSeed;
    }

    /**
     * Draw the next double, as {@link java.util.SplittableRandom#nextDouble()} does.
     *
     * @return a value from 0 (included) to 1 (excluded)
     */
    public double nextDouble() {
        return (nextLong() >>> DOUBLE_SHIFT) * DOUBLE_UNIT;
    }

    /**
     * Draw the next long.
     *
     * @return any long
     */
    public long nextLong() {
        seed += GOLDEN_GAMMA;
        long z = seed;
        z = (z ^ (z >>> 30)) * MIX_1;
        z = (z ^ (z >>> 27)) * MIX_2;
        return z ^ (z >>> 31);
    }

    /**
     * Return the state, for a state record.
     *
     * @return the seed reached
     */
    public long getState() {
        return seed;
    }

    /**
     * Put back a state {@link #getState} returned.
     *
     * @param state the seed reached
     */
    public void setState(long state) {
        seed = state;
    }
}

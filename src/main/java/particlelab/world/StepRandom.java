package particlelab.world;

/**
 * A seeded random sequence whose state can be recorded, for a demo whose steps draw random
 * numbers (a step back must draw them again): the linear congruential generator that
 * {@link java.util.Random} documents ({@code seed = (seed·0x5DEECE66D + 0xB) mod 2^48}, the
 * top bits taken), so the same seed gives the same numbers as {@code new Random(seed)}.
 */
public final class StepRandom {

    private static final long MULTIPLIER = 0x5DEECE66DL;
    private static final long ADDEND = 0xBL;
    private static final long MASK = (1L << 48) - 1;
    /** The state's bits: 48. */
    private static final int STATE_BITS = 48;
    /** The bits of a float's fraction drawn. */
    private static final int FLOAT_BITS = 24;

    private long state;

    /**
     * Start a sequence.
     *
     * @param seed the seed (any; as {@code new Random(seed)})
     */
    public StepRandom(long seed) {
        setSeed(seed);
    }

    /**
     * Start the sequence again from a seed.
     *
     * @param seed the seed (any; as {@link java.util.Random#setSeed})
     */
    public void setSeed(long seed) {
        state = (seed ^ MULTIPLIER) & MASK;
    }

    /**
     * Draw the next float, as {@link java.util.Random#nextFloat} does.
     *
     * @return a value from 0 (included) to 1 (excluded)
     */
    public float nextFloat() {
        return next(FLOAT_BITS) / (float) (1 << FLOAT_BITS);
    }

    /**
     * Return the state, for a state record.
     *
     * @return the 48-bit state
     */
    public long getState() {
        return state;
    }

    /**
     * Put back a state {@link #getState} returned.
     *
     * @param newState the 48-bit state
     */
    public void setState(long newState) {
        state = newState & MASK;
    }

    private int next(int bits) {
        state = (state * MULTIPLIER + ADDEND) & MASK;
        return (int) (state >>> (STATE_BITS - bits));
    }
}

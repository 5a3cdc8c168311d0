package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The recordable random sequences draw exactly the numbers of the JDK generators they
 * replace (so the demos' runs are unchanged), and a state put back draws the same numbers
 * again.
 */
class StepRandomTest {

    private static final int DRAWS = 100_000;
    private static final long[] SEEDS = {0L, 1L, 42L, -7L, 0x1234_5678_9abcL, Long.MIN_VALUE};

    @Test
    void stepRandomDrawsJavaUtilRandomsFloats() {
        for (long seed : SEEDS) {
            Random jdk = new Random(seed);
            StepRandom ours = new StepRandom(seed);
            for (int i = 0; i < DRAWS; ++i) {
                // Bit for bit: the same LCG and the same 24 bits.
                assertEquals(Float.floatToIntBits(jdk.nextFloat()),
                        Float.floatToIntBits(ours.nextFloat()), "seed " + seed + " draw " + i);
            }
            jdk.setSeed(seed + 1);
            ours.setSeed(seed + 1);
            assertEquals(jdk.nextFloat(), ours.nextFloat());
        }
    }

    @Test
    void splitMixDrawsSplittableRandomsDoubles() {
        for (long seed : SEEDS) {
            SplittableRandom jdk = new SplittableRandom(seed);
            SplitMixRandom ours = new SplitMixRandom(seed);
            for (int i = 0; i < DRAWS; ++i) {
                assertEquals(Double.doubleToLongBits(jdk.nextDouble()),
                        Double.doubleToLongBits(ours.nextDouble()), "seed " + seed + " draw " + i);
            }
        }
    }

    @Test
    void aStatePutBackDrawsTheSameNumbersAgain() {
        StepRandom lcg = new StepRandom(3L);
        SplitMixRandom mix = new SplitMixRandom(3L);
        lcg.nextFloat();
        mix.nextDouble();
        long lcgState = lcg.getState();
        long mixState = mix.getState();
        float lcgNext = lcg.nextFloat();
        double mixNext = mix.nextDouble();
        lcg.nextFloat();
        mix.nextDouble();
        lcg.setState(lcgState);
        mix.setState(mixState);
        assertEquals(lcgNext, lcg.nextFloat());
        assertEquals(mixNext, mix.nextDouble());
    }
}

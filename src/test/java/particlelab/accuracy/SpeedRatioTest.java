package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class SpeedRatioTest {

    @Test
    void aSlowerBatchIsCalledSlowerNotOneTimesFaster() {
        // the report once printed "1× faster" for a batch at 0.77× the lecture style's speed
        assertEquals("1.3× slower", SpeedRatio.describe(1.0, 0.77));
    }

    @Test
    void aFasterFormIsCalledFasterByTheRatioOfTimes() {
        assertEquals("3.2× faster", SpeedRatio.describe(1.0, 3.2));
        assertEquals("28× faster", SpeedRatio.describe(0.5, 14.0));
    }

    @Test
    void timesWithinRoundingAreAboutAsFast() {
        assertEquals(SpeedRatio.SAME, SpeedRatio.describe(1.0, 1.04));
        assertEquals(SpeedRatio.SAME, SpeedRatio.describe(1.04, 1.0));
    }

    @Test
    void missingOrNonPositiveTimesGiveADash() {
        assertEquals("—", SpeedRatio.describe(Double.NaN, 1.0));
        assertEquals("—", SpeedRatio.describe(1.0, 0.0));
    }
}

package particlelab.view;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The energy bars' scale without rendering: a round number at or above the largest energy,
 * so the bars keep one scale while the energy moves under it (no jitter frame to frame).
 */
class EnergyBarsTest {

    @Test
    void theScaleIsTheRoundNumberAtOrAboveTheValue() {
        // exact: every expected value is a decimal the double holds to its last bit's
        // rounding, compared with a relative 1e-12
        double[][] cases = {{321.07, 400.0}, {83.3, 100.0}, {1364.6, 1500.0}, {1.0, 1.0},
            {0.0123, 0.015}, {2.5, 3.0}, {7.9, 8.0}, {8.1, 10.0}, {0.0, 1.0}, {-5.0, 1.0}};
        for (double[] c : cases) {
            assertEquals(c[1], EnergyBars.roundUp(c[0]), 1e-12 * c[1], "roundUp(" + c[0] + ")");
        }
    }

    @Test
    void theScaleStaysWhileTheEnergyMovesBelowIt() {
        // a bouncing ball's energy falls from 83.3 J: every value under it keeps 100
        for (double joules = 83.3; joules > 60.0; joules -= 0.37) {
            assertEquals(100.0, EnergyBars.roundUp(Math.max(83.3, joules)), 0.0);
        }
    }
}

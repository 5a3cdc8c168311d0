package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

class StabilityMapTest {

    @ParameterizedTest
    @EnumSource(value = Scheme.class, names = "EXACT", mode = EnumSource.Mode.EXCLUDE)
    void bisectionFindsTheTheoreticalLimitWithinOnePercent(Scheme scheme) {
        for (double k : new double[] {0.1, 2.0, 50.0}) {
            double measured = StabilityMap.maxStableStep(scheme, k, 9.8);
            double theory = scheme.theoryStableStep(k);
            // The bound is 1%. The trial's growth test resolves a factor of 1e-4 per
            // step (2000 steps) and the float run's h rounding is 6e-8, so 1% is generous.
            assertEquals(theory, measured, 0.01 * theory, scheme + " at b/m = " + k);
        }
    }

    @ParameterizedTest
    @EnumSource(value = Scheme.class, names = {"FORWARD_EULER", "SEMI_IMPLICIT_EULER"})
    void bothEulerFormsAreStableToTwoMassesPerDrag(Scheme scheme) {
        // the headline number of NUMERICS' table, independent of Scheme's own factor
        assertEquals(2.0 / 0.5, StabilityMap.maxStableStep(scheme, 0.5, 9.8), 0.01 * 4.0);
    }

    @org.junit.jupiter.api.Test
    void exactStepIsStableAtEveryStepTried() {
        assertEquals(Double.POSITIVE_INFINITY,
                StabilityMap.maxStableStep(Scheme.EXACT, 2.0, 9.8));
    }
}

package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.physics.ParticleIntegrator;
import particlelab.reference.Scheme;


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
        // the headline number of docs/numerics.md's table, independent of Scheme's own factor
        assertEquals(2.0 / 0.5, StabilityMap.maxStableStep(scheme, 0.5, 9.8), 0.01 * 4.0);
    }

    @Test
    void exactStepIsStableAtEveryStepTried() {
        assertEquals(Double.POSITIVE_INFINITY,
                StabilityMap.maxStableStep(Scheme.EXACT, 2.0, 9.8));
    }

    @Test
    void springBisectionFindsTheDampedOscillatorLimit() {
        // Theory 4/(λ + sqrt(λ² + 4ω²)) with ω² = 100: from 2/ω = 0.2 s (weak drag) to 2/λ
        // (strong drag). Near the limit one eigenvalue is −(1 + ε), ε ~ Δh/h: 2000 steps
        // resolve about 1e-3 of h; float h rounds at 6e-8. So 0.5 % is a safe bound.
        for (double lambda : new double[] {0.1, 2.0, 10.0, 100.0}) {
            double theory =
                    ParticleIntegrator.stableStepLimit(lambda, StabilityMap.SPRING_STIFFNESS);
            double measured = StabilityMap.maxStableStepSpring(lambda,
                    StabilityMap.SPRING_STIFFNESS);
            assertEquals(theory, measured, 0.005 * theory, "b/m = " + lambda);
        }
        // Just below decays, just above grows.
        double limit = ParticleIntegrator.stableStepLimit(2.0, 100.0);
        assertTrue(StabilityMap.isSpringStable(2.0, 100.0, 0.99 * limit));
        assertFalse(StabilityMap.isSpringStable(2.0, 100.0, 1.01 * limit));
    }
}

package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.reference.VelocityVerlet;


/**
 * The report's energy section (issue 32): the numerical energy's fitted orders are the
 * steppers' known ones, and the gravity case's semi-implicit figure is the closed form.
 */
class EnergySectionTest {

    private static final double[][][] ERRORS = EnergySection.measure();

    private static double order(String scene, String method) {
        int c = java.util.Arrays.asList(EnergySection.CASES).indexOf(scene);
        int m = java.util.Arrays.asList(EnergySection.METHODS).indexOf(method);
        return EnergySection.order(ERRORS[c][m]);
    }

    @Test
    void theEulerStepsAreFirstOrderInEveryCase() {
        // a fit over 7 halvings of h: the slope of a first-order error is 1 to within the
        // curvature of its next term (forward Euler's spring: e^(ω²hT) − 1, ω²hT = 0.53 at
        // h = 1/15 s, measured 1.06)
        for (String scene : EnergySection.CASES) {
            assertEquals(1.0, order(scene, "forward"), 0.1, scene);
            assertEquals(1.0, order(scene, "semi-implicit"), 0.1, scene);
        }
    }

    @Test
    void theHigherOrderStepsShowTheirOrdersOrAreExactUnderGravity() {
        for (String method : new String[] {"verlet", "midpoint", "rk4"}) {
            double[] gravity = ERRORS[0][java.util.Arrays.asList(EnergySection.METHODS)
                    .indexOf(method)];
            for (double error : gravity) {
                // constant acceleration: each of these steps is exact, up to round-off of
                // energies of about 100 J
                assertTrue(error < EnergySection.ROUND_OFF_JOULES, method + ": " + error);
            }
        }
        assertEquals(2.0, order("spring", "verlet"), 0.15);
        // in energy: |R|² = 1 + (ωh)⁴/4 for the midpoint step, 1 − (ωh)⁶/72 for RK4
        assertEquals(3.0, order("spring", "midpoint"), 0.15);
        assertEquals(5.0, order("spring", "rk4"), 0.3);
        // drag at V½ makes games' Verlet first order (the report's VelocityVerlet Javadoc)
        assertEquals(1.0, order("drag", "verlet"), 0.15);
        assertEquals(2.0, order("drag", "midpoint"), 0.15);
        assertEquals(4.0, order("drag", "rk4"), 0.3);
    }

    @Test
    void theLectureStepUnderGravityLosesMghTimesVyChangeOverTwo() {
        // |numerical| = m·g·h·|vy − vy0|/2 = g·h·(g·t)/2 at its largest, t = 2 s, m = 1 kg
        double h = EnergySection.STEPS[2];
        double expected = 9.8 * h * (9.8 * 2.0) / 2.0;
        // doubles, 120 steps: 1e-12 of energies of 100 J
        assertEquals(expected, ERRORS[0][1][2], 1e-10);
    }

    @Test
    void theSectionListsEveryMethodWithItsOrders() {
        String text = EnergySection.markdown(ERRORS);
        assertTrue(text.contains(EnergySection.HEADING));
        for (String method : EnergySection.METHODS) {
            assertTrue(text.contains("| " + method + " |"), method);
        }
        assertTrue(EnergySection.csv(ERRORS).startsWith(EnergySection.HEADER + "\n"));
    }
}

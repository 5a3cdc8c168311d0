package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class LandingTest {

    @Test
    void aStepCrossesTheGroundOnlyFromAtOrAboveToStrictlyBelow() {
        assertTrue(Landing.crossesGround(1f, -1f));
        // A sample exactly on the ground is still "above": the crossing is in the next step.
        assertFalse(Landing.crossesGround(1f, 0f));
        assertTrue(Landing.crossesGround(0f, -0.5f));
        // Already below, or going up: no landing.
        assertFalse(Landing.crossesGround(-1f, -2f));
        assertFalse(Landing.crossesGround(-1f, 1f));
    }

    @Test
    void crossingFractionIsWhereTheStraightLineMeetsTheGround() {
        // From 3 m to -1 m the line meets y = 0 three quarters of the way: exact in binary.
        assertEquals(0.75, Landing.crossingFraction(3f, -1f), 0.0);
        // From the ground itself the crossing is at the start of the step.
        assertEquals(0.0, Landing.crossingFraction(0f, -2f), 0.0);
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The iterative aimer's HUD counts in words that agree with the count, in plain JUnit. */
class IterativeAimingHudTest {

    @Test
    void theInstantRoundSaysOneFlownShotInTheSingular() {
        IterativeAimingDemo iterate = new IterativeAimingDemo();
        iterate.setInstant(true);
        for (int frame = 0; frame < 2000 && !iterate.isRoundOver(); ++frame) {
            iterate.getRun().advancePhysics(1f / 60f);
        }
        assertTrue(iterate.isRoundOver());
        String hud = iterate.getWindow().formatHud(new StringBuilder()).toString();
        // The instant mode flies only the final shot.
        assertTrue(hud.contains("Round over after 1 flown shot (F fires a new round)"), hud);
        assertFalse(hud.contains(" 1 flown shots"), hud);
        assertFalse(hud.contains(" 1 shots"), hud);
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The Targets demo's prologue, in plain JUnit: the demo's physics and HUD text run without
 * jME. Its destroy-and-spawn cycles, whose fragments expire in a frame with views, are in
 * {@link LectureFramesHeadlessTest}.
 */
class TargetsDemoTest {

    private static final float H = 1f / 60f;

    @Test
    void theFriendlyPlatformIsIgnoredByThePrologue() {
        TargetsDemo targets = new TargetsDemo();
        targets.restart();
        targets.fireAtAngle(-90f); // straight down into the gun's platform
        for (int frame = 0; frame < 3; ++frame) {
            targets.getRun().advancePhysics(H);
        }
        targets.fireAtAngle(35f);
        String hud = targets.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("1 prologue:   ignored: friendly (the gun's own platform)"),
                hud);
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.world.World;

/** The Targets demo attached to a headless app: the three phases, and nothing left behind. */
class TargetsDemoTest {

    private static final float H = 1f / 60f;
    private static final TargetsDemo targets = new TargetsDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(targets));

    @Test
    void destroyAndSpawnCyclesLeaveNoBodyViewOrListenerBehind() throws Exception {
        Object[] result = harness.call(() -> {
            targets.restart();
            for (int frame = 0; frame < 240; ++frame) {
                targets.advance(H); // the first shot's flight; fragments expire
            }
            World world = targets.getWorld();
            int[] listeners = {world.countContactListeners(), world.countStepListeners(),
                world.countBodyListeners(), world.countRules()};
            long startDestroyed = targets.countDestroyed();
            int cycles = 0;
            while (targets.countDestroyed() - startDestroyed < 120 && cycles < 2000) {
                ++cycles;
                int alive = -1;
                for (int i = 0; i < 3 && alive < 0; ++i) {
                    if (targets.fireAt(i)) {
                        alive = i;
                    }
                }
                long before = targets.countDestroyed();
                for (int frame = 0; frame < 200 && targets.countDestroyed() == before;
                        ++frame) {
                    targets.advance(H);
                }
            }
            for (int frame = 0; frame < 400; ++frame) {
                targets.advance(H); // every fragment expires, the targets come back
            }
            return new Object[] {targets.countDestroyed() - startDestroyed, cycles,
                world.countBodies(), targets.getBodyViews().countShown(),
                targets.countTargetsAlive(), targets.countFragments(),
                world.countRecycledBodies(), listeners,
                new int[] {world.countContactListeners(), world.countStepListeners(),
                    world.countBodyListeners(), world.countRules()},
                targets.countSpawned(),
                targets.getSceneNode().getChildren().size(),
                targets.formatHud(new StringBuilder()).toString()};
        });
        long destroyed = (Long) result[0];
        assertTrue(destroyed >= 120, destroyed + " targets in " + result[1] + " shots");
        // Left: the shot, the platform and the live targets (they come back only when all are
        // gone); spheres for the platform and the live targets (the shot has its
        // ParticleView); no fragment.
        int alive = (Integer) result[4];
        assertEquals(2 + alive, (Integer) result[2], "bodies");
        assertEquals(1 + alive, (Integer) result[3], "body views");
        assertEquals(0, (Integer) result[5]);
        // Recycled bodies: at most the most ever alive at once (3 targets, 24 fragments).
        assertTrue((Integer) result[6] <= 27, "recycled " + result[6]);
        assertEquals(java.util.Arrays.toString((int[]) result[7]),
                java.util.Arrays.toString((int[]) result[8]), "listeners and rules");
        assertTrue((Long) result[9] >= 6 * destroyed);
        String hud = (String) result[11];
        assertTrue(hud.contains("3 epilogue:   destroyed target "), hud);
        assertTrue(hud.contains("sound: "), hud);
    }

    @Test
    void theFriendlyPlatformIsIgnoredByThePrologue() throws Exception {
        String hud = harness.call(() -> {
            targets.restart();
            targets.fireAtAngle(-90f); // straight down into the gun's platform
            for (int frame = 0; frame < 3; ++frame) {
                targets.advance(H);
            }
            targets.fireAtAngle(35f);
            return targets.formatHud(new StringBuilder()).toString();
        });
        assertTrue(hud.contains("1 prologue:   ignored: friendly (the gun's own platform)"),
                hud);
    }
}

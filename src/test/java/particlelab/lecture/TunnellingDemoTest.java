package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The Tunnelling demo's counts against the miss formula. Plain JUnit: the demo's physics and
 * HUD text run without jME.
 */
class TunnellingDemoTest {

    private static final float H = 1f / 60f;

    @Test
    void theSweptTestNeverMissesAndTheOverlapTestMissesAtThePredictedRate() {
        TunnellingDemo tunnelling = new TunnellingDemo();
        for (float speed : new float[] {10f, 40f, 120f}) {
            tunnelling.setSpeed(speed);
            for (int frame = 0; frame < 20000; ++frame) {
                tunnelling.getRun().advancePhysics(H);
            }
            int shots = tunnelling.countShots(false);
            int sweptShots = tunnelling.countShots(true);
            assertTrue(shots > 300, speed + " m/s: " + shots + " shots");
            assertEquals(sweptShots, tunnelling.countHits(true),
                    speed + " m/s: the swept test missed");
            double p = tunnelling.predictedMissProbability();
            double measured = 1.0 - tunnelling.countHits(false) / (double) shots;
            // A binomial count: within 4 standard deviations sqrt(p(1-p)/n), plus 1/n for the
            // float rounding of a phase at the band's edge.
            double sigma = Math.sqrt(p * (1.0 - p) / shots);
            assertEquals(p, measured, 4.0 * sigma + 1.0 / shots,
                    speed + " m/s over " + shots + " shots");
            String hud = tunnelling.getWindow().formatHud(new StringBuilder()).toString();
            assertTrue(hud.contains("swept test  :  shots " + sweptShots + "   hits "
                    + sweptShots + "   misses 0"), hud);
        }
    }
}

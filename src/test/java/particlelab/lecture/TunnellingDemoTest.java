package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;

/** The Tunnelling demo attached to a headless app: its counts against the miss formula. */
class TunnellingDemoTest {

    private static final float H = 1f / 60f;
    private static final TunnellingDemo tunnelling = new TunnellingDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(tunnelling));

    @Test
    void theSweptTestNeverMissesAndTheOverlapTestMissesAtThePredictedRate() throws Exception {
        for (float speed : new float[] {10f, 40f, 120f}) {
            Object[] result = harness.call(() -> {
                tunnelling.setSpeed(speed);
                for (int frame = 0; frame < 20000; ++frame) {
                    tunnelling.advance(H);
                }
                return new Object[] {tunnelling.countShots(false), tunnelling.countHits(false),
                    tunnelling.countShots(true), tunnelling.countHits(true),
                    tunnelling.predictedMissProbability(),
                    tunnelling.formatHud(new StringBuilder()).toString()};
            });
            int shots = (Integer) result[0];
            int sweptShots = (Integer) result[2];
            assertTrue(shots > 300, speed + " m/s: " + shots + " shots");
            assertEquals(sweptShots, (Integer) result[3], speed + " m/s: the swept test missed");
            double p = (Double) result[4];
            double measured = 1.0 - (Integer) result[1] / (double) shots;
            // A binomial count: within 4 standard deviations sqrt(p(1-p)/n), plus 1/n for the
            // float rounding of a phase at the band's edge.
            double sigma = Math.sqrt(p * (1.0 - p) / shots);
            assertEquals(p, measured, 4.0 * sigma + 1.0 / shots,
                    speed + " m/s over " + shots + " shots");
            String hud = (String) result[5];
            assertTrue(hud.contains("swept test  :  shots " + sweptShots + "   hits "
                    + sweptShots + "   misses 0"), hud);
        }
    }
}

package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

/**
 * The stepped ball's hop against {@link HopCycle}'s fixed point {@code w* = K·g·h/(1+e)}: a
 * ball dropped 4 m in a world with the swept ground, the resting fix off, stepped for 60 s.
 */
class HopCycleTest {

    private static final float G = Gravity.STANDARD_G;
    private static final float H = 1f / 60f;
    private static final float DROP_METRES = 4f;
    private static final int STEPS_IN_60_S = 3600;

    /** Every impact: the step it came in, its fraction, its speed and the rebound. */
    private static final class Impacts implements ContactListener {
        final List<Long> steps = new ArrayList<>();
        final List<Float> fractions = new ArrayList<>();
        final List<Float> speeds = new ArrayList<>();
        final List<Float> rebounds = new ArrayList<>();

        @Override
        public void resolved(Contact contact, World world) {
            steps.add(world.getStepCount());
            fractions.add(contact.getFraction());
            speeds.add(contact.getApproachSpeed());
            rebounds.add(contact.getBodyA().getVelocity().y);
        }

        int count() {
            return steps.size();
        }

        long hopSteps(int fromEnd) {
            int i = count() - fromEnd;
            return steps.get(i) - steps.get(i - 1);
        }
    }

    @ParameterizedTest(name = "e = {0}: K = {1}")
    @CsvSource({"0.8, 4", "0.6, 3"})
    void impactSpeedsConvergeToTheFormulasFixedPoint(float e, int stepsPerHop) {
        Impacts impacts = drop(e, 0f);
        double fixedPoint = HopCycle.fixedPointSpeed(stepsPerHop, e, G, H);
        assertTrue(impacts.count() > 500, "impacts: " + impacts.count());
        for (int k = 1; k <= 50; ++k) {
            int i = impacts.count() - k;
            assertEquals(stepsPerHop, impacts.hopSteps(k), "hop " + i + " in steps");
            // After hundreds of hops the transient (a factor e a hop) is gone; what is left is
            // float round-off: a hop does about K + 2 float operations on speeds below 1 m/s
            // (ulp 6e-8), and the map contracts by e, so the error stays within
            // (K + 2)·6e-8/(1 − e) ≤ 2e-6 m/s (measured: 2e-7).
            assertEquals(fixedPoint, impacts.speeds.get(i), 2e-6, "impact " + i);
            // The fraction is a ratio of gaps of about w*·h·f ≈ 2e-3 m, each rounded to half an
            // ulp of the centre height (≈ 1e-8 m at y ≈ 0): 1e-4 covers it many times.
            assertEquals(HopCycle.impactFraction(stepsPerHop, e), impacts.fractions.get(i),
                    1e-4, "fraction of impact " + i);
        }
        assertTrue(stepsPerHop <= HopCycle.maxStepsPerHop(e));
    }

    @ParameterizedTest(name = "e = {0}")
    @CsvSource({"0.8, 4", "0.6, 3"})
    void cyclonesThresholdBelowTheFixedPointNeverStopsTheBall(float e, int stepsPerHop) {
        float threshold = ImpulseResponse.CYCLONE_THRESHOLD;
        Impacts impacts = drop(e, threshold);
        assertFalse(HopCycle.thresholdStops(threshold, stepsPerHop, e, G, H));
        long lastStep = impacts.steps.get(impacts.count() - 1);
        // Still hopping after 60 s: an impact within the last hop, and it bounced back.
        assertTrue(lastStep >= STEPS_IN_60_S - 1 - stepsPerHop, "last impact at step "
                + lastStep);
        assertTrue(impacts.rebounds.get(impacts.count() - 1) > 0f);
        for (int k = 1; k <= 50; ++k) {
            float speed = impacts.speeds.get(impacts.count() - k);
            assertTrue(speed > threshold, "impact " + k + " from the end: " + speed);
        }
    }

    @Test
    void aThresholdAboveTheFixedPointStopsTheBall() {
        float e = 0.8f;
        // Just above w*(4) = 0.36296 m/s, the hop a 4 m drop settles on.
        float threshold = 0.37f;
        assertTrue(HopCycle.thresholdStops(threshold, 4, e, G, H));
        Impacts impacts = drop(e, threshold);
        int last = impacts.count() - 1;
        assertEquals(0f, impacts.rebounds.get(last), "the last impact is inelastic");
        assertTrue(impacts.speeds.get(last) <= threshold);
        // At rest: each resting step closes at g·h < v_t and gets e = 0, a rebound of 0.
        for (int i = 0; i < impacts.count(); ++i) {
            if (impacts.speeds.get(i) <= threshold) {
                assertEquals(0f, impacts.rebounds.get(i), "impact " + i);
            }
        }
        assertTrue(impacts.steps.get(last) == STEPS_IN_60_S - 1, "resting contact every step");
    }

    @Test
    void theLongestHopAndItsFractionFollowTheFormula() {
        // (1+e)/(1−e): 9 for e = 0.8, 4 for 0.6, 1.86 for 0.3; f*(K_max) = 0 when it is whole.
        assertEquals(9, HopCycle.maxStepsPerHop(0.8f));
        assertEquals(4, HopCycle.maxStepsPerHop(0.6f));
        assertEquals(1, HopCycle.maxStepsPerHop(0.3f));
        assertEquals(1, HopCycle.maxStepsPerHop(0f));
        assertEquals(Integer.MAX_VALUE, HopCycle.maxStepsPerHop(1f));
        // 4·9.8/60/1.8 = 0.362962..., the figure; to double round-off of float inputs.
        assertEquals(4.0 * 9.8 / 60.0 / 1.8, HopCycle.fixedPointSpeed(4, 0.8f, G, H), 1e-7);
        assertEquals(0.5 - 4 * 0.2 / 3.6, HopCycle.impactFraction(4, 0.8f), 1e-7);
        assertThrows(IllegalArgumentException.class, () -> HopCycle.fixedPointSpeed(0, 0.8f,
                G, H));
        assertThrows(IllegalArgumentException.class, () -> HopCycle.fixedPointSpeed(4,
                Float.NaN, G, H));
    }

    @Test
    void withTheRestingFixTheSameDropComesToRest() {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, DROP_METRES, 0f), Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.8f, 0f, true), Detection.SWEPT));
        for (int n = 0; n < STEPS_IN_60_S; ++n) {
            world.step(H);
        }
        Body ball = world.getBody(0);
        assertEquals(0f, ball.getVelocity().y);
        assertEquals(0f, ball.getPosition().y);
    }

    /** Drop the ball 4 m with the resting fix off and step 60 s. */
    private static Impacts drop(float e, float threshold) {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, DROP_METRES, 0f), Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e, threshold, false),
                Detection.SWEPT));
        Impacts impacts = new Impacts();
        world.addContactListener(impacts);
        for (int n = 0; n < STEPS_IN_60_S; ++n) {
            world.step(H);
        }
        return impacts;
    }
}

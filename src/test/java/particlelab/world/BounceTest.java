package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * A ball bouncing on the ground against the ideal sequence (NUMERICS): apexes
 * {@code e^{2n}·h0}, impact speeds {@code eⁿ·√(2g·h0)}, impact times
 * {@code t0·(1 + 2e + … + 2e^{n−1})}, {@code t0 = √(2h0/g)}; and the resting contact.
 *
 * <p>Error bounds, from the step size. The stepped ball conserves
 * {@code (v − g·h/2)²/2 + g·y} exactly between contacts (the semi-implicit step's shadow
 * energy), so between the ground and the top its speed is off the true one by at most about
 * {@code g·h}; each flight adds at most that to the next impact speed (earlier errors are
 * scaled by e ≤ 1), so impact k is within {@code k·g·h}. The resting fix takes {@code e·g·h}
 * off each rebound, inside the same bound. An apex {@code v²/(2g)} then moves by
 * {@code v·Δv/g ≤ k·v·h}, plus at most {@code v·h} because only step ends are sampled: within
 * {@code (k + 1)·v_k·h}. Flight times {@code 2v/g} move by {@code 2k·h} each, so impact k is
 * within {@code (k² + 1)·h} of its ideal time.
 */
class BounceTest {

    private static final float G = Gravity.STANDARD_G;
    private static final float H = 1f / 60f;

    /** Impacts as the epilogue sees them, and the highest point after each. */
    private static final class Recorder implements ContactListener, StepListener {
        final List<Double> times = new ArrayList<>();
        final List<Float> speeds = new ArrayList<>();
        final List<Float> rebounds = new ArrayList<>();
        final List<Contact.Resolution> resolutions = new ArrayList<>();
        final List<Float> apexes = new ArrayList<>();
        float apex = Float.NEGATIVE_INFINITY;

        @Override
        public void resolved(Contact contact, World world) {
            if (!times.isEmpty()) {
                apexes.add(apex);
            }
            apex = Float.NEGATIVE_INFINITY;
            times.add(contact.getTimeSeconds());
            speeds.add(contact.getApproachSpeed());
            rebounds.add(contact.getBodyA().getVelocity().y);
            resolutions.add(contact.getResolution());
        }

        @Override
        public void afterStep(World world, float h) {
            apex = Math.max(apex, world.getBody(0).getPosition().y);
        }
    }

    private static World drop(float height, float radius, ImpulseResponse response,
            Detection detection, Recorder recorder) {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()), new Vector3f(0f, height, 0f),
                Vector3f.ZERO, 1f, radius);
        world.addRule(SurfaceRule.ground(response, detection));
        if (recorder != null) {
            world.addContactListener(recorder);
            world.addStepListener(recorder);
        }
        return world;
    }

    @Test
    void firstImpactIsHalfAStepEarlyAtTheSteppedSpeed() {
        // The samples lie on the parabola launched at -g·h/2, i.e. the true fall started h/2
        // early: impact at t0 - h/2, to within the chord's sag g·h²/8 over the speed, twice.
        float h0 = 10f;
        Recorder recorder = new Recorder();
        World world = drop(h0, 0f, new ImpulseResponse(0.8f), Detection.SWEPT, recorder);
        for (int i = 0; i < 120; ++i) {
            world.step(H);
        }
        double t0 = Math.sqrt(2.0 * h0 / G);
        double v0 = Math.sqrt(2.0 * G * h0);
        double t1 = recorder.times.get(0);
        assertEquals(t0 - H / 2.0, t1, G * H * H / (4.0 * v0));
        // The approach speed is exactly the Euler velocity of the step the impact fell in.
        int step = (int) Math.ceil(t1 / H);
        Particle alone = new Particle(new Vector3f(0f, h0, 0f), Vector3f.ZERO, 1f);
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        for (int i = 0; i < step; ++i) {
            gravity.step(alone, H);
        }
        assertEquals(-alone.velocity.y, recorder.speeds.get(0));
    }

    @ParameterizedTest
    @CsvSource({"SWEPT, false", "SWEPT, true", "OVERLAP, false", "OVERLAP, true"})
    void apexesSpeedsAndTimesFollowTheIdealSequenceWithinTheStepBounds(Detection detection,
            boolean restingFix) {
        float h0 = 10f;
        float e = 0.8f;
        Recorder recorder = new Recorder();
        World world = drop(h0, 0f, new ImpulseResponse(e, 0f, restingFix), detection,
                recorder);
        for (int i = 0; i < 600; ++i) {
            world.step(H);
        }
        double t0 = Math.sqrt(2.0 * h0 / G);
        double v0 = Math.sqrt(2.0 * G * h0);
        double idealTime = t0;
        int bounces = 6;
        assertTrue(recorder.times.size() > bounces, recorder.times.toString());
        for (int k = 1; k <= bounces; ++k) {
            double speed = v0 * Math.pow(e, k - 1);
            assertEquals(speed, recorder.speeds.get(k - 1), k * G * H, "impact speed " + k);
            assertEquals(idealTime, recorder.times.get(k - 1), (k * k + 1) * H, "time " + k);
            double rebound = e * speed;
            assertEquals(h0 * Math.pow(e, 2 * k), recorder.apexes.get(k - 1),
                    (k + 1) * rebound * H, "apex " + k);
            idealTime += 2.0 * t0 * Math.pow(e, k);
        }
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void apexErrorIsFirstOrderInTheStep(Detection detection) {
        // First order: a quarter of the step, about a quarter of the error; at least half.
        double coarse = worstApexError(detection, 1f / 60f);
        double fine = worstApexError(detection, 1f / 240f);
        assertTrue(fine < 0.5 * coarse, "h/4: " + fine + " m against " + coarse + " m");
    }

    @ParameterizedTest
    @CsvSource({"SWEPT, true, 0", "OVERLAP, true, 0", "SWEPT, false, 0.25",
        "OVERLAP, false, 0.25", "SWEPT, false, 1", "OVERLAP, true, 1"})
    void restingBallStaysExactlyStillWithoutSinking(Detection detection, boolean restingFix,
            float threshold) {
        float radius = 0.1f;
        World world = drop(radius, radius, new ImpulseResponse(0.5f, threshold, restingFix),
                detection, null);
        Body ball = world.getBody(0);
        for (int i = 0; i < 600; ++i) {
            world.step(H);
            assertEquals(radius, ball.getPosition().y, "step " + i);
            assertEquals(0f, ball.getVelocity().y, "step " + i);
        }
        // Closing at g·h each step (gravity's gift), never bounced back.
        ContactLog.Entry last = world.getLog().latest();
        assertEquals(G * H, last.getApproachSpeed(), 1e-6f);
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void droppedBallComesToRestAndThenStaysExactlyStill(Detection detection) {
        float radius = 0.1f;
        World world = drop(1f, radius, new ImpulseResponse(0.5f), detection, null);
        Body ball = world.getBody(0);
        // T = t0·(1+e)/(1-e) = 0.43·3 = 1.3 s; by 5 s it rests.
        for (int i = 0; i < 300; ++i) {
            world.step(H);
        }
        for (int i = 0; i < 300; ++i) {
            world.step(H);
            assertEquals(radius, ball.getPosition().y, "step " + i);
            assertEquals(0f, ball.getVelocity().y, "step " + i);
        }
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void withNeitherCureARestingBallHopsForEver(Detection detection) {
        // What the fixes are for: each step closes at g·h and plain restitution sends it back.
        float radius = 0.1f;
        World world = drop(radius, radius, new ImpulseResponse(0.5f, 0f, false), detection,
                null);
        Body ball = world.getBody(0);
        int moving = 0;
        for (int i = 0; i < 600; ++i) {
            world.step(H);
            if (ball.getVelocity().y != 0f) {
                ++moving;
            }
        }
        assertTrue(moving > 500, moving + " of 600 steps moving");
    }

    @Test
    void thresholdStopsTheBouncingAtTheFirstImpactBelowIt() {
        // h0 = 2 m, e = 0.5: ideal impact speeds 6.26, 3.13, 1.57, 0.78 m/s; a threshold of
        // 1 m/s stops the fourth. At h = 1/240 s each is within k·g·h <= 0.17 m/s of ideal,
        // far from the threshold either way.
        float step = 1f / 240f;
        float threshold = 1f;
        Recorder recorder = new Recorder();
        World world = drop(2f, 0f, new ImpulseResponse(0.5f, threshold, false), Detection.SWEPT,
                recorder);
        Body ball = world.getBody(0);
        for (int i = 0; i < 2400; ++i) {
            world.step(step);
        }
        int stopper = recorder.resolutions.indexOf(Contact.Resolution.BELOW_THRESHOLD);
        assertEquals(3, stopper, recorder.speeds.toString());
        for (int k = 0; k < stopper; ++k) {
            float speed = recorder.speeds.get(k);
            assertTrue(speed > threshold);
            assertEquals(Contact.Resolution.IMPULSE, recorder.resolutions.get(k));
            assertEquals(0.5f * speed, recorder.rebounds.get(k), 1e-6f * speed);
        }
        assertTrue(recorder.speeds.get(stopper) <= threshold);
        assertEquals(0f, recorder.rebounds.get(stopper));
        // Then only resting contacts, closing at g·h, below the threshold too: exactly still.
        for (int k = stopper + 1; k < recorder.speeds.size(); ++k) {
            assertEquals(G * step, recorder.speeds.get(k), 1e-6f);
            assertEquals(0f, recorder.rebounds.get(k));
        }
        assertEquals(0f, ball.getPosition().y);
    }

    private static double worstApexError(Detection detection, float step) {
        float h0 = 10f;
        float e = 0.8f;
        Recorder recorder = new Recorder();
        World world = drop(h0, 0f, new ImpulseResponse(e, 0f, false), detection, recorder);
        for (int i = 0; i < Math.round(10f / step); ++i) {
            world.step(step);
        }
        double worst = 0.0;
        for (int k = 1; k <= 5; ++k) {
            worst = Math.max(worst, Math.abs(recorder.apexes.get(k - 1) - h0 * Math.pow(e, 2 * k)));
        }
        return worst;
    }
}

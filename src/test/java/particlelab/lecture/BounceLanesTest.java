package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.Detection;
import particlelab.world.ImpulseResponse;
import particlelab.world.SurfaceRule;
import particlelab.world.World;

/**
 * Bounce's two lanes in plain JUnit ({@code new BounceDemo()}, {@code advancePhysics}): each
 * lane against its detection test alone, the apex ratios against the restitution law e², and
 * the resting fix's cost e·g·h.
 */
class BounceLanesTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    private static final float G = Gravity.STANDARD_G;
    private static final Detection[] TESTS = {Detection.OVERLAP, Detection.SWEPT};

    /**
     * Each lane's ball, stepped in the demo's world beside the other lane's, moves bit for bit
     * as the same ball alone in a world with only its own ground rule: the lanes share the
     * world and the clock but nothing else.
     */
    @ParameterizedTest
    @CsvSource({"9, 2, false", "8, 1, false", "5, 0, true", "10, 0, false", "8, 2, true"})
    void eachLaneMovesExactlyAsItsDetectionTestAlone(int eTenths, int preset,
            boolean restingFix) {
        BounceDemo bounce = new BounceDemo();
        bounce.configure(eTenths / 10f, preset, restingFix, Detection.SWEPT);
        World[] alone = new World[TESTS.length];
        Body[] aloneBalls = new Body[TESTS.length];
        BounceRecorder[] aloneRecorders = new BounceRecorder[TESTS.length];
        for (int i = 0; i < TESTS.length; ++i) {
            alone[i] = new World();
            Body ball = bounce.getBall(TESTS[i]);
            aloneBalls[i] = alone[i].addBody(new ParticleIntegrator(new Gravity()),
                    ball.getPosition().clone(), Vector3f.ZERO, BounceDemo.MASS_KG,
                    BounceDemo.RADIUS);
            alone[i].addRule(SurfaceRule.ground(new ImpulseResponse(eTenths / 10f,
                    BounceDemo.THRESHOLDS[preset], restingFix), TESTS[i]));
            aloneRecorders[i] = new BounceRecorder(aloneBalls[i]);
            alone[i].addContactListener(aloneRecorders[i]);
            alone[i].addStepListener(aloneRecorders[i]);
        }
        World world = bounce.getWorld();
        for (int frame = 0; frame < 1200; ++frame) {
            bounce.getRun().advancePhysics(H);
            for (int i = 0; i < TESTS.length; ++i) {
                while (alone[i].getStepCount() < world.getStepCount()) {
                    alone[i].step(bounce.getClock().getStepSeconds());
                }
                Body ball = bounce.getBall(TESTS[i]);
                // Bit for bit: the same operations on the same floats, so tolerance 0.
                assertEquals(aloneBalls[i].getPosition().y, ball.getPosition().y, 0f,
                        TESTS[i] + " y at step " + world.getStepCount());
                assertEquals(aloneBalls[i].getVelocity().y, ball.getVelocity().y, 0f,
                        TESTS[i] + " V_y at step " + world.getStepCount());
            }
        }
        for (int i = 0; i < TESTS.length; ++i) {
            BounceRecorder lane = bounce.getRecorder(TESTS[i]);
            assertEquals(aloneRecorders[i].countImpacts(), lane.countImpacts(), "impacts");
            assertTrue(lane.countImpacts() >= 2, TESTS[i] + " impacts " + lane.countImpacts());
            assertEquals(aloneRecorders[i].countApexes(), lane.countApexes(), "apexes");
            // every apex the recorder still keeps (the latest MAX_APEXES)
            for (int n = lane.firstKeptApex(); n < lane.countApexes(); ++n) {
                assertEquals(aloneRecorders[i].getApex(n), lane.getApex(n), 0f, "apex " + n);
            }
        }
    }

    /**
     * The defaults (e = 0.9, fix off, Box2D's threshold) show the restitution law: each apex
     * is e² times the one before (h_0 the drop), to within the step's error. The stepped
     * apex is off the continuous flight's apex by O(h) for semi-implicit Euler: the swept
     * test meets the ground a fraction f into a step and the top step sample falls anywhere
     * in the last step, which leaves the apex within about half a step's travel at the
     * rebound speed u = e·w, u·h/2, a relative error of g·h/u on an apex u²/(2g); the overlap
     * test finds the impact up to a whole step late and pushes the ball out, u·h, so 2·g·h/u.
     * A ratio of two apexes has the sum of their two relative errors, times e². Checked for
     * the first 6 ratios, the impacts above 3 m/s (the threshold, 1 m/s, stops the ball
     * later); the rebound speeds are the ideal e^n·√(2·g·h0), which the stepped ones follow
     * to a few per cent (BounceTest).
     */
    @Test
    void theDefaultApexRatiosReadESquaredWithinTheStepsError() {
        BounceDemo bounce = new BounceDemo();
        for (int frame = 0; frame < 900; ++frame) {
            bounce.getRun().advancePhysics(H);
        }
        double e = bounce.getRestitution();
        assertEquals(0.9, e, 1e-6, "the default e");
        double impact = Math.sqrt(2.0 * G * BounceDemo.DROP_HEIGHT);
        for (Detection test : TESTS) {
            BounceRecorder lane = bounce.getRecorder(test);
            assertTrue(lane.countApexes() >= 6, test + " apexes " + lane.countApexes());
            double perRebound = test == Detection.SWEPT ? 1.0 : 2.0;
            double previousError = 0.0;
            double previous = BounceDemo.DROP_HEIGHT;
            for (int n = 1; n <= 6; ++n) {
                double rebound = Math.pow(e, n) * impact;
                double error = perRebound * G * H / rebound;
                double apex = lane.getApex(n - 1);
                assertEquals(e * e, apex / previous, e * e * (error + previousError),
                        test + " ratio h_" + n + "/h_" + (n - 1));
                previous = apex;
                previousError = error;
            }
        }
    }

    /**
     * With the resting fix every rebound is e·(w − g·h): the fix takes e·g·h off the e·w of
     * plain restitution, as the HUD says; without it the rebound is e·w. Float rounding of
     * speeds below 10 m/s: a few ulps, far below 1e-5 m/s.
     */
    @ParameterizedTest
    @CsvSource({"true", "false"})
    void theRestingFixTakesEGHOffEveryRebound(boolean restingFix) {
        BounceDemo bounce = new BounceDemo();
        bounce.configure(0.9f, 0, restingFix, Detection.SWEPT);
        float e = bounce.getRestitution();
        List<float[]> impacts = new ArrayList<>();
        bounce.getWorld().addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World world) {
                float rebound = contact.getBodyA().getVelocity().dot(contact.getNormal());
                impacts.add(new float[] {contact.getApproachSpeed(), rebound});
            }
        });
        for (int frame = 0; frame < 480; ++frame) {
            bounce.getRun().advancePhysics(H);
        }
        assertTrue(impacts.size() >= 6, "impacts " + impacts.size());
        float cost = e * G * H;
        for (float[] impact : impacts) {
            float plain = e * impact[0];
            assertEquals(restingFix ? cost : 0f, plain - impact[1], 1e-5f,
                    "impact at " + impact[0] + " m/s, rebound " + impact[1]);
        }
        String hud = bounce.getWindow().formatHud(new StringBuilder()).toString();
        StringBuilder named = new StringBuilder(restingFix
                ? "resting fix on: rebound e v - e g h, e g h = "
                : "resting fix off: rebound e v (on: less e g h = ");
        TextFormat.appendFixed(named, cost, 3);
        assertTrue(hud.contains(named), named + " in\n" + hud);
        BounceRecorder swept = bounce.getRecorder(Detection.SWEPT);
        StringBuilder last = new StringBuilder("   last impact ");
        TextFormat.appendFixed(last, swept.getLastImpactSpeed(), 3).append(", rebound ");
        TextFormat.appendFixed(last, swept.getLastReboundSpeed(), 3).append(" m/s\n");
        assertTrue(hud.contains(last), last + " in\n" + hud);
    }

    /** The HUD's table: the lane chosen, its apexes from impact 1 with their ratios. */
    @Test
    void theHudTableListsTheChosenLanesApexesAndRatios() {
        BounceDemo bounce = new BounceDemo();
        bounce.configure(0.9f, 2, false, Detection.OVERLAP);
        for (int frame = 0; frame < 300; ++frame) {
            bounce.getRun().advancePhysics(H);
        }
        String hud = bounce.getWindow().formatHud(new StringBuilder()).toString();
        BounceRecorder overlap = bounce.getRecorder(Detection.OVERLAP);
        assertTrue(overlap.countApexes() >= 2, "apexes " + overlap.countApexes());
        StringBuilder rows = new StringBuilder("overlap lane, h_n (h_n/h_(n-1)):  1: ");
        TextFormat.appendFixed(rows, overlap.getApex(0), 3).append(" (");
        TextFormat.appendFixed(rows, overlap.getApex(0) / BounceDemo.DROP_HEIGHT, 2)
                .append(")  2: ");
        TextFormat.appendFixed(rows, overlap.getApex(1), 3).append(" (");
        TextFormat.appendFixed(rows, overlap.getApex(1) / overlap.getApex(0), 2).append(')');
        assertTrue(hud.contains(rows), rows + " in\n" + hud);
        assertTrue(hud.contains("e = 0.9, e^2 = 0.81   threshold 1.00 m/s (Box2D/Jolt)"), hud);
        assertTrue(hud.contains("apex, energy: overlap "), hud);
        assertTrue(hud.contains(" J, still bouncing   swept "), hud);
    }

    /**
     * At e = 1 the overlap lane's apexes sit a constant 0.1045 m below h0: no drift that
     * grows. From rest the semi-implicit step falls g·h²·n(n+1)/2 in n steps, so the lowest
     * point first goes below the ground at step N = 54; the overlap test pushes the ball out
     * onto the ground and turns V = −N·g·h round, and the climb from y = 0 at N·g·h rises
     * g·h²·N(N−1)/2 = 3.8955 m, its steps mirroring the fall's; the next fall from that apex
     * lands on the ground at step N − 1 exactly and overlaps it at step N again, so every
     * bounce repeats the first. The HUD's line says "apex - h0" (not a drift).
     */
    @Test
    void atEOneTheOverlapLanesApexesSitAConstantOffsetBelowTheDrop() {
        BounceDemo bounce = new BounceDemo();
        bounce.configure(1f, 2, false, Detection.SWEPT);
        BounceRecorder overlap = bounce.getRecorder(Detection.OVERLAP);
        for (int frame = 0; frame < 3600 && overlap.countApexes() < 20; ++frame) {
            bounce.getRun().advancePhysics(H);
        }
        int n = 0;
        while (BounceDemo.DROP_HEIGHT - G * H * H * n * (n + 1) / 2.0 >= 0.0) {
            ++n;
        }
        assertEquals(54, n, "first overlap step");
        double offset = G * H * H * n * (n - 1) / 2.0 - BounceDemo.DROP_HEIGHT;
        assertEquals(-0.1045, offset, 5e-5, "the figure the pages give");
        assertTrue(overlap.countApexes() >= 20, "apexes " + overlap.countApexes());
        for (int i = 0; i < overlap.countApexes(); ++i) {
            // about 110 float additions of metres up to 4 (half an ulp, 2.4e-7, each) per
            // bounce, the bounce repeating the first: 1e-4 m bounds the round-off
            assertEquals(offset, overlap.getApex(i) - BounceDemo.DROP_HEIGHT, 1e-4,
                    "apex " + (i + 1));
        }
        String hud = bounce.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("e = 1, apex - h0 after "), hud);
        assertTrue(hud.contains("overlap test -0.1045 m"), hud);
    }
}

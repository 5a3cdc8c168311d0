package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.reference.ExactPath;
import particlelab.demo.DemoParticle;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * Demo 18, the spring pull, stepped in plain JUnit: its stability limits against a bisection
 * on the demo's own measured swing, and its closed form against the exact ghost's path.
 */
class SpringDemoTest {

    /** Steps per stability trial (as physics.ParticleIntegratorStabilityTest's springs). */
    private static final int TRIAL_STEPS = 2000;
    /** ω² = k/m and λ = c/m at the defaults (1/s², 1/s). */
    private static final double OMEGA_SQUARED = SpringDemo.SPRING_K;
    private static final double LAMBDA = SpringDemo.DAMPING_C;

    @Test
    void hudLimitsAreTwoOverOmegaAndTheDampedOscillatorsLimit() {
        SpringDemo spring = new SpringDemo();
        // ω = 12 /s: 2/ω = 1/6 s; damped 4/(λ + √(λ² + 4ω²)) = 4/(2 + √580) = 0.15337 s.
        // Both come from one float division of doubles: within 1e-6 s.
        assertEquals(2.0 / Math.sqrt(OMEGA_SQUARED), spring.stableStepLimit(0), 1e-6);
        assertEquals(4.0 / (LAMBDA + Math.sqrt(LAMBDA * LAMBDA + 4.0 * OMEGA_SQUARED)),
                spring.stableStepLimit(1), 1e-6);
    }

    @Test
    void stabilityLimitsMatchABisectionOnTheDemosMeasuredSwing() {
        double[] theory = {new SpringDemo().stableStepLimit(0),
            new SpringDemo().stableStepLimit(1)};
        for (int mass = 0; mass < 2; ++mass) {
            // The bracket is the panel's whole range of h, 1/240 s to 1/5 s, not the theory.
            double stable = 1.0 / 240.0;
            double unstable = 0.2;
            assertTrue(isStable(mass, stable) && !isStable(mass, unstable));
            while (unstable - stable > 1e-5) {
                double mid = 0.5 * (stable + unstable);
                if (isStable(mass, mid)) {
                    stable = mid;
                } else {
                    unstable = mid;
                }
            }
            // 2000 steps tell growth from decay to about 1e-4 relative near the limit
            // (|z| − 1 ≈ 1e-4 per step grows the swing by 20 %), and the bracket is 1e-5 s
            // (6e-5 relative): 5e-4 holds both (measured 1.7e-5 undamped, 4.5e-5 damped).
            assertEquals(theory[mass], stable, 5e-4 * theory[mass], "mass " + mass);
        }
    }

    @Test
    void closedFormIsTheExactGhostsPath() {
        SpringDemo spring = new SpringDemo();
        for (int mass = 0; mass < 2; ++mass) {
            DemoParticle demoParticle = spring.getParticles().get(mass);
            Particle launch = demoParticle.getParticle();
            ExactPath ghost = new ExactPath(demoParticle.getIntegrator());
            ghost.start(launch.position, launch.velocity, launch.getMass(), false);
            for (int n = 1; n <= 120; ++n) {
                ghost.advance(1.0 / 60.0);
                // The ghost's RK4 takes its accelerations in float (6e-8 relative), which
                // bounds its error by 6e-8·|a|·t²/2 with |a| ≤ ω²·3 m = 432 m/s²: 5.2e-5 m at
                // t = 2 s. Its substeps' own error (about h⁴) is far below that.
                assertEquals(spring.exactHeight(mass, n / 60.0), ghost.getPosition(1), 1e-4,
                        "mass " + mass + " at step " + n);
            }
        }
    }

    @Test
    void closedFormStartsAtTheLaunchAtRestAndSwingsAboutTheRestHeight() {
        SpringDemo spring = new SpringDemo();
        float startY = spring.getParticles().get(0).getParticle().position.y;
        double restY = SpringDemo.ANCHOR_Y - (double) Gravity.STANDARD_G / SpringDemo.SPRING_K;
        double halfPeriod = Math.PI / Math.sqrt(OMEGA_SQUARED);
        // cos 0 = 1; the damped form's sine term vanishes at t = 0 too (to double rounding).
        assertEquals(startY, spring.exactHeight(0, 0.0), 1e-12);
        assertEquals(startY, spring.exactHeight(1, 0.0), 1e-12);
        // Undamped, half a period later the mass is as far above y_eq as it started below.
        assertEquals(2.0 * restY - startY, spring.exactHeight(0, halfPeriod), 1e-9);
        // Damped, it settles at y_eq: e^(−λt/2) = e^-30 at t = 30 s.
        assertEquals(restY, spring.exactHeight(1, 30.0), 1e-9);
    }

    @Test
    void springConstantReachesBothSpringsAtTheNextReset() {
        SpringDemo spring = new SpringDemo();
        spring.getParameters().set("k", 400f);
        spring.restart();
        // ω = 20 /s: 2/ω = 0.1 s (one float division: 1e-7).
        assertEquals(0.1, spring.stableStepLimit(0), 1e-7);
        assertTrue(spring.stableStepLimit(1) < 0.1f);
    }

    /**
     * Run the demo at a fixed step h and tell whether one mass's swing
     * {@code sqrt(ω²·(y − y_eq)² + vy²)} shrank over {@value #TRIAL_STEPS} steps (damped) or
     * stayed within 1000 times its start (undamped: the step keeps a modified energy, so the
     * swing is bounded, by {@code 1/sqrt(1 − ωh/2)}, which is 1000 only within 1e-6 of the
     * limit; beyond it the swing grows by e^50 or more in these steps), and that nothing blew
     * up (a blow-up resets the demo, which would hide the growth).
     */
    private static boolean isStable(int mass, double stepSeconds) {
        SpringDemo spring = new SpringDemo();
        spring.getParameters().set("h", (float) stepSeconds);
        if (mass == 0) {
            // The damped mass's smaller limit would blow it up, and the reset would restart
            // both: for the undamped trial, undamp the other spring too.
            spring.getParameters().set("c", 0f);
            spring.restart();
        }
        DemoParticle demoParticle = spring.getParticles().get(mass);
        Particle particle = demoParticle.getParticle();
        ParticleIntegrator integrator = demoParticle.getIntegrator();
        double restY = SpringDemo.ANCHOR_Y - (double) Gravity.STANDARD_G / SpringDemo.SPRING_K;
        double start = swing(particle, restY);
        for (int n = 0; n < TRIAL_STEPS; ++n) {
            spring.getRun().advancePhysics((float) stepSeconds);
        }
        if (spring.getRun().countBlowUps() > 0) {
            return false;
        }
        assertEquals(TRIAL_STEPS * (float) stepSeconds, spring.getClock().getSimulatedSeconds(),
                1e-3 * TRIAL_STEPS * stepSeconds, "one step per frame");
        double end = swing(particle, restY);
        boolean damped = integrator.dampingRate(particle) > 0f;
        return damped ? end < start : end < 1000.0 * start;
    }

    private static double swing(Particle particle, double restY) {
        double offset = particle.position.y - restY;
        return Math.sqrt(OMEGA_SQUARED * offset * offset
                + (double) particle.velocity.y * particle.velocity.y);
    }
}

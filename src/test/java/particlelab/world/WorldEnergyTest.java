package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.physics.EnergyLedger;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;

/**
 * A world's energy ledger at impacts: the loss is {@code ½·μ·(1−e²)·v_n²} per impact, a
 * stick takes the whole {@code ½m|V|²}, a kinematic paddle's push is the script's work.
 *
 * <p>Tolerances: velocities are floats (2^-24 relative per rounding, a handful per
 * component), so energies are compared to 1e-6 of their scale, as ImpulseResponseTest does.
 */
class WorldEnergyTest {

    private static final float H = 1f / 60f;

    @ParameterizedTest
    @EnumSource(Detection.class)
    void twoBallsLoseHalfMuOneMinusESquaredVnSquared(Detection detection) {
        // m = 2 and 1 kg at 3 and −1 m/s, e = 0.5: μ = 2/3, v_n = 4, loss = ½·⅔·0.75·16 = 4 J
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        world.addBody(none, new Vector3f(), new Vector3f(3f, 0f, 0f), 2f, 0.5f);
        world.addBody(none, new Vector3f(3f, 0f, 0f), new Vector3f(-1f, 0f, 0f), 1f, 0.5f);
        world.addRule(new SphereRule(new ImpulseResponse(0.5f, 0f, false), detection));
        WorldEnergy energy = new WorldEnergy(world);
        for (int i = 0; i < 120; ++i) {
            world.step(H);
        }
        EnergyLedger ledger = energy.getLedger();
        assertEquals(4.0, ledger.getImpactLossJoules(), 1e-6 * 9.5);
        assertEquals(0.0, ledger.getScriptWorkJoules(), 0.0);
        // no forces, no potential: nothing is left for the step to create
        assertEquals(0.0, ledger.getNumericalJoules(), 1e-6 * 9.5);
        assertEquals(9.5 - 4.0, ledger.getKineticJoules(), 1e-6 * 9.5);
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void aKinematicPaddlesPushIsScriptWork(Detection detection) {
        // Paddle at u = 2 m/s, ball (1 kg) at −3 m/s, e = 0.5: the ball leaves at 4.5 m/s.
        // In the paddle's frame the ball loses ½·1·(1 − 0.25)·5² = 9.375 J; the paddle's
        // work is j·u = 7.5 N·s · 2 m/s = 15 J; the ball's energy 4.5 J → 10.125 J.
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        Body paddle = world.addBody(none, new Vector3f(), new Vector3f(2f, 0f, 0f), 5f, 0.5f);
        paddle.setKinematic(true);
        world.addBody(none, new Vector3f(3f, 0f, 0f), new Vector3f(-3f, 0f, 0f), 1f, 0.25f);
        world.addRule(new SphereRule(new ImpulseResponse(0.5f, 0f, false), detection));
        WorldEnergy energy = new WorldEnergy(world);
        assertEquals(EnergyLedger.KINETIC | EnergyLedger.IMPACT | EnergyLedger.SCRIPT,
                energy.getColumns());
        for (int i = 0; i < 60; ++i) {
            world.step(H);
        }
        EnergyLedger ledger = energy.getLedger();
        assertEquals(9.375, ledger.getImpactLossJoules(), 1e-6 * 25.0);
        assertEquals(15.0, ledger.getScriptWorkJoules(), 1e-6 * 25.0);
        assertEquals(0.0, ledger.getNumericalJoules(), 1e-6 * 25.0);
    }

    @Test
    void aBallOnTheGroundLosesHalfMOneMinusESquaredVnSquaredAtEveryBounce() {
        float e = 0.8f;
        float mass = 0.5f;
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, 4f, 0f), new Vector3f(1f, 0f, 0f), mass, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e, 0f, false), Detection.SWEPT));
        double[] expected = new double[1];
        int[] impacts = new int[1];
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World stepping) {
                double vn = contact.getApproachSpeed();
                expected[0] += 0.5 * mass * (1.0 - (double) e * e) * vn * vn;
                ++impacts[0];
            }
        });
        WorldEnergy energy = new WorldEnergy(world);
        for (int i = 0; i < 300; ++i) {
            world.step(H);
        }
        assertTrue(impacts[0] >= 3, "bounces: " + impacts[0]);
        // the approach speed and the velocity are the same floats; 1e-6 of the ½m·v² of 4 J
        assertEquals(expected[0], energy.getLedger().getImpactLossJoules(), 1e-6 * 20.0);
        assertTrue(ball.getPosition().y >= 0f);
    }

    @Test
    void theGroundStopTakesTheWholeKineticEnergyAsAnImpact() {
        float mass = 2f;
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()), new Vector3f(0f, 1f, 0f),
                new Vector3f(3f, 2f, 0f), mass, 0f);
        world.addRule(SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT));
        double[] expected = new double[1];
        world.addContactListener(new ContactListener() {
            @Override
            public boolean accept(Contact contact, World stepping) {
                // the body stands at the contact with the step's velocity V'
                expected[0] = 0.5 * mass * contact.getBodyA().getVelocity().lengthSquared();
                return true;
            }
        });
        WorldEnergy energy = new WorldEnergy(world);
        for (int i = 0; i < 120; ++i) {
            world.step(H);
        }
        EnergyLedger ledger = energy.getLedger();
        assertTrue(expected[0] > 0.0);
        assertEquals(expected[0], ledger.getImpactLossJoules(), 1e-6 * expected[0]);
        assertEquals(0.0, ledger.getKineticJoules(), 0.0);
        double sides = ledger.getStartJoules() - ledger.getImpactLossJoules()
                + ledger.getNumericalJoules();
        assertEquals(ledger.total(), sides, 1e-12);
    }

    @Test
    void aLaunchBetweenStepsMovesTheStartNotTheNumericalColumn() {
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(), new Vector3f(),
                new Vector3f(1f, 0f, 0f), 2f, 0f);
        WorldEnergy energy = new WorldEnergy(world);
        world.step(H);
        ball.getVelocity().set(3f, 0f, 0f);
        world.step(H);
        EnergyLedger ledger = energy.getLedger();
        // 1 J at the start, 9 J after the push: uniform motion creates nothing
        assertEquals(9.0, ledger.getStartJoules(), 1e-12);
        assertEquals(0.0, ledger.getNumericalJoules(), 1e-12);
    }

    @Test
    void keepingTheLedgerAllocatesNothing() {
        World world = new World();
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        for (int i = 0; i < 8; ++i) {
            world.addBody(gravity, new Vector3f(i, 3f + i, 0f), new Vector3f(1f, 2f, 0f), 1f,
                    0.2f);
        }
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.7f), Detection.SWEPT));
        world.addRule(new SphereRule(new ImpulseResponse(0.7f), Detection.OVERLAP));
        new WorldEnergy(world);
        Allocations.assertAllocatesNothing("500 steps with the ledger", () -> {
            for (int i = 0; i < 500; ++i) {
                world.step(H);
            }
        });
    }

    /**
     * Issue 32 §4: finding each body's start costs one look per body and step when the world
     * keeps its order, so a step is O(bodies), not O(bodies²) (a scan from the start of the
     * list for each body looked at n(n+1)/2 = 500500 bodies a step here). Counted, not
     * timed. Bodies destroyed mid-step and one added between steps keep the ledger adding up.
     */
    @Test
    void findingTheBodiesStartsCostsOneLookPerBody() {
        int bodies = 1000;
        int steps = 3;
        World world = new World();
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        Body[] made = new Body[bodies];
        for (int i = 0; i < bodies; ++i) {
            made[i] = world.addBody(gravity, new Vector3f(i, 10f, 0f), new Vector3f(1f, 2f, 0f),
                    1f, 0.2f);
        }
        WorldEnergy energy = new WorldEnergy(world);
        for (int s = 0; s < steps; ++s) {
            world.step(H);
        }
        assertEquals(steps * bodies, energy.countSearchSteps(), "one look per body and step");

        // destroyed in a step's epilogue, every seventh: the rest still one look each, and the
        // columns still add up (the start moves by what left)
        world.addStepListener(new StepListener() {
            private boolean done;

            @Override
            public void beforeStep(World stepping, float stepSeconds) {
                if (!done) {
                    for (int i = 0; i < bodies; i += 7) {
                        stepping.destroy(made[i]);
                    }
                    done = true;
                }
            }
        });
        long before = energy.countSearchSteps();
        world.step(H);
        world.addBody(gravity, new Vector3f(0f, 5f, 0f), new Vector3f(), 1f, 0.2f);
        world.step(H);
        long looks = energy.countSearchSteps() - before;
        assertTrue(looks <= 2L * 2 * bodies, looks + " looks for two steps of " + bodies);
        EnergyLedger ledger = energy.getLedger();
        double state = ledger.getColumn(0) + ledger.getColumn(1);
        double flows = ledger.getStartJoules() + ledger.getNumericalJoules();
        // double sums of about 1e5 J: 1e-9 relative is far above their rounding
        assertEquals(state, flows, 1e-9 * Math.abs(state));
    }
}

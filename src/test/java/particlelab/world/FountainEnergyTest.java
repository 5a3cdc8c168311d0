package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.physics.EnergyLedger;
import particlelab.physics.LinearDrag;

/**
 * The fountain's energy ledger (issue 32): its packed particles' kinetic and potential
 * energy, what the nozzle, the launcher and the bursts bring in, what leaves with the
 * particles going back to the pool, drag, the ground's impacts and the numerical rest.
 * Plain JUnit: the fountain stepped directly.
 */
class FountainEnergyTest {

    /** The lecture's step (s). */
    private static final float H = 1f / 60f;

    @Test
    void theColumnsAddUpAtEveryStepThroughBouncesBurstsAndRecycling() {
        Fountain fountain = new Fountain(20_000);
        FountainEnergy energy = new FountainEnergy(fountain);
        fountain.setEnergy(energy);
        EnergyLedger ledger = energy.getLedger();
        assertEquals(0.0, ledger.getStartJoules(), 0.0, "an empty pool has no energy");
        // 12 s: water lands from 2.5 s on, shells burst from 1.8 s, stars and sparks burn
        // out, drops come to rest and go back to the pool
        int steps = 720;
        double worst = 0.0;
        for (int s = 1; s <= steps; ++s) {
            fountain.step(H);
            double residual = ledger.getKineticJoules() + ledger.getPotentialJoules()
                    - (ledger.getStartJoules() + ledger.getEmittedJoules()
                    - ledger.getRemovedJoules() - ledger.getDragLossJoules()
                    - ledger.getImpactLossJoules() + ledger.getNumericalJoules());
            double scale = Math.max(Math.max(ledger.getEmittedJoules(),
                    ledger.getRemovedJoules()), ledger.getKineticJoules()
                    + Math.abs(ledger.getPotentialJoules()));
            worst = Math.max(worst, Math.abs(residual) / Math.max(scale, 1e-300));
            // Every column is a double sum of floats converted exactly; the equation adds
            // eight doubles of at most `scale`, so its rounding is a few ulp(scale), 2^-52
            // each: 1e-14 of the largest column is 45 of them. (The float state's own
            // rounding is no residual: it is what the numerical column measures.)
            assertEquals(0.0, residual, 1e-14 * scale, "the columns at step " + s);
            // kinetic and potential: the particles in flight, summed apart here
            double kinetic = 0.0;
            double potential = 0.0;
            float[] p = fountain.getPositions();
            float[] v = fountain.getVelocities();
            int n = fountain.getCapacity();
            for (int i = 0; i < fountain.countLive(); ++i) {
                kinetic += 0.5 * Fountain.MASS_KG * ((double) v[i] * v[i]
                        + (double) v[n + i] * v[n + i] + (double) v[2 * n + i] * v[2 * n + i]);
                potential += (double) Fountain.MASS_KG * 9.8f * p[n + i];
            }
            // the same terms, summed in another order: 1e-12 relative is far above the
            // 2e-16 per addition of at most 2·10^4 of them
            assertEquals(kinetic, ledger.getKineticJoules(), 1e-12 * kinetic, "K at " + s);
            assertEquals(potential, ledger.getPotentialJoules(), 1e-12 * potential,
                    "U at " + s);
        }
        // every flow took part, each with the sign it must have
        assertTrue(ledger.getEmittedJoules() > 0.0, "emitted " + ledger.getEmittedJoules());
        assertTrue(ledger.getRemovedJoules() > 0.0, "removed " + ledger.getRemovedJoules());
        assertTrue(ledger.getDragLossJoules() > 0.0, "drag " + ledger.getDragLossJoules());
        assertTrue(ledger.getImpactLossJoules() > 0.0, "impact "
                + ledger.getImpactLossJoules());
        assertTrue(fountain.countRecycledResting() > 0 && fountain.countBursts() > 0,
                "the run saw drops at rest and bursts");
        System.out.printf("fountain ledger after %d steps: K %.4f U %.4f emitted %.4f removed"
                + " %.4f drag %.4f impact %.4f numerical %.6f J; worst residual %.2g%n",
                steps, ledger.getKineticJoules(), ledger.getPotentialJoules(),
                ledger.getEmittedJoules(), ledger.getRemovedJoules(),
                ledger.getDragLossJoules(), ledger.getImpactLossJoules(),
                ledger.getNumericalJoules(), worst);
    }

    @Test
    void keepingTheLedgerAllocatesNothing() {
        Fountain fountain = new Fountain(5_000);
        fountain.setEnergy(new FountainEnergy(fountain));
        // warm up past the first bounces and bursts, then 300 steps more of all of it
        for (int s = 0; s < 200; ++s) {
            fountain.step(H);
        }
        Allocations.assertAllocatesNothing("300 fountain steps with the ledger", () -> {
            for (int s = 0; s < 300; ++s) {
                fountain.step(H);
            }
        });
    }

    @Test
    void keepingTheLedgerChangesNoBitOfTheFountain() {
        Fountain plain = new Fountain(5_000);
        Fountain kept = new Fountain(5_000);
        kept.setEnergy(new FountainEnergy(kept));
        for (int s = 0; s < 400; ++s) {
            plain.step(H);
            kept.step(H);
        }
        assertEquals(plain.countLive(), kept.countLive());
        assertArrayEquals(plain.getPositions(), kept.getPositions());
        assertArrayEquals(plain.getVelocities(), kept.getVelocities());
    }

    /**
     * Gravity alone (drag switched off, no fireworks, 1.5 s: no drop is back on the ground
     * before 2.5 s, so none bounces or leaves and no slot moves), the lecture's step: each
     * particle's numerical energy is {@code m·g·h·(vy − vy0)/2} (the step keeps
     * {@code ½(vy − g·h/2)² + g·y}), vy0 its vy when the nozzle made it; the ledger's
     * numerical column is their sum, to the floats' rounding.
     */
    @Test
    void gravityAloneNumericalIsTheClosedFormSummedOverParticles() {
        Fountain fountain = new Fountain(10_000);
        fountain.setFireworks(false);
        ((LinearDrag) fountain.getIntegrator().getForce(1)).setCoefficient(0f);
        fountain.setEnergy(new FountainEnergy(fountain));
        EnergyLedger ledger = fountain.getEnergy().getLedger();
        int n = fountain.getCapacity();
        float[] p = fountain.getPositions();
        float[] v = fountain.getVelocities();
        float[] bornVy = new float[n];
        float[] stepVy = new float[n];
        double m = Fountain.MASS_KG;
        double g = 9.8f;
        double bound = 0.0;
        int live = 0;
        for (int s = 0; s < 90; ++s) {
            System.arraycopy(v, n, stepVy, 0, live);
            fountain.step(H);
            for (int i = 0; i < live; ++i) {
                float vy0 = stepVy[i];
                float vy1 = v[n + i];
                float y1 = p[n + i];
                // The step's roundings against the exact identity: vy' = vy − g·h off by up
                // to ulp(vy')/2 and g·h itself by ulp(g·h)/2, each times the mean of
                // m·vy and m·vy' (ΔK = ½m·Δvy·(vy + vy')); y' = y + h·vy' off by up to
                // ulp(h·vy')/2 + ulp(y')/2, times m·g. Twice each, to spare any doubt about
                // the batch's order of the two roundings.
                bound += m * (0.5 * (Math.abs(vy0) + Math.abs(vy1))
                        * (Math.ulp(vy1) + Math.ulp((float) (g * H)))
                        + g * (Math.ulp(y1) + Math.ulp(H * vy1)));
            }
            for (int i = live; i < fountain.countLive(); ++i) {
                bornVy[i] = v[n + i];
            }
            live = fountain.countLive();
        }
        assertEquals(live, fountain.countLive(Fountain.WATER), "water alone");
        assertEquals(0L, fountain.countRecycledResting() + fountain.countRecycledLeaving());
        double closedForm = 0.0;
        for (int i = 0; i < live; ++i) {
            closedForm += 0.5 * m * g * H * ((double) v[n + i] - bornVy[i]);
        }
        double error = ledger.getNumericalJoules() - closedForm;
        System.out.printf("gravity alone, %d drops: numerical %.9f J, closed form %.9f J,"
                + " difference %.3g J, bound %.3g J%n", live, ledger.getNumericalJoules(),
                closedForm, error, bound);
        assertTrue(bound < 0.01 * Math.abs(closedForm), "the bound leaves the test teeth");
        assertEquals(closedForm, ledger.getNumericalJoules(), bound);
        assertEquals(0.0, ledger.getDragLossJoules(), 0.0, "b = 0");
        assertEquals(0.0, ledger.getImpactLossJoules() + ledger.getRemovedJoules(), 0.0);
    }
}

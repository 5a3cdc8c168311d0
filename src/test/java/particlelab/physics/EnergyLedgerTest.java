package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;

/**
 * The energy ledger's columns against closed forms (issue 32): gravity alone, linear drag,
 * a spring under forward Euler and under the lecture's step.
 */
class EnergyLedgerTest {

    private static final float H = 1f / 60f;

    /** Step a particle with the lecture's step, booking every step as the world does. */
    private static void stepBooked(ParticleIntegrator integrator, Particle particle,
            EnergyLedger ledger, Particle atStart) {
        atStart.copyFrom(particle);
        integrator.step(particle, H);
        ledger.addStepWork(integrator, atStart, H, particle.velocity);
        ledger.beginState();
        ledger.addBody(integrator, particle);
        ledger.endState();
    }

    private static EnergyLedger startedOn(ParticleIntegrator integrator, Particle particle) {
        EnergyLedger ledger = new EnergyLedger();
        ledger.beginState();
        ledger.addBody(integrator, particle);
        ledger.endState();
        ledger.start();
        return ledger;
    }

    @Test
    void gravityAloneNumericalIsMghTimesVyChangeOverTwo() {
        float mass = 2f;
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle particle = new Particle(new Vector3f(0f, 1f, 0f), new Vector3f(3f, 20f, 0f),
                mass);
        EnergyLedger ledger = startedOn(integrator, particle);
        Particle atStart = new Particle();
        double g = Gravity.STANDARD_G;
        double vy0 = particle.velocity.y;
        int steps = 600;
        for (int n = 1; n <= steps; ++n) {
            stepBooked(integrator, particle, ledger, atStart);
            double expected = mass * g * H * (particle.velocity.y - vy0) / 2.0;
            // The invariant ½(vy − g·h/2)² + g·y holds exactly in real arithmetic; in float
            // each step rounds vy and y once, which moves the energy by at most
            // m·(|vy|·ulp(vy) + g·ulp(y)); over n steps (|vy| < 40 m/s, |y| < 64 m here):
            double tolerance = n * mass * (40.0 * Math.ulp(40f) + g * Math.ulp(64f));
            assertEquals(expected, ledger.getNumericalJoules(), tolerance, "step " + n);
        }
        // and it is not float noise: 600 steps of h = 1/60 under g lose m·g²·h²·n/2
        assertEquals(-mass * g * g * H * H * steps / 2.0, ledger.getNumericalJoules(),
                1e-3 * mass * g * g * H * H * steps);
    }

    @Test
    void linearDragLossIsTheSumOfBhVTimesTheVelocityTheStepMovesWith() {
        float mass = 0.5f;
        float b = 0.3f;
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new LinearDrag(b));
        Particle particle = new Particle(new Vector3f(), new Vector3f(20f, 30f, 0f), mass);
        EnergyLedger ledger = startedOn(integrator, particle);
        Particle atStart = new Particle();
        Particle replay = new Particle(particle.position, particle.velocity, mass);
        double sum = 0.0;
        double magnitudes = 0.0;
        for (int n = 0; n < 400; ++n) {
            stepBooked(integrator, particle, ledger, atStart);
            // the re-simulation: V and V' as the step has them, F = −b·V at the start
            Vector3f v = new Vector3f(replay.velocity);
            integrator.step(replay, H);
            double term = b * H * ((double) v.x * replay.velocity.x
                    + (double) v.y * replay.velocity.y + (double) v.z * replay.velocity.z);
            sum += term;
            magnitudes += Math.abs(term);
        }
        // LinearDrag rounds −b·V to float once per component: 2^-24 of each term
        assertEquals(sum, ledger.getDragLossJoules(), 2.0 * magnitudes / (1 << 24));
        assertTrue(sum > 0.0);
    }

    @Test
    void dragAloneLosesHalfMKSquaredHSquaredVSquaredEachStepToTheStep() {
        // V' = (1 − kh)·V: ΔK − W = ½m|V|²((1−kh)² − 1) + m·k·h·(1−kh)·|V|² = −½m·k²h²·|V|²
        float mass = 1.5f;
        float b = 1.2f;
        double k = b / (double) mass;
        ParticleIntegrator integrator = new ParticleIntegrator(new LinearDrag(b));
        Particle particle = new Particle(new Vector3f(), new Vector3f(4f, -3f, 2f), mass);
        EnergyLedger ledger = startedOn(integrator, particle);
        Particle atStart = new Particle();
        double expected = 0.0;
        for (int n = 0; n < 300; ++n) {
            double speedSquared = particle.velocity.lengthSquared();
            expected -= 0.5 * mass * k * k * H * H * speedSquared;
            stepBooked(integrator, particle, ledger, atStart);
        }
        // each step's V' is rounded in float, 2^-24 relative, against a K of about 22 J:
        // 300 steps of about 1e-6 J each at most
        assertEquals(expected, ledger.getNumericalJoules(), 300 * 22.0 / (1 << 22));
        assertTrue(expected < -1e-3, "the step's own loss is not float noise: " + expected);
    }

    @Test
    void forwardEulerSpringEnergyGrowsByOnePlusOmegaSquaredHSquaredEachStep() {
        float mass = 2f;
        float stiffness = 50f;
        double omegaSquared = stiffness / (double) mass;
        Spring spring = new Spring(new Vector3f(), 0f, stiffness);
        ParticleIntegrator integrator = new ParticleIntegrator(spring);
        Particle particle = new Particle(new Vector3f(0.5f, 0f, 0f), new Vector3f(0f, 1f, 0f),
                mass);
        EnergyLedger ledger = startedOn(integrator, particle);
        double start = ledger.getStartJoules();
        Vector3f acceleration = new Vector3f();
        for (int n = 1; n <= 240; ++n) {
            // forward Euler: P with the old V, then V with the old a
            integrator.acceleration(particle, acceleration);
            particle.position.scaleAdd(H, particle.velocity, particle.position);
            particle.velocity.scaleAdd(H, acceleration, particle.velocity);
            ledger.beginState();
            ledger.addBody(integrator, particle);
            ledger.endState();
            double expected = start * (Math.pow(1.0 + omegaSquared * H * H, n) - 1.0);
            // the factor is exact for a spring of rest length 0 (F = −k·P); float rounds
            // P and V once a step, 2^-24 relative each, so n·2^-22 of the energy
            assertEquals(expected, ledger.getNumericalJoules(),
                    n * start * Math.pow(1.0 + omegaSquared * H * H, n) / (1 << 22),
                    "step " + n);
        }
    }

    @Test
    void lectureStepSpringStaysInABandOfWidthOmegaH() {
        // From x = A, v = 0, the lecture's step keeps ½v² + ½ω²x² − ½h·ω²·x·v exactly; so E/E0
        // stays within [1/(1 + ωh/2), 1/(1 − ωh/2)], a band of width ωh to first order.
        // Measured over 20 periods: ωh = 0.2: −0.0909 to +0.1111; 0.1: −0.0476 to +0.0526.
        float mass = 1f;
        float[] omegaH = {0.2f, 0.1f, 0.05f};
        for (float wh : omegaH) {
            float omega = wh / H;
            Spring spring = new Spring(new Vector3f(), 0f, omega * omega * mass);
            ParticleIntegrator integrator = new ParticleIntegrator(spring);
            Particle particle = new Particle(new Vector3f(1f, 0f, 0f), new Vector3f(), mass);
            EnergyLedger ledger = startedOn(integrator, particle);
            Particle atStart = new Particle();
            double start = ledger.getStartJoules();
            double low = 0.0;
            double high = 0.0;
            int steps = (int) (20 * 2 * Math.PI / wh);
            for (int n = 0; n < steps; ++n) {
                stepBooked(integrator, particle, ledger, atStart);
                double relative = ledger.getNumericalJoules() / start;
                low = Math.min(low, relative);
                high = Math.max(high, relative);
            }
            double half = wh / 2.0;
            // the band's edges are touched only near x·v extremes, which a step may miss by
            // up to ωh of phase: 2% of the edge; float adds 1e-5
            assertEquals(1.0 / (1.0 + half) - 1.0, low, 0.02 * half + 1e-5, "ωh = " + wh);
            assertEquals(1.0 / (1.0 - half) - 1.0, high, 0.02 * half + 1e-5, "ωh = " + wh);
        }
    }

    @Test
    void thrustWorkIsThrustTimesTheDistanceAlongTheVelocity() {
        // thrust along V moving straight: W = T·Σ h·|V'|, the path length the steps make
        float thrust = 3f;
        ParticleIntegrator integrator = new ParticleIntegrator(new Thrust(thrust));
        Particle particle = new Particle(new Vector3f(), new Vector3f(2f, 0f, 0f), 1f);
        EnergyLedger ledger = startedOn(integrator, particle);
        Particle atStart = new Particle();
        double path = 0.0;
        for (int n = 0; n < 120; ++n) {
            stepBooked(integrator, particle, ledger, atStart);
            path += H * (double) particle.velocity.x;
        }
        assertEquals(thrust * path, ledger.getThrustWorkJoules(), 1e-5 * thrust * path);
        assertEquals(0.0, ledger.getDragLossJoules(), 0.0);
    }

    @Test
    void aSpringsDampingIsDragLoss() {
        // Along the spring, its damping is linear drag with c: b·h·V·V' as for LinearDrag
        float c = 0.8f;
        Spring spring = new Spring(new Vector3f(), 0f, 30f, c);
        ParticleIntegrator integrator = new ParticleIntegrator(spring);
        Particle particle = new Particle(new Vector3f(1f, 0f, 0f), new Vector3f(2f, 0f, 0f),
                1f);
        EnergyLedger ledger = startedOn(integrator, particle);
        Particle atStart = new Particle();
        double sum = 0.0;
        for (int n = 0; n < 100; ++n) {
            float v = particle.velocity.x;
            stepBooked(integrator, particle, ledger, atStart);
            sum += c * H * (double) v * particle.velocity.x;
        }
        // the damping force rounded to float: 2^-24 relative of each term, |terms| < 0.1 J
        assertEquals(sum, ledger.getDragLossJoules(), 100 * 0.1 / (1 << 23));
        assertTrue(sum > 0.1);
        assertEquals(0.0, ledger.getThrustWorkJoules(), 0.0);
    }

    @Test
    void columnsAddUpAndBookingAllocatesNothing() {
        Spring spring = new Spring(new Vector3f(0f, 3f, 0f), 1f, 40f, 0.5f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new LinearDrag(0.2f), new QuadraticDrag(0.01f), new Thrust(0.4f), spring);
        Particle particle = new Particle(new Vector3f(1f, 0f, 0f), new Vector3f(2f, 5f, 1f),
                1.3f);
        EnergyLedger ledger = startedOn(integrator, particle);
        Particle atStart = new Particle();
        Allocations.assertAllocatesNothing("1000 booked steps", () -> {
            for (int n = 0; n < 1000; ++n) {
                stepBooked(integrator, particle, ledger, atStart);
            }
        });
        double sides = ledger.getStartJoules() + ledger.getThrustWorkJoules()
                - ledger.getDragLossJoules() + ledger.getNumericalJoules();
        // sums of a few dozen J in double: 1e-12 is a thousand roundings
        assertEquals(ledger.total(), sides, 1e-12);
        assertTrue(ledger.getDragLossJoules() > 0.0);
        assertEquals(EnergyLedger.POTENTIAL | EnergyLedger.SPRING | EnergyLedger.DRAG
                | EnergyLedger.THRUST, EnergyLedger.columnsOf(integrator));
    }
}

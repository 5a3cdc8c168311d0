package particlelab.rigid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;

/**
 * A torque-free asymmetric body, Euler's equations {@code I·ω̇ = −ω × I·ω} in the body frame:
 * energy and |L| under the two angular methods, and the intermediate-axis (tennis racket) flip
 * against a double-precision RK4 reference.
 */
class TorqueFreeTest {

    private static final double EPS = Math.ulp(1f);
    /** The tennis racket's moments (kg·m²): the middle axis, B = 2, is the unstable one. */
    private static final Inertia RACKET = Inertia.of(1f, 2f, 3f);
    /** Spun at 5 rad/s about the middle axis, 0.2 rad/s off it. */
    private static final Vector3f NEAR_MIDDLE = new Vector3f(0.2f, 5f, 0.2f);

    private static RigidBody body(Vector3f bodyOmega) {
        RigidBody body = new RigidBody(1f, RACKET);
        // R = I at the start, so the world ω is the body ω.
        body.setAngularVelocity(bodyOmega);
        return body;
    }

    @Test
    void explicitEulerRaisesEnergyAndAngularMomentumEveryStep() {
        // One explicit step adds h²·½·ω̇ᵀIω̇ to the energy and h²·|I·ω̇|² to |L|²: the
        // first-order terms vanish exactly, since ω̇ = I⁻¹(I·ω × ω) makes ω·I·ω̇ = 0 and
        // I·ω·I·ω̇ = 0. Here
        // |ω̇| ≈ 2 rad/s², so each step adds about 1e-3 J, far above float round-off (1e-6).
        RigidBody body = body(new Vector3f(1f, 2f, 1.5f));
        RotationIntegrator explicit =
                new RotationIntegrator(Orientation.EXACT, Angular.EXPLICIT, true);
        Vector3f scratch = new Vector3f();
        double energy = body.rotationalEnergy(scratch);
        double momentum = body.angularMomentum(scratch);
        double start = energy;
        for (int n = 1; n <= 600; ++n) {
            explicit.step(body, 1f / 60f);
            double nextEnergy = body.rotationalEnergy(scratch);
            double nextMomentum = body.angularMomentum(scratch);
            assertTrue(nextEnergy > energy, "energy rises at step " + n);
            assertTrue(nextMomentum > momentum, "|L| rises at step " + n);
            energy = nextEnergy;
            momentum = nextMomentum;
        }
        assertTrue(energy > 1.1 * start, "10 s gain more than 10 %: " + start + " -> " + energy);
    }

    @Test
    void implicitMidpointKeepsEnergyAndAngularMomentumToRoundOff() {
        RigidBody body = body(new Vector3f(1f, 2f, 1.5f));
        RotationIntegrator midpoint =
                new RotationIntegrator(Orientation.EXACT, Angular.IMPLICIT_MIDPOINT, true);
        Vector3f scratch = new Vector3f();
        double energy = body.rotationalEnergy(scratch);
        double momentum = body.angularMomentum(scratch);
        int steps = 600;
        for (int n = 1; n <= steps; ++n) {
            midpoint.step(body, 1f / 60f);
        }
        // Each step rounds ω (3 floats) and R (9) once: a relative change of a few EPS in
        // the energy and |L| per step, at worst n·4·EPS after n steps (2.9e-4 here; explicit
        // Euler gains over 10 % in the same run, see above).
        assertEquals(energy, body.rotationalEnergy(scratch), steps * 4 * EPS * energy);
        assertEquals(momentum, body.angularMomentum(scratch), steps * 4 * EPS * momentum);
    }

    @Test
    void implicitMidpointKeepsThemEvenAtALongStep() {
        // The invariants are kept for any h, not only as h → 0: h|ω| ≈ 0.7 here, where
        // explicit Euler gains energy by the tens of percent in a few steps.
        RigidBody body = body(new Vector3f(1f, 2f, 1.5f));
        RotationIntegrator midpoint =
                new RotationIntegrator(Orientation.EXACT, Angular.IMPLICIT_MIDPOINT, true);
        Vector3f scratch = new Vector3f();
        double energy = body.rotationalEnergy(scratch);
        double momentum = body.angularMomentum(scratch);
        int steps = 100;
        for (int n = 1; n <= steps; ++n) {
            midpoint.step(body, 0.25f);
        }
        // the same float round-off bound as above, for 100 steps
        assertEquals(energy, body.rotationalEnergy(scratch), steps * 4 * EPS * energy);
        assertEquals(momentum, body.angularMomentum(scratch), steps * 4 * EPS * momentum);
    }

    /** The times at which ωy (body frame) changes sign, interpolated within the step. */
    private static List<Double> flipTimes(RotationIntegrator integrator, float h,
            double seconds) {
        RigidBody body = body(NEAR_MIDDLE);
        Vector3f omega = new Vector3f();
        List<Double> flips = new ArrayList<>();
        double previous = body.bodyAngularVelocity(omega).y;
        int steps = (int) Math.round(seconds / h);
        for (int n = 1; n <= steps; ++n) {
            integrator.step(body, h);
            double now = body.bodyAngularVelocity(omega).y;
            if (Math.signum(now) != Math.signum(previous)) {
                flips.add((n - 1 + previous / (previous - now)) * h);
            }
            previous = now;
        }
        return flips;
    }

    /** The same flip times from RK4 in double on Euler's equations, h = 1/4000 s. */
    private static List<Double> referenceFlipTimes(double seconds) {
        double a = RACKET.getMoment(0);
        double b = RACKET.getMoment(1);
        double c = RACKET.getMoment(2);
        double[] w = {NEAR_MIDDLE.x, NEAR_MIDDLE.y, NEAR_MIDDLE.z};
        double h = 1.0 / 4000.0;
        double[][] k = new double[4][3];
        double[] probe = new double[3];
        List<Double> flips = new ArrayList<>();
        int steps = (int) Math.round(seconds / h);
        for (int n = 1; n <= steps; ++n) {
            double previous = w[1];
            for (int stage = 0; stage < 4; ++stage) {
                double f = stage == 0 ? 0.0 : stage == 3 ? 1.0 : 0.5;
                for (int i = 0; i < 3; ++i) {
                    probe[i] = w[i] + (stage == 0 ? 0.0 : f * h * k[stage - 1][i]);
                }
                k[stage][0] = (b - c) * probe[1] * probe[2] / a;
                k[stage][1] = (c - a) * probe[2] * probe[0] / b;
                k[stage][2] = (a - b) * probe[0] * probe[1] / c;
            }
            for (int i = 0; i < 3; ++i) {
                w[i] += h / 6.0 * (k[0][i] + 2.0 * k[1][i] + 2.0 * k[2][i] + k[3][i]);
            }
            if (Math.signum(w[1]) != Math.signum(previous)) {
                flips.add((n - 1 + previous / (previous - w[1])) * h);
            }
        }
        return flips;
    }

    @Test
    void theRacketSpunNearItsMiddleAxisFlipsAtTheReferencePeriod() {
        double seconds = 20.0;
        List<Double> reference = referenceFlipTimes(seconds);
        // A flip every 2.95 s (the reference), the first at 1.70 s.
        assertTrue(reference.size() >= 6, "reference flips: " + reference);
        RotationIntegrator midpoint =
                new RotationIntegrator(Orientation.EXACT, Angular.IMPLICIT_MIDPOINT, true);
        List<Double> flips = flipTimes(midpoint, 1f / 60f, seconds);
        assertEquals(reference.size(), flips.size(), flips + " vs " + reference);
        double referencePeriod = (reference.get(reference.size() - 1) - reference.get(0))
                / (reference.size() - 1);
        double period = (flips.get(flips.size() - 1) - flips.get(0)) / (flips.size() - 1);
        // Midpoint keeps E and |L| only to float round-off, about sqrt(n)·EPS relative after
        // n steps (4e-6 here). The orbit's distance from the separatrix,
        // L² − 2E·B = Σ I_i·(I_i − B)·ω_i² = 0.08 of L² = 100.4, moves by up to 0.5 % with
        // that, and the period, which grows with the log of the inverse distance (about 7
        // here), by about 0.07 %; its truncation error (second order) is below that at 1/60
        // (measured: period 2.94670 s against 2.94684 s; 1/120 and 1/240 s land 3e-4 either
        // side, round-off again). Hence 0.2 %.
        assertEquals(referencePeriod, period, 0.002 * referencePeriod);
    }

    @Test
    void withoutTheGyroscopicTermTheRacketNeverFlips() {
        RotationIntegrator noGyroscopic =
                new RotationIntegrator(Orientation.EXACT, Angular.EXPLICIT, false);
        assertEquals(List.of(), flipTimes(noGyroscopic, 1f / 60f, 20.0));
        // ...and ω stays what it was, in both frames (to R's round-off).
        RigidBody body = body(NEAR_MIDDLE);
        for (int n = 0; n < 1200; ++n) {
            noGyroscopic.step(body, 1f / 60f);
        }
        assertEquals(NEAR_MIDDLE, body.angularVelocity);
        Vector3f bodyOmega = body.bodyAngularVelocity(new Vector3f());
        assertEquals(NEAR_MIDDLE.y, bodyOmega.y, 1200 * EPS * NEAR_MIDDLE.y);
    }
}

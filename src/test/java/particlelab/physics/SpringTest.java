package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static particlelab.VectorAssert.assertVectorEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;

/**
 * {@link Spring}: Hooke's law with a dashpot, its rates, and the lecture's Euler step on it
 * against the step's own closed form (docs/numerics.md, "Spring").
 *
 * <p>The oscillator runs along x with the anchor at the origin and rest length {@link #REST},
 * the particle near {@code x = REST}: the distance stays positive, so the force is exactly
 * {@code −k·(x − L) − c·v} and the motion is the linear oscillator of the theory.
 */
class SpringTest {

    private static final float REST = 2f;
    private static final float MASS = 0.5f;

    @Test
    void stretchedSpringPullsTowardTheAnchorCompressedPushesAway() {
        Spring spring = new Spring(new Vector3f(1f, 2f, 3f), 1f, 10f);
        Particle stretched = new Particle(new Vector3f(1f, 2f, 6f), Vector3f.ZERO, 1f);
        Particle compressed = new Particle(new Vector3f(1.5f, 2f, 3f), Vector3f.ZERO, 1f);

        Vector3f force = new Vector3f();
        spring.addForce(stretched, force);
        // |d| = 3, stretch 2: 20 N toward the anchor (−z). Exact in float.
        assertVectorEquals(new Vector3f(0f, 0f, -20f), force, 0f);
        force.zero();
        spring.addForce(compressed, force);
        // |d| = 0.5, compressed by 0.5: 5 N away from the anchor (+x).
        assertVectorEquals(new Vector3f(5f, 0f, 0f), force, 0f);
    }

    @Test
    void dampingActsOnlyAlongTheSpringAndAddsToTheForceSoFar() {
        Spring spring = new Spring(Vector3f.ZERO, 3f, 10f, 2f);
        // At rest length, moving 4 m/s along the spring (x) and 7 m/s across it (y).
        Particle particle = new Particle(new Vector3f(3f, 0f, 0f), new Vector3f(4f, 7f, 0f), 1f);
        Vector3f force = new Vector3f(1f, 1f, 1f);

        spring.addForce(particle, force);

        // −c·(V·u)·u = −8 N along x; nothing across; the 1 N already there is kept.
        assertVectorEquals(new Vector3f(-7f, 1f, 1f), force, 0f);
    }

    @Test
    void atTheAnchorThereIsNoDirectionAndNoForce() {
        Spring spring = new Spring(Vector3f.ZERO, 1f, 10f, 1f);
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(1f, 0f, 0f), 1f);
        Vector3f force = new Vector3f();

        spring.addForce(particle, force);

        assertVectorEquals(Vector3f.ZERO, force, 0f);
    }

    @Test
    void reportsStiffnessKOverMAndDampingCOverM() {
        Spring spring = new Spring(Vector3f.ZERO, 1f, 8f, 3f);
        Particle particle = new Particle(new Vector3f(5f, 0f, 0f), Vector3f.UNIT_Y, 2f);

        assertEquals(4f, spring.stiffness(particle), 0f);
        assertEquals(1.5f, spring.dampingRate(particle), 0f);
        assertEquals(0f, new Gravity().stiffness(particle), 0f);
        assertEquals(0f, new LinearDrag(1f).stiffness(particle), 0f);
    }

    @Test
    void describeGivesTheEquationWithItsNumbers() {
        String undamped = new Spring(new Vector3f(0f, 5f, 0f), 1.5f, 20f).describe();
        String damped = new Spring(Vector3f.ZERO, 1f, 20f, 0.5f).describe();

        assertEquals("F = -20.0·(|d| - 1.5)·u, d = P - (0.0, 5.0, 0.0), u = d/|d|", undamped);
        assertTrue(damped.contains("- 0.5·(V·u)·u"), damped);
    }

    @Test
    void rejectsBadCoefficients() {
        assertThrows(IllegalArgumentException.class,
                () -> new Spring(Vector3f.ZERO, 1f, -1f));
        assertThrows(IllegalArgumentException.class,
                () -> new Spring(Vector3f.ZERO, Float.NaN, 1f));
        assertThrows(IllegalArgumentException.class,
                () -> new Spring(Vector3f.ZERO, 1f, 1f, Float.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> new Spring(null, 1f, 1f));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Spring(new Vector3f(Float.NaN, 0f, 0f), 1f, 1f));
        assertTrue(e.getMessage().contains("anchor"), e.getMessage());
    }

    @Test
    void eulerStepKeepsTheModifiedEnergyOfTheUndampedSpringExactly() {
        // For x'' = −ω²·x, V ← V − h·ω²·x then x ← x + h·V keeps
        // E = v² + ω²·x² − h·ω²·x·v exactly (the step is symplectic), so the swing neither
        // grows nor decays even at ω·h = 1.6, close to the limit 2.
        float k = 8f;
        float omegaSquared = k / MASS;
        float h = 1.6f / (float) Math.sqrt(omegaSquared);
        Particle particle = oscillator(0.3f, 0f);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Spring(Vector3f.ZERO, REST, k));
        double start = modifiedEnergy(particle, omegaSquared, h);

        double worst = 0.0;
        for (int n = 1; n <= 10_000; ++n) {
            integrator.step(particle, h);
            worst = Math.max(worst, Math.abs(modifiedEnergy(particle, omegaSquared, h) - start));
        }

        // Only float round-off moves E: x carries an absolute error of ulp(REST) = 2.4e-7 m
        // per step, a random walk of about 100 steps' worth after 10^4; E changes by
        // 2·ω²·x·δx, so 1e-3 relative leaves a factor 10 above that.
        assertTrue(worst < 1e-3 * start, "modified energy drifted by " + worst + " of " + start);
    }

    @Test
    void eulerStepMatchesTheDiscreteSolutionOfTheDampedSpring() {
        // x'' = −ω²x − λv stepped exactly: (x, v) ← M·(x, v), M = [[1 − ω²h², h(1 − λh)],
        // [−ω²h, 1 − λh]], iterated here in double from the same start.
        float k = 8f;
        float c = 0.6f;
        float h = 0.1f;
        double omegaSquared = k / MASS;
        double lambda = c / MASS;
        Particle particle = oscillator(0.4f, -1f);
        ParticleIntegrator integrator =
                new ParticleIntegrator(new Spring(Vector3f.ZERO, REST, k, c));
        double x = 0.4;
        double v = -1.0;

        for (int n = 1; n <= 200; ++n) {
            integrator.step(particle, h);
            v = (1 - lambda * h) * v - omegaSquared * h * x;
            x = x + h * v;
            // Float round-off of x − L near L = 2: ulp(2) per step, 200 steps, decaying
            // modes: 1e-5 m is over 20 times that bound.
            assertEquals(x, particle.position.x - REST, 1e-5, "x at step " + n);
            assertEquals(v, particle.velocity.x, 1e-4, "v at step " + n);
        }
        // The swing has decayed (the energy falls by about e^(−λt), t = 20 s).
        assertTrue(Math.abs(x) < 0.01, "x = " + x);
    }

    @Test
    void stepWithASpringAllocatesNothing() {
        Particle particle = oscillator(0.3f, 0.1f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new Spring(Vector3f.ZERO, REST, 8f, 0.2f));

        Allocations.assertAllocatesNothing("100000 steps with a spring", () -> {
            for (int i = 0; i < 100_000; ++i) {
                integrator.step(particle, 1f / 60f);
                integrator.maxStableStep(particle);
                integrator.regime(particle, 1f / 60f);
            }
        });
        assertTrue(particle.isFinite(), particle.toString());
    }

    /** A particle of {@link #MASS} at x = REST + offset on the x axis, moving at v. */
    private static Particle oscillator(float offset, float velocity) {
        return new Particle(new Vector3f(REST + offset, 0f, 0f), new Vector3f(velocity, 0f, 0f),
                MASS);
    }

    private static double modifiedEnergy(Particle particle, double omegaSquared, double h) {
        double x = particle.position.x - REST;
        double v = particle.velocity.x;
        return v * v + omegaSquared * x * x - h * omegaSquared * x * v;
    }
}

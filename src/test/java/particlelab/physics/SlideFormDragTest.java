package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * {@link SlideFormDrag}: the slide's −c·|V|²·V, cubic in speed, and its rate 3c·|V|²/m.
 */
class SlideFormDragTest {

    @Test
    void forceIsCubicInSpeedAgainstTheVelocity() {
        SlideFormDrag drag = new SlideFormDrag(0.5f);
        Particle particle = new Particle(new Vector3f(), new Vector3f(3f, 0f, -4f), 2f);
        Vector3f force = new Vector3f(1f, 1f, 1f);
        drag.addForce(particle, force);
        // |V| = 5: F = -0.5·25·V = (-37.5, 0, 50) added to (1, 1, 1); |F| = c·|V|³ = 62.5.
        // Two float products of exact small numbers: exact.
        assertEquals(-36.5f, force.x, 0f);
        assertEquals(1f, force.y, 0f);
        assertEquals(51f, force.z, 0f);
        // λ = 3c·|V|²/m = 3·0.5·25/2 = 18.75 /s, computed in double: exact.
        assertEquals(18.75f, drag.dampingRate(particle), 0f);
    }

    @Test
    void terminalSpeedIsTheCubeRootAndTheStepSettlesThere() {
        double vt = SlideFormDrag.terminalSpeed(2.0, 9.8, 0.1);
        assertEquals(Math.cbrt(196.0), vt, 1e-12);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(),
                new SlideFormDrag(0.1f));
        Particle particle = new Particle(new Vector3f(), new Vector3f(), 2f);
        for (int n = 0; n < 3000; ++n) {
            integrator.step(particle, 1f / 60f);
        }
        // The fixed point of V += h·(g − c|V|²V/m) is a = 0: v_t, to a few float ulps.
        assertEquals(vt, particle.velocity.length(), 1e-5 * vt);
    }

    @Test
    void badCoefficientIsRefusedWithItsName() {
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> new SlideFormDrag(-1f));
        assertEquals(true, refused.getMessage().contains("slide-form drag c"),
                refused.getMessage());
    }
}

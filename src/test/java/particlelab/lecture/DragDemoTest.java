package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParticle;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SlideFormDrag;

/**
 * Demo 3's terminal speeds and its slide-form switch, in plain JUnit: each sphere's own forces
 * stepped from rest until the speed settles, against the closed forms.
 */
class DragDemoTest {

    private static final float H = 1f / 60f;
    private static final double G = 9.8;

    @Test
    void steppedTerminalSpeedsAreTheClosedForms() {
        DragDemo drag = new DragDemo();
        // linear v_t = m·g/b = 9.8/0.9; physical quadratic √(m·g/c) = √(9.8/0.064).
        double linear = G / DragDemo.LINEAR_B;
        double quadratic = Math.sqrt(G / DragDemo.QUADRATIC_C);
        // The demo's HUD: the closed forms in double from float g, b, c (1e-6 relative).
        assertEquals(linear, drag.terminalSpeed(1), 1e-6 * linear);
        assertEquals(quadratic, drag.terminalSpeed(2), 1e-6 * quadratic);
        // The Euler step's fixed point is where a = 0, the same v_t; from rest, 60 s of steps
        // leave e^-54 of the linear gap (k = 0.9 /s) and less of the quadratic ones. In float
        // the speed then sits within a few ulps (2^-24 relative each) of it: 1e-5 relative.
        assertEquals(linear, fallFromRest(drag, 1), 1e-5 * linear);
        assertEquals(quadratic, fallFromRest(drag, 2), 1e-5 * quadratic);
    }

    @Test
    void slideFormFallsToTheCubeRootAndIsLabelledNotPhysical() {
        DragDemo drag = new DragDemo();
        drag.getParameters().set("law", 1f);
        drag.restart();
        assertTrue(drag.isSlideForm());
        DemoParticle sphere = drag.getParticles().get(2);
        assertTrue(sphere.getLabel().contains("not physical"), sphere.getLabel());
        // |V|³ = m·g/c: ∛(9.8/0.064) = 5.35 m/s.
        double slide = Math.cbrt(G / DragDemo.QUADRATIC_C);
        assertEquals(slide, drag.terminalSpeed(2), 1e-6 * slide);
        assertEquals(slide, SlideFormDrag.terminalSpeed(1.0, G, DragDemo.QUADRATIC_C),
                1e-6 * slide);
        assertEquals(slide, fallFromRest(drag, 2), 1e-5 * slide);
        // Back to the physical law: the slide's force is set to 0 again.
        drag.getParameters().set("law", 0f);
        drag.restart();
        assertFalse(drag.isSlideForm());
        assertEquals(Math.sqrt(G / DragDemo.QUADRATIC_C), fallFromRest(drag, 2), 1e-4);
    }

    @Test
    void slideFormsLimitAtTerminalSpeedIsTwoThirdsOfVtOverG() {
        DragDemo drag = new DragDemo();
        drag.getParameters().set("law", 1f);
        drag.restart();
        ParticleIntegrator forces = drag.getParticles().get(2).getIntegrator();
        double vt = Math.cbrt(G / DragDemo.QUADRATIC_C);
        // λ = 3c·v_t²/m = 3g/v_t at v_t: the limit 2/λ = 2v_t/(3g), 0.364 s (float rates:
        // 1e-6 relative).
        Particle falling = new Particle(new Vector3f(), new Vector3f(0f, (float) -vt, 0f), 1f);
        assertEquals(2.0 * vt / (3.0 * G), forces.maxStableStep(falling),
                1e-6 * vt / G);
        // Measured: a 10 % kick off v_t settles at 0.9 of the limit, and at 1.1 it does not.
        double limit = 2.0 * vt / (3.0 * G);
        assertTrue(kickShrinks(forces, vt, (float) (0.9 * limit)));
        assertFalse(kickShrinks(forces, vt, (float) (1.1 * limit)));
    }

    /** Step a sphere's own forces on a copy from rest for 60 s at h; return its speed. */
    private static double fallFromRest(DragDemo drag, int index) {
        ParticleIntegrator forces = drag.getParticles().get(index).getIntegrator();
        Particle particle = new Particle(new Vector3f(), new Vector3f(), 1f);
        for (int n = 0; n < 3600; ++n) {
            forces.step(particle, H);
        }
        return particle.velocity.length();
    }

    /** Whether 400 steps of h shrink a 10 % kick off the terminal speed. */
    private static boolean kickShrinks(ParticleIntegrator forces, double vt, float h) {
        Particle particle = new Particle(new Vector3f(), new Vector3f(0f, (float) (-1.1 * vt),
                0f), 1f);
        for (int n = 0; n < 400; ++n) {
            forces.step(particle, h);
        }
        return Math.abs(particle.velocity.length() - vt) < 0.1 * vt;
    }
}

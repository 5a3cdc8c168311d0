package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParticle;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SlideFormDrag;
import particlelab.view.TextFormat;

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

    /**
     * With the laws swapped ({@code drag=swapped}) the v_t line gives the step limits of the
     * laws the spheres run now: the linear sphere's quadratic c' at its v_t = m·g/b has
     * {@code 2/λ = v_t/g = m/b = 1.111} s, the quadratic sphere's linear b' at its
     * v_t = √(m·g/c) has {@code 2v_t/g = 2.525} s; not the labelled laws' 2.222 and 1.263 s.
     * The running integrators' own limits at those speeds say the same.
     */
    @Test
    void swappedStabilityLineGivesTheLimitsOfTheLawsTheSpheresRun() throws IOException {
        DragDemo drag = new DragDemo();
        drag.getParameters().set("drag", 1f);
        double linearVt = G / DragDemo.LINEAR_B;
        double quadraticVt = Math.sqrt(G / DragDemo.QUADRATIC_C);
        double quadraticLimit = linearVt / G;
        double linearLimit = 2.0 * quadraticVt / G;
        // the bodies' integrators are the swapped laws; their λ in float: 1e-5 relative
        assertEquals(quadraticLimit, limitAt(drag, 1, linearVt), 1e-5 * quadraticLimit);
        assertEquals(linearLimit, limitAt(drag, 2, quadraticVt), 1e-5 * linearLimit);
        String line = hudLine(drag, "v_t (h < there)");
        // printed to 3 decimals: 1.1111 and 2.5254 are far from a rounding edge
        assertEquals("v_t (h < there), laws swapped: quadratic c' √(mg/c') 10.89 m/s (1.111 s),"
                + " linear b' mg/b' 12.37 (2.525 s)", line);
        // docs/demos/drag.md quotes the line
        assertTrue(new String(Files.readAllBytes(Paths.get("docs/demos/drag.md")),
                StandardCharsets.UTF_8).contains("\n" + line + "\n"), line);
    }

    /**
     * With the laws swapped the generic stability line and the step warnings speak of the
     * forces each sphere runs now ({@link DemoParticle#getForcesNow()}, the world's body
     * integrator), not the labelled ones: the line read 'h < 2.222 s for swapped: quadratic
     * ... (λ = 0.90 /s)', the labelled linear law's limit, for a sphere running quadratic drag.
     */
    @Test
    void stabilityLineSpeaksOfTheForcesTheSpheresRunNow() {
        DragDemo drag = new DragDemo();
        drag.getParameters().set("drag", 1f);
        drag.restart();
        stepSingly(drag, 10);
        float limit = Float.POSITIVE_INFINITY;
        DemoParticle limiting = null;
        for (int i = 0; i < 3; ++i) {
            DemoParticle sphere = drag.getParticles().get(i);
            assertSame(drag.getWorld().getBody(i).getIntegrator(), sphere.getForcesNow(),
                    sphere.getLabel());
            float own = sphere.getForcesNow().maxStableStep(sphere.getParticle());
            if (!sphere.isHeld() && own < limit) {
                limit = own;
                limiting = sphere;
            }
        }
        // the labelled laws differ: the swapped linear sphere is no longer at the labelled λ
        float labelled = drag.getParticles().get(1).getIntegrator()
                .dampingRate(drag.getParticles().get(1).getParticle());
        float running = drag.getParticles().get(1).getForcesNow()
                .dampingRate(drag.getParticles().get(1).getParticle());
        assertFalse(Math.abs(labelled - running) < 0.01f, labelled + " " + running);
        StringBuilder expected = new StringBuilder("Stability: h < ");
        TextFormat.appendFixed(expected, limit, 3).append(" s for '")
                .append(limiting.getLabel()).append("' (λ = ");
        TextFormat.appendFixed(expected,
                limiting.getForcesNow().dampingRate(limiting.getParticle()), 2);
        String line = hudLine(drag, "Stability:");
        assertTrue(line.startsWith(expected.toString()), line + " | expected " + expected);
    }

    /**
     * The comparison lane follows the labelled linear law (its forces, exact path and slide
     * code are the labelled sphere's): with the laws swapped its lines say so, and only then.
     */
    @Test
    void laneSaysItFollowsTheLabelledLawWhenTheLawsAreSwapped() {
        DragDemo drag = new DragDemo();
        drag.getParameters().set("lane", 2f);
        drag.restart();
        stepSingly(drag, 10);
        String note = "the lane, its exact path and the seen errors follow the labelled law";
        String hud = hud(drag);
        assertTrue(hud.contains("Lane forward Euler (L):"), hud);
        assertFalse(hud.contains(note), hud);
        drag.getParameters().set("drag", 1f);
        stepSingly(drag, 1);
        hud = hud(drag);
        assertTrue(hud.contains("\n   " + note + " F = -b V, not the swapped one the sphere"
                + " runs\n"), hud);
    }

    /**
     * The derivative lens re-takes the recipe's step with the labelled forces: with forward
     * Euler ({@code method=euler}) or the swapped laws its lines say it is not the sphere's
     * step, and with neither they say nothing of the kind.
     */
    @Test
    void lensSaysItIsNotTheSpheresStepUnderAnotherMethodOrLaw() {
        DragDemo drag = new DragDemo();
        drag.getParameters().set("lens", 1f);
        stepSingly(drag, 10);
        assertTrue(hud(drag).contains("derivative lens (O; click a step dot)"), hud(drag));
        assertFalse(hud(drag).contains("not the sphere's step"), hud(drag));
        drag.getParameters().set("method", 1f);
        stepSingly(drag, 1);
        assertTrue(hud(drag).contains(" s; arrows from P_i, in m/s:\n  not the sphere's step:"
                + " the lens re-takes the lecture's recipe, the sphere steps by forward Euler"
                + " (method)\n"), hud(drag));
        drag.getParameters().set("method", 0f);
        drag.getParameters().set("drag", 1f);
        stepSingly(drag, 1);
        assertTrue(hud(drag).contains("\n  not the sphere's step: the lens re-takes the"
                + " labelled law F = -b V, the sphere runs the swapped one (drag)\n"), hud(drag));
        drag.getParameters().set("method", 1f);
        assertTrue(hud(drag).contains("\n  not the sphere's step: the lens re-takes the"
                + " labelled law by the recipe, the sphere the swapped one by forward Euler\n"),
                hud(drag));
    }

    private static String hud(DragDemo drag) {
        return drag.getWindow().formatHud(new StringBuilder()).toString();
    }

    /** The HUD's line that starts with the prefix. */
    private static String hudLine(DragDemo drag, String prefix) {
        String[] lines = hud(drag).split("\n");
        for (String line : lines) {
            if (line.startsWith(prefix)) {
                return line;
            }
        }
        throw new AssertionError("no HUD line starts with '" + prefix + "' in " + hud(drag));
    }

    /** The stability limit of the integrator the world steps a sphere with, at speed v down. */
    private static double limitAt(DragDemo drag, int index, double speed) {
        Particle falling = new Particle(new Vector3f(), new Vector3f(0f, (float) -speed, 0f),
                1f);
        return drag.getWorld().getBody(index).getIntegrator().maxStableStep(falling);
    }

    /** Take steps one at a time with the demo's single step, as N does. */
    private static void stepSingly(DragDemo drag, int steps) {
        for (int i = 0; i < steps; ++i) {
            drag.getRun().singleStep();
            drag.getRun().advancePhysics(0f);
        }
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

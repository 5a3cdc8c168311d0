package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * {@link StepWarnings} without a window: the warning follows a coefficient changed mid-run,
 * although the integrator answers most steps from a remembered bound.
 */
class StepWarningsTest {

    private static final float H = 1f / 60f;

    @Test
    void aDragCoefficientChangedMidRunRaisesTheWarningAtTheNextStep() {
        SimulationClock clock = new SimulationClock();
        int[] changes = {0};
        StepWarnings warnings = new StepWarnings(clock, () -> ++changes[0]);
        QuadraticDrag drag = new QuadraticDrag(0.05f);
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity(), drag);
        Particle ball = new Particle(new Vector3f(), new Vector3f(30f, 40f, 0f), 1f);
        StringBuilder text = new StringBuilder();
        // λ = 2c·|V|/m = 5 /s at 50 m/s: h·λ = 0.08, far from every limit
        takeSteps(warnings, integrator, ball, 30);
        assertEquals("", warnings.format(text).toString());
        assertEquals(0, changes[0]);
        // c = 2 kg/m: λ = 4·|V| /s, so h·λ > 2 at any speed above 30 m/s: unstable at 50
        drag.setCoefficient(2f);
        ball.velocity.set(30f, 40f, 0f);
        float limit = integrator.maxStableStep(ball);
        takeSteps(warnings, integrator, ball, 1);
        StringBuilder expected = new StringBuilder("UNSTABLE: h = ");
        TextFormat.appendFixed(expected, H * 1000f, 1).append(" ms is beyond the stability"
                + " limit ");
        TextFormat.appendFixed(expected, limit * 1000f, 1).append(" ms of 'ball': ");
        String warning = warnings.format(text).toString();
        assertTrue(warning.startsWith(expected.toString()), warning);
        assertEquals(1, changes[0]);
        // back to c = 0.05 kg/m: no new warning, and the old one goes after SHOW_SECONDS
        drag.setCoefficient(0.05f);
        ball.velocity.set(30f, 40f, 0f);
        warnings.age(StepWarnings.SHOW_SECONDS + 0.1f);
        takeSteps(warnings, integrator, ball, 30);
        assertEquals("", warnings.format(text).toString());
        assertEquals(1, changes[0]);
    }

    private static void takeSteps(StepWarnings warnings, ParticleIntegrator integrator,
            Particle ball, int steps) {
        for (int n = 0; n < steps; ++n) {
            warnings.beginStep(H);
            warnings.observe("ball", integrator, ball);
            integrator.step(ball, H);
            warnings.endStep();
        }
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Test;
import particlelab.lecture.DragDemo;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.physics.Spring;

/**
 * The HUD's stability line and warning: one statement, naming the particle it is about, with
 * the limits of drag and of springs (docs/numerics.md, "Stability"). Plain JUnit: the demo's
 * run steps without jME, and the warning is the text its run's {@link StepWarnings} hands
 * the HUD's warning line.
 */
class StabilityHudTest {

    private static final float H = 1f / 60f;
    /** The sprung ball: k = 16 N/m on 1 kg, so omega = 4 /s and the limit 2/omega = 0.5 s. */
    private static final float SPRING_K = 16f;

    private final DragDemo drag = declared(new DragDemo());
    private final SprungDemo sprung = declared(new SprungDemo());

    @Test
    void dragDemoLineNamesTheSphereWithTheSmallestLimit() throws Exception {
        String body = measure(() -> {
            drag.restart();
            return drag.getWindow().formatHud(new StringBuilder()).toString();
        });
        // At launch |V| = sqrt(200): quadratic lambda = 2·0.064·14.142 = 1.810 /s, limit
        // 2/lambda = 1.105 s, below linear drag's 2m/b = 2.222 s. No "k", no second limit.
        assertTrue(body.contains("Stability: h < 1.105 s for 'quadratic drag  F = -c |V|V'"
                + " (λ = 1.81 /s)\n"), body);
        // (The drag demo's terminal-speed line gives 2m/b at v_t; the stability line does not.)
        assertTrue(!stabilityLine(body).contains("2.222") && !body.contains("any h"), body);
    }

    @Test
    void dragDemoWarningNamesTheSameSphereAndSaysWhatTheStepDoes() throws Exception {
        String[] texts = measure(() -> {
            drag.restart();
            drag.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            // 1.2 s: beyond the quadratic sphere's 1.105 s, within the linear one's 2.222 s.
            drag.getClock().setStepSeconds(1.2f);
            takeOneStep(drag);
            String warning = warningOf(drag);
            drag.getClock().setStepSeconds(SimulationClock.DEFAULT_STEP_SECONDS);
            drag.restart();
            return new String[] {warning,
                    drag.getWindow().formatHud(new StringBuilder()).toString()};
        });
        String warning = texts[0];
        assertTrue(warning.startsWith("UNSTABLE: h = 1200.0 ms is beyond the stability limit"
                + " 1104.9 ms of 'quadratic drag  F = -c |V|V': small changes of the motion"
                + " grow every step"), warning);
        assertTrue(texts[1].contains("for 'quadratic drag  F = -c |V|V'"), texts[1]);
    }

    @Test
    void springShowsItsLimitTwoOverOmegaAndWarnsBeyondIt() throws Exception {
        String[] texts = measure(() -> {
            sprung.restart();
            String body = sprung.getWindow().formatHud(new StringBuilder()).toString();
            sprung.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            sprung.getClock().setStepSeconds(0.55f);
            takeOneStep(sprung);
            String warning = warningOf(sprung);
            sprung.getClock().setStepSeconds(SimulationClock.DEFAULT_STEP_SECONDS);
            sprung.restart();
            return new String[] {body, warning};
        });
        // Before: "no drag: any h is stable" beside a blow-up at 2/omega.
        assertTrue(texts[0].contains("Stability: h < 0.500 s for 'sprung' (λ = 0.00 /s,"
                + " ω = 4.00 /s)\n"), texts[0]);
        assertEquals("UNSTABLE: h = 550.0 ms is beyond the stability limit 500.0 ms of"
                + " 'sprung': small changes of the motion grow every step instead of dying out",
                texts[1]);
    }

    @Test
    void landedParticlesAreLeftOutOfTheLine() throws Exception {
        String body = measure(() -> {
            drag.restart();
            for (int frame = 0; frame < 600; ++frame) {
                drag.getRun().advancePhysics(H);
            }
            return drag.getWindow().formatHud(new StringBuilder()).toString();
        });
        // After 10 s all three spheres have landed and stopped: no limit to show, and not
        // the landed quadratic sphere's (infinite) one as "any h is stable".
        assertTrue(body.contains("Stability: no particle is in flight, so no particle step"
                + " limit applies\n"),
                body);
    }

    @Test
    void whileTheWarningIsUpTheLineGivesTheLimitItIsAboutNotAnyHIsStable() throws Exception {
        String[] texts = measure(() -> {
            drag.getParameters().set("c", 0.5f);
            drag.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            drag.getClock().setStepSeconds(0.2f);
            drag.restart();
            // 1.7 s of frames (0.2 s steps): the quadratic sphere passed its limit in the first
            // step and landed, the linear one has landed too, only "gravity only" flies; the
            // warning stays up for 4 s of real time.
            for (int frame = 0; frame < 102; ++frame) {
                drag.getRun().advancePhysics(H);
            }
            String[] result = {warningOf(drag),
                drag.getWindow().formatHud(new StringBuilder()).toString()};
            drag.getParameters().set("c", DragDemo.QUADRATIC_C);
            drag.getClock().setStepSeconds(SimulationClock.DEFAULT_STEP_SECONDS);
            drag.restart();
            return result;
        });
        // At launch |V| = sqrt(200): lambda = 2·0.5·14.142 = 14.142 /s, limit 2/lambda =
        // 0.1414 s, which h = 0.2 s passes.
        assertTrue(texts[0].startsWith("UNSTABLE: h = 200.0 ms is beyond the stability limit"
                + " 141.4 ms of 'quadratic drag  F = -c |V|V'"), texts[0]);
        String body = texts[1];
        assertTrue(body.contains("Stability: h < 0.141 s for 'quadratic drag  F = -c |V|V' at"
                + " the step the warning below is about\n"), body);
        assertTrue(!body.contains("any h") && !stabilityLine(body).contains("2.222"), body);
    }

    /** The HUD body's "Stability:" line. */
    private static String stabilityLine(String body) {
        int start = body.indexOf("Stability:");
        return start < 0 ? "" : body.substring(start, body.indexOf('\n', start));
    }

    /** Feed frames of H until the clock has taken its first (long) step from the launch. */
    private static void takeOneStep(DemoState demo) {
        for (int frame = 0; frame < 1000 && demo.getClock().getSimulatedSeconds() == 0.0;
                ++frame) {
            demo.getRun().advancePhysics(H);
        }
        assertTrue(demo.getClock().getSimulatedSeconds() > 0.0, "no step taken");
    }

    /** The warning line the HUD shows now: the run's warnings, as the HUD asks for them. */
    private static String warningOf(DemoState demo) {
        return demo.getRun().getWarnings().format(new StringBuilder()).toString();
    }

    /**
     * Declare a demo's scene, as a window's start does before anything else: its setters
     * act on the particles the scene created.
     */
    private static <D extends DemoState> D declared(D demo) {
        demo.getRun();
        return demo;
    }

    /** Run one block of a test and hand back what it measured. */
    private static <T> T measure(Callable<T> block) throws Exception {
        return block.call();
    }

    /** A test-only demo: a ball on an undamped spring under gravity. */
    static final class SprungDemo extends DemoState {
        SprungDemo() {
            super("Spring (test)");
        }

        @Override
        protected void createScene() {
            addParticle("sprung", ColorRGBA.Green, new Vector3f(0f, 3f, 0f), Vector3f.ZERO, 1f,
                    new ParticleIntegrator(new Gravity(),
                            new Spring(new Vector3f(0f, 5f, 0f), 1f, SPRING_K)));
        }
    }
}

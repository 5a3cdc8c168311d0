package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import particlelab.aiming.FrameJitter;
import particlelab.aiming.FrameRateRun;
import particlelab.aiming.JitterHistogram;
import particlelab.demo.DemoParticle;
import particlelab.demo.RateLanes;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;

/**
 * The rate lanes ({@code --set rates=on}) in the gravitational-pull and drag demos, stepped in
 * plain JUnit: each lane moves through its own monitor's frames in step with the demo's time
 * and lands where its run flown alone lands; the HUD says so.
 */
class RateLanesDemoTest {

    private static final float H = 1f / 60f;

    @Test
    void eachLaneTakesItsMonitorsFramesInStepWithTheDemo() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        pull.getParameters().set(RateLanes.PARAMETER, 1f);
        RateLanes rates = pull.getRates();
        int steps = 31;
        for (int frame = 0; frame < steps; ++frame) {
            pull.advancePhysics(H);
        }
        // after 31 steps of 1/60 s, a monitor at f Hz has shown floor(31·f/60) frames, each
        // one raw step (31/60 s is a whole number of 1/f for none of them but 60 Hz)
        for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
            int expected = (int) Math.floor(steps * RateLanes.RATES_HZ[i] / 60.0 + 1e-9);
            assertEquals(expected, rates.getRun(i).getSteps(), RateLanes.RATES_HZ[i] + " Hz");
        }
    }

    @Test
    void lanesLandWhereTheirRunsFlownAloneLandAndTheHudSaysSo() {
        for (DemoCase demo : new DemoCase[] {DemoCase.PULL, DemoCase.DRAG}) {
            FreeFlight flight = demo.create();
            flight.setRates();
            for (int frame = 0; frame < 600; ++frame) {
                flight.advance();
            }
            RateLanes rates = flight.rates();
            DemoParticle followed = flight.followed();
            Particle launch = new Particle(followed.copyLaunchPosition(new Vector3f()),
                    followed.copyLaunchVelocity(new Vector3f()), followed.getParticle().getMass());
            String hud = flight.hud();
            for (int i = 0; i < RateLanes.RATES_HZ.length; ++i) {
                FrameRateRun alone = new FrameRateRun(followed.getIntegrator());
                alone.start(launch, RateLanes.RATES_HZ[i], SimulationClock.Mode.RAW_TPF, H);
                assertTrue(alone.flyToLanding());
                FrameRateRun lane = rates.getRun(i);
                assertTrue(lane.hasLanded(), demo + " " + i);
                // the same frames of 1/f from the same launch: the same bits
                assertEquals(alone.getLanding().getX(), lane.getLanding().getX(), 0.0);
                String shown = String.format(Locale.ROOT, "%d Hz %.2f m (%+.2f)", (int) RateLanes.RATES_HZ[i],
                        alone.getLanding().getX(), alone.getLanding().getX()
                                - rates.getFixedRun().getLanding().getX());
                assertTrue(hud.contains(shown), demo + ": " + shown + " in\n" + hud);
            }
            // the fixed step (the demo's own h) is where the followed sphere landed, to the
            // float the world keeps its landing in
            assertEquals(followed.getLandingX(), rates.getFixedRun().getLanding().getX(),
                    Math.ulp(followed.getLandingX()), demo.toString());
            // 30 Hz lands furthest from the fixed step, 240 Hz nearest
            double fixedX = rates.getFixedRun().getLanding().getX();
            assertTrue(Math.abs(rates.getRun(0).getLanding().getX() - fixedX)
                    > Math.abs(rates.getRun(3).getLanding().getX() - fixedX), demo.toString());
        }
    }

    @Test
    void jitterHistogramIsComputedAtTheLaunchWithTheFixedStepsBar() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        pull.getParameters().set(RateLanes.PARAMETER, 1f);
        pull.getParameters().set(RateLanes.JITTER, 2f);
        pull.getParameters().set(RateLanes.JITTER_WIDTH, 3f);
        pull.advancePhysics(H);
        JitterHistogram histogram = pull.getRates().getHistogram();
        assertEquals(JitterHistogram.DEFAULT_RUNS, histogram.getRuns());
        // the same computation, done here: run i of seed 33 + i, normal, 3 ms, 60 Hz
        JitterHistogram again = new JitterHistogram(pull.getParticles().get(0).getIntegrator(),
                JitterHistogram.DEFAULT_RUNS);
        Particle launch = new Particle(new Vector3f(), new Vector3f(10f, 10f, 0f), 1f);
        again.compute(launch, 60f, FrameJitter.Distribution.NORMAL, 0.003f, RateLanes.SEED,
                JitterHistogram.DEFAULT_RUNS, H);
        for (int bin = 0; bin < JitterHistogram.BINS; ++bin) {
            assertEquals(again.getCount(bin), histogram.getCount(bin), "bin " + bin);
        }
        assertEquals(pull.getRates().getFixedRun().getLanding().getX(), histogram.getFixedX(),
                0.0);
        String hud = pull.formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("Jitter normal 3.0 ms at 60 Hz, 1000 runs land "), hud);
        assertTrue(hud.contains("fixed step: all 1000 runs in one bar at "), hud);
    }

    @Test
    void lanesOffLeaveTheHudAlone() {
        GravitationalPullDemo pull = new GravitationalPullDemo();
        pull.advancePhysics(H);
        assertFalse(pull.getRates().isOn());
        assertFalse(pull.formatHud(new StringBuilder()).toString().contains("Raw tpf"));
        assertEquals(0, pull.getRates().getRun(0).getSteps());
    }

    /** The two free-flight demos with the lanes. */
    private enum DemoCase {
        PULL, DRAG;

        FreeFlight create() {
            return this == PULL ? new FreeFlight(new GravitationalPullDemo())
                    : new FreeFlight(new DragDemo());
        }
    }

    /** One of them, behind the few calls the test makes. */
    private static final class FreeFlight {
        private final GravitationalPullDemo pull;
        private final DragDemo drag;

        FreeFlight(GravitationalPullDemo demo) {
            pull = demo;
            drag = null;
        }

        FreeFlight(DragDemo demo) {
            pull = null;
            drag = demo;
        }

        void setRates() {
            if (pull != null) {
                pull.getParameters().set(RateLanes.PARAMETER, 1f);
            } else {
                drag.getParameters().set(RateLanes.PARAMETER, 1f);
            }
        }

        void advance() {
            if (pull != null) {
                pull.advancePhysics(H);
            } else {
                drag.advancePhysics(H);
            }
        }

        RateLanes rates() {
            return pull != null ? pull.getRates() : drag.getRates();
        }

        DemoParticle followed() {
            // the ball; the drag demo's linear-drag sphere (its second)
            return pull != null ? pull.getParticles().get(0) : drag.getParticles().get(1);
        }

        String hud() {
            return (pull != null ? pull.formatHud(new StringBuilder())
                    : drag.formatHud(new StringBuilder())).toString();
        }
    }
}

package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.app.DemoCatalog;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;

/**
 * The demos' physics in plain JUnit, with no jME application: each demo is made with
 * {@code new} and driven by {@link DemoState#advancePhysics}, the frame without its views.
 */
class DemoPhysicsTest {

    private static final float H = 1f / 60f;

    @Test
    void everyDemoMovesItsParticlesExactlyAsTheIntegratorSays() {
        int steps = 50; // under a second: no particle of any demo lands or wraps yet
        for (DemoState demo : demos()) {
            if (demo.getWorld().countRules() > 0) {
                continue; // a collision demo's contacts change velocities: its own tests
            }
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < steps; ++frame) {
                demo.advancePhysics(H);
            }
            for (DemoParticle particle : demo.getParticles()) {
                if (particle.getPathIntegrator() != particle.getIntegrator()) {
                    // a comparison lane's sphere, moved by its lane: ComparisonLaneTest
                    continue;
                }
                // The same Euler steps, done directly: the demo adds nothing of its own.
                Particle reference = new Particle(
                        particle.copyLaunchPosition(new Vector3f()),
                        particle.copyLaunchVelocity(new Vector3f()),
                        particle.getParticle().getMass());
                for (int i = 0; i < steps; ++i) {
                    particle.getIntegrator().step(reference, H);
                }
                String name = demo.getTitle() + "/" + particle.getLabel();
                assertEquals(reference.position, particle.getParticle().position, name);
                assertEquals(reference.velocity, particle.getParticle().velocity, name);
            }
            // One fixed step per frame of exactly h: 50 steps, summed in double.
            assertEquals(steps * (double) H, demo.getClock().getSimulatedSeconds(), 1e-9);
        }
    }

    @Test
    void everyDemoIsSteppedByItsWorldOneWorldStepPerClockStep() {
        for (DemoState demo : demos()) {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < 30; ++frame) {
                demo.advancePhysics(H);
            }
            assertEquals(30L, demo.getWorld().getStepCount(), demo.getTitle());
            // The world sums the same float steps in double as the clock does.
            assertEquals(demo.getClock().getSimulatedSeconds(),
                    demo.getWorld().getTimeSeconds(), 1e-12, demo.getTitle());
            for (DemoParticle particle : demo.getParticles()) {
                assertEquals(particle.getParticle(), particle.getBody().getParticle(),
                        demo.getTitle() + ": a particle outside the world");
                assertEquals(true, particle.getBody().isInWorld(), demo.getTitle());
            }
        }
    }

    @Test
    void pullDemoFollowsTheEulerStepsClosedForm() {
        DemoState pull = DemoCatalog.entries().get(DemoCatalog.indexOf("pull")).create();
        int steps = 90;
        pull.restart();
        for (int frame = 0; frame < steps; ++frame) {
            pull.advancePhysics(H);
        }
        Vector3f position = pull.getParticles().get(0).getParticle().position;
        // docs/numerics.md: y_n = n·h·vy − g·h²·n(n+1)/2, x_n = n·h·vx (the stepped parabola).
        double h = H;
        double y = steps * h * 10.0 - Gravity.STANDARD_G * h * h * steps * (steps + 1) / 2.0;
        double x = steps * h * 10.0;
        // 90 float steps of size ~0.17 m: rounding grows to a few 1e-6 m, far below 1e-4.
        assertEquals(x, position.x, 1e-4);
        assertEquals(y, position.y, 1e-4);
    }

    private static List<DemoState> demos() {
        List<DemoState> demos = new ArrayList<>(DemoCatalog.createAll());
        demos.add(new DemoStateHeadlessTest.StiffDemo());
        return demos;
    }
}

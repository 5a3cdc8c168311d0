package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import particlelab.app.DemoCatalog;
import particlelab.physics.Force;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;

/**
 * The demos' physics in plain JUnit, with no jME application: each demo is made with
 * {@code new} and driven by {@link DemoRun#advancePhysics}, the frame without its views.
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
                demo.getRun().advancePhysics(H);
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
    void aLandingStepIsIntegratedOnceAndItsExportRowIsTheStateBelowTheGround() {
        // A force that adds nothing and counts the integrator's calls of it.
        int[] calls = new int[1];
        Force counting = new Force() {
            @Override
            public void addForce(Particle particle, Vector3f netForce) {
                ++calls[0];
            }

            @Override
            public String describe() {
                return "nothing, counted";
            }
        };
        DemoRun run = new DemoRun(new NoHooks());
        DemoParticle shot = run.addParticle("shot", ColorRGBA.White, Vector3f.ZERO,
                new Vector3f(20f, 30f, 0f), 1f,
                new ParticleIntegrator(new Gravity(), counting)).stopAtGround();
        run.advancePhysics(H);
        // The calls of one step: the integration's, and the stability warning's look at the
        // forces before it.
        int callsPerStep = calls[0];
        int frames = 1;
        while (!shot.hasLanded()) {
            assertTrue(frames < 1_000, "never landed");
            run.advancePhysics(H);
            ++frames;
        }
        // One fixed step per frame of exactly h; the landing step's row is the last.
        TrajectoryRecord record = shot.getRecord();
        assertEquals(frames + 1, record.size());
        assertEquals(frames * callsPerStep, calls[0],
                "each step integrated once, the landing step too");

        // The same Euler steps, done directly: the last row is the landing step's state below
        // the ground, as `trajectory --until-ground` prints it, bit for bit.
        Particle reference = new Particle(Vector3f.ZERO, new Vector3f(20f, 30f, 0f), 1f);
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity());
        for (int i = 0; i < frames; ++i) {
            gravity.step(reference, H);
        }
        int last = frames;
        assertTrue(record.get(last, 2) < 0f, "below the ground");
        float[] expected = {reference.position.x, reference.position.y, reference.position.z,
            reference.velocity.x, reference.velocity.y, reference.velocity.z};
        for (int column = 1; column <= 6; ++column) {
            assertEquals(expected[column - 1], record.get(last, column), 0f, "column " + column);
        }
        // The particle itself rests at the crossing, and the landing is the ground stop's.
        assertEquals(0f, shot.getParticle().position.y, 0f);
        assertEquals(shot.getParticle().position.x, shot.getLandingX(), 0f);
        assertEquals(run.getGroundStop().getLandingSeconds(0), shot.getLandingSeconds(), 0.0);
        assertTrue(shot.getLandingSeconds() > (frames - 1) * (double) H
                && shot.getLandingSeconds() < frames * (double) H);
        assertEquals(frames * (double) H, shot.getFlightSeconds(), 1e-12);
    }

    @Test
    void everyDemoIsSteppedByItsWorldOneWorldStepPerClockStep() {
        for (DemoState demo : demos()) {
            demo.getClock().setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            for (int frame = 0; frame < 30; ++frame) {
                demo.getRun().advancePhysics(H);
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
            pull.getRun().advancePhysics(H);
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

    /** A run's hooks for a run without a demo: nothing to declare, nothing to show. */
    private static final class NoHooks implements DemoRun.Hooks {
        @Override
        public void prepare() {
        }

        @Override
        public void beforeStep(float stepSeconds) {
        }

        @Override
        public void afterStep(float stepSeconds) {
        }

        @Override
        public void beforeRestart() {
        }

        @Override
        public void particlesRestarted() {
        }

        @Override
        public void restarted() {
        }

        @Override
        public void changed() {
        }
    }
}

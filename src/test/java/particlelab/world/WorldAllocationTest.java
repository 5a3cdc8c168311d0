package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.Allocations;
import particlelab.collision.Plane;
import particlelab.collision.ThinWall;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;

/**
 * A world step with contacts allocates nothing once its pools have grown: measured in bytes
 * with the thread's allocation counter (see {@link Allocations}).
 */
class WorldAllocationTest {

    private static final int STEPS = 20_000;
    private static final float H = 1f / 60f;

    @ParameterizedTest
    @EnumSource(Detection.class)
    void steppingBouncingBallsWithEveryPhaseAllocatesNothing(Detection detection) {
        World world = new World(64);
        ParticleIntegrator forces = new ParticleIntegrator(new Gravity(), new LinearDrag(0.05f));
        for (int i = 0; i < 4; ++i) {
            world.addBody(forces, new Vector3f(0.3f * i, 1f + i, 0f),
                    new Vector3f(1f - 0.5f * i, 0f, 0.2f * i), 1f + i, 0.2f);
        }
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.7f, 0.25f, true), detection));
        world.addRule(new SurfaceRule("wall", new ThinWall(Vector3f.UNIT_X, 1.5f, 0.1f),
                new ImpulseResponse(0.9f), detection));
        world.addRule(new SurfaceRule("back wall", new Plane(Vector3f.UNIT_X, -1.5f),
                new ImpulseResponse(0.9f), detection));
        world.addRule(new SphereRule(new ImpulseResponse(0.8f), detection));
        int[] epilogues = {0};
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World w) {
                contact.setEpilogueNote("counted");
                ++epilogues[0];
            }
        });
        world.addStepListener(new StepListener() {
        });

        Allocations.assertAllocatesNothing(STEPS + " steps with contacts", () -> {
            world.restart();
            for (int i = 0; i < STEPS; ++i) {
                world.step(H);
                world.getImpacts().clear();
            }
        });
        assertTrue(epilogues[0] > STEPS, epilogues[0] + " epilogues");
        assertTrue(world.getLog().getTotal() > STEPS);
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void destroyAndSpawnFromThePoolAllocateNothing(Detection detection) {
        World world = new World(16);
        ParticleIntegrator fall = new ParticleIntegrator(new Gravity());
        ParticleIntegrator fragmentForces = new ParticleIntegrator(new Gravity(),
                new LinearDrag(0.5f));
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.5f), detection));
        Vector3f start = new Vector3f(0f, 0.5f, 0f);
        Vector3f up = new Vector3f(0.5f, 2f, 0f);
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World w) {
                Body body = contact.getBodyA();
                if (body.getIntegrator() == fall) {
                    w.destroy(body);
                    w.addBody(fragmentForces, body.getPosition(), up, 0.1f, 0.02f);
                    w.addBody(fragmentForces, body.getPosition(), up, 0.1f, 0.02f);
                } else if (body.getFlightSeconds() > 0.4) {
                    w.destroy(body);
                }
            }
        });
        world.addBody(fall, start, Vector3f.ZERO, 1f, 0.1f);

        Allocations.assertAllocatesNothing(STEPS + " steps destroying and spawning", () -> {
            for (int i = 0; i < STEPS; ++i) {
                if (world.countBodies() == 0) {
                    world.addBody(fall, start, Vector3f.ZERO, 1f, 0.1f);
                }
                world.step(H);
            }
        });
        assertTrue(world.countRecycledBodies() <= 3, world.countRecycledBodies() + " pooled");
    }
}

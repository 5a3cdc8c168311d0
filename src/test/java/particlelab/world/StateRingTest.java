package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.collision.Plane;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleIntegrator;

/**
 * The state ring: a world stepped back and stepped forward again gives the same bits as the
 * first run, spawns and destroys in the epilogue included; the ring keeps to its byte budget;
 * recording allocates nothing.
 */
class StateRingTest {

    private static final float H = 1f / 60f;
    private static final int STEPS = 400;
    /** The epilogue spawns while fewer bodies than this are alive. */
    private static final int MAX_ALIVE = 12;

    @Test
    void slabKeepsEveryBit() {
        int[] block = new int[16];
        StateSlab slab = new StateSlab();
        slab.point(block, 1, 15);
        float payloadNaN = Float.intBitsToFloat(0x7fc0_1234);
        slab.putFloat(-0f);
        slab.putFloat(payloadNaN);
        slab.putDouble(Math.PI);
        slab.putLong(Long.MIN_VALUE + 12345L);
        slab.putBoolean(true);
        slab.putVector(new Vector3f(1f, -2f, Float.MIN_VALUE));
        assertEquals(10, slab.position());
        slab.point(block, 1, 15);
        assertEquals(Float.floatToRawIntBits(-0f), Float.floatToRawIntBits(slab.getFloat()));
        assertEquals(0x7fc0_1234, Float.floatToRawIntBits(slab.getFloat()));
        assertEquals(Double.doubleToRawLongBits(Math.PI),
                Double.doubleToRawLongBits(slab.getDouble()));
        assertEquals(Long.MIN_VALUE + 12345L, slab.getLong());
        assertTrue(slab.getBoolean());
        assertEquals(new Vector3f(1f, -2f, Float.MIN_VALUE), slab.getVector(new Vector3f()));
        slab.point(block, 0, 1);
        slab.putInt(7);
        assertThrows(IllegalStateException.class, () -> slab.putInt(8));
    }

    @Test
    void stepBackThenReplayGivesTheSameBitsWithSpawnsAndDestroys() {
        World world = spawningWorld();
        StateRing ring = new StateRing();
        ring.record(world, 0f);
        for (int i = 0; i < STEPS; ++i) {
            world.step(H);
            world.getImpacts().clear();
            ring.record(world, H);
        }
        assertTrue(world.getLog().getTotal() > 50, world.getLog().getTotal() + " contacts");
        assertTrue(world.countRecycledBodies() > 0, "some bodies were destroyed");
        int[][] first = new int[STEPS + 1][];
        for (int i = 0; i <= STEPS; ++i) {
            first[i] = ring.copyEntry(i);
        }
        for (int back : new int[] {1, 37, 150, STEPS}) {
            long from = ring.getLastIndex() - back;
            ring.restore(from, world);
            ring.truncateAfter(from);
            // The state read back writes the same bits as were recorded.
            StateRing again = new StateRing();
            again.record(world, 0f);
            assertArrayEquals(first[(int) from], again.copyEntry(0), "read back " + back);
            for (int i = 0; i < back; ++i) {
                world.step(H);
                world.getImpacts().clear();
                ring.record(world, H);
                long index = ring.getLastIndex();
                // Bit for bit: the step is deterministic, so no tolerance.
                assertArrayEquals(first[(int) index], ring.copyEntry(index),
                        "step " + index + " replayed after going back " + back);
            }
        }
    }

    @Test
    void ringKeepsToItsBudgetOverALongRun() {
        World world = spawningWorld();
        long budget = 256L * 1024L;
        StateRing ring = new StateRing(budget, StateRing.DEFAULT_MAX_STEPS);
        int longRun = 20_000;
        long most = 0L;
        for (int i = 0; i < longRun; ++i) {
            world.step(H);
            world.getImpacts().clear();
            ring.record(world, H);
            most = Math.max(most, ring.getBytes());
        }
        assertTrue(most <= budget, most + " bytes, budget " + budget);
        assertTrue(ring.getCapacity() < StateRing.DEFAULT_MAX_STEPS,
                "the budget, not the step cap, sized this ring");
        assertEquals(ring.getCapacity(), ring.size());
        assertEquals(longRun - 1, ring.getLastIndex());
        // capacity − 1 steps of h between the oldest and the newest entry; the sum in double
        // of a few hundred floats of h is exact to far better than 1e-9 s.
        assertEquals((ring.getCapacity() - 1) * (double) H, ring.getSpanSeconds(), 1e-9);
    }

    @Test
    void ringCapsItsSteps() {
        World world = spawningWorld();
        StateRing ring = new StateRing(StateRing.DEFAULT_BUDGET_BYTES, 100);
        for (int i = 0; i < 500; ++i) {
            world.step(H);
            world.getImpacts().clear();
            ring.record(world, H);
        }
        assertEquals(100, ring.size());
        assertEquals(400, ring.getFirstIndex());
        assertTrue(ring.getBytes() <= (long) Integer.BYTES * 100 * (ring.getStrideInts() + 2));
    }

    /** A fork's twin limits its ring before recording: two entries, then refused. */
    @Test
    void limitedStepsCapTheRingAndAreRefusedOnceItRecorded() {
        World world = spawningWorld();
        StateRing ring = new StateRing();
        ring.limitSteps(2);
        for (int i = 0; i < 50; ++i) {
            world.step(H);
            world.getImpacts().clear();
            ring.record(world, H);
        }
        assertEquals(2, ring.getCapacity());
        assertEquals(48, ring.getFirstIndex());
        assertThrows(IllegalStateException.class, () -> ring.limitSteps(2));
        assertThrows(IllegalArgumentException.class, () -> new StateRing().limitSteps(1));
        assertThrows(IllegalArgumentException.class,
                () -> new StateRing().limitSteps(StateRing.DEFAULT_MAX_STEPS + 1));
    }

    @Test
    void recordingAndRestoringAllocateNothing() {
        World world = spawningWorld();
        StateRing ring = new StateRing();
        for (int i = 0; i < 2 * STEPS; ++i) {
            world.step(H);
            world.getImpacts().clear();
            ring.record(world, H);
        }
        Allocations.assertAllocatesNothing("steps recorded, restored, replayed", () -> {
            ring.restore(ring.getLastIndex() - 100, world);
            ring.truncateAfter(ring.getLastIndex() - 100);
            for (int i = 0; i < 100; ++i) {
                world.step(H);
                world.getImpacts().clear();
                ring.record(world, H);
            }
        });
    }

    /**
     * Balls falling on the ground and on each other; a ball that hits the ground leaves in
     * the epilogue and two new ones are spawned above it while fewer than {@link #MAX_ALIVE}
     * are alive: a rule that reads only the world, so it needs no state of its own.
     */
    private static World spawningWorld() {
        World world = new World(64);
        ParticleIntegrator forces = new ParticleIntegrator(new Gravity(), new LinearDrag(0.05f));
        ParticleIntegrator free = new ParticleIntegrator(new Gravity());
        for (int i = 0; i < 4; ++i) {
            world.addBody(forces, new Vector3f(0.3f * i, 1f + i, 0f),
                    new Vector3f(1f - 0.5f * i, 0f, 0.2f * i), 1f + i, 0.2f);
        }
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.7f), Detection.SWEPT));
        world.addRule(new SurfaceRule("wall", new Plane(new Vector3f(-1f, 0f, 0f), -3f),
                new ImpulseResponse(0.9f), Detection.SWEPT));
        world.addRule(new SphereRule(new ImpulseResponse(0.8f), Detection.OVERLAP));
        Vector3f at = new Vector3f();
        Vector3f velocity = new Vector3f();
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World stepping) {
                Body body = contact.getBodyA();
                if (contact.getBodyB() != null || !body.isInWorld()
                        || body.getId() % 3 != 0) {
                    return;
                }
                stepping.destroy(body);
                for (int k = 0; k < 2 && stepping.countBodies() < MAX_ALIVE; ++k) {
                    at.set(body.getPosition()).addLocal(0.4f * k - 0.2f, 2f, 0f);
                    velocity.set(0.5f - k, 1f, 0f);
                    stepping.addBody(k == 0 ? free : forces, at, velocity, 0.5f, 0.15f);
                }
            }
        });
        return world;
    }
}

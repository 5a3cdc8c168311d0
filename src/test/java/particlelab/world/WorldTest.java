package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.VectorAssert;
import particlelab.collision.Plane;
import particlelab.collision.ThinWall;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.physics.Thrust;

/** The world's step: its order, its phases, its bookkeeping. */
class WorldTest {

    private static final float H = 1f / 60f;

    @Test
    void worldWithoutRulesStepsEachBodyExactlyAsItsIntegrator() {
        ParticleIntegrator drag = new ParticleIntegrator(new Gravity(), new LinearDrag(0.3f));
        ParticleIntegrator thrust = new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.05f),
                new Thrust(2f));
        World world = new World();
        Body a = world.addBody(drag, new Vector3f(0f, 1f, 0f), new Vector3f(10f, 10f, 0f), 2f, 0f);
        Body b = world.addBody(thrust, new Vector3f(1f, 2f, 3f), new Vector3f(-4f, 9f, 1f), 0.5f,
                0.2f);
        Particle expectA = new Particle(new Vector3f(0f, 1f, 0f), new Vector3f(10f, 10f, 0f), 2f);
        Particle expectB = new Particle(new Vector3f(1f, 2f, 3f), new Vector3f(-4f, 9f, 1f), 0.5f);
        for (int i = 0; i < 1000; ++i) {
            world.step(H);
            drag.step(expectA, H);
            thrust.step(expectB, H);
            assertBitwiseEqual(expectA, a.getParticle());
            assertBitwiseEqual(expectB, b.getParticle());
        }
        assertEquals(1000L, world.getStepCount());
        assertEquals(1000 * (double) H, a.getFlightSeconds(), 1e-9);
    }

    /**
     * A body given another integrator ({@link World#setIntegrator}: a demo's choice of how
     * its bodies step) steps by it from the next step on, bit for bit, and a state read back
     * gives the body the integrator it had when the state was written. Foreign bodies and
     * null are refused.
     */
    @Test
    void aBodyGivenAnotherIntegratorStepsByItAndTheStateNamesWhich() {
        ParticleIntegrator falling = new ParticleIntegrator(new Gravity());
        ParticleIntegrator coasting = new ParticleIntegrator();
        World world = new World();
        Body body = world.addBody(falling, new Vector3f(), new Vector3f(10f, 10f, 0f), 1f, 0f);
        world.step(H);
        int[] written = new int[world.countStateInts()];
        StateSlab slab = new StateSlab();
        slab.point(written, 0, written.length);
        world.writeState(slab);
        world.setIntegrator(body, coasting);
        Particle expected = new Particle();
        expected.copyFrom(body.getParticle());
        world.step(H);
        coasting.step(expected, H);
        assertBitwiseEqual(expected, body.getParticle());
        assertSame(coasting, body.getIntegrator());
        slab.point(written, 0, written.length);
        world.readState(slab);
        assertSame(falling, body.getIntegrator(), "the state names the integrator it had");
        assertThrows(IllegalArgumentException.class, () -> world.setIntegrator(body, null));
        Body foreign = new World().addBody(falling, new Vector3f(), new Vector3f(), 1f, 0f);
        assertThrows(IllegalArgumentException.class,
                () -> world.setIntegrator(foreign, coasting));
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void prologueThatIgnoresSkipsResolutionAndEpilogue(Detection detection) {
        World world = fallingBallOnGround(detection, 0.5f);
        List<Contact.Resolution> epilogues = new ArrayList<>();
        world.addContactListener(new ContactListener() {
            @Override
            public boolean accept(Contact contact, World w) {
                return false;
            }

            @Override
            public void resolved(Contact contact, World w) {
                epilogues.add(contact.getResolution());
            }
        });
        for (int i = 0; i < 120; ++i) {
            world.step(H);
        }
        // Free fall from 1 m: through the ground, never bounced.
        assertTrue(world.getBody(0).getPosition().y < -1f, world.getBody(0).toString());
        assertEquals(List.of(), epilogues);
        ContactLog log = world.getLog();
        assertTrue(log.size() > 0);
        for (int i = 0; i < log.size(); ++i) {
            assertEquals(Contact.Prologue.IGNORED_BY_LISTENER, log.get(i).getPrologue());
            assertEquals(Contact.Resolution.NONE, log.get(i).getResolution());
        }
        assertEquals(0, world.getImpacts().size(), "no effects for an ignored contact");
    }

    @Test
    void ghostsFiltersAndOneWaySurfacesAreIgnoredByTheWorldsOwnPrologue() {
        World world = new World();
        ParticleIntegrator fall = new ParticleIntegrator(new Gravity());
        Body ghost = world.addBody(fall, new Vector3f(0f, 1f, 0f), Vector3f.ZERO, 1f, 0.1f);
        ghost.setGhost(true);
        Body filtered = world.addBody(fall, new Vector3f(5f, 1f, 0f), Vector3f.ZERO, 1f, 0.1f);
        filtered.setCollisionFilter(2, ~1);
        Body rising = world.addBody(new ParticleIntegrator(), new Vector3f(9f, -1f, 0f),
                new Vector3f(0f, 5f, 0f), 1f, 0.1f);
        Body falling = world.addBody(fall, new Vector3f(-5f, 1f, 0f), Vector3f.ZERO, 1f, 0.1f);
        // A one-way floor at y = 0: things fall onto it, things from below pass up through.
        world.addRule(new SurfaceRule("floor", new ThinWall(Vector3f.UNIT_Y, 0f, 0.05f),
                new ImpulseResponse(0f), Detection.SWEPT).setOneWay(true));
        for (int i = 0; i < 120; ++i) {
            world.step(H);
        }
        assertTrue(ghost.getPosition().y < -1f, "the ghost falls through");
        assertTrue(filtered.getPosition().y < -1f, "group 2 does not touch group 1");
        assertTrue(rising.getPosition().y > 5f, "from below, the one-way floor lets it pass");
        assertEquals(0.125f, falling.getPosition().y, 1e-6f, "rests on the floor: r + D/2");
        ContactLog log = world.getLog();
        boolean[] seen = new boolean[Contact.Prologue.values().length];
        for (int i = 0; i < log.size(); ++i) {
            seen[log.get(i).getPrologue().ordinal()] = true;
        }
        assertTrue(seen[Contact.Prologue.IGNORED_GHOST.ordinal()]);
        assertTrue(seen[Contact.Prologue.IGNORED_BY_FILTER.ordinal()]);
        assertTrue(seen[Contact.Prologue.IGNORED_ONE_WAY.ordinal()]);
        assertTrue(seen[Contact.Prologue.ACCEPTED.ordinal()]);
    }

    @Test
    void epilogueRunsAfterEveryResolutionOfTheStepInTimeOrder() {
        // Two balls reach the ground in the same step, the first earlier in the step.
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        Body early = world.addBody(none, new Vector3f(0f, 0.05f, 0f), new Vector3f(0f, -6f, 0f),
                1f, 0f);
        Body late = world.addBody(none, new Vector3f(3f, 0.08f, 0f), new Vector3f(0f, -6f, 0f),
                1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(1f, 0f, false), Detection.SWEPT));
        List<Body> order = new ArrayList<>();
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World w) {
                // Both already bounced, whichever contact the epilogue is at.
                assertTrue(early.getVelocity().y > 0f && late.getVelocity().y > 0f);
                order.add(contact.getBodyA());
            }
        });
        world.step(H);
        assertEquals(List.of(early, late), order);
        assertTrue(world.getLog().get(0).getTimeSeconds() < world.getLog().get(1).getTimeSeconds());
        // Each continues for the rest of the step at +6 m/s from its own impact.
        assertEquals((H - 0.05f / 6f) * 6f, early.getPosition().y, 1e-6f);
        assertEquals((H - 0.08f / 6f) * 6f, late.getPosition().y, 1e-6f);
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void newtonsCradlePassesTheImpulseDownTheRow(Detection detection) {
        // Four touching balls at rest, a fifth arrives: e = 1, equal masses, so the last ball
        // leaves at the incoming speed and the others stop (to round-off).
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        float r = 0.5f;
        Body hitter = world.addBody(none, new Vector3f(-3f, 0f, 0f), new Vector3f(4f, 0f, 0f),
                1f, r);
        List<Body> row = new ArrayList<>();
        for (int i = 0; i < 4; ++i) {
            row.add(world.addBody(none, new Vector3f(2f * r * i, 0f, 0f), Vector3f.ZERO, 1f, r));
        }
        world.addRule(new SphereRule(new ImpulseResponse(1f, 0f, false), detection));
        for (int i = 0; i < 60; ++i) {
            world.step(H);
        }
        VectorAssert.assertVectorEquals(new Vector3f(4f, 0f, 0f), row.get(3).getVelocity(),
                1e-5f, "last ball");
        VectorAssert.assertVectorEquals(Vector3f.ZERO, hitter.getVelocity(), 1e-5f);
        for (int i = 0; i < 3; ++i) {
            VectorAssert.assertVectorEquals(Vector3f.ZERO, row.get(i).getVelocity(), 1e-5f,
                    "ball " + i);
        }
        assertFalse(world.getCapHits() > 0L);
    }

    @Test
    void reachingTheImpactCapIsReported() {
        // A ball rattling in a gap barely wider than itself: ~10 bounces a step, cap 4.
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(), new Vector3f(0f, 0.125f, 0f),
                new Vector3f(0f, 30f, 0f), 1f, 0.1f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(1f, 0f, false), Detection.SWEPT));
        world.addRule(new SurfaceRule("ceiling", new Plane(new Vector3f(0f, -1f, 0f), -0.25f),
                new ImpulseResponse(1f, 0f, false), Detection.SWEPT));
        world.setMaxImpactsPerStep(4);
        world.step(H);
        assertTrue(world.didLastStepHitCap());
        assertEquals(1L, world.getCapHits());
        assertEquals(4, world.getLog().size(), "the cap's impacts, each logged");
        assertTrue(ball.getPosition().y > 0.09f && ball.getPosition().y < 0.16f,
                "stays in the gap: " + ball);
    }

    @Test
    void destroyAndSpawnCyclesLeaveNothingBehind() {
        World world = new World(32);
        ParticleIntegrator fall = new ParticleIntegrator(new Gravity());
        ParticleIntegrator fragmentForces = new ParticleIntegrator(new Gravity(),
                new LinearDrag(0.5f));
        Map<Body, String> views = new IdentityHashMap<>();
        world.addBodyListener(new BodyListener() {
            @Override
            public void bodyAdded(World w, Body body) {
                views.put(body, "view");
            }

            @Override
            public void bodyRemoved(World w, Body body) {
                assertTrue(views.remove(body) != null, "removed once");
            }
        });
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.5f), Detection.SWEPT));
        int[] cycles = {0};
        Vector3f up = new Vector3f();
        world.addContactListener(new ContactListener() {
            @Override
            public void resolved(Contact contact, World w) {
                Body body = contact.getBodyA();
                if (body.getIntegrator() == fall) {
                    w.destroy(body);
                    w.destroy(body);
                    contact.setEpilogueNote("destroyed target");
                    for (int k = 0; k < 3; ++k) {
                        up.set(k - 1f, 3f, 0f);
                        w.addBody(fragmentForces, body.getPosition(), up, 0.1f, 0.02f);
                    }
                    ++cycles[0];
                }
            }
        });
        world.addStepListener(new StepListener() {
            @Override
            public void afterStep(World w, float h) {
                for (int i = w.countBodies() - 1; i >= 0; --i) {
                    if (w.getBody(i).getFlightSeconds() > 0.5) {
                        w.destroy(w.getBody(i));
                    }
                }
            }
        });
        Vector3f start = new Vector3f(0f, 0.3f, 0f);
        int steps = 0;
        while (cycles[0] < 150 && steps < 100_000) {
            if (world.countBodies() == 0) {
                world.addBody(fall, start, Vector3f.ZERO, 1f, 0.1f);
            }
            world.step(H);
            world.getImpacts().clear();
            ++steps;
        }
        while (world.countBodies() > 0) {
            world.step(H);
        }
        assertEquals(150, cycles[0]);
        assertEquals(0, world.countBodies());
        assertTrue(views.isEmpty(), views.size() + " views left");
        assertTrue(world.countRecycledBodies() <= 4, world.countRecycledBodies() + " pooled");
        assertEquals(1, world.countContactListeners());
        assertEquals(1, world.countStepListeners());
        assertEquals(1, world.countBodyListeners());
        assertEquals(32, world.getLog().size());
        assertTrue(world.getLog().getTotal() >= 150L);
        assertEquals("destroyed target", findNote(world.getLog()));
    }

    @Test
    void logIsBoundedAndKeepsTheNewestInOrder() {
        World world = new World(8);
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()), new Vector3f(0f, 0f, 0f),
                Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0f), Detection.SWEPT));
        for (int i = 0; i < 100; ++i) {
            world.step(H);
        }
        ContactLog log = world.getLog();
        assertEquals(8, log.size());
        assertEquals(100L, log.getTotal(), "a resting contact every step");
        for (int i = 1; i < log.size(); ++i) {
            assertEquals(log.get(i - 1).getSequence() + 1, log.get(i).getSequence());
        }
        assertEquals(99L, log.latest().getSequence());
        assertEquals(ball.getId(), log.latest().getBodyA());
        assertEquals(-1, log.latest().getBodyB());
        assertThrows(IndexOutOfBoundsException.class, () -> log.get(8));
    }

    @Test
    void nonFiniteStepThrowsAndLeavesTheWorldUsable() {
        World world = new World();
        // h = 1/60 s is far beyond 2m/b = 2e-4 s: the velocity grows 166x a step.
        Body body = world.addBody(new ParticleIntegrator(new LinearDrag(1e4f)), new Vector3f(),
                new Vector3f(1f, 0f, 0f), 1f, 0f);
        IllegalStateException thrown = assertThrows(IllegalStateException.class, () -> {
            for (int i = 0; i < 1000; ++i) {
                world.step(H);
            }
        });
        assertTrue(thrown.getMessage().contains("non-finite"), thrown.getMessage());
        assertTrue(body.getParticle().isFinite());
        assertFalse(world.isStepping());
    }

    @Test
    void restartFromInsideAStepIsRefusedAndFromOutsideReturnsToTheLaunch() {
        World world = fallingBallOnGround(Detection.SWEPT, 0.5f);
        StepListener restarter = new StepListener() {
            @Override
            public void afterStep(World w, float h) {
                w.restart();
            }
        };
        world.addStepListener(restarter);
        assertThrows(IllegalStateException.class, () -> world.step(H));
        assertFalse(world.isStepping());
        world.removeStepListener(restarter);
        world.step(H);
        world.restart();
        assertEquals(0.0, world.getTimeSeconds());
        VectorAssert.assertVectorEquals(new Vector3f(0f, 1f, 0f),
                world.getBody(0).getPosition(), 0f);
        assertEquals(0, world.getLog().size());
    }

    @Test
    void impactsQueueLoudnessFollowsTheApproachSpeedAboveTheHitThreshold() {
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        world.addBody(none, new Vector3f(0f, 0.01f, 0f), new Vector3f(0f, -0.4f, 0f), 1f, 0f);
        world.addBody(none, new Vector3f(1f, 0.01f, 0f), new Vector3f(0f, -5.25f, 0f), 1f, 0f);
        world.addBody(none, new Vector3f(2f, 0.1f, 0f), new Vector3f(0f, -12f, 0f), 1f, 0f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(0.5f), Detection.SWEPT));
        world.getImpacts().setSpeeds(0.5f, 10f);
        for (int i = 0; i < 3; ++i) {
            world.step(H);
        }
        Impacts impacts = world.getImpacts();
        assertEquals(2, impacts.size(), "0.4 m/s is below the 0.5 m/s hit threshold");
        assertEquals(0.5f, impacts.get(0).getLoudness(), 1e-6f, "(5.25 - 0.5)/(10 - 0.5)");
        assertEquals(1f, impacts.get(1).getLoudness(), 0f, "clamped");
        VectorAssert.assertVectorEquals(new Vector3f(1f, 0f, 0f), impacts.get(0).getPoint(),
                1e-6f);
        impacts.clear();
        assertEquals(0, impacts.size());
    }

    @Test
    void scriptedStickHoldsTheBodyWhereItHitAndBreaksMomentumOnPurpose() {
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, 1f, 0f), new Vector3f(2f, 0f, 0f), 1f, 0.1f);
        world.addRule(SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT));
        for (int i = 0; i < 120; ++i) {
            world.step(H);
        }
        assertTrue(ball.isHeld());
        assertEquals(0.1f, ball.getPosition().y, 1e-6f, "stuck touching the ground");
        VectorAssert.assertVectorEquals(Vector3f.ZERO, ball.getVelocity(), 0f);
        double stuckAt = ball.getScriptedSinceSeconds();
        assertTrue(stuckAt > 0.3 && stuckAt < 0.5, "fell 0.9 m in about 0.43 s: " + stuckAt);
        assertEquals(Contact.Resolution.STUCK, world.getLog().latest().getResolution());
        assertEquals(1, world.getLog().size(), "a held body has no further contacts");
    }

    @Test
    void clipResponseStopsBothBodiesAndHandsThemToTheScriptWhateverTheImpact() {
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        // Two pairs far apart, closing at 2 and at 9 m/s: the clip's start knows neither.
        Body slow = world.addBody(none, new Vector3f(0f, 0f, 0f), new Vector3f(2f, 0f, 0f), 1f,
                0.5f);
        Body slowTarget = world.addBody(none, new Vector3f(1.02f, 0f, 0f), Vector3f.ZERO, 2f,
                0.5f);
        Body fast = world.addBody(none, new Vector3f(0f, 10f, 0f), new Vector3f(9f, 0f, 0f), 1f,
                0.5f);
        Body fastTarget = world.addBody(none, new Vector3f(1.1f, 10f, 0f), Vector3f.ZERO, 2f,
                0.5f);
        world.addRule(new SphereRule(ScriptedResponse.clip(), Detection.SWEPT));
        world.step(H);
        Body[] all = {slow, slowTarget, fast, fastTarget};
        for (Body body : all) {
            assertEquals(0f, body.getVelocity().length(), 0f, body + " stopped at the touch");
            assertTrue(body.isKinematic(), body + " is the script's now");
            assertTrue(body.getScriptedSinceSeconds() > 0.0
                    && body.getScriptedSinceSeconds() < H, "its clip starts at the contact");
        }
        assertEquals(Contact.Resolution.CLIP, world.getLog().latest().getResolution());
    }

    @Test
    void badArgumentsAreRefusedWithTheirNames() {
        World world = new World();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> world.addBody(new ParticleIntegrator(), Vector3f.ZERO, Vector3f.ZERO, -1f,
                        0f));
        assertTrue(e.getMessage().contains("mass"), e.getMessage());
        assertEquals(0, world.countBodies());
        assertEquals(1, world.countRecycledBodies(), "the refused body went back to the pool");
        e = assertThrows(IllegalArgumentException.class, () -> new ImpulseResponse(1.5f));
        assertTrue(e.getMessage().contains("restitution"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> world.step(Float.NaN));
        Body body = world.addBody(new ParticleIntegrator(), Vector3f.ZERO, Vector3f.ZERO, 1f, 0f);
        world.destroy(body);
        assertThrows(IllegalArgumentException.class, () -> world.destroy(body));
        assertNotEquals(null, body.toString());
    }

    private static World fallingBallOnGround(Detection detection, float e) {
        World world = new World();
        world.addBody(new ParticleIntegrator(new Gravity()), new Vector3f(0f, 1f, 0f),
                Vector3f.ZERO, 1f, 0.1f);
        world.addRule(SurfaceRule.ground(new ImpulseResponse(e), detection));
        return world;
    }

    private static String findNote(ContactLog log) {
        for (int i = 0; i < log.size(); ++i) {
            if (log.get(i).getEpilogueNote() != null) {
                return log.get(i).getEpilogueNote();
            }
        }
        return null;
    }

    @Test
    void flightTimeCountsAStepOnceItsContactsAreOverAsTheWorldsTimeDoes() {
        World world = new World();
        Body ball = world.addBody(new ParticleIntegrator(new Gravity()),
                new Vector3f(0f, 0.1f, 0f), Vector3f.ZERO, 1f, 0f);
        world.addRule(SurfaceRule.ground(ScriptedResponse.stick(), Detection.SWEPT));
        double[] seen = {Double.NaN, Double.NaN, Double.NaN};
        world.addContactListener(new ContactListener() {
            @Override
            public boolean accept(Contact contact, World w) {
                seen[0] = contact.getBodyA().getFlightSeconds();
                return true;
            }

            @Override
            public void resolved(Contact contact, World w) {
                seen[1] = contact.getBodyA().getFlightSeconds();
                seen[2] = w.getTimeSeconds();
            }
        });
        double start = 0.0;
        int steps = 0;
        while (!ball.isHeld()) {
            assertTrue(steps < 100, "never landed");
            if (steps > 0) {
                start += H;
            }
            world.step(H);
            ++steps;
        }
        // During the landing step's contacts: the step's start, for time and flight alike,
        // so a contact's time since the launch is the flight time plus fraction·h.
        assertEquals(start, seen[0], 0.0);
        assertEquals(start, seen[1], 0.0);
        assertEquals(start, seen[2], 0.0);
        assertEquals(start + H, ball.getFlightSeconds(), 0.0);
        world.step(H);
        assertEquals(start + H, ball.getFlightSeconds(), 0.0, "held: no flight");
    }

    private static void assertBitwiseEqual(Particle expected, Particle actual) {
        assertEquals(expected.position.x, actual.position.x);
        assertEquals(expected.position.y, actual.position.y);
        assertEquals(expected.position.z, actual.position.z);
        assertEquals(expected.velocity.x, actual.velocity.x);
        assertEquals(expected.velocity.y, actual.velocity.y);
        assertEquals(expected.velocity.z, actual.velocity.z);
        assertSame(expected.getClass(), actual.getClass());
    }
}

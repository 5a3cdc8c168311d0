package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import particlelab.Allocations;
import particlelab.app.DemoCatalog;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.DragDemo;
import particlelab.physics.Force;
import particlelab.physics.LinearDrag;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;
import particlelab.world.StateRing;

/**
 * What-if forks in plain JUnit (no jME): a twin of a demo takes a recorded state and runs on
 * with one change. Every comparison is of whole ring entries (t, each particle's P and V,
 * the world, the counters, the demo's own state) bit for bit: the step is deterministic, so
 * no tolerance; any difference is state the fork failed to copy or a change applied
 * differently.
 */
class WhatIfForkTest {

    /** The span: the fork's future compared over this many steps. */
    private static final int FUTURE_STEPS = 300;
    /** The recorded step forked from: the flight under way. */
    private static final int FORK_STEP = 40;
    /** The changed step h' (in seconds): one of the panel's stops, 1/30 s. */
    private static final float H_PRIME = 1f / 30f;

    /** A fork with nothing changed has the demo's own recorded future, bit for bit. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"uniform", "pull", "drag", "thrust", "bounce"})
    void aForkWithNothingChangedIsTheOriginalFuture(String name) {
        DemoState origin = create(name);
        StateRing ring = origin.getRun().getStateRing();
        stepSingly(origin, FORK_STEP + FUTURE_STEPS);
        WhatIfFork fork = new WhatIfFork(create(name));
        fork.start(origin, FORK_STEP, null, 0f);
        assertSameFuture(ring, fork, name);
    }

    /**
     * A fork with h' from a recorded step equals the run that reached that step and went on
     * at h' (h set with {@code --set}'s parameter at that step, then stepped). Not uniform:
     * at h' = 1/30 s its sphere leaves the screen within the span and the demo loops by a
     * reset, which clears the ring and numbers its entries from 0 again.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pull", "drag", "thrust", "bounce"})
    void aForkWithAnotherStepIsTheRunStartedThereAtThatStep(String name) {
        DemoState origin = create(name);
        stepSingly(origin, FORK_STEP);
        DemoState reference = create(name);
        stepSingly(reference, FORK_STEP);
        reference.getParameters().set("h", H_PRIME);
        StateRing referenceRing = reference.getRun().getStateRing();
        stepSingly(reference, FUTURE_STEPS);
        assertEquals(H_PRIME, referenceRing.getStepSeconds(referenceRing.getLastIndex()));

        WhatIfFork fork = new WhatIfFork(create(name));
        fork.start(origin, FORK_STEP, "h", H_PRIME);
        assertSameFuture(referenceRing, fork, name + " at h'");
    }

    /**
     * A fork with the drag laws swapped ({@code drag=swapped}) equals the run that reached
     * the forked step with the labelled laws and went on swapped, every entry bit for bit.
     */
    @Test
    void aForkWithTheDragLawsSwappedIsTheRunSwappedThere() {
        DemoState origin = create("drag");
        stepSingly(origin, FORK_STEP);
        DemoState reference = create("drag");
        stepSingly(reference, FORK_STEP);
        reference.getParameters().set("drag", 1f);
        StateRing referenceRing = reference.getRun().getStateRing();
        stepSingly(reference, FUTURE_STEPS);

        WhatIfFork fork = new WhatIfFork(create("drag"));
        fork.start(origin, FORK_STEP, "drag", 1f);
        assertSameFuture(referenceRing, fork, "drag laws swapped");
        assertTrue(fork.getRun().getParticles().get(1).getLabel().startsWith("swapped"),
                "the swapped sphere says so on its label");
    }

    /**
     * The swapped laws keep each sphere's terminal speed: the linear sphere's quadratic drag
     * has {@code √(m·g/c') = m·g/b}, the quadratic sphere's linear drag
     * {@code m·g/b' = √(m·g/c)}; and stepped for a long time (50 s, far past the approach,
     * which decays like {@code e^(−g·t/v_t)} or faster) with the forces the swap gives the
     * bodies, each sphere's speed settles on that v_t (the Euler step's fixed point is where
     * a = 0).
     */
    @Test
    void swappedLawsKeepTheTerminalSpeeds() {
        DragDemo drag = new DragDemo();
        double linear = drag.terminalSpeed(1);
        double quadratic = drag.terminalSpeed(2);
        drag.getParameters().set("drag", 1f);
        assertTrue(drag.isSwapped());
        ParticleIntegrator linearSphere = drag.getWorld().getBody(1).getIntegrator();
        ParticleIntegrator quadraticSphere = drag.getWorld().getBody(2).getIntegrator();
        float cPrime = coefficient(linearSphere, QuadraticDrag.class);
        float bPrime = coefficient(quadraticSphere, LinearDrag.class);
        double weight = 9.8 * drag.getParticles().get(1).getParticle().getMass();
        // c' and b' are rounded to floats (2⁻²⁴ relative); v_t goes as c'^(-1/2) and 1/b',
        // so 1e-6 relative covers them with room
        assertEquals(linear, Math.sqrt(weight / cPrime), 1e-6 * linear);
        assertEquals(quadratic, weight / bPrime, 1e-6 * quadratic);
        // at the lecture's numbers: c' = b²/(m·g) = 0.81/9.8, b' = √(m·g·c) = √(9.8·0.064)
        assertEquals(0.81 / 9.8, cPrime, 1e-7);
        assertEquals(Math.sqrt(9.8 * 0.064), bPrime, 1e-6);
        // The speeds the stepped spheres settle on: float steps near v_t ≈ 11-12 m/s move V by
        // h·a with a → 0; the fixed point holds to a few ulps of v_t (1e-6 relative ≈ 8 ulps)
        assertEquals(linear, settledSpeed(linearSphere), 1e-5 * linear);
        assertEquals(quadratic, settledSpeed(quadraticSphere), 1e-5 * quadratic);
        // the HUD says what changed, with the two constants (docs/demos/drag.md quotes it)
        StringBuilder hud = new StringBuilder();
        drag.getWindow().formatHud(hud);
        assertTrue(hud.toString().contains("\nLaws swapped (drag), v_t kept:  c' = b²/(mg) ="
                + " 0.083 kg/m,  b' = mg/v_t = 0.792 N s/m\n"), hud.toString());
    }

    /**
     * A fork with forward Euler ({@code method=euler}) is forward Euler from the forked state,
     * bit for bit: the same code run in the test, {@code P ← P + h·V} with the old V, then
     * {@code V ← V + h·a} with a the sphere's forces give at the step's start (the recipe's
     * first line, {@link ParticleIntegrator#acceleration}), in float, every sphere, every step
     * until it lands. And it is forward Euler, not the recipe: under gravity alone its
     * samples lie on forward Euler's closed form {@code P_n = P_0 + n·h·V_0 + g·h²·n(n−1)/2}.
     */
    @Test
    void aForkWithForwardEulerIsForwardEulerFromTheForkedState() {
        DemoState origin = create("drag");
        stepSingly(origin, FORK_STEP);
        float h = origin.getClock().getStepSeconds();
        int spheres = 3;
        Particle[] expected = new Particle[spheres];
        ParticleIntegrator[] forces = new ParticleIntegrator[spheres];
        for (int i = 0; i < spheres; ++i) {
            DemoParticle sphere = origin.getParticles().get(i);
            expected[i] = new Particle();
            expected[i].copyFrom(sphere.getParticle());
            forces[i] = sphere.getIntegrator();
        }
        Vector3f start = expected[0].position.clone();
        Vector3f startVelocity = expected[0].velocity.clone();
        WhatIfFork fork = new WhatIfFork(create("drag"));
        fork.start(origin, FORK_STEP, "method", MethodPart.FORWARD_EULER);
        MethodPart method = ((DragDemo) fork.getTwin()).getMethod();
        Vector3f a = new Vector3f();
        Vector3f velocity = new Vector3f();
        int compared = 0;
        for (int k = 1; k <= FUTURE_STEPS; ++k) {
            fork.step();
            for (int i = 0; i < spheres; ++i) {
                DemoParticle sphere = fork.getRun().getParticles().get(i);
                if (sphere.hasLanded()) {
                    continue;
                }
                Particle p = expected[i];
                forces[i].acceleration(p, a);
                p.position.set(p.position.x + h * p.velocity.x, p.position.y + h * p.velocity.y,
                        p.position.z + h * p.velocity.z);
                p.velocity.set(p.velocity.x + h * a.x, p.velocity.y + h * a.y,
                        p.velocity.z + h * a.z);
                assertBits(p.position, sphere.getParticle().position, "sphere " + i
                        + ", step " + k + ": P");
                assertBits(p.velocity, method.copyNextVelocity(sphere, velocity), "sphere " + i
                        + ", step " + k + ": V");
                ++compared;
                if (i == 0) {
                    // forward Euler's closed form under gravity, in double; float round-off
                    // of P (|P| < 20 m: ulp 2e-6 m) over at most 300 steps stays under 1e-3 m,
                    // where the recipe lies g·h²·n away (0.27 m at n = 100)
                    double n = k;
                    double g = -9.8;
                    assertEquals(start.x + n * h * startVelocity.x, p.position.x, 1e-3);
                    assertEquals(start.y + n * h * startVelocity.y
                            + g * h * (double) h * n * (n - 1.0) / 2.0, p.position.y, 1e-3);
                }
            }
        }
        assertTrue(compared > 100, "compared " + compared + " sphere steps in flight");
    }

    /**
     * Three forks stepped long past the demo's ring: each twin keeps two entries, so all
     * three together cost less than the demo's own ring (without the limit each twin's ring
     * would size itself as the demo's does, three times its bytes).
     */
    @Test
    void forksStayWithinTheRingsCap() {
        DemoState origin = create("drag");
        stepSingly(origin, FORK_STEP);
        StateRing ring = origin.getRun().getStateRing();
        long twinBytes = 0L;
        String[] names = {"h", "drag", "method"};
        float[] values = {H_PRIME, 1f, MethodPart.FORWARD_EULER};
        for (int f = 0; f < names.length; ++f) {
            WhatIfFork fork = new WhatIfFork(create("drag"));
            fork.start(origin, FORK_STEP, names[f], values[f]);
            for (int k = 0; k < 2 * StateRing.DEFAULT_MAX_STEPS; ++k) {
                fork.step();
            }
            StateRing twinRing = fork.getRun().getStateRing();
            assertEquals(WhatIfFork.TWIN_RING_STEPS, twinRing.getCapacity());
            assertTrue(twinRing.size() <= WhatIfFork.TWIN_RING_STEPS);
            twinBytes += twinRing.getBytes();
        }
        assertTrue(twinBytes <= ring.getBytes(), "three forks' rings take " + twinBytes
                + " bytes, the demo's ring " + ring.getBytes());
    }

    /**
     * Keeping a fork: the demo goes on from the forked step with the change and ends in the
     * fork's state, bit for bit; at bounce, whose e resets the drop, too.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"drag:h:0.033333335", "drag:drag:1", "drag:method:1",
        "bounce:e:0.6", "bounce:h:0.033333335"})
    void keepingAForkGoesOnFromItsState(String spec) {
        String[] parts = spec.split(":");
        DemoState origin = create(parts[0]);
        stepSingly(origin, FORK_STEP + FUTURE_STEPS);
        WhatIfFork fork = new WhatIfFork(create(parts[0]));
        fork.start(origin, FORK_STEP, parts[1], Float.parseFloat(parts[2]));
        for (int k = 0; k < FUTURE_STEPS / 2; ++k) {
            fork.step();
        }
        fork.keep(origin);
        StateRing ring = origin.getRun().getStateRing();
        StateRing twinRing = fork.getRun().getStateRing();
        assertArrayEquals(twinRing.copyEntry(twinRing.getLastIndex()),
                ring.copyEntry(ring.getLastIndex()), spec + ": the kept state");
        assertEquals(Float.parseFloat(parts[2]), origin.getParameters().getValue(parts[1]));
    }

    /**
     * The part's keys without a window: Insert forks lanes with the changes offered in turn,
     * the HUD line names them, frames move them on, J keeps the newest (the demo's state is
     * then the lane's, bit for bit), and a fourth Insert drops three lanes.
     */
    @Test
    void thePartForksKeepsAndDropsLanes() {
        BounceDemo bounce = new BounceDemo();
        stepSingly(bounce, FORK_STEP);
        WhatIfPart whatIf = bounce.getWhatIf();
        for (int lane = 0; lane < WhatIfPart.MAX_LANES; ++lane) {
            whatIf.forkOrDrop();
        }
        assertEquals(WhatIfPart.MAX_LANES, whatIf.countLanes());
        StringBuilder hud = new StringBuilder();
        whatIf.writeHudLines(hud);
        assertEquals("what if (J keeps the newest, Insert drops them):  pink as recorded,"
                + "  yellow e = 0.6,  lilac h = 1/30 s;  next: as recorded\n", hud.toString());
        for (int frame = 0; frame < 60; ++frame) {
            whatIf.afterFrame();
        }
        // 60 frames of 1/60 s of lane time: 60 steps at h = 1/60 s, 30 at 1/30 s (a lane
        // steps up to the nearest step's end, so a float h a little over 1/60 loses none).
        assertEquals(60, whatIf.getLane(0).getSteps());
        assertEquals(60, whatIf.getLane(1).getSteps());
        assertEquals(30, whatIf.getLane(2).getSteps());
        WhatIfFork newest = whatIf.getLane(2);
        whatIf.keepNewest();
        assertEquals(0, whatIf.countLanes());
        StateRing ring = bounce.getRun().getStateRing();
        StateRing twinRing = newest.getRun().getStateRing();
        assertArrayEquals(twinRing.copyEntry(twinRing.getLastIndex()),
                ring.copyEntry(ring.getLastIndex()), "the kept lane's state");
        assertEquals(1f / 30f, bounce.getParameters().getValue("h"));
        for (int lane = 0; lane <= WhatIfPart.MAX_LANES; ++lane) {
            whatIf.forkOrDrop();
        }
        assertEquals(0, whatIf.countLanes(), "a fourth Insert drops the lanes");
    }

    /**
     * Drag's changes in the order Delete offers them, named on the HUD line: a choice by its
     * value's name (the laws swapped, forward Euler), not its index; the demo's own HUD then
     * says what a kept change runs.
     */
    @Test
    void dragForksNameTheLawAndTheMethod() {
        DragDemo drag = new DragDemo();
        stepSingly(drag, FORK_STEP);
        WhatIfPart whatIf = drag.getWhatIf();
        // as recorded, h, b; a fourth Insert drops them; then the laws and the method
        for (int insert = 0; insert < WhatIfPart.MAX_LANES + 3; ++insert) {
            whatIf.forkOrDrop();
        }
        StringBuilder hud = new StringBuilder();
        whatIf.writeHudLines(hud);
        assertEquals("what if (J keeps the newest, Insert forks another):  pink drag = swapped,"
                + "  yellow method = euler;  next: as recorded\n", hud.toString());
        whatIf.keepNewest();
        hud.setLength(0);
        drag.getMethod().writeHudLines(hud);
        assertEquals("Method (method): forward Euler: P += h·V with the old V, then V += h·a"
                + " (not the lecture's recipe)\n", hud.toString());
    }

    /**
     * Lanes going on frame by frame, and their HUD line, allocate nothing: every change drag
     * offers, the swapped laws and forward Euler among them.
     */
    @Test
    void lanesGoingOnAllocateNothing() {
        DragDemo drag = new DragDemo();
        stepSingly(drag, FORK_STEP);
        WhatIfPart whatIf = drag.getWhatIf();
        StringBuilder hud = new StringBuilder(256);
        for (int round = 0; round < 2; ++round) {
            for (int lane = 0; lane < WhatIfPart.MAX_LANES; ++lane) {
                whatIf.forkOrDrop();
            }
            whatIf.afterFrame();
            Allocations.assertAllocatesNothing("what-if lanes, 60 frames", () -> {
                for (int frame = 0; frame < 60; ++frame) {
                    whatIf.afterFrame();
                    hud.setLength(0);
                    whatIf.writeHudLines(hud);
                }
            });
            assertTrue(whatIf.getLane(0).getSteps() > 60, "the lanes moved on");
            // a fourth Insert drops them; the next round forks the next three changes
            whatIf.forkOrDrop();
        }
    }

    /**
     * Step a fork {@link #FUTURE_STEPS} times and compare each state with the recorded
     * future: a flight that lands stops there (its scene is over, no step is taken), and the
     * fork must land at the same step and stay there.
     */
    private static void assertSameFuture(StateRing expected, WhatIfFork fork, String name) {
        StateRing twinRing = fork.getRun().getStateRing();
        long expectedLast = expected.getLastIndex();
        for (int k = 1; k <= FUTURE_STEPS; ++k) {
            fork.step();
            long index = Math.min(FORK_STEP + k, expectedLast);
            assertArrayEquals(expected.copyEntry(index),
                    twinRing.copyEntry(twinRing.getLastIndex()),
                    name + ": step " + k + " after the fork");
        }
        // The twin's ring counts its steps from the fork's start (entry 0).
        assertEquals(expectedLast - FORK_STEP, twinRing.getLastIndex(),
                name + ": steps taken after the fork");
    }

    /** The one coefficient of a force class the integrator holds. */
    private static float coefficient(ParticleIntegrator integrator, Class<?> type) {
        for (int k = 0; k < integrator.countForces(); ++k) {
            Force force = integrator.getForce(k);
            if (type.isInstance(force)) {
                return force instanceof LinearDrag ? ((LinearDrag) force).getCoefficient()
                        : ((QuadraticDrag) force).getCoefficient();
            }
        }
        throw new AssertionError("no " + type.getSimpleName() + " in " + integrator.describe());
    }

    /** The speed a particle launched at (10, 10) settles on after 50 s of recipe steps. */
    private static double settledSpeed(ParticleIntegrator forces) {
        Particle particle = new Particle();
        particle.velocity.set(10f, 10f, 0f);
        for (int n = 0; n < 3000; ++n) {
            forces.step(particle, 1f / 60f);
        }
        return particle.velocity.length();
    }

    private static void assertBits(Vector3f expected, Vector3f actual, String what) {
        assertArrayEquals(new int[] {Float.floatToIntBits(expected.x),
            Float.floatToIntBits(expected.y), Float.floatToIntBits(expected.z)},
                new int[] {Float.floatToIntBits(actual.x), Float.floatToIntBits(actual.y),
                    Float.floatToIntBits(actual.z)}, what + ": expected " + expected + ", was "
                + actual);
    }

    private static DemoState create(String name) {
        return DemoCatalog.entries().get(DemoCatalog.indexOf(name)).create();
    }

    /** Take steps one at a time with the demo's single step, as N does. */
    private static void stepSingly(DemoState demo, int steps) {
        for (int i = 0; i < steps; ++i) {
            demo.getRun().singleStep();
            demo.getRun().advancePhysics(0f);
        }
    }
}

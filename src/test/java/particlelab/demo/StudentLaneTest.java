package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;
import particlelab.reference.MotionState;
import particlelab.reference.SlideCode;
import particlelab.coursework.RecipeExercise;
import particlelab.lecture.DragDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.ThrustDemo;
import particlelab.lecture.UniformMotionDemo;
import particlelab.physics.Gravity;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.QuadraticDrag;

/**
 * The comparison lane's {@code student} (issue 31 §3), in plain JUnit: exercise 1's class
 * found by name and stepped on a worker thread. With the reference solution it flies the
 * shared step's floats; the stub, a recipe that throws, one that gives NaN, one that never
 * returns and a missing class each stop the lane with one line while the demo runs on.
 */
class StudentLaneTest {

    private static final float H = 1f / 60f;
    /** More steps than any of these flights takes to land at the default launch. */
    private static final int MAX_STEPS = 600;
    /** The reference solution, on the test classpath with the stubs. */
    private static final String SOLUTION = "particlelab.solutions.Recipe";
    /** A limit for the recipes that return: far above a step's microseconds, even loaded. */
    private static final long GENEROUS_LIMIT_NANOS = 10_000_000_000L;

    /** A recipe whose third step throws. */
    public static final class ThrowingRecipe implements RecipeExercise {
        private int calls;

        @Override
        public void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
                float dragNsPerM, float thrustN, float stepSeconds) {
            if (++calls == 3) {
                throw new IllegalStateException("boom at call " + calls);
            }
            position.scaleAdd(stepSeconds, velocity, position);
        }
    }

    /** A recipe that divides by the drag, 0 in the pull demo: 0/0 is NaN. */
    public static final class NanRecipe implements RecipeExercise {
        @Override
        public void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
                float dragNsPerM, float thrustN, float stepSeconds) {
            velocity.multLocal(dragNsPerM / dragNsPerM);
            position.scaleAdd(stepSeconds, velocity, position);
        }
    }

    /** A recipe that never returns, until the test lets it go. */
    public static final class EndlessRecipe implements RecipeExercise {
        static volatile boolean released;

        @Override
        public void step(Vector3f position, Vector3f velocity, float massKg, Vector3f gravity,
                float dragNsPerM, float thrustN, float stepSeconds) {
            while (!released) {
                Thread.onSpinWait();
            }
        }
    }

    /** Choose a lane as {@code --set lane=...} does, then launch. */
    private static void choose(DemoState demo, ComparisonLane.Kind kind) {
        demo.getParameters().set(ComparisonLane.PARAMETER, kind.ordinal());
        demo.restart();
    }

    private static ComparisonLane studentLane(DemoState demo, ComparisonLane lane,
            String className, long limitNanos) {
        lane.useStudentClass(className, limitNanos);
        choose(demo, ComparisonLane.Kind.STUDENT);
        return lane;
    }

    private static String hud(DemoState demo) {
        StringBuilder text = new StringBuilder();
        demo.writeOwnHudLines(text);
        return text.toString();
    }

    private static void assertSameBits(MotionState expected, MotionState actual, String what) {
        for (int i = 0; i < 3; ++i) {
            assertEquals(Double.doubleToLongBits(expected.position[i]),
                    Double.doubleToLongBits(actual.position[i]), what + ", P[" + i + "]");
            assertEquals(Double.doubleToLongBits(expected.velocity[i]),
                    Double.doubleToLongBits(actual.velocity[i]), what + ", V[" + i + "]");
        }
    }

    /**
     * Fly two copies of a demo, one with the semi-implicit lane and one with the student lane
     * running the reference solution, and compare the lanes' states after every step.
     *
     * @return the steps flown
     */
    private static int assertStudentIsSemi(DemoState semiDemo, ComparisonLane semiLane,
            DemoState studentDemo, ComparisonLane studentLane) {
        choose(semiDemo, ComparisonLane.Kind.SEMI);
        studentLane(studentDemo, studentLane, SOLUTION, GENEROUS_LIMIT_NANOS);
        int steps = 0;
        while (!semiLane.getParticle().hasLanded() && steps < MAX_STEPS) {
            semiDemo.getRun().advancePhysics(H);
            studentDemo.getRun().advancePhysics(H);
            ++steps;
            assertSameBits(semiLane.getState(), studentLane.getState(), "step " + steps);
        }
        assertNull(studentLane.getStudentProblem());
        return steps;
    }

    @Test
    void withTheSolutionThePullsStudentLaneIsTheSemiLaneBitForBit() {
        // Gravity only: the solution's a = (−0·V + 0·V/|V|)/m + g is g exactly, then
        // V += h·a and P += h·V, the shared step's own float operations in its order.
        GravitationalPullDemo semi = new GravitationalPullDemo();
        GravitationalPullDemo student = new GravitationalPullDemo();
        int steps = assertStudentIsSemi(semi, semi.getLane(), student, student.getLane());
        assertTrue(semi.getLane().getParticle().hasLanded(), "landed after " + steps);
        assertTrue(student.getLane().getParticle().hasLanded());
        assertTrue(steps > 100, "flew " + steps + " steps");
    }

    @Test
    void withTheSolutionTheUniformStudentLaneIsTheSemiLaneBitForBit() {
        UniformMotionDemo semi = new UniformMotionDemo();
        UniformMotionDemo student = new UniformMotionDemo();
        choose(semi, ComparisonLane.Kind.SEMI);
        studentLane(student, student.getLane(), SOLUTION, GENEROUS_LIMIT_NANOS);
        for (int n = 1; n <= 300; ++n) {
            semi.getRun().advancePhysics(H);
            student.getRun().advancePhysics(H);
            assertSameBits(semi.getLane().getState(), student.getLane().getState(),
                    "step " + n);
        }
        assertNull(student.getLane().getStudentProblem());
    }

    @Test
    void withTheSolutionTheDragsStudentLaneIsTheSlideLaneBitForBit() {
        // Linear drag: the slide's listing (force = −b·V, a = g + force/m, V + a·h, P + V·h)
        // and the solution (a = (−b·V)/m + g, V += h·a, P += h·V) are the same float
        // operations; jME's divide and divideLocal both multiply by 1/m.
        assertStudentLaneIsTheSlideLane(new DragDemo(), new DragDemo());
    }

    @Test
    void withTheSolutionTheThrustsStudentLaneIsTheSlideLaneBitForBit() {
        // Thrust: the slide adds velocity.normalize().mult(k) to −b·V, the solution adds
        // normalizeLocal().multLocal(T) of a copy of V: the same float operations again.
        assertStudentLaneIsTheSlideLane(new ThrustDemo(), new ThrustDemo());
    }

    private static void assertStudentLaneIsTheSlideLane(DemoState slide, DemoState student) {
        ComparisonLane slideLane = laneOf(slide);
        ComparisonLane studentLane = laneOf(student);
        choose(slide, ComparisonLane.Kind.SLIDE);
        studentLane(student, studentLane, SOLUTION, GENEROUS_LIMIT_NANOS);
        int steps = 0;
        while (!studentLane.getParticle().hasLanded() && steps < MAX_STEPS) {
            slide.getRun().advancePhysics(H);
            student.getRun().advancePhysics(H);
            ++steps;
            if (studentLane.getParticle().hasLanded()) {
                break;
            }
            Vector3f p = slideLane.getSlideCode().position;
            Vector3f v = slideLane.getSlideCode().velocity;
            MotionState state = studentLane.getState();
            for (int i = 0; i < 3; ++i) {
                assertEquals(Float.floatToIntBits(p.get(i)),
                        Float.floatToIntBits((float) state.position[i]), "P at step " + steps);
                assertEquals(Float.floatToIntBits(v.get(i)),
                        Float.floatToIntBits((float) state.velocity[i]), "V at step " + steps);
            }
        }
        assertTrue(steps > 90, "flew " + steps + " steps");
    }

    private static ComparisonLane laneOf(DemoState demo) {
        return demo instanceof DragDemo ? ((DragDemo) demo).getLane()
                : ((ThrustDemo) demo).getLane();
    }

    @Test
    void withTheSolutionDragAndThrustLanesAreTheRecipeRunInFloat() {
        // Linear drag and thrust: the shared step folds the forces (FoldedForces), the
        // solution writes the recipe plainly: the same real numbers, rounded differently, so
        // here the lane is checked against the solution stepped alone, bit for bit (the lane
        // adds nothing to the recipe's floats), and against the shared step within round-off.
        DragDemo drag = new DragDemo();
        assertLaneIsTheSolutionAlone(drag, drag.getLane(), drag.getParticles().get(1),
                new Vector3f(10f, 10f, 0f), DragDemo.LINEAR_B, 0f);
        ThrustDemo thrust = new ThrustDemo();
        DemoParticle thruster = thrust.getParticles().get(1);
        float thrustN = Float.NaN;
        for (int i = 0; i < thruster.getIntegrator().countForces(); ++i) {
            // the thrust among the forces (the bug hunt's faulty thrusts follow it, at 0)
            if (thruster.getIntegrator().getForce(i) instanceof particlelab.physics.Thrust) {
                thrustN = ((particlelab.physics.Thrust) thruster.getIntegrator().getForce(i))
                        .getMagnitude();
            }
        }
        assertLaneIsTheSolutionAlone(thrust, thrust.getLane(), thruster,
                thruster.copyLaunchVelocity(new Vector3f()), linearDragOf(thruster), thrustN);
    }

    private static float linearDragOf(DemoParticle sphere) {
        for (int i = 0; i < sphere.getIntegrator().countForces(); ++i) {
            if (sphere.getIntegrator().getForce(i) instanceof particlelab.physics.LinearDrag) {
                return ((particlelab.physics.LinearDrag) sphere.getIntegrator().getForce(i))
                        .getCoefficient();
            }
        }
        return 0f;
    }

    private static void assertLaneIsTheSolutionAlone(DemoState demo, ComparisonLane lane,
            DemoParticle followed, Vector3f launchVelocity, float drag, float thrust) {
        studentLane(demo, lane, SOLUTION, GENEROUS_LIMIT_NANOS);
        RecipeExercise alone = new particlelab.solutions.Recipe();
        Vector3f p = followed.copyLaunchPosition(new Vector3f());
        Vector3f v = new Vector3f(launchVelocity);
        Vector3f g = new Vector3f(0f, -9.8f, 0f);
        double largest = 0.0;
        int steps = 0;
        while (!lane.getParticle().hasLanded() && steps < MAX_STEPS) {
            demo.getRun().advancePhysics(H);
            ++steps;
            if (lane.getParticle().hasLanded()) {
                break;
            }
            alone.step(p, v, 1f, g, drag, thrust, H);
            MotionState state = lane.getState();
            for (int i = 0; i < 3; ++i) {
                assertEquals(Float.floatToIntBits(p.get(i)),
                        Float.floatToIntBits((float) state.position[i]), "P at step " + steps);
                assertEquals(Float.floatToIntBits(v.get(i)),
                        Float.floatToIntBits((float) state.velocity[i]), "V at step " + steps);
                // the float went into the double unchanged
                assertEquals(p.get(i), state.position[i], 0.0);
            }
            if (!followed.hasLanded()) {
                largest = Math.max(largest, p.distance(followed.getParticle().position));
            }
        }
        assertTrue(lane.getParticle().hasLanded(), "landed after " + steps);
        assertNull(lane.getStudentProblem());
        // Under 200 steps of positions up to ~10 m, each rounding ~1e-6 m apart: far under
        // 1e-4 m; any error of the method (vx·h ≈ 0.17 m) or a wrong force is far over it.
        assertTrue(largest < 1e-4, "student vs shared: " + largest + " m");
    }

    @Test
    void theStubShowsNotWrittenYetAndTheDemoRunsOn() {
        GravitationalPullDemo demo = new GravitationalPullDemo();
        ComparisonLane lane = demo.getLane();
        // the default class: exercise 1's stub, on the test classpath as under gradle run
        choose(demo, ComparisonLane.Kind.STUDENT);
        DemoParticle shared = demo.getParticles().get(0);
        for (int n = 0; n < 30; ++n) {
            demo.getRun().advancePhysics(H);
        }
        assertEquals("not written yet", lane.getStudentProblem());
        String hud = hud(demo);
        // the lane's one line is all it writes
        assertEquals("Lane student's recipe (L):  not written yet: write"
                + " particlelab.exercises.Recipe (docs/exercises.md)\n", hud);
        assertTrue(shared.getParticle().position.x > 0f, "the shared sphere flew on");
        assertEquals(30 * H, demo.getClock().getSimulatedSeconds(), 1e-4,
                "every frame stepped (float sums of 30 h: round-off ~1e-6 s)");
    }

    @Test
    void aThrowingRecipeStopsTheLaneWithOneLineAndTheDemoRunsOn() {
        GravitationalPullDemo demo = new GravitationalPullDemo();
        ComparisonLane lane = studentLane(demo, demo.getLane(),
                ThrowingRecipe.class.getName(), GENEROUS_LIMIT_NANOS);
        DemoParticle shared = demo.getParticles().get(0);
        for (int n = 0; n < 20; ++n) {
            demo.getRun().advancePhysics(H);
        }
        String problem = lane.getStudentProblem();
        assertTrue(problem.matches("step 3: threw IllegalStateException: boom at call 3"
                + " \\(StudentLaneTest\\.java:\\d+\\)"), problem);
        String hud = hud(demo);
        assertEquals("Lane student's recipe (L):  " + problem + "\n", hud);
        // The lane's sphere stays where its last good step left it (2 steps of vx·h ...)
        float laneX = lane.getParticle().getParticle().position.x;
        demo.getRun().advancePhysics(H);
        assertEquals(laneX, lane.getParticle().getParticle().position.x, 0f);
        // ... and the shared sphere flies on.
        assertTrue(shared.getParticle().position.x > 2f * laneX, "shared flew on");
        // A new launch calls the same instance again: past its third call it steps on.
        demo.restart();
        for (int n = 0; n < 20; ++n) {
            demo.getRun().advancePhysics(H);
        }
        assertNull(lane.getStudentProblem());
        assertTrue(lane.getParticle().getParticle().position.x > laneX, "the lane flew on");
    }

    @Test
    void aNanRecipeStopsTheLaneNamingTheStepAndTheValue() {
        GravitationalPullDemo demo = new GravitationalPullDemo();
        ComparisonLane lane = studentLane(demo, demo.getLane(), NanRecipe.class.getName(),
                GENEROUS_LIMIT_NANOS);
        for (int n = 0; n < 10; ++n) {
            demo.getRun().advancePhysics(H);
        }
        assertEquals("step 1 gave P = (NaN, NaN, NaN) m, V = (NaN, NaN, NaN) m/s: not a"
                + " number", lane.getStudentProblem());
        String hud = hud(demo);
        assertTrue(hud.startsWith("Lane student's recipe (L):  step 1 gave P = (NaN, NaN,"
                + " NaN) m"), hud);
        // the NaN went nowhere: the lane's state and sphere stay finite
        assertTrue(lane.getState().isFinite(), lane.getState().toString());
        assertTrue(Vector3f.isValidVector(lane.getParticle().getParticle().position));
    }

    @Test
    void aRecipeThatNeverReturnsIsAbandonedAndTheDemoRunsOn() {
        EndlessRecipe.released = false;
        try {
            GravitationalPullDemo demo = new GravitationalPullDemo();
            // 0.2 s: long enough for a step on a loaded machine, short for a test
            ComparisonLane lane = studentLane(demo, demo.getLane(),
                    EndlessRecipe.class.getName(), 200_000_000L);
            DemoParticle shared = demo.getParticles().get(0);
            demo.getRun().advancePhysics(H);
            assertEquals("step 1: did not return within 0.2 s: an endless loop? (no more"
                    + " calls)", lane.getStudentProblem());
            // No more calls: the next frames and a new launch take no 0.2 s each (not timed:
            // the runner is abandoned, which the line after a restart still says).
            for (int n = 0; n < 30; ++n) {
                demo.getRun().advancePhysics(H);
            }
            demo.restart();
            demo.getRun().advancePhysics(H);
            assertTrue(lane.getStudentProblem().contains("did not return"),
                    lane.getStudentProblem());
            assertTrue(shared.getParticle().position.x > 0f, "the shared sphere flew on");
            assertTrue(hud(demo).startsWith("Lane student's recipe (L):  step 1: did not"
                    + " return within 0.2 s"), hud(demo));
        } finally {
            EndlessRecipe.released = true;
        }
    }

    /** A sphere under quadratic drag, which exercise 1's recipe does not have. */
    private static final class QuadraticDragDemo extends DemoState {
        private final LaunchControl launch = new LaunchControl(new Vector3f(10f, 10f, 0f));
        private final ComparisonLane lane = addPart(new ComparisonLane(SlideCode::uniform,
                0.3f));

        QuadraticDragDemo() {
            super("quadratic drag");
        }

        @Override
        protected void createScene() {
            DemoParticle sphere = launch.add(addParticle("sphere", ColorRGBA.Cyan,
                    Vector3f.ZERO, new Vector3f(10f, 10f, 0f), 1f,
                    new ParticleIntegrator(new Gravity(), new QuadraticDrag(0.1f))));
            sphere.stopAtGround();
            lane.follow(launch, sphere);
        }
    }

    @Test
    void forcesTheRecipeHasNotStopTheLaneSayingSo() {
        QuadraticDragDemo demo = new QuadraticDragDemo();
        studentLane(demo, demo.lane, SOLUTION, GENEROUS_LIMIT_NANOS);
        demo.getRun().advancePhysics(H);
        assertEquals("these forces are not exercise 1's (gravity, linear drag, thrust)",
                demo.lane.getStudentProblem());
        assertEquals("Lane student's recipe (L):  these forces are not exercise 1's (gravity,"
                + " linear drag, thrust)\n", hud(demo));
    }

    @Test
    void aMissingClassSaysSoInOneLine() {
        DragDemo demo = new DragDemo();
        ComparisonLane lane = studentLane(demo, demo.getLane(), "particlelab.nowhere.Recipe",
                GENEROUS_LIMIT_NANOS);
        demo.getRun().advancePhysics(H);
        assertEquals("no class particlelab.nowhere.Recipe here: run it with gradle run"
                + " (docs/exercises.md)", lane.getStudentProblem());
        assertNotEquals(0f, demo.getParticles().get(0).getParticle().position.x);
    }

    @Test
    void theStudentLanesStepsAllocateNothingOnTheDemosThread() {
        // The handoff to the worker and back is allocation-free; the recipe's own allocation
        // (none for the solution) would be on the worker's thread.
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        DragDemo demo = new DragDemo();
        ComparisonLane lane = studentLane(demo, demo.getLane(), SOLUTION,
                GENEROUS_LIMIT_NANOS);
        long least = Long.MAX_VALUE;
        // Flights of under 100 steps, relaunched: the least of several windows, since a JVM
        // under load may charge a window bytes of its own work (a real allocation shows in
        // every window).
        for (int window = 0; window < 8; ++window) {
            demo.restart();
            for (int n = 0; n < 5; ++n) {
                demo.getRun().advancePhysics(H);
            }
            long before = threads.getThreadAllocatedBytes(Thread.currentThread().getId());
            for (int n = 0; n < 60; ++n) {
                demo.getRun().advancePhysics(H);
            }
            long after = threads.getThreadAllocatedBytes(Thread.currentThread().getId());
            least = Math.min(least, after - before);
        }
        assertNull(lane.getStudentProblem());
        assertEquals(0L, least, "bytes allocated in 60 frames");
    }
}

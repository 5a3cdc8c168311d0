package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import particlelab.coursework.AimingExercise;
import particlelab.demo.DemoParticle;

/**
 * HelloAiming's student aim ({@code --set aim=student}, issue 31 §3), in plain JUnit:
 * exercise 3's {@code discreteVy}, found by name and called on a worker thread, fires a third
 * bullet beside the lecture's two; the stub, a throw, a NaN and an endless loop fire none and
 * say why in one line, while the two lecture bullets fly and land.
 */
class HelloAimingStudentTest {

    private static final float H = 1f / 60f;
    /** A flight of S/vx = 5 s at 60 steps a second, and some. */
    private static final int FLIGHT_STEPS = 320;
    private static final String SOLUTION = "particlelab.solutions.Aiming";
    /** A limit for the aims that return: far above a call's microseconds, even loaded. */
    private static final long GENEROUS_LIMIT_NANOS = 10_000_000_000L;

    /** An aim whose discreteVy throws. */
    public static final class ThrowingAim implements AimingExercise {
        @Override
        public float continuousVy(float vx, float rangeM, float gravity) {
            return gravity * rangeM / (2f * vx);
        }

        @Override
        public float discreteVy(float vx, float rangeM, float gravity, float stepSeconds) {
            int[] table = new int[1];
            return table[Math.round(stepSeconds * 60f)];
        }
    }

    /** An aim that divides by zero: 0/0. */
    public static final class NanAim implements AimingExercise {
        @Override
        public float continuousVy(float vx, float rangeM, float gravity) {
            return 0f / (vx - vx);
        }

        @Override
        public float discreteVy(float vx, float rangeM, float gravity, float stepSeconds) {
            return continuousVy(vx, rangeM, gravity);
        }
    }

    /** An aim that never returns, until the test lets it go. */
    public static final class EndlessAim implements AimingExercise {
        static volatile boolean released;

        @Override
        public float continuousVy(float vx, float rangeM, float gravity) {
            while (!released) {
                Thread.onSpinWait();
            }
            return 0f;
        }

        @Override
        public float discreteVy(float vx, float rangeM, float gravity, float stepSeconds) {
            return continuousVy(vx, rangeM, gravity);
        }
    }

    private static HelloAimingDemo withStudent(String className, long limitNanos) {
        HelloAimingDemo demo = new HelloAimingDemo();
        demo.useStudentClass(className, limitNanos);
        demo.getParameters().set("aim", HelloAimingDemo.WITH_STUDENT);
        return demo;
    }

    private static void fly(HelloAimingDemo demo) {
        for (int n = 0; n < FLIGHT_STEPS; ++n) {
            demo.getRun().advancePhysics(H);
        }
    }

    private static String hud(HelloAimingDemo demo) {
        return demo.getWindow().formatHud(new StringBuilder()).toString();
    }

    /** The lecture's two bullets landed as they do without the student's. */
    private static void assertLectureShotLanded(HelloAimingDemo demo) {
        assertEquals(1, demo.getLandedShotNumber(HelloAimingDemo.Aim.LECTURE));
        // the discrete aim lands on the target to float round-off (AimsFollowTheStepTest)
        assertEquals(100.0, demo.getLastLandingX(HelloAimingDemo.Aim.DISCRETE), 1e-3);
    }

    @Test
    void theSolutionsBulletFliesTheDiscreteAimsShot() {
        HelloAimingDemo demo = withStudent(SOLUTION, GENEROUS_LIMIT_NANOS);
        DemoParticle student = demo.getStudentBullet();
        DemoParticle discrete = demo.getBullet(HelloAimingDemo.Aim.DISCRETE);
        assertFalse(student.isParked(), "the student's bullet is in the shot");
        // The solution sums g·S/(2·vx) + g·h/2 in float, the lecture's aim in double, then
        // rounds: a float ulp or two of 24.58 m/s (2e-6 m/s each).
        float lectureVy = demo.getVerticalSpeed(HelloAimingDemo.Aim.DISCRETE);
        assertEquals(lectureVy, demo.getStudentVy(), 3 * Math.ulp(lectureVy));
        fly(demo);
        assertTrue(student.hasLanded() && discrete.hasLanded());
        assertNull(demo.getStudentProblem());
        // Two ulps of vy over 5 s move the landing by ~1e-5 m; any other aim misses by cm.
        assertEquals(discrete.getLandingX(), demo.getStudentLandingX(), 1e-3);
        assertEquals(100.0, demo.getStudentLandingX(), 1e-3);
        String hud = hud(demo);
        assertTrue(hud.contains("Student's aim (exercise 3), green:  discreteVy = 24.582 m/s"
                + " (the lecture's 24.582 m/s)\n"), hud);
        assertTrue(hud.contains("; student x = 100.000 m, miss 0.000 m\n"), hud);
    }

    @Test
    void theStubFiresNoStudentBulletAndSaysNotWrittenYet() {
        HelloAimingDemo demo = new HelloAimingDemo();
        demo.getParameters().set("aim", HelloAimingDemo.WITH_STUDENT);
        assertEquals("not written yet", demo.getStudentProblem());
        assertTrue(demo.getStudentBullet().isParked());
        fly(demo);
        assertLectureShotLanded(demo);
        assertTrue(hud(demo).contains("Student's aim (exercise 3), green:  not written yet:"
                + " write particlelab.exercises.Aiming (docs/exercises.md)\n"), hud(demo));
    }

    @Test
    void aThrowingAimSaysWhereInOneLine() {
        HelloAimingDemo demo = withStudent(ThrowingAim.class.getName(), GENEROUS_LIMIT_NANOS);
        String problem = demo.getStudentProblem();
        assertTrue(problem.matches("threw ArrayIndexOutOfBoundsException: Index 1 out of bounds"
                + " for length 1 \\(HelloAimingStudentTest\\.java:\\d+\\)"), problem);
        fly(demo);
        assertLectureShotLanded(demo);
        assertTrue(demo.getStudentBullet().isParked());
    }

    @Test
    void aNanAimNamesItsArgumentsAndTheValue() {
        HelloAimingDemo demo = withStudent(NanAim.class.getName(), GENEROUS_LIMIT_NANOS);
        assertEquals("discreteVy(vx = 20.0, S = 100.0, g = 9.80, h = 0.01667) gave NaN: not a"
                + " number", demo.getStudentProblem());
        fly(demo);
        assertLectureShotLanded(demo);
    }

    @Test
    void anAimThatNeverReturnsIsAbandonedAndTheShotFlies() {
        EndlessAim.released = false;
        try {
            HelloAimingDemo demo = withStudent(EndlessAim.class.getName(), 200_000_000L);
            assertEquals("did not return within 0.2 s: an endless loop? (no more calls)",
                    demo.getStudentProblem());
            fly(demo);
            assertLectureShotLanded(demo);
            // the next shot asks no more
            demo.fire();
            assertTrue(demo.getStudentProblem().startsWith("did not return"));
        } finally {
            EndlessAim.released = true;
        }
    }

    @Test
    void withoutTheStudentsAimNothingAsksIt() {
        HelloAimingDemo demo = new HelloAimingDemo();
        fly(demo);
        assertNull(demo.getStudentProblem());
        assertTrue(demo.getStudentBullet().isParked());
        assertFalse(hud(demo).contains("Student's aim"), hud(demo));
    }
}

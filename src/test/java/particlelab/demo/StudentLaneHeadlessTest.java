package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.app.ParticleLabApp;
import particlelab.lecture.GravitationalPullDemo;

/**
 * The student lane in a real headless application (issue 31 §3's acceptance): a student's
 * recipe that throws, or never returns, leaves the window running, whole frames and all, with
 * one line on the HUD; nothing is thrown on the render thread and the window recovers from
 * nothing.
 */
class StudentLaneHeadlessTest {

    private static final float H = 1f / 60f;
    /** Whole frames after the lane stopped: a second of flight. */
    private static final int FRAMES = 60;

    private static final GravitationalPullDemo pull = new GravitationalPullDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(() -> List.of(pull));

    /** Choose the student lane with a class and a limit, launch, and run whole frames. */
    private static String[] runFrames(String className, long limitNanos) throws Exception {
        return harness.call(() -> {
            ParticleLabApp app = harness.app();
            pull.getLane().useStudentClass(className, limitNanos);
            pull.getParameters().set(ComparisonLane.PARAMETER,
                    ComparisonLane.Kind.STUDENT.ordinal());
            pull.restart();
            pull.getClock().setPaused(false);
            double before = pull.getClock().getSimulatedSeconds();
            for (int frame = 0; frame < FRAMES; ++frame) {
                SmallPanelHeadlessTest.frame(app);
            }
            return new String[] {pull.getHud().getBodyText(),
                String.valueOf(pull.getClock().getSimulatedSeconds() - before),
                String.valueOf(app.getRecovered()), String.valueOf(app.getFailure())};
        });
    }

    @Test
    void aThrowingRecipeLeavesTheWindowRunningWithOneLine() throws Exception {
        String[] result = runFrames(StudentLaneTest.ThrowingRecipe.class.getName(),
                10_000_000_000L);
        String hud = result[0];
        assertTrue(hud.matches("(?s).*\nLane student's recipe \\(L\\):  step 3: threw"
                + " IllegalStateException: boom at call 3 \\(StudentLaneTest\\.java:\\d+\\)"
                + "\n.*"), hud);
        // 60 frames of h: the clock ran on (float sums: round-off ~1e-5 s)
        assertEquals(FRAMES * H, Double.parseDouble(result[1]), 1e-3);
        assertEquals("null", result[2], "the window recovered from");
        assertEquals("null", result[3], "the window failed");
        // and jME's own loop goes on
        harness.awaitFrames(3);
        assertNull(harness.app().getRecovered());
    }

    @Test
    void aRecipeThatNeverReturnsLeavesTheWindowRunningWithOneLine() throws Exception {
        StudentLaneTest.EndlessRecipe.released = false;
        try {
            String[] result = runFrames(StudentLaneTest.EndlessRecipe.class.getName(),
                    200_000_000L);
            assertTrue(result[0].contains("\nLane student's recipe (L):  step 1: did not"
                    + " return within 0.2 s: an endless loop? (no more calls)\n"), result[0]);
            assertEquals(FRAMES * H, Double.parseDouble(result[1]), 1e-3);
            assertEquals("null", result[2], "the window recovered from");
            harness.awaitFrames(3);
        } finally {
            StudentLaneTest.EndlessRecipe.released = true;
        }
    }
}

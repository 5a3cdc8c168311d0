package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import particlelab.app.HeadlessHarness;
import particlelab.lecture.RotationDemo;
import particlelab.lecture.SpinThrowDemo;
import particlelab.lecture.TennisRacketDemo;
import particlelab.physics.SimulationClock;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationCheck;
import particlelab.view.BoxView;
import particlelab.view.OrientationBlend;

/**
 * Slow motion is smooth in the demos that draw rotating boxes (rotation, throw, racket), in a
 * real headless jME application at x1/64: every frame the box's mesh is the blend of the
 * body's last two states at the frame's {@code α = leftover / h}: its centre
 * {@code P_prev + α·(P − P_prev)}, its orientation between R_prev and R (at an angle from
 * each no more than the step's, in proportion to α), R_prev at α = 0 and R at α = 1; with
 * F6 off, the raw step. And the stepping line no longer says these demos draw raw steps.
 */
class BoxInterpolationHeadlessTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    /** x1/64: a step every 64 frames of h. */
    private static final float SLOW = 1f / 64f;
    /** Frames: three steps and more, at every leftover. */
    private static final int FRAMES = 220;
    private static final RotationDemo ROTATION = new RotationDemo();
    private static final SpinThrowDemo THROW = new SpinThrowDemo();
    private static final TennisRacketDemo RACKET = new TennisRacketDemo();
    @RegisterExtension
    static final HeadlessHarness harness = HeadlessHarness.perClass(
            () -> List.of(ROTATION, THROW, RACKET));

    @Test
    void rotationBoxesAreDrawnBetweenTheirLastTwoStates() throws Exception {
        for (int box = 0; box < 3; ++box) {
            int index = box;
            check(ROTATION, () -> ROTATION.getWorld().getBody(index).getRigidBody(),
                    () -> ROTATION.getView(index), "rotation box " + box);
        }
    }

    @Test
    void theThrownBoxIsDrawnBetweenItsLastTwoStates() throws Exception {
        check(THROW, THROW::getBody, THROW::getBoxView, "throw");
    }

    @Test
    void theRacketsAreDrawnBetweenTheirLastTwoStates() throws Exception {
        for (int method = 0; method < 2; ++method) {
            int index = method;
            check(RACKET, () -> RACKET.getBody(index), () -> RACKET.getView(index),
                    "racket " + method);
        }
    }

    /** Run a demo at x1/64 and check each frame's drawn box against the blend. */
    private static void check(DemoState demo, java.util.function.Supplier<RigidBody> body,
            java.util.function.Supplier<BoxView> view, String what) throws Exception {
        List<String> problems = harness.call(() -> {
            List<String> found = new ArrayList<>();
            SimulationClock clock = demo.getClock();
            clock.setMode(SimulationClock.Mode.FIXED_STEP);
            demo.restart();
            clock.setPaused(false);
            clock.setTimeScale(SLOW);
            demo.getReplayControls().setInterpolating(true);
            RigidBody rigid = body.get();
            Matrix3f before = new Matrix3f();
            Vector3f beforeCentre = new Vector3f();
            Matrix3f previous = new Matrix3f(rigid.orientation);
            Vector3f previousCentre = new Vector3f(rigid.getParticle().position);
            OrientationBlend blend = new OrientationBlend();
            Matrix3f drawn = new Matrix3f();
            Vector3f centre = new Vector3f();
            RotationCheck check = new RotationCheck();
            int between = 0;
            for (int frame = 0; frame < FRAMES; ++frame) {
                before.set(rigid.orientation);
                beforeCentre.set(rigid.getParticle().position);
                long steps = demo.getWorld().getStepCount();
                demo.advance(H);
                if (demo.getWorld().getStepCount() != steps) {
                    previous.set(before);
                    previousCentre.set(beforeCentre);
                }
                float alpha = demo.getRun().getReplay().getFrameBlend();
                blend.blend(previous, rigid.orientation, alpha, drawn);
                centre.set(previousCentre).interpolateLocal(rigid.getParticle().position,
                        alpha);
                String mesh = compareMesh(view.get(), drawn, centre);
                if (mesh != null) {
                    found.add("frame " + frame + " α " + alpha + ": " + mesh);
                }
                // The angles between the matrices' rotations, each taken the same way (the
                // columns made orthonormal), so a drifted matrix (the plain box) compares too.
                Matrix3f rotationBefore = rotationOf(previous);
                Matrix3f rotationNow = rotationOf(rigid.orientation);
                Matrix3f rotationDrawn = rotationOf(drawn);
                double step = check.angleError(rotationNow, rotationBefore);
                double fromPrevious = check.angleError(rotationDrawn, rotationBefore);
                double fromCurrent = check.angleError(rotationDrawn, rotationNow);
                // Float round-off of the matrices' entries: a few ulps of 1, in radians.
                double tolerance = 1e-5;
                if (fromPrevious > step + tolerance || fromCurrent > step + tolerance) {
                    found.add("frame " + frame + " α " + alpha + ": " + fromPrevious + ", "
                            + fromCurrent + " rad from the states, the step turns " + step);
                }
                if (Math.abs(fromPrevious - alpha * step) > 1e-3 * step + tolerance) {
                    found.add("frame " + frame + " α " + alpha + ": " + fromPrevious
                            + " rad from R_prev, not α of the step's " + step);
                }
                if (alpha > 0f && alpha < 1f && step > 0.0) {
                    ++between;
                }
                if (found.size() > 3) {
                    break;
                }
            }
            if (between < FRAMES / 2) {
                found.add("only " + between + " frames drawn between two steps");
            }
            // F6 off: the raw step, R itself.
            demo.getReplayControls().setInterpolating(false);
            demo.advance(H);
            String raw = compareMesh(view.get(), rigid.orientation, rigid.getParticle().position);
            if (raw != null) {
                found.add("F6 off: " + raw);
            }
            demo.getReplayControls().setInterpolating(true);
            String hud = demo.formatHud(new StringBuilder()).toString();
            if (hud.contains("raw steps (this demo's views)")) {
                found.add("the HUD still says raw steps: " + hud);
            }
            clock.setTimeScale(1f);
            return found;
        });
        assertTrue(problems.isEmpty(), what + ": " + problems);
    }

    @Test
    void theBlendIsThePreviousStateAtZeroAndTheCurrentAtOne() {
        Matrix3f previous = new Matrix3f();
        previous.fromAngleNormalAxis(0.3f, new Vector3f(0f, 0f, 1f));
        // A drifted matrix, as the plain Euler step leaves it: grown and sheared.
        Matrix3f current = new Matrix3f(1.01f, -0.3f, 0f, 0.31f, 0.99f, 0f, 0f, 0.02f, 1f);
        OrientationBlend blend = new OrientationBlend();
        Matrix3f drawn = new Matrix3f();
        assertEquals(previous, blend.blend(previous, current, 0f, drawn));
        assertEquals(current, blend.blend(previous, current, 1f, drawn));
        // Just inside: within float round-off of the ends (products of entries below 1.1).
        blend.blend(previous, current, 1e-6f, drawn);
        assertMatrixEquals(previous, drawn, 1e-5f);
        blend.blend(previous, current, 1f - 1e-6f, drawn);
        assertMatrixEquals(current, drawn, 1e-5f);
    }

    private static void assertMatrixEquals(Matrix3f expected, Matrix3f actual, float tol) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                assertEquals(expected.get(row, column), actual.get(row, column), tol,
                        "entry " + row + "," + column + " of " + actual);
            }
        }
    }

    /** The mesh's vertices against P + R·b; null if they agree. */
    private static String compareMesh(BoxView view, Matrix3f r, Vector3f centre) {
        Vector3f body = new Vector3f();
        Vector3f expected = new Vector3f();
        Vector3f actual = new Vector3f();
        for (int vertex = 0; vertex < 24; ++vertex) {
            view.copyBodyVertex(vertex, body);
            r.mult(body, expected).addLocal(centre);
            view.copyVertex(vertex, actual);
            // The same float operations in another order: a few ulps of metres-sized values.
            if (expected.distance(actual) > 1e-5f) {
                return "vertex " + vertex + " drawn at " + actual + ", expected " + expected;
            }
        }
        return null;
    }

    /** The nearest rotation's stand-in: the columns made orthonormal (for the angles). */
    private static Matrix3f rotationOf(Matrix3f m) {
        Vector3f c0 = m.getColumn(0).normalizeLocal();
        Vector3f c1 = m.getColumn(1);
        c1.subtractLocal(c0.mult(c0.dot(c1))).normalizeLocal();
        Vector3f c2 = c0.cross(c1);
        Matrix3f q = new Matrix3f();
        q.setColumn(0, c0);
        q.setColumn(1, c1);
        q.setColumn(2, c2);
        return q;
    }
}

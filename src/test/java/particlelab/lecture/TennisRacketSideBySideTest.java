package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoParameters;
import particlelab.rigid.RigidBody;
import particlelab.rigid.RotationIntegrator;

/**
 * Issue 19 §8: the tennis racket's two methods side by side, from the same start, in the same
 * world with the same clock. Plain JUnit: the demo's physics runs without jME.
 */
class TennisRacketSideBySideTest {

    /** The demo's fixed step (s). */
    private static final float H = 1f / 60f;
    /** Frames of H: 10 s, past three flips of each racket. */
    private static final int FRAMES = 600;

    @Test
    void bothRacketsStartEqualAndEachMatchesItsMethodSteppedAlone() {
        TennisRacketDemo racket = new TennisRacketDemo();
        RigidBody explicit = racket.getBody(0);
        RigidBody midpoint = racket.getBody(1);
        // The same start, to the bit: one tilt and one ω for both.
        assertEquals(explicit.orientation, midpoint.orientation);
        assertEquals(explicit.angularVelocity, midpoint.angularVelocity);
        for (int frame = 0; frame < FRAMES; ++frame) {
            racket.getRun().advancePhysics(H);
        }
        int steps = (int) Math.round(racket.getClock().getSimulatedSeconds() / H);
        assertTrue(steps >= FRAMES - 1, "steps " + steps);
        for (int method = 0; method < TennisRacketDemo.METHODS.length; ++method) {
            RigidBody alone = steppedAlone(racket, TennisRacketDemo.METHODS[method], steps);
            RigidBody inWorld = racket.getBody(method);
            // The world calls the same integrator with the same h on the same floats as the
            // old single-racket path: equal bit for bit, no tolerance.
            assertEquals(alone.orientation, inWorld.orientation, "method " + method);
            assertEquals(alone.angularVelocity, inWorld.angularVelocity, "method " + method);
        }
        // And the two really differ by now: explicit Euler's gain has moved its flips.
        assertTrue(racket.angleBetweenRadians() > 0.1, "apart " + racket.angleBetweenRadians());
    }

    @Test
    void bothRacketsAreShownSideBySideByDefaultAndIStepsThroughOneAlone() {
        TennisRacketDemo racket = new TennisRacketDemo();
        racket.getWorld();
        assertEquals(TennisRacketDemo.BOTH, racket.getShownMethod());
        assertTrue(racket.isShown(0) && racket.isShown(1));
        // Left and right of x = 0, at one height: the world holds each body at its centre.
        Vector3f left = racket.getBody(0).getParticle().position;
        Vector3f right = racket.getBody(1).getParticle().position;
        assertEquals(racket.getCentre(0), left);
        assertEquals(racket.getCentre(1), right);
        assertTrue(left.x < 0f && right.x > 0f, left + " " + right);
        assertEquals(-left.x, right.x, 0f);
        assertEquals(left.y, right.y, 0f);
        // I: both -> explicit alone -> midpoint alone -> both, as --set method= names them.
        String[] names = {"explicit", "midpoint", "both"};
        for (String name : names) {
            DemoParameters parameters = racket.getParameters();
            parameters.set("method",
                    parameters.get(parameters.indexOf("method")).indexOfChoice(name));
            int shown = racket.getShownMethod();
            assertEquals(name.equals("both") ? TennisRacketDemo.BOTH : name.equals("explicit")
                    ? 0 : 1, shown, name);
            assertEquals(!name.equals("midpoint"), racket.isShown(0), name);
            assertEquals(!name.equals("explicit"), racket.isShown(1), name);
        }
        String hud = racket.getWindow().formatHud(new StringBuilder()).toString();
        assertTrue(hud.contains("shown (I): both,"), hud);
        assertTrue(hud.contains("explicit Euler vs implicit midpoint: the plates are 0.0° apart"),
                hud);
        assertFalse(hud.contains("NaN"), hud);
    }

    /** The old single-racket path: one body, one integrator, the same start and step. */
    private static RigidBody steppedAlone(TennisRacketDemo racket,
            RotationIntegrator.Angular method, int steps) {
        RigidBody body = new RigidBody(1f, TennisRacketDemo.INERTIA);
        Matrix3f start = new Matrix3f();
        start.set(racket.getStartOrientation());
        body.setOrientation(start);
        start.mult(TennisRacketDemo.BODY_SPIN, body.angularVelocity);
        RotationIntegrator integrator = new RotationIntegrator(
                RotationIntegrator.Orientation.EXACT, method, true);
        for (int i = 0; i < steps; ++i) {
            integrator.step(body, H);
        }
        return body;
    }
}

package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.VectorAssert;
import particlelab.demo.DemoParticle;
import particlelab.demo.Presentation;
import particlelab.view.TextFormat;
import particlelab.world.StateRing;

/**
 * The collisions demo's impulses as the arrows draw them, its paddle's kinematics and the
 * momentum bookkeeping, stepped in plain JUnit (no jME application).
 */
class CollisionsImpulsesTest {

    private static final float H = 1f / 60f;

    private static CollisionsDemo demo(CollisionsDemo.Preset preset, int eTenths, int m1,
            int m2) {
        CollisionsDemo demo = new CollisionsDemo();
        demo.getWorld();
        demo.setMasses(m1, m2);
        demo.setRestitutionTenths(eTenths);
        demo.choose(preset);
        return demo;
    }

    @Test
    void aBallBallContactDrawsEqualAndOppositeImpulsesOfTheClosedForm() {
        // Head-on, m1 = 2 kg at 4 m/s, m2 = 1 kg at -2 m/s, e = 0.5: v_rel = 6 m/s,
        // J = (1+e)·m1·m2/(m1+m2)·v_rel = 1.5 · 2/3 · 6 = 6 N·s.
        CollisionsDemo demo = demo(CollisionsDemo.Preset.HEAD_ON, 5, 1, 0);
        ContactImpulses impulses = demo.getImpulses();
        for (int frame = 0; frame < 120 && impulses.size() == 0; ++frame) {
            demo.getRun().advancePhysics(H);
        }
        assertEquals(1, impulses.size(), "one contact between the balls");
        Vector3f onA = impulses.copyImpulse(0, true, new Vector3f());
        Vector3f onB = impulses.copyImpulse(0, false, new Vector3f());
        // Newton's third law, exactly: B's arrow is A's negated, bit for bit.
        VectorAssert.assertVectorEquals(onA.negate(), onB, 0f);
        // Products and sums of a few floats of order 10: 1e-5 N·s.
        assertEquals(6f, onA.length(), 1e-5f);
        assertEquals(6f, impulses.getMagnitude(0), 1e-5f);
        // Along the line of centres (x), pushing ball 1 (A, the left one) back.
        assertEquals(-6f, onA.x, 1e-5f);
        assertTrue(impulses.isApplied(0, true) && impulses.isApplied(0, false));
        // And it is what the balls got: ball 1 goes from 4 to 4 - 6/2 = 1 m/s.
        assertEquals(1f, demo.getParticles().get(0).getParticle().velocity.x, 1e-5f);
        // The arrows stay half a second of simulated time, then go.
        double found = demo.getWorld().getTimeSeconds();
        assertTrue(impulses.isShown(0, found));
        while (demo.getWorld().getTimeSeconds() - found <= ContactImpulses.HOLD_SECONDS) {
            demo.getRun().advancePhysics(H);
        }
        assertFalse(impulses.isShown(0, demo.getWorld().getTimeSeconds()));
    }

    @Test
    void atAPaddleContactTheBallGetsItsImpulseAndThePaddleKeepsTheScriptsVelocity() {
        CollisionsDemo demo = demo(CollisionsDemo.Preset.PADDLE, 10, 0, 0);
        DemoParticle paddle = demo.getPaddle();
        DemoParticle ball = demo.getParticles().get(0);
        float mass = ball.getParticle().getMass();
        Vector3f before = new Vector3f();
        double start = 0.0;
        for (int frame = 0; frame < 200 && demo.countPaddleContacts() == 0; ++frame) {
            before.set(ball.getParticle().velocity);
            start = demo.getWorld().getTimeSeconds();
            demo.getRun().advancePhysics(H);
        }
        assertEquals(1, demo.countPaddleContacts(), "the paddle hit ball 1 once");
        // The ball's momentum change is the impulse it got (no force acts in free flight).
        Vector3f change = ball.getParticle().velocity.subtract(before).multLocal(mass);
        Vector3f given = demo.copyLastPaddleImpulse(new Vector3f());
        // Round-off of a velocity of a few m/s times 1 kg: 1e-5 kg·m/s.
        VectorAssert.assertVectorEquals(given, change, 1e-5f);
        // The paddle's velocity is the script's speed·U(t) of that step, untouched by the hit.
        float angle = CollisionsDemo.scriptAngle(start);
        Vector3f script = new Vector3f(FastMath.cos(angle), FastMath.sin(angle), 0f)
                .multLocal(CollisionsDemo.PADDLE_SPEED);
        VectorAssert.assertVectorEquals(script, paddle.getParticle().velocity, 0f);
        // The arrows: the ball's side applied with +J, the paddle's -J not applied.
        ContactImpulses impulses = demo.getImpulses();
        assertEquals(1, impulses.size());
        boolean ballIsA = impulses.isApplied(0, true);
        assertFalse(impulses.isApplied(0, !ballIsA), "the paddle's side is not applied");
        VectorAssert.assertVectorEquals(given, impulses.copyImpulse(0, ballIsA, new Vector3f()),
                0f);
        // The closed form of the infinite mass: the resting ball leaves at (1+e)·(u·n) along
        // n, so |J| = m·(1+e)·(u·n), n the unit normal from the paddle to the ball.
        Vector3f n = given.normalize();
        assertEquals(mass * 2f * script.dot(n), given.length(), 1e-5f);
    }

    @Test
    void theHudsMomentumChangeIsTheSumOfThePaddlesImpulses() {
        CollisionsDemo demo = demo(CollisionsDemo.Preset.PADDLE, 10, 0, 0);
        Vector3f sum = new Vector3f();
        Vector3f last = new Vector3f();
        int contacts = 0;
        for (int frame = 0; frame < 600; ++frame) {
            demo.getRun().advancePhysics(H);
            // One paddle contact a step at most here: each new one adds its impulse.
            if (demo.countPaddleContacts() != contacts) {
                assertEquals(contacts + 1, demo.countPaddleContacts());
                contacts = demo.countPaddleContacts();
                sum.addLocal(demo.copyLastPaddleImpulse(last));
            }
        }
        assertTrue(contacts >= 2, "the paddle hit " + contacts + " balls");
        Vector3f total = demo.copyPaddleImpulse(new Vector3f());
        // The same floats summed in the same order.
        VectorAssert.assertVectorEquals(sum, total, 0f);
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        String shown = TextFormat.appendVector(new StringBuilder("ΣJ from the paddle "), total,
                3).toString();
        assertTrue(hud.contains(shown), hud);
        // Momentum bookkeeping: the balls start at rest, and only the paddle's and the walls'
        // impulses change their total (ball-ball contacts cancel): round-off of a few dozen
        // impulses of order 10 N·s, 1e-4 kg·m/s.
        Vector3f now = demo.copyMomentum(new Vector3f());
        Vector3f external = total.add(demo.copyWallImpulse(new Vector3f()));
        VectorAssert.assertVectorEquals(external, now, 1e-4f);
        assertTrue(total.length() > 1f, "the paddle changed the momentum: " + total);
    }

    @Test
    void theArrowsAndThePaddlesReadoutsReplayWithTheirStep() {
        // Home 40 steps from 2.5 s (the paddle's contacts since 1.25 s), then Space: the
        // arrows' contacts and the ΣJ lines belong to the state the ring records.
        CollisionsDemo demo = demo(CollisionsDemo.Preset.PADDLE, 10, 0, 0);
        StateRing ring = demo.getRun().getStateRing();
        String[] lines = new String[400];
        for (int frame = 0; frame < 150; ++frame) {
            demo.getRun().advancePhysics(H);
            lines[(int) ring.getLastIndex()] = ownLines(demo);
        }
        for (int i = 0; i < 40; ++i) {
            assertTrue(demo.getReplayControls().stepBack());
        }
        long shown = demo.getRun().getShownStep();
        assertEquals(lines[(int) shown], ownLines(demo), "read back at step " + shown);
        demo.getClock().setPaused(false);
        for (int i = 0; i < 40; ++i) {
            demo.getRun().advancePhysics(H);
            long index = ring.getLastIndex();
            assertEquals(lines[(int) index], ownLines(demo), "re-simulated step " + index);
        }
    }

    /** The demo's own HUD lines and its arrows' contacts, as text. */
    private static String ownLines(CollisionsDemo demo) {
        StringBuilder text = new StringBuilder();
        demo.writeHudLines(text);
        ContactImpulses impulses = demo.getImpulses();
        double now = demo.getWorld().getTimeSeconds();
        Vector3f scratch = new Vector3f();
        for (int i = 0; i < impulses.size(); ++i) {
            text.append(impulses.isShown(i, now)).append(' ')
                    .append(impulses.copyPoint(i, scratch)).append(' ')
                    .append(impulses.copyImpulse(i, true, scratch)).append(' ')
                    .append(impulses.isApplied(i, true)).append(impulses.isApplied(i, false))
                    .append('\n');
        }
        return text.toString();
    }

    @Test
    void eachPresetHasItsOwnFormulaLine() {
        CollisionsDemo demo = demo(CollisionsDemo.Preset.PADDLE, 10, 0, 0);
        assertTrue(demo.getWindow().formatHud(new StringBuilder()).toString()
                .startsWith("paddle-ball (1/m_paddle = 0):  v' = (1+e) u - e v along n"));
        for (CollisionsDemo.Preset preset : new CollisionsDemo.Preset[] {
            CollisionsDemo.Preset.HEAD_ON, CollisionsDemo.Preset.GLANCING,
            CollisionsDemo.Preset.CRADLE}) {
            demo.choose(preset);
            String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
            assertTrue(hud.startsWith("j = -(1+e) v_rel.n / (1/m1 + 1/m2)"), hud);
        }
    }

    @Test
    void thePaddlesSlideShowsNumbersOfTheFullHud() {
        CollisionsDemo demo = demo(CollisionsDemo.Preset.PADDLE, 10, 0, 0);
        for (int frame = 0; frame < 150; ++frame) {
            demo.getRun().advancePhysics(H);
        }
        assertTrue(demo.countPaddleContacts() >= 1);
        String hud = demo.getWindow().formatHud(new StringBuilder()).toString();
        Presentation slide = demo.getWindow().formatPresentation();
        String readout = slide.getReadout().toString();
        String total = TextFormat.appendVector(new StringBuilder(),
                demo.copyPaddleImpulse(new Vector3f()), 3).toString();
        assertTrue(readout.contains(total), readout);
        assertTrue(hud.contains(total), hud);
        String formulas = slide.getFormulas().toString();
        int at = formulas.indexOf("θ = ");
        String angle = formulas.substring(at + 4, formulas.indexOf(" rad", at));
        assertTrue(hud.contains(") = " + angle + " rad"), angle + " in " + hud);
    }
}

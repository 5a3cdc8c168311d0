package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;

/**
 * The Collisions demo's momentum, energy and paddle, in plain JUnit: its physics and HUD text
 * run without jME. Its framing, labels and a frame with impulse arrows are checked in
 * {@link LectureFramesHeadlessTest}.
 */
class CollisionsDemoTest {

    private static final float H = 1f / 60f;
    private final CollisionsDemo collisions = declared(new CollisionsDemo());

    private Object[] run(CollisionsDemo.Preset preset, int eTenths, int m1, int m2,
            int frames) {
        collisions.setMasses(m1, m2);
        collisions.setRestitutionTenths(eTenths);
        collisions.choose(preset);
        Vector3f start = collisions.copyMomentum(new Vector3f());
        float startEnergy = collisions.kineticEnergy();
        for (int frame = 0; frame < frames; ++frame) {
            collisions.getRun().advancePhysics(H);
        }
        return new Object[] {start, collisions.copyMomentum(new Vector3f()), startEnergy,
            collisions.kineticEnergy(), collisions.countImpactSteps(),
            collisions.getImpactEnergyBefore() - collisions.getImpactEnergyAfter(),
            collisions.getImpactPredictedLoss(), collisions.exitAngleDegrees(),
            collisions.getParticles().get(0).getParticle().velocity.clone(),
            collisions.getParticles().get(4).getParticle().velocity.clone(),
            collisions.getWindow().formatHud(new StringBuilder()).toString()};
    }

    @Test
    void headOnConservesMomentumAndLosesHalfMuOneMinusESquaredVnSquared() {
        // m1 = 2, m2 = 1 kg, normal velocities 4 and -2 m/s, e = 0.5: v_n = 6 m/s,
        // mu = 2/3 kg, loss = 1/2 * 2/3 * 0.75 * 36 = 9 J.
        Object[] r = run(CollisionsDemo.Preset.HEAD_ON, 5, 1, 0, 120);
        assertEquals(1, (Integer) r[4]);
        Vector3f before = (Vector3f) r[0];
        Vector3f after = (Vector3f) r[1];
        // Float round-off of a few products of order 10: 1e-5 kg m/s.
        assertEquals(before.x, after.x, 1e-5f);
        assertEquals(before.y, after.y, 1e-5f);
        assertEquals(9f, (Float) r[6], 1e-4f);
        assertEquals(9f, (Float) r[5], 1e-4f);
        assertEquals(9f, (Float) r[2] - (Float) r[3], 1e-4f);
        String hud = (String) r[10];
        assertTrue(hud.contains("½·μ·(1 − e²)·v_n² = 9.000 J  (v_n = 6.000 m/s, μ = 0.667"
                + " kg)"), hud);
    }

    @Test
    void equalMassesWithEOneLeaveAGlancingImpactAtRightAngles() {
        Object[] r = run(CollisionsDemo.Preset.GLANCING, 10, 0, 0, 120);
        assertEquals(1, (Integer) r[4]);
        // The swept test finds the touch on the segment; the normal is exact to float
        // round-off (1e-6 rad), so the angle is 90 degrees to well under 0.01.
        assertEquals(90f, (Float) r[7], 0.01f);
        assertEquals((Float) r[2], (Float) r[3], 1e-4f, "e = 1 keeps the energy");
    }

    @Test
    void theCradlePassesTheMomentumDownTheRowWorstFirst() {
        Object[] r = run(CollisionsDemo.Preset.CRADLE, 10, 0, 0, 90); // before the far wall
        Vector3f before = (Vector3f) r[0];
        Vector3f after = (Vector3f) r[1];
        assertEquals(before.x, after.x, 1e-4f);
        Vector3f first = (Vector3f) r[8];
        Vector3f last = (Vector3f) r[9];
        // Resolved pair by pair, the row hands the 4 m/s on to its last ball.
        assertEquals(4f, last.x, 0.05f);
        assertEquals(0f, first.x, 0.05f);
    }

    @Test
    void theScriptedPaddleAddsEnergyTheBallsDidNotHave() {
        Object[] r = run(CollisionsDemo.Preset.PADDLE, 10, 0, 0, 300);
        assertEquals(0f, (Float) r[2]);
        assertTrue((Integer) r[4] >= 1, "the paddle hit nothing");
        assertTrue((Float) r[3] > 1f, "energy " + r[3]);
    }

    @Test
    void theExitAngleIsTheImpactsEvenAfterTheBallsBounceOffTheWalls() {
        // 10 s: ball 1 leaves at 2 m/s, 60 degrees below +x, from 3 m up, and meets the ground
        // within 2 s; ball 2 the right wall or the top soon after.
        Object[] r = run(CollisionsDemo.Preset.GLANCING, 10, 0, 0, 600);
        Vector3f v1 = collisionsVelocity(0);
        Vector3f v2 = collisionsVelocity(1);
        double now = Math.toDegrees(Math.acos(v1.dot(v2) / (v1.length() * v2.length())));
        assertTrue(Math.abs(now - 90.0) > 1.0, "the walls did not turn the balls: " + now);
        // The angle is taken from the velocities the impulse left, whatever the walls did
        // since: exact to float round-off as above, 90 to well under 0.01 degrees.
        assertEquals(90f, (Float) r[7], 0.01f);
        String hud = (String) r[10];
        assertTrue(hud.contains("angle between the exit velocities just after the impact:"
                + " 90.0 deg"), hud);
    }

    private Vector3f collisionsVelocity(int ball) {
        return collisions.getParticles().get(ball).getParticle().velocity.clone();
    }

    /**
     * Declare a demo's scene, as a window's start does before anything else: its setters
     * act on the particles the scene created.
     */
    private static <D extends DemoState> D declared(D demo) {
        demo.getRun();
        return demo;
    }
}

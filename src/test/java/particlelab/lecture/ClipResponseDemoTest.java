package particlelab.lecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static particlelab.lecture.ClipResponseDemo.CLIP_LANE;
import static particlelab.lecture.ClipResponseDemo.PHYSICS_LANE;
import static particlelab.lecture.ClipResponseDemo.ROCKET;
import static particlelab.lecture.ClipResponseDemo.TARGET;

import com.jme3.math.Vector3f;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import particlelab.VectorAssert;
import particlelab.physics.SimulationClock;
import particlelab.world.Clip;

/**
 * The clip demo's two lanes in plain JUnit ({@code new ClipResponseDemo()},
 * {@code advancePhysics}): the clip lane plays the same motion whatever the impact, the
 * physics lane gives the closed-form impulse and keeps the momentum, and the HUD's clip error
 * is the difference of the lanes' numbers.
 */
class ClipResponseDemoTest {

    private static final float H = SimulationClock.DEFAULT_STEP_SECONDS;
    /** Steps to fly the 3.5 m run-up at the slowest speed, 4 m/s, with room to spare (s/h). */
    private static final int STEPS_TO_IMPACT = 90;
    /** The clips last at most 1.3 s; 2 s more holds their last keys (in steps). */
    private static final int STEPS_AFTER = 200;
    private static final Pattern NUMBER = Pattern.compile("-?\\d+\\.\\d+");

    /**
     * At 8 and at 32 m/s, level and at 30 degrees, each clip body moves from where it was at the
     * contact by the clip's offset at the time since the contact, every step after the contact's
     * own: the motion is the clip's, whatever the impact. The bodies' positions are about 5 m,
     * where a float's spacing is 4.8e-7 m; the step P += h·V with V = (key − P)/h rounds a few
     * times that, so 1e-5 m is a bound with a margin, far below the clip's centimetres.
     */
    @ParameterizedTest
    @CsvSource({"8, 0", "32, 0", "8, 30", "32, 30"})
    void theClipLaneFollowsTheClipFromTheContactWhateverTheImpact(float speed, float angle) {
        ClipResponseDemo demo = new ClipResponseDemo();
        demo.fire(speed, angle);
        Clip clip = demo.getClip();
        int checked = 0;
        Vector3f origin = new Vector3f();
        Vector3f expected = new Vector3f();
        Vector3f offset = new Vector3f();
        boolean pastContactStep = false;
        for (int i = 0; i < STEPS_TO_IMPACT + STEPS_AFTER; ++i) {
            boolean hitBefore = demo.hasHit(CLIP_LANE);
            demo.getRun().advancePhysics(H);
            pastContactStep |= hitBefore;
            if (!pastContactStep) {
                continue;
            }
            double clipSeconds = demo.getWorld().getTimeSeconds() - demo.getClipStartSeconds();
            for (int b = 0; b < 2; ++b) {
                clip.copyOffset(clip.indexOf(b == ROCKET ? "rocket" : "target"), clipSeconds,
                        offset);
                expected.set(demo.copyClipOrigin(b, origin)).addLocal(offset);
                VectorAssert.assertVectorEquals(expected, demo.body(CLIP_LANE, b).getPosition(),
                        1e-5f, "step " + i + ", body " + b);
            }
            ++checked;
        }
        assertTrue(checked > STEPS_AFTER, "checked " + checked + " steps after the contact");
    }

    /**
     * Two speeds, two angles: the clip lane's velocities, momentum and energy after the impact
     * are the same bits (they come from the clip alone), and where its bodies come to rest,
     * measured from where they were at the contact, agrees to float rounding (see above);
     * the physics lane's momentum is 4 times as large at 4 times the speed.
     */
    @Test
    void theClipGivesTheSameResultAtTwoImpactSpeedsAndThePhysicsDoesNot() {
        ClipResponseDemo slow = flown(8f, 0f);
        ClipResponseDemo fast = flown(32f, 20f);
        for (int b = 0; b < 2; ++b) {
            assertEquals(slow.copyVelocityAfter(CLIP_LANE, b, new Vector3f()),
                    fast.copyVelocityAfter(CLIP_LANE, b, new Vector3f()));
            Vector3f slowRest = slow.body(CLIP_LANE, b).getPosition()
                    .subtract(slow.copyClipOrigin(b, new Vector3f()));
            Vector3f fastRest = fast.body(CLIP_LANE, b).getPosition()
                    .subtract(fast.copyClipOrigin(b, new Vector3f()));
            VectorAssert.assertVectorEquals(slowRest, fastRest, 1e-5f);
        }
        assertEquals(slow.momentumAfter(CLIP_LANE, new Vector3f()),
                fast.momentumAfter(CLIP_LANE, new Vector3f()));
        assertEquals(slow.energyAfter(CLIP_LANE), fast.energyAfter(CLIP_LANE), 0f);
        // The physics scales with the shot: p = m_r·v (kept), 4 times at 4 times v.
        float slowP = slow.momentumAfter(PHYSICS_LANE, new Vector3f()).length();
        float fastP = fast.momentumAfter(PHYSICS_LANE, new Vector3f()).length();
        assertEquals(4f, fastP / slowP, 1e-4f);
        assertNotEquals(slow.energyAfter(PHYSICS_LANE), fast.energyAfter(PHYSICS_LANE));
    }

    /**
     * The physics lane after its impact against the closed form of the 1-D impulse along the
     * flight (the hit is head-on, n the flight direction d):
     * {@code v_r' = v·d·(m_r − e·m_t)/(m_r + m_t)}, {@code v_t' = v·d·(1+e)·m_r/(m_r + m_t)},
     * and the momentum {@code m_r·v·d} kept. The normal comes from float positions about 5 m
     * from the origin over the 0.5 m reach, so its direction is good to about 1e-6 rad; with
     * the float velocities that bounds the error near 2e-6·v, and 1e-5·v leaves a margin.
     */
    @ParameterizedTest
    @CsvSource({"12, 0, 0.5, 1, 2", "40, 30, 1, 1, 1", "4, 10, 0, 2, 0.5", "25, 20, 0.8, 5, 10"})
    void thePhysicsLaneGivesTheClosedFormImpulseAndKeepsTheMomentum(float v, float angle,
            float e, float rocketKg, float targetKg) {
        ClipResponseDemo demo = new ClipResponseDemo();
        demo.getParameters().set("e", e);
        demo.getParameters().set("m_rocket", rocketKg);
        demo.getParameters().set("m_target", targetKg);
        demo.fire(v, angle);
        for (int i = 0; i < STEPS_TO_IMPACT && !demo.hasHit(PHYSICS_LANE); ++i) {
            demo.getRun().advancePhysics(H);
        }
        assertTrue(demo.hasHit(PHYSICS_LANE));
        double theta = Math.toRadians(angle);
        Vector3f d = new Vector3f((float) Math.cos(theta), (float) Math.sin(theta), 0f);
        float total = rocketKg + targetKg;
        float tolerance = 1e-5f * v;
        VectorAssert.assertVectorEquals(d.mult(v * (rocketKg - e * targetKg) / total),
                demo.copyVelocityAfter(PHYSICS_LANE, ROCKET, new Vector3f()), tolerance);
        VectorAssert.assertVectorEquals(d.mult(v * (1f + e) * rocketKg / total),
                demo.copyVelocityAfter(PHYSICS_LANE, TARGET, new Vector3f()), tolerance);
        VectorAssert.assertVectorEquals(d.mult(rocketKg * v),
                demo.momentumAfter(PHYSICS_LANE, new Vector3f()), tolerance * total);
        // Energy lost: ½·μ·(1 − e²)·v², μ = m_r·m_t/(m_r + m_t); relative float rounding.
        float lost = 0.5f * rocketKg * targetKg / total * (1f - e * e) * v * v;
        float before = 0.5f * rocketKg * v * v;
        assertEquals(before - lost, demo.energyAfter(PHYSICS_LANE), 1e-4f * before);
    }

    /**
     * The HUD's clip error line is the difference of the two lanes' lines: the energy it says
     * the clip creates or loses is the clip lane's KE less the physics lane's, and |dp| the
     * distance of their momenta, to the printed digits (each figure rounded to 0.005, so the
     * difference of two is within 0.01, and a distance of rounded components within 0.015).
     */
    @ParameterizedTest
    @CsvSource({"8, 0", "36, 20"})
    void theHudsClipErrorIsTheDifferenceOfTheLanes(float speed, float angle) {
        ClipResponseDemo demo = flown(speed, angle);
        StringBuilder hud = new StringBuilder();
        demo.writeHudLines(hud);
        String[] lines = hud.toString().split("\n");
        double[] physics = numbers(lines[0]);
        double[] clip = numbers(lines[1]);
        // A lane: v_r (x, y), v_t (x, y), p (x, y), KE; the clip's line then its error:
        // |dv_r|, |dv_t|, |dp|, KE created or lost.
        assertEquals(7, physics.length, lines[0]);
        assertEquals(11, clip.length, lines[1]);
        int physicsAt = 0;
        int clipAt = 0;
        double[] error = java.util.Arrays.copyOfRange(clip, 7, 11);
        double energy = clip[clipAt + 6] - physics[physicsAt + 6];
        double sign = lines[1].contains("lost") ? -1.0 : 1.0;
        assertEquals(energy, sign * error[3], 0.01, hud.toString());
        double dpx = clip[clipAt + 4] - physics[physicsAt + 4];
        double dpy = clip[clipAt + 5] - physics[physicsAt + 5];
        assertEquals(Math.hypot(dpx, dpy), error[2], 0.015, hud.toString());
        for (int b = 0; b < 2; ++b) {
            double dvx = clip[clipAt + 2 * b] - physics[physicsAt + 2 * b];
            double dvy = clip[clipAt + 2 * b + 1] - physics[physicsAt + 2 * b + 1];
            assertEquals(Math.hypot(dvx, dvy), error[b], 0.015, hud.toString());
        }
        assertEquals(demo.energyError(), demo.energyAfter(CLIP_LANE)
                - demo.energyAfter(PHYSICS_LANE), 0f);
    }

    /**
     * The shots line keeps each shot: at two speeds its clip column reads the same and its
     * physics column differs.
     */
    @Test
    void theShotsLineShowsTheClipUnchangedAndThePhysicsChanged() {
        ClipResponseDemo demo = new ClipResponseDemo();
        demo.fire(8f, 0f);
        step(demo, STEPS_TO_IMPACT);
        demo.fire(24f, 0f);
        step(demo, STEPS_TO_IMPACT);
        assertEquals(2, demo.countShots());
        StringBuilder hud = new StringBuilder();
        demo.writeHudLines(hud);
        String line = hud.toString().split("\n")[2];
        String[] shots = line.substring(line.indexOf("):") + 2).split(";");
        assertEquals(2, shots.length, line);
        String[] first = shots[0].split("\\|");
        String[] second = shots[1].split("\\|");
        assertTrue(first[0].trim().startsWith("8 m/s 0 deg:"), line);
        assertTrue(second[0].trim().startsWith("24 m/s 0 deg:"), line);
        assertEquals(first[1], second[1], "clip KE: " + line);
        assertNotEquals(first[0].substring(first[0].indexOf(':')),
                second[0].substring(second[0].indexOf(':')), "physics KE: " + line);
    }

    private static ClipResponseDemo flown(float speed, float angle) {
        ClipResponseDemo demo = new ClipResponseDemo();
        demo.fire(speed, angle);
        step(demo, STEPS_TO_IMPACT + STEPS_AFTER);
        assertTrue(demo.hasHit(PHYSICS_LANE) && demo.hasHit(CLIP_LANE));
        return demo;
    }

    private static void step(ClipResponseDemo demo, int steps) {
        for (int i = 0; i < steps; ++i) {
            demo.getRun().advancePhysics(H);
        }
    }

    private static double[] numbers(String line) {
        Matcher m = NUMBER.matcher(line);
        java.util.List<Double> found = new java.util.ArrayList<>();
        while (m.find()) {
            found.add(Double.parseDouble(m.group()));
        }
        double[] values = new double[found.size()];
        for (int i = 0; i < values.length; ++i) {
            values[i] = found.get(i);
        }
        return values;
    }
}

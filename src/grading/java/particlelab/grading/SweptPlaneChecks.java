package particlelab.grading;

import static particlelab.grading.Numbers.f;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.coursework.SweptPlaneExercise;
import particlelab.world.SplitMixRandom;

/** Exercise 6's checks: the contact time, no miss over many fast shots, no false touch. */
final class SweptPlaneChecks {

    private static final float H = 1f / 60f;
    private static final float RADIUS = 0.1f;
    /** The wall's front face: the plane x = 0, its front toward −x. */
    private static final Vector3f NORMAL = new Vector3f(-1f, 0f, 0f);
    private static final int SHOTS = 10_000;
    private static final long SEED = 31L;

    private SweptPlaneChecks() {
    }

    static Exercise exercise() {
        return new Exercise(6, "SweptPlane", SweptPlaneExercise.class, "Tunnelling",
                List.of(new Check("contact time", SweptPlaneChecks::slowSphereTouchesOnTime),
                        new Check("never misses", SweptPlaneChecks::fastShotsNeverTunnel),
                        new Check("no false touch", SweptPlaneChecks::missesAreMisses)));
    }

    /** Slow spheres that end the step overlapping the face: {@code t = (r − dist)/(n·v)}. */
    private static void slowSphereTouchesOnTime(Submission s) throws Exception {
        SweptPlaneExercise test = s.create(SweptPlaneExercise.class);
        float[][] cases = {{-0.15f, 6f, 1f}, {-0.2f, 9f, 0f}, {-0.12f, 3f, -2f}};
        for (float[] c : cases) {
            Vector3f p = new Vector3f(c[0], 1f, 0f);
            Vector3f vel = new Vector3f(c[1], c[2], 0f);
            double expected = (RADIUS - (-c[0])) / (-c[1]);
            float t = test.hitTime(p, vel, RADIUS, NORMAL, 0f, H);
            // Times near 0.01 s from two float operations: 1e-7 s.
            if (!Numbers.near(expected, t, 1e-7)) {
                throw new Mistake("a sphere at x = " + f(c[0]) + " moving at " + f(c[1])
                        + " m/s touches x = 0 at t = (r - dist)/(n·v) = " + f(expected)
                        + " s, you said " + f(t));
            }
        }
        float t = test.hitTime(new Vector3f(-0.05f, 0f, 0f), new Vector3f(1f, 0f, 0f), RADIUS,
                NORMAL, 0f, H);
        if (t != 0f) {
            throw new Mistake("a sphere already touching at the start touches at t = 0,"
                    + " you said " + f(t));
        }
    }

    /** Random fast shots that cross the face within the step, ending beyond a thin wall. */
    private static void fastShotsNeverTunnel(Submission s) throws Exception {
        SweptPlaneExercise test = s.create(SweptPlaneExercise.class);
        SplitMixRandom random = new SplitMixRandom(SEED);
        int missed = 0;
        Vector3f p = new Vector3f();
        Vector3f vel = new Vector3f();
        for (int shot = 0; shot < SHOTS; ++shot) {
            float speed = (float) (30.0 + 470.0 * random.nextDouble());
            float angle = (float) (1.2 * (random.nextDouble() - 0.5));
            vel.set(speed * (float) Math.cos(angle), speed * (float) Math.sin(angle), 0f);
            // Start in front of the face, touching it between 0.1 % and 99.9 % of the step.
            float reach = vel.x * H;
            float fraction = (float) (0.001 + 0.998 * random.nextDouble());
            p.set(-(RADIUS + fraction * reach), 0f, 0f);
            float t = test.hitTime(p, vel, RADIUS, NORMAL, 0f, H);
            double expected = (RADIUS + p.x) / -vel.x;
            // Relative 1e-5: a few float roundings of numbers up to 8 m.
            if (!(t >= 0f && t <= H && Math.abs(t - expected) <= 1e-5 * H)) {
                ++missed;
            }
        }
        if (missed > 0) {
            throw new Mistake("missed " + missed + " of " + SHOTS + " shots that reach the wall"
                    + " within the step: an overlap test looks only at the step's end;"
                    + " the swept test solves for the time of touch");
        }
    }

    /** Moving away, along the face, or stopping short: no touch (−1). */
    private static void missesAreMisses(Submission s) throws Exception {
        SweptPlaneExercise test = s.create(SweptPlaneExercise.class);
        float[][] cases = {{-1f, -50f, 0f}, {-1f, 0f, 20f}, {-1f, 30f, 0f}};
        for (float[] c : cases) {
            float t = test.hitTime(new Vector3f(c[0], 0f, 0f), new Vector3f(c[1], c[2], 0f),
                    RADIUS, NORMAL, 0f, H);
            if (t != -1f) {
                throw new Mistake("a sphere 0.9 m from the wall moving at (" + f(c[1]) + ", "
                        + f(c[2]) + ") m/s does not touch it within h, you said t = " + f(t));
            }
        }
    }
}

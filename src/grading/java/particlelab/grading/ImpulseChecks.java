package particlelab.grading;

import static particlelab.grading.Numbers.f;
import static particlelab.grading.Numbers.v;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.coursework.ImpulseExercise;

/** Exercise 5's checks: momentum kept, separation at e × approach, separating pairs left alone. */
final class ImpulseChecks {

    /** Cases: m1, m2 (kg), e, then v1 and v2 (m/s); centres at (0,0,0) and (1.2, 0.5, 0). */
    private static final float[][] CASES = {
        {1f, 1f, 1f, 3f, 0f, 0f, -1f, 0f, 0f},
        {2f, 0.5f, 0.5f, 4f, 1f, 0f, 0f, -2f, 1f},
        {1f, 3f, 0.8f, 2f, 2f, -1f, -3f, 0f, 0f},
    };
    private static final Vector3f P1 = new Vector3f();
    private static final Vector3f P2 = new Vector3f(1.2f, 0.5f, 0f);

    private ImpulseChecks() {
    }

    static Exercise exercise() {
        return new Exercise(5, "Impulse", ImpulseExercise.class, "Collision resolution",
                List.of(new Check("momentum", ImpulseChecks::momentumIsKept),
                        new Check("restitution", ImpulseChecks::separationIsEApproach),
                        new Check("separating", ImpulseChecks::separatingPairIsLeftAlone)));
    }

    private static void momentumIsKept(Submission s) throws Exception {
        for (float[] c : CASES) {
            Vector3f v1 = new Vector3f(c[3], c[4], c[5]);
            Vector3f v2 = new Vector3f(c[6], c[7], c[8]);
            Vector3f before = v1.mult(c[0]).addLocal(v2.mult(c[1]));
            s.create(ImpulseExercise.class).resolve(P1, v1, c[0], P2, v2, c[1], c[2]);
            Numbers.requireFinite(v1, "v1");
            Vector3f after = v1.mult(c[0]).addLocal(v2.mult(c[1]));
            // Momenta of a few kg·m/s, a few float roundings each: 1e-5 kg·m/s.
            if (after.distance(before) > 1e-5f) {
                throw new Mistake("momentum m1 v1 + m2 v2 went from " + v(before) + " to "
                        + v(after) + ": apply +j/m1 to v1 and -j/m2 to v2, along the same n");
            }
        }
    }

    private static void separationIsEApproach(Submission s) throws Exception {
        Vector3f n = P1.subtract(P2).normalizeLocal();
        for (float[] c : CASES) {
            Vector3f v1 = new Vector3f(c[3], c[4], c[5]);
            Vector3f v2 = new Vector3f(c[6], c[7], c[8]);
            float approach = -(v1.dot(n) - v2.dot(n));
            s.create(ImpulseExercise.class).resolve(P1, v1, c[0], P2, v2, c[1], c[2]);
            Numbers.requireFinite(v2, "v2");
            float separation = v1.dot(n) - v2.dot(n);
            // Speeds of a few m/s: 1e-5 m/s of rounding.
            if (Numbers.near(c[2] * approach, separation, 1e-5)) {
                continue;
            }
            if (Numbers.near(0.0, separation, 1e-5)) {
                throw new Mistake("with e = " + f(c[2]) + " the spheres stick (separate at 0):"
                        + " the impulse lacks its (1+e), j = -(1+e)(v1-v2)·n/(1/m1+1/m2)");
            }
            throw new Mistake("with e = " + f(c[2]) + " they approach at " + f(approach)
                    + " m/s and separate at " + f(separation) + ", not e × approach");
        }
    }

    private static void separatingPairIsLeftAlone(Submission s) throws Exception {
        Vector3f v1 = new Vector3f(-1f, 0.5f, 0f);
        Vector3f v2 = new Vector3f(2f, 0f, 1f);
        s.create(ImpulseExercise.class).resolve(P1, v1, 1f, P2, v2, 2f, 0.5f);
        if (!v1.equals(new Vector3f(-1f, 0.5f, 0f)) || !v2.equals(new Vector3f(2f, 0f, 1f))) {
            throw new Mistake("spheres moving apart were changed to v1 = " + v(v1) + ", v2 = "
                    + v(v2) + ": only an approaching pair, (v1-v2)·n < 0, gets an impulse");
        }
    }
}

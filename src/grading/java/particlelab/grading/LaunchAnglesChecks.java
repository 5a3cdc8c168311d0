package particlelab.grading;

import static particlelab.grading.Numbers.f;

import java.util.List;
import particlelab.coursework.LaunchAnglesExercise;

/** Exercise 4's checks: both arcs pass through the target; out of reach is said so. */
final class LaunchAnglesChecks {

    private static final float G = 9.8f;
    /** Reachable targets (s m/s, x m, y m): raised, lowered, far. */
    private static final float[][] REACHABLE = {{30f, 50f, 10f}, {25f, 40f, -5f}, {40f, 100f, 20f}};

    private LaunchAnglesChecks() {
    }

    static Exercise exercise() {
        return new Exercise(4, "LaunchAngles", LaunchAnglesExercise.class, "Aim at any height",
                List.of(new Check("both arcs", LaunchAnglesChecks::bothArcsPassThrough),
                        new Check("out of reach", LaunchAnglesChecks::unreachableIsRefused)));
    }

    /** Each angle's parabola {@code y = x·tanθ − g·x²·(1 + tan²θ)/(2s²)} meets the target. */
    private static void bothArcsPassThrough(Submission s) throws Exception {
        LaunchAnglesExercise solver = s.create(LaunchAnglesExercise.class);
        for (float[] target : REACHABLE) {
            float[] angles = {Float.NaN, Float.NaN};
            if (!solver.angles(target[0], target[1], target[2], G, angles)) {
                throw new Mistake("(" + f(target[1]) + ", " + f(target[2]) + ") at " + f(target[0])
                        + " m/s is in reach (s^4 >= g(g x^2 + 2 y s^2)), you said it is not");
            }
            for (int i = 0; i < 2; ++i) {
                double tan = Math.tan(angles[i]);
                double x = target[1];
                double height = x * tan - G * x * x * (1.0 + tan * tan)
                        / (2.0 * target[0] * target[0]);
                // A float angle is within 6e-8 rad; dy/dθ is under 2e3 m/rad here: 1e-3 m.
                if (!Numbers.near(target[2], height, 1e-3)) {
                    throw new Mistake("at " + f(Math.toDegrees(angles[i])) + " degrees the shot"
                            + " passes x = " + f(x) + " at y = " + f(height) + ", not "
                            + f(target[2]) + ": tan θ = (s^2 ∓ √(s^4 - g(g x^2 + 2 y s^2)))/(g x)");
                }
            }
            if (!(angles[0] < angles[1])) {
                throw new Mistake("the low angle " + f(angles[0]) + " is not below the high "
                        + f(angles[1]) + ": store the low one in [0]");
            }
        }
    }

    /** {@code s⁴ < g·(g·x² + 2·y·s²)}: no real angle. */
    private static void unreachableIsRefused(Submission s) throws Exception {
        LaunchAnglesExercise solver = s.create(LaunchAnglesExercise.class);
        float[] angles = new float[2];
        // 20 m/s to (50, 10): s^4 = 160000 < 9.8·(9.8·2500 + 2·10·400) = 318500.
        if (solver.angles(20f, 50f, 10f, G, angles)) {
            throw new Mistake("(50, 10) at 20 m/s is out of reach (s^4 < g(g x^2 + 2 y s^2)),"
                    + " you returned angles " + f(angles[0]) + " and " + f(angles[1]));
        }
    }
}

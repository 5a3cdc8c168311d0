package particlelab.grading;

import static particlelab.grading.Numbers.f;

import java.util.List;
import particlelab.coursework.AimingExercise;

/** Exercise 3's checks: the lecture's aim, and the correction that lands exactly when stepped. */
final class AimingChecks {

    private static final float G = 9.8f;
    /** Cases (vx m/s, S m, 1/h): S/(vx·h) is a whole number of steps, the landing on a step. */
    private static final float[][] STEPPED = {{20f, 100f, 50f}, {15f, 60f, 40f}, {25f, 80f, 100f}};

    private AimingChecks() {
    }

    static Exercise exercise() {
        return new Exercise(3, "Aiming", AimingExercise.class, "HelloAiming",
                List.of(new Check("formula", AimingChecks::continuousFlightLandsOnTheTarget),
                        new Check("discrete", AimingChecks::steppedFlightLandsOnTheTarget)));
    }

    /** The parabola launched with {@code vy} lands at {@code 2·vx·vy/g = S}. */
    private static void continuousFlightLandsOnTheTarget(Submission s) throws Exception {
        AimingExercise aim = s.create(AimingExercise.class);
        for (float[] shot : STEPPED) {
            float vy = aim.continuousVy(shot[0], shot[1], G);
            double landing = 2.0 * shot[0] * vy / G;
            // One float division and product: relative 1e-6 of S.
            if (!Numbers.near(shot[1], landing, 1e-6 * shot[1])) {
                throw new Mistake("vy = " + f(vy) + " for vx = " + f(shot[0]) + ", S = "
                        + f(shot[1]) + ": the parabola lands at 2 vx vy/g = " + f(landing)
                        + ", so vy = g S/(2 vx)");
            }
        }
    }

    /** Stepped in float32 with the recipe, the shot is at height 0 when x reaches S. */
    private static void steppedFlightLandsOnTheTarget(Submission s) throws Exception {
        AimingExercise aim = s.create(AimingExercise.class);
        for (float[] shot : STEPPED) {
            float vx = shot[0];
            float range = shot[1];
            float h = 1f / shot[2];
            float continuous = G * range / (2f * vx);
            float vy = aim.discreteVy(vx, range, G, h);
            int steps = Math.round(range / (vx * h));
            float y = 0f;
            float vyNow = vy;
            for (int n = 0; n < steps; ++n) {
                vyNow -= G * h;      // V += h·a
                y += h * vyNow;      // P += h·V
            }
            // Heights up to 25 m (ulp 2e-6 m) over at most 320 steps: rounding under 2e-3 m.
            // The continuous aim misses by g·h·S/(2·vx), 0.16 to 0.49 m here.
            if (Numbers.near(0.0, y, 2e-3)) {
                continue;
            }
            if (Math.abs(vy - continuous) <= 1e-6f * continuous) {
                throw new Mistake("you fired the continuous aim: stepped with h = " + f(h)
                        + " it flies the parabola of vy - g h/2 and lands vx·h short");
            }
            throw new Mistake("vy = " + f(vy) + " stepped with h = " + f(h) + " is at y = "
                    + f(y) + " m when x reaches S = " + f(range) + ", not 0");
        }
    }
}

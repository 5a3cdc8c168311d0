package particlelab.grading;

import static particlelab.grading.Numbers.f;
import static particlelab.grading.Numbers.near;
import static particlelab.grading.Numbers.v;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.coursework.RecipeExercise;

/** Exercise 1's checks: the recipe against the Euler step's discrete closed forms. */
final class RecipeChecks {

    private static final float H = 1f / 60f;
    private static final float G = 9.8f;

    private RecipeChecks() {
    }

    static Exercise exercise() {
        return new Exercise(1, "Recipe", RecipeExercise.class, "Simulation recipe", List.of(
                new Check("velocity", RecipeChecks::velocityFollowsTheDiscreteDragSolution),
                new Check("order", RecipeChecks::positionUsesTheNewVelocity),
                new Check("thrust", RecipeChecks::thrustActsAlongTheVelocity)));
    }

    /** Gravity and linear drag: {@code V_n = V* + (V0 − V*)·rⁿ}, {@code r = 1 − k·h}. */
    private static void velocityFollowsTheDiscreteDragSolution(Submission s) throws Exception {
        RecipeExercise recipe = s.create(RecipeExercise.class);
        float mass = 2f;
        float drag = 1f;
        int steps = 120;
        Vector3f p = new Vector3f();
        Vector3f vel = new Vector3f(20f, 30f, 0f);
        Vector3f g = new Vector3f(0f, -G, 0f);
        for (int n = 0; n < steps; ++n) {
            recipe.step(p, vel, mass, g, drag, 0f, H);
        }
        Numbers.requireFinite(vel, "V");
        double k = drag / mass;
        double decay = Math.pow(1.0 - k * H, steps);
        double vx = 20.0 * decay;
        double terminalY = -G / k;
        double vy = terminalY + (30.0 - terminalY) * decay;
        // 120 float steps of |V| ≤ 36 m/s, each rounding at most a few ulp (4e-6 m/s), the
        // errors damped by r < 1: far under 1e-3 m/s. A missing drag is off by metres per second.
        if (!near(vx, vel.x, 1e-3) || !near(vy, vel.y, 1e-3) || vel.z != 0f) {
            throw new Mistake("V after " + steps + " steps is " + v(vel) + ", the recipe's V*"
                    + " + (V0 - V*)(1 - k h)^n gives (" + f(vx) + ", " + f(vy) + ", 0):"
                    + " check a = g - (b/m) V and V += h a");
        }
    }

    /** Gravity only: {@code y_n = n·h·vy − g·h²·n(n+1)/2}; P before V gives {@code n(n−1)/2}. */
    private static void positionUsesTheNewVelocity(Submission s) throws Exception {
        RecipeExercise recipe = s.create(RecipeExercise.class);
        int steps = 100;
        Vector3f p = new Vector3f();
        Vector3f vel = new Vector3f(20f, 30f, 0f);
        Vector3f g = new Vector3f(0f, -G, 0f);
        for (int n = 0; n < steps; ++n) {
            recipe.step(p, vel, 1f, g, 0f, 0f, H);
        }
        Numbers.requireFinite(p, "P");
        double x = steps * H * 20.0;
        double semiImplicit = steps * H * 30.0 - G * H * H * steps * (steps + 1) / 2.0;
        double positionFirst = steps * H * 30.0 - G * H * H * steps * (steps - 1) / 2.0;
        // Positions up to 50 m (ulp 4e-6 m) over 100 steps: under 2e-3 m of rounding. The two
        // orders differ by g·h²·n = 0.27 m.
        double tolerance = 2e-3;
        if (near(x, p.x, tolerance) && near(semiImplicit, p.y, tolerance)) {
            return;
        }
        if (near(positionFirst, p.y, tolerance)) {
            throw new Mistake("P was updated before V: your shot lands vx·h long"
                    + " (forward Euler); the recipe updates V first, then P with the new V");
        }
        throw new Mistake("P after " + steps + " steps is " + v(p) + ", the recipe gives ("
                + f(x) + ", " + f(semiImplicit) + ", 0): P += h V with the new V");
    }

    /** Thrust a along V, linear drag k: the speed follows {@code s' = s + h·(a − k·s)}. */
    private static void thrustActsAlongTheVelocity(Submission s) throws Exception {
        RecipeExercise recipe = s.create(RecipeExercise.class);
        float thrust = 2f;
        float drag = 0.5f;
        int steps = 120;
        Vector3f p = new Vector3f();
        Vector3f vel = new Vector3f(3f, 4f, 0f);
        Vector3f none = new Vector3f();
        for (int n = 0; n < steps; ++n) {
            recipe.step(p, vel, 1f, none, drag, thrust, H);
        }
        Numbers.requireFinite(vel, "V under thrust");
        double terminal = thrust / drag;
        double speed = terminal + (5.0 - terminal) * Math.pow(1.0 - drag * H, steps);
        // Speeds of 4-5 m/s, 120 float steps: rounding under 1e-4 m/s; the direction keeps
        // (3, 4)/5, so 4·vx − 3·vy stays 0 within the same rounding.
        if (!near(speed, vel.length(), 1e-4) || Math.abs(4f * vel.x - 3f * vel.y) > 1e-4) {
            throw new Mistake("thrust 2 N along V with b = 0.5: V became " + v(vel)
                    + ", speed " + f(vel.length()) + " instead of " + f(speed)
                    + " along (3, 4)/5: thrust adds T V/|V|");
        }
        Vector3f rest = new Vector3f();
        recipe.step(p, rest, 1f, none, drag, thrust, H);
        if (rest.lengthSquared() != 0f) {
            throw new Mistake("thrust at rest gave V = " + v(rest) + ": V/|V| has no direction"
                    + " at |V| = 0, so thrust acts only while the particle moves");
        }
    }
}

package particlelab.solutions;

import particlelab.coursework.LaunchAnglesExercise;

/** Exercise 4, solved: {@code tan θ = (s² ∓ √(s⁴ − g(g·x² + 2·y·s²)))/(g·x)}. */
public final class LaunchAngles implements LaunchAnglesExercise {

    @Override
    public boolean angles(float speed, float x, float y, float gravity, float[] storeAngles) {
        double s2 = (double) speed * speed;
        double discriminant = s2 * s2 - gravity * ((double) gravity * x * x + 2.0 * y * s2);
        if (discriminant < 0.0) {
            return false;
        }
        double root = Math.sqrt(discriminant);
        storeAngles[0] = (float) Math.atan((s2 - root) / (gravity * x));
        storeAngles[1] = (float) Math.atan((s2 + root) / (gravity * x));
        return true;
    }
}

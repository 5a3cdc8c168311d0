package particlelab.exercises;

import com.jme3.math.Vector3f;
import particlelab.demo.DemoState;

/**
 * Exercise 8. Slide: "Wind" (docs/extending.md, the student guide's worked example).
 *
 * <p>Write a demo of your own: in {@code createScene()}, add two particles launched from the
 * origin at {@link #LAUNCH} with mass {@link #MASS_KG}: first "still air" under gravity only,
 * then "in the wind" under gravity and a wind force {@code F = b·(W − V)} with {@link #WIND} and
 * {@link #WIND_B}, both stopping at the ground; frame the view with {@code setView}.
 *
 * <p>Hint: the wind is a {@code particlelab.physics.Force} (a nested class here) whose
 * {@code addForce} adds {@code b·W} and {@code −b·V} with two {@code scaleAdd} calls. Follow
 * docs/extending.md, sections 3 and 5.
 */
public final class OwnDemo extends DemoState {

    /** The wind's velocity W (in m/s). */
    public static final Vector3f WIND = new Vector3f(-6f, 0f, 0f);
    /** The wind's drag coefficient b (in N·s/m). */
    public static final float WIND_B = 0.3f;
    /** Both balls' launch velocity (in m/s). */
    public static final Vector3f LAUNCH = new Vector3f(10f, 10f, 0f);
    /** Both balls' mass (in kg). */
    public static final float MASS_KG = 1f;

    /** A demo titled for the menu. */
    public OwnDemo() {
        super("Own demo (exercise 8)");
    }

    @Override
    protected void createScene() {
        throw new UnsupportedOperationException("not written yet");
    }
}

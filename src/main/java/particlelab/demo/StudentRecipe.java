package particlelab.demo;

import com.jme3.math.Vector3f;
import particlelab.reference.MotionState;
import particlelab.coursework.RecipeExercise;
import particlelab.coursework.StudentRunner;
import particlelab.view.TextFormat;

/**
 * The student lane's mover: exercise 1's class ({@link RecipeExercise}, found by name), one
 * call of its {@code step} per step of the demo, through a {@link StudentRunner}, so a recipe
 * that throws, gives NaN or never returns stops the lane with one line and nothing else.
 *
 * <p>The state crosses in float, as the student's recipe takes it: the lane's double state
 * holds the floats the recipe returned, so a float run of the recipe is what the lane flies.
 * Allocates nothing per step while the recipe returns finite numbers.
 */
final class StudentRecipe {

    /** The exercise's class, in the package the app was started with. */
    static final String SIMPLE_NAME = "Recipe";

    private final StudentRunner runner;
    /** The student's instance (null before the first step, or when it could not be made). */
    private RecipeExercise recipe;
    private boolean created;
    /** The call the worker makes: step the fields below once. */
    private final Runnable stepCall = this::callStep;
    /** The recipe's arguments and results (m, m/s, m/s², kg, N·s/m, N, s). */
    private final Vector3f position = new Vector3f();
    private final Vector3f velocity = new Vector3f();
    private final Vector3f gravity = new Vector3f();
    private float massKg;
    private float dragNsPerM;
    private float thrustN;
    private float stepSeconds;
    /** Steps taken since the launch; the one that went wrong is named. */
    private int steps;
    /** What stopped the lane, or null. */
    private String problem;

    /**
     * Create the mover for one class.
     *
     * @param className the class (not null), e.g. {@code particlelab.exercises.Recipe}
     * @param limitNanos how long one call may take (in ns, &gt;0)
     */
    StudentRecipe(String className, long limitNanos) {
        runner = new StudentRunner(className, limitNanos);
    }

    /**
     * Return the class run.
     *
     * @return its binary name
     */
    String getClassName() {
        return runner.getClassName();
    }

    /** A new launch: count from 0 and try again, unless a call was abandoned. */
    void restart() {
        steps = 0;
        problem = null;
        runner.clearProblem();
    }

    /**
     * Step the lane's state once with the student's recipe, under the followed sphere's
     * forces.
     *
     * @param state the lane's state (modified: rounded to float, then stepped)
     * @param g gravity (in m/s², not modified)
     * @param mass m (in kg)
     * @param drag b (in N·s/m)
     * @param thrust T (in N)
     * @param h the step (in s)
     * @return true if the recipe returned a finite state; false if the lane must stop
     *     ({@link #getProblem()} says why)
     */
    boolean step(MotionState state, Vector3f g, float mass, float drag, float thrust,
            float h) {
        if (!created) {
            created = true;
            recipe = runner.create(RecipeExercise.class);
        }
        if (recipe == null) {
            problem = runner.getProblem();
            return false;
        }
        double[] p = state.position;
        double[] v = state.velocity;
        position.set((float) p[0], (float) p[1], (float) p[2]);
        velocity.set((float) v[0], (float) v[1], (float) v[2]);
        gravity.set(g);
        massKg = mass;
        dragNsPerM = drag;
        thrustN = thrust;
        stepSeconds = h;
        ++steps;
        if (!runner.run(stepCall)) {
            String line = runner.getProblem();
            problem = StudentRunner.NOT_WRITTEN.equals(line) ? line
                    : "step " + steps + ": " + line;
            return false;
        }
        if (!Vector3f.isValidVector(position) || !Vector3f.isValidVector(velocity)) {
            StringBuilder line = new StringBuilder("step ").append(steps).append(" gave P = ");
            TextFormat.appendVector(line, position, 3).append(" m, V = ");
            TextFormat.appendVector(line, velocity, 3).append(" m/s: not a number");
            problem = line.toString();
            return false;
        }
        p[0] = position.x;
        p[1] = position.y;
        p[2] = position.z;
        v[0] = velocity.x;
        v[1] = velocity.y;
        v[2] = velocity.z;
        return true;
    }

    /**
     * Return what stopped the lane.
     *
     * @return one line ("not written yet", "step N: threw ...", "step N gave P = (NaN, ...)",
     *     a missing class), or null while the recipe runs
     */
    String getProblem() {
        return problem;
    }

    /** On the worker: the student's step, with the fields as arguments. */
    private void callStep() {
        recipe.step(position, velocity, massKg, gravity, dragNsPerM, thrustN, stepSeconds);
    }
}

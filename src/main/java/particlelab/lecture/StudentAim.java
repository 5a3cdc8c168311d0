package particlelab.lecture;

import particlelab.coursework.AimingExercise;
import particlelab.coursework.StudentRunner;
import particlelab.view.TextFormat;

/**
 * HelloAiming's student bullet's aim: exercise 3's class ({@link AimingExercise}, found by
 * name), its {@code discreteVy} called once per shot through a {@link StudentRunner}, so an
 * aim that throws, gives NaN or never returns leaves the shot without the student's bullet and
 * one line saying why. Allocates nothing while the aim returns a finite number.
 */
final class StudentAim {

    /** The exercise's class, in the package the app was started with. */
    static final String SIMPLE_NAME = "Aiming";

    private final StudentRunner runner;
    private AimingExercise aiming;
    private boolean created;
    /** The call the worker makes: the fields below in, {@link #vy} out. */
    private final Runnable discreteCall = this::callDiscrete;
    /** The arguments (m/s, m, m/s², s) and the result (m/s). */
    private float vx;
    private float rangeM;
    private float gravity;
    private float stepSeconds;
    private float vy;
    /** What kept the last shot from the student's aim, or null. */
    private String problem;

    /**
     * Create the aim for one class.
     *
     * @param className the class (not null), e.g. {@code particlelab.exercises.Aiming}
     * @param limitNanos how long one call may take (in ns, &gt;0)
     */
    StudentAim(String className, long limitNanos) {
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

    /**
     * Ask the student's {@code discreteVy} for a shot's launch.
     *
     * @param shotVx vx (in m/s)
     * @param distance S (in m)
     * @param g g, pointing down (in m/s²)
     * @param h the step the shot is flown with (in s)
     * @return vy (in m/s), or NaN when the student's code failed ({@link #getProblem()})
     */
    float discreteVy(float shotVx, float distance, float g, float h) {
        problem = null;
        runner.clearProblem();
        if (!created) {
            created = true;
            aiming = runner.create(AimingExercise.class);
        }
        if (aiming == null) {
            problem = runner.getProblem();
            return Float.NaN;
        }
        vx = shotVx;
        rangeM = distance;
        gravity = g;
        stepSeconds = h;
        if (!runner.run(discreteCall)) {
            problem = runner.getProblem();
            return Float.NaN;
        }
        if (!Float.isFinite(vy)) {
            StringBuilder line = new StringBuilder("discreteVy(vx = ");
            TextFormat.appendFixed(line, vx, 1).append(", S = ");
            TextFormat.appendFixed(line, rangeM, 1).append(", g = ");
            TextFormat.appendFixed(line, gravity, 2).append(", h = ");
            TextFormat.appendFixed(line, stepSeconds, 5).append(") gave ")
                    .append(vy).append(": not a number");
            problem = line.toString();
            return Float.NaN;
        }
        return vy;
    }

    /**
     * Return what kept the last shot from the student's aim.
     *
     * @return one line ("not written yet", "threw ...", "did not return ...", "discreteVy(...)
     *     gave NaN", a missing class), or null when the aim returned a number
     */
    String getProblem() {
        return problem;
    }

    /** On the worker: the student's discrete aim, with the fields as arguments. */
    private void callDiscrete() {
        vy = aiming.discreteVy(vx, rangeM, gravity, stepSeconds);
    }
}

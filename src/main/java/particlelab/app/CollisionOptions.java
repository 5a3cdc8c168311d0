package particlelab.app;

import com.jme3.math.Vector3f;
import particlelab.world.Detection;

/**
 * What the collision subcommands ({@code bounce}, {@code collide}, {@code tunnel}) read alike:
 * the restitution, the detection, required vectors and step counts.
 */
final class CollisionOptions {

    /** The most steps one run takes. */
    static final int MAX_STEPS = 1_000_000;
    /** The option choosing the detection. */
    static final String DETECTION = "--detection";
    /** Its help text. */
    static final String DETECTION_HELP = "overlap: the overlap test at the end of each step;"
            + " swept: the intersection test over the step, exact for the Euler step's straight"
            + " segment.";

    private CollisionOptions() {
    }

    /**
     * Read a restitution e from 0 to 1.
     *
     * @param options parsed options (not null)
     * @param name the option (declared)
     * @param command the command's full name, for the "see help" hint (not null)
     * @return e (0 to 1)
     * @throws UsageException if absent or out of range
     */
    static float restitution(Options options, String name, String command) {
        if (!options.has(name)) {
            throw new UsageException(name + ": is required, a number from 0 to 1 (see "
                    + command + " " + Options.HELP + ")");
        }
        float e = options.finiteFloat(name, Float.NaN);
        if (!(e >= 0f && e <= 1f)) {
            throw new UsageException(name + ": the restitution e must be a number from 0 to 1"
                    + " (0: perfectly inelastic, 1: elastic), but was " + e);
        }
        return e;
    }

    /**
     * Read the detection.
     *
     * @param options parsed options (not null)
     * @param required true if the option must be given
     * @param command the command's full name, for the "see help" hint (not null)
     * @return the detection (swept when optional and absent)
     */
    static Detection detection(Options options, boolean required, String command) {
        if (required && !options.has(DETECTION)) {
            throw new UsageException(DETECTION + ": is required, overlap or swept (see "
                    + command + " " + Options.HELP + ")");
        }
        String word = options.choice(DETECTION, "swept", "overlap", "swept");
        return "overlap".equals(word) ? Detection.OVERLAP : Detection.SWEPT;
    }

    /**
     * Read a required vector.
     *
     * @param options parsed options (not null)
     * @param name the option (declared)
     * @param command the command's full name (not null)
     * @return a new vector (finite)
     */
    static Vector3f requiredVector(Options options, String name, String command) {
        if (!options.has(name)) {
            throw new UsageException(name + ": is required, three finite numbers X,Y,Z (see "
                    + command + " " + Options.HELP + ")");
        }
        return options.vector(name, Vector3f.ZERO);
    }

    /**
     * Turn a duration into a whole number of steps, {@code T/h} rounded to the nearest, at
     * least 1.
     *
     * @param name the option the duration came from
     * @return the step count (1 to {@link #MAX_STEPS})
     */
    static int stepsFor(String name, float durationSeconds, float stepSeconds) {
        double steps = Math.floor(durationSeconds / (double) stepSeconds + 0.5);
        if (steps > MAX_STEPS) {
            throw new UsageException(name + ": must take at most " + MAX_STEPS + " steps of "
                    + stepSeconds + " s (" + (MAX_STEPS * (double) stepSeconds) + " s), but was "
                    + durationSeconds);
        }
        return Math.max(1, (int) steps);
    }
}

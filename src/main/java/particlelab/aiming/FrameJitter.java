package particlelab.aiming;

import java.util.Random;
import particlelab.physics.Validate;

/**
 * Seeded frame-time jitter: each frame of a monitor at {@code f} Hz lasts {@code 1/f} plus a
 * draw from a named distribution of a given width, as a loaded machine's frames do. The same
 * seed gives the same frames, so a landing histogram can be simulated again draw for draw.
 * <ul>
 * <li>{@link Distribution#UNIFORM}: {@code 1/f + w·(2u − 1)}, u uniform in [0, 1): every
 * frame within {@code ±w};</li>
 * <li>{@link Distribution#NORMAL}: {@code 1/f + w·z}, z standard normal: w is the standard
 * deviation.</li>
 * </ul>
 * A draw below {@link #MIN_FRAME_SECONDS} is taken as that (a frame takes some time; a
 * negative frame time is no frame), so a width wider than the frame itself stays finite and
 * positive. Allocates nothing once made.
 */
public final class FrameJitter {

    /** The named distributions of a frame's jitter. */
    public enum Distribution {
        /** Uniform in {@code ±w}. */
        UNIFORM("uniform"),
        /** Normal with standard deviation {@code w}. */
        NORMAL("normal");

        private final String id;

        Distribution(String id) {
            this.id = id;
        }

        /** @return the name on the command line and the HUD */
        public String id() {
            return id;
        }
    }

    /** The shortest frame a draw gives (in seconds): 0.1 ms. */
    public static final float MIN_FRAME_SECONDS = 1e-4f;

    private final Random random = new Random();
    private Distribution distribution = Distribution.UNIFORM;
    private float widthSeconds;

    /**
     * Start the draws of one run (no allocation).
     *
     * @param newDistribution the distribution (not null)
     * @param newWidthSeconds its width w (in seconds, finite, &ge;0)
     * @param seed the run's seed
     */
    public void start(Distribution newDistribution, float newWidthSeconds, long seed) {
        distribution = Validate.notNull(newDistribution, "jitter distribution");
        if (!(newWidthSeconds >= 0f) || newWidthSeconds == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("jitter width (s) must be finite and >= 0, but"
                    + " was " + newWidthSeconds);
        }
        widthSeconds = newWidthSeconds;
        random.setSeed(seed);
    }

    /**
     * Draw the next frame's time.
     *
     * @param nominalSeconds the unjittered frame time 1/f (in seconds, &gt;0)
     * @return the frame time (in seconds, at least {@link #MIN_FRAME_SECONDS})
     */
    public float next(float nominalSeconds) {
        double offset = distribution == Distribution.UNIFORM
                ? 2.0 * random.nextDouble() - 1.0 : random.nextGaussian();
        float tpf = (float) (nominalSeconds + widthSeconds * offset);
        return Math.max(MIN_FRAME_SECONDS, tpf);
    }
}

package particlelab.demo;

import com.jme3.math.Vector3f;
import particlelab.view.LensGraph;
import particlelab.world.StateRing;
import particlelab.world.StateSlab;

/**
 * The steps the derivative lens plots and picks from, without jME: the followed sphere's
 * time, position and velocity at each recorded step of the replay ring from its oldest entry
 * (or the last {@value #CAPACITY} − 1) to the step shown, the <em>chosen</em> step, then the
 * step looked at, {@code V_{i+1}} at {@code t_i + h}. The slope of each velocity component at
 * the chosen step is computed from those two plotted points, {@code (V_{i+1} − V_i)/h}: the
 * acceleration the step applied, {@code −g} in y under gravity alone.
 *
 * <p>Read from the ring's entries as the run writes them (t, then each particle's P and V
 * first), so a step back or a click on a step dot reads the same numbers the steps wrote.
 * Allocates nothing: the arrays are made once.
 */
final class LensSteps {

    /** The most points plotted: the chosen step's past, the chosen step and the next. */
    static final int CAPACITY = LensGraph.CAPACITY;
    private static final int FLOATS_PER_PARTICLE = 6;

    private final double[] times = new double[CAPACITY];
    private final float[] positions = new float[3 * CAPACITY];
    private final float[] velocityX = new float[CAPACITY];
    private final float[] velocityY = new float[CAPACITY];
    /** The ring's number of each point's entry (the next point: the chosen entry + 1). */
    private final long[] entries = new long[CAPACITY];
    private int count;

    /**
     * Read the steps from a ring: its entries up to the one shown (the chosen step), the
     * oldest dropped beyond the capacity; then the step looked at from there.
     *
     * @param ring the demo's replay ring (not null, not empty)
     * @param shownIndex the number of the entry shown (in the ring)
     * @param particleIndex the followed sphere's place in the demo's particles (&ge;0)
     * @param nextSeconds the time at the step's end, {@code t_i + h} (in seconds)
     * @param nextVelocity {@code V_{i+1}}, the step's velocity (in m/s, not null, not
     *     modified)
     */
    void read(StateRing ring, long shownIndex, int particleIndex, double nextSeconds,
            Vector3f nextVelocity) {
        long first = Math.max(ring.getFirstIndex(), shownIndex - (CAPACITY - 2));
        count = 0;
        for (long index = first; index <= shownIndex; ++index) {
            StateSlab slab = ring.read(index);
            times[count] = slab.getDouble();
            for (int skip = 0; skip < FLOATS_PER_PARTICLE * particleIndex; ++skip) {
                slab.getFloat();
            }
            positions[3 * count] = slab.getFloat();
            positions[3 * count + 1] = slab.getFloat();
            positions[3 * count + 2] = slab.getFloat();
            velocityX[count] = slab.getFloat();
            velocityY[count] = slab.getFloat();
            entries[count] = index;
            ++count;
        }
        times[count] = nextSeconds;
        velocityX[count] = nextVelocity.x;
        velocityY[count] = nextVelocity.y;
        entries[count] = shownIndex + 1L;
        ++count;
    }

    /** Forget every step (nothing is plotted or picked). */
    void clear() {
        count = 0;
    }

    /** @return how many points are plotted: the recorded steps and the next (&ge;0) */
    int size() {
        return count;
    }

    /** @return how many points are step dots of the trail: all but the next (&ge;0) */
    int countDots() {
        return Math.max(0, count - 1);
    }

    /** @return the chosen step's place among the points (the second last; -1 if none) */
    int getChosen() {
        return count - 2;
    }

    /**
     * Return the ring's number of a point's entry.
     *
     * @param point the point's place (from 0, &lt; {@link #size()})
     * @return the entry's number
     */
    long getEntry(int point) {
        return entries[point];
    }

    /** @return the points' times (in seconds; live, the first {@link #size()} are set) */
    double[] getTimes() {
        return times;
    }

    /** @return the step dots' positions, x, y, z per step (in m; live) */
    float[] getPositions() {
        return positions;
    }

    /** @return the points' V_x (in m/s; live, the first {@link #size()} are set) */
    float[] getVelocityX() {
        return velocityX;
    }

    /** @return the points' V_y (in m/s; live, the first {@link #size()} are set) */
    float[] getVelocityY() {
        return velocityY;
    }

    /**
     * The slope of V_x at the chosen step, from the two plotted points there.
     *
     * @return {@code (V_x,i+1 − V_x,i)/(t_{i+1} − t_i)} (in m/s², NaN without two points)
     */
    double slopeX() {
        return slope(velocityX);
    }

    /**
     * The slope of V_y at the chosen step, from the two plotted points there: {@code −g}
     * under gravity alone, to float rounding.
     *
     * @return {@code (V_y,i+1 − V_y,i)/(t_{i+1} − t_i)} (in m/s², NaN without two points)
     */
    double slopeY() {
        return slope(velocityY);
    }

    private double slope(float[] values) {
        int chosen = getChosen();
        if (chosen < 0) {
            return Double.NaN;
        }
        double seconds = times[chosen + 1] - times[chosen];
        if (!(seconds > 0.0)) {
            return Double.NaN;
        }
        return ((double) values[chosen + 1] - values[chosen]) / seconds;
    }
}

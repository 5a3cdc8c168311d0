package particlelab.lecture;

import com.jme3.math.Vector3f;
import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;

/**
 * The latest contacts between two bodies, as the world resolved them: where, along which
 * normal and with which impulse, for the collisions demo's arrows (Newton's third law: the
 * impulse {@code j·n} on A, {@code −j·n} on B, at the same point). A bounded ring, newest
 * first, kept in the demo's state so a replayed step shows the arrows it had; copied from
 * the world's {@link Contact}, never computed again. Allocates nothing once created.
 */
public final class ContactImpulses implements StateRecord {

    /** How many contacts are kept (older ones are overwritten). */
    public static final int CAPACITY = 8;
    /** How long a contact's arrows stay on screen (in seconds of simulated time). */
    public static final float HOLD_SECONDS = 0.5f;
    /** Ints one kept contact takes in the state: point 3, normal 3, j, t (2), two flags. */
    private static final int INTS_PER_CONTACT = 3 + 3 + 1 + 2 + 2;

    private final float[] pointX = new float[CAPACITY];
    private final float[] pointY = new float[CAPACITY];
    private final float[] pointZ = new float[CAPACITY];
    private final float[] normalX = new float[CAPACITY];
    private final float[] normalY = new float[CAPACITY];
    private final float[] normalZ = new float[CAPACITY];
    /** j of each contact (in N·s, &gt;0). */
    private final float[] impulse = new float[CAPACITY];
    /** When each contact was found (in seconds of simulated time). */
    private final double[] timeSeconds = new double[CAPACITY];
    /** Whether A, B has a finite mass, so the impulse changed its velocity. */
    private final boolean[] appliedA = new boolean[CAPACITY];
    private final boolean[] appliedB = new boolean[CAPACITY];
    /** The ring's slot of the newest contact. */
    private int newest = CAPACITY - 1;
    /** How many slots hold a contact (0 to CAPACITY). */
    private int count;

    // ---------------------------------------------------------------------- public API ----

    /** Forget every contact (a restart). */
    public void clear() {
        count = 0;
        newest = CAPACITY - 1;
    }

    /**
     * Keep a resolved contact between two bodies, if its resolution gave an impulse; a
     * contact with a static surface, or one that was already separating, is not kept.
     *
     * @param contact the contact, read in a {@code ContactListener} call (not null, not
     *     modified, not kept)
     */
    public void record(Contact contact) {
        Body a = contact.getBodyA();
        Body b = contact.getBodyB();
        float j = contact.getImpulse();
        if (b == null || !(j > 0f)) {
            return;
        }
        newest = (newest + 1) % CAPACITY;
        count = Math.min(CAPACITY, count + 1);
        Vector3f point = contact.getPoint();
        Vector3f normal = contact.getNormal();
        pointX[newest] = point.x;
        pointY[newest] = point.y;
        pointZ[newest] = point.z;
        normalX[newest] = normal.x;
        normalY[newest] = normal.y;
        normalZ[newest] = normal.z;
        impulse[newest] = j;
        timeSeconds[newest] = contact.getTimeSeconds();
        appliedA[newest] = a.getInverseMass() > 0f;
        appliedB[newest] = b.getInverseMass() > 0f;
    }

    /** @return how many contacts are kept (0 to {@link #CAPACITY}) */
    public int size() {
        return count;
    }

    /**
     * Return how long ago a kept contact was found.
     *
     * @param index 0 for the newest, up to {@link #size()} - 1
     * @param nowSeconds the simulated time now (in seconds)
     * @return the age (in seconds)
     */
    public double ageSeconds(int index, double nowSeconds) {
        return nowSeconds - timeSeconds[slot(index)];
    }

    /**
     * Test whether a kept contact's arrows are still shown: found at most
     * {@link #HOLD_SECONDS} ago, and not in the future (after a step back).
     *
     * @param index 0 for the newest, up to {@link #size()} - 1
     * @param nowSeconds the simulated time now (in seconds)
     * @return true if shown
     */
    public boolean isShown(int index, double nowSeconds) {
        double age = ageSeconds(index, nowSeconds);
        return age >= 0.0 && age <= HOLD_SECONDS;
    }

    /**
     * Copy a kept contact's point (on B's surface).
     *
     * @param index 0 for the newest, up to {@link #size()} - 1
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in metres)
     */
    public Vector3f copyPoint(int index, Vector3f storeResult) {
        int s = slot(index);
        return storeResult.set(pointX[s], pointY[s], pointZ[s]);
    }

    /**
     * Copy the impulse one side of a kept contact received: {@code j·n} on A, {@code −j·n}
     * on B, equal and opposite (it is the same whether or not that side's mass let it act).
     *
     * @param index 0 for the newest, up to {@link #size()} - 1
     * @param onA true for A's, false for B's
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (in N·s)
     */
    public Vector3f copyImpulse(int index, boolean onA, Vector3f storeResult) {
        int s = slot(index);
        float signed = onA ? impulse[s] : -impulse[s];
        return storeResult.set(signed * normalX[s], signed * normalY[s], signed * normalZ[s]);
    }

    /**
     * Return a kept contact's impulse magnitude.
     *
     * @param index 0 for the newest, up to {@link #size()} - 1
     * @return j (in N·s, &gt;0)
     */
    public float getMagnitude(int index) {
        return impulse[slot(index)];
    }

    /**
     * Test whether one side's impulse changed its velocity: false for a kinematic (or held)
     * body, whose mass is infinite.
     *
     * @param index 0 for the newest, up to {@link #size()} - 1
     * @param onA true for A, false for B
     * @return true if applied
     */
    public boolean isApplied(int index, boolean onA) {
        int s = slot(index);
        return onA ? appliedA[s] : appliedB[s];
    }

    // ------------------------------------------------------------ StateRecord overrides ----

    @Override
    public int countStateInts() {
        return 2 + CAPACITY * INTS_PER_CONTACT;
    }

    @Override
    public void writeState(StateSlab slab) {
        slab.putInt(newest);
        slab.putInt(count);
        for (int s = 0; s < CAPACITY; ++s) {
            slab.putFloat(pointX[s]);
            slab.putFloat(pointY[s]);
            slab.putFloat(pointZ[s]);
            slab.putFloat(normalX[s]);
            slab.putFloat(normalY[s]);
            slab.putFloat(normalZ[s]);
            slab.putFloat(impulse[s]);
            slab.putDouble(timeSeconds[s]);
            slab.putBoolean(appliedA[s]);
            slab.putBoolean(appliedB[s]);
        }
    }

    @Override
    public void readState(StateSlab slab) {
        newest = slab.getInt();
        count = slab.getInt();
        for (int s = 0; s < CAPACITY; ++s) {
            pointX[s] = slab.getFloat();
            pointY[s] = slab.getFloat();
            pointZ[s] = slab.getFloat();
            normalX[s] = slab.getFloat();
            normalY[s] = slab.getFloat();
            normalZ[s] = slab.getFloat();
            impulse[s] = slab.getFloat();
            timeSeconds[s] = slab.getDouble();
            appliedA[s] = slab.getBoolean();
            appliedB[s] = slab.getBoolean();
        }
    }

    // ---------------------------------------------------------------- private helpers ----

    /** The ring's slot of the index-th newest contact. */
    private int slot(int index) {
        if (index < 0 || index >= count) {
            throw new IndexOutOfBoundsException("contact index must be 0 to " + (count - 1)
                    + ", but was " + index);
        }
        return ((newest - index) % CAPACITY + CAPACITY) % CAPACITY;
    }
}

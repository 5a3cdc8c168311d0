package particlelab.lecture;

import particlelab.world.Body;
import particlelab.world.Contact;
import particlelab.world.ContactListener;
import particlelab.world.HopCycle;
import particlelab.world.StateRecord;
import particlelab.world.StateSlab;
import particlelab.world.StepListener;
import particlelab.world.World;


/**
 * The measurements of a bouncing ball, heard from its world: each impact (in the epilogue),
 * the highest point after each impact (after each step) and the moment it came to rest. An
 * impact is every resolved contact of the ball except those of a ball at rest (a contact that
 * leaves it with rebound 0 after one that did too), as in the {@code bounce} command.
 * Heights are of the ball's lowest point above the ground, {@code y − R}. Each of Bounce's
 * lanes has its own. Allocates nothing.
 */
final class BounceRecorder implements ContactListener, StepListener, StateRecord {

    /**
     * The latest apexes kept, a ring: every apex is counted, and the latest this many can be
     * read (the HUD's table shows the last few for as long as the ball bounces).
     */
    static final int MAX_APEXES = 64;
    /**
     * The latest hops kept (whole steps and the impact speed that ended each), a ring twice
     * as long as the longest orbit looked for, {@link #MAX_ORBIT_HOPS}.
     */
    static final int HOP_HISTORY = 256;
    /**
     * The longest orbit of hops looked for: twice the 64-hop cycle of the demo's own 4 m drop
     * at e = 0.9 ({@link particlelab.world.HopCycle}).
     */
    static final int MAX_ORBIT_HOPS = HOP_HISTORY / 2;
    /**
     * How close the impact speeds one round apart must be, relatively, for the hops to count
     * as on their orbit: the speeds close in on it by about a factor e a hop, so this is
     * reached some 60 hops after a ball first comes within 0.5 of it at e = 0.9, and float
     * round-off (1e-7 relatively) is far below it.
     */
    static final double ORBIT_TOLERANCE = 1e-3;

    private final Body ball;
    private final float[] apexes = new float[MAX_APEXES];
    private int apexCount;
    private int impacts;
    private boolean resting;
    private float apex = Float.NEGATIVE_INFINITY;
    private double restSeconds = Double.NaN;
    private float lastImpactSpeed;
    /** The normal speed right after the latest impact's resolution (m/s, 0 before one). */
    private float lastReboundSpeed;
    /** The step h under way (s, 0 before one). */
    private float currentStepSeconds;
    /** The step h of the latest impact's step (s, 0 before one). */
    private float impactStepSeconds;
    /** The world's step count at the latest impact, -1 before one. */
    private long lastImpactStep = -1L;
    /** Whole steps between the last two impacts, K (0 until there are two). */
    private int lastHopSteps;
    /** The latest hops' whole steps, a ring: hop m at m % HOP_HISTORY. */
    private final int[] hopSteps = new int[HOP_HISTORY];
    /** The impact speed that ended each of those hops (m/s). */
    private final float[] hopImpactSpeeds = new float[HOP_HISTORY];
    /** The hops completed (two impacts make one). */
    private int hopCount;
    /** The step h of the latest step (in seconds, 0 before one). */
    private float lastStepSeconds;

    /**
     * Create a recorder for one ball.
     *
     * @param ball the ball (not null)
     */
    BounceRecorder(Body ball) {
        this.ball = ball;
    }

    @Override
    public void resolved(Contact contact, World world) {
        if (contact.getBodyA() != ball) {
            return;
        }
        float rebound = ball.getVelocity().dot(contact.getNormal());
        if (resting && rebound == 0f) {
            return;
        }
        closeApex();
        ++impacts;
        lastImpactSpeed = contact.getApproachSpeed();
        lastReboundSpeed = rebound;
        impactStepSeconds = currentStepSeconds;
        long step = world.getStepCount();
        if (lastImpactStep >= 0L) {
            lastHopSteps = (int) Math.min(Integer.MAX_VALUE, step - lastImpactStep);
            if (hopCount < Integer.MAX_VALUE) {
                hopSteps[hopCount % HOP_HISTORY] = lastHopSteps;
                hopImpactSpeeds[hopCount % HOP_HISTORY] = lastImpactSpeed;
                ++hopCount;
            }
        }
        lastImpactStep = step;
        resting = rebound == 0f;
        if (resting && Double.isNaN(restSeconds)) {
            restSeconds = contact.getTimeSeconds();
        }
    }

    @Override
    public void beforeStep(World world, float stepSeconds) {
        currentStepSeconds = stepSeconds;
    }

    @Override
    public void afterStep(World world, float stepSeconds) {
        lastStepSeconds = stepSeconds;
        if (impacts > 0 && !resting) {
            apex = Math.max(apex, ball.getPosition().y - ball.getRadius());
        }
    }

    /** @return the ints of the recorder's state (for the ring) */
    @Override
    public int countStateInts() {
        return MAX_APEXES + 1 + 1 + 1 + 1 + 2 + 1 + 2 + 1 + 2 * HOP_HISTORY + 1 + 1 + 3;
    }

    /**
     * Write the recorder's state (apexes, impacts, the hop) for the ring. Allocates nothing.
     *
     * @param slab where to write (not null, modified)
     */
    @Override
    public void writeState(StateSlab slab) {
        for (int i = 0; i < MAX_APEXES; ++i) {
            slab.putFloat(apexes[i]);
        }
        slab.putInt(apexCount);
        slab.putInt(impacts);
        slab.putBoolean(resting);
        slab.putFloat(apex);
        slab.putDouble(restSeconds);
        slab.putFloat(lastImpactSpeed);
        slab.putLong(lastImpactStep);
        slab.putInt(lastHopSteps);
        for (int i = 0; i < HOP_HISTORY; ++i) {
            slab.putInt(hopSteps[i]);
            slab.putFloat(hopImpactSpeeds[i]);
        }
        slab.putInt(hopCount);
        slab.putFloat(lastStepSeconds);
        slab.putFloat(lastReboundSpeed);
        slab.putFloat(currentStepSeconds);
        slab.putFloat(impactStepSeconds);
    }

    /**
     * Put back a state {@link #writeState} wrote.
     *
     * @param slab where to read (not null, modified)
     */
    @Override
    public void readState(StateSlab slab) {
        for (int i = 0; i < MAX_APEXES; ++i) {
            apexes[i] = slab.getFloat();
        }
        apexCount = slab.getInt();
        impacts = slab.getInt();
        resting = slab.getBoolean();
        apex = slab.getFloat();
        restSeconds = slab.getDouble();
        lastImpactSpeed = slab.getFloat();
        lastImpactStep = slab.getLong();
        lastHopSteps = slab.getInt();
        for (int i = 0; i < HOP_HISTORY; ++i) {
            hopSteps[i] = slab.getInt();
            hopImpactSpeeds[i] = slab.getFloat();
        }
        hopCount = slab.getInt();
        lastStepSeconds = slab.getFloat();
        lastReboundSpeed = slab.getFloat();
        currentStepSeconds = slab.getFloat();
        impactStepSeconds = slab.getFloat();
    }

    /** Forget everything: the ball was dropped again. */
    void clear() {
        apexCount = 0;
        impacts = 0;
        resting = false;
        apex = Float.NEGATIVE_INFINITY;
        restSeconds = Double.NaN;
        lastImpactSpeed = 0f;
        lastReboundSpeed = 0f;
        impactStepSeconds = 0f;
        lastImpactStep = -1L;
        lastHopSteps = 0;
        hopCount = 0;
        lastStepSeconds = 0f;
    }

    /** @return the count of impacts so far (&ge;0) */
    int countImpacts() {
        return impacts;
    }

    /** @return the count of completed apexes (an apex is complete at the next impact) */
    int countApexes() {
        return apexCount;
    }

    /**
     * Return the highest point after an impact, before the next.
     *
     * @param index 0 for the apex after impact 1 (from {@link #firstKeptApex()}, &lt;{@link
     *     #countApexes()})
     * @return the height of the ball's lowest point (in metres)
     */
    float getApex(int index) {
        if (index < firstKeptApex() || index >= apexCount) {
            throw new IndexOutOfBoundsException("apex index must be from " + firstKeptApex()
                    + " to " + (apexCount - 1) + ", but was " + index);
        }
        return apexes[index % MAX_APEXES];
    }

    /** @return the index of the oldest apex still kept (0 until more than the ring holds) */
    int firstKeptApex() {
        return Math.max(0, apexCount - MAX_APEXES);
    }

    /** @return true once the ball rests on the ground */
    boolean isResting() {
        return resting;
    }

    /** @return when the ball came to rest (in seconds of world time), NaN while it bounces */
    double getRestSeconds() {
        return restSeconds;
    }

    /** @return the normal approach speed of the latest impact (in m/s, 0 before one) */
    float getLastImpactSpeed() {
        return lastImpactSpeed;
    }

    /** @return the normal speed right after the latest impact (in m/s, 0 before one) */
    float getLastReboundSpeed() {
        return lastReboundSpeed;
    }

    /** @return the step h of the latest impact's step (in seconds, 0 before one) */
    float getImpactStepSeconds() {
        return impactStepSeconds;
    }

    /**
     * Return the length of the latest hop in whole steps: K, the steps from one impact's step
     * to the next one's.
     *
     * @return K (&ge;1), 0 before two impacts
     */
    int getLastHopSteps() {
        return lastHopSteps;
    }

    /**
     * Return the orbit the latest hops repeat ({@link HopCycle#findOrbitHops}): 1 on a K-step
     * fixed point, n &gt; 1 on a cycle of n hops. Allocates nothing.
     *
     * @return the hops in one round of it, 0 while the hops repeat none (yet)
     */
    int getOrbitHops() {
        return HopCycle.findOrbitHops(hopSteps, hopImpactSpeeds, hopCount, MAX_ORBIT_HOPS,
                ORBIT_TOLERANCE);
    }

    /**
     * Return the fewest or the most whole steps among the latest hops.
     *
     * @param hops how many of the latest hops (1 to the hops kept)
     * @param most true for the most, false for the fewest
     * @return K (&ge;1)
     */
    int getHopStepsBound(int hops, boolean most) {
        int bound = hopSteps[(hopCount - 1) % HOP_HISTORY];
        for (int back = 1; back < hops; ++back) {
            int steps = hopSteps[(hopCount - 1 - back) % HOP_HISTORY];
            bound = most ? Math.max(bound, steps) : Math.min(bound, steps);
        }
        return bound;
    }

    /**
     * Return the slowest or the fastest impact that ended one of the latest hops.
     *
     * @param hops how many of the latest hops (1 to the hops kept)
     * @param fastest true for the fastest, false for the slowest
     * @return the speed (in m/s)
     */
    float getHopImpactBound(int hops, boolean fastest) {
        float bound = hopImpactSpeeds[(hopCount - 1) % HOP_HISTORY];
        for (int back = 1; back < hops; ++back) {
            float speed = hopImpactSpeeds[(hopCount - 1 - back) % HOP_HISTORY];
            bound = fastest ? Math.max(bound, speed) : Math.min(bound, speed);
        }
        return bound;
    }

    /** @return the step h of the latest step (in seconds, 0 before one) */
    float getLastStepSeconds() {
        return lastStepSeconds;
    }

    private void closeApex() {
        if (impacts > 0 && apex > Float.NEGATIVE_INFINITY && apexCount < Integer.MAX_VALUE) {
            apexes[apexCount % MAX_APEXES] = apex;
            ++apexCount;
        }
        apex = Float.NEGATIVE_INFINITY;
    }
}

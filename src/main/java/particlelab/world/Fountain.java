package particlelab.world;

import com.jme3.math.Vector3f;
import java.util.Arrays;
import particlelab.physics.FloorContacts;
import particlelab.physics.Gravity;
import particlelab.physics.LinearDrag;
import particlelab.physics.ParticleBatch;
import particlelab.physics.ParticleIntegrator;

/**
 * A fountain with fireworks: a fixed pool of particles, packed in float arrays and moved by
 * the shared Euler step in its batch form ({@link ParticleBatch#stepPacked}), bouncing on
 * the ground ({@link GroundBounce}), recycled when they come to rest or leave the region.
 *
 * <p>Every step, in order:
 * <ol>
 * <li>the Euler step of every particle in flight, gravity and linear drag
 * ({@code V ← (1 − h·b/m)·V + h·g}, {@code P ← P + h·V}), which finds the particles in
 * contact with the ground on the way ({@link ParticleBatch#stepPackedFindingFloor}:
 * each block of particles while it is in the cache);</li>
 * <li>the ground: restitution e with Cyclone's resting fix ({@link GroundBounce}), on those
 * in contact alone;</li>
 * <li>the lifecycle, on the particles it concerns and no others: water in contact whose
 * rebound is slower than {@link #REST_SPEED} (it no longer bounces: it joins the puddle), or
 * that has left the region or outlived {@link #MAX_AGE_SECONDS}, goes back to the pool, found
 * among the contacts (water always comes down: gravity brings every drop to the ground within
 * seconds, so the ground is where its region and age are checked); the fireworks, in the
 * first slots, burn their fuses and are checked against the region and the age: a shell
 * bursts at its apex or when its fuse has burnt, a star when its fuse has burnt, a spark goes
 * out;</li>
 * <li>the bursts' payloads, then a new shell when the launch timer says so, then new water
 * from the nozzle, all from the pool.</li>
 * </ol>
 *
 * <p>The fireworks follow Cyclone's fireworks demo (Millington): each kind has a rule, a fuse
 * (its age limit, drawn between a least and a most) and a payload (how many children of which
 * kind it leaves when the fuse burns out), each child starting where its parent burst with the
 * parent's velocity plus a random one. Here a shell leaves {@value #STARS_PER_SHELL} stars, a
 * star {@value #SPARKS_PER_STAR} sparks, a spark nothing.
 *
 * <p>The pool never grows, and the particles in flight are kept first: slots 0 to
 * {@link #countLive()} − 1 are in flight, the rest dormant (at the nozzle, {@code P = (0, r,
 * 0)}, {@code V = 0}, invisible), so every pass touches only the particles in flight (the
 * Euler step too: {@link ParticleBatch#stepPacked(float[], float[], int, int, float,
 * float)} with the pool as the stride), and the fireworks first of them (slots 0 to
 * {@link #countFireworks()} − 1), so their pass reads a few hundred slots side by side
 * rather than scattered over the pool. A water particle going back to the pool takes the
 * last one in flight into its slot; a firework takes the last firework into its slot, and
 * the slot that leaves, the last water. New water takes the first dormant slot; a new
 * firework the first slot after the fireworks, whose water moves to the first dormant slot.
 * The fireworks stay in the order they were launched in but for those removals (the last
 * into the gap), so they burst, and draw their random numbers, in a fixed order. A
 * twentieth of the pool is
 * kept for the fireworks: water takes a slot only while more are free. Nothing decays for
 * ever (every particle in flight is recycled within {@link #MAX_AGE_SECONDS}), so no velocity
 * becomes a subnormal float (see {@code docs/numerics.md}). A step allocates nothing.
 */
public final class Fountain implements StateRecord {

    /** The default pool size (particles). */
    public static final int DEFAULT_PARTICLES = 100_000;
    /** The largest pool (particles). */
    public static final int MAX_PARTICLES = 1_000_000;
    /** A slot that is not in flight. */
    public static final byte DORMANT = 0;
    /** Water from the nozzle. */
    public static final byte WATER = 1;
    /** A firework shell, rising. */
    public static final byte SHELL = 2;
    /** A star of a burst shell. */
    public static final byte STAR = 3;
    /** A spark of a burnt-out star. */
    public static final byte SPARK = 4;
    /** Each particle's mass (in kilograms): a drop of about a gram. */
    public static final float MASS_KG = 0.001f;
    /** Linear drag b (in kg/s): b/m = 0.2 per second. */
    public static final float DRAG_B = 0.0002f;
    /** The particles' radius for the ground contact (in metres). */
    public static final float RADIUS_METRES = 0.05f;
    /** The ground's default restitution e. */
    public static final float DEFAULT_RESTITUTION = 0.5f;
    /** Water that rebounds off the ground slower than this is at rest (in m/s). */
    public static final float REST_SPEED = 1f;
    /** Anything older than this is recycled (in seconds). */
    public static final float MAX_AGE_SECONDS = 20f;
    /** The region: |x| at most this (in metres); beyond it a particle is recycled. */
    public static final float REGION_HALF_WIDTH = 24f;
    /** The region: |z| at most this (in metres). */
    public static final float REGION_HALF_DEPTH = 12f;
    /** The region: y at most this (in metres). */
    public static final float REGION_TOP = 40f;
    /** The nozzle's least launch speed (in m/s). */
    public static final float WATER_MIN_SPEED = 13f;
    /** The nozzle's largest launch speed (in m/s). */
    public static final float WATER_MAX_SPEED = 15f;
    /** The half angle of the nozzle's cone about +y (in radians). */
    public static final float WATER_CONE_RADIANS = 0.25f;
    /** New water per second, as a fraction of the pool. */
    public static final float WATER_RATE_PER_POOL = 0.2f;
    /** The share of the pool kept for the fireworks. */
    public static final float FIREWORK_RESERVE = 0.05f;
    /** Seconds between two shells; they go up at x = ±{@link #LAUNCHER_X} in turn. */
    public static final float SHELL_INTERVAL_SECONDS = 1.2f;
    /** How far from the nozzle the shells go up (in metres). */
    public static final float LAUNCHER_X = 12f;
    /** A shell's least launch speed (in m/s). */
    public static final float SHELL_MIN_SPEED = 24f;
    /** A shell's largest launch speed (in m/s). */
    public static final float SHELL_MAX_SPEED = 27f;
    /** The half angle of the shells' cone about +y (in radians). */
    public static final float SHELL_CONE_RADIANS = 0.1f;
    /** A shell's payload: how many stars it bursts into. */
    public static final int STARS_PER_SHELL = 300;
    /** A star's payload: how many sparks it bursts into. */
    public static final int SPARKS_PER_STAR = 3;
    /** Bursts handled in one step at most; more wait for the next step. */
    static final int MAX_BURSTS_PER_STEP = 1024;
    /** The random sequence's seed: a reset replays the same fountain. */
    private static final long SEED = 12;
    private static final float TWO_PI = (float) (2.0 * Math.PI);
    /** The fireworks' pass works on this many slots at a time ({@link #markFireworks}). */
    private static final int FIREWORK_CHUNK = 1024;
    /** cos of the nozzle's half angle, the least cos θ of a drop's direction. */
    private static final float WATER_CONE_COS = (float) Math.cos(WATER_CONE_RADIANS);
    /** cos of the shells' half angle. */
    private static final float SHELL_CONE_COS = (float) Math.cos(SHELL_CONE_RADIANS);
    /** The burst queue's record: P, V, colour. */
    private static final int BURST_FLOATS = 6;

    /** The fireworks rules (Cyclone's FireworkRule), by kind; null for water. */
    private static final Rule[] RULES = {
        null,
        null,
        new Rule(1.8f, 2.4f, 0f, 0f, STAR, STARS_PER_SHELL),
        new Rule(1.2f, 2.0f, 5f, 9f, SPARK, SPARKS_PER_STAR),
        new Rule(0.3f, 0.7f, 1f, 3f, DORMANT, 0),
    };
    /** The stars' colours, one per shell in turn (0xRRGGBB). */
    private static final int[] STAR_COLOURS = {0xff5a3c, 0x5cff7a, 0xffd24a, 0xc070ff,
        0x4ad8ff};
    /** The water's colour (0xRRGGBB). */
    public static final int WATER_COLOUR = 0x5a9cff;

    private final int capacity;
    private final int reserve;
    private final Gravity gravity = new Gravity();
    private final LinearDrag drag = new LinearDrag(DRAG_B);
    private final ParticleIntegrator integrator = new ParticleIntegrator(gravity, drag);
    private final GroundBounce ground =
            new GroundBounce(RADIUS_METRES, DEFAULT_RESTITUTION, 0f, true);
    /** P and V of every slot, planar: all x, then all y, then all z. */
    private final float[] positions;
    private final float[] velocities;
    /**
     * vy before the step of each slot in contact after it, in the order of
     * {@link #contacts}, for the resting fix (m/s), and the step's scratch; after the step,
     * the fireworks' marks ({@link #markFireworks}).
     */
    private final float[] velocityYBefore;
    /** The fireworks' pass's scratch, a chunk of one array's values ... */
    private final float[] chunkValues = new float[FIREWORK_CHUNK];
    /** ... the chunk's marks ... */
    private final float[] chunkMarks = new float[FIREWORK_CHUNK];
    /** ... 1 for a shell, 0 for the others ... */
    private final float[] chunkShells = new float[FIREWORK_CHUNK];
    /** ... and zeros, which the marks are compared with ({@link #nextMarked}). */
    private final float[] zeros = new float[FIREWORK_CHUNK];
    private final byte[] kinds;
    /**
     * The slots in contact with the ground after the step ({@link GroundBounce}'s output),
     * then, in place, the slots going back to the pool this step.
     */
    private final int[] contacts;
    /** When each particle was launched (s; +∞ for a dormant slot). */
    private final float[] births;
    /** How many fireworks (shell, star, spark) are in flight: slots 0 to fireworkCount − 1. */
    private int fireworkCount;
    /** A firework's fuse at launch, and what is left of it (s). */
    private final float[] fuses;
    private final float[] fusesLeft;
    /** The colour each particle was given (0xRRGGBB). */
    private final int[] colours;
    /** What takes each block's contacts from the step: {@link #touchGround}. */
    private final FloorContacts onGround = this::touchGround;
    /** During a step: the least birth that is not too old, for {@link #touchGround} ... */
    private float blockOldestBirth;
    /** ... and how many slots it has sent back to the pool so far. */
    private int blockLeaving;
    /** How many slots are in flight: slots 0 to live − 1. */
    private int live;
    private final int[] liveByKind = new int[RULES.length];
    /** The bursts of the current step: parent kind, and P, V, colour. */
    private final byte[] burstKinds = new byte[MAX_BURSTS_PER_STEP];
    private final float[] burstStates = new float[MAX_BURSTS_PER_STEP * BURST_FLOATS];
    private final int[] burstColours = new int[MAX_BURSTS_PER_STEP];
    private int burstCount;
    private SplitMixRandom random;
    private float waterCarry;
    private float shellTimerSeconds;
    private int shellsLaunched;
    private boolean fireworks = true;
    private double timeSeconds;
    private long steps;
    private long recycledResting;
    private long recycledLeaving;
    private long recycledBurnt;
    private long bursts;
    /** The energy ledger, kept only while attached (null: none, the step as ever). */
    private FountainEnergy energy;

    /**
     * Create a fountain with every slot dormant.
     *
     * @param particles the pool size (from 1 to {@link #MAX_PARTICLES})
     */
    public Fountain(int particles) {
        if (particles < 1 || particles > MAX_PARTICLES) {
            throw new IllegalArgumentException("fountain particle count must be from 1 to "
                    + MAX_PARTICLES + ", but was " + particles);
        }
        capacity = particles;
        reserve = (int) (FIREWORK_RESERVE * particles);
        positions = new float[3 * particles];
        velocities = new float[3 * particles];
        velocityYBefore = new float[particles];
        kinds = new byte[particles];
        contacts = new int[particles];
        births = new float[particles];
        fuses = new float[particles];
        fusesLeft = new float[particles];
        colours = new int[particles];
        reset();
    }

    /**
     * Put every slot back in the pool and replay from the start.
     */
    public void reset() {
        live = 0;
        for (int i = 0; i < capacity; ++i) {
            park(i);
        }
        Arrays.fill(liveByKind, 0);
        fireworkCount = 0;
        random = new SplitMixRandom(SEED);
        waterCarry = 0f;
        shellTimerSeconds = 0f;
        shellsLaunched = 0;
        burstCount = 0;
        timeSeconds = 0.0;
        steps = 0L;
        recycledResting = 0L;
        recycledLeaving = 0L;
        recycledBurnt = 0L;
        bursts = 0L;
        if (energy != null) {
            energy.restart();
        }
    }

    /**
     * Count the ints of the fountain's state: every slot's P, V, kind, birth, fuses and
     * colour, how many are in flight and how many of them fireworks, the bursts waiting, the
     * counters.
     *
     * @return the count (&gt;0, fixed by the pool size)
     */
    @Override
    public int countStateInts() {
        return 3 * capacity + 3 * capacity + 5 * capacity + 1 + 1
                + liveByKind.length + 1 + burstKinds.length + burstStates.length
                + burstColours.length + 2 + 1 + 1 + 1 + 1 + 2 + 2 + 4 * 2 + 2;
    }

    /**
     * Write the fountain's state: everything its next step reads, so a step from the state
     * read back gives the same bits (the random sequence's state included). Allocates
     * nothing.
     *
     * @param slab where to write (not null, modified)
     */
    @Override
    public void writeState(StateSlab slab) {
        slab.putFloats(positions, 0, 3 * capacity);
        slab.putFloats(velocities, 0, 3 * capacity);
        for (int i = 0; i < capacity; ++i) {
            slab.putInt(kinds[i]);
        }
        slab.putFloats(births, 0, capacity);
        slab.putFloats(fuses, 0, capacity);
        slab.putFloats(fusesLeft, 0, capacity);
        slab.putInts(colours, 0, capacity);
        slab.putInt(live);
        slab.putInt(fireworkCount);
        for (int i = 0; i < liveByKind.length; ++i) {
            slab.putInt(liveByKind[i]);
        }
        slab.putInt(burstCount);
        for (int i = 0; i < burstKinds.length; ++i) {
            slab.putInt(burstKinds[i]);
            slab.putInt(burstColours[i]);
        }
        for (int i = 0; i < burstStates.length; ++i) {
            slab.putFloat(burstStates[i]);
        }
        slab.putLong(random.getState());
        slab.putFloat(waterCarry);
        slab.putFloat(shellTimerSeconds);
        slab.putInt(shellsLaunched);
        slab.putBoolean(fireworks);
        slab.putDouble(timeSeconds);
        slab.putLong(steps);
        slab.putLong(recycledResting);
        slab.putLong(recycledLeaving);
        slab.putLong(recycledBurnt);
        slab.putLong(bursts);
    }

    /**
     * Put back a state {@link #writeState} wrote.
     *
     * @param slab where to read (not null, modified)
     */
    @Override
    public void readState(StateSlab slab) {
        slab.getFloats(positions, 0, 3 * capacity);
        slab.getFloats(velocities, 0, 3 * capacity);
        for (int i = 0; i < capacity; ++i) {
            kinds[i] = (byte) slab.getInt();
        }
        slab.getFloats(births, 0, capacity);
        slab.getFloats(fuses, 0, capacity);
        slab.getFloats(fusesLeft, 0, capacity);
        slab.getInts(colours, 0, capacity);
        live = slab.getInt();
        fireworkCount = slab.getInt();
        for (int i = 0; i < liveByKind.length; ++i) {
            liveByKind[i] = slab.getInt();
        }
        burstCount = slab.getInt();
        for (int i = 0; i < burstKinds.length; ++i) {
            burstKinds[i] = (byte) slab.getInt();
            burstColours[i] = slab.getInt();
        }
        for (int i = 0; i < burstStates.length; ++i) {
            burstStates[i] = slab.getFloat();
        }
        random.setState(slab.getLong());
        waterCarry = slab.getFloat();
        shellTimerSeconds = slab.getFloat();
        shellsLaunched = slab.getInt();
        fireworks = slab.getBoolean();
        timeSeconds = slab.getDouble();
        steps = slab.getLong();
        recycledResting = slab.getLong();
        recycledLeaving = slab.getLong();
        recycledBurnt = slab.getLong();
        bursts = slab.getLong();
        if (energy != null) {
            // a state put back is energy put in between steps: it moves the start
            energy.restart();
        }
    }

    /**
     * Advance the fountain by one step.
     *
     * @param stepSeconds h (in seconds, finite, &gt;0)
     * @throws particlelab.physics.NonFiniteStepException if the Euler step left a particle
     *     non-finite; {@link #reset} before stepping again
     */
    public void step(float stepSeconds) {
        timeSeconds += stepSeconds;
        blockOldestBirth = oldestBirth();
        blockLeaving = 0;
        if (energy != null) {
            energy.beforeStep(stepSeconds);
        }
        // the step finds the ground's contacts (y <= r) and hands each block's on to
        // touchGround while the block is in the cache
        integrator.batch().stepPackedFindingFloor(positions, velocities, capacity, live, MASS_KG,
                stepSeconds, ground.getRadius(), contacts, velocityYBefore, onGround);
        if (energy != null) {
            // every slot stepped still holds its particle: none has moved yet
            energy.afterEulerStep(live);
        }
        int waterHoles = blockLeaving;
        int leaving = burnFuses(stepSeconds, waterHoles);
        compact(waterHoles, leaving);
        for (int b = 0; b < burstCount; ++b) {
            spawnPayload(b);
        }
        if (fireworks) {
            shellTimerSeconds -= stepSeconds;
            if (shellTimerSeconds <= 0f) {
                shellTimerSeconds += SHELL_INTERVAL_SECONDS;
                launchShell();
            }
        }
        emitWater(stepSeconds);
        ++steps;
        if (energy != null) {
            energy.afterStep();
        }
    }

    /**
     * Return the pool size: how many particles each step moves.
     *
     * @return the count (&ge;1)
     */
    public int getCapacity() {
        return capacity;
    }

    /**
     * Count the particles in flight.
     *
     * @return the count (from 0 to the pool size)
     */
    public int countLive() {
        return live;
    }

    /**
     * Count the particles in flight of one kind.
     *
     * @param kind {@link #WATER}, {@link #SHELL}, {@link #STAR} or {@link #SPARK}
     * @return the count (&ge;0)
     */
    public int countLive(byte kind) {
        return liveByKind[kind];
    }

    /**
     * Count the particles recycled because they came to rest on the ground.
     *
     * @return the count since the last reset (&ge;0)
     */
    public long countRecycledResting() {
        return recycledResting;
    }

    /**
     * Count the particles recycled because they left the region or outlived
     * {@link #MAX_AGE_SECONDS}.
     *
     * @return the count since the last reset (&ge;0)
     */
    public long countRecycledLeaving() {
        return recycledLeaving;
    }

    /**
     * Count the fireworks whose fuse burnt out (shells and stars that burst, sparks).
     *
     * @return the count since the last reset (&ge;0)
     */
    public long countRecycledBurnt() {
        return recycledBurnt;
    }

    /**
     * Count the bursts: shells and stars that left their payload.
     *
     * @return the count since the last reset (&ge;0)
     */
    public long countBursts() {
        return bursts;
    }

    /**
     * Return the simulated time since the last reset.
     *
     * @return the time (in seconds, &ge;0)
     */
    public double getTimeSeconds() {
        return timeSeconds;
    }

    /**
     * Access the positions, planar as {@link ParticleBatch#stepPacked} packs them.
     *
     * @return the live array of 3·{@link #getCapacity()} floats (in metres, do not modify)
     */
    public float[] getPositions() {
        return positions;
    }

    /**
     * Access the velocities, planar.
     *
     * @return the live array of 3·{@link #getCapacity()} floats (in m/s, do not modify)
     */
    public float[] getVelocities() {
        return velocities;
    }

    /**
     * Count the fireworks in flight (shells, stars and sparks): they hold slots 0 to this
     * count − 1, the water the slots after them up to {@link #countLive()} − 1.
     *
     * @return the count (from 0 to {@link #countLive()})
     */
    public int countFireworks() {
        return fireworkCount;
    }

    /**
     * Return a slot's kind.
     *
     * @param index the slot (from 0 to the pool size − 1)
     * @return {@link #DORMANT}, {@link #WATER}, {@link #SHELL}, {@link #STAR} or
     *     {@link #SPARK}
     */
    public byte getKind(int index) {
        return kinds[index];
    }

    /**
     * Access every slot's kind, e.g. to compare them in bulk.
     *
     * @return the live array of {@link #getCapacity()} kinds as {@link #getKind} gives them
     *     (do not modify)
     */
    public byte[] getKinds() {
        return kinds;
    }

    /**
     * Return a particle's colour.
     *
     * @param index the slot (from 0 to the pool size − 1)
     * @return 0xRRGGBB
     */
    public int getColour(int index) {
        return colours[index];
    }

    /**
     * Return what is left of a firework's fuse, as a fraction: 1 at launch, 0 burnt out; 1
     * for water.
     *
     * @param index the slot (from 0 to the pool size − 1)
     * @return the fraction (0 to 1)
     */
    public float fuseFraction(int index) {
        float fuse = fuses[index];
        return fuse > 0f ? Math.max(0f, fusesLeft[index] / fuse) : 1f;
    }

    /**
     * Access the ground, e.g. to change its restitution.
     *
     * @return the live ground (not null)
     */
    public GroundBounce getGround() {
        return ground;
    }

    /**
     * Access the integrator that steps the pool (gravity and linear drag).
     *
     * @return the live integrator (not null)
     */
    public ParticleIntegrator getIntegrator() {
        return integrator;
    }

    /**
     * Keep an energy ledger of the particles, or stop keeping one: the step books into it
     * from then on (O(particles in flight) a step more), and without one does what it always
     * did. Attaching one starts it from the state now.
     *
     * @param newEnergy the ledger, made for this fountain (null: none)
     */
    public void setEnergy(FountainEnergy newEnergy) {
        energy = newEnergy;
        if (newEnergy != null) {
            newEnergy.restart();
        }
    }

    /**
     * Access the energy ledger.
     *
     * @return the ledger kept, or null if none
     */
    public FountainEnergy getEnergy() {
        return energy;
    }

    /**
     * Return the particles' linear drag b.
     *
     * @return b (in kg/s, &ge;0)
     */
    public float getDragCoefficient() {
        return drag.getCoefficient();
    }

    /**
     * Copy the particles' gravity g.
     *
     * @param storeResult storage for g (in m/s², not null, modified)
     * @return storeResult
     */
    public Vector3f copyGravity(Vector3f storeResult) {
        return gravity.copyAcceleration(storeResult);
    }

    /**
     * Test whether shells are launched.
     *
     * @return true if so
     */
    public boolean isFireworks() {
        return fireworks;
    }

    /**
     * Launch shells or stop launching them (those in flight burst as usual).
     *
     * @param newFireworks true to launch
     */
    public void setFireworks(boolean newFireworks) {
        fireworks = newFireworks;
    }

    // ---------------------------------------------------------------- private helpers ----

    /**
     * One block's contacts with the ground, as the step hands them on: the ground's rule
     * ({@link GroundBounce#resolveFound}), then water in contact goes back to the pool if its
     * rebound is slower than {@link #REST_SPEED} (at rest), or if it is out of the region or
     * older than {@link #MAX_AGE_SECONDS} (leaving). A firework in contact is left to the
     * ground and to {@link #burnFuses}. The slots going back are written at the start of
     * contacts, over entries already handed on ({@link #blockLeaving} of them so far).
     */
    private void touchGround(int[] found, float[] velocityYBefore, int from, int to) {
        if (energy != null) {
            energy.beforeContacts(found, from, to);
        }
        ground.resolveFound(positions, velocities, capacity, found, velocityYBefore, from, to);
        if (energy != null) {
            energy.afterContacts(found, from, to);
        }
        int y = capacity;
        float oldest = blockOldestBirth;
        int leaving = blockLeaving;
        int fireworksEnd = fireworkCount;
        for (int c = from; c < to; ++c) {
            int i = found[c];
            // the fireworks hold the first slots: the rest in flight are water, known
            // without reading the slot's kind (another miss per contact at 10^6)
            if (i < fireworksEnd) {
                continue;
            }
            if (velocities[y + i] < REST_SPEED) {
                ++recycledResting;
                contacts[leaving++] = retireWater(i);
            } else if (isLeaving(i, oldest)) {
                ++recycledLeaving;
                contacts[leaving++] = retireWater(i);
            }
        }
        blockLeaving = leaving;
    }

    /** The least birth time that is not too old: now − {@link #MAX_AGE_SECONDS} (s). */
    private float oldestBirth() {
        return (float) timeSeconds - MAX_AGE_SECONDS;
    }

    /** Whether slot i is out of the region or was born before oldestBirth. */
    private boolean isLeaving(int i, float oldestBirth) {
        return isOutOfRegion(i) || births[i] < oldestBirth;
    }

    /** Whether slot i is out of the region. */
    private boolean isOutOfRegion(int i) {
        int n = capacity;
        return Math.abs(positions[i]) > REGION_HALF_WIDTH || positions[n + i] > REGION_TOP
                || Math.abs(positions[2 * n + i]) > REGION_HALF_DEPTH;
    }

    /**
     * The fireworks' fuses burn: a shell bursts at its apex or when its fuse has burnt, a
     * star when its fuse has burnt (queued, spawned after this pass), a spark just goes out;
     * a firework out of the region or older than {@link #MAX_AGE_SECONDS} goes back to the
     * pool unburst. One pass over slots 0 to {@link #countFireworks()} − 1: a firework that
     * goes takes the last one into its slot (looked at next), and the slot freed at the end
     * of the fireworks is a hole for {@link #compact}.
     *
     * @param leaving how many slots at the start of contacts go back already
     * @return how many go back now (the holes this pass leaves appended)
     */
    private int burnFuses(float stepSeconds, int leaving) {
        burstCount = 0;
        float oldestBirth = oldestBirth();
        float[] marks = velocityYBefore;
        markFireworks(stepSeconds, oldestBirth, marks);
        int i = 0;
        while ((i = nextMarked(marks, i)) < fireworkCount) {
            byte kind = kinds[i];
            boolean gone = false;
            if (isLeaving(i, oldestBirth)) {
                ++recycledLeaving;
                retire(i);
                gone = true;
            } else {
                float left = fusesLeft[i];
                boolean apex = kind == SHELL && velocities[capacity + i] <= 0f;
                if (left <= 0f || apex) {
                    if (RULES[kind].payloadCount == 0) {
                        gone = true;
                    } else if (burstCount < MAX_BURSTS_PER_STEP) {
                        queueBurst(i, kind);
                        gone = true;
                    }
                    // else the queue is full: burst next step
                    if (gone) {
                        ++recycledBurnt;
                        retire(i);
                    }
                }
            }
            if (gone) {
                // the last firework takes the slot, whose new one is looked at next; the
                // slot it leaves is the water's now, a hole for compact to fill
                int last = --fireworkCount;
                if (last != i) {
                    move(last, i);
                    marks[i] = marks[last];
                }
                contacts[leaving++] = last;
            } else {
                ++i;
            }
        }
        return leaving;
    }

    /**
     * Burn every firework's fuse by h, and mark each that {@link #burnFuses} must look at:
     * a mark is +0 for a firework inside the region, young enough, its fuse not burnt and
     * not a shell at its apex, and positive (or NaN) otherwise, so that pass jumps from one
     * marked firework to the next. Each condition c is a difference e that is positive just
     * where c holds, and adds {@code |e| + e} (2e there, +0 elsewhere); a sum of such terms
     * is 0 only if each is. The fuse and the apex test {@code < MIN_NORMAL} rather than
     * {@code <= 0} (a normal bound: no subnormal arithmetic), which marks a few more than
     * need it; the pass decides each exactly, as before, so a mark too many changes nothing.
     * The loops read and write at one index (one axis or array copied into a scratch of a
     * chunk first), which C2's superword needs to vectorise them.
     */
    private void markFireworks(float stepSeconds, float oldestBirth, float[] marks) {
        int n = capacity;
        float[] values = chunkValues;
        float[] chunk = chunkMarks;
        float[] shells = chunkShells;
        for (int start = 0; start < fireworkCount; start += FIREWORK_CHUNK) {
            int length = Math.min(FIREWORK_CHUNK, fireworkCount - start);
            int end = start + length;
            for (int i = start; i < end; ++i) {
                fusesLeft[i] = fusesLeft[i] - stepSeconds;
            }
            System.arraycopy(positions, start, values, 0, length);
            for (int k = 0; k < length; ++k) {
                float e = Math.abs(values[k]) - REGION_HALF_WIDTH;
                chunk[k] = Math.abs(e) + e;
            }
            System.arraycopy(positions, n + start, values, 0, length);
            for (int k = 0; k < length; ++k) {
                float e = values[k] - REGION_TOP;
                chunk[k] += Math.abs(e) + e;
            }
            System.arraycopy(positions, 2 * n + start, values, 0, length);
            for (int k = 0; k < length; ++k) {
                float e = Math.abs(values[k]) - REGION_HALF_DEPTH;
                chunk[k] += Math.abs(e) + e;
            }
            System.arraycopy(births, start, values, 0, length);
            for (int k = 0; k < length; ++k) {
                float e = oldestBirth - values[k];
                chunk[k] += Math.abs(e) + e;
            }
            System.arraycopy(fusesLeft, start, values, 0, length);
            for (int k = 0; k < length; ++k) {
                float e = Float.MIN_NORMAL - values[k];
                chunk[k] += Math.abs(e) + e;
            }
            for (int k = 0; k < length; ++k) {
                shells[k] = kinds[start + k] == SHELL ? 1f : 0f;
            }
            System.arraycopy(velocities, n + start, values, 0, length);
            for (int k = 0; k < length; ++k) {
                float e = Float.MIN_NORMAL - values[k];
                chunk[k] += shells[k] * (Math.abs(e) + e);
            }
            System.arraycopy(chunk, 0, marks, start, length);
        }
    }

    /**
     * The first firework from slot from on whose mark is not +0, by
     * {@link Arrays#mismatch(float[], int, int, float[], int, int)} against zeros, a chunk at
     * a time.
     *
     * @return its slot, or {@link #fireworkCount} if none
     */
    private int nextMarked(float[] marks, int from) {
        int i = from;
        while (i < fireworkCount) {
            int length = Math.min(FIREWORK_CHUNK, fireworkCount - i);
            int offset = Arrays.mismatch(marks, i, i + length, zeros, 0, length);
            if (offset >= 0) {
                return i + offset;
            }
            i += length;
        }
        return fireworkCount;
    }

    /**
     * Give the retired slots back to the pool and keep the ones in flight first: each retired
     * slot below the live end takes the last particle in flight. The holes are all at or
     * after the fireworks ({@link #burnFuses} closes its own), so what moves into one is
     * water. Retired slots are dormant already ({@link #retire}), so the last slot moved is
     * always one in flight and no retired index ever points at a moved particle: any order
     * works.
     *
     * @param waterHoles how many of the holes, the first ones, were water retired by
     *     {@link #touchGround}: water moving into one of those keeps the fuses and colour
     *     the slot already holds, which are water's ({@link #moveWater})
     * @param leaving how many holes in all
     */
    private void compact(int waterHoles, int leaving) {
        for (int k = 0; k < leaving; ++k) {
            while (live > 0 && kinds[live - 1] == DORMANT) {
                park(--live);
            }
            int i = contacts[k];
            if (i < live) {
                if (k < waterHoles) {
                    moveWater(--live, i);
                } else {
                    move(--live, i);
                }
            }
        }
        while (live > 0 && kinds[live - 1] == DORMANT) {
            park(--live);
        }
    }

    private void queueBurst(int i, byte kind) {
        int at = burstCount * BURST_FLOATS;
        for (int axis = 0; axis < 3; ++axis) {
            burstStates[at + axis] = positions[axis * capacity + i];
            burstStates[at + 3 + axis] = velocities[axis * capacity + i];
        }
        burstKinds[burstCount] = kind;
        burstColours[burstCount] = colours[i];
        ++burstCount;
        ++bursts;
    }

    /** A burst's children: at the parent's P, with its V plus a random one. */
    private void spawnPayload(int burst) {
        Rule parent = RULES[burstKinds[burst]];
        Rule child = RULES[parent.payloadKind];
        int at = burst * BURST_FLOATS;
        int colour = parent.payloadKind == SPARK ? brighten(burstColours[burst])
                : burstColours[burst];
        for (int c = 0; c < parent.payloadCount && live < capacity; ++c) {
            int i = take(parent.payloadKind);
            float speed = between(child.minSpeed, child.maxSpeed);
            // a random direction, uniform on the sphere: z = cos θ uniform in [−1, 1]
            float dz = between(-1f, 1f);
            float ring = (float) Math.sqrt(Math.max(0f, 1f - dz * dz));
            float phi = between(0f, TWO_PI);
            float dx = ring * (float) Math.cos(phi);
            float dy = ring * (float) Math.sin(phi);
            place(i, burstStates[at], burstStates[at + 1], burstStates[at + 2],
                    burstStates[at + 3] + speed * dx, burstStates[at + 4] + speed * dy,
                    burstStates[at + 5] + speed * dz);
            fuses[i] = between(child.minFuse, child.maxFuse);
            fusesLeft[i] = fuses[i];
            colours[i] = colour;
            if (energy != null) {
                energy.emitted(i);
            }
        }
    }

    private void launchShell() {
        if (live == capacity) {
            return;
        }
        int i = take(SHELL);
        float x = (shellsLaunched % 2 == 0 ? -1f : 1f) * LAUNCHER_X;
        launchInCone(i, x, between(SHELL_MIN_SPEED, SHELL_MAX_SPEED), SHELL_CONE_COS);
        Rule rule = RULES[SHELL];
        fuses[i] = between(rule.minFuse, rule.maxFuse);
        fusesLeft[i] = fuses[i];
        colours[i] = STAR_COLOURS[shellsLaunched % STAR_COLOURS.length];
        ++shellsLaunched;
    }

    private void emitWater(float stepSeconds) {
        waterCarry += WATER_RATE_PER_POOL * capacity * stepSeconds;
        int wanted = (int) waterCarry;
        waterCarry -= wanted;
        int count = Math.min(wanted, capacity - live - reserve);
        for (int n = 0; n < count; ++n) {
            int i = take(WATER);
            launchInCone(i, 0f, between(WATER_MIN_SPEED, WATER_MAX_SPEED), WATER_CONE_COS);
            fuses[i] = 0f;
            fusesLeft[i] = 0f;
            colours[i] = WATER_COLOUR;
        }
    }

    /**
     * From (x, r, 0), up at a speed within a cone about +y of a half angle α, given as cos α
     * (computed once: it was a cosine per particle).
     */
    private void launchInCone(int i, float x, float speed, float coneCos) {
        // cos θ uniform in [cos α, 1]: directions uniform over the cone's cap
        float cosTheta = between(coneCos, 1f);
        float sinTheta = (float) Math.sqrt(Math.max(0f, 1f - cosTheta * cosTheta));
        float phi = between(0f, TWO_PI);
        place(i, x, RADIUS_METRES, 0f, speed * sinTheta * (float) Math.cos(phi),
                speed * cosTheta, speed * sinTheta * (float) Math.sin(phi));
        if (energy != null) {
            energy.emitted(i);
        }
    }

    /**
     * A slot for a new particle of a kind: water takes the first dormant slot; a firework the
     * first slot after the fireworks, whose water (if any) moves to the first dormant slot.
     */
    private int take(byte kind) {
        int i;
        if (kind == WATER) {
            i = live;
        } else {
            i = fireworkCount++;
            if (i < live) {
                move(i, live);
            }
        }
        ++live;
        kinds[i] = kind;
        births[i] = (float) timeSeconds;
        ++liveByKind[kind];
        return i;
    }

    /**
     * A particle goes back to the pool: counted out of its kind and marked dormant, its slot
     * given back by {@link #compact} at the end of the lifecycle passes.
     *
     * @return the slot
     */
    private int retire(int i) {
        if (energy != null) {
            energy.removed(i);
        }
        --liveByKind[kinds[i]];
        kinds[i] = DORMANT;
        return i;
    }

    /** {@link #retire} of a slot known to hold water, without reading its kind. */
    private int retireWater(int i) {
        if (energy != null) {
            energy.removed(i);
        }
        --liveByKind[WATER];
        kinds[i] = DORMANT;
        return i;
    }

    /** The particle in slot from moves to slot to (dormant), and from becomes dormant. */
    private void move(int from, int to) {
        place(to, positions[from], positions[capacity + from], positions[2 * capacity + from],
                velocities[from], velocities[capacity + from], velocities[2 * capacity + from]);
        kinds[to] = kinds[from];
        births[to] = births[from];
        fuses[to] = fuses[from];
        fusesLeft[to] = fusesLeft[from];
        colours[to] = colours[from];
        park(from);
    }

    /**
     * {@link #move} of water into a slot that held water a moment ago (retired, not yet
     * parked): its fuses (0) and colour ({@link #WATER_COLOUR}) are the mover's already, so
     * only P, V, kind and birth are written, three random writes fewer at a scattered hole.
     */
    private void moveWater(int from, int to) {
        place(to, positions[from], positions[capacity + from], positions[2 * capacity + from],
                velocities[from], velocities[capacity + from], velocities[2 * capacity + from]);
        kinds[to] = WATER;
        births[to] = births[from];
        park(from);
    }

    /** Dormant: at rest on the ground at the nozzle. */
    private void park(int i) {
        kinds[i] = DORMANT;
        place(i, 0f, RADIUS_METRES, 0f, 0f, 0f, 0f);
        births[i] = Float.POSITIVE_INFINITY;
        fuses[i] = 0f;
        fusesLeft[i] = 0f;
        colours[i] = 0;
    }

    private void place(int i, float px, float py, float pz, float vx, float vy, float vz) {
        int y = capacity + i;
        int z = 2 * capacity + i;
        positions[i] = px;
        positions[y] = py;
        positions[z] = pz;
        velocities[i] = vx;
        velocities[y] = vy;
        velocities[z] = vz;
    }

    private float between(float least, float most) {
        return least + (most - least) * (float) random.nextDouble();
    }

    /** A spark's colour: its star's, halfway to white. */
    private static int brighten(int rgb) {
        int r = (rgb >> 16) & 0xff;
        int g = (rgb >> 8) & 0xff;
        int b = rgb & 0xff;
        return ((r + 255) / 2) << 16 | ((g + 255) / 2) << 8 | (b + 255) / 2;
    }

    /** Cyclone's FireworkRule: the fuse, the children's speed, the payload. */
    private static final class Rule {
        final float minFuse;
        final float maxFuse;
        final float minSpeed;
        final float maxSpeed;
        final byte payloadKind;
        final int payloadCount;

        /**
         * @param minFuse the shortest fuse (in seconds, &gt;0)
         * @param maxFuse the longest fuse (in seconds, &ge;minFuse)
         * @param minSpeed the least speed a child of this kind gets on top of its parent's
         *     (in m/s, &ge;0)
         * @param maxSpeed the most (in m/s, &ge;minSpeed)
         * @param payloadKind the kind of the children it leaves
         * @param payloadCount how many (&ge;0)
         */
        Rule(float minFuse, float maxFuse, float minSpeed, float maxSpeed, byte payloadKind,
                int payloadCount) {
            this.minFuse = minFuse;
            this.maxFuse = maxFuse;
            this.minSpeed = minSpeed;
            this.maxSpeed = maxSpeed;
            this.payloadKind = payloadKind;
            this.payloadCount = payloadCount;
        }
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;
import java.util.Arrays;

/**
 * The batch form of {@link ParticleIntegrator}'s step ({@link ParticleBatch#stepPacked}):
 * many particles of one mass in planar float arrays, with the folded forces' numbers
 * ({@link FoldedForces}), so it computes the floats of the per-particle step: the recipe
 * ({@link EulerRecipe}) with the folded a, {@code V ← V + h·(g − σ·V)}, {@code P ← P + h·V}.
 * Three forms:
 * <ul>
 * <li>by axes (gravity and linear drag: one σ for all), scalar passes the JIT vectorises, or
 * the Vector API ({@link VectorBatch}) with the check fused in;</li>
 * <li>by speed (quadratic drag, thrust): in blocks, each particle's σ first, then by
 * axes;</li>
 * <li>one by one (other forces, or b/m beyond the float range): each particle through
 * {@link FoldedForces#acceleration} and {@link EulerRecipe#step}.</li>
 * </ul>
 * Each checks that every particle is finite after the step and throws otherwise. The scalar
 * check of the step by axes has two forms, chosen once per JVM ({@link #FUSED_CHECK}): the
 * tree of sums ({@link #isSumFinite}) and the fused AND ({@link #isFusedFinite}).
 */
final class PackedStep {

    /**
     * True if this JVM has the Vector API ({@code --add-modules jdk.incubator.vector}), which
     * {@link VectorBatch} needs; asked of the boot layer, so {@link VectorBatch} is not loaded.
     */
    static final boolean VECTOR_API =
            ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();
    /**
     * Particles per block of the step by axes: their positions and velocities (24 KB) stay
     * in a core's first-level cache until their check has read them.
     */
    private static final int BATCH_BLOCK = 1024;
    /**
     * The first JDK feature release on which the fused check is the default, if any measured
     * win says so: {@code docs/speed.md} ("The finiteness check on JDK 17 and JDK 25") gives
     * the numbers. {@link Integer#MAX_VALUE} keeps the tree on every JDK.
     */
    static final int FUSED_CHECK_FROM_JDK = 25;
    /**
     * True if this JVM's scalar check is the fused AND, false for the tree of sums: chosen
     * once, at class initialisation, from the system property {@code particlelab.check}
     * ({@code tree} or {@code fused}: tests and benchmarks force a form with it) and the
     * running JDK ({@link #chooseFusedCheck}). (The property's name and values are literals:
     * this class keeps no static field but primitive constants.)
     */
    static final boolean FUSED_CHECK = chooseFusedCheckOrWarn(
            System.getProperty("particlelab.check"), Runtime.version().feature());

    private final FoldedForces folded;
    /** True if the step by axes runs on {@link VectorBatch}. */
    private boolean vectorBatch = VECTOR_API;
    /** True if the scalar check is the fused AND ({@link #FUSED_CHECK} unless a test says). */
    private boolean fusedCheck = FUSED_CHECK;
    /** Scratch for the one-by-one form: the particle being stepped ... */
    private final Particle particle = new Particle();
    /** ... and its acceleration (m/s²). */
    private final Vector3f acceleration = new Vector3f();
    /** Scratch of the step that finds a floor: vy of one block before its step (m/s) ... */
    private final float[] blockVelocityY = new float[BATCH_BLOCK];
    /** ... y of the block after it (m) ... */
    private final float[] blockHeights = new float[BATCH_BLOCK];
    /** ... x or z of the block after it (m) ... */
    private final float[] blockOthers = new float[BATCH_BLOCK];
    /** ... and each one's mark: +0 if above the floor and finite, else not ... */
    private final float[] blockMarks = new float[BATCH_BLOCK];
    /** ... which {@link Arrays#mismatch} compares with these zeros. */
    private final float[] zeros = new float[BATCH_BLOCK];
    /** Scratch of the step by speed: σ of each particle of one block (1/s). */
    private final float[] blockSigmas = new float[BATCH_BLOCK];
    /**
     * ... and one axis of its V (m/s) and P (m), copied so that every array of the pass on
     * that axis has the same index, which the JIT of JDK 17 needs to vectorise it.
     */
    private final float[] blockVelocities = new float[BATCH_BLOCK];
    private final float[] blockPositions = new float[BATCH_BLOCK];
    /** What the last step that finds a floor found: how many it stored. */
    private int foundCount;
    /** Whether the last block {@link #findInBlock} looked at was finite. */
    private boolean blockFinite;

    /**
     * Create the batch form of an integrator.
     *
     * @param folded the integrator's folded forces (not null)
     */
    PackedStep(FoldedForces folded) {
        this.folded = folded;
    }

    /** True if the step by axes runs on the Vector API. */
    boolean isVectorBatch() {
        return vectorBatch;
    }

    /** Choose the form of the step by axes (see {@link ParticleBatch#setVectorBatch}). */
    void setVectorBatch(boolean use) {
        if (use && !VECTOR_API) {
            throw new IllegalStateException("the batch step can use the Vector API only in a"
                    + " JVM started with --add-modules jdk.incubator.vector, and this one was"
                    + " not");
        }
        vectorBatch = use;
    }

    /** True if the scalar check is the fused AND, false for the tree of sums. */
    boolean isFusedCheck() {
        return fusedCheck;
    }

    /**
     * Choose the scalar check's form for this batch (tests: both forms on every JDK).
     *
     * @param fused true for the fused AND, false for the tree of sums
     */
    void setFusedCheck(boolean fused) {
        fusedCheck = fused;
    }

    /**
     * Choose the scalar check's form.
     *
     * @param property the value of the property {@code particlelab.check} (null if unset)
     * @param jdkFeature the running JDK's feature release (17, 25, ...)
     * @return true for the fused AND, false for the tree of sums
     * @throws IllegalArgumentException if the property is neither {@code tree} nor
     *     {@code fused}
     */
    static boolean chooseFusedCheck(String property, int jdkFeature) {
        if (property == null || property.isEmpty()) {
            return jdkFeature >= FUSED_CHECK_FROM_JDK;
        }
        if (property.equals("tree")) {
            return false;
        }
        if (property.equals("fused")) {
            return true;
        }
        throw new IllegalArgumentException("-Dparticlelab.check must be tree or fused, but was "
                + property);
    }

    /**
     * Step the particles, the numbers for h and m remembered ({@link StepLimits#remember}).
     *
     * @throws NonFiniteStepException as {@link ParticleBatch#stepPacked}
     */
    void step(float[] positions, float[] velocities, int stride, int count, float massKg,
            float stepSeconds) {
        float factor = Float.NaN;
        int bad;
        if (folded.hasOthers || !Float.isFinite(folded.stepLinearRate)) {
            // other forces, or b/m beyond the float range, which the recipe may survive
            bad = stepOneByOne(positions, velocities, stride, count, massKg, stepSeconds);
        } else if (folded.speedDependent) {
            bad = stepBySpeed(positions, velocities, stride, count, stepSeconds);
        } else {
            // a = g − σ·V with σ = b/m, the same for every particle
            factor = folded.stepFactor;
            bad = stepByAxes(positions, velocities, stride, count, stepSeconds, 0f, null,
                    null, null);
        }
        if (bad >= 0) {
            throw failure(positions, velocities, stride, count, bad, stepSeconds,
                    factor < -1f ? factor : Float.NaN);
        }
    }

    /**
     * {@link #step}, and find the particles whose y ends at or below a floor
     * ({@link HeightScan}), each with its vy before the step. The step by axes tests each
     * block right after stepping it, while it is in the cache, and keeps only that block's
     * vy before (a scratch of {@value #BATCH_BLOCK}); the other forms copy every vy into
     * storeVelocityYBefore first, step, test, and keep the found ones' in place; eachBlock
     * (if not null) then takes them all as one block.
     *
     * @return how many were found: their indices, increasing, are at the start of
     *     storeBelow, their vy before the step at the start of storeVelocityYBefore
     * @throws NonFiniteStepException as {@link #step}; then what is stored means nothing
     */
    int stepFindingFloor(float[] positions, float[] velocities, int stride, int count,
            float massKg, float stepSeconds, float floorMetres, int[] storeBelow,
            float[] storeVelocityYBefore, FloorContacts eachBlock) {
        if (folded.hasOthers || !Float.isFinite(folded.stepLinearRate) || folded.speedDependent) {
            System.arraycopy(velocities, stride, storeVelocityYBefore, 0, count);
            step(positions, velocities, stride, count, massKg, stepSeconds);
            return findAll(positions, stride, count, floorMetres, storeBelow,
                    storeVelocityYBefore, 0, storeVelocityYBefore, eachBlock);
        }
        float factor = folded.stepFactor;
        int bad = stepByAxes(positions, velocities, stride, count, stepSeconds, floorMetres,
                storeBelow, storeVelocityYBefore, eachBlock);
        if (bad >= 0) {
            throw failure(positions, velocities, stride, count, bad, stepSeconds,
                    factor < -1f ? factor : Float.NaN);
        }
        return foundCount;
    }

    /**
     * Refuse a negative count, a stride below it, or arrays too short for three axes of
     * stride floats, by name.
     */
    static void checkArrays(float[] positions, float[] velocities, int stride, int count) {
        if (count < 0) {
            throw new IllegalArgumentException("particle count must be >= 0, but was " + count);
        }
        if (stride < count) {
            throw new IllegalArgumentException("the stride between the axes must be >= the"
                    + " particle count " + count + ", but was " + stride);
        }
        long needed = 3L * stride;
        String name = stride == count ? "3*count" : "3*stride";
        if (positions == null || positions.length < needed) {
            throw new IllegalArgumentException("positions must hold " + name + " = " + needed
                    + " floats, but " + (positions == null ? "was null"
                    : "held " + positions.length));
        }
        if (velocities == null || velocities.length < needed) {
            throw new IllegalArgumentException("velocities must hold " + name + " = " + needed
                    + " floats, but " + (velocities == null ? "was null"
                    : "held " + velocities.length));
        }
    }

    /**
     * Find, in one pass over them all ({@link HeightScan#findAtOrBelow}), the particles whose
     * y is at or below the floor, keep each one's vy from velocityY, and hand them all on as
     * one block.
     *
     * @param velocityY where particle i's vy is, at velocityYOffset + i (it may be
     *     storeVelocityYBefore itself, offset 0: the c-th index found is at least c, so
     *     keeping them in place reads ahead only)
     * @return how many were found
     */
    static int findAll(float[] positions, int stride, int count, float floorMetres,
            int[] storeBelow, float[] velocityY, int velocityYOffset,
            float[] storeVelocityYBefore, FloorContacts eachBlock) {
        int found = HeightScan.findAtOrBelow(positions, stride, count, floorMetres, 0,
                storeBelow, 0);
        for (int c = 0; c < found; ++c) {
            storeVelocityYBefore[c] = velocityY[velocityYOffset + storeBelow[c]];
        }
        if (eachBlock != null && found > 0) {
            eachBlock.take(storeBelow, storeVelocityYBefore, 0, found);
        }
        return found;
    }

    /**
     * Gravity and linear drag, {@value #BATCH_BLOCK} particles at a time, in one of two forms:
     * <ul>
     * <li>scalar: each axis of the block in one pass ({@link #stepAxis}), then the block's
     * positions checked while they are still in the cache (a position is finite only if the
     * velocity that moved it is);</li>
     * <li>on the Vector API ({@link #vectorBatch}): each axis of the block in one pass that
     * also sums the new positions ({@link VectorBatch#stepAxis}). Blocks rather than whole
     * axes here too: over a loop of more than a few thousand vectors the JIT boxes the
     * vector of sums now and then (2.3 kB per call measured at 10^5 particles on JDK 17),
     * and blocks of 1024 allocate nothing.</li>
     * </ul>
     *
     * <p>With storeBelow (not null), each block's y is then tested against the floor
     * ({@link #findInBlock}, which checks the block's finiteness on the way), and the vy the
     * block had before its step, copied into a scratch of one block just before, is kept for
     * each one found; {@link #foundCount} says how many. Each block's found ones go to eachBlock
     * (if not null) right after its test, while the block is in the cache.
     *
     * @return the index of the first non-finite value, or -1
     */
    private int stepByAxes(float[] positions, float[] velocities, int stride, int count,
            float stepSeconds, float floorMetres, int[] storeBelow,
            float[] storeVelocityYBefore, FloorContacts eachBlock) {
        float sigma = folded.stepLinearRate;
        float gx = folded.gravityX;
        float gy = folded.gravityY;
        float gz = folded.gravityZ;
        boolean finite = true;
        int found = 0;
        for (int start = 0; start < count; start += BATCH_BLOCK) {
            int n = Math.min(BATCH_BLOCK, count - start);
            int y = stride + start;
            int z = 2 * stride + start;
            if (storeBelow != null) {
                System.arraycopy(velocities, y, blockVelocityY, 0, n);
            }
            // & rather than &&: every block is stepped and checked whatever the one before
            // found, with no branch per axis
            if (vectorBatch) {
                finite &= VectorBatch.stepAxis(positions, velocities, start, n, sigma, gx,
                                stepSeconds)
                        & VectorBatch.stepAxis(positions, velocities, y, n, sigma, gy,
                                stepSeconds)
                        & VectorBatch.stepAxis(positions, velocities, z, n, sigma, gz,
                                stepSeconds);
            } else {
                stepAxis(positions, velocities, start, n, sigma, gx, stepSeconds);
                stepAxis(positions, velocities, y, n, sigma, gy, stepSeconds);
                stepAxis(positions, velocities, z, n, sigma, gz, stepSeconds);
                // checked here, or by the floor's marks, which see a non-finite P too
                if (storeBelow == null) {
                    finite &= fusedCheck
                            ? isFusedFinite(positions, start, n) & isFusedFinite(positions, y, n)
                                    & isFusedFinite(positions, z, n)
                            : isSumFinite(positions, start, n) & isSumFinite(positions, y, n)
                                    & isSumFinite(positions, z, n);
                }
            }
            if (storeBelow != null) {
                int was = found;
                found = findInBlock(positions, stride, n, start, floorMetres, storeBelow,
                        storeVelocityYBefore, found);
                finite &= blockFinite;
                if (eachBlock != null && found > was) {
                    eachBlock.take(storeBelow, storeVelocityYBefore, was, found);
                }
            }
        }
        foundCount = found;
        return finite ? -1 : searchNonFinite(positions, stride, count);
    }

    /**
     * One axis of gravity and linear drag, the recipe with the folded a ({@link EulerRecipe},
     * {@link FoldedForces#acceleration}): {@code a = g − σ·V}, {@code V ← V + h·a}, then
     * {@code P ← P + h·V} with the new V.
     */
    private static void stepAxis(float[] positions, float[] velocities, int start, int count,
            float sigma, float gravity, float stepSeconds) {
        int end = start + count;
        for (int i = start; i < end; ++i) {
            float v = velocities[i];
            v = v + stepSeconds * (gravity - sigma * v);
            velocities[i] = v;
            positions[i] += stepSeconds * v;
        }
    }

    /**
     * The floor's test of one block just stepped, in passes the JIT vectorises: y copied into
     * a scratch (so that the next loop reads and writes at the same index, which C2's
     * superword needs), then each one's mark {@code |e| + e} with
     * {@code e = nextUp(floor) − y}, then {@link Arrays#mismatch} from one nonzero
     * mark to the next. For a finite y, e &gt; 0 exactly when y &le; floor (a rounded
     * difference keeps its sign, is 0 only for equal floats, and no float lies between the
     * floor and the next one up), so the mark is 2e &gt; 0 (or +∞) there and +0 (bits 0)
     * above it; y = NaN gives NaN, y = +∞ gives ∞ − ∞ = NaN, y = −∞ gives +∞. Then x and
     * z (copied likewise) add {@code p − p}: +0 for a finite p, NaN otherwise. A nonzero
     * mark is thus a particle at or below the floor or with a non-finite P, and is looked
     * at: the same particles as {@link HeightScan#findAtOrBelow}, in the same order, and the
     * block's finiteness check (in place of the tree of sums), which sets
     * {@link #blockFinite}. Where the fused check runs ({@link #isFusedFinite}, JDK 25 on),
     * x and z are checked by it in place instead: no copies and no additions to the marks,
     * which then say only "at or below the floor, or y not finite"; a non-finite x or z
     * sets {@link #blockFinite} false all the same.
     *
     * @return how many are stored now: found plus this block's
     */
    private int findInBlock(float[] positions, int stride, int n, int start,
            float floorMetres, int[] storeBelow, float[] storeVelocityYBefore, int found) {
        float[] heights = blockHeights;
        float[] marks = blockMarks;
        float[] others = blockOthers;
        System.arraycopy(positions, stride + start, heights, 0, n);
        float above = Math.nextUp(floorMetres);
        for (int k = 0; k < n; ++k) {
            float e = above - heights[k];
            marks[k] = Math.abs(e) + e;
        }
        boolean finite = true;
        if (fusedCheck) {
            // x and z by the fused AND, in place: one vectorised pass each where it runs
            finite = isFusedFinite(positions, start, n)
                    & isFusedFinite(positions, 2 * stride + start, n);
        } else {
            // x and z: p − p is +0 for a finite p and NaN otherwise, so the marks check them
            System.arraycopy(positions, start, others, 0, n);
            for (int k = 0; k < n; ++k) {
                float p = others[k];
                marks[k] += p - p;
            }
            System.arraycopy(positions, 2 * stride + start, others, 0, n);
            for (int k = 0; k < n; ++k) {
                float p = others[k];
                marks[k] += p - p;
            }
        }
        int stored = found;
        int k = 0;
        while (k < n) {
            int next = Arrays.mismatch(marks, k, n, zeros, k, n);
            if (next < 0) {
                break;
            }
            k += next;
            float h = heights[k];
            if (h <= floorMetres) {
                storeBelow[stored] = start + k;
                storeVelocityYBefore[stored] = blockVelocityY[k];
                ++stored;
            }
            finite &= Float.isFinite(h) & Float.isFinite(positions[start + k])
                    & Float.isFinite(positions[2 * stride + start + k]);
            ++k;
        }
        blockFinite = finite;
        return stored;
    }

    /**
     * σ depends on the speed (quadratic drag, thrust): {@value #BATCH_BLOCK} particles at a
     * time, first each one's σ into a scratch ({@link FoldedForces#dragRate} of its speed, as
     * {@link FoldedForces#acceleration} computes it; the square root and thrust's division
     * keep this pass scalar), then each axis of the block in a pass the JIT vectorises
     * ({@link #stepAxisBySpeed}: the recipe with a = g − σ·V), then the block's positions
     * checked while they are in the cache, as the step by axes checks them. The same floats
     * as the one pass per particle this replaced, which did not vectorise: with the recipe's
     * four operations per axis on V (the fold had two) it was 1.3 to 1.4 times the fold's
     * (docs/speed.md, issue 30).
     *
     * @return the index of the first non-finite value, or -1
     */
    private int stepBySpeed(float[] positions, float[] velocities, int stride, int count,
            float stepSeconds) {
        FoldedForces forces = folded;
        float gx = forces.gravityX;
        float gy = forces.gravityY;
        float gz = forces.gravityZ;
        float inverseMass = forces.stepInverseMass;
        float[] sigmas = blockSigmas;
        boolean finite = true;
        for (int start = 0; start < count; start += BATCH_BLOCK) {
            int n = Math.min(BATCH_BLOCK, count - start);
            int y = stride + start;
            int z = 2 * stride + start;
            for (int k = 0; k < n; ++k) {
                sigmas[k] = forces.dragRate(FoldedForces.speed(velocities[start + k],
                        velocities[y + k], velocities[z + k]), inverseMass);
            }
            stepAxisBySpeed(positions, velocities, start, n, gx, stepSeconds);
            stepAxisBySpeed(positions, velocities, y, n, gy, stepSeconds);
            stepAxisBySpeed(positions, velocities, z, n, gz, stepSeconds);
            finite &= fusedCheck
                    ? isFusedFinite(positions, start, n) & isFusedFinite(positions, y, n)
                            & isFusedFinite(positions, z, n)
                    : isSumFinite(positions, start, n) & isSumFinite(positions, y, n)
                            & isSumFinite(positions, z, n);
        }
        return finite ? -1 : searchNonFinite(positions, stride, count);
    }

    /**
     * One axis of a block by speed, the recipe with the folded a: {@code a = g − σ·V} with
     * each particle's σ from {@link #blockSigmas} (index 0 for the particle at start),
     * {@code V ← V + h·a}, then {@code P ← P + h·V} with the new V. On copies of the axis's V
     * and P, so that every array of the loop has the index k: JDK 17's JIT did not vectorise
     * the loop that read V and P at start + k and σ at k (PrintAssembly: no packed operation).
     */
    private void stepAxisBySpeed(float[] positions, float[] velocities, int start,
            int count, float gravity, float stepSeconds) {
        float[] sigmas = blockSigmas;
        float[] v = blockVelocities;
        float[] p = blockPositions;
        System.arraycopy(velocities, start, v, 0, count);
        System.arraycopy(positions, start, p, 0, count);
        for (int k = 0; k < count; ++k) {
            float next = v[k] + stepSeconds * (gravity - sigmas[k] * v[k]);
            v[k] = next;
            p[k] += stepSeconds * next;
        }
        System.arraycopy(v, 0, velocities, start, count);
        System.arraycopy(p, 0, positions, start, count);
    }

    /**
     * Other forces, or b/m beyond the float range: every particle through a scratch particle,
     * {@link FoldedForces#acceleration} (force by force where the fold overflows) and the
     * recipe's update, as {@link ParticleIntegrator#step(Particle, float)} does; unchecked.
     *
     * @return the index of the first non-finite value, or -1
     */
    private int stepOneByOne(float[] positions, float[] velocities, int stride, int count,
            float massKg, float stepSeconds) {
        particle.setMass(massKg);
        for (int i = 0; i < count; ++i) {
            int y = stride + i;
            int z = 2 * stride + i;
            particle.position.set(positions[i], positions[y], positions[z]);
            particle.velocity.set(velocities[i], velocities[y], velocities[z]);
            folded.acceleration(particle, acceleration);
            // unchecked here: the arrays are checked below
            EulerRecipe.step(particle, acceleration.x, acceleration.y, acceleration.z,
                    stepSeconds);
            positions[i] = particle.position.x;
            positions[y] = particle.position.y;
            positions[z] = particle.position.z;
            velocities[i] = particle.velocity.x;
            velocities[y] = particle.velocity.y;
            velocities[z] = particle.velocity.z;
        }
        boolean finite = isSumFinite(positions, 0, count)
                & isSumFinite(positions, stride, count) & isSumFinite(positions, 2 * stride, count);
        return finite ? -1 : searchNonFinite(positions, stride, count);
    }

    /**
     * Tell whether values might all be finite, cheaply: one pass summing them, sixteen at a
     * time as a tree into four independent sums (short chains keep the additions in flight).
     * A finite total means every value is finite (an infinity or NaN makes the sum infinite
     * or NaN); a total that overflows although every value is finite only costs a search.
     *
     * @return true if every value of values[start .. start + length) is finite; false if one
     *     is not, or perhaps if their sum overflows
     */
    static boolean isSumFinite(float[] values, int start, int length) {
        float sum0 = 0f;
        float sum1 = 0f;
        float sum2 = 0f;
        float sum3 = 0f;
        int end = start + length;
        int i = start;
        for (; i + 16 <= end; i += 16) {
            sum0 += (values[i] + values[i + 1]) + (values[i + 2] + values[i + 3]);
            sum1 += (values[i + 4] + values[i + 5]) + (values[i + 6] + values[i + 7]);
            sum2 += (values[i + 8] + values[i + 9]) + (values[i + 10] + values[i + 11]);
            sum3 += (values[i + 12] + values[i + 13]) + (values[i + 14] + values[i + 15]);
        }
        for (; i < end; ++i) {
            sum0 += values[i];
        }
        return Float.isFinite((sum0 + sum1) + (sum2 + sum3));
    }

    /**
     * Tell whether values are all finite, exactly: {@code acc &= (int) ((p − p) + 1f)} over
     * them, one pass with no dependence between the values but the AND, which the JIT of
     * JDK 25 vectorises (JDK 17's does not). {@code p − p} is 0 for a finite p and NaN for
     * ±∞ or NaN, and {@code (int) NaN} is 0, so acc stays 1 only if every value is finite.
     * No false alarms: a large finite value gives 0 + 1 like any other.
     *
     * @return true if every value of values[start .. start + length) is finite
     */
    static boolean isFusedFinite(float[] values, int start, int length) {
        int acc = 1;
        int end = start + length;
        for (int i = start; i < end; ++i) {
            float p = values[i];
            acc &= (int) ((p - p) + 1f);
        }
        return acc == 1;
    }

    /**
     * {@link #chooseFusedCheck}, but a bad property only warns (one line on stderr naming it
     * and what is allowed) and the JDK decides: a class initialiser must not throw.
     */
    private static boolean chooseFusedCheckOrWarn(String property, int jdkFeature) {
        try {
            return chooseFusedCheck(property, jdkFeature);
        } catch (IllegalArgumentException bad) {
            System.err.println("particle-lab: " + bad.getMessage() + "; using the JDK's"
                    + " default form");
            return chooseFusedCheck(null, jdkFeature);
        }
    }

    /** The particle of the first non-finite value, axis by axis (x, then y, z), or -1. */
    private static int searchNonFinite(float[] values, int stride, int count) {
        for (int axis = 0; axis < 3 * stride; axis += stride) {
            for (int i = 0; i < count; ++i) {
                if (!Float.isFinite(values[axis + i])) {
                    return i;
                }
            }
        }
        return -1;
    }

    private static NonFiniteStepException failure(float[] positions, float[] velocities,
            int stride, int count, int particle, float stepSeconds, float unstableFactor) {
        int y = stride + particle;
        int z = 2 * stride + particle;
        String why = Float.isNaN(unstableFactor)
                ? "its state was already non-finite or the numbers overflowed the float range"
                : "the velocity factor 1 - h*b/m = " + unstableFactor + " is beyond -1"
                        + " (h > 2m/b)";
        return new NonFiniteStepException("the Euler step h=" + stepSeconds + " s left"
                + " packed particle " + particle + " of " + count + " non-finite: P=("
                + positions[particle] + ", " + positions[y] + ", " + positions[z] + "), V=("
                + velocities[particle] + ", " + velocities[y] + ", " + velocities[z] + "); "
                + why + "; every particle was stepped, so reset the arrays before stepping"
                + " again");
    }
}

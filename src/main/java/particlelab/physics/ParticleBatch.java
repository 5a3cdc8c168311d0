package particlelab.physics;

/**
 * The batch form of {@link ParticleIntegrator}'s step ({@link ParticleIntegrator#batch}):
 * many particles of one mass, packed in planar float arrays, each moved by the recipe
 * ({@link EulerRecipe}) with the folded acceleration, in loops the JIT vectorises
 * ({@link PackedStep}, and {@link VectorBatch} on the Vector API): the same floats as stepping
 * each as a {@link Particle}, a test checks it for every mix of forces
 * ({@code FastPathsMatchTheRecipeTest}). Its integrator's forces, fold and regime bound are
 * shared; like the integrator, not thread-safe, and a step allocates nothing.
 */
public final class ParticleBatch {

    /** The integrator's folded forces. */
    private final FoldedForces folded;
    /** The integrator's limits, which remember the step and mass with the fold. */
    private final StepLimits limits;
    /** The loops. */
    private final PackedStep packed;

    /**
     * Create the batch form of an integrator.
     *
     * @param folded the integrator's folded forces (not null)
     * @param limits the integrator's limits (not null)
     */
    ParticleBatch(FoldedForces folded, StepLimits limits) {
        this.folded = folded;
        this.limits = limits;
        packed = new PackedStep(folded);
    }

    /**
     * Advance many particles of one mass, packed in two float arrays, by one Euler step each
     * ({@link PackedStep}): identical floats to stepping each as an object of that mass (only
     * where a particle's folded acceleration overflows does the per-particle step ask every
     * force before refusing; the batch refuses). Allocates nothing. Layout ("planar"): with
     * {@code n = count}, particle i has {@code P = (positions[i], positions[n + i],
     * positions[2n + i])} and V likewise. It checks that every particle is finite after the
     * step and otherwise throws; it keeps no copy of the states (that would double the cost),
     * so the arrays then hold the step's result, the non-finite ones included: reset them.
     *
     * @param positions P of every particle, planar (in m, finite, length &ge; 3·count, modified)
     * @param velocities V, likewise (in m/s, finite, length &ge; 3·count, modified)
     * @param count the number of particles (&ge;0)
     * @param massKg the mass of each (in kilograms, finite, &ge;{@link Particle#MIN_MASS_KG})
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0; 0 does nothing)
     * @throws NonFiniteStepException if after the step a particle is not finite; the message
     *     names the first such particle and its state, and every particle has been stepped
     */
    public void stepPacked(float[] positions, float[] velocities, int count, float massKg,
            float stepSeconds) {
        PackedStep.checkArrays(positions, velocities, count, count);
        Particle.checkMass(massKg);
        Validate.nonNegative(stepSeconds, "step h (s)");
        if (stepSeconds == 0f || count == 0) {
            return;
        }
        folded.refoldIfStale();
        limits.remember(stepSeconds, massKg);
        packed.step(positions, velocities, count, count, massKg, stepSeconds);
    }

    /**
     * {@link #stepPacked(float[], float[], int, float, float)} for the first count particles
     * of arrays laid out for stride particles: particle i has {@code P = (positions[i],
     * positions[stride + i], positions[2·stride + i])}, V likewise; the rest are not touched.
     * A pool that keeps its particles in flight first steps only those. (Its body repeats
     * the form above rather than either calling the other: a call more between the caller
     * and the batch's loops measured 1.2 to 2.6 times slower in some rows, the JIT then
     * inlining the loops differently; CompareBuilds, docs/speed.md.)
     *
     * @param positions P, planar with the stride (in m, finite, length &ge; 3·stride, modified)
     * @param velocities V, likewise (in m/s, finite, length &ge; 3·stride, modified)
     * @param stride the particles the layout has room for (&ge;count)
     * @param count the particles to step, the first ones (&ge;0)
     * @param massKg as above
     * @param stepSeconds as above
     * @throws IllegalArgumentException if stride &lt; count or the arrays hold fewer than
     *     3·stride floats
     */
    public void stepPacked(float[] positions, float[] velocities, int stride, int count,
            float massKg, float stepSeconds) {
        PackedStep.checkArrays(positions, velocities, stride, count);
        Particle.checkMass(massKg);
        Validate.nonNegative(stepSeconds, "step h (s)");
        if (stepSeconds == 0f || count == 0) {
            return;
        }
        folded.refoldIfStale();
        limits.remember(stepSeconds, massKg);
        packed.step(positions, velocities, stride, count, massKg, stepSeconds);
    }

    /**
     * {@link #stepPacked(float[], float[], int, int, float, float)}, and find the particles
     * whose y ends the step at or below a floor, each with the vy it had before the step: a
     * ground's contact test and what Cyclone's resting fix needs
     * ({@code particlelab.world.GroundBounce#resolveFound}), done on each block of particles
     * while the step has it in the cache, instead of a copy of every vy before the step and
     * a pass over every y after it. The same floats as stepPacked, the same particles found
     * as {@link HeightScan#findAtOrBelow} over the stepped y (a test checks both, for every
     * form of the batch). (Its body repeats stepPacked's checks, for the reason given there.)
     *
     * @param positions as stepPacked with a stride (modified)
     * @param velocities as stepPacked with a stride (modified)
     * @param stride as stepPacked with a stride
     * @param count as stepPacked with a stride
     * @param massKg as stepPacked
     * @param stepSeconds as stepPacked
     * @param floorMetres the floor: a particle is found if its y after the step is at or
     *     below it (in metres, finite)
     * @param storeBelow where to write the found particles' indices, increasing (length
     *     &ge; count, modified from index 0 on)
     * @param storeVelocityYBefore where to write their vy before the step, in the same order
     *     (in m/s, length &ge; count, modified from index 0 on: up to count floats as
     *     scratch)
     * @return how many particles were found (with h = 0, those at or below it already)
     * @throws NonFiniteStepException as stepPacked; the stores then mean nothing
     */
    public int stepPackedFindingFloor(float[] positions, float[] velocities, int stride,
            int count, float massKg, float stepSeconds, float floorMetres, int[] storeBelow,
            float[] storeVelocityYBefore) {
        return stepPackedFindingFloor(positions, velocities, stride, count, massKg,
                stepSeconds, floorMetres, storeBelow, storeVelocityYBefore, null);
    }

    /**
     * {@link #stepPackedFindingFloor(float[], float[], int, int, float, float, float, int[],
     * float[])}, handing each block's particles found to eachBlock right after that block's
     * step, while its arrays are in the cache (with h = 0, or in the batch's forms that do
     * not work in blocks, all of them as one block at the end): a ground's rule applied
     * there reads nothing from memory again. The stores hold what the form without it
     * gives, unless eachBlock writes over the entries it was handed (it may).
     *
     * @param positions as above
     * @param velocities as above
     * @param stride as above
     * @param count as above
     * @param massKg as above
     * @param stepSeconds as above
     * @param floorMetres as above
     * @param storeBelow as above
     * @param storeVelocityYBefore as above
     * @param eachBlock what takes each block's particles found (null: nothing)
     * @return how many particles were found
     * @throws NonFiniteStepException as stepPacked; eachBlock may have taken blocks before
     */
    public int stepPackedFindingFloor(float[] positions, float[] velocities, int stride,
            int count, float massKg, float stepSeconds, float floorMetres, int[] storeBelow,
            float[] storeVelocityYBefore, FloorContacts eachBlock) {
        PackedStep.checkArrays(positions, velocities, stride, count);
        Particle.checkMass(massKg);
        Validate.nonNegative(stepSeconds, "step h (s)");
        Validate.finite(floorMetres, "floor (m)");
        if (storeBelow == null || storeBelow.length < count || storeVelocityYBefore == null
                || storeVelocityYBefore.length < count) {
            throw new IllegalArgumentException("the stores of the particles found and of"
                    + " their vy before the step must each hold count = " + count
                    + " values, but held " + (storeBelow == null ? "null"
                    : String.valueOf(storeBelow.length)) + " and "
                    + (storeVelocityYBefore == null ? "null"
                    : String.valueOf(storeVelocityYBefore.length)));
        }
        if (stepSeconds == 0f) {
            // nothing moves: those at or below the floor already, with the vy they keep
            return PackedStep.findAll(positions, stride, count, floorMetres, storeBelow,
                    velocities, stride, storeVelocityYBefore, eachBlock);
        }
        if (count == 0) {
            return 0;
        }
        folded.refoldIfStale();
        limits.remember(stepSeconds, massKg);
        return packed.stepFindingFloor(positions, velocities, stride, count, massKg,
                stepSeconds, floorMetres, storeBelow, storeVelocityYBefore, eachBlock);
    }

    /**
     * Tell whether this JVM can run the batch step on the Vector API: it was started with
     * {@code --add-modules jdk.incubator.vector} (README, "The Vector API, opt-in").
     *
     * @return true if {@link #setVectorBatch(boolean) setVectorBatch(true)} is allowed
     */
    public static boolean isVectorApiAvailable() {
        return PackedStep.VECTOR_API;
    }

    /**
     * Tell which code {@link #stepPacked} runs with gravity and linear drag (the only forces
     * it has two forms for).
     *
     * @return true: the Vector API, the check fused in; false: scalar passes, a separate check
     */
    public boolean isVectorBatch() {
        return packed.isVectorBatch();
    }

    /**
     * Choose the code {@link #stepPacked} runs with gravity and linear drag; both give
     * identical numbers, so this only matters for speed. Default: the Vector API if present.
     *
     * @param use true for the Vector API (only if {@link #isVectorApiAvailable()}), false for
     *     the scalar passes
     * @throws IllegalStateException if use is true and this JVM has no Vector API
     */
    public void setVectorBatch(boolean use) {
        packed.setVectorBatch(use);
    }
}

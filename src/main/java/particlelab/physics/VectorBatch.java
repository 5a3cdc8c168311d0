package particlelab.physics;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The batch step with gravity and linear drag written with the JDK's Vector API
 * ({@code jdk.incubator.vector}): the second form of {@link PackedStep}'s step by axes (for
 * {@link ParticleBatch#stepPacked}) when the JVM was started with
 * {@code --add-modules jdk.incubator.vector}.
 *
 * <p>Why it exists: the JIT turns the scalar pass of one axis into vector instructions, but
 * not a check of its results (a sum over the positions is a reduction it will not reorder),
 * and that check costs more than the step (docs/speed.md). Here the check rides along in a
 * vector of partial sums, one addition per vector of positions, and its lanes are tested once
 * at the end of the axis.
 *
 * <p>The arithmetic is the scalar pass's, operation for operation: {@code a = g − σ·v}, then
 * {@code v + h·a}, then {@code P + h·v}, each rounded to float (no fused multiply-add), so the
 * results are bit for bit those of the scalar pass and of {@code step(Particle, h)}.
 *
 * <p>This class is loaded only if the module is present
 * ({@link ParticleBatch#isVectorApiAvailable()}): nothing else in the project refers to
 * the incubator API, so without the module the scalar passes run and nothing fails.
 */
final class VectorBatch {

    /** The widest vector shape this machine computes natively (16 floats with AVX-512). */
    private static final VectorSpecies<Float> SPECIES = FloatVector.SPECIES_PREFERRED;

    private VectorBatch() {
    }

    /**
     * Step one axis of {@code count} particles, {@code V ← V + h·(g − σ·V)}, then
     * {@code P ← P + h·V} with the new V, and tell whether the new positions are all finite.
     *
     * @param positions the packed positions (modified)
     * @param velocities the packed velocities (modified)
     * @param start the first index of the axis
     * @param count the number of particles
     * @param sigma σ = b/m (1/s)
     * @param gravity g on this axis (m/s²)
     * @param stepSeconds h (s)
     * @return true if the sum of the new positions is finite, which means every one is; false
     *     if one is not, or perhaps if the sum overflowed although every one is finite
     */
    static boolean stepAxis(float[] positions, float[] velocities, int start, int count,
            float sigma, float gravity, float stepSeconds) {
        int lanes = SPECIES.length();
        int vectorEnd = start + SPECIES.loopBound(count);
        int end = start + count;
        FloatVector sums = FloatVector.zero(SPECIES);
        int i = start;
        for (; i < vectorEnd; i += lanes) {
            FloatVector v = FloatVector.fromArray(SPECIES, velocities, i);
            // V + h·(g − σ·V): −σ·V + g is g − σ·V exactly, h·a + V is V + h·a
            v = v.mul(-sigma).add(gravity).mul(stepSeconds).add(v);
            v.intoArray(velocities, i);
            FloatVector p = FloatVector.fromArray(SPECIES, positions, i)
                    .add(v.mul(stepSeconds));
            p.intoArray(positions, i);
            sums = sums.add(p);
        }
        float tail = 0f;
        for (; i < end; ++i) {
            float v = velocities[i];
            v = v + stepSeconds * (gravity - sigma * v);
            velocities[i] = v;
            float p = positions[i] + stepSeconds * v;
            positions[i] = p;
            tail += p;
        }
        return sums.test(VectorOperators.IS_FINITE).allTrue() && Float.isFinite(tail);
    }
}

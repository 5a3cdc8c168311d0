package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The lecture's simulation recipe, as the code every per-particle step runs
 * ({@link ParticleIntegrator#step(Particle, float)}, the batch's one-by-one form, the careful
 * step where a fast form declines):
 *
 * <pre>
 *   a = g + F(P, V)/m      the forces at the start of the step  ({@link #accelerationOf})
 *   V ← V + h·a            velocity first                      ({@link #step})
 *   P ← P + h·V            then position, with the NEW velocity
 * </pre>
 *
 * This is the semi-implicit (symplectic) Euler method. Swap the last two lines and it becomes
 * forward (explicit) Euler, which moves P with the old V: a level shot then lands
 * {@code vx·h} long instead of {@code vx·h} short ({@code EulerRecipeTest} shows both).
 * The integrator may compute a faster (its built-in forces folded, {@link FoldedForces}), but
 * the update is always these two lines. Unchecked: the integrator decides what a non-finite
 * result means. Allocates nothing.
 */
final class EulerRecipe {

    private EulerRecipe() {
    }

    /**
     * The recipe's first line, force by force: sum {@code a = g + F/m} over some forces into
     * storeResult, with scratch vectors for g and F.
     *
     * @param forces the forces to ask (not null, no null elements)
     * @param particle the particle (not null, not modified)
     * @param field scratch: g, the sum of field accelerations (m/s², modified)
     * @param push scratch: F, the sum of pushing forces (N, modified)
     * @param storeResult storage for a (m/s², modified)
     * @return storeResult
     */
    static Vector3f accelerationOf(Force[] forces, Particle particle, Vector3f field,
            Vector3f push, Vector3f storeResult) {
        field.zero();
        push.zero();
        for (int i = 0; i < forces.length; ++i) {
            forces[i].addFieldAcceleration(particle, field);
            forces[i].addForce(particle, push);
        }
        // a = g + F/m
        return storeResult.set(field).scaleAdd(1f / particle.getMass(), push, storeResult);
    }

    /**
     * The recipe's update, written into the particle: {@code V ← V + h·a}, then
     * {@code P ← P + h·V} with the new velocity. Unchecked: it tells whether the new position
     * is finite, and the caller decides what a non-finite one means (the integrator puts the
     * old state back and refuses; the batch names the particle).
     *
     * @param particle the particle at the start of the step (not null, modified)
     * @param ax a along x at the start of the step (m/s²)
     * @param ay a along y (m/s²)
     * @param az a along z (m/s²)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return true if the new position is finite (with h &gt; 0, so is the new velocity)
     */
    static boolean step(Particle particle, float ax, float ay, float az, float stepSeconds) {
        Vector3f velocity = particle.velocity;
        Vector3f position = particle.position;
        // V ← V + h·a
        float vx = velocity.x + stepSeconds * ax;
        float vy = velocity.y + stepSeconds * ay;
        float vz = velocity.z + stepSeconds * az;
        // P ← P + h·V, with the new V
        float px = position.x + stepSeconds * vx;
        float py = position.y + stepSeconds * vy;
        float pz = position.z + stepSeconds * vz;
        // P stored before V: the next step starts by reading V, and C2 hands a value read
        // right after its own store over in a register only if no store to the same field
        // of another Vector3f (P's, which it cannot tell apart) came between; stored the
        // other way round, V went through memory on the step's chain (docs/speed.md, "One
        // particle against the primitive loop on this host")
        position.set(px, py, pz);
        velocity.set(vx, vy, vz);
        // a finite sum means three finite terms
        return Float.isFinite(px + py + pz)
                || Float.isFinite(px) && Float.isFinite(py) && Float.isFinite(pz);
    }
}

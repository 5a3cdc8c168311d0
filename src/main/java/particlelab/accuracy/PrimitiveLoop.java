package particlelab.accuracy;

import particlelab.physics.Thrust;

/**
 * The practical speed limit: gravity plus linear drag (or any {@link ForceMix}) stepped by a
 * hand-written loop over primitive float arrays, with no objects, no force abstraction and no
 * checks. The layout is planar (all x, then all y, then all z), the one
 * {@code ParticleBatch.stepPacked} takes, so the JIT can vectorise both. Benchmarks and
 * the report compare the shared integrator against it.
 */
public final class PrimitiveLoop {

    private PrimitiveLoop() {
    }

    /**
     * Take several semi-implicit Euler steps of one particle held in two 3-float arrays, for
     * the one-particle benchmarks (a separate method, so its JIT profile stays apart from the
     * bulk loop's).
     *
     * @param position P (in metres, length 3, modified)
     * @param velocity V (in m/s, length 3, modified)
     * @param gravity g per axis (in m/s², length 3, not modified)
     * @param linearRate k = b/m (in 1/s)
     * @param stepSeconds h (in seconds)
     * @param steps how many steps (&ge;0)
     */
    public static void stepOne(float[] position, float[] velocity, float[] gravity,
            float linearRate, float stepSeconds, int steps) {
        float factor = 1f - stepSeconds * linearRate;
        float stepGravityX = stepSeconds * gravity[0];
        float stepGravityY = stepSeconds * gravity[1];
        float stepGravityZ = stepSeconds * gravity[2];
        float px = position[0];
        float py = position[1];
        float pz = position[2];
        float vx = velocity[0];
        float vy = velocity[1];
        float vz = velocity[2];
        for (int n = 0; n < steps; ++n) {
            vx = vx * factor + stepGravityX;
            vy = vy * factor + stepGravityY;
            vz = vz * factor + stepGravityZ;
            px += stepSeconds * vx;
            py += stepSeconds * vy;
            pz += stepSeconds * vz;
        }
        position[0] = px;
        position[1] = py;
        position[2] = pz;
        velocity[0] = vx;
        velocity[1] = vy;
        velocity[2] = vz;
    }

    /**
     * Take several semi-implicit Euler steps of one particle under gravity and a force mix,
     * folded by hand: {@code V ← (1 − h·σ)·V + h·g} with {@code σ = (b + c·|V| − k/|V|)/m}
     * (the thrust term only while {@code |V| ≥} {@link Thrust#MIN_SPEED}). Without quadratic
     * drag and thrust σ is a constant and this is {@link #stepOne(float[], float[], float[],
     * float, float, int)}.
     *
     * @param position P (in metres, length 3, modified)
     * @param velocity V (in m/s, length 3, modified)
     * @param gravity g per axis (in m/s², length 3, not modified)
     * @param mix the forces besides gravity, on a particle of {@link ForceMix#MASS_KG} (not
     *     null)
     * @param stepSeconds h (in seconds)
     * @param steps how many steps (&ge;0)
     */
    public static void stepOne(float[] position, float[] velocity, float[] gravity,
            ForceMix mix, float stepSeconds, int steps) {
        float linearRate = mix.linearDrag() / ForceMix.MASS_KG;
        if (mix.quadraticDrag() == 0f && mix.thrustNewtons() == 0f) {
            stepOne(position, velocity, gravity, linearRate, stepSeconds, steps);
            return;
        }
        float stepLinear = stepSeconds * linearRate;
        float stepQuadratic = stepSeconds * mix.quadraticDrag() / ForceMix.MASS_KG;
        float stepThrust = stepSeconds * mix.thrustNewtons() / ForceMix.MASS_KG;
        float stepGravityX = stepSeconds * gravity[0];
        float stepGravityY = stepSeconds * gravity[1];
        float stepGravityZ = stepSeconds * gravity[2];
        float px = position[0];
        float py = position[1];
        float pz = position[2];
        float vx = velocity[0];
        float vy = velocity[1];
        float vz = velocity[2];
        for (int n = 0; n < steps; ++n) {
            float speed = (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
            float thrust = speed >= Thrust.MIN_SPEED ? stepThrust / speed : 0f;
            float factor = 1f - stepLinear - stepQuadratic * speed + thrust;
            vx = vx * factor + stepGravityX;
            vy = vy * factor + stepGravityY;
            vz = vz * factor + stepGravityZ;
            px += stepSeconds * vx;
            py += stepSeconds * vy;
            pz += stepSeconds * vz;
        }
        position[0] = px;
        position[1] = py;
        position[2] = pz;
        velocity[0] = vx;
        velocity[1] = vy;
        velocity[2] = vz;
    }

    /**
     * Take one semi-implicit Euler step of every particle under gravity and a force mix,
     * folded by hand as in {@link #stepOne(float[], float[], float[], ForceMix, float, int)}:
     * one pass per axis when σ is a constant, else one pass over the particles.
     *
     * @param positions P, planar (in metres, length &ge; 3·count, modified)
     * @param velocities V, planar (in m/s, length &ge; 3·count, modified)
     * @param count the number of particles (&ge;0)
     * @param gravity g per axis (in m/s², length 3, not modified)
     * @param mix the forces besides gravity, on particles of {@link ForceMix#MASS_KG} (not
     *     null)
     * @param stepSeconds h (in seconds)
     */
    public static void step(float[] positions, float[] velocities, int count, float[] gravity,
            ForceMix mix, float stepSeconds) {
        float linearRate = mix.linearDrag() / ForceMix.MASS_KG;
        if (mix.quadraticDrag() == 0f && mix.thrustNewtons() == 0f) {
            step(positions, velocities, count, gravity, linearRate, stepSeconds);
            return;
        }
        float stepLinear = stepSeconds * linearRate;
        float stepQuadratic = stepSeconds * mix.quadraticDrag() / ForceMix.MASS_KG;
        float stepThrust = stepSeconds * mix.thrustNewtons() / ForceMix.MASS_KG;
        float stepGravityX = stepSeconds * gravity[0];
        float stepGravityY = stepSeconds * gravity[1];
        float stepGravityZ = stepSeconds * gravity[2];
        for (int x = 0, y = count, z = 2 * count; x < count; ++x, ++y, ++z) {
            float vx = velocities[x];
            float vy = velocities[y];
            float vz = velocities[z];
            float speed = (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
            float thrust = speed >= Thrust.MIN_SPEED ? stepThrust / speed : 0f;
            float factor = 1f - stepLinear - stepQuadratic * speed + thrust;
            vx = vx * factor + stepGravityX;
            vy = vy * factor + stepGravityY;
            vz = vz * factor + stepGravityZ;
            velocities[x] = vx;
            velocities[y] = vy;
            velocities[z] = vz;
            positions[x] += stepSeconds * vx;
            positions[y] += stepSeconds * vy;
            positions[z] += stepSeconds * vz;
        }
    }

    /**
     * Take one semi-implicit Euler step of every particle:
     * {@code V ← V + h·(g − k·V)}, {@code P ← P + h·V}.
     *
     * @param positions P, planar (in metres, length &ge; 3·count, modified)
     * @param velocities V, planar (in m/s, length &ge; 3·count, modified)
     * @param count the number of particles (&ge;0)
     * @param gravity g per axis (in m/s², length 3, not modified)
     * @param linearRate k = b/m (in 1/s)
     * @param stepSeconds h (in seconds)
     */
    public static void step(float[] positions, float[] velocities, int count, float[] gravity,
            float linearRate, float stepSeconds) {
        float factor = 1f - stepSeconds * linearRate;
        for (int axis = 0; axis < 3; ++axis) {
            float stepGravity = stepSeconds * gravity[axis];
            int end = (axis + 1) * count;
            for (int i = axis * count; i < end; ++i) {
                float v = velocities[i] * factor + stepGravity;
                velocities[i] = v;
                positions[i] += stepSeconds * v;
            }
        }
    }
}

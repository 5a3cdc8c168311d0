package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The fast form of {@link ParticleIntegrator}'s recipe: its built-in forces folded into four
 * numbers, the summed gravity g, linear drag b, quadratic drag c and thrust k. Their pushes
 * all point along V, so {@code F/m = −σ·V} with {@code σ = (b + c·|V| − k/|V|)/m} (the thrust
 * term only from {@link Thrust#MIN_SPEED} on), and the recipe's velocity update becomes
 * <pre>
 *   V + h·a = V + h·(g − σ·V) = (1 − h·σ)·V + h·g
 * </pre>
 * with h and 1/m folded in too, per step and mass:
 * {@code 1 − h·σ = (1 − h·b/m) − (h·c/m)·|V| + (h·k/m)/|V|}. This rounds differently from the
 * recipe; the bound is in {@link ParticleIntegrator}'s Javadoc and
 * {@code ParticleIntegratorFoldingTest} and {@code FastPathsMatchTheRecipeTest} prove it.
 *
 * <p>The per-particle step ({@link #step}), the careful step ({@link #compute}) and the batch
 * ({@link PackedStep}) read the same remembered numbers, so they compute the same floats. The
 * numbers for a step and mass are filled by {@link StepLimits#remember}, which keys the
 * regime's bound on the same h and m. A setter of a folded force marks this fold
 * {@link #markStale stale} ({@link FoldedForce}); the integrator folds again before its next
 * step ({@link #refoldIfStale}).
 */
final class FoldedForces {

    /** True if the scene has forces that are not folded (asked through the interface). */
    final boolean hasOthers;
    /** Folded: the summed field acceleration g per axis (m/s²). */
    float gravityX;
    float gravityY;
    float gravityZ;
    /** Folded: the summed linear drag b (kg/s). */
    float linearSum;
    /** Folded: the summed quadratic drag c (kg/m). */
    float quadraticSum;
    /** Folded: the summed thrust k (N). */
    float thrustSum;
    /** Folded: true if σ depends on |V| (some c or k is not zero). */
    boolean speedDependent;
    /** Remembered for one step and mass ({@link #isRememberedFor}): h·g (m/s) ... */
    float stepGravityX;
    float stepGravityY;
    float stepGravityZ;
    /** ... 1/m (1/kg) ... */
    float stepInverseMass;
    /** ... the velocity factor 1 − h·b/m of linear drag ... */
    float stepFactor;
    /** ... h·c/m of quadratic drag (1/m) ... */
    float stepQuadratic;
    /** ... h·k/m of thrust (m/s) ... */
    float stepThrust;

    /** The built-in forces by type, each in the scene's order. */
    private final Gravity[] gravities;
    private final LinearDrag[] linearDrags;
    private final QuadraticDrag[] quadraticDrags;
    private final Thrust[] thrusts;
    /** True if a setter changed a folded force since the last fold. */
    private boolean stale;
    /** The step the numbers above were remembered for (s; NaN: none since the last fold) ... */
    private float rememberedSeconds = Float.NaN;
    /** ... and the mass (kg). */
    private float rememberedMass = Float.NaN;
    /** The mass whose inverse is {@link #cachedInverseMass} (kg; NaN: none yet). */
    private float cachedMass = Float.NaN;
    /** 1/{@link #cachedMass} (1/kg). */
    private float cachedInverseMass = Float.NaN;
    /** Scratch for {@link #fold}: one gravity's g (m/s²). */
    private final Vector3f oneGravity = new Vector3f();

    /**
     * Fold the built-in forces of a scene.
     *
     * @param forces the scene's forces (not null, no null elements; the others are skipped)
     */
    FoldedForces(Force[] forces) {
        gravities = new Gravity[count(forces, Gravity.class)];
        linearDrags = new LinearDrag[count(forces, LinearDrag.class)];
        quadraticDrags = new QuadraticDrag[count(forces, QuadraticDrag.class)];
        thrusts = new Thrust[count(forces, Thrust.class)];
        int gravity = 0;
        int linear = 0;
        int quadratic = 0;
        int thrust = 0;
        for (Force force : forces) {
            if (force instanceof FoldedForce) {
                ((FoldedForce) force).foldedBy(this);
            }
            if (force instanceof Gravity) {
                gravities[gravity++] = (Gravity) force;
            } else if (force instanceof LinearDrag) {
                linearDrags[linear++] = (LinearDrag) force;
            } else if (force instanceof QuadraticDrag) {
                quadraticDrags[quadratic++] = (QuadraticDrag) force;
            } else if (force instanceof Thrust) {
                thrusts[thrust++] = (Thrust) force;
            }
        }
        hasOthers = gravity + linear + quadratic + thrust < forces.length;
        fold();
    }

    /**
     * Pick the forces that are not folded, asked through the {@link Force} interface.
     *
     * @param forces a scene's forces (not null, no null elements, not modified)
     * @return those that are not built-in, in the scene's order (a new array)
     */
    static Force[] others(Force[] forces) {
        Force[] others = new Force[forces.length - count(forces, FoldedForce.class)];
        for (int i = 0, other = 0; i < forces.length; ++i) {
            if (!(forces[i] instanceof FoldedForce)) {
                others[other++] = forces[i];
            }
        }
        return others;
    }

    /** Note that a folded force changed: called by its setters ({@link FoldedForce}). */
    void markStale() {
        stale = true;
    }

    /** Fold again if a setter changed a folded force since the last fold: one flag read. */
    void refoldIfStale() {
        if (stale) {
            fold();
        }
    }

    /**
     * Tell whether the numbers are remembered for this step and mass.
     *
     * @param stepSeconds h (in seconds)
     * @param massKg m (in kilograms)
     * @return true if {@link #remember} was last called with them since the last fold
     */
    boolean isRememberedFor(float stepSeconds, float massKg) {
        return stepSeconds == rememberedSeconds && massKg == rememberedMass;
    }

    /**
     * Step one particle with the folded forces alone, from the numbers remembered for its
     * step and mass, and commit the result if it is finite.
     *
     * @param particle the particle (not null, modified only on success)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return true if stepped; false (particle untouched) if the scene has other forces, h or
     *     m are not the remembered ones, or the result is not finite: then the integrator's
     *     careful step decides
     */
    boolean step(Particle particle, float stepSeconds) {
        if (hasOthers || !isRememberedFor(stepSeconds, particle.getMass())) {
            return false;
        }
        Vector3f velocity = particle.velocity;
        Vector3f position = particle.position;
        float vx = velocity.x;
        float vy = velocity.y;
        float vz = velocity.z;
        float factor = speedDependent ? factor(speed(vx, vy, vz)) : stepFactor;
        // V' = (1 − h·σ)·V + h·g, then P' = P + h·V' with the new V
        vx = vx * factor + stepGravityX;
        vy = vy * factor + stepGravityY;
        vz = vz * factor + stepGravityZ;
        float px = position.x + stepSeconds * vx;
        float py = position.y + stepSeconds * vy;
        float pz = position.z + stepSeconds * vz;
        // P' = P + h·V' with h > 0 is finite only if V' is; a finite sum means three finite
        // terms
        if (Float.isFinite(px + py + pz)
                || Float.isFinite(px) && Float.isFinite(py) && Float.isFinite(pz)) {
            velocity.set(vx, vy, vz);
            position.set(px, py, pz);
            return true;
        }
        return false;
    }

    /**
     * The folded step with the other forces' acceleration added to g, unchecked:
     * {@code V' = (1 − h·σ)·V + h·(g + a_other)}, then {@code P' = P + h·V'}. The numbers for
     * h and the particle's mass must be remembered ({@link StepLimits#remember}).
     *
     * @param particle the particle (not null, not modified)
     * @param stepSeconds h (in seconds, &gt;0)
     * @param otherAcceleration a of the forces that are not folded (m/s², zero if none)
     * @param nextVelocity storage for V' (m/s, modified)
     * @param nextPosition storage for P' (m, modified)
     */
    void compute(Particle particle, float stepSeconds, Vector3f otherAcceleration,
            Vector3f nextVelocity, Vector3f nextPosition) {
        Vector3f velocity = particle.velocity;
        float vx = velocity.x;
        float vy = velocity.y;
        float vz = velocity.z;
        float factor = speedDependent ? factor(speed(vx, vy, vz)) : stepFactor;
        // g + 0 is g: without other forces this is the floats of step()
        float ax = gravityX + otherAcceleration.x;
        float ay = gravityY + otherAcceleration.y;
        float az = gravityZ + otherAcceleration.z;
        vx = vx * factor + stepSeconds * ax;
        vy = vy * factor + stepSeconds * ay;
        vz = vz * factor + stepSeconds * az;
        nextVelocity.set(vx, vy, vz);
        Vector3f position = particle.position;
        nextPosition.set(position.x + stepSeconds * vx, position.y + stepSeconds * vy,
                position.z + stepSeconds * vz);
    }

    /**
     * Remember what depends only on h, the mass and the folded forces (call through
     * {@link StepLimits#remember}, which remembers the regime's bound with it).
     *
     * @param stepSeconds h (in seconds)
     * @param massKg m (in kilograms)
     */
    void remember(float stepSeconds, float massKg) {
        stepInverseMass = inverseMass(massKg);
        stepGravityX = stepSeconds * gravityX;
        stepGravityY = stepSeconds * gravityY;
        stepGravityZ = stepSeconds * gravityZ;
        stepFactor = 1f - stepSeconds * (linearSum * stepInverseMass);
        stepQuadratic = stepSeconds * (quadraticSum * stepInverseMass);
        stepThrust = stepSeconds * (thrustSum * stepInverseMass);
        rememberedSeconds = stepSeconds;
        rememberedMass = massKg;
    }

    /**
     * The folded velocity factor {@code 1 − h·σ = (1 − h·b/m) − (h·c/m)·|V| + (h·k/m)/|V|}
     * for the remembered step and mass: the speed reaches it through one multiplication and
     * one division, as in a hand-written loop.
     *
     * @param speed |V| (in m/s; 0 if neither c nor k matters)
     * @return the factor (may be infinite where h·b/m overflows)
     */
    float factor(float speed) {
        // c = 0 gives no term even when |V|² overflowed to an infinite speed (0·∞ is NaN)
        float factor = quadraticSum == 0f ? stepFactor : stepFactor - stepQuadratic * speed;
        return thrustSum != 0f && speed >= Thrust.MIN_SPEED ? factor + stepThrust / speed
                : factor;
    }

    /**
     * The folded forces' drag rate {@code σ = (b + c·|V| − k/|V|)/m} in float, as the step
     * uses it (the thrust term only from {@link Thrust#MIN_SPEED} on).
     *
     * @param speed |V| (in m/s; 0 if neither c nor k matters)
     * @param inverseMass 1/m (in 1/kg)
     * @return σ (in 1/s)
     */
    float dragRate(float speed, float inverseMass) {
        // c = 0 gives no term even when |V|² overflowed to an infinite speed (0·∞ is NaN)
        float drag = quadraticSum == 0f ? linearSum : linearSum + quadraticSum * speed;
        // no division without thrust (k = 0 would subtract 0 anyway)
        float thrustPerSpeed = thrustSum != 0f && speed >= Thrust.MIN_SPEED
                ? thrustSum / speed : 0f;
        return (drag - thrustPerSpeed) * inverseMass;
    }

    /**
     * Return 1/m, remembered for the last mass asked for: most scenes step particles of one
     * mass, and a division per step and per rate is a good part of their cost.
     *
     * @param massKg m (in kilograms)
     * @return 1/m (in 1/kg)
     */
    float inverseMass(float massKg) {
        if (massKg != cachedMass) {
            cachedInverseMass = 1f / massKg;
            cachedMass = massKg;
        }
        return cachedInverseMass;
    }

    /**
     * |V| computed as {@link Vector3f#length()} does.
     *
     * @return the speed (in m/s)
     */
    static float speed(float vx, float vy, float vz) {
        return (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
    }

    /** Sum the built-in forces' coefficients, in the order the scene gave them. */
    private void fold() {
        gravityX = 0f;
        gravityY = 0f;
        gravityZ = 0f;
        for (int i = 0; i < gravities.length; ++i) {
            gravities[i].copyAcceleration(oneGravity);
            gravityX += oneGravity.x;
            gravityY += oneGravity.y;
            gravityZ += oneGravity.z;
        }
        linearSum = 0f;
        for (int i = 0; i < linearDrags.length; ++i) {
            linearSum += linearDrags[i].getCoefficient();
        }
        quadraticSum = 0f;
        for (int i = 0; i < quadraticDrags.length; ++i) {
            quadraticSum += quadraticDrags[i].getCoefficient();
        }
        thrustSum = 0f;
        for (int i = 0; i < thrusts.length; ++i) {
            thrustSum += thrusts[i].getMagnitude();
        }
        speedDependent = quadraticSum != 0f || thrustSum != 0f;
        // nothing remembered for the old coefficients holds: neither step nor regime bound
        rememberedSeconds = Float.NaN;
        stale = false;
    }

    /** Count the forces of one built-in type. */
    private static int count(Force[] forces, Class<? extends Force> type) {
        int n = 0;
        for (Force force : forces) {
            if (type.isInstance(force)) {
                ++n;
            }
        }
        return n;
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The fast form of the recipe's first line, {@code a = g + F/m} ({@link EulerRecipe}): the
 * built-in forces folded into four numbers, the summed gravity g, linear drag b, quadratic
 * drag c and thrust k. Their pushes all point along V, so {@code F/m = −σ·V} with
 * {@code σ = (b + c·|V| − k/|V|)/m} (the thrust term only from {@link Thrust#MIN_SPEED} on),
 * and a costs no call per force:
 * <pre>
 *   a = (g + a_other) − σ·V       a_other: the other forces, asked through the interface
 * </pre>
 * The fold speeds up the acceleration only: the update {@code V ← V + h·a},
 * {@code P ← P + h·V} is the recipe's ({@link EulerRecipe#step}). Against the force-by-force
 * sum ({@link EulerRecipe#accelerationOf}) a rounds differently by a few ulp
 * ({@code ParticleIntegratorFoldingTest}); gravity alone gives identical numbers.
 *
 * <p>The per-particle step ({@link #step}), {@link #acceleration} and the batch
 * ({@link PackedStep}) compute the same σ and a, so they give the same floats. The step
 * reads each particle's 1/m ({@link Particle#inverseMass}); the batch's numbers for one step
 * and mass are filled by {@link StepLimits#remember}, which keys the regime's bound on the
 * same h and m. A setter of a folded force marks this fold {@link #markStale stale}
 * ({@link FoldedForce}); the integrator folds again before its next step
 * ({@link #refoldIfStale}).
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
    /** Remembered for the batch's step and mass ({@link #isRememberedFor}): 1/m (1/kg) ... */
    float stepInverseMass;
    /** ... σ of the folded forces at rest, {@code dragRate(0, 1/m)}: b/m (1/s) ... */
    float stepLinearRate;
    /** ... and the velocity factor 1 − h·b/m of linear drag, for the batch's message. */
    float stepFactor;

    /** The scene's forces, in its order: asked one by one where the fold overflows. */
    private final Force[] forces;
    /** Those that are not folded, asked through the interface every step. */
    private final Force[] others;
    /** Scratch for {@link EulerRecipe#accelerationOf}: g (m/s²) ... */
    private final Vector3f field = new Vector3f();
    /** ... F (N) ... */
    private final Vector3f push = new Vector3f();
    /** ... and a of the other forces (m/s²). */
    private final Vector3f otherAcceleration = new Vector3f();

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
        this.forces = forces;
        others = others(forces);
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
     * One per-particle step: the recipe ({@link EulerRecipe#step}) with a computed here in
     * locals, {@code a = (g + a_other) − σ·V} as {@link #acceleration} computes it, with the
     * particle's 1/m ({@link Particle#inverseMass}, the floats of {@link #inverseMass}).
     *
     * @param particle the particle (not null, modified even where the result is not finite)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return true if the new position is finite; false if not (then the integrator puts the
     *     old state back and takes {@link #acceleration}, which asks every force where the
     *     fold overflows)
     */
    boolean step(Particle particle, float stepSeconds) {
        Vector3f velocity = particle.velocity;
        float vx = velocity.x;
        float vy = velocity.y;
        float vz = velocity.z;
        float ax = gravityX;
        float ay = gravityY;
        float az = gravityZ;
        if (hasOthers) {
            EulerRecipe.accelerationOf(others, particle, field, push, otherAcceleration);
            ax += otherAcceleration.x;
            ay += otherAcceleration.y;
            az += otherAcceleration.z;
        }
        // the particle's own 1/m: nothing remembered for one h and m, so a loop over particles
        // has no branch that calls out to remember them (a call on any path of a loop makes
        // the JIT read every field again per particle)
        float sigma = dragRate(speedDependent ? speed(vx, vy, vz) : 0f, particle.inverseMass());
        // F/m = −σ·V; σ = 0 adds nothing to a finite V, so skip it (gravity alone)
        if (sigma != 0f) {
            ax -= sigma * vx;
            ay -= sigma * vy;
            az -= sigma * vz;
        }
        return EulerRecipe.step(particle, ax, ay, az, stepSeconds);
    }

    /**
     * The acceleration every per-particle step uses, {@code a = g + F/m} of all the scene's
     * forces at the particle's state: the built-in ones folded, {@code a = (g + a_other) − σ·V}
     * with {@code σ = (b + c·|V| − k/|V|)/m} ({@link #dragRate}), the others asked through
     * the interface ({@link EulerRecipe#accelerationOf}); the same floats as {@link #step}
     * and the batch ({@link PackedStep}). Where the folded sum is not finite (b/m beyond the
     * float range for a particle at rest: ∞·0) it asks every force instead.
     *
     * @param particle the particle (not null, not modified)
     * @param storeResult storage for a (m/s², not null, modified)
     */
    void acceleration(Particle particle, Vector3f storeResult) {
        float ax = gravityX;
        float ay = gravityY;
        float az = gravityZ;
        if (hasOthers) {
            EulerRecipe.accelerationOf(others, particle, field, push, otherAcceleration);
            ax += otherAcceleration.x;
            ay += otherAcceleration.y;
            az += otherAcceleration.z;
        }
        Vector3f velocity = particle.velocity;
        float vx = velocity.x;
        float vy = velocity.y;
        float vz = velocity.z;
        float sigma = dragRate(speedDependent ? speed(vx, vy, vz) : 0f,
                inverseMass(particle.getMass()));
        // F/m = −σ·V, skipped for σ = 0 as in step()
        if (sigma != 0f) {
            ax -= sigma * vx;
            ay -= sigma * vy;
            az -= sigma * vz;
        }
        // a finite sum means three finite terms
        if (Float.isFinite(ax + ay + az)
                || Float.isFinite(ax) && Float.isFinite(ay) && Float.isFinite(az)) {
            storeResult.set(ax, ay, az);
        } else {
            EulerRecipe.accelerationOf(forces, particle, field, push, storeResult);
        }
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
        stepLinearRate = dragRate(0f, stepInverseMass);
        stepFactor = 1f - stepSeconds * stepLinearRate;
        rememberedSeconds = stepSeconds;
        rememberedMass = massKg;
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
        // nothing remembered for the old coefficients holds: neither the batch's numbers nor
        // the regime's bound
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

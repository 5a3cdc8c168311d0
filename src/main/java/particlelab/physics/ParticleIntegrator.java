package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The one Euler step every demo uses: the lecture's "simulation recipe".
 *
 * <pre>
 *   forces from the state at the start of the step:  a = g + F(P, V)/m
 *   velocity first:                                  V ← V + h·a
 *   then position, with the NEW velocity:            P ← P + h·V
 * </pre>
 *
 * This is the <b>semi-implicit (symplectic) Euler</b> method, first order in h. Forward
 * (explicit) Euler would move P with the old V instead; the order matters (a level shot lands
 * {@code vx·h} short here, {@code vx·h} long with forward Euler).
 *
 * <p><b>Folded forces.</b> The built-in forces are folded into a few numbers: the summed
 * gravity g, linear drag b, quadratic drag c and thrust k. Their pushes all point along V,
 * {@code F = −(b + c·|V| − k/|V|)·V}, so {@code F/m = −σ·V} with the drag rate
 * {@code σ = (b + c·|V| − k/|V|)/m} (the thrust term only while {@code |V| ≥}
 * {@link Thrust#MIN_SPEED}), and the recipe's velocity update becomes one formula without a
 * call per force:
 * <pre>
 *   V + h·a = V + h·(g − σ·V) = (1 − h·σ)·V + h·g
 * </pre>
 * Other forces (a {@link Spring}, a student's own {@link Force}) are asked through the
 * interface, only in scenes that have one, and add their acceleration to g. The folding is
 * redone at the next step whenever a setter changed a folded force, and h and 1/m are folded
 * in too, per step and mass: {@code 1 − h·σ = (1 − h·b/m) − (h·c/m)·|V| + (h·k/m)/|V|}. The
 * rearranged formula rounds differently from evaluating {@code g + F/m} force by force
 * ({@link #acceleration}): per step and component the two velocities differ by at most 24
 * roundings (2^-24 each) of
 * {@code |V|·(1 + h·σ⁺) + h·|g| + |V'|}, σ⁺ the drag rate with every term positive (about 3
 * measured, 1–2 ulp of the new velocity); gravity alone gives identical numbers.
 *
 * <p>An integrator holds the forces of one scene (or of one particle in a side-by-side scene)
 * and a few scratch vectors, so it is not thread-safe and {@link #step} allocates nothing.
 *
 * <p>Every method that takes an object refuses null with an {@link IllegalArgumentException}
 * naming the parameter; a step that would make a particle non-finite throws
 * {@link NonFiniteStepException}.
 */
public final class ParticleIntegrator {

    /**
     * How close (relatively) h·σ or h·λ may come to a limit before {@link #regime} checks it
     * with the quotients: float roundings differ by about 1e-7, so 1e-4 leaves no doubt.
     */
    private static final float LIMIT_MARGIN = 1e-4f;
    /**
     * Particles per block of the batch step with gravity and linear drag: their positions and
     * velocities (24 KB) stay in a core's first-level cache until their check has read them.
     */
    private static final int BATCH_BLOCK = 1024;
    /**
     * True if this JVM has the Vector API ({@code --add-modules jdk.incubator.vector}), which
     * {@link VectorBatch} needs; asked of the boot layer, so {@link VectorBatch} is not loaded.
     */
    private static final boolean VECTOR_API =
            ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();

    private final Force[] forces;
    private final Gravity[] gravities;
    private final LinearDrag[] linearDrags;
    private final QuadraticDrag[] quadraticDrags;
    private final Thrust[] thrusts;
    /** The built-in forces of the four arrays above, in the scene's order. */
    private final FoldedForce[] folded;
    /** The forces that are not folded: asked through the {@link Force} interface. */
    private final Force[] others;
    /** The sum of the folded forces' change counts when they were last folded. */
    private int foldedChanges;
    /** {@link FoldedForce#anyChangeCount()} when this integrator last looked. */
    private int seenAnyChanges = FoldedForce.anyChangeCount();
    /** Folded: the summed field acceleration g per axis (m/s²). */
    private float gravityX;
    private float gravityY;
    private float gravityZ;
    /** Folded: the summed linear drag b (kg/s). */
    private float linearSum;
    /** Folded: the summed quadratic drag c (kg/m). */
    private float quadraticSum;
    /** Folded: the summed thrust k (N). */
    private float thrustSum;
    /** Folded: true if σ depends on |V| (some c or k is not zero). */
    private boolean speedDependent;
    /** The mass whose inverse is {@link #cachedInverseMass} (kg; NaN: none yet). */
    private float cachedMass = Float.NaN;
    /** 1/{@link #cachedMass} (1/kg). */
    private float cachedInverseMass = Float.NaN;
    /**
     * Remembered for {@link #stepFolded}, for {@link #stepCacheSeconds} and
     * {@link #stepCacheMass}: h·g per axis (m/s) ...
     */
    private float stepGravityX;
    private float stepGravityY;
    private float stepGravityZ;
    /** ... 1/m (1/kg) ... */
    private float stepInverseMass;
    /** ... the velocity factor 1 − h·b/m of linear drag ... */
    private float stepFactor;
    /** ... h·c/m of quadratic drag (1/m) ... */
    private float stepQuadratic;
    /** ... h·k/m of thrust (m/s) ... */
    private float stepThrust;
    /** ... for this step (s; NaN: not known since the last fold) ... */
    private float stepCacheSeconds = Float.NaN;
    /** ... and this mass (kg). */
    private float stepCacheMass = Float.NaN;
    /**
     * Remembered for {@link #regime} with the numbers above, for the same step and mass: the
     * regime of a moving particle without speed-dependent forces ...
     */
    private StepRegime movingRegime = StepRegime.STABLE;
    /**
     * ... and the |V|² up to which every particle is {@link StepRegime#STABLE} (m²/s²;
     * infinite: at every speed; -1: none) ...
     */
    private float stableSpeedSquared = -1f;
    /** ... or true if without speed-dependent forces every particle is stable. */
    private boolean stableAtAnySpeed;
    /** Scratch: g of the other forces (m/s²). */
    private final Vector3f otherField = new Vector3f();
    /** Scratch: F of the other forces (N). */
    private final Vector3f otherForce = new Vector3f();
    /** Scratch: g, the sum of field accelerations (m/s²). */
    private final Vector3f fieldAcceleration = new Vector3f();
    /** Scratch: F, the sum of pushing forces (N). */
    private final Vector3f netForce = new Vector3f();
    /** Scratch: a = g + F/m (m/s²). */
    private final Vector3f acceleration = new Vector3f();
    /** Scratch: the velocity after the step (m/s), committed only if finite. */
    private final Vector3f nextVelocity = new Vector3f();
    /** Scratch: the position after the step (m), committed only if finite. */
    private final Vector3f nextPosition = new Vector3f();
    /** Scratch for {@link #dragRate}: a of the other forces at the particle's state (m/s²). */
    private final Vector3f movingAcceleration = new Vector3f();
    /** Scratch for {@link #dragRate}: a of the other forces at rest (m/s²). */
    private final Vector3f restingAcceleration = new Vector3f();
    /** Scratch for {@link #dragRate}: the particle at rest. */
    private final Particle restingScratch = new Particle();
    /** Scratch for {@link #regime}: a particle moving at 1 m/s along x, of the mass asked. */
    private final Particle movingScratch =
            new Particle(Vector3f.ZERO, Vector3f.UNIT_X, 1f);
    /** True if the batch step with gravity and linear drag runs on {@link VectorBatch}. */
    private boolean vectorBatch = VECTOR_API;
    /** Scratch for {@link #stepPacked}: the particle being stepped with other forces. */
    private final Particle packedParticle = new Particle();

    /**
     * Create an integrator for a scene's forces.
     *
     * @param forces the forces the scene models, only those (none means uniform motion; not
     *     null, no null elements; the array is copied, the forces are shared)
     */
    public ParticleIntegrator(Force... forces) {
        if (forces == null) {
            throw new IllegalArgumentException("forces must be an array, but was null");
        }
        for (int i = 0; i < forces.length; ++i) {
            if (forces[i] == null) {
                throw new IllegalArgumentException(
                        "forces[" + i + "] must be a force, but was null");
            }
        }
        this.forces = forces.clone();
        gravities = new Gravity[count(Gravity.class)];
        linearDrags = new LinearDrag[count(LinearDrag.class)];
        quadraticDrags = new QuadraticDrag[count(QuadraticDrag.class)];
        thrusts = new Thrust[count(Thrust.class)];
        folded = new FoldedForce[count(FoldedForce.class)];
        others = new Force[forces.length - folded.length];
        int gravity = 0;
        int linear = 0;
        int quadratic = 0;
        int thrust = 0;
        int other = 0;
        for (int i = 0; i < forces.length; ++i) {
            Force force = forces[i];
            if (force instanceof FoldedForce) {
                folded[gravity + linear + quadratic + thrust] = (FoldedForce) force;
            }
            if (force instanceof Gravity) {
                gravities[gravity++] = (Gravity) force;
            } else if (force instanceof LinearDrag) {
                linearDrags[linear++] = (LinearDrag) force;
            } else if (force instanceof QuadraticDrag) {
                quadraticDrags[quadratic++] = (QuadraticDrag) force;
            } else if (force instanceof Thrust) {
                thrusts[thrust++] = (Thrust) force;
            } else {
                others[other++] = force;
            }
        }
        fold();
    }

    /**
     * Advance one particle by one Euler step.
     *
     * @param particle the particle to move (not null, modified unless the step fails)
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0; 0 does nothing)
     * @throws NonFiniteStepException if the step would leave the particle with a NaN or
     *     infinite component (the step was far beyond the stability limit, the numbers
     *     overflowed the float range, or the particle was already non-finite): stop rather than
     *     spread NaN. The particle then keeps its state from before the step.
     */
    public void step(Particle particle, float stepSeconds) {
        Validate.notNull(particle, "particle");
        checkStep(stepSeconds);
        if (stepSeconds == 0f) {
            return;
        }
        foldIfChanged();
        stepFolded(particle, stepSeconds);
    }

    /**
     * Advance each of several particles by one Euler step, all under this integrator's forces.
     * A particle whose step fails keeps its state and stops the loop: the ones before it have
     * been stepped, the ones after it not.
     *
     * @param particles the particles to move (not null, elements not null and modified)
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0)
     * @throws NonFiniteStepException as {@link #step(Particle, float)}
     */
    public void step(Particle[] particles, float stepSeconds) {
        Validate.notNull(particles, "particles");
        checkStep(stepSeconds);
        for (int i = 0; i < particles.length; ++i) {
            if (particles[i] == null) {
                throw new IllegalArgumentException("particles[" + i + "] must not be null");
            }
        }
        if (stepSeconds == 0f) {
            return;
        }
        foldIfChanged();
        for (int i = 0; i < particles.length; ++i) {
            stepFolded(particles[i], stepSeconds);
        }
    }

    /**
     * Advance many particles of one mass, packed in two float arrays, by one Euler step each:
     * the batch form for scenes with many particles, the same recipe and the same arithmetic
     * as {@link #step(Particle, float)} without an object per particle, so its results are
     * identical to stepping each particle as an object of the same mass (only where the folded
     * step overflows the float range does the per-particle step try the force-by-force recipe
     * before refusing; the batch refuses).
     *
     * <p>Layout (structure of arrays, "planar"): with {@code n = count}, particle i has
     * {@code P = (positions[i], positions[n + i], positions[2n + i])} and V likewise in
     * velocities: all x, then all y, then all z.
     *
     * <p>Gravity and linear drag give every particle the same velocity factor
     * {@code 1 − h·b/m}, so the step is one simple pass per axis over adjacent floats that the
     * JIT turns into vector instructions, a block of particles at a time (or, in a JVM with
     * the Vector API, one pass per axis with the check fused in: {@link #setVectorBatch}).
     * Quadratic drag and thrust depend on each particle's speed: one pass over the particles.
     * Other forces ({@link Spring}, a student's own) are asked through the interface, one
     * particle at a time through a scratch particle. Allocates nothing.
     *
     * <p>Like {@link #step(Particle, float)} it refuses to spread NaN: it checks that every
     * particle is finite after the step (a position is finite only if the velocity that moved
     * it is), and otherwise it throws. It keeps no copy of the states (that would double the
     * cost of every step), so on that failure the arrays hold the result of the step for every
     * particle, the non-finite ones included: reset them before stepping again.
     *
     * @param positions P of every particle, planar (in metres, finite, length &ge; 3·count,
     *     modified)
     * @param velocities V of every particle, planar (in m/s, finite, length &ge; 3·count,
     *     modified)
     * @param count the number of particles (&ge;0)
     * @param massKg the mass of each particle (in kilograms, finite,
     *     &ge;{@link Particle#MIN_MASS_KG})
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0; 0 does nothing)
     * @throws NonFiniteStepException if after the step a particle has a NaN or infinite
     *     component (its state was already non-finite, the step was far beyond the stability
     *     limit, or the numbers overflowed the float range); the message names the first such
     *     particle and its state, and every particle has been stepped
     */
    public void stepPacked(float[] positions, float[] velocities, int count, float massKg,
            float stepSeconds) {
        checkPacked(positions, velocities, count);
        Particle.checkMass(massKg);
        checkStep(stepSeconds);
        if (stepSeconds == 0f || count == 0) {
            return;
        }
        foldIfChanged();
        if (stepSeconds != stepCacheSeconds || massKg != stepCacheMass) {
            rememberStep(stepSeconds, massKg);
        }
        float factor = Float.NaN;
        int bad;
        if (others.length > 0 || !Float.isFinite(stepFactor)) {
            // other forces, or h·b/m beyond the float range, which the recipe may survive
            bad = stepPackedOneByOne(positions, velocities, count, massKg, stepSeconds);
        } else if (speedDependent) {
            bad = stepPackedBySpeed(positions, velocities, count, stepSeconds);
        } else {
            // V ← (1 − h·σ)·V + h·g with σ = b/m, the same for every particle
            factor = stepFactor;
            bad = stepPackedByAxes(positions, velocities, count, stepSeconds);
        }
        if (bad >= 0) {
            throw packedFailure(positions, velocities, count, bad % count, stepSeconds,
                    factor < -1f ? factor : Float.NaN);
        }
    }

    /**
     * Tell whether this JVM can run the batch step on the Vector API: it was started with
     * {@code --add-modules jdk.incubator.vector} (an incubating JDK module, which makes the
     * JVM print a warning when it starts, so the app leaves it off unless asked: README,
     * "The Vector API, opt-in").
     *
     * @return true if {@link #setVectorBatch(boolean) setVectorBatch(true)} is allowed
     */
    public static boolean isVectorApiAvailable() {
        return VECTOR_API;
    }

    /**
     * Tell which code {@link #stepPacked} runs with gravity and linear drag (the only forces
     * it has two forms for; quadratic drag, thrust and other forces run one form).
     *
     * @return true: the Vector API, its finiteness check fused with the step; false: the
     *     scalar passes, which the JIT vectorises, and a separate check
     */
    public boolean isVectorBatch() {
        return vectorBatch;
    }

    /**
     * Choose the code {@link #stepPacked} runs with gravity and linear drag; both give
     * identical numbers and refuse the same non-finite results, so this only matters for
     * speed (the benchmarks time both). The default is the Vector API where this JVM has it.
     *
     * @param use true for the Vector API (only if {@link #isVectorApiAvailable()}), false for
     *     the scalar passes
     * @throws IllegalStateException if use is true and this JVM has no Vector API
     */
    public void setVectorBatch(boolean use) {
        if (use && !VECTOR_API) {
            throw new IllegalStateException("the batch step can use the Vector API only in a"
                    + " JVM started with --add-modules jdk.incubator.vector, and this one was"
                    + " not");
        }
        vectorBatch = use;
    }

    /**
     * Calculate the particle's acceleration {@code a = g + F/m} at its current state.
     *
     * @param particle the particle (not null, not modified)
     * @param storeResult storage for the result (in m/s², not null, modified)
     * @return storeResult
     */
    public Vector3f acceleration(Particle particle, Vector3f storeResult) {
        Validate.notNull(particle, "particle");
        Validate.notNull(storeResult, "storeResult");
        fieldAcceleration.zero();
        netForce.zero();
        for (int i = 0; i < forces.length; ++i) {
            forces[i].addFieldAcceleration(particle, fieldAcceleration);
            forces[i].addForce(particle, netForce);
        }
        // a = g + F/m
        return storeResult.set(fieldAcceleration)
                .scaleAdd(1f / particle.getMass(), netForce, storeResult);
    }

    /**
     * Return the total damping rate λ of the forces at the particle's state (see
     * {@link Force#dampingRate}).
     *
     * @param particle the particle (not null, not modified)
     * @return λ (in 1/s, finite, &ge;0; sums beyond the float range give the largest float)
     */
    public float dampingRate(Particle particle) {
        Validate.notNull(particle, "particle");
        foldIfChanged();
        return dampingRateAt(particle, quadraticSum == 0f ? 0f : particle.velocity.length());
    }

    /**
     * Return the total stiffness ω² of the forces at the particle's state (see
     * {@link Force#stiffness}).
     *
     * @param particle the particle (not null, not modified)
     * @return ω² (in 1/s², finite, &ge;0; sums beyond the float range give the largest float)
     */
    public float stiffness(Particle particle) {
        Validate.notNull(particle, "particle");
        // the folded forces do not depend on position: only the others can pull back
        double total = 0.0;
        for (int i = 0; i < others.length; ++i) {
            total += others[i].stiffness(particle);
        }
        return clampRate(total);
    }

    /**
     * Return the drag rate σ ("sigma") of the forces at the particle's state: how fast the
     * velocity-dependent forces slow the particle itself, so that through them one Euler step
     * scales the velocity by {@code 1 − σh}. It is the part of the acceleration that the
     * velocity adds, per unit of velocity, along V: {@code σ = −(a(V) − a(0))·V/|V|²}.
     * Linear drag gives {@code b/m} (equal to its λ), quadratic drag {@code c·|V|/m} (half its
     * λ), thrust {@code −k/(m·|V|)} (it speeds the particle up). The step reverses the velocity
     * once {@code σh > 1} and makes the speed grow once {@code σh > 2} (see {@link StepRegime}).
     * Allocates nothing.
     *
     * @param particle the particle (not null, not modified)
     * @return σ (in 1/s; 0 at rest; may be negative; the largest float when the forces
     *     overflow)
     */
    public float dragRate(Particle particle) {
        Validate.notNull(particle, "particle");
        foldIfChanged();
        return dragRateAt(particle, particle.velocity.length());
    }

    /**
     * Return the largest step for which the Euler step is stable at the particle's current
     * state: small changes of its motion die out rather than grow, so it can settle (at a
     * terminal velocity, at a spring's rest). With the forces' damping rate λ and stiffness
     * ω² this is {@link #stableStepLimit(double, double)}: {@code 2/λ} for drag alone (linear
     * drag {@code 2m/b}; quadratic drag {@code m/(c·|V|)}, which at the terminal speed
     * {@code v_t = sqrt(m·g/c)} is {@code v_t/g}), {@code 2/ω} for an undamped spring.
     *
     * @param particle the particle (not null, not modified)
     * @return the limit (in seconds, &gt;0; infinite when nothing damps or pulls back)
     */
    public float maxStableStep(Particle particle) {
        return (float) stableStepLimit(dampingRate(particle), stiffness(particle));
    }

    /**
     * Return the largest step for which the damping does not overshoot at the particle's
     * current state: {@code 1/λ}. Beyond it the step turns a small change of velocity into
     * one of the opposite sign: linear drag ({@code m/b}) reverses the velocity every step;
     * with quadratic drag ({@code m/(2c·|V|)}) the speed swings about its terminal value.
     *
     * @param particle the particle (not null, not modified)
     * @return the limit (in seconds, &gt;0; infinite when nothing damps)
     */
    public float maxMonotoneStep(Particle particle) {
        return 1f / dampingRate(particle);
    }

    /**
     * Tell what a step of h does at the particle's current state: the most serious of
     * {@link StepRegime}'s cases that applies (the drag rate σ for the motion itself, the
     * damping rate λ and stiffness ω² for small changes of it). Allocates nothing.
     *
     * @param particle the particle (not null, not modified)
     * @param stepSeconds h (in seconds, &ge;0)
     * @return the regime (not null)
     */
    public StepRegime regime(Particle particle, float stepSeconds) {
        Validate.notNull(particle, "particle");
        foldIfChanged();
        // This runs for every particle every step: what depends only on the step, the mass
        // and the folded forces is remembered (never with other forces), and the usual answer
        // is a few comparisons, kept here so that the JIT can inline them into the demo loop,
        // the same ones the step that follows makes.
        if (stepSeconds == stepCacheSeconds && particle.getMass() == stepCacheMass
                && (stableAtAnySpeed
                        || particle.velocity.lengthSquared() <= stableSpeedSquared)) {
            return StepRegime.STABLE;
        }
        return regimeOtherwise(particle, stepSeconds);
    }

    /** {@link #regime} where the remembered bound does not answer. */
    private StepRegime regimeOtherwise(Particle particle, float stepSeconds) {
        if (others.length > 0) {
            return regimeByLimits(particle, stepSeconds);
        }
        float massKg = particle.getMass();
        if (stepSeconds != stepCacheSeconds || massKg != stepCacheMass) {
            rememberStep(stepSeconds, massKg);
        }
        float speedSquared = particle.velocity.lengthSquared();
        if (stableAtAnySpeed || speedSquared <= stableSpeedSquared) {
            return StepRegime.STABLE;
        }
        if (speedDependent) {
            return regimeByProducts(particle, stepSeconds, speedSquared);
        }
        if (movingRegime == StepRegime.STABLE) {
            return StepRegime.STABLE;
        }
        return speedSquared == 0f ? regimeByProducts(particle, stepSeconds, 0f) : movingRegime;
    }

    /**
     * Return the stability limit of the semi-implicit Euler step for a damped oscillator
     * {@code x'' = −ω²·x − λ·x'}. One step maps (x, v) by a matrix of determinant
     * {@code 1 − λh} and trace {@code 2 − λh − ω²h²}; both eigenvalues lie inside the unit
     * circle (Jury's test) iff {@code λh < 2} and {@code ω²h² + 2λh < 4}, that is iff
     * {@code h < 4/(λ + sqrt(λ² + 4ω²))}. Without a spring this is {@code 2/λ}, without
     * damping {@code 2/ω} (there the step is marginally stable: it keeps a modified energy).
     * Computed in double without squaring λ, so nothing in between overflows.
     *
     * @param dampingRate λ (in 1/s, &ge;0, may be infinite)
     * @param stiffness ω² (in 1/s², &ge;0, may be infinite)
     * @return the limit (in seconds, &ge;0; infinite when both are 0)
     */
    public static double stableStepLimit(double dampingRate, double stiffness) {
        if (!(dampingRate >= 0.0) || !(stiffness >= 0.0)) {
            throw new IllegalArgumentException("damping rate lambda (1/s) and stiffness omega^2"
                    + " (1/s^2) must be >= 0, but were " + dampingRate + " and " + stiffness);
        }
        if (stiffness == 0.0) {
            // hypot(λ, 0) = λ: the same number, without hypot's cost (the usual scene)
            return 4.0 / (dampingRate + dampingRate);
        }
        // hypot: sqrt(λ² + 4ω²) without squaring λ, which would overflow for huge rates
        return 4.0 / (dampingRate + Math.hypot(dampingRate, 2.0 * Math.sqrt(stiffness)));
    }

    /**
     * Count the forces.
     *
     * @return the number of forces (&ge;0)
     */
    public int countForces() {
        return forces.length;
    }

    /**
     * Access a force.
     *
     * @param index which force (&ge;0, &lt;{@link #countForces()})
     * @return the live force
     */
    public Force getForce(int index) {
        return forces[index];
    }

    /**
     * Describe the forces, one equation each, for a HUD or a report.
     *
     * @return e.g. {@code "g = (0.0, -9.8, 0.0) m/s², F = -0.9·V"}, or "no force"
     */
    public String describe() {
        if (forces.length == 0) {
            return "no force";
        }
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < forces.length; ++i) {
            if (i > 0) {
                text.append(", ");
            }
            text.append(forces[i].describe());
        }
        return text.toString();
    }

    /** A rate as a float: at most the largest float, never infinite. */
    private static float clampRate(double rate) {
        return (float) Math.min(rate, Float.MAX_VALUE);
    }

    /**
     * {@link #regime} for the folded forces alone, first without a division: h·σ and h·λ
     * against 1 and 2 (with no spring the limits are 1/σ, 2/σ, 1/λ and 2/λ). Only near a
     * limit, where a rounding could tip it, do the quotients decide.
     */
    private StepRegime regimeByProducts(Particle particle, float stepSeconds,
            float speedSquared) {
        float speed = speedDependent ? (float) Math.sqrt(speedSquared) : 0f;
        float inverseMass = inverseMass(particle.getMass());
        float dampingH = stepSeconds * inverseMass
                * (quadraticSum == 0f ? linearSum : linearSum + 2f * quadraticSum * speed);
        float dragH = speedSquared == 0f ? 0f : stepSeconds * foldedDragRate(speed, inverseMass);
        if (isClearOfLimits(dampingH) && isClearOfLimits(dragH)) {
            return dragH > 2f ? StepRegime.GROWS
                    : dampingH > 2f ? StepRegime.UNSTABLE
                    : dragH > 1f ? StepRegime.REVERSES
                    : dampingH > 1f ? StepRegime.OVERSHOOTS
                    : StepRegime.STABLE;
        }
        return regimeByLimits(particle, stepSeconds);
    }

    /** {@link #regime} from the limits themselves: one speed and one λ for all three. */
    private StepRegime regimeByLimits(Particle particle, float stepSeconds) {
        float speed = particle.velocity.length();
        float lambda = dampingRateAt(particle, speed);
        float stable = (float) stableStepLimit(lambda, stiffness(particle));
        return StepRegime.of(stepSeconds, dragRateAt(particle, speed), stable, 1f / lambda);
    }

    /**
     * Remember for {@link #regime} what depends only on the step, the mass and the folded
     * forces. Gravity and linear drag: σ = λ = b/m for every moving particle, so one regime
     * for all of them; at rest σ = 0, which can only make it milder, so a stable step is
     * stable at every speed. Quadratic drag and thrust: λ = (b + 2c·|V|)/m grows with the
     * speed, and σ = (b + c·|V| − k/|V|)/m never exceeds it (c, k &ge; 0), so every particle
     * with {@code h·λ ≤ 1/2} is stable: that is {@code |V| ≤ (m/(2h) − b)/(2c)}. The float
     * arithmetic of {@link #regimeByProducts} rounds h·λ and h·σ by about ten roundings
     * (10·2^-24 relatively, and monotonically in |V|), far too little to take a value of 1/2
     * near the limit 1, so below that speed it answers {@link StepRegime#STABLE} too (provided
     * h·k/(m·{@link Thrust#MIN_SPEED}) is finite, so h·σ is).
     */
    private void rememberRegime(float stepSeconds, float massKg) {
        if (others.length > 0) {
            // other forces are asked every time
            stableAtAnySpeed = false;
            stableSpeedSquared = -1f;
            return;
        }
        movingScratch.setMass(massKg);
        movingRegime = speedDependent ? StepRegime.STABLE
                : regimeByProducts(movingScratch, stepSeconds, 1f);
        stableAtAnySpeed = !speedDependent && movingRegime == StepRegime.STABLE;
        if (!speedDependent) {
            stableSpeedSquared = -1f;
        } else {
            double stepPerMass = (double) stepSeconds / massKg;
            double halfLimit = 0.5 / stepPerMass - linearSum;
            double thrustH = stepPerMass * thrustSum / Thrust.MIN_SPEED;
            if (!(halfLimit >= 0.0) || !(thrustH < Float.MAX_VALUE)) {
                stableSpeedSquared = -1f;
            } else if (quadraticSum == 0f) {
                stableSpeedSquared = Float.POSITIVE_INFINITY;
            } else {
                double speed = halfLimit / (2.0 * quadraticSum);
                stableSpeedSquared = (float) Math.min(speed * speed, Float.MAX_VALUE);
            }
        }
    }

    /**
     * True if a product h·rate is finite and clear of the limits 1 and 2 by far more than
     * the few roundings in which it and the quotients 1/rate, 2/rate can differ.
     */
    private static boolean isClearOfLimits(float stepTimesRate) {
        return Float.isFinite(stepTimesRate)
                && Math.abs(stepTimesRate - 1f) > LIMIT_MARGIN
                && Math.abs(stepTimesRate - 2f) > 2f * LIMIT_MARGIN;
    }

    /** Count the forces of one built-in type. */
    private int count(Class<? extends Force> type) {
        int n = 0;
        for (int i = 0; i < forces.length; ++i) {
            if (type.isInstance(forces[i])) {
                ++n;
            }
        }
        return n;
    }

    /**
     * Fold again if a setter changed a folded force since the last fold: one load while no
     * folded force anywhere changed, this integrator's forces asked only after a change.
     */
    private void foldIfChanged() {
        int anyChanges = FoldedForce.anyChangeCount();
        if (anyChanges != seenAnyChanges) {
            seenAnyChanges = anyChanges;
            if (changeCount() != foldedChanges) {
                fold();
            }
        }
    }

    /** The sum of the folded forces' change counts: it changes whenever one of them does. */
    private int changeCount() {
        int changes = 0;
        for (int i = 0; i < folded.length; ++i) {
            changes += folded[i].changeCount();
        }
        return changes;
    }

    /** Sum the built-in forces' coefficients, in the order the scene gave them. */
    private void fold() {
        gravityX = 0f;
        gravityY = 0f;
        gravityZ = 0f;
        for (int i = 0; i < gravities.length; ++i) {
            gravities[i].copyAcceleration(otherField);
            gravityX += otherField.x;
            gravityY += otherField.y;
            gravityZ += otherField.z;
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
        stepCacheSeconds = Float.NaN;
        foldedChanges = changeCount();
    }

    /**
     * The folded forces' drag rate {@code σ = (b + c·|V| − k/|V|)/m}, in float as the step
     * uses it (the thrust term only from {@link Thrust#MIN_SPEED} on, as {@link Thrust}).
     *
     * @param speed |V| (in m/s; 0 if neither c nor k matters)
     * @param inverseMass 1/m (in 1/kg)
     */
    private float foldedDragRate(float speed, float inverseMass) {
        // c = 0 gives no term even when |V|² overflowed to an infinite speed (0·∞ is NaN)
        float drag = quadraticSum == 0f ? linearSum : linearSum + quadraticSum * speed;
        // no division without thrust (k = 0 would subtract 0 anyway)
        float thrustPerSpeed = thrustSum != 0f && speed >= Thrust.MIN_SPEED
                ? thrustSum / speed : 0f;
        return (drag - thrustPerSpeed) * inverseMass;
    }

    /** |V| computed as {@link Vector3f#length()} does. */
    private static float speed(float vx, float vy, float vz) {
        return (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
    }

    /** λ at the particle's state, its speed given: folded in double, plus the others'. */
    private float dampingRateAt(Particle particle, float speed) {
        // λ = b/m + 2c·|V|/m (thrust does not depend on small changes of V: 0)
        double rate = quadraticSum == 0f ? linearSum : linearSum + 2.0 * quadraticSum * speed;
        rate /= particle.getMass();
        for (int i = 0; i < others.length; ++i) {
            rate += others[i].dampingRate(particle);
        }
        return clampRate(rate);
    }

    /** σ at the particle's state, its speed given: folded in double, plus the others'. */
    private float dragRateAt(Particle particle, float speed) {
        if (speed == 0f) {
            return 0f;
        }
        double rate = quadraticSum == 0f ? linearSum : linearSum + (double) quadraticSum * speed;
        if (speed >= Thrust.MIN_SPEED) {
            rate -= (double) thrustSum / speed;
        }
        rate /= particle.getMass();
        if (others.length > 0) {
            // the others' share: −(a(V) − a(0))·V/|V|², a measured at V and at rest
            Vector3f velocity = particle.velocity;
            otherAcceleration(particle, movingAcceleration);
            restingScratch.copyFrom(particle);
            restingScratch.velocity.zero();
            otherAcceleration(restingScratch, restingAcceleration);
            movingAcceleration.subtractLocal(restingAcceleration);
            rate -= ((double) movingAcceleration.x * velocity.x
                    + (double) movingAcceleration.y * velocity.y
                    + (double) movingAcceleration.z * velocity.z) / ((double) speed * speed);
        }
        if (Double.isNaN(rate) || rate > Float.MAX_VALUE) {
            return Float.MAX_VALUE;
        }
        return (float) Math.max(rate, -Float.MAX_VALUE);
    }

    /** a = g + F/m of the forces that are not folded, through the interface. */
    private Vector3f otherAcceleration(Particle particle, Vector3f storeResult) {
        otherField.zero();
        otherForce.zero();
        for (int i = 0; i < others.length; ++i) {
            others[i].addFieldAcceleration(particle, otherField);
            others[i].addForce(particle, otherForce);
        }
        return storeResult.set(otherField)
                .scaleAdd(1f / particle.getMass(), otherForce, storeResult);
    }

    /**
     * Step one particle with the folded forces and commit the result if it is finite. If it
     * is not, the recipe decides, force by force: the folded factor {@code 1 − h·σ} can
     * overflow where {@code g + F/m} does not (b/m beyond the float range, a particle at
     * rest), and only a step that the recipe cannot take either is refused.
     */
    private void stepFolded(Particle particle, float stepSeconds) {
        if (others.length == 0) {
            // the usual scene: the arithmetic of computeFolded in locals, committed straight
            // from them (a round trip through scratch vectors would lengthen every step), with
            // what depends only on h, m and the forces remembered from the step before
            float massKg = particle.getMass();
            if (stepSeconds != stepCacheSeconds || massKg != stepCacheMass) {
                rememberStep(stepSeconds, massKg);
            }
            Vector3f velocity = particle.velocity;
            Vector3f position = particle.position;
            float vx = velocity.x;
            float vy = velocity.y;
            float vz = velocity.z;
            float factor = speedDependent ? foldedFactor(speed(vx, vy, vz)) : stepFactor;
            vx = vx * factor + stepGravityX;
            vy = vy * factor + stepGravityY;
            vz = vz * factor + stepGravityZ;
            float px = position.x + stepSeconds * vx;
            float py = position.y + stepSeconds * vy;
            float pz = position.z + stepSeconds * vz;
            // P' = P + h·V' with h > 0 is finite only if V' is; a finite sum means three
            // finite terms
            if (Float.isFinite(px + py + pz)
                    || Float.isFinite(px) && Float.isFinite(py) && Float.isFinite(pz)) {
                velocity.set(vx, vy, vz);
                position.set(px, py, pz);
                return;
            }
        }
        stepThroughScratch(particle, stepSeconds);
    }

    /**
     * Remember for {@link #stepFolded}, {@link #computeFolded} and the batch what depends only
     * on h, the mass and the folded forces, so all of them compute the same floats, and for
     * {@link #regime} its bound ({@link #rememberRegime}).
     */
    private void rememberStep(float stepSeconds, float massKg) {
        stepInverseMass = inverseMass(massKg);
        stepGravityX = stepSeconds * gravityX;
        stepGravityY = stepSeconds * gravityY;
        stepGravityZ = stepSeconds * gravityZ;
        stepFactor = 1f - stepSeconds * (linearSum * stepInverseMass);
        stepQuadratic = stepSeconds * (quadraticSum * stepInverseMass);
        stepThrust = stepSeconds * (thrustSum * stepInverseMass);
        rememberRegime(stepSeconds, massKg);
        stepCacheSeconds = stepSeconds;
        stepCacheMass = massKg;
    }

    /**
     * The folded velocity factor {@code 1 − h·σ = (1 − h·b/m) − (h·c/m)·|V| + (h·k/m)/|V|}
     * for the step and mass last remembered ({@link #rememberStep}): with h and m folded in,
     * the speed reaches the factor through one multiplication and one division, as in a
     * hand-written loop (the thrust term only from {@link Thrust#MIN_SPEED} on).
     *
     * @param speed |V| (in m/s; 0 if neither c nor k matters)
     */
    private float foldedFactor(float speed) {
        // c = 0 gives no term even when |V|² overflowed to an infinite speed (0·∞ is NaN)
        float factor = quadraticSum == 0f ? stepFactor : stepFactor - stepQuadratic * speed;
        return thrustSum != 0f && speed >= Thrust.MIN_SPEED ? factor + stepThrust / speed
                : factor;
    }

    /**
     * Step one particle through the scratch vectors: with other forces, or when the fast
     * path of {@link #stepFolded} found a non-finite result (kept apart so that the fast path
     * stays small enough for the JIT to inline).
     */
    private void stepThroughScratch(Particle particle, float stepSeconds) {
        computeFolded(particle, stepSeconds);
        if (!isNextFinite()) {
            computeRecipe(particle, stepSeconds);
            if (!isNextFinite()) {
                String why = particle.isFinite()
                        ? "; the largest stable step here is " + maxStableStep(particle) + " s"
                        : "; it was already non-finite before the step";
                throw new NonFiniteStepException("the Euler step h=" + stepSeconds
                        + " s would leave the particle non-finite: " + particle
                        + " would get P=" + nextPosition + ", V=" + nextVelocity + why);
            }
        }
        particle.velocity.set(nextVelocity);
        particle.position.set(nextPosition);
    }

    /**
     * Return 1/m, remembered for the last mass asked for: most scenes step particles of one
     * mass, and a division per step and per rate is a good part of their cost.
     */
    private float inverseMass(float massKg) {
        if (massKg != cachedMass) {
            cachedInverseMass = 1f / massKg;
            cachedMass = massKg;
        }
        return cachedInverseMass;
    }

    /** True if the computed step is finite: one test for the usual case. */
    private boolean isNextFinite() {
        // a finite sum means six finite terms
        return Float.isFinite(nextVelocity.x + nextVelocity.y + nextVelocity.z
                + nextPosition.x + nextPosition.y + nextPosition.z)
                || Validate.isFinite(nextVelocity) && Validate.isFinite(nextPosition);
    }

    /**
     * The recipe with the folded forces, into {@link #nextVelocity} and {@link #nextPosition},
     * unchecked: {@code V ← (1 − h·σ)·V + h·(g + a_other)}, then {@code P ← P + h·V}.
     */
    private void computeFolded(Particle particle, float stepSeconds) {
        Vector3f velocity = particle.velocity;
        float vx = velocity.x;
        float vy = velocity.y;
        float vz = velocity.z;
        float massKg = particle.getMass();
        if (stepSeconds != stepCacheSeconds || massKg != stepCacheMass) {
            rememberStep(stepSeconds, massKg);
        }
        // forces from the state at the start of the step: σ for the folded ones ...
        float factor = speedDependent ? foldedFactor(speed(vx, vy, vz)) : stepFactor;
        float ax = gravityX;
        float ay = gravityY;
        float az = gravityZ;
        if (others.length > 0) {
            // ... and g + F/m of the others, through the interface
            otherAcceleration(particle, acceleration);
            ax += acceleration.x;
            ay += acceleration.y;
            az += acceleration.z;
        }
        // velocity first, V + h·a = (1 − h·σ)·V + h·(g + a_other) ...
        vx = vx * factor + stepSeconds * ax;
        vy = vy * factor + stepSeconds * ay;
        vz = vz * factor + stepSeconds * az;
        nextVelocity.set(vx, vy, vz);
        // ... then the position, with the new velocity
        Vector3f position = particle.position;
        nextPosition.set(position.x + stepSeconds * vx, position.y + stepSeconds * vy,
                position.z + stepSeconds * vz);
    }

    /**
     * The recipe force by force, through the interface, into {@link #nextVelocity} and
     * {@link #nextPosition}, unchecked.
     */
    private void computeRecipe(Particle particle, float stepSeconds) {
        acceleration(particle, acceleration);
        Vector3f velocity = particle.velocity;
        Vector3f position = particle.position;
        // V ← V + h·a, then P ← P + h·V with the new V
        float vx = velocity.x + stepSeconds * acceleration.x;
        float vy = velocity.y + stepSeconds * acceleration.y;
        float vz = velocity.z + stepSeconds * acceleration.z;
        nextVelocity.set(vx, vy, vz);
        nextPosition.set(position.x + stepSeconds * vx, position.y + stepSeconds * vy,
                position.z + stepSeconds * vz);
    }

    /** One axis of gravity and linear drag: V ← r·V + h·g, then P ← P + h·V with the new V. */
    private static void stepAxis(float[] positions, float[] velocities, int start, int count,
            float factor, float stepGravity, float stepSeconds) {
        int end = start + count;
        for (int i = start; i < end; ++i) {
            float v = velocities[i] * factor + stepGravity;
            velocities[i] = v;
            positions[i] += stepSeconds * v;
        }
    }

    /**
     * The packed step with gravity and linear drag, {@value #BATCH_BLOCK} particles at a time,
     * in one of two forms:
     * <ul>
     * <li>scalar: each axis of the block in one pass, then the block's positions checked
     * while they are still in the cache (a position is finite only if the velocity that
     * moved it is);</li>
     * <li>on the Vector API ({@link #vectorBatch}): each axis of the block in one pass that
     * also sums the new positions ({@link VectorBatch#stepAxis}). Blocks rather than whole
     * axes here too: over a loop of more than a few thousand vectors the JIT boxes the
     * vector of sums now and then (2.3 kB per call measured at 10^5 particles on JDK 17),
     * and blocks of 1024 allocate nothing.</li>
     * </ul>
     *
     * @return the index of the first non-finite value, or -1
     */
    private int stepPackedByAxes(float[] positions, float[] velocities, int count,
            float stepSeconds) {
        float factor = stepFactor;
        boolean finite = true;
        for (int start = 0; start < count; start += BATCH_BLOCK) {
            int n = Math.min(BATCH_BLOCK, count - start);
            int y = count + start;
            int z = 2 * count + start;
            // & rather than &&: every block is stepped and checked whatever the one before
            // found, with no branch per axis
            if (vectorBatch) {
                finite &= VectorBatch.stepAxis(positions, velocities, start, n, factor,
                                stepGravityX, stepSeconds)
                        & VectorBatch.stepAxis(positions, velocities, y, n, factor,
                                stepGravityY, stepSeconds)
                        & VectorBatch.stepAxis(positions, velocities, z, n, factor,
                                stepGravityZ, stepSeconds);
            } else {
                stepAxis(positions, velocities, start, n, factor, stepGravityX, stepSeconds);
                stepAxis(positions, velocities, y, n, factor, stepGravityY, stepSeconds);
                stepAxis(positions, velocities, z, n, factor, stepGravityZ, stepSeconds);
                finite &= isSumFinite(positions, start, n) & isSumFinite(positions, y, n)
                        & isSumFinite(positions, z, n);
            }
        }
        return finite ? -1 : searchNonFinite(positions, 3 * count);
    }

    /**
     * The packed step when σ depends on the speed (quadratic drag, thrust): one pass over the
     * particles, the arithmetic of {@link #computeFolded}, and the finiteness check on the way:
     * the sum of the positions is finite only if every position is (a sum that overflows
     * although every position is finite only costs a search).
     *
     * @return the index of the first non-finite value, or -1
     */
    private int stepPackedBySpeed(float[] positions, float[] velocities, int count,
            float stepSeconds) {
        float gx = stepGravityX;
        float gy = stepGravityY;
        float gz = stepGravityZ;
        float check = 0f;
        for (int x = 0, y = count, z = 2 * count; x < count; ++x, ++y, ++z) {
            float vx = velocities[x];
            float vy = velocities[y];
            float vz = velocities[z];
            float factor = foldedFactor(speed(vx, vy, vz));
            vx = vx * factor + gx;
            vy = vy * factor + gy;
            vz = vz * factor + gz;
            velocities[x] = vx;
            velocities[y] = vy;
            velocities[z] = vz;
            float px = positions[x] + stepSeconds * vx;
            float py = positions[y] + stepSeconds * vy;
            float pz = positions[z] + stepSeconds * vz;
            positions[x] = px;
            positions[y] = py;
            positions[z] = pz;
            check += (px + py) + pz;
        }
        return Float.isFinite(check) ? -1 : searchNonFinite(positions, 3 * count);
    }

    /**
     * The packed step with forces that are not folded: every particle through a scratch
     * particle and {@link #computeFolded} (the recipe deciding where that overflows, as in
     * {@link #step(Particle, float)}), unchecked.
     *
     * @return the index of the first non-finite value, or -1
     */
    private int stepPackedOneByOne(float[] positions, float[] velocities, int count,
            float massKg, float stepSeconds) {
        Particle particle = packedParticle;
        particle.setMass(massKg);
        for (int i = 0; i < count; ++i) {
            int y = count + i;
            int z = 2 * count + i;
            particle.position.set(positions[i], positions[y], positions[z]);
            particle.velocity.set(velocities[i], velocities[y], velocities[z]);
            computeFolded(particle, stepSeconds);
            if (!isNextFinite()) {
                computeRecipe(particle, stepSeconds);
            }
            positions[i] = nextPosition.x;
            positions[y] = nextPosition.y;
            positions[z] = nextPosition.z;
            velocities[i] = nextVelocity.x;
            velocities[y] = nextVelocity.y;
            velocities[z] = nextVelocity.z;
        }
        return firstNonFinite(positions, 3 * count);
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
    private static boolean isSumFinite(float[] values, int start, int length) {
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

    /** The index of the first non-finite value, or -1 if a full check finds none. */
    private static int firstNonFinite(float[] values, int length) {
        return isSumFinite(values, 0, length) ? -1 : searchNonFinite(values, length);
    }

    /** The index of the first non-finite value, or -1. */
    private static int searchNonFinite(float[] values, int length) {
        for (int j = 0; j < length; ++j) {
            if (!Float.isFinite(values[j])) {
                return j;
            }
        }
        return -1;
    }

    private static NonFiniteStepException packedFailure(float[] positions, float[] velocities,
            int count, int particle, float stepSeconds, float unstableFactor) {
        int y = count + particle;
        int z = 2 * count + particle;
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

    private static void checkPacked(float[] positions, float[] velocities, int count) {
        if (count < 0) {
            throw new IllegalArgumentException("particle count must be >= 0, but was " + count);
        }
        long needed = 3L * count;
        if (positions == null || positions.length < needed) {
            throw new IllegalArgumentException("positions must hold 3*count = " + needed
                    + " floats, but " + (positions == null ? "was null"
                    : "held " + positions.length));
        }
        if (velocities == null || velocities.length < needed) {
            throw new IllegalArgumentException("velocities must hold 3*count = " + needed
                    + " floats, but " + (velocities == null ? "was null"
                    : "held " + velocities.length));
        }
    }

    private static void checkStep(float stepSeconds) {
        if (!(stepSeconds >= 0f) || stepSeconds == Float.POSITIVE_INFINITY) {
            throw new IllegalArgumentException(
                    "step h (s) must be finite and >= 0, but was " + stepSeconds);
        }
    }
}

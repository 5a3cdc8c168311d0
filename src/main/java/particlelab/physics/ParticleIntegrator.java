package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The one Euler step every demo uses: the lecture's "simulation recipe".
 *
 * <pre>
 *   forces from the state at the start of the step:  a = g + F(P, V)/m
 *   velocity first:                                  V ← V + h·a
 *   then position, with the NEW velocity:            P ← P + h·V
 *   refuse a non-finite result rather than spread NaN
 * </pre>
 *
 * This is the <b>semi-implicit (symplectic) Euler</b> method, first order in h. Forward
 * (explicit) Euler would move P with the old V instead; the order matters (a level shot lands
 * {@code vx·h} short here, {@code vx·h} long with forward Euler). The recipe as code:
 * {@link #acceleration} and {@link #computeRecipe}.
 *
 * <p><b>The rule: the lecture's code is the reference.</b> A faster form lives in its own
 * package-private class, named for its one job, and a test proves it equal to the recipe
 * ({@code ParticleIntegratorFoldingTest}, {@code FastPathsMatchTheRecipeTest}):
 * <ul>
 * <li>{@link FoldedForces}: gravity, linear and quadratic drag and thrust folded into four
 * numbers g, b, c, k, so the step is {@code V ← (1 − h·σ)·V + h·g} with no call per force.
 * Per step and component its velocity differs from the recipe's by at most 24 roundings
 * (2^-24 each) of {@code |V|·(1 + h·σ⁺) + h·|g| + |V'|}, σ⁺ the drag rate with every term
 * positive (about 3 measured, 1–2 ulp of V'); gravity alone gives identical numbers. Other
 * forces ({@link Spring}, a student's own) are asked through the interface.</li>
 * <li>{@link PackedStep} (with {@link VectorBatch}): the batch {@link #stepPacked}, bit for
 * bit the per-particle step.</li>
 * <li>{@link StepLimits}: the rates, limits and {@link #regime}, with its remembered bound.</li>
 * </ul>
 * A setter of a folded force marks the folds of the integrators that hold it stale
 * ({@link FoldedForce}); each integrator reads that one flag of its own before a step and
 * folds again: no state is shared between integrators.
 *
 * <p>An integrator holds the forces of one scene and a few scratch vectors: not thread-safe,
 * and {@link #step} allocates nothing. A null argument is refused with an
 * {@link IllegalArgumentException} naming it; a step that would make a particle non-finite
 * throws {@link NonFiniteStepException}.
 */
public final class ParticleIntegrator {

    /** The forces of the scene, in its order ... */
    private final Force[] forces;
    /** ... those that are not folded, asked through the interface ... */
    private final Force[] others;
    /** ... and the built-in ones folded: the fast form of the step. */
    private final FoldedForces folded;
    /** The rates, limits and regime. */
    private final StepLimits limits;
    /** The batch form. */
    private final PackedStep packed;
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
        folded = new FoldedForces(this.forces);
        others = FoldedForces.others(this.forces);
        limits = new StepLimits(folded, others);
        packed = new PackedStep(folded, this);
    }

    /**
     * Advance one particle by one Euler step.
     *
     * @param particle the particle to move (not null, modified unless the step fails)
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0; 0 does nothing)
     * @throws NonFiniteStepException if the step would leave the particle with a NaN or
     *     infinite component (far beyond the stability limit, beyond the float range, or
     *     non-finite already): stop rather than spread NaN; the particle keeps its state
     */
    public void step(Particle particle, float stepSeconds) {
        Validate.notNull(particle, "particle");
        Validate.nonNegative(stepSeconds, "step h (s)");
        if (stepSeconds == 0f) {
            return;
        }
        // the recipe in its fast form (FoldedForces); where that declines, the careful step:
        // with the other forces, the recipe itself where the fast form overflows, the guard
        folded.refoldIfStale();
        if (!folded.step(particle, stepSeconds)) {
            stepCarefully(particle, stepSeconds);
        }
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
        Validate.nonNegative(stepSeconds, "step h (s)");
        for (int i = 0; i < particles.length; ++i) {
            if (particles[i] == null) {
                throw new IllegalArgumentException("particles[" + i + "] must not be null");
            }
        }
        if (stepSeconds == 0f) {
            return;
        }
        folded.refoldIfStale();
        for (int i = 0; i < particles.length; ++i) {
            if (!folded.step(particles[i], stepSeconds)) {
                stepCarefully(particles[i], stepSeconds);
            }
        }
    }

    /**
     * Advance many particles of one mass, packed in two float arrays, by one Euler step each
     * ({@link PackedStep}): identical floats to stepping each as an object of that mass (only
     * where the folded step overflows does the per-particle step try the force-by-force recipe
     * before refusing; the batch refuses). Allocates nothing. Layout ("planar"): with
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

    /**
     * Calculate the particle's acceleration {@code a = g + F/m} at its current state, asking
     * every force: the recipe's first line.
     *
     * @param particle the particle (not null, not modified)
     * @param storeResult storage for the result (in m/s², not null, modified)
     * @return storeResult
     */
    public Vector3f acceleration(Particle particle, Vector3f storeResult) {
        Validate.notNull(particle, "particle");
        Validate.notNull(storeResult, "storeResult");
        return accelerationOf(forces, particle, fieldAcceleration, netForce, storeResult);
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
        folded.refoldIfStale();
        return limits.dampingRate(particle);
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
        return limits.stiffness(particle);
    }

    /**
     * Return the drag rate σ of the forces at the particle's state: one Euler step scales the
     * velocity by {@code 1 − σh} through them, {@code σ = −(a(V) − a(0))·V/|V|²}. Linear drag
     * gives {@code b/m} (its λ), quadratic drag {@code c·|V|/m} (half its λ), thrust
     * {@code −k/(m·|V|)}. The step reverses the velocity once {@code σh > 1} and makes the
     * speed grow once {@code σh > 2} ({@link StepRegime}). Allocates nothing.
     *
     * @param particle the particle (not null, not modified)
     * @return σ (in 1/s; 0 at rest; may be negative; the largest float if the forces overflow)
     */
    public float dragRate(Particle particle) {
        Validate.notNull(particle, "particle");
        folded.refoldIfStale();
        return limits.dragRate(particle);
    }

    /**
     * Return the largest step for which the Euler step is stable at the particle's current
     * state: small changes of its motion die out rather than grow, so it can settle. With the
     * forces' λ and ω² this is {@link #stableStepLimit(double, double)}: {@code 2/λ} for drag
     * alone (linear drag {@code 2m/b}; quadratic drag {@code m/(c·|V|)}, at the terminal speed
     * {@code v_t = sqrt(m·g/c)} that is {@code v_t/g}), {@code 2/ω} for an undamped spring.
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
     * {@link StepRegime}'s cases that applies (σ for the motion, λ and ω² for small changes of
     * it). The demos ask for every particle every step; allocates nothing.
     *
     * @param particle the particle (not null, not modified)
     * @param stepSeconds h (in seconds, &ge;0)
     * @return the regime (not null)
     */
    public StepRegime regime(Particle particle, float stepSeconds) {
        Validate.notNull(particle, "particle");
        folded.refoldIfStale();
        // the usual answer: a bound remembered with the step's numbers, under their h and m,
        // so that in a demo's loop the JIT merges these checks with the step's
        if (folded.isRememberedFor(stepSeconds, particle.getMass())
                && limits.isStableBelowTheBound(particle)) {
            return StepRegime.STABLE;
        }
        return limits.regime(particle, stepSeconds);
    }

    /**
     * Return the stability limit of the semi-implicit Euler step for a damped oscillator
     * {@code x'' = −ω²·x − λ·x'}: {@code h < 4/(λ + sqrt(λ² + 4ω²))} (derived in
     * {@link StepLimits#stableStepLimit}); {@code 2/λ} without a spring, {@code 2/ω} without
     * damping (there the step is marginally stable: it keeps a modified energy).
     *
     * @param dampingRate λ (in 1/s, &ge;0, may be infinite)
     * @param stiffness ω² (in 1/s², &ge;0, may be infinite)
     * @return the limit (in seconds, &ge;0; infinite when both are 0)
     */
    public static double stableStepLimit(double dampingRate, double stiffness) {
        return StepLimits.stableStepLimit(dampingRate, stiffness);
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
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < forces.length; ++i) {
            text.append(i > 0 ? ", " : "").append(forces[i].describe());
        }
        return forces.length == 0 ? "no force" : text.toString();
    }

    /**
     * One step of a particle (not modified) into V' and P' (m/s, m; modified), unchecked: the
     * folded form with the other forces' acceleration ({@link FoldedForces#compute}), and
     * where that is not finite the recipe. h and m must be remembered ({@link StepLimits}).
     */
    void computeStep(Particle particle, float stepSeconds, Vector3f nextVelocity,
            Vector3f nextPosition) {
        accelerationOf(others, particle, fieldAcceleration, netForce, acceleration);
        folded.compute(particle, stepSeconds, acceleration, nextVelocity, nextPosition);
        if (!(Validate.isFinite(nextVelocity) && Validate.isFinite(nextPosition))) {
            // the folded factor 1 − h·σ can overflow where g + F/m does not (b/m beyond the
            // float range, a particle at rest)
            computeRecipe(particle, stepSeconds, nextVelocity, nextPosition);
        }
    }

    /**
     * Sum {@code a = g + F/m} (m/s²) over some forces into storeResult, with scratch vectors
     * for g and F; return storeResult.
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
     * The lecture's recipe, force by force, unchecked: {@code a = g + F/m},
     * {@code V' = V + h·a}, then {@code P' = P + h·V'} with the new velocity.
     */
    private void computeRecipe(Particle particle, float stepSeconds, Vector3f nextVelocity,
            Vector3f nextPosition) {
        Vector3f a = acceleration(particle, acceleration);
        Vector3f velocity = particle.velocity;
        Vector3f position = particle.position;
        float vx = velocity.x + stepSeconds * a.x;
        float vy = velocity.y + stepSeconds * a.y;
        float vz = velocity.z + stepSeconds * a.z;
        nextVelocity.set(vx, vy, vz);
        nextPosition.set(position.x + stepSeconds * vx, position.y + stepSeconds * vy,
                position.z + stepSeconds * vz);
    }

    /**
     * The step where the fast form declined (other forces, a new h or m, a non-finite
     * result): {@link #computeStep}, then the guard: commit only a finite result.
     */
    private void stepCarefully(Particle particle, float stepSeconds) {
        limits.remember(stepSeconds, particle.getMass());
        computeStep(particle, stepSeconds, nextVelocity, nextPosition);
        if (!(Validate.isFinite(nextVelocity) && Validate.isFinite(nextPosition))) {
            String why = particle.isFinite()
                    ? "; the largest stable step here is " + maxStableStep(particle) + " s"
                    : "; it was already non-finite before the step";
            throw new NonFiniteStepException("the Euler step h=" + stepSeconds
                    + " s would leave the particle non-finite: " + particle
                    + " would get P=" + nextPosition + ", V=" + nextVelocity + why);
        }
        particle.velocity.set(nextVelocity);
        particle.position.set(nextPosition);
    }
}

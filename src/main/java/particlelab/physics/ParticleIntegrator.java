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
 * {@code vx·h} short here, {@code vx·h} long with forward Euler).
 *
 * <p><b>The recipe is the code that runs.</b> The two update lines are
 * {@link EulerRecipe#step}, and every per-particle step runs them ({@link #step}); the batch
 * ({@link PackedStep}) runs the same arithmetic in loops, bit for bit. Only the first line has
 * a fast form: {@link FoldedForces} folds gravity, linear and quadratic drag and thrust into
 * four numbers, so {@code a = g − σ·V} costs no call per force; other forces ({@link Spring},
 * a student's own) are asked through the interface ({@link EulerRecipe#accelerationOf}).
 * {@link #acceleration} returns the a the step uses, so {@code EulerRecipeTest} can check
 * every step against {@code V + h·a}, {@code P + h·V'} computed in the test. The rates,
 * limits and {@link #regime} are {@link StepLimits}'s. A setter of a folded force marks the
 * folds of the integrators that hold it stale ({@link FoldedForce}); each integrator reads
 * that one flag of its own before a step and folds again: no state is shared between
 * integrators.
 *
 * <p>An integrator holds the forces of one scene and a few scratch vectors: not thread-safe,
 * and {@link #step} allocates nothing. A null argument is refused with an
 * {@link IllegalArgumentException} naming it; a step that would make a particle non-finite
 * throws {@link NonFiniteStepException}.
 */
public final class ParticleIntegrator {

    /** The forces of the scene, in its order ... */
    private final Force[] forces;
    /** ... and the built-in ones folded: the fast form of the acceleration. */
    private final FoldedForces folded;
    /** The rates, limits and regime. */
    private final StepLimits limits;
    /** The batch form. */
    private final ParticleBatch batch;
    /** Scratch: a = g + F/m (m/s²). */
    private final Vector3f acceleration = new Vector3f();
    /** Scratch for {@link #stepCarefully}: the velocity before the step (m/s) ... */
    private final Vector3f oldVelocity = new Vector3f();
    /** ... and the position (m), put back if the step is not finite. */
    private final Vector3f oldPosition = new Vector3f();

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
        limits = new StepLimits(folded, FoldedForces.others(this.forces));
        batch = new ParticleBatch(folded, limits);
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
        folded.refoldIfStale();
        stepOne(particle, stepSeconds);
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
            stepOne(particles[i], stepSeconds);
        }
    }

    /**
     * Access the batch form of this integrator's step: many particles of one mass in planar
     * float arrays, the same floats as {@link #step(Particle, float)} each.
     *
     * @return the batch (not null, live, shares the forces and the fold)
     */
    public ParticleBatch batch() {
        return batch;
    }

    /**
     * Calculate the particle's acceleration {@code a = g + F/m} at its current state: the
     * recipe's first line, the very floats {@link #step(Particle, float)} moves it with (the
     * built-in forces folded, {@link FoldedForces#acceleration}; the others asked).
     *
     * @param particle the particle (not null, not modified)
     * @param storeResult storage for the result (in m/s², not null, modified)
     * @return storeResult
     */
    public Vector3f acceleration(Particle particle, Vector3f storeResult) {
        Validate.notNull(particle, "particle");
        Validate.notNull(storeResult, "storeResult");
        folded.refoldIfStale();
        folded.acceleration(particle, storeResult);
        return storeResult;
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
     * One step of a particle: the recipe ({@link EulerRecipe#step}) with the folded
     * acceleration ({@link FoldedForces#step}); where the new state is not finite, the old one
     * is put back and {@link #stepCarefully} decides.
     */
    private void stepOne(Particle particle, float stepSeconds) {
        // nothing remembered for h and m: the fold reads the particle's 1/m, so no path of the
        // step calls out (regime() remembers its bound for itself)
        Vector3f velocity = particle.velocity;
        Vector3f position = particle.position;
        float vx = velocity.x;
        float vy = velocity.y;
        float vz = velocity.z;
        float px = position.x;
        float py = position.y;
        float pz = position.z;
        if (!folded.step(particle, stepSeconds)) {
            velocity.set(vx, vy, vz);
            position.set(px, py, pz);
            stepCarefully(particle, stepSeconds);
        }
    }

    /**
     * The step where the folded one was not finite: the recipe again with
     * {@link #acceleration}, which asks every force where the fold overflows; a result that is
     * still not finite is refused, the particle keeping its state.
     */
    private void stepCarefully(Particle particle, float stepSeconds) {
        oldVelocity.set(particle.velocity);
        oldPosition.set(particle.position);
        folded.acceleration(particle, acceleration);
        if (!EulerRecipe.step(particle, acceleration.x, acceleration.y, acceleration.z,
                stepSeconds)) {
            String bad = "P=" + particle.position + ", V=" + particle.velocity;
            particle.velocity.set(oldVelocity);
            particle.position.set(oldPosition);
            String why = particle.isFinite()
                    ? "; the largest stable step here is " + maxStableStep(particle) + " s"
                    : "; it was already non-finite before the step";
            throw new NonFiniteStepException("the Euler step h=" + stepSeconds
                    + " s would leave the particle non-finite: " + particle
                    + " would get " + bad + why);
        }
    }
}

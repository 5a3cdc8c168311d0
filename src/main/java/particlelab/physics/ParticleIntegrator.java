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
 * <p>An integrator holds the forces of one scene (or of one particle in a side-by-side scene)
 * and a few scratch vectors, so it is not thread-safe and {@link #step} allocates nothing.
 *
 * <p>Every method that takes an object refuses null with an {@link IllegalArgumentException}
 * naming the parameter; a step that would make a particle non-finite throws
 * {@link NonFiniteStepException}.
 */
public final class ParticleIntegrator {

    private final Force[] forces;
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
    /** Scratch for {@link #dragRate}: a at the particle's state (m/s²). */
    private final Vector3f movingAcceleration = new Vector3f();
    /** Scratch for {@link #dragRate}: a at the same position at rest (m/s²). */
    private final Vector3f restingAcceleration = new Vector3f();
    /** Scratch for {@link #dragRate}: the particle at rest. */
    private final Particle restingScratch = new Particle();
    /** Scratch for {@link #stepPacked}: one gravity's g (m/s²). */
    private final Vector3f packedGravity = new Vector3f();
    /** Scratch for {@link #stepPacked}: g per axis (m/s²). */
    private final float[] packedFieldAcceleration = new float[3];
    /** Scratch for {@link #stepPacked}: the particle being stepped on the general path. */
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
        computeStep(particle, stepSeconds);
        // One test for the usual case: a finite sum means six finite terms.
        if (!Float.isFinite(nextVelocity.x + nextVelocity.y + nextVelocity.z
                + nextPosition.x + nextPosition.y + nextPosition.z)
                && (!Validate.isFinite(nextVelocity) || !Validate.isFinite(nextPosition))) {
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

    /**
     * Advance each of several particles by one Euler step, all under this integrator's forces.
     *
     * @param particles the particles to move (not null, elements not null and modified)
     * @param stepSeconds h, the step duration (in seconds, finite, &ge;0)
     */
    public void step(Particle[] particles, float stepSeconds) {
        Validate.notNull(particles, "particles");
        for (int i = 0; i < particles.length; ++i) {
            if (particles[i] == null) {
                throw new IllegalArgumentException("particles[" + i + "] must not be null");
            }
            step(particles[i], stepSeconds);
        }
    }

    /**
     * Advance many particles of one mass, packed in two float arrays, by one Euler step each:
     * the batch form for scenes with many particles, the same recipe as
     * {@link #step(Particle, float)} without an object per particle.
     *
     * <p>Layout (structure of arrays, "planar"): with {@code n = count}, particle i has
     * {@code P = (positions[i], positions[n + i], positions[2n + i])} and V likewise in
     * velocities: all x, then all y, then all z. One axis at a time, each loop is a simple
     * pass over adjacent floats that the JIT turns into vector instructions.
     *
     * <p>When the forces are only {@link Gravity} and {@link LinearDrag} (the usual scene),
     * they fold into two numbers per step, {@code r = 1 − h·b/m} and {@code h·g}, and the step
     * is {@code V ← r·V + h·g}, {@code P ← P + h·V}: the same arithmetic as the per-particle
     * step, rearranged, so results agree to float rounding (a few ulp per step). Any other
     * force is applied through a scratch particle, one particle at a time, with results
     * identical to {@link #step(Particle, float)}. Allocates nothing.
     *
     * <p>Like {@link #step(Particle, float)} it refuses to spread NaN: after the step one pass
     * over the positions checks that every particle is finite (a position is finite only if
     * the velocity that moved it is), and otherwise it throws. It keeps no copy of the states
     * (that would double the cost of every step), so on that failure the arrays hold the
     * result of the step for every particle, the non-finite ones included: reset them before
     * stepping again.
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
        float[] g = packedFieldAcceleration;
        g[0] = 0f;
        g[1] = 0f;
        g[2] = 0f;
        float linearDrag = 0f;
        boolean onlyGravityAndLinearDrag = true;
        for (int i = 0; i < forces.length; ++i) {
            Force force = forces[i];
            if (force instanceof Gravity) {
                ((Gravity) force).copyAcceleration(packedGravity);
                g[0] += packedGravity.x;
                g[1] += packedGravity.y;
                g[2] += packedGravity.z;
            } else if (force instanceof LinearDrag) {
                linearDrag += ((LinearDrag) force).getCoefficient();
            } else {
                onlyGravityAndLinearDrag = false;
            }
        }
        // a = g − (b/m)·V, so V + h·a = r·V + h·g with r = 1 − h·b/m
        float factor = 1f - stepSeconds * linearDrag * (1f / massKg);
        if (onlyGravityAndLinearDrag) {
            for (int axis = 0; axis < 3; ++axis) {
                stepAxis(positions, velocities, axis * count, count, factor,
                        stepSeconds * g[axis], stepSeconds);
            }
        } else {
            stepPackedOneByOne(positions, velocities, count, massKg, stepSeconds);
        }
        int bad = firstNonFinite(positions, 3 * count);
        if (bad >= 0) {
            throw packedFailure(positions, velocities, count, bad % count, stepSeconds,
                    onlyGravityAndLinearDrag && factor < -1f ? factor : Float.NaN);
        }
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
        double rate = 0.0;
        for (int i = 0; i < forces.length; ++i) {
            rate += forces[i].dampingRate(particle);
        }
        return clampRate(rate);
    }

    /**
     * Return the total stiffness ω² of the forces at the particle's state (see
     * {@link Force#stiffness}).
     *
     * @param particle the particle (not null, not modified)
     * @return ω² (in 1/s², finite, &ge;0; sums beyond the float range give the largest float)
     */
    public float stiffness(Particle particle) {
        double total = 0.0;
        for (int i = 0; i < forces.length; ++i) {
            total += forces[i].stiffness(particle);
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
        Vector3f velocity = particle.velocity;
        float speedSquared = velocity.lengthSquared();
        if (speedSquared == 0f) {
            return 0f;
        }
        acceleration(particle, movingAcceleration);
        restingScratch.copyFrom(particle);
        restingScratch.velocity.zero();
        acceleration(restingScratch, restingAcceleration);
        movingAcceleration.subtractLocal(restingAcceleration);
        double rate = -((double) movingAcceleration.x * velocity.x
                + (double) movingAcceleration.y * velocity.y
                + (double) movingAcceleration.z * velocity.z) / speedSquared;
        if (Double.isNaN(rate) || rate > Float.MAX_VALUE) {
            return Float.MAX_VALUE;
        }
        return (float) Math.max(rate, -Float.MAX_VALUE);
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
        return StepRegime.of(stepSeconds, dragRate(particle), maxStableStep(particle),
                maxMonotoneStep(particle));
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

    /** One axis of the folded step: V ← r·V + h·g, then P ← P + h·V with the new V. */
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
     * Compute one Euler step of a particle into {@link #nextVelocity} and
     * {@link #nextPosition}, without checking or committing it.
     */
    private void computeStep(Particle particle, float stepSeconds) {
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

    /** The general packed path: every particle through {@link #computeStep}, unchecked. */
    private void stepPackedOneByOne(float[] positions, float[] velocities, int count,
            float massKg, float stepSeconds) {
        Particle particle = packedParticle;
        particle.setMass(massKg);
        for (int i = 0; i < count; ++i) {
            int y = count + i;
            int z = 2 * count + i;
            particle.position.set(positions[i], positions[y], positions[z]);
            particle.velocity.set(velocities[i], velocities[y], velocities[z]);
            computeStep(particle, stepSeconds);
            positions[i] = nextPosition.x;
            positions[y] = nextPosition.y;
            positions[z] = nextPosition.z;
            velocities[i] = nextVelocity.x;
            velocities[y] = nextVelocity.y;
            velocities[z] = nextVelocity.z;
        }
    }

    /**
     * Find the first non-finite value: one pass summing the values, sixteen at a time as a
     * tree into four independent sums (short chains keep the additions in flight), then a
     * search only if the total is not finite. A finite total means every value is finite (an
     * infinity or NaN makes the sum infinite or NaN); a total that overflows although every
     * value is finite costs only the search.
     *
     * @return its index, or -1 if every value is finite
     */
    private static int firstNonFinite(float[] values, int length) {
        float sum0 = 0f;
        float sum1 = 0f;
        float sum2 = 0f;
        float sum3 = 0f;
        int i = 0;
        for (; i + 16 <= length; i += 16) {
            sum0 += (values[i] + values[i + 1]) + (values[i + 2] + values[i + 3]);
            sum1 += (values[i + 4] + values[i + 5]) + (values[i + 6] + values[i + 7]);
            sum2 += (values[i + 8] + values[i + 9]) + (values[i + 10] + values[i + 11]);
            sum3 += (values[i + 12] + values[i + 13]) + (values[i + 14] + values[i + 15]);
        }
        for (; i < length; ++i) {
            sum0 += values[i];
        }
        if (Float.isFinite((sum0 + sum1) + (sum2 + sum3))) {
            return -1;
        }
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

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The stability limits and the regime of {@link ParticleIntegrator}'s step: the rates λ, ω²
 * and σ of a scene's forces at a particle's state, the limits they give, and the regime a step
 * of h is in ({@link StepRegime}), with the regime's bound remembered per step and mass so
 * that the demos' check of every particle every step is a few comparisons.
 *
 * <p>The folded forces' rates come from their coefficients ({@link FoldedForces}), in double;
 * the other forces are asked through the {@link Force} interface.
 */
final class StepLimits {

    /**
     * How close (relatively) h·σ or h·λ may come to a limit before {@link #regime} checks it
     * with the quotients: float roundings differ by about 1e-7, so 1e-4 leaves no doubt.
     */
    private static final float LIMIT_MARGIN = 1e-4f;

    private final FoldedForces folded;
    /** The forces that are not folded. */
    private final Force[] others;
    /**
     * Remembered with the fold's numbers, for the same h and m
     * ({@link FoldedForces#isRememberedFor}): the regime of a moving particle without
     * speed-dependent forces ...
     */
    private StepRegime movingRegime = StepRegime.STABLE;
    /**
     * ... and the |V|² up to which every particle is {@link StepRegime#STABLE} (m²/s²;
     * infinite: at every speed; -1: none) ...
     */
    private float stableSpeedSquared = -1f;
    /** ... or true if without speed-dependent forces every particle is stable. */
    private boolean stableAtAnySpeed;
    /** Scratch for {@link #dragRate}: a of the other forces at the particle's state (m/s²). */
    private final Vector3f movingAcceleration = new Vector3f();
    /** Scratch for {@link #dragRate}: a of the other forces at rest (m/s²). */
    private final Vector3f restingAcceleration = new Vector3f();
    /** Scratch: g of the other forces (m/s²). */
    private final Vector3f otherField = new Vector3f();
    /** Scratch: F of the other forces (N). */
    private final Vector3f otherForce = new Vector3f();
    /** Scratch for {@link #dragRate}: the particle at rest. */
    private final Particle restingScratch = new Particle();
    /** Scratch for {@link #remember}: a particle moving at 1 m/s along x, of the mass asked. */
    private final Particle movingScratch = new Particle(Vector3f.ZERO, Vector3f.UNIT_X, 1f);

    /**
     * Create the limits of a scene's forces.
     *
     * @param folded the scene's folded forces (not null)
     * @param others the scene's other forces (not null, shared)
     */
    StepLimits(FoldedForces folded, Force[] others) {
        this.folded = folded;
        this.others = others;
    }

    /**
     * Make sure the fold's numbers ({@link FoldedForces#remember}) and the regime's
     * bound are remembered for h and m: both under one key, so that in a demo's loop the JIT
     * merges the regime's checks with the step's.
     *
     * <p>The bound. Gravity and linear drag: σ = λ = b/m for every moving particle, so one
     * regime for all of them; at rest σ = 0, which can only make it milder, so a stable step is
     * stable at every speed. Quadratic drag and thrust: λ = (b + 2c·|V|)/m grows with the
     * speed, and σ = (b + c·|V| − k/|V|)/m never exceeds it (c, k &ge; 0), so every particle
     * with {@code h·λ ≤ 1/2} is stable: that is {@code |V| ≤ (m/(2h) − b)/(2c)}. The float
     * arithmetic of {@link #regimeByProducts} rounds h·λ and h·σ by about ten roundings
     * (10·2^-24 relatively, and monotonically in |V|), far too little to take a value of 1/2
     * near the limit 1, so below that speed it answers {@link StepRegime#STABLE} too (provided
     * h·k/(m·{@link Thrust#MIN_SPEED}) is finite, so h·σ is). Other forces: no bound.
     *
     * @param stepSeconds h (in seconds)
     * @param massKg m (in kilograms)
     */
    void remember(float stepSeconds, float massKg) {
        if (folded.isRememberedFor(stepSeconds, massKg)) {
            return;
        }
        folded.remember(stepSeconds, massKg);
        if (others.length > 0) {
            stableAtAnySpeed = false;
            stableSpeedSquared = -1f;
            return;
        }
        boolean speedDependent = folded.speedDependent;
        movingScratch.setMass(massKg);
        movingRegime = speedDependent ? StepRegime.STABLE
                : regimeByProducts(movingScratch, stepSeconds, 1f);
        stableAtAnySpeed = !speedDependent && movingRegime == StepRegime.STABLE;
        if (!speedDependent) {
            stableSpeedSquared = -1f;
            return;
        }
        double stepPerMass = (double) stepSeconds / massKg;
        double halfLimit = 0.5 / stepPerMass - folded.linearSum;
        double thrustH = stepPerMass * folded.thrustSum / Thrust.MIN_SPEED;
        if (!(halfLimit >= 0.0) || !(thrustH < Float.MAX_VALUE)) {
            stableSpeedSquared = -1f;
        } else if (folded.quadraticSum == 0f) {
            stableSpeedSquared = Float.POSITIVE_INFINITY;
        } else {
            double speed = halfLimit / (2.0 * folded.quadraticSum);
            stableSpeedSquared = (float) Math.min(speed * speed, Float.MAX_VALUE);
        }
    }

    /**
     * Tell whether the bound remembered for the step's h and m says the particle is
     * {@link StepRegime#STABLE}: true only if h and m are those of
     * {@link FoldedForces#isRememberedFor} (ask that first).
     *
     * @param particle the particle (not null, not modified)
     * @return true if surely stable; false if {@link #regime} must decide
     */
    boolean isStableBelowTheBound(Particle particle) {
        return stableAtAnySpeed || particle.velocity.lengthSquared() <= stableSpeedSquared;
    }

    /**
     * See {@link ParticleIntegrator#regime}, which asks {@link #isStableBelowTheBound} first.
     *
     * @param particle the particle (not null, not modified)
     * @param stepSeconds h (in seconds, &ge;0)
     * @return the regime (not null)
     */
    StepRegime regime(Particle particle, float stepSeconds) {
        if (others.length > 0) {
            return regimeByLimits(particle, stepSeconds);
        }
        remember(stepSeconds, particle.getMass());
        float speedSquared = particle.velocity.lengthSquared();
        if (stableAtAnySpeed || speedSquared <= stableSpeedSquared) {
            return StepRegime.STABLE;
        }
        if (folded.speedDependent) {
            return regimeByProducts(particle, stepSeconds, speedSquared);
        }
        if (movingRegime == StepRegime.STABLE) {
            return StepRegime.STABLE;
        }
        return speedSquared == 0f ? regimeByProducts(particle, stepSeconds, 0f) : movingRegime;
    }

    /** λ at the particle's state (see {@link ParticleIntegrator#dampingRate}). */
    float dampingRate(Particle particle) {
        return dampingRateAt(particle,
                folded.quadraticSum == 0f ? 0f : particle.velocity.length());
    }

    /** ω² at the particle's state: the folded forces do not depend on position. */
    float stiffness(Particle particle) {
        double total = 0.0;
        for (int i = 0; i < others.length; ++i) {
            total += others[i].stiffness(particle);
        }
        return clampRate(total);
    }

    /** σ at the particle's state (see {@link ParticleIntegrator#dragRate}). */
    float dragRate(Particle particle) {
        return dragRateAt(particle, particle.velocity.length());
    }

    /**
     * The stability limit of the step for a damped oscillator {@code x'' = −ω²·x − λ·x'}
     * ({@link ParticleIntegrator#stableStepLimit}). One step maps (x, v) by a matrix of
     * determinant {@code 1 − λh} and trace {@code 2 − λh − ω²h²}; both eigenvalues lie inside
     * the unit circle (Jury's test) iff {@code λh < 2} and {@code ω²h² + 2λh < 4}, that is iff
     * {@code h < 4/(λ + sqrt(λ² + 4ω²))}. Computed in double without squaring λ, so nothing in
     * between overflows.
     *
     * @param dampingRate λ (in 1/s, &ge;0, may be infinite)
     * @param stiffness ω² (in 1/s², &ge;0, may be infinite)
     * @return the limit (in seconds, &ge;0; infinite when both are 0)
     */
    static double stableStepLimit(double dampingRate, double stiffness) {
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
     * {@link #regime} for the folded forces alone, first without a division: h·σ and h·λ
     * against 1 and 2 (with no spring the limits are 1/σ, 2/σ, 1/λ and 2/λ). Only near a
     * limit, where a rounding could tip it, do the quotients decide.
     */
    private StepRegime regimeByProducts(Particle particle, float stepSeconds,
            float speedSquared) {
        float speed = folded.speedDependent ? (float) Math.sqrt(speedSquared) : 0f;
        float inverseMass = folded.inverseMass(particle.getMass());
        float linear = folded.linearSum;
        float quadratic = folded.quadraticSum;
        float dampingH = stepSeconds * inverseMass
                * (quadratic == 0f ? linear : linear + 2f * quadratic * speed);
        float dragH = speedSquared == 0f ? 0f
                : stepSeconds * folded.dragRate(speed, inverseMass);
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

    /** λ at the particle's state, its speed given: folded in double, plus the others'. */
    private float dampingRateAt(Particle particle, float speed) {
        // λ = b/m + 2c·|V|/m (thrust does not depend on small changes of V: 0)
        float linear = folded.linearSum;
        float quadratic = folded.quadraticSum;
        double rate = quadratic == 0f ? linear : linear + 2.0 * quadratic * speed;
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
        float linear = folded.linearSum;
        float quadratic = folded.quadraticSum;
        double rate = quadratic == 0f ? linear : linear + (double) quadratic * speed;
        if (speed >= Thrust.MIN_SPEED) {
            rate -= (double) folded.thrustSum / speed;
        }
        rate /= particle.getMass();
        if (others.length > 0) {
            // the others' share: −(a(V) − a(0))·V/|V|², a measured at V and at rest
            Vector3f velocity = particle.velocity;
            EulerRecipe.accelerationOf(others, particle, otherField, otherForce,
                    movingAcceleration);
            restingScratch.copyFrom(particle);
            restingScratch.velocity.zero();
            EulerRecipe.accelerationOf(others, restingScratch, otherField, otherForce,
                    restingAcceleration);
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

    /**
     * True if a product h·rate is finite and clear of the limits 1 and 2 by far more than
     * the few roundings in which it and the quotients 1/rate, 2/rate can differ.
     */
    private static boolean isClearOfLimits(float stepTimesRate) {
        return Float.isFinite(stepTimesRate)
                && Math.abs(stepTimesRate - 1f) > LIMIT_MARGIN
                && Math.abs(stepTimesRate - 2f) > 2f * LIMIT_MARGIN;
    }

    /** A rate as a float: at most the largest float, never infinite. */
    private static float clampRate(double rate) {
        return (float) Math.min(rate, Float.MAX_VALUE);
    }
}

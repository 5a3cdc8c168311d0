package particlelab.physics;

/**
 * What one Euler step of h does to a particle, from the two kinds of limit the project uses.
 *
 * <p><b>The motion itself.</b> Through its velocity-dependent forces one step scales the
 * velocity by {@code 1 − σh}, σ being the drag rate ({@link ParticleIntegrator#dragRate}):
 * linear drag {@code b/m}, quadratic drag {@code c·|V|/m}. Drag reverses the velocity once
 * {@code σh > 1} ({@link #REVERSES}: it still shrinks it) and makes the speed grow once
 * {@code σh > 2} ({@link #GROWS}: the step blows up; with quadratic drag the factor worsens
 * every step). These hold where drag dominates; where another force balances it (gravity at
 * the terminal velocity) the limits on small changes below decide.
 *
 * <p><b>Small changes of the motion</b>, which decide whether it can settle at a steady state
 * (a terminal velocity, a spring's rest). They are damped at the rate λ and pulled back with
 * the stiffness ω² ({@link Force#dampingRate}, {@link Force#stiffness}); they grow beyond the
 * stability limit {@code 4/(λ + sqrt(λ² + 4ω²))} ({@link #UNSTABLE}; {@code 2/λ} for drag
 * alone, {@code 2/ω} for an undamped spring, {@code v_t/g} for quadratic drag at its terminal
 * speed {@code v_t}, where a step just beyond swings about v_t for ever and longer ones run
 * away) and alternate in sign beyond {@code 1/λ} ({@link #OVERSHOOTS}).
 *
 * <p>For linear drag σ = λ, so {@link #REVERSES} comes with {@link #OVERSHOOTS} and
 * {@link #GROWS} with {@link #UNSTABLE}. For quadratic drag σ = λ/2: the step overshoots
 * beyond {@code 1/λ}, reverses and is unstable beyond {@code 2/λ}, and grows the speed only
 * beyond {@code 4/λ}: at a state far from steady, "unstable" is a statement about one step.
 * The constants are ordered from harmless to most serious.
 */
public enum StepRegime {

    /** Below every limit: the step follows the motion without artefacts. */
    STABLE("the step is within every limit"),
    /** {@code λh > 1}: small changes of velocity alternate in sign as they die out. */
    OVERSHOOTS("the velocity overshoots and swings about its steady value before settling"),
    /** {@code σh > 1}: the drag reverses the velocity every step; the speed still shrinks. */
    REVERSES("drag reverses the velocity every step but still shrinks it"),
    /** Beyond the stability limit: small changes of the motion grow every step. */
    UNSTABLE("small changes of the motion grow every step instead of dying out"),
    /** {@code σh > 2}: the speed itself grows every step. */
    GROWS("drag makes the speed grow every step: the Euler step blows up");

    private final String consequence;

    StepRegime(String consequence) {
        this.consequence = consequence;
    }

    /**
     * Say what this regime does to the motion, in words for a HUD or a warning.
     *
     * @return a clause such as "the speed grows every step: the Euler step blows up"
     */
    public String consequence() {
        return consequence;
    }

    /**
     * Classify a step: the most serious regime whose limit it passes.
     *
     * @param stepSeconds h (in seconds, &ge;0)
     * @param dragRate σ (in 1/s, may be negative)
     * @param stableSeconds the stability limit for small changes (in seconds, &gt;0, may be
     *     infinite)
     * @param monotoneSeconds the overshoot limit {@code 1/λ} (in seconds, &gt;0, may be
     *     infinite)
     * @return the regime (not null)
     */
    public static StepRegime of(float stepSeconds, float dragRate, float stableSeconds,
            float monotoneSeconds) {
        float motion = stepSeconds * dragRate;
        if (motion > 2f) {
            return GROWS;
        }
        if (stepSeconds > stableSeconds) {
            return UNSTABLE;
        }
        if (motion > 1f) {
            return REVERSES;
        }
        if (stepSeconds > monotoneSeconds) {
            return OVERSHOOTS;
        }
        return STABLE;
    }
}

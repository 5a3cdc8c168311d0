package particlelab.demo;

import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.SimulationClock;
import particlelab.physics.StepRegime;
import particlelab.view.TextFormat;

/**
 * The warning line of a demo's HUD: what went wrong with the stepping lately. Each warning
 * stays up for {@link #SHOW_SECONDS} of real time after its cause:
 * <ul>
 * <li>a step past a limit of the Euler step ({@link StepRegime}): the most serious case of any
 * particle in the step, named with the particle, the limit and what it does (λ, lambda, the
 * damping rate of small changes; σ, sigma, the drag rate of the motion itself);</li>
 * <li>blow-up: a step left a particle non-finite and the demo reset its scene; no other
 * warning replaces it while it is up;</li>
 * <li>hitch: one long frame was injected; says what the clock made of it.</li>
 * </ul>
 * The demo reports each step as it takes it ({@link #beginStep}, {@link #observe},
 * {@link #endStep}) and asks for the text when it refreshes the HUD ({@link #format}). Nothing
 * here allocates, except the message of a blow-up.
 */
final class StepWarnings {

    /** How long a warning stays up after its cause (in seconds of real time). */
    static final float SHOW_SECONDS = 4f;
    /** What the warning line currently reports. */
    private enum Warning {
        NONE, LIMIT, BLOW_UP, HITCH
    }

    private final SimulationClock clock;
    private final Runnable onChange;
    /** h of the step being taken, or of the last one (in seconds). */
    private float stepSeconds;
    /** The most serious regime of any particle in the step being taken. */
    private StepRegime worstRegime = StepRegime.STABLE;
    /** The label of the particle in that regime (not null). */
    private String worstLabel = "";
    /** The limit that particle passed (in seconds). */
    private float worstLimitSeconds;
    /** That particle's stability limit at that state (in seconds; infinite below UNSTABLE). */
    private float worstStableSeconds = Float.POSITIVE_INFINITY;
    private Warning warning = Warning.NONE;
    private float warningAgeSeconds;
    private float warningStepSeconds;
    private float warningLimitSeconds;
    /** The stability limit of the warned particle at the warned state (in seconds). */
    private float warningStableSeconds = Float.POSITIVE_INFINITY;
    private StepRegime warningRegime = StepRegime.STABLE;
    private String warningLabel = "";
    /** The clock's dropped time when the hitch was injected (in seconds). */
    private double droppedAtHitch;
    private String blowUpMessage = "";

    /**
     * Create the warnings of one demo, showing none.
     *
     * @param clock the demo's clock, read for the hitch warning (not null, not modified)
     * @param onChange run whenever the warning changes, to redraw the HUD (not null)
     */
    StepWarnings(SimulationClock clock, Runnable onChange) {
        this.clock = clock;
        this.onChange = onChange;
    }

    /**
     * Note the start of a step, before any particle moves.
     *
     * @param stepSeconds h of the step (in seconds, &gt;0)
     */
    void beginStep(float stepSeconds) {
        this.stepSeconds = stepSeconds;
    }

    /**
     * Note one particle about to be stepped in the current step: what the step of h does to
     * it at its state ({@link ParticleIntegrator#regime}).
     *
     * @param label the particle's label, to name it in the warning (not null)
     * @param integrator the particle's forces (not null)
     * @param particle its state before the step (not null, not modified)
     */
    void observe(String label, ParticleIntegrator integrator, Particle particle) {
        StepRegime regime = integrator.regime(particle, stepSeconds);
        if (regime.compareTo(worstRegime) > 0) {
            worstRegime = regime;
            worstLabel = label;
            worstLimitSeconds = limitSeconds(regime, integrator, particle);
            worstStableSeconds = regime.compareTo(StepRegime.UNSTABLE) >= 0
                    ? integrator.maxStableStep(particle) : Float.POSITIVE_INFINITY;
        }
    }

    /**
     * Note the end of a step: raise a warning if it passed a limit.
     */
    void endStep() {
        if (worstRegime != StepRegime.STABLE && (warning != Warning.LIMIT
                || warningAgeSeconds > SHOW_SECONDS
                || worstRegime.compareTo(warningRegime) >= 0)) {
            warningRegime = worstRegime;
            warningLabel = worstLabel;
            warningStableSeconds = worstStableSeconds;
            raise(Warning.LIMIT, stepSeconds, worstLimitSeconds);
        }
        worstRegime = StepRegime.STABLE;
    }

    /**
     * Note that a hitch was injected and will come with the next frame: remember how much
     * simulated time the clock had dropped so far, to report what the hitch drops.
     */
    void hitchInjected() {
        droppedAtHitch = clock.getDroppedSeconds();
    }

    /**
     * Warn of the hitch the clock is being handed now.
     *
     * @param frameSeconds the long frame (in seconds, &gt;0)
     */
    void hitchApplied(float frameSeconds) {
        raise(Warning.HITCH, frameSeconds, 0f);
    }

    /**
     * Warn that the current step blew up and the scene was reset. Call after the reset.
     */
    void blewUp() {
        blowUpMessage = "The Euler step h = " + stepSeconds + " s blew up (beyond the stability"
                + " limit): the scene was reset.";
        warning = Warning.BLOW_UP;
        warningAgeSeconds = 0f;
        onChange.run();
    }

    /**
     * Age the warning by one frame.
     *
     * @param realSeconds the frame time (in seconds of real time, &ge;0)
     */
    void age(float realSeconds) {
        warningAgeSeconds += realSeconds;
    }

    /**
     * Take the warning down and forget the current step's rates, for a reset.
     */
    void clear() {
        warning = Warning.NONE;
        worstRegime = StepRegime.STABLE;
    }

    /**
     * Test whether the warning line shows a step beyond a stability limit (UNSTABLE, or worse),
     * so the HUD's stability line can speak of the same particle and limit.
     *
     * @return true while such a warning is up
     */
    boolean isUnstableShowing() {
        return warning == Warning.LIMIT && warningAgeSeconds <= SHOW_SECONDS
                && warningRegime.compareTo(StepRegime.UNSTABLE) >= 0;
    }

    /**
     * Return the stability limit of the particle the warning names, at the state of the step
     * that raised it ({@link ParticleIntegrator#maxStableStep}).
     *
     * @return the limit (in seconds; infinite unless {@link #isUnstableShowing()})
     */
    float getWarnedStableSeconds() {
        return isUnstableShowing() ? warningStableSeconds : Float.POSITIVE_INFINITY;
    }

    /**
     * Return the label of the particle the warning names.
     *
     * @return the label (not null; empty before a warning)
     */
    String getWarnedLabel() {
        return warningLabel;
    }

    /**
     * Write the warning line into storeResult (empty when no warning is up), without
     * allocating.
     *
     * @param storeResult storage for the text (not null, cleared and modified)
     * @return storeResult
     */
    StringBuilder format(StringBuilder storeResult) {
        StringBuilder text = storeResult;
        text.setLength(0);
        if (warning == Warning.NONE || warningAgeSeconds > SHOW_SECONDS) {
            return text;
        }
        switch (warning) {
            case BLOW_UP:
                text.append(blowUpMessage);
                break;
            case LIMIT:
                appendLimit(text);
                break;
            case HITCH:
                text.append("Hitch: one ");
                TextFormat.appendFixed(text, warningStepSeconds, 2).append(" s frame. ");
                if (clock.getMode() == SimulationClock.Mode.RAW_TPF) {
                    text.append("Raw tpf took it as ONE Euler step.");
                } else {
                    text.append("Fixed step clamped it; dropped ");
                    TextFormat.appendFixed(text, clock.getDroppedSeconds() - droppedAtHitch, 2)
                            .append(" s of simulated time.");
                }
                break;
            default:
                break;
        }
        return text;
    }

    /**
     * Append e.g. "UNSTABLE: h = 500.0 ms is beyond the stability limit 275.1 ms of 'spring':
     * small changes of the motion grow every step instead of dying out", or "h = 250.0 ms is
     * beyond 2/σ = 200.0 ms of 'ball': ..." (the HUD font has the Greek letters).
     */
    private void appendLimit(StringBuilder text) {
        boolean serious = warningRegime.compareTo(StepRegime.UNSTABLE) >= 0;
        text.append(serious ? "UNSTABLE: h = " : "h = ");
        TextFormat.appendFixed(text, warningStepSeconds * 1000f, 1).append(" ms is beyond ")
                .append(limitName(warningRegime));
        TextFormat.appendFixed(text, warningLimitSeconds * 1000f, 1).append(" ms of '")
                .append(warningLabel).append("': ").append(warningRegime.consequence());
    }

    /** The limit a regime passes, as the warning names it. */
    private static String limitName(StepRegime regime) {
        switch (regime) {
            case GROWS:
                return "2/σ = ";
            case UNSTABLE:
                return "the stability limit ";
            case REVERSES:
                return "1/σ = ";
            default:
                return "1/λ = ";
        }
    }

    /** The limit (in seconds) that a particle in the regime has passed. */
    private static float limitSeconds(StepRegime regime, ParticleIntegrator integrator,
            Particle particle) {
        switch (regime) {
            case GROWS:
                return 2f / integrator.dragRate(particle);
            case UNSTABLE:
                return integrator.maxStableStep(particle);
            case REVERSES:
                return 1f / integrator.dragRate(particle);
            default:
                return integrator.maxMonotoneStep(particle);
        }
    }

    private void raise(Warning newWarning, float causeSeconds, float limitSeconds) {
        if (warning == Warning.BLOW_UP && warningAgeSeconds < SHOW_SECONDS) {
            return;
        }
        warning = newWarning;
        warningAgeSeconds = 0f;
        warningStepSeconds = causeSeconds;
        warningLimitSeconds = limitSeconds;
        onChange.run();
    }
}

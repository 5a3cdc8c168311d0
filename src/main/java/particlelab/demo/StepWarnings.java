package particlelab.demo;

import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * The warning line of a demo's HUD: what went wrong with the stepping lately. Each warning
 * stays up for {@link #SHOW_SECONDS} of real time after its cause:
 * <ul>
 * <li>reversing: a step had {@code h·λ > 1} (λ the damping rate of the forces, b/m for linear
 * drag): the drag overshoots and reverses the velocity each step;</li>
 * <li>unstable: a step had {@code h·λ > 2}: the Euler step amplifies the velocity;</li>
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
    /** Beyond this h·λ the Euler step amplifies the velocity. */
    private static final float UNSTABLE_RATE = 2f;
    /** Beyond this h·λ linear drag reverses the velocity each step. */
    private static final float REVERSING_RATE = 1f;

    /** What the warning line currently reports. */
    private enum Warning {
        NONE, REVERSING, UNSTABLE, BLOW_UP, HITCH
    }

    private final SimulationClock clock;
    private final Runnable onChange;
    /** h of the step being taken, or of the last one (in seconds). */
    private float stepSeconds;
    /** The worst h·λ of any particle in the step being taken (dimensionless). */
    private float worstStepRate;
    private Warning warning = Warning.NONE;
    private float warningAgeSeconds;
    private float warningStepSeconds;
    private float warningLimitSeconds;
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
     * Note the damping rate one particle is stepped with in the current step.
     *
     * @param dampingRate λ of the forces on the particle (in 1/s, &ge;0)
     */
    void observe(float dampingRate) {
        float stepRate = stepSeconds * dampingRate;
        if (stepRate > worstStepRate) {
            worstStepRate = stepRate;
        }
    }

    /**
     * Note the end of a step: raise a warning if it passed a limit (h·λ &gt; 1 or 2).
     */
    void endStep() {
        if (worstStepRate > UNSTABLE_RATE) {
            raise(Warning.UNSTABLE, stepSeconds, UNSTABLE_RATE * stepSeconds / worstStepRate);
        } else if (worstStepRate > REVERSING_RATE && warning != Warning.UNSTABLE) {
            raise(Warning.REVERSING, stepSeconds, REVERSING_RATE * stepSeconds / worstStepRate);
        }
        worstStepRate = 0f;
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
        worstStepRate = 0f;
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
            case UNSTABLE:
                appendStepBeyondLimit(text, "UNSTABLE: h = ",
                        " ms is beyond the stability limit 2/k = ",
                        " ms: the Euler step amplifies the velocity");
                break;
            case REVERSING:
                appendStepBeyondLimit(text, "h = ", " ms is beyond 1/k = ",
                        " ms: drag overshoots and reverses the velocity each step");
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

    /** Append "{before} h {middle} limit {after}", h and the limit in milliseconds. */
    private void appendStepBeyondLimit(StringBuilder text, String before, String middle,
            String after) {
        text.append(before);
        TextFormat.appendFixed(text, warningStepSeconds * 1000f, 1).append(middle);
        TextFormat.appendFixed(text, warningLimitSeconds * 1000f, 1).append(after);
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

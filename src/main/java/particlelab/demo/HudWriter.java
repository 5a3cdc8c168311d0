package particlelab.demo;

import java.util.List;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * The part of a demo's HUD body that every demo shows: the equations it runs, the time line
 * (simulated time, pause, the time scale asked for and the one measured, whether time is being
 * dropped, the pause at the next contact, and the keys that change it), a short notice if
 * one is up, one line per particle (position, velocity, speed and where and when it landed),
 * the stepping line (fixed h or raw tpf) and the stability line (the smallest limit and the
 * particle it belongs to). In a demo with exact ghosts a particle's line ends with its
 * distance to its ghost, and once landed it is the particle's readouts, Euler against exact
 * ({@link ExactGhosts}). The demo's own lines follow, from {@link DemoState#writeHudLines}.
 * Key names come from the bindings. Writing allocates nothing.
 */
final class HudWriter {

    /** How long a notice stays up (in seconds of real time). */
    static final float NOTICE_SECONDS = 3f;

    private final SimulationClock clock;
    private final List<DemoParticle> particles;
    private String equations = "";
    private KeyBinding pauseKey;
    private KeyBinding stepKey;
    private KeyBinding resetKey;
    private KeyBinding fasterKey;
    private KeyBinding slowerKey;
    private KeyBinding realTimeKey;
    private String notice;
    private float noticeAgeSeconds;
    /** The demo's exact ghosts, which add to the particle lines (null: none). */
    private ExactGhosts ghosts;
    /** Says what is drawn and where the replay is, on the stepping line (null: nothing). */
    private Replay replay;
    /** The demo's warning line, which the stability line agrees with (null: none). */
    private StepWarnings warnings;
    /** The pause at the next contact, whose line follows the time line (null: none). */
    private ContactPause contactPause;

    /**
     * Create a writer for one demo.
     *
     * @param clock the demo's clock (not null, not modified)
     * @param particles the demo's particles (not null, live, not modified)
     */
    HudWriter(SimulationClock clock, List<DemoParticle> particles) {
        this.clock = clock;
        this.particles = particles;
    }

    /**
     * Say on the stepping line what is drawn (interpolated or raw) and where the replay is.
     *
     * @param newReplay the demo's replay (not null)
     */
    void setReplay(Replay newReplay) {
        replay = newReplay;
    }

    /**
     * Let the demo's exact ghosts add to the particle lines: the live distance while a
     * particle flies, and its readouts, Euler against exact, in place of its line once it
     * and its ghost have landed.
     *
     * @param exactGhosts the demo's ghosts (not null)
     */
    void setGhosts(ExactGhosts exactGhosts) {
        ghosts = exactGhosts;
    }

    /**
     * Let the stability line agree with the demo's warning line: while that warns of a step
     * beyond a stability limit smaller than every moving particle's limit now (the particle
     * has slowed, or landed and stopped), the line gives the warned particle's limit at the
     * state of that step, not a limit (or "any h is stable") that the warning contradicts.
     *
     * @param stepWarnings the demo's warnings (not null, not modified)
     */
    void setWarnings(StepWarnings stepWarnings) {
        warnings = stepWarnings;
    }

    /**
     * Let the pause at the next contact write in the time line: that it is armed, or which
     * contact the clock stands at (in place of the usual pause text).
     *
     * @param pause the demo's pause (not null)
     */
    void setContactPause(ContactPause pause) {
        contactPause = pause;
    }

    /**
     * Set the equations shown at the top, one line each.
     *
     * @param text the lines, each ending in a newline (not null)
     */
    void setEquations(String text) {
        equations = text;
    }

    /**
     * Return the equations shown at the top.
     *
     * @return the lines, each ending in a newline (not null)
     */
    String getEquations() {
        return equations;
    }

    /**
     * Name the keys the time line mentions.
     *
     * @param pause pause / resume (not null)
     * @param step single step (not null)
     * @param reset reset the scene (not null)
     * @param faster time scale x2 (not null)
     * @param slower time scale /2 (not null)
     * @param realTime time scale back to x1 (not null)
     */
    void setTimeKeys(KeyBinding pause, KeyBinding step, KeyBinding reset, KeyBinding faster,
            KeyBinding slower, KeyBinding realTime) {
        pauseKey = pause;
        stepKey = step;
        resetKey = reset;
        fasterKey = faster;
        slowerKey = slower;
        realTimeKey = realTime;
    }

    /**
     * Show a short notice below the time line for {@link #NOTICE_SECONDS}.
     *
     * @param text the notice, one line (not null)
     */
    void showNotice(String text) {
        if (text == null || text.isEmpty() || text.indexOf('\n') >= 0) {
            throw new IllegalArgumentException("a notice must be one non-empty line, but was "
                    + (text == null ? "null" : "\"" + text + "\""));
        }
        notice = text;
        noticeAgeSeconds = 0f;
    }

    /**
     * Return the notice shown now.
     *
     * @return the notice, or null if none is up
     */
    String getNotice() {
        return notice;
    }

    /**
     * Let real time pass for the notice.
     *
     * @param realSeconds the frame time (in seconds, &ge;0)
     */
    void age(float realSeconds) {
        if (notice != null) {
            noticeAgeSeconds += realSeconds;
            if (noticeAgeSeconds >= NOTICE_SECONDS) {
                notice = null;
            }
        }
    }

    /**
     * Write the shared body text into storeResult, without allocating.
     *
     * @param storeResult storage for the text (not null, cleared and modified)
     * @param sceneOver true if every particle has landed, so the clock has stopped
     * @return storeResult
     */
    StringBuilder write(StringBuilder storeResult, boolean sceneOver) {
        StringBuilder text = storeResult;
        text.setLength(0);
        text.append(equations);
        appendTimeLines(text, sceneOver);
        if (notice != null) {
            text.append(notice).append('\n');
        }
        for (int i = 0; i < particles.size(); ++i) {
            if (particles.get(i).isParked()) {
                continue;
            }
            if (ghosts != null && ghosts.hasReadout(i)) {
                ghosts.appendReadout(text, i);
            } else {
                appendParticleLine(text, particles.get(i), i);
            }
        }
        appendSteppingLine(text);
        if (!particles.isEmpty()) {
            // a demo without particles of its own (the fountain) says what limits its step
            appendStabilityLine(text);
        }
        return text;
    }

    /**
     * Append a time scale as the keys make it: x64, x2, x1, x1/2, x1/64 (or with decimals if
     * it is not a whole number or the inverse of one).
     *
     * @param text where to append (not null, modified)
     * @param scale the scale (&gt;0)
     * @return text
     */
    static StringBuilder appendScale(StringBuilder text, float scale) {
        text.append('x');
        if (scale >= 1f) {
            return TextFormat.appendFixed(text, scale, scale == Math.rint(scale) ? 0 : 2);
        }
        float inverse = 1f / scale;
        if (inverse == Math.rint(inverse)) {
            return TextFormat.appendFixed(text.append("1/"), inverse, 0);
        }
        return TextFormat.appendFixed(text, scale, 3);
    }

    /**
     * A measured rate: three decimals below 0.1 (x0.016 at x1/64), two below 10 (x5.75,
     * x0.25), one above (x15.0).
     */
    private static StringBuilder appendRate(StringBuilder text, float rate) {
        return TextFormat.appendFixed(text, rate, rate < 0.1f ? 3 : rate < 10f ? 2 : 1);
    }

    /**
     * The time line: t, then what stops it (the contact the pause at the next contact stopped
     * at, a finished scene, pause) and whether that pause is armed, the time scale asked
     * for and, when it matters, the one measured and why they differ; then, unless the scale
     * is x1 and nothing is dropped, the keys that change it and its limits.
     */
    private void appendTimeLines(StringBuilder text, boolean sceneOver) {
        text.append("t = ");
        TextFormat.appendFixed(text, clock.getSimulatedSeconds(), 2).append(" s");
        boolean running = !sceneOver && !clock.isPaused();
        if (contactPause != null && contactPause.isAtContact()) {
            contactPause.appendAtContact(text.append("   "));
        } else if (sceneOver) {
            text.append("   stopped: every particle has landed (").append(resetKey.getKeyLabel())
                    .append(" launches again)");
        } else if (clock.isPaused()) {
            text.append("   PAUSED: ").append(pauseKey.getKeyLabel()).append(" resumes, ")
                    .append(stepKey.getKeyLabel()).append(" takes one step");
        }
        if (contactPause != null && contactPause.isArmed()) {
            contactPause.appendArmed(text.append("   "));
        }
        float scale = clock.getTimeScale();
        float measured = clock.getMeasuredTimeScale();
        boolean dropping = running && clock.isDroppingTime();
        text.append("   time ");
        appendScale(text, scale);
        if (running && (scale != 1f || dropping) && !Float.isNaN(measured)) {
            text.append(" asked, x");
            appendRate(text, measured).append(" measured");
        }
        if (dropping) {
            text.append(": DROPPING TIME (a frame simulates at most ");
            TextFormat.appendFixed(text, clock.getMaxSimulatedSecondsPerFrame(), 3)
                    .append(" s");
            float frameSeconds = clock.getMeasuredFrameSeconds();
            if (!Float.isNaN(frameSeconds)) {
                // The frame time, not a rounded fps: "at 5 fps that is x1.31" read as a sum
                // that does not add up (0.25 s × 5 = 1.25) when the frames took 191 ms.
                text.append("; frames take ");
                TextFormat.appendFixed(text, 1000f * frameSeconds, 1).append(" ms, so at most x");
                appendRate(text, clock.getMaxMeasurableTimeScale());
            }
            text.append(')');
        }
        text.append('\n');
        if (scale != 1f || dropping) {
            text.append("   ").append(fasterKey.getKeyLabel()).append("  x2,   ")
                    .append(slowerKey.getKeyLabel()).append("  /2   (");
            appendScale(text, SimulationClock.MIN_TIME_SCALE).append(" to ");
            appendScale(text, SimulationClock.MAX_TIME_SCALE).append("),   ")
                    .append(realTimeKey.getKeyLabel()).append("  back to x1\n");
        }
    }

    private void appendParticleLine(StringBuilder text, DemoParticle demoParticle, int index) {
        Particle particle = demoParticle.getParticle();
        text.append(demoParticle.getLabel()).append(":  P = ");
        TextFormat.appendVector(text, particle.position, 2).append(" m   V = ");
        TextFormat.appendVector(text, particle.velocity, 2).append(" m/s   |V| = ");
        TextFormat.appendFixed(text, particle.velocity.length(), 2).append(" m/s");
        if (demoParticle.hasLanded()) {
            text.append("   landed at x = ");
            TextFormat.appendFixed(text, demoParticle.getLandingX(), 2).append(" m after ");
            TextFormat.appendFixed(text, demoParticle.getLandingSeconds(), 2).append(" s");
        }
        if (ghosts != null) {
            ghosts.appendLiveError(text, index);
        }
        text.append('\n');
    }

    private void appendSteppingLine(StringBuilder text) {
        text.append("Stepping: ");
        if (clock.getMode() == SimulationClock.Mode.FIXED_STEP) {
            text.append("fixed h = ");
            TextFormat.appendFixed(text, clock.getStepSeconds() * 1000f, 1).append(" ms");
        } else {
            text.append("raw tpf, last h = ");
            TextFormat.appendFixed(text, clock.getCurrentStepSeconds() * 1000f, 1)
                    .append(" ms");
        }
        if (replay != null) {
            replay.appendHudText(text);
        }
        text.append('\n');
    }

    /**
     * The stability line: the smallest stability limit of the particles still moving, at their
     * current states, naming the particle it belongs to with its damping rate λ and, for a
     * spring, its angular frequency ω = √(k/m); or, while the warning line is about a step
     * beyond a smaller limit, that one (see {@link #setWarnings}).
     */
    private void appendStabilityLine(StringBuilder text) {
        float limit = Float.POSITIVE_INFINITY;
        DemoParticle limiting = null;
        int moving = 0;
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.isHeld()) {
                continue;
            }
            ++moving;
            float particleLimit = particle.getForcesNow().maxStableStep(particle.getParticle());
            if (particleLimit < limit) {
                limit = particleLimit;
                limiting = particle;
            }
        }
        float warned = warnings == null ? Float.POSITIVE_INFINITY
                : warnings.getWarnedStableSeconds();
        if (warned < limit) {
            text.append("Stability: h < ");
            TextFormat.appendFixed(text, warned, 3).append(" s for '")
                    .append(warnings.getWarnedLabel())
                    .append("' at the step the warning below is about\n");
            return;
        }
        if (moving == 0) {
            // Rigid bodies may still turn: the line speaks of the particle step only.
            text.append("Stability: no particle is in flight, so no particle step limit"
                    + " applies\n");
            return;
        }
        if (limiting == null) {
            text.append("Stability: any h is stable (no drag or spring on a moving particle)\n");
            return;
        }
        Particle particle = limiting.getParticle();
        text.append("Stability: h < ");
        TextFormat.appendFixed(text, limit, 3).append(" s for '").append(limiting.getLabel())
                .append("' (λ = ");
        TextFormat.appendFixed(text, limiting.getForcesNow().dampingRate(particle), 2)
                .append(" /s");
        float stiffness = limiting.getForcesNow().stiffness(particle);
        if (stiffness > 0f) {
            text.append(", ω = ");
            TextFormat.appendFixed(text, (float) Math.sqrt(stiffness), 2).append(" /s");
        }
        text.append(")\n");
    }
}

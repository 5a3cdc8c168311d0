package particlelab.lecture;

import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * A bug hunt's consequence in numbers ({@link FaultHunt}): where a demo's sphere lands with
 * the fault that runs and where it lands with the correct code, both flown ahead from its
 * launch as the world steps it, and the phrase the HUD's fault line ends with. The demo gives
 * the flight ({@link AheadFlight}: its forces, its order of the updates); this class keeps
 * the two landings and the phrase, and flies again only when h changed or the demo said that
 * the launch, a coefficient or the fault did ({@link #markStale}). Allocates nothing once
 * the demo's flight is made.
 */
final class FaultConsequence {

    /** The longest flight flown ahead (steps): 5.5 min at 60 Hz. */
    static final int MAX_FLIGHT_STEPS = 20_000;

    /** A demo's sphere flown ahead from its launch. */
    interface AheadFlight {
        /**
         * Fly the sphere from its launch with the fault or with the correct code. Allocates
         * nothing.
         *
         * @param fault 0 for the correct code, else the fault (1 to n, in the bug hunt's order)
         * @param stepSeconds h (in seconds, &gt;0)
         * @return its landing x (in metres; NaN if it does not land within
         *     {@link #MAX_FLIGHT_STEPS})
         */
        double landingX(int fault, float stepSeconds);

        /**
         * Append what the demo says of the fault before its landing (e.g. the force it
         * pushes with). Allocates nothing. The default says nothing.
         *
         * @param text where to append (not null, modified)
         * @param fault the fault that runs (1 to n)
         */
        default void appendBefore(StringBuilder text, int fault) {
        }

        /**
         * Append what the demo says after both landings (e.g. the closed form of their
         * difference). Allocates nothing. The default says nothing.
         *
         * @param text where to append (not null, modified)
         * @param stepSeconds h of the flights (in seconds)
         */
        default void appendAfter(StringBuilder text, float stepSeconds) {
        }
    }

    private final FaultHunt faults;
    private final SimulationClock clock;
    /** What lands, as the phrase names it: "the thruster". */
    private final String subject;
    /** What the fault is measured against: "the correct code". */
    private final String correct;
    private final StringBuilder text = new StringBuilder();
    private AheadFlight flight;
    private double faultyLandingX = Double.NaN;
    private double correctLandingX = Double.NaN;
    private boolean stale = true;
    /** The h the landings were flown with (s). */
    private float flownStepSeconds;

    /**
     * Create a demo's consequence; it has no flight until {@link #setFlight}.
     *
     * @param faults the demo's bug hunt (not null)
     * @param clock the demo's clock, whose h the flights take (not null)
     * @param subject what lands, for the phrase, e.g. "the thruster" (not null)
     * @param correct what the fault is measured against, e.g. "the correct code" (not null)
     */
    FaultConsequence(FaultHunt faults, SimulationClock clock, String subject, String correct) {
        this.faults = faults;
        this.clock = clock;
        this.subject = subject;
        this.correct = correct;
    }

    /** @param newFlight the demo's flight, made with its scene (not null) */
    void setFlight(AheadFlight newFlight) {
        flight = newFlight;
        stale = true;
    }

    /** The launch, a coefficient or the fault changed: fly again when next asked. */
    void markStale() {
        stale = true;
    }

    /**
     * Return where the sphere lands with the fault that runs, flown ahead if stale.
     *
     * @return the landing x (in metres; NaN without a fault or a landing)
     */
    double getFaultyLandingX() {
        refresh();
        return faultyLandingX;
    }

    /**
     * Return where the sphere lands with the correct code from the same launch, flown ahead
     * if stale.
     *
     * @return the landing x (in metres; NaN without a fault or a landing)
     */
    double getCorrectLandingX() {
        refresh();
        return correctLandingX;
    }

    /**
     * Append the bug hunt's HUD line with this consequence ({@link FaultHunt#appendHudLine}).
     * Allocates nothing.
     *
     * @param hud where to append (not null, modified)
     * @param revealKey the reveal key as printed, e.g. "B" (not null)
     */
    void appendHudLine(StringBuilder hud, String revealKey) {
        refresh();
        faults.appendHudLine(hud, revealKey, text);
    }

    /** Fly both landings and write the phrase, if h or anything else changed since. */
    private void refresh() {
        float h = clock.getStepSeconds();
        if (!stale && h == flownStepSeconds) {
            return;
        }
        stale = false;
        flownStepSeconds = h;
        text.setLength(0);
        faultyLandingX = Double.NaN;
        correctLandingX = Double.NaN;
        int fault = faults.active();
        if (fault == 0 || flight == null) {
            return;
        }
        faultyLandingX = flight.landingX(fault, h);
        correctLandingX = flight.landingX(0, h);
        flight.appendBefore(text, fault);
        if (Double.isNaN(faultyLandingX)) {
            text.append(subject).append(" never lands (").append(correct)
                    .append(" lands at x = ");
            TextFormat.appendFixed(text, correctLandingX, 2).append(" m)");
            return;
        }
        double difference = faultyLandingX - correctLandingX;
        text.append("lands at x = ");
        TextFormat.appendFixed(text, faultyLandingX, 2).append(" m, ");
        TextFormat.appendFixed(text, Math.abs(difference), 2)
                .append(difference < 0.0 ? " m short of " : " m beyond ").append(correct)
                .append("'s ");
        TextFormat.appendFixed(text, correctLandingX, 2).append(" m");
        flight.appendAfter(text, h);
    }
}

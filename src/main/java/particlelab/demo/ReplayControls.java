package particlelab.demo;

/**
 * The replay's controls beside a demo's base class (issue 21): a step back, a step forward,
 * the timeline's scrub and F6's interpolation, each marking the HUD for a rebuild and saying
 * on it why a key did nothing; and the trails walked back and forth with the ring. The
 * {@link Replay} itself (the ring, the step shown, the blend) belongs to the run, without
 * jME; these are what the keys, the panel's timeline and the application call
 * ({@link DemoState#getReplayControls}). None of them allocates.
 */
public final class ReplayControls {

    /** Why a step back did nothing. */
    static final String NO_EARLIER_STEP =
            "no earlier step recorded (the ring starts at the last reset)";

    private final DemoRun run;
    private final Replay replay;
    private final HudWriter hudWriter;
    private final DemoHud hud;

    /**
     * Wire the controls to a demo's run, and the run's replay to the trails of its scene.
     *
     * @param run the demo's run (not null)
     * @param scene the scene whose trails follow the ring (not null)
     * @param hudWriter shows the notices (not null)
     * @param hud the HUD to rebuild after each control (not null)
     */
    ReplayControls(DemoRun run, DemoScene scene, HudWriter hudWriter, DemoHud hud) {
        this.run = run;
        this.replay = run.getReplay();
        this.hudWriter = hudWriter;
        this.hud = hud;
        replay.setTrails(new Replay.TrailWalk() {
            @Override
            public void undone(DemoParticle particle) {
                scene.undoTrailStep(particle);
            }

            @Override
            public void redone(DemoParticle particle) {
                scene.redoTrailStep(particle);
            }
        });
    }

    /**
     * Step back one recorded step: the ring's previous state is put back and the clock
     * paused; if the ring holds none, say so on the HUD.
     *
     * @return false if the ring holds no earlier step
     */
    public boolean stepBack() {
        boolean done = replay.stepBack();
        if (!done) {
            hudWriter.showNotice(NO_EARLIER_STEP);
        }
        hud.markDirty();
        return done;
    }

    /**
     * Step forward one step: the ring's next state while behind the live end, else a new
     * step of h like N.
     */
    public void stepForward() {
        if (!replay.stepForward()) {
            run.singleStep();
        }
        hud.markDirty();
    }

    /**
     * Show a recorded step by its place on the timeline, pausing first (the panel's slider).
     *
     * @param fraction 0 for the oldest step the ring holds, 1 for the newest (clamped)
     */
    public void scrubTo(double fraction) {
        replay.scrub(fraction);
        hud.markDirty();
    }

    /** @return true if the views blend the last two physics states (F6 switches) */
    public boolean isInterpolating() {
        return replay.isInterpolating();
    }

    /**
     * Draw the bodies between their last two physics states, or at the raw steps (F6).
     *
     * @param newInterpolating true to interpolate
     */
    public void setInterpolating(boolean newInterpolating) {
        if (newInterpolating != replay.isInterpolating()) {
            replay.toggleInterpolation();
            hud.markDirty();
        }
    }
}

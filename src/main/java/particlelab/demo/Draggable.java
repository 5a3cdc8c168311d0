package particlelab.demo;

import com.jme3.math.Vector3f;
import java.util.List;

/**
 * One thing of a demo the mouse may drag, declared like its keys and parameters
 * ({@link DemoState#declareDraggable}): which particles offer a grip (their sphere, or the tip
 * of their velocity arrow), what moving the grip changes, and when. The help overlay's
 * "Mouse" section and the pages' mouse table are written from these declarations.
 *
 * <p>A grip is either a particle's sphere ({@link Grip#BODY}: the mover gets the plane point
 * under the mouse, in metres) or the tip of its velocity arrow ({@link Grip#ARROW_TIP}: the
 * mover gets the velocity whose arrow ends there, {@code V = (tip − P)/T} with T the arrow's
 * {@link particlelab.view.ParticleView#ARROW_SECONDS}, in m/s). A drag of the
 * {@link Effect#LAUNCH launch} starts the scene again at t = 0 with every move, so the exact
 * ghosts, readouts and kept shots follow the new launch; a drag of the
 * {@link Effect#STATE state} changes the body where it is; a drag of a
 * {@link Effect#PLACE place} (a target) leaves the rest to the demo. Immutable.
 */
public final class Draggable {

    /** What the mouse takes hold of. */
    public enum Grip {
        /** The particle's sphere: the mover gets a position (m). */
        BODY("sphere"),
        /** The tip of the particle's velocity arrow: the mover gets a velocity (m/s). */
        ARROW_TIP("arrow tip");

        private final String label;

        Grip(String label) {
            this.label = label;
        }

        /** @return the grip as the help names it (not null) */
        public String getLabel() {
            return label;
        }
    }

    /** What a drag changes, and so what the scene does around it. */
    public enum Effect {
        /** The launch: the scene starts again at t = 0 from it at each move (paused). */
        LAUNCH,
        /** The body's state now (position or velocity); the clock stays where it is. */
        STATE,
        /** A place the demo aims at (a target): the demo reacts itself. */
        PLACE
    }

    /** Receives what a drag's grip stands for now. */
    @FunctionalInterface
    public interface Mover {
        /**
         * Take a new value from the mouse; may allocate (a drag is an event, not a frame).
         *
         * @param particle the particle whose grip is held (one of the declaration's)
         * @param value a position (m) for a {@link Grip#BODY} grip, a velocity (m/s) for an
         *     {@link Grip#ARROW_TIP} grip; z = 0 (not null, do not keep)
         */
        void moveTo(DemoParticle particle, Vector3f value);
    }

    /** How the help says when a launch's drag works, and what it does to the scene. */
    public static final String PAUSED_NOTE = " (pauses, t = 0)";

    private final String what;
    private final Grip grip;
    private final Effect effect;
    private final List<DemoParticle> particles;
    private final String summary;
    private final String note;
    private final boolean whileRunning;
    private final Mover mover;

    /**
     * Declare a draggable thing.
     *
     * @param what the particles as the help names them, e.g. "a sphere" (not null, not empty)
     * @param grip what the mouse takes hold of (not null)
     * @param effect what a drag changes (not null)
     * @param particles the particles that offer the grip (not null, not empty; copied)
     * @param description what moving it does, for the help (not null, not empty)
     * @param whileRunning true if it may be dragged while the clock runs; false: a press on
     *     it pauses the simulation first
     * @param mover takes each new value (not null)
     */
    public Draggable(String what, Grip grip, Effect effect, List<DemoParticle> particles,
            String description, boolean whileRunning, Mover mover) {
        this(what, grip, effect, particles, description, "", whileRunning, mover);
    }

    /**
     * Declare a draggable thing whose description ends in a note on when it works, which
     * the help writes once for a sphere and its arrow tip declared one after the other
     * ({@link DragControl#helpRows}).
     *
     * @param what the particles as the help names them, e.g. "a sphere" (not null, not empty)
     * @param grip what the mouse takes hold of (not null)
     * @param effect what a drag changes (not null)
     * @param particles the particles that offer the grip (not null, not empty; copied)
     * @param summary what moving it changes, e.g. "launch P0" (not null, not empty)
     * @param note when and how, e.g. {@link #PAUSED_NOTE}, appended to the summary (not
     *     null; may be empty)
     * @param whileRunning true if it may be dragged while the clock runs; false: a press on
     *     it pauses the simulation first
     * @param mover takes each new value (not null)
     */
    public Draggable(String what, Grip grip, Effect effect, List<DemoParticle> particles,
            String summary, String note, boolean whileRunning, Mover mover) {
        if (what == null || what.isEmpty() || summary == null || summary.isEmpty()
                || note == null) {
            throw new IllegalArgumentException("a draggable needs a name and a description,"
                    + " but had " + what + " and " + summary);
        }
        if (grip == null || effect == null || mover == null) {
            throw new IllegalArgumentException("a draggable's grip, effect and mover must not"
                    + " be null (" + what + ")");
        }
        if (particles == null || particles.isEmpty()) {
            throw new IllegalArgumentException("a draggable needs at least one particle ("
                    + what + ")");
        }
        for (int i = 0; i < particles.size(); ++i) {
            if (particles.get(i) == null) {
                throw new IllegalArgumentException("particle " + i + " of draggable " + what
                        + " is null");
            }
        }
        this.what = what;
        this.grip = grip;
        this.effect = effect;
        this.particles = List.copyOf(particles);
        this.summary = summary;
        this.note = note;
        this.whileRunning = whileRunning;
        this.mover = mover;
    }

    /**
     * Declare the drag of a launch position: every particle's launch moves by the same
     * amount as the gripped one's, which goes under the mouse; y stays &ge; 0 (above the
     * ground). Paused only.
     *
     * @param what the particles as the help names them (not null)
     * @param particles the particles launched together (not null, not empty)
     * @return the declaration (not null)
     */
    public static Draggable launchPosition(String what, List<DemoParticle> particles) {
        List<DemoParticle> group = List.copyOf(particles);
        Vector3f launchPosition = new Vector3f();
        Vector3f launchVelocity = new Vector3f();
        Vector3f offset = new Vector3f();
        return new Draggable(what, Grip.BODY, Effect.LAUNCH, group,
                "launch P0" + ofAll(countShown(group)), PAUSED_NOTE,
                false, (particle, point) -> {
                    offset.set(point.x, Math.max(0f, point.y), 0f)
                            .subtractLocal(particle.copyLaunchPosition(launchPosition));
                    for (int i = 0; i < group.size(); ++i) {
                        DemoParticle each = group.get(i);
                        each.copyLaunchPosition(launchPosition).addLocal(offset);
                        each.setLaunch(launchPosition, each.copyLaunchVelocity(launchVelocity));
                    }
                });
    }

    /**
     * Declare the drag of a launch velocity by its arrow's tip, set on every particle
     * directly (for a demo whose launch is no parameter). Paused only.
     *
     * @param what the particles as the help names them (not null)
     * @param particles the particles launched together (not null, not empty)
     * @return the declaration (not null)
     */
    public static Draggable launchVelocity(String what, List<DemoParticle> particles) {
        List<DemoParticle> group = List.copyOf(particles);
        Vector3f launchPosition = new Vector3f();
        return new Draggable(what, Grip.ARROW_TIP, Effect.LAUNCH, group,
                "launch V0" + ofAll(countShown(group)), PAUSED_NOTE,
                false, (particle, velocity) -> {
                    for (int i = 0; i < group.size(); ++i) {
                        DemoParticle each = group.get(i);
                        each.setLaunch(each.copyLaunchPosition(launchPosition), velocity);
                    }
                });
    }

    /** @return the particles as the help names them (not null) */
    public String getWhat() {
        return what;
    }

    /** @return what the mouse takes hold of (not null) */
    public Grip getGrip() {
        return grip;
    }

    /** @return what a drag changes (not null) */
    public Effect getEffect() {
        return effect;
    }

    /** @return the particles that offer the grip (unmodifiable, not null, not empty) */
    public List<DemoParticle> getParticles() {
        return particles;
    }

    /** @return what moving it does and when: the summary and the note (not null) */
    public String getDescription() {
        return summary + note;
    }

    /** @return what moving it changes, without the note (not null) */
    public String getSummary() {
        return summary;
    }

    /** @return when and how it works, appended to the summary (not null, may be empty) */
    public String getNote() {
        return note;
    }

    /** @return true if it may be dragged while the clock runs */
    public boolean isDraggableWhileRunning() {
        return whileRunning;
    }

    /**
     * Return how the help and the pages' table name the gesture: "drag a sphere", "drag a
     * sphere's arrow tip".
     *
     * @return the label (not null)
     */
    public String getGestureLabel() {
        return grip == Grip.BODY ? "drag " + what : "drag " + what + "'s arrow tip";
    }

    /**
     * Hand a new value to the mover.
     *
     * @param particle the particle whose grip is held (one of {@link #getParticles()})
     * @param value a position (m) or a velocity (m/s), as the grip says (not null)
     */
    public void moveTo(DemoParticle particle, Vector3f value) {
        mover.moveTo(particle, value);
    }

    /**
     * Name a group of particles launched together, for a description.
     *
     * @param count how many (&ge;1)
     * @return "" for one, " of both" for two, " of all N" for more
     */
    public static String ofAll(int count) {
        return count == 1 ? "" : count == 2 ? " of both" : " of all " + count;
    }

    /**
     * Count the particles of a group that are shown, for a description: a parked one (a
     * comparison lane's sphere, moved with the launch but off unless chosen) is left out.
     *
     * @param group the particles launched together (not null)
     * @return how many are not parked (at least 1)
     */
    public static int countShown(List<DemoParticle> group) {
        int shown = 0;
        for (int i = 0; i < group.size(); ++i) {
            if (!group.get(i).isParked()) {
                ++shown;
            }
        }
        return Math.max(1, shown);
    }

    @Override
    public String toString() {
        return getGestureLabel() + ": " + getDescription();
    }
}

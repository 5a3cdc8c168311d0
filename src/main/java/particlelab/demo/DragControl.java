package particlelab.demo;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.BooleanSupplier;
import particlelab.physics.SimulationClock;
import particlelab.view.ParticleView;
import particlelab.view.PlanePick;

/**
 * The mouse on a demo's bodies: a press picks the grip under it (a sphere, or the tip of a
 * velocity arrow, of a {@link Draggable} the demo declared; else any sphere, to inspect it),
 * moves drag it in the plane of the body's motion, a release lets go. What is picked stays
 * picked, for the inspector, until a press on empty space. Driven by the window's mouse
 * (the application's pick input) or by a test, with a {@link Camera} only: no application.
 *
 * <p>A drag starts once the mouse has moved {@value #DRAG_START_PIXELS} pixels from the
 * press, so a click only picks. At its start a drag that may not run with the clock pauses
 * it; a drag of the {@link Draggable.Effect#LAUNCH launch} starts the scene again at t = 0 (a
 * reset: the ended flight becomes a kept shot) and again after each move, so the exact ghosts
 * and readouts follow the new launch while the mouse moves.
 */
public final class DragControl {

    /**
     * Told of every drag (a recording, issue 33): its start, each value handed to
     * {@link Draggable#moveTo}, its end; {@link #startDrag}, {@link #dragTo} and
     * {@link #release} do the same again from what it was told.
     */
    public interface Listener {
        /**
         * @param draggable the grip's declaration, its index in {@link #getDraggables()}
         * @param particle the particle, its index in the declaration's particles
         */
        void dragStarted(int draggable, int particle);

        /** @param value the value handed to moveTo (not null, not to be kept) */
        void draggedTo(Vector3f value);

        /** The drag ended. */
        void dragEnded();
    }

    /** How far the mouse moves from the press before a drag starts (in pixels). */
    public static final float DRAG_START_PIXELS = 3f;
    /** The least pick radius around a sphere's centre or an arrow's tip (in pixels). */
    public static final float MIN_PICK_PIXELS = 12f;
    /** The gesture that turns the camera (the window maps it; the footer names it). */
    public static final String CAMERA_GESTURE = "right drag";
    /** The gesture that picks a body for the inspector, and what it does. */
    public static final String CLICK_GESTURE = "click a sphere";
    /** What a click does, for the help. */
    public static final String CLICK_DESCRIPTION = "inspect P, V, m, forces";

    /**
     * What a press on nothing else may choose (the derivative lens's step dots): asked in
     * the order added, after the grips and the spheres, until one takes the press.
     */
    @FunctionalInterface
    public interface ClickTarget {
        /**
         * Take a press at a screen point, if it is on this target.
         *
         * @param camera the camera the scene is drawn with (not null, not modified)
         * @param screenX the point's x (in pixels from the window's left edge)
         * @param screenY the point's y (in pixels from the window's bottom edge)
         * @return true if the press chose something here (no later target is asked)
         */
        boolean click(Camera camera, float screenX, float screenY);
    }

    private final List<Draggable> draggables = new ArrayList<>();
    private final List<ClickTarget> clickTargets = new ArrayList<>();
    private final List<Draggable> draggablesView = Collections.unmodifiableList(draggables);
    private final List<DemoParticle> particles;
    private final SimulationClock clock;
    private final Runnable restart;
    /** Frames what the launches reach, once a drag has ended (not during it). */
    private final Runnable dragEnded;
    private final PlanePick pick = new PlanePick();
    /** Whether arrows are drawn (an arrow tip is a grip only then). */
    private final BooleanSupplier arrowsShown;
    /** The spheres' radius as drawn (in metres). */
    private float sphereRadius = 0.3f;
    /** The particle picked last (the inspector's), or null. */
    private DemoParticle picked;
    /** The grip held down, or null. */
    private Draggable held;
    /** Whether the last press was taken by a click target. */
    private boolean clickTaken;
    /** Whether the held grip has started to drag. */
    private boolean dragging;
    private float pressX;
    private float pressY;
    /** The plane the held grip moves in (z, in metres). */
    private float planeZ;
    /** How many moves changed something since the demo was created. */
    private int moves;
    /** Told of every drag, or null. */
    private Listener listener;
    /** Scratch: the plane point under the mouse (m), a grip's point (m), a value. */
    private final Vector3f point = new Vector3f();
    private final Vector3f gripPoint = new Vector3f();
    private final Vector3f rim = new Vector3f();
    private final Vector3f value = new Vector3f();

    /**
     * Create the control of a demo's bodies.
     *
     * @param particles the demo's particles (not null, live)
     * @param clock the demo's clock, paused by a drag that needs it (not null)
     * @param restart starts the scene again at t = 0 (the demo's reset, not null); while
     *     a drag is on it must not move the camera, so the grip stays under the mouse
     * @param dragEnded run when a drag ends: the camera may frame the new launch (not null)
     * @param arrowsShown tells whether velocity arrows are drawn (not null)
     */
    DragControl(List<DemoParticle> particles, SimulationClock clock, Runnable restart,
            Runnable dragEnded, BooleanSupplier arrowsShown) {
        this.particles = particles;
        this.clock = clock;
        this.restart = restart;
        this.dragEnded = dragEnded;
        this.arrowsShown = arrowsShown;
    }

    /**
     * Add a declaration; its particles must be the demo's.
     *
     * @param draggable the declaration (not null)
     * @return draggable
     */
    Draggable add(Draggable draggable) {
        if (draggable == null) {
            throw new IllegalArgumentException("draggable must not be null");
        }
        for (DemoParticle particle : draggable.getParticles()) {
            if (!particles.contains(particle)) {
                throw new IllegalArgumentException(draggable.getGestureLabel()
                        + ": its particle \"" + particle.getLabel() + "\" is not the demo's");
            }
        }
        draggables.add(draggable);
        return draggable;
    }

    /**
     * Set the spheres' radius as drawn, which sizes a sphere's pick radius.
     *
     * @param radiusMetres the radius (in metres, &gt;0)
     */
    void setSphereRadius(float radiusMetres) {
        sphereRadius = radiusMetres;
    }

    /**
     * Write the help's "Mouse" rows: each declaration's gesture and description, then the
     * click that inspects (the camera's gesture is in jME's section). A sphere and its arrow
     * tip declared one after the other, for the same particles with the same note, share one
     * row ("drag a sphere / its arrow tip  -  launch P0 / launch V0 (note)"), so the help
     * stays short enough to be set in legible columns.
     *
     * @param declared the declarations (not null)
     * @return new rows, each {gesture, description} (not null)
     */
    public static List<String[]> helpRows(List<Draggable> declared) {
        List<String[]> rows = new ArrayList<>();
        for (int i = 0; i < declared.size(); ++i) {
            Draggable draggable = declared.get(i);
            Draggable next = i + 1 < declared.size() ? declared.get(i + 1) : null;
            if (next != null && draggable.getGrip() == Draggable.Grip.BODY
                    && next.getGrip() == Draggable.Grip.ARROW_TIP
                    && next.getWhat().equals(draggable.getWhat())
                    && next.getNote().equals(draggable.getNote())
                    && next.getParticles().equals(draggable.getParticles())) {
                rows.add(new String[] {draggable.getGestureLabel() + " / its arrow tip",
                    draggable.getSummary() + " / " + next.getSummary() + draggable.getNote()});
                ++i;
            } else {
                rows.add(new String[] {draggable.getGestureLabel(),
                    draggable.getDescription()});
            }
        }
        rows.add(new String[] {CLICK_GESTURE, CLICK_DESCRIPTION});
        return rows;
    }

    /**
     * Add a target a press on no grip and no sphere may choose (a part's step dots).
     *
     * @param target the target (not null)
     */
    public void addClickTarget(ClickTarget target) {
        if (target == null) {
            throw new IllegalArgumentException("click target must not be null");
        }
        clickTargets.add(target);
    }

    /** @return the declarations, in declaration order (unmodifiable, live, not null) */
    public List<Draggable> getDraggables() {
        return draggablesView;
    }

    /**
     * Press the button at a screen point: pick the grip there (the nearest within its pick
     * radius), or, where there is none, the nearest sphere to inspect, or else hand the press
     * to the click targets (a step dot); a press on empty space picks nothing (the inspector
     * closes).
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @return true if a body or grip was picked, or a click target took the press
     */
    public boolean press(Camera camera, float screenX, float screenY) {
        clickTaken = false;
        held = null;
        dragging = false;
        picked = null;
        pressX = screenX;
        pressY = screenY;
        float best = Float.POSITIVE_INFINITY;
        for (int d = 0; d < draggables.size(); ++d) {
            Draggable draggable = draggables.get(d);
            if (draggable.getGrip() == Draggable.Grip.ARROW_TIP && !arrowsShown.getAsBoolean()) {
                continue;
            }
            List<DemoParticle> grips = draggable.getParticles();
            for (int i = 0; i < grips.size(); ++i) {
                DemoParticle particle = grips.get(i);
                if (particle.isParked() && draggable.getGrip() == Draggable.Grip.ARROW_TIP) {
                    continue;
                }
                copyGripPoint(draggable.getGrip(), particle, gripPoint);
                float distance = pick.screenDistance(camera, gripPoint, screenX, screenY);
                if (distance <= pickRadius(camera, draggable.getGrip(), gripPoint)
                        && distance < best) {
                    best = distance;
                    held = draggable;
                    picked = particle;
                }
            }
        }
        if (held != null) {
            planeZ = picked.getParticle().position.z;
            return true;
        }
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.isParked()) {
                continue;
            }
            gripPoint.set(particle.getParticle().position);
            float distance = pick.screenDistance(camera, gripPoint, screenX, screenY);
            if (distance <= pickRadius(camera, Draggable.Grip.BODY, gripPoint)
                    && distance < best) {
                best = distance;
                picked = particle;
            }
        }
        if (picked != null) {
            return true;
        }
        for (int i = 0; i < clickTargets.size(); ++i) {
            if (clickTargets.get(i).click(camera, screenX, screenY)) {
                clickTaken = true;
                return true;
            }
        }
        return false;
    }

    /** @return true if the last press was taken by a click target (a step dot) */
    public boolean wasClickTaken() {
        return clickTaken;
    }

    /**
     * Move the mouse with the button down: drag the grip held, if any, to the plane point
     * under the mouse.
     *
     * @param camera the camera the scene is drawn with (not null, not modified)
     * @param screenX the point's x (in pixels from the window's left edge)
     * @param screenY the point's y (in pixels from the window's bottom edge)
     * @return true if the move dragged something
     */
    public boolean move(Camera camera, float screenX, float screenY) {
        if (held == null) {
            return false;
        }
        if (!dragging) {
            if (Math.hypot(screenX - pressX, screenY - pressY) < DRAG_START_PIXELS) {
                return false;
            }
            beginDrag();
        }
        if (!pick.screenToPlane(camera, screenX, screenY, planeZ, point)) {
            return false;
        }
        if (held.getGrip() == Draggable.Grip.BODY) {
            value.set(point);
        } else {
            // The arrow is drawn from P to P + V·T: the tip at the mouse gives V.
            value.set(point).subtractLocal(picked.getParticle().position)
                    .divideLocal(ParticleView.ARROW_SECONDS);
            value.z = 0f;
        }
        dragTo(value);
        return true;
    }

    /**
     * Start a drag as a mouse's does, without a mouse: what a recording's replay does.
     *
     * @param draggable the declaration's index in {@link #getDraggables()}
     * @param particle the particle's index in the declaration's particles
     */
    public void startDrag(int draggable, int particle) {
        held = draggables.get(draggable);
        picked = held.getParticles().get(particle);
        planeZ = picked.getParticle().position.z;
        beginDrag();
    }

    /**
     * Hand a value to the grip being dragged, as a move of the mouse does after its pick.
     *
     * @param newValue the position or velocity to move to (in m or m/s, not null, not
     *     modified)
     * @throws IllegalStateException if no drag is on
     */
    public void dragTo(Vector3f newValue) {
        if (held == null || !dragging) {
            throw new IllegalStateException("no drag is on");
        }
        if (newValue != value) {
            value.set(newValue);
        }
        held.moveTo(picked, value);
        if (held.getEffect() == Draggable.Effect.LAUNCH) {
            restart.run();
        }
        ++moves;
        if (listener != null) {
            listener.draggedTo(value);
        }
    }

    /**
     * Tell a listener of every drag from now on (one at a time).
     *
     * @param newListener the listener, or null for none
     */
    public void setListener(Listener newListener) {
        listener = newListener;
    }

    /**
     * Release the button: the drag ends (the camera may now frame what the new launch
     * reaches); the picked body stays picked.
     *
     * @return true if a drag ended
     */
    public boolean release() {
        boolean ended = held != null && dragging;
        held = null;
        dragging = false;
        if (ended) {
            dragEnded.run();
            if (listener != null) {
                listener.dragEnded();
            }
        }
        return ended;
    }

    /**
     * Pick a particle for the inspector, as a click on its sphere does.
     *
     * @param particle one of the demo's particles, or null to pick nothing
     */
    public void inspect(DemoParticle particle) {
        if (particle != null && !particles.contains(particle)) {
            throw new IllegalArgumentException("only the demo's particles can be inspected,"
                    + " not \"" + particle.getLabel() + "\"");
        }
        release();
        picked = particle;
    }

    /** Forget the picked body (the inspector closes), e.g. at a change of scene. */
    public void clearPick() {
        release();
        picked = null;
    }

    /** @return the particle picked last (the inspector's), or null */
    public DemoParticle getPicked() {
        return picked;
    }

    /** @return the declaration whose grip is held down, or null */
    public Draggable getHeld() {
        return held;
    }

    /** @return true while a grip is being dragged */
    public boolean isDragging() {
        return dragging;
    }

    /** @return how many moves dragged something since the demo was created (&ge;0) */
    public int countMoves() {
        return moves;
    }

    /**
     * Copy where a grip of a particle is now: its centre, or its arrow's tip
     * {@code P + V·T}.
     *
     * @param grip the grip (not null)
     * @param particle the particle (not null)
     * @param storeResult storage for the point (in metres, not null, modified)
     * @return storeResult
     */
    public static Vector3f copyGripPoint(Draggable.Grip grip, DemoParticle particle,
            Vector3f storeResult) {
        storeResult.set(particle.getParticle().position);
        if (grip == Draggable.Grip.ARROW_TIP) {
            storeResult.x += particle.getParticle().velocity.x * ParticleView.ARROW_SECONDS;
            storeResult.y += particle.getParticle().velocity.y * ParticleView.ARROW_SECONDS;
        }
        return storeResult;
    }

    /** The drag of the held grip starts: the clock pauses, a launch starts again. */
    private void beginDrag() {
        dragging = true;
        if (listener != null) {
            listener.dragStarted(draggables.indexOf(held), held.getParticles().indexOf(picked));
        }
        if (!held.isDraggableWhileRunning()) {
            clock.setPaused(true);
        }
        if (held.getEffect() == Draggable.Effect.LAUNCH) {
            restart.run();
        }
    }

    /** How near a press must be to a grip at a point (pixels): the sphere as drawn, or more. */
    private float pickRadius(Camera camera, Draggable.Grip grip, Vector3f at) {
        if (grip == Draggable.Grip.ARROW_TIP) {
            return MIN_PICK_PIXELS;
        }
        rim.set(at).x += sphereRadius;
        return Math.max(MIN_PICK_PIXELS, pick.screenDistance(camera, at, rim));
    }
}

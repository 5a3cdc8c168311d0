package particlelab.world;

import com.jme3.math.Vector3f;
import particlelab.collision.Surface;

/**
 * One contact found in a step, as it goes through the lecture's three phases: detected by a
 * {@link CollisionRule}, then the <b>prologue</b> (ignore it? effects at the moment of impact),
 * the <b>collision</b> (resolve it), and the <b>epilogue</b> (destroy, spawn, score, sound).
 * Each phase writes what it decided here, and the world copies it into the {@link ContactLog}.
 *
 * <p>Contacts are pooled and reused every step: read them in a {@link ContactListener} call,
 * never keep one. The normal points from B (or the surface) towards A.
 */
public final class Contact {

    /** What the prologue decided. */
    public enum Prologue {
        /** Not looked at yet. */
        PENDING,
        /** Go on to the resolution. */
        ACCEPTED,
        /** Ignored: the collision groups and masks say these two never touch. */
        IGNORED_BY_FILTER,
        /** Ignored: one of the bodies is a ghost. */
        IGNORED_GHOST,
        /** Ignored: a one-way surface hit from behind (the velocity along its front normal). */
        IGNORED_ONE_WAY,
        /** Ignored by a {@link ContactListener#accept}: the scene's own rule. */
        IGNORED_BY_LISTENER
    }

    /** What the resolution did. */
    public enum Resolution {
        /** Not resolved (ignored, or not reached). */
        NONE,
        /** Physics: an impulse along the normal with the restitution e. */
        IMPULSE,
        /** Physics: approach speed at or below the threshold, so e = 0 (perfectly inelastic). */
        BELOW_THRESHOLD,
        /** Physics: the resting-contact fix removed the rebound the step's forces would give. */
        RESTING,
        /** Physics: already separating, so only the interpenetration was removed. */
        SEPARATING,
        /** Animation: the body stuck where it hit (held; a view plays its squash or fade). */
        STUCK,
        /** Animation: both bodies stopped at the touch, kinematic, and handed to a clip. */
        CLIP,
        /** Both sides have infinite mass (static or kinematic): nothing can move. */
        IMMOVABLE
    }

    final Vector3f point = new Vector3f();
    final Vector3f normal = new Vector3f();
    CollisionRule rule;
    Body bodyA;
    Body bodyB;
    Surface surface;
    float fraction;
    double timeSeconds;
    boolean swept;
    float approachSpeed;
    float penetrationMetres;
    /** The closing speed now, refreshed while the overlap contacts are resolved (m/s). */
    float closingNow;
    /** The penetration now, refreshed likewise (in metres). */
    float penetrationNow;
    float impulse;
    /** The kinetic energy the resolution took, in the contact's frame (J): the impact's. */
    double impactLossJoules;
    /** What the resolution gave the bodies beyond that, a kinematic body's push (J). */
    double scriptWorkJoules;
    Prologue prologue = Prologue.PENDING;
    Resolution resolution = Resolution.NONE;
    String epilogueNote;
    long sequence;

    Contact() {
    }

    /**
     * Access body A, the body the normal points towards.
     *
     * @return the live body (not null)
     */
    public Body getBodyA() {
        return bodyA;
    }

    /**
     * Access body B.
     *
     * @return the live body, or null when A hit a static surface
     */
    public Body getBodyB() {
        return bodyB;
    }

    /**
     * Access the static surface A hit.
     *
     * @return the surface, or null for a contact between two bodies
     */
    public Surface getSurface() {
        return surface;
    }

    /**
     * Access the rule that found the contact.
     *
     * @return the rule (not null)
     */
    public CollisionRule getRule() {
        return rule;
    }

    /**
     * Return when inside the step the contact happened: the time of impact of the swept test,
     * or 1 (the step's end) for the overlap test, which only sees the end.
     *
     * @return the fraction of the step (0 to 1)
     */
    public float getFraction() {
        return fraction;
    }

    /**
     * Return the world time of the contact: the step's start plus {@code fraction·h}.
     *
     * @return the time (in seconds)
     */
    public double getTimeSeconds() {
        return timeSeconds;
    }

    /**
     * Test whether the swept test found this contact (else the overlap test).
     *
     * @return true if swept
     */
    public boolean isSwept() {
        return swept;
    }

    /**
     * Access the contact point (on B's surface, or on the static surface).
     *
     * @return the live point (in metres, not null)
     */
    public Vector3f getPoint() {
        return point;
    }

    /**
     * Access the unit normal, from B (or the surface) towards A.
     *
     * @return the live normal (not null)
     */
    public Vector3f getNormal() {
        return normal;
    }

    /**
     * Return the normal approach speed when the contact was found,
     * {@code −(V_A − V_B)·n}: positive when closing.
     *
     * @return the speed (in m/s)
     */
    public float getApproachSpeed() {
        return approachSpeed;
    }

    /**
     * Return how deep A is inside B or the surface along the normal (0 for a swept contact,
     * found at the touch).
     *
     * @return the depth (in metres)
     */
    public float getPenetration() {
        return penetrationMetres;
    }

    /**
     * Return the impulse the resolution applied along the normal, {@code j} in
     * {@code V_A += j·n/m_A}, {@code V_B −= j·n/m_B}.
     *
     * @return j (in N·s), 0 if none
     */
    public float getImpulse() {
        return impulse;
    }

    /**
     * Return the kinetic energy the resolution took from the bodies, measured in the frame of
     * the contact (the static or kinematic side at rest): {@code ½·μ·(1−e²)·v_n²} for an
     * impulse with restitution e, {@code ½m|V|²} for a stick.
     *
     * @return the energy (in J), 0 if none
     */
    public double getImpactLossJoules() {
        return impactLossJoules;
    }

    /**
     * Return the kinetic energy the resolution gave the dynamic bodies beyond the impact's
     * loss: the work of a kinematic body that hit them (a scripted paddle), 0 against a static
     * surface or between two dynamic bodies.
     *
     * @return the work (in J)
     */
    public double getScriptWorkJoules() {
        return scriptWorkJoules;
    }

    /**
     * Return what the prologue decided.
     *
     * @return the decision (not null)
     */
    public Prologue getPrologue() {
        return prologue;
    }

    /**
     * Test whether the prologue ignored the contact.
     *
     * @return true if ignored (no resolution, no epilogue)
     */
    public boolean isIgnored() {
        return prologue != Prologue.ACCEPTED && prologue != Prologue.PENDING;
    }

    /**
     * Return what the resolution did.
     *
     * @return the decision (not null)
     */
    public Resolution getResolution() {
        return resolution;
    }

    /**
     * Return what the epilogue noted (for example "destroyed target").
     *
     * @return the note, or null
     */
    public String getEpilogueNote() {
        return epilogueNote;
    }

    /**
     * Note what the epilogue did with this contact, for the log and the HUD.
     *
     * @param note a short constant text, e.g. "destroyed target" (may be null; not copied,
     *     so pass a constant to allocate nothing)
     */
    public void setEpilogueNote(String note) {
        epilogueNote = note;
    }

    /**
     * Return the closing speed at the current state, {@code −(V_A − V_B)·n}, which the
     * resolution changes (a response reads this, not {@link #getApproachSpeed()}).
     *
     * @return the speed (in m/s, positive when closing)
     */
    public float getClosingSpeedNow() {
        return closingNow;
    }

    /**
     * Return the penetration still to remove along the normal.
     *
     * @return the depth (in metres)
     */
    public float getPenetrationNow() {
        return penetrationNow;
    }

    /**
     * Return the contact's number in the world, counting every contact found.
     *
     * @return the sequence number (&ge;0)
     */
    public long getSequence() {
        return sequence;
    }

    /**
     * Test whether this contact is between the same two things as another.
     *
     * @param other the other contact (not null)
     * @return true if the same rule, bodies and surface, in either order
     */
    boolean samePair(Contact other) {
        if (rule != other.rule || surface != other.surface) {
            return false;
        }
        return bodyA == other.bodyA && bodyB == other.bodyB
                || bodyA == other.bodyB && bodyB == other.bodyA;
    }

    void copyFrom(Contact source) {
        point.set(source.point);
        normal.set(source.normal);
        rule = source.rule;
        bodyA = source.bodyA;
        bodyB = source.bodyB;
        surface = source.surface;
        fraction = source.fraction;
        timeSeconds = source.timeSeconds;
        swept = source.swept;
        approachSpeed = source.approachSpeed;
        penetrationMetres = source.penetrationMetres;
        closingNow = source.closingNow;
        penetrationNow = source.penetrationNow;
        impulse = source.impulse;
        impactLossJoules = source.impactLossJoules;
        scriptWorkJoules = source.scriptWorkJoules;
        prologue = source.prologue;
        resolution = source.resolution;
        epilogueNote = source.epilogueNote;
        sequence = source.sequence;
    }

    /** Forget every reference and decision, so a pooled contact keeps nothing alive. */
    void clear() {
        rule = null;
        bodyA = null;
        bodyB = null;
        surface = null;
        prologue = Prologue.PENDING;
        resolution = Resolution.NONE;
        epilogueNote = null;
        impulse = 0f;
        impactLossJoules = 0.0;
        scriptWorkJoules = 0.0;
        penetrationMetres = 0f;
        closingNow = 0f;
        penetrationNow = 0f;
        approachSpeed = 0f;
        fraction = 0f;
        swept = false;
    }

    @Override
    public String toString() {
        return "Contact#" + sequence + "[t=" + timeSeconds + " s, A=" + bodyA + ", B="
                + (bodyB != null ? bodyB : surface != null ? surface.describe() : "none")
                + ", n=" + normal + ", approach=" + approachSpeed + " m/s, " + prologue + ", "
                + resolution + ", j=" + impulse + " N s]";
    }
}

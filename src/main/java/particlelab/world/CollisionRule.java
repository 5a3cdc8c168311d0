package particlelab.world;

/**
 * A collision rule of a scene: which things can touch, how contacts are detected, and how
 * they are resolved. {@link SurfaceRule} (bodies against a static surface) and
 * {@link SphereRule} (bodies against each other) are the worked examples; a student's rule
 * implements this interface and is registered with {@link World#addRule}.
 */
public interface CollisionRule {

    /**
     * Return how this rule detects contacts.
     *
     * @return the detection (not null)
     */
    Detection getDetection();

    /**
     * Append the contacts found now. For {@link Detection#SWEPT}, each body moves from
     * {@link Body#copySegmentStart} (at {@link Body#getSegmentFraction()} of the step) to its
     * position (the step's end) on a straight line; report the first touch of each pair still
     * ahead, with its fraction of the whole step. For {@link Detection#OVERLAP}, report each
     * touching or overlapping pair at the step's end (fraction 1). Fill in the bodies, the
     * surface (if any), the fraction, the normal (from B towards A), the approach speed, the
     * penetration and the swept flag; set the closing speed and penetration "now" to the same.
     * Skip held bodies and pairs where neither side can move.
     *
     * @param world the world (not null)
     * @param stepSeconds h (in seconds, &gt;0)
     * @param out where to append (not null)
     */
    void detect(World world, float stepSeconds, Contacts out);

    /**
     * Recompute a contact's closing speed and penetration now from its bodies' state, keeping
     * its normal (the overlap resolver calls this between contacts).
     *
     * @param contact one of this rule's contacts (modified)
     */
    void refresh(Contact contact);

    /**
     * Return the response that resolves this rule's contacts.
     *
     * @return the response (not null)
     */
    ContactResponse getResponse();

    /**
     * Return the groups a static surface of this rule belongs to (bodies' groups are their
     * own).
     *
     * @return group bits
     */
    default int getGroup() {
        return Body.DEFAULT_GROUP;
    }

    /**
     * Return the groups a static surface of this rule may touch.
     *
     * @return mask bits
     */
    default int getMask() {
        return Body.ALL_GROUPS;
    }

    /**
     * Test whether the rule's surface is one-way: a body moving along its front normal
     * ({@code V·n ≥ 0}, coming from behind) passes through.
     *
     * @return true if one-way
     */
    default boolean isOneWay() {
        return false;
    }

    /**
     * Describe the rule for a HUD or a report.
     *
     * @return its shape, detection and response, e.g. {@code "ground y = 0, swept, e = 0.5"}
     */
    String describe();
}

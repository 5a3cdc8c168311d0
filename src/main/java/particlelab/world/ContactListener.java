package particlelab.world;

/**
 * Hears the contacts of a {@link World}'s steps: the lecture's prologue and epilogue.
 *
 * <ul>
 * <li>{@link #accept} is the <b>prologue</b>, called once per contact before it is resolved,
 * at the moment of impact: return false to ignore the contact (a per-scene rule: friendly
 * fire, a pane that lets shots through), or start an effect (a flash at
 * {@link Contact#getPoint()}, a sound as loud as {@link Contact#getApproachSpeed()}). The
 * world's own filters (groups and masks, ghosts, one-way surfaces) run first.</li>
 * <li>{@link #resolved} is the <b>epilogue</b>, called after <em>every</em> contact of the
 * step has been resolved, in time order: destroy or spawn bodies ({@link World#destroy} waits
 * until the epilogue is over, so no loop is corrupted), count a score, queue a sound.</li>
 * </ul>
 * Ignored contacts reach no epilogue. Implementations should allocate nothing.
 */
public interface ContactListener {

    /**
     * Prologue: decide whether a contact is resolved.
     *
     * @param contact the contact (live, pooled: do not keep it)
     * @param world the world stepping (not null)
     * @return true to resolve it, false to ignore it (the bodies pass through each other)
     */
    default boolean accept(Contact contact, World world) {
        return true;
    }

    /**
     * Epilogue: propagate the effects of a resolved contact.
     *
     * @param contact the contact (live, pooled: do not keep it)
     * @param world the world stepping (not null)
     */
    default void resolved(Contact contact, World world) {
    }
}

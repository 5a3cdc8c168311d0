package particlelab.world;

/**
 * The collision phase of the pipeline: what happens to the bodies of an accepted contact.
 * {@link ImpulseResponse} is physics-based (an impulse with restitution);
 * {@link ScriptedResponse} is animation-based (a canned reaction). Implementations change V
 * and P of the contact's bodies in place, write {@link Contact}'s resolution and impulse, and
 * allocate nothing.
 */
public interface ContactResponse {

    /**
     * Resolve a contact. The world has placed the bodies where they are at the contact
     * (swept) or left them where the step ended (overlap); {@link Contact#getClosingSpeedNow()}
     * and {@link Contact#getPenetrationNow()} describe the state now.
     *
     * @param contact the contact (live, pooled; its bodies are modified)
     * @param stepSeconds h (in seconds, &gt;0)
     */
    void resolve(Contact contact, float stepSeconds);

    /**
     * Describe the response with its coefficients, for a HUD or a report.
     *
     * @return e.g. {@code "impulse, e = 0.5, threshold 0.25 m/s, resting fix on"}
     */
    String describe();
}

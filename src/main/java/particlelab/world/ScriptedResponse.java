package particlelab.world;

import com.jme3.math.Vector3f;
import particlelab.physics.Validate;

/**
 * Animation-based resolution: a scripted reaction instead of the physics. Body A (the body
 * that hit) does what the script says and B is left alone, so neither momentum nor the
 * physics energy loss {@code ½·μ·(1−e²)·v_n²} holds; that is the point of showing it.
 *
 * <ul>
 * <li>{@link #stick()}: A stops dead at the contact and is held; its
 * {@link Body#getScriptedSinceSeconds()} starts a canned squash or fade in the view. With a
 * point body on the ground this is the lecture's "stop at the ground".</li>
 * <li>{@link #authoredBounce(float)}: A leaves along the normal at an authored speed, whatever
 * it arrived with (a game's "always bounce this high").</li>
 * </ul>
 */
public final class ScriptedResponse implements ContactResponse {

    private final boolean stick;
    private final float reboundSpeed;

    private ScriptedResponse(boolean stick, float reboundSpeed) {
        this.stick = stick;
        this.reboundSpeed = reboundSpeed;
    }

    /**
     * Create the "stick and play a canned animation" response.
     *
     * @return a new response (not null)
     */
    public static ScriptedResponse stick() {
        return new ScriptedResponse(true, 0f);
    }

    /**
     * Create the "authored bounce" response.
     *
     * @param reboundSpeed the speed A leaves with along the normal (in m/s, finite, &ge;0)
     * @return a new response (not null)
     */
    public static ScriptedResponse authoredBounce(float reboundSpeed) {
        return new ScriptedResponse(false,
                Validate.nonNegative(reboundSpeed, "authored rebound speed (m/s)"));
    }

    @Override
    public void resolve(Contact contact, float stepSeconds) {
        Body a = contact.bodyA;
        Vector3f n = contact.normal;
        float depth = contact.penetrationNow;
        if (depth > 0f) {
            ImpulseResponse.addAlong(a.particle.position, n, depth);
            contact.penetrationNow = 0f;
        }
        Vector3f v = a.particle.velocity;
        float normalSpeed = v.dot(n);
        if (stick) {
            contact.impulse = -normalSpeed * a.getMass();
            v.zero();
            a.setHeld(true);
            contact.resolution = Contact.Resolution.STUCK;
        } else {
            float change = reboundSpeed - normalSpeed;
            contact.impulse = change * a.getMass();
            ImpulseResponse.addAlong(v, n, change);
            contact.resolution = Contact.Resolution.AUTHORED_BOUNCE;
        }
        a.startScript(contact.timeSeconds);
        contact.closingNow = 0f;
    }

    @Override
    public String describe() {
        return stick ? "scripted: stick" : "scripted: bounce at " + reboundSpeed + " m/s";
    }
}

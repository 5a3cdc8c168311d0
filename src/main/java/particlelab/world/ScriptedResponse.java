package particlelab.world;

import com.jme3.math.Vector3f;
import particlelab.physics.EnergyLedger;

/**
 * Animation-based resolution: a scripted reaction instead of the physics. The bodies do what
 * the script says, so neither momentum nor the physics energy loss
 * {@code ½·μ·(1−e²)·v_n²} holds; that is the point of showing it.
 *
 * <ul>
 * <li>{@link #stick()}: A (the body that hit) stops dead at the contact and is held, B is left
 * alone; A's {@link Body#getScriptedSinceSeconds()} starts a canned squash or fade in the
 * view. With a point body on the ground this is the lecture's "stop at the ground".</li>
 * <li>{@link #clip()}: both bodies stop where they touch and become kinematic, their
 * {@link Body#getScriptedSinceSeconds()} the contact's time: from then on an authored
 * {@link Clip} moves them (its keyframes, the same whatever the impact), through the
 * velocities a demo sets from it before each step.</li>
 * </ul>
 */
public final class ScriptedResponse implements ContactResponse {

    private final boolean stick;

    private ScriptedResponse(boolean stick) {
        this.stick = stick;
    }

    /**
     * Create the "stick and play a canned animation" response.
     *
     * @return a new response (not null)
     */
    public static ScriptedResponse stick() {
        return new ScriptedResponse(true);
    }

    /**
     * Create the "hand both bodies to a clip" response.
     *
     * @return a new response (not null)
     */
    public static ScriptedResponse clip() {
        return new ScriptedResponse(false);
    }

    /**
     * Tell whether this is the "hand both bodies to a clip" response.
     *
     * @return true for {@link #clip()}, false for {@link #stick()}
     */
    public boolean isClip() {
        return !stick;
    }

    @Override
    public void resolve(Contact contact, float stepSeconds) {
        Body a = contact.bodyA;
        Body b = contact.bodyB;
        Vector3f n = contact.normal;
        float depth = contact.penetrationNow;
        if (depth > 0f) {
            ImpulseResponse.addAlong(a.particle.position, n, depth);
            contact.penetrationNow = 0f;
        }
        Vector3f v = a.particle.velocity;
        // What A's momentum along n loses: the "impulse" a script takes away.
        contact.impulse = -v.dot(n) * a.getMass();
        if (stick) {
            // The stop takes A's whole kinetic energy: an impact's loss.
            contact.impactLossJoules += EnergyLedger.kineticJoules(a.particle);
        }
        v.zero();
        if (stick) {
            a.setHeld(true);
            contact.resolution = Contact.Resolution.STUCK;
        } else {
            a.setKinematic(true);
            if (b != null) {
                b.particle.velocity.zero();
                b.setKinematic(true);
                b.startScript(contact.timeSeconds);
            }
            contact.resolution = Contact.Resolution.CLIP;
        }
        a.startScript(contact.timeSeconds);
        contact.closingNow = 0f;
    }

    @Override
    public String describe() {
        return stick ? "scripted: stick" : "scripted: clip (keyframes from the contact)";
    }
}

package particlelab.world;

import com.jme3.math.Vector3f;
import particlelab.physics.EnergyLedger;
import particlelab.physics.Validate;

/**
 * Physics-based resolution: an impulse along the contact normal with restitution e, then the
 * interpenetration removed in proportion to inverse mass.
 *
 * <pre>
 *   separating speed   v_s = (V_A − V_B)·n          (negative: closing)
 *   wanted after       v_s' = −e·v_s
 *   impulse            j = (v_s' − v_s)/(1/m_A + 1/m_B) = −(1+e)·v_s/(1/m_A + 1/m_B)
 *   velocities         V_A += (j/m_A)·n,   V_B −= (j/m_B)·n
 *   interpenetration   P_A += d·(w_A/(w_A+w_B))·n,   P_B −= d·(w_B/(w_A+w_B))·n,   w = 1/m
 * </pre>
 * Momentum is unchanged, the separation speed is e times the approach speed and the kinetic
 * energy lost is {@code ½·μ·(1−e²)·v_s²}, {@code μ = m_A·m_B/(m_A+m_B)}. A static surface has
 * {@code 1/m = 0}; a kinematic body moving at u (infinite mass) sends A off at
 * {@code (1+e)·u − e·v} along n.
 *
 * <p>Resting contact: a ball lying on the ground closes at {@code g·h} in its next step (the
 * speed the step's gravity gave it), so plain restitution sends it back up, and a stepped
 * ball never settles: it hops for ever. Two remedies, each switchable so the difference can
 * be shown; only the second always works:
 * <ul>
 * <li><b>threshold</b> (Box2D, Jolt: 1 m/s; Cyclone's rigid bodies 0.25 m/s): a contact
 * closing at or below the threshold speed gets e = 0, perfectly inelastic. On the ground with
 * the swept test the hops end on an orbit of {@link HopCycle}, K whole steps a hop at the
 * impact speed {@code w* = K·g·h/(1+e)} or a cycle of several K, and the threshold stops the
 * ball only once one impact is at or below it (on a fixed point, {@code w* ≤ threshold}):
 * 0.25 m/s never stops a 4 m drop with e = 0.8 at h = 1/60 (w* = 0.363 m/s);</li>
 * <li><b>resting fix</b> (Cyclone's particle contacts): remove from the rebound the part due
 * to the velocity the forces added during this step, {@code Δv = h·a}: when
 * {@code (Δv_A − Δv_B)·n < 0}, {@code v_s' += e·(Δv_A − Δv_B)·n}, never below 0. A ball at
 * rest then stops exactly, and no hop can repeat ({@link HopCycle}). It also takes
 * {@code e·g·h} off every real bounce's rebound, as Cyclone's does.</li>
 * </ul>
 */
public final class ImpulseResponse implements ContactResponse {

    /** Cyclone's rigid-body restitution threshold (in m/s). */
    public static final float CYCLONE_THRESHOLD = 0.25f;
    /** Box2D's and Jolt's restitution threshold (in m/s). */
    public static final float BOX2D_THRESHOLD = 1f;

    private float restitution;
    private float thresholdSpeed;
    private boolean restingFix;
    /** Scratch: V_A − V_B (m/s). */
    private final Vector3f relative = new Vector3f();

    /**
     * Create a response with no threshold and the resting fix on.
     *
     * @param restitution e (from 0 to 1)
     */
    public ImpulseResponse(float restitution) {
        this(restitution, 0f, true);
    }

    /**
     * Create a response.
     *
     * @param restitution e (from 0 to 1)
     * @param thresholdSpeed contacts closing at or below this speed get e = 0 (in m/s,
     *     finite, &ge;0; 0: none)
     * @param restingFix true to remove the velocity the step's forces added (Cyclone)
     */
    public ImpulseResponse(float restitution, float thresholdSpeed, boolean restingFix) {
        setRestitution(restitution);
        setThresholdSpeed(thresholdSpeed);
        this.restingFix = restingFix;
    }

    /**
     * Return e.
     *
     * @return the restitution (0 to 1)
     */
    public float getRestitution() {
        return restitution;
    }

    /**
     * Alter e.
     *
     * @param newRestitution the restitution (from 0 to 1)
     */
    public void setRestitution(float newRestitution) {
        restitution = checkRestitution(newRestitution);
    }

    /**
     * Refuse a coefficient of restitution outside 0 to 1 (NaN included).
     *
     * @param restitution e
     * @return e
     * @throws IllegalArgumentException naming the value and the range
     */
    static float checkRestitution(float restitution) {
        if (!(restitution >= 0f && restitution <= 1f)) {
            throw new IllegalArgumentException(
                    "restitution e must be from 0 to 1, but was " + restitution);
        }
        return restitution;
    }

    /**
     * Return the restitution threshold.
     *
     * @return the speed (in m/s, &ge;0)
     */
    public float getThresholdSpeed() {
        return thresholdSpeed;
    }

    /**
     * Alter the restitution threshold.
     *
     * @param newThresholdSpeed the speed (in m/s, finite, &ge;0; 0: none)
     */
    public void setThresholdSpeed(float newThresholdSpeed) {
        thresholdSpeed = Validate.nonNegative(newThresholdSpeed, "restitution threshold (m/s)");
    }

    /**
     * Test whether the resting-contact fix is on.
     *
     * @return true if on
     */
    public boolean isRestingFix() {
        return restingFix;
    }

    /**
     * Switch the resting-contact fix.
     *
     * @param newRestingFix true for on
     */
    public void setRestingFix(boolean newRestingFix) {
        restingFix = newRestingFix;
    }

    @Override
    public void resolve(Contact contact, float stepSeconds) {
        Body a = contact.bodyA;
        Body b = contact.bodyB;
        float wa = a.getInverseMass();
        float wb = b == null ? 0f : b.getInverseMass();
        float w = wa + wb;
        if (w == 0f) {
            contact.resolution = Contact.Resolution.IMMOVABLE;
            return;
        }
        float shareA = wa / w;
        float shareB = wb / w;
        Vector3f n = contact.normal;
        relative.set(a.particle.velocity);
        if (b != null) {
            relative.subtractLocal(b.particle.velocity);
        }
        float separating = relative.dot(n);
        Contact.Resolution decision;
        if (separating < 0f) {
            float closing = -separating;
            float e = closing > thresholdSpeed ? restitution : 0f;
            decision = e == restitution ? Contact.Resolution.IMPULSE
                    : Contact.Resolution.BELOW_THRESHOLD;
            float wanted = -e * separating;
            if (restingFix) {
                relative.set(a.gainedVelocity);
                if (b != null) {
                    relative.subtractLocal(b.gainedVelocity);
                }
                float gained = relative.dot(n);
                if (gained < 0f) {
                    float fixed = Math.max(0f, wanted + e * gained);
                    if (fixed == 0f && wanted > 0f) {
                        decision = Contact.Resolution.RESTING;
                    }
                    wanted = fixed;
                }
            }
            float change = wanted - separating;
            double kineticBefore = dynamicKinetic(a, b, wa, wb);
            addAlong(a.particle.velocity, n, change * shareA);
            if (b != null) {
                addAlong(b.particle.velocity, n, -change * shareB);
            }
            contact.impulse += change / w;
            bookEnergy(contact, kineticBefore, dynamicKinetic(a, b, wa, wb), separating,
                    change, w, b != null && (wa == 0f || wb == 0f));
        } else {
            decision = Contact.Resolution.SEPARATING;
        }
        float depth = contact.penetrationNow;
        if (depth > 0f) {
            addAlong(a.particle.position, n, depth * shareA);
            if (b != null) {
                addAlong(b.particle.position, n, -depth * shareB);
            }
            contact.penetrationNow = 0f;
        }
        contact.closingNow = 0f;
        // An overlap contact may be resolved again for its penetration alone: keep what its
        // velocity resolution decided.
        if (decision != Contact.Resolution.SEPARATING
                || contact.resolution == Contact.Resolution.NONE) {
            contact.resolution = decision;
        }
    }

    @Override
    public String describe() {
        return "impulse, e = " + restitution
                + (thresholdSpeed > 0f ? ", threshold " + thresholdSpeed + " m/s" : "")
                + ", resting fix " + (restingFix ? "on" : "off");
    }

    /**
     * Book the energy of one resolution on the contact. Against a static surface or between
     * two dynamic bodies every joule of kinetic energy the bodies lost is the impact's. When
     * one side is a body of infinite mass that may move (kinematic, held), the impact's loss
     * is measured in its frame, {@code −j·(v_s + Δv_s/2)} with {@code j = Δv_s/(w_A + w_B)}
     * ({@code ½·μ·(1−e²)·v_s²} without the resting fix), and what the dynamic bodies gained
     * beyond it is the script's work.
     */
    private static void bookEnergy(Contact contact, double kineticBefore, double kineticAfter,
            float separating, float change, float inverseMassSum, boolean pushed) {
        double gained = kineticAfter - kineticBefore;
        if (!pushed) {
            contact.impactLossJoules -= gained;
            return;
        }
        double loss = -((double) change / inverseMassSum) * (separating + 0.5 * change);
        contact.impactLossJoules += loss;
        contact.scriptWorkJoules += gained + loss;
    }

    /** The kinetic energy ½m|V|² of the contact's bodies that have a finite mass (J). */
    private static double dynamicKinetic(Body a, Body b, float wa, float wb) {
        double sum = wa > 0f ? EnergyLedger.kineticJoules(a.particle) : 0.0;
        if (b != null && wb > 0f) {
            sum += EnergyLedger.kineticJoules(b.particle);
        }
        return sum;
    }

    /** vector += amount·n, in place. */
    static void addAlong(Vector3f vector, Vector3f n, float amount) {
        vector.set(vector.x + amount * n.x, vector.y + amount * n.y, vector.z + amount * n.z);
    }
}

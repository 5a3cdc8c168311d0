package particlelab.world;

import particlelab.physics.HeightScan;
import particlelab.physics.Validate;

/**
 * The lecture's ground {@code y = 0} for many particles at once, packed as
 * {@link particlelab.physics.ParticleBatch#stepPacked} packs them: the same contact as a
 * {@link World} with {@code SurfaceRule.ground(new ImpulseResponse(e, threshold, fix),
 * Detection.OVERLAP)} gives one body of radius r, as one small loop after the step instead of
 * a contact object per particle.
 *
 * <p>The rule, with the ground's normal {@code n = (0, 1, 0)} and its infinite mass (so the
 * particle takes the whole impulse and the whole position correction):
 * <pre>
 *   contact when        d = r − y ≥ 0                  (the overlap test, at the step's end)
 *   separating speed    v_s = V·n = vy                   (negative: closing)
 *   restitution         e' = e if −v_s &gt; threshold, else 0
 *   wanted after        v_s' = −e'·v_s
 *   resting fix         if Δvy &lt; 0: v_s' = max(0, v_s' + e'·Δvy),  Δvy = vy − vy_before
 *   velocity            vy ← vy + (v_s' − v_s)
 *   interpenetration    y ← y + d
 * </pre>
 * {@link ImpulseResponse} documents the same formula for two bodies; with {@code 1/m_B = 0} it
 * is the one above. As in the world, a contact is worked on only if it closes faster than
 * the world's tolerance (1e-6 m/s) or is deeper than its slop (1e-4 m), and the depth is
 * computed in double and rounded to float, as {@code Plane.overlap} does: one particle
 * bounces to the same bits as the world's body (a test checks it).
 *
 * <p>An instance holds e, the threshold and the fix; {@link #resolve} allocates nothing.
 */
public final class GroundBounce {

    private final float radiusMetres;
    private float restitution;
    private float thresholdSpeed;
    private boolean restingFix;

    /**
     * Create the ground for particles of one radius.
     *
     * @param radiusMetres the particles' radius r (in metres, finite, &ge;0)
     * @param restitution e (from 0 to 1)
     * @param thresholdSpeed contacts closing at or below this speed get e = 0 (in m/s,
     *     finite, &ge;0; 0: none)
     * @param restingFix true to take the velocity the step's forces added off the rebound
     *     (Cyclone's particle contacts: a particle at rest stays at rest)
     */
    public GroundBounce(float radiusMetres, float restitution, float thresholdSpeed,
            boolean restingFix) {
        this.radiusMetres = Validate.nonNegative(radiusMetres, "particle radius r (m)");
        setRestitution(restitution);
        this.thresholdSpeed = Validate.nonNegative(thresholdSpeed,
                "restitution threshold (m/s)");
        this.restingFix = restingFix;
    }

    /**
     * Return the particles' radius.
     *
     * @return r (in metres, &ge;0)
     */
    public float getRadius() {
        return radiusMetres;
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
        restitution = ImpulseResponse.checkRestitution(newRestitution);
    }

    /**
     * Test whether the resting fix is on.
     *
     * @return true if on
     */
    public boolean isRestingFix() {
        return restingFix;
    }

    /**
     * Resolve every particle's contact with the ground, after a step.
     *
     * @param positions P of every particle, planar as in {@code stepPacked} (in metres, length
     *     &ge; 3·count, modified: y of those in contact)
     * @param velocities V after the step, planar (in m/s, length &ge; 3·count, modified: vy of
     *     those in contact)
     * @param velocitiesYBefore vy of every particle before the step (in m/s, length &ge;
     *     count, not modified)
     * @param count the number of particles (&ge;0)
     * @param storeContacts where to write the index of each particle in contact this step, in
     *     increasing order (length &ge; count, modified from index 0 on)
     * @return how many particles were in contact: the indices written
     */
    public int resolve(float[] positions, float[] velocities, float[] velocitiesYBefore,
            int count, int[] storeContacts) {
        return resolve(positions, velocities, velocitiesYBefore, count, count, storeContacts);
    }

    /**
     * {@link #resolve(float[], float[], float[], int, int[])} for the first count particles
     * of arrays laid out for stride particles, as
     * {@link particlelab.physics.ParticleBatch#stepPacked(float[], float[], int, int,
     * float, float)} lays them out: y of particle i is {@code positions[stride + i]}.
     *
     * @param positions P, planar with the stride (in metres, length &ge; 3·stride, modified)
     * @param velocities V after the step, likewise (in m/s, length &ge; 3·stride, modified)
     * @param velocitiesYBefore vy of the first count particles before the step (in m/s,
     *     length &ge; count, not modified)
     * @param stride the particles the layout has room for (&ge;count)
     * @param count the particles to resolve, the first ones (&ge;0)
     * @param storeContacts as above (length &ge; count)
     * @return how many particles were in contact
     */
    public int resolve(float[] positions, float[] velocities, float[] velocitiesYBefore,
            int stride, int count, int[] storeContacts) {
        if (count < 0 || stride < count || positions.length < 3L * stride
                || velocities.length < 3L * stride || velocitiesYBefore.length < count
                || storeContacts.length < count) {
            throw new IllegalArgumentException("count must be >= 0 with 3*count positions and"
                    + " velocities and count previous vy and contact indices, but count was "
                    + count + (stride == count ? "" : " with a stride of " + stride));
        }
        // two passes: the contact test over every particle, then the rule on the few in
        // contact
        int contacts = HeightScan.findAtOrBelow(positions, stride, count, radiusMetres, 0,
                storeContacts, 0);
        for (int c = 0; c < contacts; ++c) {
            int i = storeContacts[c];
            resolveContact(positions, velocities, stride, i, velocitiesYBefore[i]);
        }
        return contacts;
    }

    /**
     * Resolve the contacts a step found itself: {@link
     * particlelab.physics.ParticleBatch#stepPackedFindingFloor} with the floor at r
     * finds the same particles as the contact test of {@link #resolve} (y &le; r) and gives
     * each one's vy before the step, so this applies the same rule to the same numbers as
     * resolve would, without a pass over every particle (and, given each block as the step
     * hands it on, while the block is in the cache).
     *
     * @param positions P, planar with the stride (in metres, modified: y of those in contact)
     * @param velocities V after the step, likewise (in m/s, modified: vy of those in contact)
     * @param stride the particles the layout has room for
     * @param contacts the indices of the particles in contact (not modified)
     * @param velocitiesYBefore vy before the step of each, at the same places (in m/s, not
     *     modified)
     * @param from the first contact to resolve (&ge;0)
     * @param to one past the last (from &le; to &le; both arrays' lengths)
     */
    public void resolveFound(float[] positions, float[] velocities, int stride, int[] contacts,
            float[] velocitiesYBefore, int from, int to) {
        if (from < 0 || to < from || to > contacts.length || to > velocitiesYBefore.length) {
            throw new IllegalArgumentException("the contacts to resolve must lie within 0 to "
                    + Math.min(contacts.length, velocitiesYBefore.length) + ", but were "
                    + from + " to " + to);
        }
        for (int c = from; c < to; ++c) {
            resolveContact(positions, velocities, stride, contacts[c], velocitiesYBefore[c]);
        }
    }

    /**
     * The rule of the class comment for particle i, which is in contact (y &le; r), its vy
     * before the step given.
     */
    private void resolveContact(float[] positions, float[] velocities, int stride, int i,
            float velocityYBefore) {
        int y = stride + i;
        float py = positions[y];
        float depth = (float) ((double) radiusMetres - py);
        float separating = velocities[y];
        if (!(-separating > World.CLOSING_TOLERANCE || depth > World.PENETRATION_TOLERANCE)) {
            return;
        }
        if (separating < 0f) {
            float closing = -separating;
            float bounce = closing > thresholdSpeed ? restitution : 0f;
            float wanted = -bounce * separating;
            if (restingFix) {
                float gained = separating - velocityYBefore;
                if (gained < 0f) {
                    wanted = Math.max(0f, wanted + bounce * gained);
                }
            }
            velocities[y] = separating + (wanted - separating);
        }
        if (depth > 0f) {
            positions[y] = py + depth;
        }
    }
}

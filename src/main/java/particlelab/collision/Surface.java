package particlelab.collision;

import com.jme3.math.Vector3f;

/**
 * A static surface a sphere can hit: infinite mass, never moves. Both detection approaches
 * are offered: {@link #sweep} over a straight segment (exact for the semi-implicit Euler step,
 * within which a particle moves on the straight line {@code P..P + h·V}) and {@link #overlap}
 * at one position.
 *
 * <p>Implementations allocate nothing and compute in double precision.
 */
public interface Surface {

    /** Returned by {@link #sweep} when the sphere does not hit the surface on the segment. */
    double NO_HIT = -1.0;

    /**
     * Sweep a sphere along a straight segment and find the first touch: the intersection test.
     * A hit needs the sphere to move towards the surface and to be inside it at the segment's
     * end (strictly); a sphere that starts touching or inside and moves deeper hits at 0.
     *
     * @param start the centre at the segment's start (in metres, not null, not modified)
     * @param end the centre at the segment's end (in metres, not null, not modified)
     * @param radiusMetres the sphere's radius r (in metres, &ge;0)
     * @param storeNormal storage for the contact normal, a unit vector pointing from the
     *     surface towards the sphere (not null, modified only on a hit)
     * @return the fraction of the segment at the first touch (0 to 1), or {@link #NO_HIT}
     */
    double sweep(Vector3f start, Vector3f end, float radiusMetres, Vector3f storeNormal);

    /**
     * Test a sphere at one position: the overlap test.
     *
     * @param centre the sphere's centre (in metres, not null, not modified)
     * @param radiusMetres the sphere's radius r (in metres, &ge;0)
     * @param storeNormal storage for the normal along which to push the sphere out, a unit
     *     vector pointing from the surface towards the sphere (not null, modified)
     * @return the penetration depth (in metres): &ge;0 when the sphere touches or overlaps
     *     the surface, negative (minus the gap) when it is clear
     */
    double overlap(Vector3f centre, float radiusMetres, Vector3f storeNormal);

    /**
     * Copy the surface's front normal, the side a one-way surface lets things hit.
     *
     * @param storeResult storage for the unit normal (not null, modified)
     * @return storeResult
     */
    Vector3f copyFrontNormal(Vector3f storeResult);

    /**
     * Describe the surface for a HUD or a report.
     *
     * @return e.g. {@code "plane n·x = 0, n = (0.0, 1.0, 0.0)"}
     */
    String describe();
}

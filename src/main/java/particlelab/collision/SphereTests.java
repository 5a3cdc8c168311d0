package particlelab.collision;

import com.jme3.math.Vector3f;

/**
 * Sphere-against-sphere detection, both approaches, in double precision, allocating nothing.
 *
 * <p>Swept test (NUMERICS): with the relative position {@code Δp = pA − pB} at the start and
 * the relative displacement {@code Δs = sA − sB} over the segment, the spheres touch where
 * {@code |Δp + u·Δs| = rA + rB}: {@code a·u² + b·u + c = 0} with {@code a = |Δs|²},
 * {@code b = 2·Δp·Δs}, {@code c = |Δp|² − (rA + rB)²}. They approach when {@code b < 0}; the
 * first root is {@code u = (−b − √(b² − 4ac))/(2a)}, computed as {@code 2c/(−b + √(b² − 4ac))},
 * which is the same number without the cancellation.
 */
public final class SphereTests {

    private SphereTests() {
    }

    /**
     * Sweep two spheres along straight segments covering the same time and find their first
     * touch, even when they would pass through each other within the segment. A hit needs them
     * to approach and to touch before the segments' end; two spheres that start touching or
     * overlapping and approach hit at 0.
     *
     * @param startA A's centre at the start (in metres, not null, not modified)
     * @param endA A's centre at the end (in metres, not null, not modified)
     * @param startB B's centre at the start (in metres, not null, not modified)
     * @param endB B's centre at the end (in metres, not null, not modified)
     * @param radiusSum {@code rA + rB} (in metres, &ge;0)
     * @return the fraction of the segments at the first touch (0 to 1), or
     *     {@link Surface#NO_HIT}
     */
    public static double sweep(Vector3f startA, Vector3f endA, Vector3f startB, Vector3f endB,
            float radiusSum) {
        double px = (double) startA.x - startB.x;
        double py = (double) startA.y - startB.y;
        double pz = (double) startA.z - startB.z;
        double sx = ((double) endA.x - startA.x) - ((double) endB.x - startB.x);
        double sy = ((double) endA.y - startA.y) - ((double) endB.y - startB.y);
        double sz = ((double) endA.z - startA.z) - ((double) endB.z - startB.z);
        double a = sx * sx + sy * sy + sz * sz;
        double b = 2.0 * (px * sx + py * sy + pz * sz);
        double reach = radiusSum;
        double c = px * px + py * py + pz * pz - reach * reach;
        if (!(b < 0.0)) {
            return Surface.NO_HIT;
        }
        if (c <= 0.0) {
            return 0.0;
        }
        double discriminant = b * b - 4.0 * a * c;
        if (discriminant < 0.0) {
            return Surface.NO_HIT;
        }
        double u = 2.0 * c / (-b + Math.sqrt(discriminant));
        // Strictly inside the segment, as for planes: touching exactly at the end is found at
        // the start of the next segment instead.
        return u < 1.0 ? u : Surface.NO_HIT;
    }

    /**
     * Test two spheres at one moment: the overlap test.
     *
     * @param centreA A's centre (in metres, not null, not modified)
     * @param centreB B's centre (in metres, not null, not modified)
     * @param radiusSum {@code rA + rB} (in metres, &ge;0)
     * @param storeNormal storage for the unit normal from B towards A (not null, modified;
     *     +y when the centres coincide)
     * @return the penetration depth {@code rA + rB − |pA − pB|} (in metres; &ge;0 when they
     *     touch or overlap)
     */
    public static double overlap(Vector3f centreA, Vector3f centreB, float radiusSum,
            Vector3f storeNormal) {
        double dx = (double) centreA.x - centreB.x;
        double dy = (double) centreA.y - centreB.y;
        double dz = (double) centreA.z - centreB.z;
        double distance = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (distance > 0.0) {
            storeNormal.set((float) (dx / distance), (float) (dy / distance),
                    (float) (dz / distance));
        } else {
            storeNormal.set(Vector3f.UNIT_Y);
        }
        return radiusSum - distance;
    }
}

package particlelab.collision;

import com.jme3.math.Vector3f;
import particlelab.physics.Validate;

/**
 * A static half-space: the solid is everything behind the plane {@code n·x = d}; its front,
 * where {@code n·x > d}, is open. The ground {@code y = 0} is {@link #ground()}; walls and
 * slanted planes are other normals and offsets. A sphere of radius r touches it when its
 * centre is at {@code n·p − d = r}.
 *
 * <p>Swept test (NUMERICS): on the segment {@code p(u) = p0 + u·s}, {@code 0 ≤ u ≤ 1}, the
 * sphere touches at {@code u = (r − (n·p0 − d))/(n·s)} when {@code n·s < 0}. Because a solid
 * half-space has no far side, the overlap test never misses it either; it only finds the
 * contact late (at the step's end, already inside).
 */
public final class Plane implements Surface {

    private final Vector3f normal = new Vector3f();
    private final float offsetMetres;

    /**
     * Create a plane {@code n·x = d}.
     *
     * @param normal the front normal n (finite, not zero, not null; copied and normalised)
     * @param offsetMetres d, the plane's signed distance from the origin along n (in metres,
     *     finite)
     */
    public Plane(Vector3f normal, float offsetMetres) {
        Validate.finite(normal, "plane normal");
        float length = normal.length();
        if (!(length > 0f) || !Float.isFinite(length)) {
            throw new IllegalArgumentException(
                    "plane normal must have a finite length > 0, but was " + normal);
        }
        this.normal.set(normal).divideLocal(length);
        this.offsetMetres = Validate.finite(offsetMetres, "plane offset d (m)");
    }

    /**
     * Create the lecture's ground: the plane {@code y = 0}, open above.
     *
     * @return a new plane with n = (0, 1, 0), d = 0 (not null)
     */
    public static Plane ground() {
        return new Plane(Vector3f.UNIT_Y, 0f);
    }

    /**
     * Return the signed distance of a point from the plane, {@code n·p − d}.
     *
     * @param point the point (in metres, not null, not modified)
     * @return the distance (in metres; positive in front)
     */
    public double distance(Vector3f point) {
        return (double) normal.x * point.x + (double) normal.y * point.y
                + (double) normal.z * point.z - offsetMetres;
    }

    /**
     * Return d.
     *
     * @return the offset (in metres)
     */
    public float getOffset() {
        return offsetMetres;
    }

    @Override
    public double sweep(Vector3f start, Vector3f end, float radiusMetres,
            Vector3f storeNormal) {
        double gapStart = distance(start) - radiusMetres;
        double gapEnd = distance(end) - radiusMetres;
        double hit = sweepGap(gapStart, gapEnd);
        if (hit != NO_HIT) {
            storeNormal.set(normal);
        }
        return hit;
    }

    @Override
    public double overlap(Vector3f centre, float radiusMetres, Vector3f storeNormal) {
        storeNormal.set(normal);
        return radiusMetres - distance(centre);
    }

    @Override
    public Vector3f copyFrontNormal(Vector3f storeResult) {
        return storeResult.set(normal);
    }

    @Override
    public String describe() {
        return "plane n·x = " + offsetMetres + " m, n = (" + normal.x + ", " + normal.y + ", "
                + normal.z + ")";
    }

    /**
     * The swept test along one axis: the gap (distance minus radius) goes linearly from
     * gapStart to gapEnd over the segment.
     *
     * @return the fraction where the gap reaches 0, 0 if it starts closed and closes further,
     *     or {@link #NO_HIT}
     */
    static double sweepGap(double gapStart, double gapEnd) {
        if (!(gapEnd < 0.0) || !(gapEnd < gapStart)) {
            return NO_HIT;
        }
        if (gapStart <= 0.0) {
            return 0.0;
        }
        return gapStart / (gapStart - gapEnd);
    }
}

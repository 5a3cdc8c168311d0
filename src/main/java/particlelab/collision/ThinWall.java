package particlelab.collision;

import com.jme3.math.Vector3f;
import particlelab.physics.Validate;

/**
 * A static wall of thickness D with two open sides: the solid slab
 * {@code |n·x − c| ≤ D/2} around its centre plane {@code n·x = c}, unbounded along the plane.
 * A sphere of radius r touches it when {@code |n·p − c| = r + D/2}.
 *
 * <p>This is the shape that shows tunnelling. The overlap test sees the sphere only if some
 * step ends with its centre inside the band of width {@code 2r + D}; a sphere that travels
 * {@code v·h > 2r + D} in a step can jump over the band, and for a uniformly random phase it
 * does so with probability {@code max(0, 1 − (2r + D)/(v·h))}. The swept test checks the whole
 * segment and never misses. The overlap test also pushes a sphere out of the nearer face, so a
 * sphere caught more than half-way through is seen but leaves by the far side.
 */
public final class ThinWall implements Surface {

    private final Plane centrePlane;
    private final Vector3f normal = new Vector3f();
    private final float thicknessMetres;

    /**
     * Create a thin wall.
     *
     * @param normal the front normal n (finite, not zero, not null; copied and normalised)
     * @param centreOffsetMetres c, the centre plane's signed distance from the origin along n
     *     (in metres, finite)
     * @param thicknessMetres D (in metres, finite, &gt;0)
     */
    public ThinWall(Vector3f normal, float centreOffsetMetres, float thicknessMetres) {
        this.centrePlane = new Plane(normal, centreOffsetMetres);
        centrePlane.copyFrontNormal(this.normal);
        this.thicknessMetres = Validate.positive(thicknessMetres, "wall thickness D (m)");
    }

    /**
     * Return D.
     *
     * @return the thickness (in metres, &gt;0)
     */
    public float getThickness() {
        return thicknessMetres;
    }

    /**
     * Return the miss probability of the overlap test for a sphere crossing the wall along
     * its normal at constant speed, with a uniformly random phase:
     * {@code max(0, 1 − (2r + D)/(v·h))}.
     *
     * @param radiusMetres r (in metres, &ge;0)
     * @param speed v (in m/s, &gt;0)
     * @param stepSeconds h (in seconds, &gt;0)
     * @return the probability (0 to 1)
     */
    public double overlapMissProbability(float radiusMetres, float speed, float stepSeconds) {
        double travel = (double) speed * stepSeconds;
        return Math.max(0.0, 1.0 - (2.0 * radiusMetres + thicknessMetres) / travel);
    }

    @Override
    public double sweep(Vector3f start, Vector3f end, float radiusMetres,
            Vector3f storeNormal) {
        double reach = radiusMetres + 0.5 * thicknessMetres;
        double sideStart = centrePlane.distance(start);
        double sideEnd = centrePlane.distance(end);
        // Hit the face on the side the centre starts on.
        double sign = sideStart >= 0.0 ? 1.0 : -1.0;
        double hit = Plane.sweepGap(sign * sideStart - reach, sign * sideEnd - reach);
        if (hit != NO_HIT) {
            storeNormal.set(normal).multLocal((float) sign);
        }
        return hit;
    }

    @Override
    public double overlap(Vector3f centre, float radiusMetres, Vector3f storeNormal) {
        double side = centrePlane.distance(centre);
        storeNormal.set(normal);
        if (side < 0.0) {
            storeNormal.negateLocal();
        }
        return radiusMetres + 0.5 * thicknessMetres - Math.abs(side);
    }

    @Override
    public Vector3f copyFrontNormal(Vector3f storeResult) {
        return storeResult.set(normal);
    }

    @Override
    public String describe() {
        return "thin wall |n·x - " + centrePlane.getOffset() + "| <= " + 0.5f * thicknessMetres
                + " m, n = (" + normal.x + ", " + normal.y + ", " + normal.z + ")";
    }
}

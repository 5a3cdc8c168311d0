package particlelab.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.VectorAssert;

/**
 * The swept and overlap tests against hand-worked geometry. Inputs are small decimals whose
 * float rounding (about 1e-7 relative) bounds the error of every fraction; 1e-6 allows that
 * with room.
 */
class CollisionGeometryTest {

    private static final double TOLERANCE = 1e-6;
    private final Vector3f normal = new Vector3f();

    @Test
    void sphereFallingOntoTheGroundTouchesWhereItsCentreIsOneRadiusUp() {
        // From y = 2 to y = -1, r = 0.5: the touch at y = 0.5 is half-way.
        double u = Plane.ground().sweep(new Vector3f(3f, 2f, 0f), new Vector3f(3f, -1f, 0f),
                0.5f, normal);
        assertEquals(0.5, u, TOLERANCE);
        VectorAssert.assertVectorEquals(Vector3f.UNIT_Y, normal, 0f);
    }

    @Test
    void planeSweepNeedsApproachAndAnEndInside() {
        Plane ground = Plane.ground();
        assertEquals(Surface.NO_HIT, ground.sweep(new Vector3f(0f, 2f, 0f),
                new Vector3f(0f, 0.6f, 0f), 0.5f, normal), "ends clear");
        assertEquals(Surface.NO_HIT, ground.sweep(new Vector3f(0f, 0.5f, 0f),
                new Vector3f(0f, 3f, 0f), 0.5f, normal), "moves away");
        assertEquals(0.0, ground.sweep(new Vector3f(0f, 0.5f, 0f), new Vector3f(0f, 0.4f, 0f),
                0.5f, normal), "starts touching and moves in");
    }

    @Test
    void slantedPlaneUsesItsOwnNormal() {
        // n = (1, 1, 0)/√2, d = 0; a point sphere moving along -x from x = 2 touches at x = 0.
        Plane slope = new Plane(new Vector3f(1f, 1f, 0f), 0f);
        double u = slope.sweep(new Vector3f(2f, 0f, 0f), new Vector3f(-2f, 0f, 0f), 0f, normal);
        assertEquals(0.5, u, TOLERANCE);
        float s = (float) Math.sqrt(0.5);
        VectorAssert.assertVectorEquals(new Vector3f(s, s, 0f), normal, 1e-7f);
        assertEquals(Math.sqrt(2.0) + 0.25, slope.overlap(new Vector3f(-1f, -1f, 0f), 0.25f,
                normal), TOLERANCE);
    }

    @Test
    void thinWallIsHitFromEitherSideEvenWhenTheSegmentJumpsOverIt() {
        // |x| <= 0.05, r = 0.1: reach 0.15. A segment from -1 to +1 jumps the whole wall.
        ThinWall wall = new ThinWall(Vector3f.UNIT_X, 0f, 0.1f);
        double u = wall.sweep(new Vector3f(-1f, 0f, 0f), new Vector3f(1f, 0f, 0f), 0.1f, normal);
        assertEquals((1.0 - 0.15) / 2.0, u, TOLERANCE);
        VectorAssert.assertVectorEquals(new Vector3f(-1f, 0f, 0f), normal, 0f);
        u = wall.sweep(new Vector3f(1f, 0f, 0f), new Vector3f(-1f, 0f, 0f), 0.1f, normal);
        assertEquals((1.0 - 0.15) / 2.0, u, TOLERANCE);
        VectorAssert.assertVectorEquals(Vector3f.UNIT_X, normal, 0f);
        // Both end points clear of the wall: the overlap test sees nothing at either.
        assertTrue(wall.overlap(new Vector3f(-1f, 0f, 0f), 0.1f, normal) < 0.0);
        assertTrue(wall.overlap(new Vector3f(1f, 0f, 0f), 0.1f, normal) < 0.0);
    }

    @Test
    void overlapMissProbabilityIsTheLectureFormula() {
        ThinWall wall = new ThinWall(Vector3f.UNIT_X, 0f, 0.2f);
        // v·h = 100/60 = 1.667 m, 2r + D = 0.4 m: 1 - 0.4/1.667 = 0.76.
        assertEquals(0.76, wall.overlapMissProbability(0.1f, 100f, 1f / 60f), 1e-6);
        assertEquals(0.0, wall.overlapMissProbability(0.1f, 10f, 1f / 60f), 0.0);
    }

    @Test
    void spheresHeadOnTouchWhenTheirCentresAreTheRadiiApart() {
        // A from 0 to 10 along x, B still at 5, rA + rB = 1: touch with A at 4, u = 0.4.
        Vector3f b = new Vector3f(5f, 0f, 0f);
        double u = SphereTests.sweep(new Vector3f(), new Vector3f(10f, 0f, 0f), b, b, 1f);
        assertEquals(0.4, u, TOLERANCE);
    }

    @Test
    void spheresThatPassThroughEachOtherInOneSegmentAreFound() {
        // Both move, crossing completely: A 0 -> 4, B 4 -> 0, reach 0.5: touch when the gap is
        // 0.5, after closing 3.5 of 8: u = 0.4375.
        double u = SphereTests.sweep(new Vector3f(), new Vector3f(4f, 0f, 0f),
                new Vector3f(4f, 0f, 0f), new Vector3f(), 0.5f);
        assertEquals(3.5 / 8.0, u, TOLERANCE);
    }

    @Test
    void glancingSpheresTouchWhereTheGapAlongTheLineCloses() {
        // A moves along x at offset y = 0.6 past B at the origin, reach 1: touch at
        // x = -sqrt(1 - 0.36) = -0.8; from x = -2 to 2, u = 1.2/4 = 0.3.
        Vector3f b = new Vector3f();
        double u = SphereTests.sweep(new Vector3f(-2f, 0.6f, 0f), new Vector3f(2f, 0.6f, 0f),
                b, b, 1f);
        assertEquals(0.3, u, TOLERANCE);
        assertEquals(Surface.NO_HIT, SphereTests.sweep(new Vector3f(-2f, 1.01f, 0f),
                new Vector3f(2f, 1.01f, 0f), b, b, 1f), "passes clear");
        assertEquals(Surface.NO_HIT, SphereTests.sweep(new Vector3f(2f, 0.6f, 0f),
                new Vector3f(4f, 0.6f, 0f), b, b, 1f), "moves away");
    }

    @Test
    void sphereOverlapDepthAndNormal() {
        double depth = SphereTests.overlap(new Vector3f(0f, 1.5f, 0f), new Vector3f(), 2f,
                normal);
        assertEquals(0.5, depth, TOLERANCE);
        VectorAssert.assertVectorEquals(Vector3f.UNIT_Y, normal, 0f);
    }

    @Test
    void badShapesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new Plane(Vector3f.ZERO, 0f));
        assertThrows(IllegalArgumentException.class,
                () -> new Plane(Vector3f.UNIT_Y, Float.NaN));
        assertThrows(IllegalArgumentException.class,
                () -> new ThinWall(Vector3f.UNIT_X, 0f, 0f));
    }
}

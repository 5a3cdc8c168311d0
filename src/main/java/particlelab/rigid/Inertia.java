package particlelab.rigid;

import com.jme3.math.Vector3f;
import particlelab.physics.Validate;

/**
 * The principal moments of inertia A, B, C (kg·m²) of a solid body about its body axes x, y,
 * z, through the centre of mass: the body-frame inertia {@code I = diag(A, B, C)}, immutable.
 *
 * <p>Every solid body has moments that satisfy the triangle inequality
 * ({@code A ≤ B + C}, and likewise for B and C), since {@code B + C − A = 2∫x²dm ≥ 0}; a flat
 * plate reaches equality. The factories for uniform solids:
 * <ul>
 * <li>sphere of radius r: {@code A = B = C = ⅖·m·r²};</li>
 * <li>box with sides a, b, c along x, y, z: {@code A = m(b² + c²)/12},
 * {@code B = m(a² + c²)/12}, {@code C = m(a² + b²)/12}.</li>
 * </ul>
 */
public final class Inertia {

    /**
     * How far a moment may exceed the sum of the other two, relative to that sum: a few float
     * roundings, so that a box of zero thickness (exactly a plate) is accepted.
     */
    private static final double TRIANGLE_SLACK = 4.0 * Math.ulp(1f);

    private final float a;
    private final float b;
    private final float c;

    private Inertia(float a, float b, float c) {
        this.a = a;
        this.b = b;
        this.c = c;
    }

    /**
     * Principal moments given directly.
     *
     * @param a A, about the body x axis (in kg·m², finite, &gt;0, &le; B + C)
     * @param b B, about the body y axis (in kg·m², finite, &gt;0, &le; A + C)
     * @param c C, about the body z axis (in kg·m², finite, &gt;0, &le; A + B)
     * @return the inertia (not null)
     * @throws IllegalArgumentException if a moment is not finite and &gt;0 or exceeds the sum
     *     of the other two
     */
    public static Inertia of(float a, float b, float c) {
        Validate.positive(a, "moment of inertia A (kg*m^2)");
        Validate.positive(b, "moment of inertia B (kg*m^2)");
        Validate.positive(c, "moment of inertia C (kg*m^2)");
        checkTriangle("A", a, b, c);
        checkTriangle("B", b, a, c);
        checkTriangle("C", c, a, b);
        return new Inertia(a, b, c);
    }

    /**
     * A uniform solid sphere: {@code ⅖·m·r²} about every axis.
     *
     * @param massKg m (in kg, finite, &gt;0)
     * @param radiusMetres r (in metres, finite, &gt;0)
     * @return the inertia (not null)
     */
    public static Inertia sphere(float massKg, float radiusMetres) {
        Validate.positive(massKg, "mass (kg)");
        Validate.positive(radiusMetres, "sphere radius (m)");
        float moment = (float) (0.4 * massKg * radiusMetres * radiusMetres);
        return of(moment, moment, moment);
    }

    /**
     * A uniform solid box: {@code m(b² + c²)/12} about the axis along side a, and likewise.
     *
     * @param massKg m (in kg, finite, &gt;0)
     * @param sideX a, the side along the body x axis (in metres, finite, &gt;0)
     * @param sideY b, along y (in metres, finite, &gt;0)
     * @param sideZ c, along z (in metres, finite, &gt;0)
     * @return the inertia (not null)
     */
    public static Inertia box(float massKg, float sideX, float sideY, float sideZ) {
        Validate.positive(massKg, "mass (kg)");
        Validate.positive(sideX, "box side a (m)");
        Validate.positive(sideY, "box side b (m)");
        Validate.positive(sideZ, "box side c (m)");
        double x2 = (double) sideX * sideX;
        double y2 = (double) sideY * sideY;
        double z2 = (double) sideZ * sideZ;
        double twelfth = massKg / 12.0;
        return of((float) (twelfth * (y2 + z2)), (float) (twelfth * (x2 + z2)),
                (float) (twelfth * (x2 + y2)));
    }

    /**
     * Return one principal moment.
     *
     * @param axis 0 for x (A), 1 for y (B), 2 for z (C)
     * @return the moment (in kg·m², &gt;0)
     */
    public float getMoment(int axis) {
        switch (axis) {
            case 0:
                return a;
            case 1:
                return b;
            case 2:
                return c;
            default:
                throw new IllegalArgumentException("axis must be 0, 1 or 2, but was " + axis);
        }
    }

    /**
     * Test whether a torque-free body spinning at this body-frame ω keeps ω constant: when
     * {@code I·ω} is parallel to ω, i.e. ω lies in one eigenspace of I (along a principal
     * axis, or any ω when the moments of its non-zero components are equal). Then the motion
     * is the steady rotation {@code R(t) = exp(t·[ω]×)·R(0)}. Decided from the moments
     * exactly, without round-off.
     *
     * @param bodyOmega ω in the body frame (in rad/s, not null, not modified)
     * @return true if {@code ω × I·ω = 0}
     */
    public boolean isSteadySpin(Vector3f bodyOmega) {
        boolean x = bodyOmega.x != 0f;
        boolean y = bodyOmega.y != 0f;
        boolean z = bodyOmega.z != 0f;
        return (!x || !y || a == b) && (!x || !z || a == c) && (!y || !z || b == c);
    }

    /**
     * Calculate the rotational kinetic energy {@code ½·ωᵀ·I·ω}.
     *
     * @param bodyOmega ω in the body frame (in rad/s, not null, not modified)
     * @return the energy (in joules, &ge;0)
     */
    public double kineticEnergy(Vector3f bodyOmega) {
        double x = bodyOmega.x;
        double y = bodyOmega.y;
        double z = bodyOmega.z;
        return 0.5 * (a * x * x + b * y * y + c * z * z);
    }

    /**
     * Calculate the magnitude of the angular momentum {@code |L| = |I·ω|}.
     *
     * @param bodyOmega ω in the body frame (in rad/s, not null, not modified)
     * @return |L| (in kg·m²/s, &ge;0)
     */
    public double angularMomentum(Vector3f bodyOmega) {
        double x = a * (double) bodyOmega.x;
        double y = b * (double) bodyOmega.y;
        double z = c * (double) bodyOmega.z;
        return Math.sqrt(x * x + y * y + z * z);
    }

    @Override
    public String toString() {
        return "Inertia[A=" + a + ", B=" + b + ", C=" + c + " kg*m^2]";
    }

    private static void checkTriangle(String name, float moment, float other1, float other2) {
        double sum = (double) other1 + other2;
        if (moment > sum * (1.0 + TRIANGLE_SLACK)) {
            throw new IllegalArgumentException("moment of inertia " + name + " (kg*m^2) must be"
                    + " at most the sum of the other two, " + (float) sum + ", as for every"
                    + " solid body, but was " + moment);
        }
    }
}

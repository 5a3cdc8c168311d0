package particlelab.rigid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

class InertiaTest {

    /** One float rounding of a moment. */
    private static final float EPS = Math.ulp(1f);

    @Test
    void sphereIsTwoFifthsMRSquaredAboutEveryAxis() {
        Inertia sphere = Inertia.sphere(5f, 0.5f);
        for (int axis = 0; axis < 3; ++axis) {
            assertEquals(0.4f * 5f * 0.25f, sphere.getMoment(axis), EPS * 0.5f);
        }
    }

    @Test
    void boxIsMassTimesTheOtherTwoSidesSquaredOverTwelve() {
        Inertia box = Inertia.box(12f, 1f, 2f, 3f);
        // m/12 = 1: A = b² + c² = 13, B = a² + c² = 10, C = a² + b² = 5
        assertEquals(13f, box.getMoment(0), 13f * EPS);
        assertEquals(10f, box.getMoment(1), 10f * EPS);
        assertEquals(5f, box.getMoment(2), 5f * EPS);
    }

    @Test
    void aFlatPlateReachesTheTriangleInequalityAndIsAccepted() {
        // A square plate's axis across it: C = A + B exactly, in real numbers.
        Inertia plate = Inertia.of(1f / 3f, 1f / 3f, 2f / 3f);
        assertEquals(2f / 3f, plate.getMoment(2));
    }

    @Test
    void momentsNoSolidBodyHasAreRefused() {
        String message = assertThrows(IllegalArgumentException.class,
                () -> Inertia.of(1f, 1f, 3f)).getMessage();
        assertTrue(message.contains("C") && message.contains("3.0")
                && message.contains("at most the sum"), message);
        assertThrows(IllegalArgumentException.class, () -> Inertia.of(0f, 1f, 1f));
        assertThrows(IllegalArgumentException.class, () -> Inertia.of(1f, -1f, 1f));
        assertThrows(IllegalArgumentException.class, () -> Inertia.of(1f, 1f, Float.NaN));
        assertThrows(IllegalArgumentException.class,
                () -> Inertia.of(Float.POSITIVE_INFINITY, 1f, 1f));
        assertThrows(IllegalArgumentException.class, () -> Inertia.sphere(1f, 0f));
        assertThrows(IllegalArgumentException.class, () -> Inertia.box(-1f, 1f, 1f, 1f));
        assertThrows(IllegalArgumentException.class, () -> Inertia.of(1f, 2f, 3f)
                .getMoment(3));
    }

    @Test
    void steadySpinIsAlongAPrincipalAxisOrWithinEqualMoments() {
        Inertia racket = Inertia.of(1f, 2f, 3f);
        assertTrue(racket.isSteadySpin(new Vector3f(0f, 5f, 0f)));
        assertFalse(racket.isSteadySpin(new Vector3f(1e-6f, 5f, 0f)));
        Inertia symmetric = Inertia.of(2f, 2f, 3f);
        assertTrue(symmetric.isSteadySpin(new Vector3f(1f, 5f, 0f)));
        assertFalse(symmetric.isSteadySpin(new Vector3f(1f, 5f, 1f)));
        assertTrue(Inertia.sphere(1f, 1f).isSteadySpin(new Vector3f(1f, 2f, 3f)));
    }

    @Test
    void energyAndMomentumAreTheQuadraticForms() {
        Inertia racket = Inertia.of(1f, 2f, 3f);
        Vector3f omega = new Vector3f(1f, 2f, 3f);
        // ½(1·1 + 2·4 + 3·9) = 18; |(1, 4, 9)| = √98
        assertEquals(18.0, racket.kineticEnergy(omega), 0.0);
        assertEquals(Math.sqrt(98.0), racket.angularMomentum(omega), 1e-15);
    }
}

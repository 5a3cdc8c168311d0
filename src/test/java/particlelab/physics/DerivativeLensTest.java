package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Issue 32 §2, the derivative lens, against closed forms (no jME application): in the
 * lecture's step the chord is {@code V_{i+1}}; under gravity it differs from the exact
 * tangent at {@code t_i} by {@code g·h} and at the step's middle by {@code g·h/2}, and the
 * measured order of both differences in h is 1.
 */
class DerivativeLensTest {

    private static final float G = 9.81f;
    private static final Vector3f GRAVITY = new Vector3f(0f, -G, 0f);

    /**
     * Where the float sums are exact (h a power of two, the state and g·h dyadic with few
     * bits: P_{i+1} − P_i = h·V_{i+1} and the division by h undo each other exactly), the
     * chord equals V_{i+1} bit for bit.
     */
    @Test
    void inTheLecturesStepTheChordIsTheNewVelocityBitForBit() {
        float h = 1f / 64f;
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity(new Vector3f(0f, -8f,
                0f)));
        DerivativeLens lens = new DerivativeLens();
        lens.look(gravity, 1f, new Vector3f(2f, 3.5f, 0f), new Vector3f(10f, 10f, 0f), h);
        assertBits(lens.stepVelocity, lens.chord);
        // V_{i+1} = V_i + h·a: the step used the new velocity, not the old one
        assertBits(new Vector3f(10f, 10f - 8f * h, 0f), lens.stepVelocity);
    }

    /**
     * At any state, the chord is V_{i+1} to the rounding of P_{i+1} (half an ulp of each
     * coordinate, divided by h) and of the subtraction: within 2 ulp(P)/h.
     */
    @Test
    void theChordIsTheNewVelocityToThePositionsRounding() {
        float h = 1f / 60f;
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity(GRAVITY));
        DerivativeLens lens = new DerivativeLens();
        Vector3f p = new Vector3f(13.37f, 4.2f, 0f);
        Vector3f v = new Vector3f(9.3f, -2.7f, 0f);
        for (int i = 0; i < 200; ++i) {
            lens.look(gravity, 1f, p, v, h);
            float tolX = 2f * Math.ulp(Math.abs(lens.endPosition.x) + 1f) / h;
            float tolY = 2f * Math.ulp(Math.abs(lens.endPosition.y) + 1f) / h;
            assertEquals(lens.stepVelocity.x, lens.chord.x, tolX);
            assertEquals(lens.stepVelocity.y, lens.chord.y, tolY);
            p.set(lens.endPosition);
            v.set(lens.stepVelocity);
        }
    }

    /**
     * Under gravity the chord less the exact tangent at t_i is g·h, at the middle g·h/2
     * (the exact motion from the same launch: V(t) = V_0 + g·t, and the step's velocity
     * update is exact, so V_i is V(t_i) to float rounding). Tolerance: the chord's rounding,
     * 2 ulp(P)/h, as above, plus V's float rounding over the 40 steps (an ulp of 10 m/s,
     * 9.5e-7, per step: under 4e-5, so 1e-4 m/s).
     */
    @Test
    void underGravityTheChordMissesTheTangentsByGhAndHalfGh() {
        Vector3f v0 = new Vector3f(10f, 10f, 0f);
        for (float h : new float[] {1f / 30f, 1f / 60f, 1f / 120f}) {
            ParticleIntegrator gravity = new ParticleIntegrator(new Gravity(GRAVITY));
            DerivativeLens lens = new DerivativeLens();
            Vector3f p = new Vector3f();
            Vector3f v = new Vector3f(v0);
            Vector3f atStart = new Vector3f();
            Vector3f atMiddle = new Vector3f();
            Vector3f difference = new Vector3f();
            for (int i = 0; i < 40; ++i) {
                double t = i * (double) h;
                atStart.set(v0.x, (float) (v0.y - G * t), 0f);
                atMiddle.set(v0.x, (float) (v0.y - G * (t + 0.5 * h)), 0f);
                lens.look(gravity, 1f, p, v, h);
                lens.setExactTangents(atStart, atMiddle);
                float tol = 2f * Math.ulp(Math.abs(lens.endPosition.y) + 1f) / h + 1e-4f;
                lens.copyChordLessStartTangent(difference);
                assertEquals(-G * h, difference.y, tol, "start, h = " + h + ", step " + i);
                assertEquals(0f, difference.x, 2f * Math.ulp(lens.endPosition.x + 1f) / h);
                lens.copyChordLessMiddleTangent(difference);
                assertEquals(-0.5f * G * h, difference.y, tol, "middle, h = " + h);
                p.set(lens.endPosition);
                v.set(lens.stepVelocity);
            }
        }
    }

    /**
     * The measured order: halving h halves both differences, so the fitted order
     * log2(d(h)/d(h/2)) is 1 (to 1e-3: the differences are g·h to the chord's rounding,
     * 2 ulp(5 m)/h = 1.5e-5 m/s at h = 1/16 s, under 3e-5 of g·h).
     */
    @Test
    void theMeasuredOrderOfBothDifferencesIsOne() {
        double[] start = new double[2];
        double[] middle = new double[2];
        float[] steps = {1f / 8f, 1f / 16f};
        for (int k = 0; k < steps.length; ++k) {
            float h = steps[k];
            DerivativeLens lens = new DerivativeLens();
            Vector3f v0 = new Vector3f(3f, 12f, 0f);
            // the step that starts at t = 0.5 s, from the exact state there
            double t = 0.5;
            Vector3f p = new Vector3f((float) (v0.x * t),
                    (float) (v0.y * t - 0.5 * G * t * t), 0f);
            Vector3f v = new Vector3f(v0.x, (float) (v0.y - G * t), 0f);
            lens.look(new ParticleIntegrator(new Gravity(GRAVITY)), 1f, p, v, h);
            lens.setExactTangents(v, new Vector3f(v0.x, (float) (v0.y - G * (t + 0.5 * h)),
                    0f));
            start[k] = lens.copyChordLessStartTangent(new Vector3f()).length();
            middle[k] = lens.copyChordLessMiddleTangent(new Vector3f()).length();
        }
        assertEquals(1.0, Math.log(start[0] / start[1]) / Math.log(2.0), 1e-3);
        assertEquals(1.0, Math.log(middle[0] / middle[1]) / Math.log(2.0), 1e-3);
    }

    private static void assertBits(Vector3f expected, Vector3f actual) {
        assertEquals(Float.floatToIntBits(expected.x), Float.floatToIntBits(actual.x), "x");
        assertEquals(Float.floatToIntBits(expected.y), Float.floatToIntBits(actual.y), "y");
        assertEquals(Float.floatToIntBits(expected.z), Float.floatToIntBits(actual.z), "z");
    }
}

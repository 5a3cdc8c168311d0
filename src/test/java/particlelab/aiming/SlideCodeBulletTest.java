package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * HelloAiming's slide code against the shared recipe: the same floats while in flight, and
 * the slide's {@code if (y >= 0)} stopping the bullet one step below the ground.
 */
class SlideCodeBulletTest {

    private static final float G = Gravity.STANDARD_G;
    private static final float H = 1f / 60f;
    private static final float S = 100f;

    /**
     * Under gravity alone the slide's allocating update and the shared integrator do the same
     * float operations (see the class's Javadoc), so every position and velocity is equal bit
     * for bit: compared with {@code Float.floatToIntBits}, no tolerance. Several launches and
     * steps, raw-tpf-like steps included.
     */
    @Test
    void positionsEqualTheSharedIntegratorsBitForBitWhileInFlight() {
        float[] vxs = {12f, 20f, 23f, 37.5f, 60f};
        float[] steps = {1f / 240f, H, 0.0213f, 0.1f, 0.25f};
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Vector3f gravity = new Vector3f(0f, -G, 0f);
        for (float vx : vxs) {
            for (float h : steps) {
                float vy = (float) LevelAim.lectureVy(G, S, vx);
                Vector3f launch = new Vector3f(vx, vy, 0f);
                Particle recipe = new Particle(new Vector3f(), launch, 1f);
                SlideCodeBullet slide = new SlideCodeBullet();
                slide.launch(Vector3f.ZERO, launch);
                int n = 0;
                while (slide.update(gravity, h)) {
                    integrator.step(recipe, h);
                    ++n;
                    assertBits(recipe.position, slide.position, vx, h, n);
                    assertBits(recipe.velocity, slide.velocity, vx, h, n);
                }
                assertEquals(n, slide.getSteps());
            }
        }
    }

    /**
     * The slide stops the bullet at the first sample below the ground. The stepped samples are
     * {@code y_n = n·h·vy − g·h²·n(n+1)/2}; with the lecture's {@code vy = g·T/2},
     * {@code T = S/vx}, {@code y_n < 0} exactly when {@code n > T/h − 1}: the first such n is
     * {@code N = ceil(T/h − 1)}, and the bullet ends at {@code x = N·h·vx}. vx = 23 m/s keeps
     * {@code T/h = 260.87} far from an integer, so float rounding cannot move N.
     */
    @Test
    void stopsAtTheFirstStepBelowTheGroundFromTheClosedForm() {
        float vx = 23f;
        float vy = (float) LevelAim.lectureVy(G, S, vx);
        SlideCodeBullet slide = new SlideCodeBullet();
        slide.launch(Vector3f.ZERO, new Vector3f(vx, vy, 0f));
        Vector3f gravity = new Vector3f(0f, -G, 0f);
        float previousY = 0f;
        while (slide.update(gravity, H)) {
            if (!slide.isStopped()) {
                previousY = slide.position.y;
            }
        }
        double flight = S / (double) vx;
        int expectedSteps = (int) Math.ceil(flight / H - 1.0);
        assertEquals(260, expectedSteps);
        assertEquals(expectedSteps, slide.getSteps());
        assertTrue(slide.isStopped());
        assertTrue(slide.position.y < 0f, "y = " + slide.position.y);
        assertTrue(previousY >= 0f, "the step before is not below: " + previousY);
        // x = N·h·vx: each step adds h·vx in float; 260 additions of about 0.38 m to a sum
        // below 100 m round at most 260 · 2^-18 ≈ 1e-3 m in all (ulp(64..128) = 2^-17 m,
        // half of it per addition).
        assertEquals(expectedSteps * H * (double) vx, slide.position.x, 1e-3);
        // The slide's y there is the closed form y_N (the same rounding bound, on smaller
        // numbers: 1e-3 m).
        double n = expectedSteps;
        double yN = n * H * vy - G * H * H * n * (n + 1.0) / 2.0;
        assertEquals(yN, slide.position.y, 1e-3);
        // And a stopped bullet stays where it is.
        Vector3f end = slide.position;
        assertFalse(slide.update(gravity, H));
        assertEquals(end, slide.position);
    }

    /** Each moving step replaces the vectors with new ones: the slide's allocating style. */
    @Test
    void eachStepReplacesTheVectorsWithNewOnes() {
        SlideCodeBullet slide = new SlideCodeBullet();
        slide.launch(Vector3f.ZERO, new Vector3f(20f, 24.5f, 0f));
        Vector3f position = slide.position;
        Vector3f velocity = slide.velocity;
        assertTrue(slide.update(new Vector3f(0f, -G, 0f), H));
        assertNotSame(position, slide.position);
        assertNotSame(velocity, slide.velocity);
    }

    /** Null is refused naming the parameter, as everywhere in the aiming package. */
    @Test
    void nullIsRefusedNamingTheParameter() {
        SlideCodeBullet slide = new SlideCodeBullet();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> slide.update(null, H));
        assertTrue(e.getMessage().contains("gravity"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> slide.launch(Vector3f.ZERO, null));
        assertTrue(e.getMessage().contains("launchVelocity"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> slide.setSteps(-1));
        assertTrue(e.getMessage().contains("-1"), e.getMessage());
    }

    private static void assertBits(Vector3f expected, Vector3f actual, float vx, float h,
            int step) {
        String where = "vx " + vx + ", h " + h + ", step " + step;
        assertEquals(Float.floatToIntBits(expected.x), Float.floatToIntBits(actual.x), where);
        assertEquals(Float.floatToIntBits(expected.y), Float.floatToIntBits(actual.y), where);
        assertEquals(Float.floatToIntBits(expected.z), Float.floatToIntBits(actual.z), where);
    }
}

package particlelab.aiming;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

class HitscanTest {

    private static final double G = 9.8;
    private static final float H = 1f / 60f;
    private static final float RADIUS = 0.25f;

    private static Hitscan range() {
        return new Hitscan(new ParticleIntegrator(new Gravity()), H, 1_000_000);
    }

    @Test
    void formulaDropIsHalfGTimesFlightTimeSquared() {
        // 100 m at 35 m/s: t = 2.857 s, ½·9.8·t² = 40 m.
        assertEquals(40.0, Hitscan.formulaDrop(G, 100.0, 35.0), 1e-12);
        // 900 m/s: ½·9.8·(1/9)² = 0.0604938...
        assertEquals(4.9 / 81.0, Hitscan.formulaDrop(G, 100.0, 900.0), 1e-15);
    }

    /** At {@code d = v·√(2r/g)} the drop is exactly r: the cheat is good enough below it. */
    @Test
    void cheatDistanceIsWhereTheDropReachesTheRadius() {
        for (double speed : new double[] {35.0, 300.0, 900.0}) {
            double limit = Hitscan.cheatDistance(speed, RADIUS, G);
            assertEquals(RADIUS, Hitscan.formulaDrop(G, limit, speed), 1e-12 * RADIUS);
            assertTrue(Hitscan.formulaDrop(G, 0.99 * limit, speed) < RADIUS);
        }
        assertEquals(900.0 * Math.sqrt(0.5 / G), Hitscan.cheatDistance(900.0, 0.25, G), 1e-9);
    }

    /**
     * The stepped projectile's drop at {@code x = d} is the SIE's discrete solution read on
     * the chord, {@code ½g·h²(n+1)(n+2f)}, and exceeds {@code ½g(d/v)²} by the half-step
     * offset {@code ½·g·h·t} plus {@code ½·g·h²·f(1−f) ≤ g·h²/8} (exact algebra, checked to
     * 1e-12). The fired shot matches the closed form to float round-off: each of its N steps
     * rounds y by half an ulp of the drop and x by half an ulp of d, and an x error moves the
     * crossing's y by the slope {@code g·t/v} (at most 0.33 here); 2·N·(ulp(drop) + ulp(d))
     * bounds both with room.
     */
    @Test
    void steppedDropMatchesTheFormulaPlusTheHalfStepOffset() {
        Hitscan range = range();
        TargetImpact impact = new TargetImpact();
        double[][] shots = {{100.0, 900.0}, {100.0, 35.0}, {37.5, 300.0}, {250.0, 600.0}};
        for (double[] shot : shots) {
            double d = shot[0];
            double v = shot[1];
            double t = d / v;
            double formula = Hitscan.formulaDrop(G, d, v);
            double stepped = Hitscan.steppedDrop(G, d, v, H);
            assertTrue(stepped - formula >= 0.5 * G * H * t - 1e-12, "at least ½ g h t");
            assertTrue(stepped - formula <= 0.5 * G * H * t + G * H * H / 8.0 + 1e-12,
                    "at most ½ g h t + g h²/8");

            assertTrue(range.fireAtDisc((float) v, (float) d, RADIUS, impact));
            double steps = d / (v * H);
            double roundOff = 2.0 * Math.ceil(steps)
                    * (Math.ulp((float) stepped) + Math.ulp((float) d));
            assertEquals(stepped, impact.getDrop(), roundOff, "d=" + d + " v=" + v);
            assertEquals(t, impact.getTimeSeconds(), roundOff / v + 1e-6, "flight time");
            assertEquals(impact.getDrop() <= RADIUS, impact.isHit());
        }
    }

    /**
     * At 900 m/s a step covers 15 m: the disc at 100 m is crossed inside the seventh step,
     * which ends at 105 m. The impact is placed at the crossing, x = d, not at the step's end,
     * and the bullet falls 0.0699 m there: within 0.25 m, a hit. At 35 m/s it falls 40 m.
     */
    @Test
    void discImpactIsPlacedWhereTheSegmentCrossesTheTarget() {
        TargetImpact impact = new TargetImpact();
        assertTrue(range().fireAtDisc(900f, 100f, RADIUS, impact));
        assertEquals(7, impact.getSteps());
        assertEquals(100.0, impact.getX(), 7 * Math.ulp(100f));
        assertTrue(impact.isHit());
        assertEquals(Hitscan.steppedDrop(G, 100.0, 900.0, H), impact.getDrop(), 1e-6);
        assertEquals(0.0699, impact.getDrop(), 1e-4);

        assertTrue(range().fireAtDisc(35f, 100f, RADIUS, impact));
        assertFalse(impact.isHit());
        assertEquals(100.0, impact.getX(), 172 * Math.ulp(100f));
    }

    /**
     * A fast bullet against a small sphere (15 m steps, 0.5 m across): no step ends inside the
     * sphere, so the overlap test would see nothing, yet the swept test puts the impact on the
     * sphere's near surface, within the last step, in front of the centre.
     */
    @Test
    void sphereImpactIsTheFirstHitPointOfTheSegment() {
        TargetImpact impact = new TargetImpact();
        float distance = 100f;
        assertTrue(range().fireAtSphere(900f, distance, RADIUS, impact));
        double dx = impact.getX() - distance;
        double dy = impact.getY();
        assertEquals(RADIUS, Math.sqrt(dx * dx + dy * dy), 1e-5, "on the surface");
        assertTrue(dx < 0.0, "in front of the centre, not behind it");

        // The same bullet's step ends, as an overlap test would see them: none inside.
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle bullet = new Particle(Vector3f.ZERO, new Vector3f(900f, 0f, 0f), 1f);
        Vector3f centre = new Vector3f(distance, 0f, 0f);
        for (int step = 1; step <= impact.getSteps(); ++step) {
            integrator.step(bullet, H);
            assertTrue(bullet.position.distance(centre) > RADIUS, "step " + step);
        }
        assertTrue(bullet.position.x > distance + RADIUS, "the last step ends behind it");
        double startX = bullet.position.x - 900.0 * H;
        assertTrue(impact.getX() > startX && impact.getX() < bullet.position.x);
    }

    @Test
    void slowBulletPassesBelowTheSphere() {
        TargetImpact impact = new TargetImpact();
        assertFalse(range().fireAtSphere(35f, 100f, RADIUS, impact));
        assertFalse(impact.isHit());
        assertTrue(Double.isNaN(impact.getX()));
    }

    /** A demo fires every frame: once warm, a shot at either target allocates nothing. */
    @Test
    void firingAllocatesNothingOnceWarm() {
        Hitscan range = range();
        TargetImpact impact = new TargetImpact();
        range.fireAtDisc(35f, 100f, RADIUS, impact);
        range.fireAtSphere(900f, 100f, RADIUS, impact);
        Allocations.assertAllocatesNothing("1000 shots", () -> {
            for (int i = 0; i < 500; ++i) {
                range.fireAtDisc(35f, 100f, RADIUS, impact);
                range.fireAtSphere(900f, 100f, RADIUS, impact);
            }
        });
    }
}

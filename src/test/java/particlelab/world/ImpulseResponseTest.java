package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.math.Vector3f;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import particlelab.VectorAssert;
import particlelab.physics.ParticleIntegrator;

/**
 * The physics-based resolution between two spheres in free flight, against NUMERICS'
 * closed forms: momentum unchanged, separation speed = e × approach speed, kinetic energy
 * lost ½·μ·(1−e²)·v_n², the worked example, right-angle exits, a kinematic paddle.
 *
 * <p>Tolerances: velocities are floats (relative round-off 6e-8 per operation, a handful of
 * operations per component), so conserved sums are compared to 1e-6 of their scale
 * ({@code Σ m·|v|} for momentum, {@code Σ ½·m·|v|²} for energy).
 */
class ImpulseResponseTest {

    private static final float H = 1f / 60f;
    private static final double ROUND_OFF = 1e-6;

    /** Velocities just before the first impact, and the contact's normal and speed. */
    private static final class FirstImpact implements ContactListener {
        final Vector3f v1 = new Vector3f();
        final Vector3f v2 = new Vector3f();
        final Vector3f normal = new Vector3f();
        float approach;
        int impacts;

        @Override
        public boolean accept(Contact contact, World world) {
            if (impacts == 0) {
                v1.set(world.getBody(0).getVelocity());
                v2.set(world.getBody(1).getVelocity());
                normal.set(contact.getNormal());
                approach = contact.getApproachSpeed();
            }
            ++impacts;
            return true;
        }
    }

    private static World pair(Detection detection, float e, float m1, float m2, Vector3f p1,
            Vector3f p2, Vector3f v1, Vector3f v2, float r1, float r2, FirstImpact first) {
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        world.addBody(none, p1, v1, m1, r1);
        world.addBody(none, p2, v2, m2, r2);
        world.addRule(new SphereRule(new ImpulseResponse(e, 0f, false), detection));
        world.addContactListener(first);
        for (int i = 0; i < 600 && first.impacts == 0; ++i) {
            world.step(H);
        }
        assertEquals(1, first.impacts, "one impact");
        return world;
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void workedExampleTwoAndOneKilogramsLeaveAtOneAndThreeLosingFourJoules(
            Detection detection) {
        // m = 2 and 1 kg, normal velocities 3 and -1 m/s, e = 0.5: separation 0.5·4 = 2 m/s,
        // momentum 5 kg·m/s: v1' = 1, v2' = 3; KE 9.5 J -> 5.5 J.
        FirstImpact first = new FirstImpact();
        World world = pair(detection, 0.5f, 2f, 1f, new Vector3f(), new Vector3f(1f, 0f, 0f),
                new Vector3f(3f, 0f, 0f), new Vector3f(-1f, 0f, 0f), 0.25f, 0.25f, first);
        VectorAssert.assertVectorEquals(new Vector3f(1f, 0f, 0f),
                world.getBody(0).getVelocity(), 1e-6f);
        VectorAssert.assertVectorEquals(new Vector3f(3f, 0f, 0f),
                world.getBody(1).getVelocity(), 1e-6f);
        assertEquals(4.0, kineticEnergy(first.v1, first.v2, 2f, 1f)
                - kineticEnergy(world), 1e-5);
        assertEquals(4f, first.approach, 1e-6f);
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void randomImpactsConserveMomentumScaleSeparationByEAndLoseTheFormulasEnergy(
            Detection detection) {
        Random random = new Random(8);
        for (int trial = 0; trial < 200; ++trial) {
            float m1 = 0.1f + 10f * random.nextFloat();
            float m2 = 0.1f + 10f * random.nextFloat();
            float e = random.nextFloat();
            float r1 = 0.1f + random.nextFloat();
            float r2 = 0.1f + random.nextFloat();
            Vector3f v1 = new Vector3f(2f + 10f * random.nextFloat(), random.nextFloat() - 0.5f,
                    random.nextFloat() - 0.5f);
            Vector3f v2 = new Vector3f(-10f * random.nextFloat(), random.nextFloat() - 0.5f,
                    0f);
            // Closest approach at t = 1.5 s, at a random distance below the radius sum along
            // a direction across the relative velocity: a head-on to glancing impact.
            Vector3f w = v1.subtract(v2);
            Vector3f across = w.cross(new Vector3f(random.nextFloat() - 0.5f,
                    random.nextFloat() - 0.5f, random.nextFloat() - 0.5f)).normalizeLocal();
            Vector3f p2 = w.mult(1.5f).addLocal(across.multLocal(0.9f * (r1 + r2)
                    * random.nextFloat()));
            FirstImpact first = new FirstImpact();
            World world = pair(detection, e, m1, m2, new Vector3f(), p2, v1, v2, r1, r2, first);
            Vector3f after1 = world.getBody(0).getVelocity();
            Vector3f after2 = world.getBody(1).getVelocity();
            String what = "trial " + trial;

            double scale = m1 * first.v1.length() + m2 * first.v2.length();
            Vector3f before = first.v1.mult(m1).addLocal(first.v2.mult(m2));
            Vector3f afterMomentum = after1.mult(m1).addLocal(after2.mult(m2));
            VectorAssert.assertVectorEquals(before, afterMomentum, (float) (ROUND_OFF * scale),
                    what + " momentum");

            float separation = after1.subtract(after2).dot(first.normal);
            assertEquals(e * first.approach, separation,
                    ROUND_OFF * (first.v1.length() + first.v2.length()), what + " separation");

            double mu = m1 * (double) m2 / (m1 + m2);
            double lost = kineticEnergy(first.v1, first.v2, m1, m2) - kineticEnergy(world);
            double energyScale = kineticEnergy(first.v1, first.v2, m1, m2);
            assertEquals(0.5 * mu * (1.0 - (double) e * e) * first.approach * first.approach,
                    lost, 10.0 * ROUND_OFF * energyScale, what + " energy lost");
        }
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void equalMassesElasticGlancingLeaveAtRightAngles(Detection detection) {
        FirstImpact first = new FirstImpact();
        World world = pair(detection, 1f, 1.5f, 1.5f, new Vector3f(), new Vector3f(2f, 0.3f, 0f),
                new Vector3f(5f, 0f, 0f), Vector3f.ZERO, 0.5f, 0.5f, first);
        Vector3f after1 = world.getBody(0).getVelocity();
        Vector3f after2 = world.getBody(1).getVelocity();
        assertTrue(after1.length() > 1f && after2.length() > 1f, after1 + ", " + after2);
        // cos of the angle between the exits: 0 to round-off.
        assertEquals(0.0, after1.dot(after2) / (after1.length() * after2.length()), 1e-6);
    }

    @ParameterizedTest
    @EnumSource(Detection.class)
    void kinematicPaddleSendsTheBallOffAtOnePlusETimesUMinusEV(Detection detection) {
        // Paddle at u = 2 m/s (infinite mass, moved without forces), ball at v = -3 m/s,
        // e = 0.5: the ball leaves at (1+e)·u - e·v = 3 + 1.5 = 4.5 m/s; the paddle keeps u.
        World world = new World();
        ParticleIntegrator none = new ParticleIntegrator();
        Body paddle = world.addBody(none, new Vector3f(), new Vector3f(2f, 0f, 0f), 5f, 0.5f);
        paddle.setKinematic(true);
        Body ball = world.addBody(none, new Vector3f(3f, 0f, 0f), new Vector3f(-3f, 0f, 0f), 1f,
                0.25f);
        world.addRule(new SphereRule(new ImpulseResponse(0.5f, 0f, false), detection));
        for (int i = 0; i < 60; ++i) {
            world.step(H);
        }
        VectorAssert.assertVectorEquals(new Vector3f(4.5f, 0f, 0f), ball.getVelocity(), 1e-6f);
        VectorAssert.assertVectorEquals(new Vector3f(2f, 0f, 0f), paddle.getVelocity(), 0f);
        // The ball's energy grew, 4.5 J to 10.125 J: a scripted paddle is a source of energy.
        assertEquals(10.125, 0.5 * ball.getMass() * ball.getVelocity().lengthSquared(), 1e-5);
    }

    private static double kineticEnergy(Vector3f v1, Vector3f v2, float m1, float m2) {
        return 0.5 * m1 * v1.lengthSquared() + 0.5 * m2 * v2.lengthSquared();
    }

    private static double kineticEnergy(World world) {
        double sum = 0.0;
        for (int i = 0; i < world.countBodies(); ++i) {
            Body body = world.getBody(i);
            sum += 0.5 * body.getMass() * body.getVelocity().lengthSquared();
        }
        return sum;
    }
}

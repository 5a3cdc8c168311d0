package particlelab.rigid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.jme3.math.Matrix3f;
import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.VectorAssert;
import particlelab.physics.Gravity;
import particlelab.physics.NonFiniteStepException;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;
import particlelab.rigid.RotationIntegrator.Angular;
import particlelab.rigid.RotationIntegrator.Orientation;

class RigidBodyTest {

    @Test
    void translationIsExactlyTheParticleStep() {
        // A thrown, spinning box: its centre must move bit for bit as a lone particle does.
        ParticleIntegrator gravity = new ParticleIntegrator(new Gravity(new Vector3f(0f, -9.8f,
                0f)));
        RigidBody box = new RigidBody(2f, Inertia.box(2f, 1f, 0.5f, 0.25f));
        box.getParticle().setState(new Vector3f(0f, 1f, 0f), new Vector3f(3f, 8f, 0f));
        box.setAngularVelocity(new Vector3f(1f, 4f, 0.5f));
        Particle lone = new Particle(
                new Vector3f(0f, 1f, 0f), new Vector3f(3f, 8f, 0f), 2f);
        RotationIntegrator rotation =
                new RotationIntegrator(Orientation.EXACT, Angular.EXPLICIT, true);
        for (int i = 0; i < 100; ++i) {
            box.step(gravity, rotation, 1f / 60f);
            gravity.step(lone, 1f / 60f);
        }
        VectorAssert.assertVectorEquals(lone.position, box.getParticle().position, 0f);
        VectorAssert.assertVectorEquals(lone.velocity, box.getParticle().velocity, 0f);
    }

    @Test
    void bodyFrameOmegaIsRTransposeOmega() {
        RigidBody body = new RigidBody(1f, Inertia.of(1f, 2f, 3f));
        // R: a quarter turn about z, so the body x axis points along world y.
        body.setOrientation(new Matrix3f(0f, -1f, 0f, 1f, 0f, 0f, 0f, 0f, 1f));
        body.setAngularVelocity(new Vector3f(0f, 2f, 0f));
        VectorAssert.assertVectorEquals(new Vector3f(2f, 0f, 0f),
                body.bodyAngularVelocity(new Vector3f()), 0f);
        // ½·A·ω² and A·ω with A = 1
        Vector3f scratch = new Vector3f();
        assertEquals(2.0, body.rotationalEnergy(scratch), 0.0);
        assertEquals(2.0, body.angularMomentum(scratch), 0.0);
    }

    @Test
    void aBodyPointIsTheCentrePlusRTimesIt() {
        Particle centre = new Particle(
                new Vector3f(1f, 2f, 3f), Vector3f.ZERO, 1f);
        RigidBody body = new RigidBody(centre, Inertia.of(1f, 1f, 1f));
        // A quarter turn about z: body x is world y, body y is world -x.
        body.setOrientation(new Matrix3f(0f, -1f, 0f, 1f, 0f, 0f, 0f, 0f, 1f));
        VectorAssert.assertVectorEquals(new Vector3f(0f, 2.5f, 3.25f),
                body.bodyToWorld(new Vector3f(0.5f, 1f, 0.25f), new Vector3f()), 0f);
        // The centre is shared: moving the particle moves the body.
        centre.position.set(0f, 0f, 0f);
        VectorAssert.assertVectorEquals(new Vector3f(-1f, 0.5f, 0.25f),
                body.bodyToWorld(new Vector3f(0.5f, 1f, 0.25f), new Vector3f()), 0f);
    }

    @Test
    void badInputIsRefusedWithTheValueNamed() {
        RigidBody body = new RigidBody(1f, Inertia.of(1f, 1f, 1f));
        assertThrows(IllegalArgumentException.class,
                () -> body.setAngularVelocity(new Vector3f(Float.NaN, 0f, 0f)));
        assertThrows(IllegalArgumentException.class,
                () -> body.setTorque(new Vector3f(0f, Float.POSITIVE_INFINITY, 0f)));
        assertThrows(IllegalArgumentException.class, () -> body.setInertia(null));
        Matrix3f bad = new Matrix3f();
        bad.set(1, 2, Float.NaN);
        assertThrows(IllegalArgumentException.class, () -> body.setOrientation(bad));
        assertThrows(IllegalArgumentException.class, () -> new RigidBody(0f,
                Inertia.of(1f, 1f, 1f)));
        assertThrows(IllegalArgumentException.class,
                () -> new RigidBody((Particle) null, Inertia.of(1f, 1f, 1f)));
    }

    @Test
    void aRotationThatBlowsUpLeavesTheWholeBodyAsItWas() {
        ParticleIntegrator none = new ParticleIntegrator();
        RigidBody body = new RigidBody(1f, Inertia.of(1f, 2f, 3f));
        body.getParticle().setState(Vector3f.ZERO, new Vector3f(1f, 0f, 0f));
        // (A − B)·ωx·ωy ≈ 1e76 rad/s² overflows the float ω.
        body.setAngularVelocity(new Vector3f(3e38f, 3e38f, 0f));
        RotationIntegrator rotation = new RotationIntegrator(Orientation.EULER,
                Angular.EXPLICIT, true);
        assertThrows(NonFiniteStepException.class, () -> body.step(none, rotation, 1f));
        VectorAssert.assertVectorEquals(Vector3f.ZERO, body.getParticle().position, 0f);
        VectorAssert.assertVectorEquals(new Vector3f(3e38f, 3e38f, 0f), body.angularVelocity,
                0f);
        assertEquals(new Matrix3f(), body.orientation);
    }
}

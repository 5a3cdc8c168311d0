package particlelab.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.jme3.math.Vector3f;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import particlelab.aiming.AimResult;
import particlelab.aiming.IterativeAim;
import particlelab.aiming.Landing;
import particlelab.aiming.ShotSimulator;

/**
 * The convention for null (see {@link Validate}): every public method of the physics and
 * aiming packages that takes an object refuses null with an IllegalArgumentException naming
 * the parameter, never a NullPointerException from deep inside.
 */
class NullArgumentTest {

    private static final float H = 1f / 60f;

    /** One call with a null argument, and the parameter name its message must give. */
    private static final class Case {
        final String parameter;
        final Executable call;

        Case(String parameter, Executable call) {
            this.parameter = parameter;
            this.call = call;
        }

        @Override
        public String toString() {
            return parameter;
        }
    }

    static List<Case> cases() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle particle = new Particle();
        ShotSimulator simulator = new ShotSimulator(integrator, 1f, H, 10f);
        return Arrays.asList(
                new Case("position", () -> new Particle(null, new Vector3f(), 1f)),
                new Case("velocity", () -> particle.setState(new Vector3f(), null)),
                new Case("source", () -> particle.copyFrom(null)),
                new Case("forces", () -> new ParticleIntegrator((Force[]) null)),
                new Case("forces[1]", () -> new ParticleIntegrator(new Gravity(), null)),
                new Case("particle", () -> integrator.step((Particle) null, H)),
                new Case("particles", () -> integrator.step((Particle[]) null, H)),
                new Case("particles[1]",
                        () -> integrator.step(new Particle[] {particle, null}, H)),
                new Case("particle", () -> integrator.acceleration(null, new Vector3f())),
                new Case("storeResult", () -> integrator.acceleration(particle, null)),
                new Case("positions",
                        () -> integrator.batch().stepPacked(null, new float[3], 1, 1f, H)),
                new Case("integrator", () -> new ShotSimulator(null, 1f, H, 10f)),
                new Case("storeResult", () -> simulator.fire(20f, 20f, null)),
                new Case("start", () -> simulator.fire(null, new Landing())),
                new Case("storeResult", () -> simulator.fire(particle, null)),
                new Case("simulator", () -> new IterativeAim(null, 9.8, 0.001, 10)),
                new Case("method", () -> new AimResult(null, true, 1, 1, 1, 1, 1, 1, "hit")),
                new Case("explanation", () -> new AimResult("x", true, 1, 1, 1, 1, 1, 1, null)),
                new Case("vector", () -> Validate.isFinite(null)),
                new Case("stepper", () -> new SimulationClock().advance(H, null)),
                new Case("storeResult", () -> new Gravity().copyAcceleration(null)),
                new Case("particle", () -> new LinearDrag(1f).addForce(null, new Vector3f())),
                new Case("netForce", () -> new QuadraticDrag(1f).addForce(particle, null)),
                new Case("particle", () -> new Thrust(1f).addForce(null, new Vector3f())),
                new Case("fieldAcceleration",
                        () -> new Gravity().addFieldAcceleration(particle, null)),
                new Case("particle", () -> new QuadraticDrag(1f).dampingRate(null)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void nullIsRefusedNamingTheParameter(Case c) {
        IllegalArgumentException thrown = assertThrows(IllegalArgumentException.class, c.call);
        String message = thrown.getMessage();
        assertEquals(c.parameter, message.substring(0, message.indexOf(' ')), message);
    }
}

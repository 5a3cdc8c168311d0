package particlelab.reference;

import com.jme3.math.Vector3f;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

/**
 * The lecture's semi-implicit Euler step as the demos run it: the shared
 * {@link ParticleIntegrator} itself (not a copy), on a {@link Particle} of jME floats, under the
 * physics force classes built by {@link ForceModel#toForces()}.
 *
 * <p>{@link #advance} loads the double state into the particle once (rounding it to float),
 * takes every step in float with {@code h} rounded to float, and stores the result back, so a
 * run through this stepper is exactly a float run of the shared integrator. Like the
 * integrator, a step that leaves the particle non-finite throws
 * {@link IllegalStateException}.
 */
public final class SharedEulerStepper implements Stepper {

    private final ParticleIntegrator integrator;
    private final Particle particle;
    private final Vector3f scratchPosition = new Vector3f();
    private final Vector3f scratchVelocity = new Vector3f();

    /**
     * Create a stepper around a new shared integrator for a scene.
     *
     * @param forces the scene's forces (not null)
     */
    public SharedEulerStepper(ForceModel forces) {
        Steppers.require(forces);
        this.integrator = new ParticleIntegrator(forces.toForces());
        this.particle = new Particle(new Vector3f(), new Vector3f(), (float) forces.getMassKg());
    }

    @Override
    public Scheme scheme() {
        return Scheme.SEMI_IMPLICIT_EULER;
    }

    @Override
    public void step(MotionState state, double stepSeconds) {
        advance(state, stepSeconds, 1);
    }

    @Override
    public void advance(MotionState state, double stepSeconds, int steps) {
        double[] p = state.position;
        double[] v = state.velocity;
        scratchPosition.set((float) p[0], (float) p[1], (float) p[2]);
        scratchVelocity.set((float) v[0], (float) v[1], (float) v[2]);
        particle.setState(scratchPosition, scratchVelocity);
        float h = (float) stepSeconds;
        for (int n = 0; n < steps; ++n) {
            integrator.step(particle, h);
        }
        p[0] = particle.position.x;
        p[1] = particle.position.y;
        p[2] = particle.position.z;
        v[0] = particle.velocity.x;
        v[1] = particle.velocity.y;
        v[2] = particle.velocity.z;
    }

    /**
     * Access the shared integrator this stepper drives.
     *
     * @return the live integrator
     */
    public ParticleIntegrator getIntegrator() {
        return integrator;
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * One force acting on a particle, as the lecture's recipe uses it: {@code a = g + F/m}.
 *
 * <p>A scene composes only the forces it shows. Field forces such as gravity give every mass
 * the same acceleration and contribute to {@code g}; the others push with a force in newtons
 * and contribute to {@code F}. Implementations read the particle's current state and must
 * not modify it, and must allocate nothing.
 */
public interface Force {

    /**
     * Add this force's push, in newtons, to the net force F. Field forces add nothing here.
     *
     * @param particle the particle pushed (not null, not modified)
     * @param netForce the sum of forces so far (in newtons, not null, modified)
     */
    default void addForce(Particle particle, Vector3f netForce) {
    }

    /**
     * Add this force's mass-independent field acceleration to g. Pushing forces add nothing.
     *
     * @param particle the particle accelerated (not null, not modified)
     * @param fieldAcceleration the sum of field accelerations so far (in m/s², not null,
     *     modified)
     */
    default void addFieldAcceleration(Particle particle, Vector3f fieldAcceleration) {
    }

    /**
     * Return how fast this force damps a small change of the particle's velocity at its
     * current state: the damping rate {@code λ} ("lambda", per second), the largest eigenvalue
     * of {@code −(∂F/∂V)/m}, for which the Euler step scales such a change by {@code 1 − λh}.
     * Linear drag gives {@code b/m}; quadratic drag {@code 2c·|V|/m} (its force grows with the
     * square of the speed, so a change of speed changes it twice as fast). Rates of several
     * forces add. Forces that do not depend on velocity return 0.
     *
     * <p>With {@link #stiffness} it sets the stability limit of the Euler step, see
     * {@link ParticleIntegrator#stableStepLimit(double, double)}: {@code 2/λ} for drag alone.
     *
     * @param particle the particle (not null, not modified)
     * @return the damping rate λ (in 1/s, finite, &ge;0)
     */
    default float dampingRate(Particle particle) {
        return 0f;
    }

    /**
     * Return how strongly this force pulls the particle back when its position changes a
     * little: the stiffness {@code ω²} ("omega squared", per second squared), the largest
     * eigenvalue of {@code −(∂F/∂P)/m}. A spring of constant k gives {@code k/m}, so
     * {@code ω} is its angular frequency. Stiffnesses of several forces add. Forces that do
     * not depend on position return 0.
     *
     * @param particle the particle (not null, not modified)
     * @return the stiffness ω² (in 1/s², finite, &ge;0)
     */
    default float stiffness(Particle particle) {
        return 0f;
    }

    /**
     * Describe this force with its current coefficients, for a HUD or a report.
     *
     * @return a short equation such as {@code F = -0.9·V}
     */
    String describe();
}

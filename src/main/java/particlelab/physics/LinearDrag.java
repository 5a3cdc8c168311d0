package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Linear (viscous) drag {@code F = −b·V}: slow flow, small particles. With mass m the speed
 * decays at the damping rate {@code λ = b/m}; the Euler step multiplies the velocity by
 * {@code 1 − λh}, so it is stable for {@code h < 2m/b} and never reverses the velocity for
 * {@code h < m/b} (see {@link StepRegime}).
 */
public final class LinearDrag extends FoldedForce {

    private float coefficient;

    /**
     * Create linear drag.
     *
     * @param coefficient b (in N·s/m = kg/s, finite, &ge;0)
     */
    public LinearDrag(float coefficient) {
        setCoefficient(coefficient);
    }

    /**
     * Return the coefficient.
     *
     * @return b (in N·s/m, &ge;0)
     */
    public float getCoefficient() {
        return coefficient;
    }

    /**
     * Alter the coefficient.
     *
     * @param coefficient b (in N·s/m = kg/s, finite, &ge;0)
     */
    public void setCoefficient(float coefficient) {
        this.coefficient = Validate.nonNegative(coefficient, "linear drag b (N*s/m)");
        changed();
    }

    @Override
    public void addForce(Particle particle, Vector3f netForce) {
        Validate.notNull(particle, "particle");
        Validate.notNull(netForce, "netForce");
        // F = -b V
        netForce.scaleAdd(-coefficient, particle.velocity, netForce);
    }

    @Override
    public float dampingRate(Particle particle) {
        Validate.notNull(particle, "particle");
        // In double: b/m may overflow a float for a tiny mass.
        return (float) Math.min((double) coefficient / particle.getMass(), Float.MAX_VALUE);
    }

    @Override
    public String describe() {
        return "F = -" + coefficient + "·V";
    }
}

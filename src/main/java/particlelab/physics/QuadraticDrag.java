package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Quadratic (turbulent) drag {@code F = −c·|V|·V}: its magnitude is {@code c·|V|²}, the drag
 * of a ball through air at game speeds.
 *
 * <p>The lecture slide writes {@code −c·|V|²·V}; that vector's magnitude is {@code c·|V|³},
 * cubic in speed, which is neither the physical law nor what the slide's "quadratic" means, so
 * we use {@code −c·|V|·V}.
 *
 * <p>Stability. The Euler step scales the speed by {@code 1 − c·h·|V|/m}: drag alone reverses
 * the velocity once {@code h > m/(c·|V|)} and makes the speed grow once
 * {@code h > 2m/(c·|V|)}. Because the force grows with the square of the speed, a small change
 * of speed changes the force twice as fast: it decays at the rate {@code 2c·|V|/m}, which is
 * what {@link #dampingRate} returns. So when another force holds the speed up (gravity, at the
 * terminal speed {@code v_t = sqrt(m·g/c)}), the step swings about {@code v_t} once
 * {@code h > v_t/(2g)} and no longer settles once {@code h > v_t/g}, half the drag-alone limits.
 */
public final class QuadraticDrag implements Force {

    private float coefficient;

    /**
     * Create quadratic drag.
     *
     * @param coefficient c (in N·s²/m² = kg/m, finite, &ge;0)
     */
    public QuadraticDrag(float coefficient) {
        setCoefficient(coefficient);
    }

    /**
     * Return the coefficient.
     *
     * @return c (in kg/m, &ge;0)
     */
    public float getCoefficient() {
        return coefficient;
    }

    /**
     * Alter the coefficient.
     *
     * @param coefficient c (in N·s²/m² = kg/m, finite, &ge;0)
     */
    public void setCoefficient(float coefficient) {
        this.coefficient = Validate.nonNegative(coefficient, "quadratic drag c (kg/m)");
    }

    @Override
    public void addForce(Particle particle, Vector3f netForce) {
        // F = -c |V| V
        float speed = particle.velocity.length();
        netForce.scaleAdd(-coefficient * speed, particle.velocity, netForce);
    }

    /**
     * {@inheritDoc}
     *
     * <p>Here {@code λ = 2c·|V|/m}: {@code d(c·v²)/dv = 2c·v}.
     */
    @Override
    public float dampingRate(Particle particle) {
        return 2f * coefficient * particle.velocity.length() / particle.getMass();
    }

    @Override
    public String describe() {
        return "F = -" + coefficient + "·|V|·V";
    }
}

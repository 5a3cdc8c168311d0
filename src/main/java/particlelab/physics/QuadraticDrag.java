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
 * <p>Stability (see {@link StepRegime}). Drag alone: one Euler step scales the velocity by
 * {@code 1 − c·h·|V|/m}, so it reverses the velocity once {@code c·h·|V|/m > 1} (the speed still
 * shrinks, and the factor improves as it does) and makes the speed grow once
 * {@code c·h·|V|/m > 2}, after which the factor worsens every step: it blows up. Because the
 * force grows with the square of the speed, a small change of speed changes it twice as fast:
 * it decays at the rate {@code λ = 2c·|V|/m}, which is what {@link #dampingRate} returns. So when
 * another force holds the speed up (gravity, at the terminal speed {@code v_t = sqrt(m·g/c)},
 * where {@code λ = 2g/v_t}), the step swings about {@code v_t} once {@code h > v_t/(2g)} and no
 * longer settles once {@code h > v_t/g}.
 */
public final class QuadraticDrag extends FoldedForce {

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
        changed();
    }

    @Override
    public void addForce(Particle particle, Vector3f netForce) {
        Validate.notNull(particle, "particle");
        Validate.notNull(netForce, "netForce");
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
        Validate.notNull(particle, "particle");
        // In double: 2c·|V| may overflow a float, and overflow times a zero speed is NaN.
        double rate = 2.0 * coefficient * particle.velocity.length() / particle.getMass();
        return (float) Math.min(rate, Float.MAX_VALUE);
    }

    @Override
    public String describe() {
        return "F = -" + coefficient + "·|V|·V";
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * Quadratic (turbulent) drag {@code F = −c·|V|·V}: its magnitude is {@code c·|V|²}, the drag
 * of a ball through air at game speeds.
 *
 * <p>The lecture slide writes {@code −c·|V|²·V}; that vector's magnitude is {@code c·|V|³},
 * cubic in speed, which is neither the physical law nor what the slide's "quadratic" means, so
 * we use {@code −c·|V|·V}. The Euler step scales the speed by {@code 1 − c·h·|V|/m}: it
 * reverses the velocity once {@code h > m/(c·|V|)} and diverges once {@code h > 2m/(c·|V|)}.
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

    @Override
    public float dampingRate(Particle particle) {
        return coefficient * particle.velocity.length() / particle.getMass();
    }

    @Override
    public String describe() {
        return "F = -" + coefficient + "·|V|·V";
    }
}

package particlelab.physics;

import com.jme3.math.Vector3f;

/**
 * The lecture slide's "quadratic" drag as the slide writes it, {@code F = −c·|V|²·V}: its
 * magnitude is {@code c·|V|³}, cubic in speed, which is not how air drags a ball. The project
 * uses the physical {@code −c·|V|·V} ({@link QuadraticDrag}, magnitude {@code c·|V|²}); this
 * form exists so the drag demo can show why, beside it.
 *
 * <p>Terminal speed: gravity balances it where {@code c·v_t³ = m·g}, so
 * {@code v_t = (m·g/c)^(1/3)} ({@link #terminalSpeed}). Stability: a small change of speed changes
 * the force by {@code d(c·v³)/dv = 3c·v²}, so it decays at {@code λ = 3c·|V|²/m}
 * ({@link #dampingRate}), and the Euler step settles only for {@code h < 2/λ}; at the terminal
 * speed {@code λ = 3g/v_t}, so {@code h < 2·v_t/(3g)}, against {@code v_t/g} for the physical
 * form and {@code 2·v_t/g = 2m/b} for linear drag (each law {@code |F| ∝ vⁿ} gives
 * {@code 2·v_t/(n·g)}). The drag alone scales V by {@code 1 − c·h·|V|²/m} per step: it reverses
 * the velocity once {@code c·h·|V|²/m > 1} and makes the speed grow once it exceeds 2, which
 * with the cube comes at a lower speed the longer h is.
 *
 * <p>Not folded into {@link ParticleIntegrator}'s coefficients: it is asked through the
 * {@link Force} interface every step, like {@link Spring}.
 */
public final class SlideFormDrag implements Force {

    private float coefficient;

    /**
     * Create the slide's drag.
     *
     * @param coefficient c (in N·s³/m³ = kg·s/m², finite, &ge;0)
     */
    public SlideFormDrag(float coefficient) {
        setCoefficient(coefficient);
    }

    /**
     * Return the terminal speed under gravity: {@code v_t = (m·g/c)^(1/3)}.
     *
     * @param massKg m (in kilograms, &gt;0)
     * @param gravity g (in m/s², &ge;0)
     * @param coefficient c (in kg·s/m², &gt;0)
     * @return v_t (in m/s)
     */
    public static double terminalSpeed(double massKg, double gravity, double coefficient) {
        return Math.cbrt(massKg * gravity / coefficient);
    }

    /**
     * Return the coefficient.
     *
     * @return c (in kg·s/m², &ge;0)
     */
    public float getCoefficient() {
        return coefficient;
    }

    /**
     * Alter the coefficient, from the next step.
     *
     * @param coefficient c (in N·s³/m³ = kg·s/m², finite, &ge;0)
     */
    public void setCoefficient(float coefficient) {
        this.coefficient = Validate.nonNegative(coefficient, "slide-form drag c (kg*s/m^2)");
    }

    @Override
    public void addForce(Particle particle, Vector3f netForce) {
        Validate.notNull(particle, "particle");
        Validate.notNull(netForce, "netForce");
        // F = -c |V|² V
        float speedSquared = particle.velocity.lengthSquared();
        netForce.scaleAdd(-coefficient * speedSquared, particle.velocity, netForce);
    }

    /**
     * {@inheritDoc}
     *
     * <p>Here {@code λ = 3c·|V|²/m}: {@code d(c·v³)/dv = 3c·v²}.
     */
    @Override
    public float dampingRate(Particle particle) {
        Validate.notNull(particle, "particle");
        // In double: 3c·|V|² may overflow a float.
        double rate = 3.0 * coefficient * particle.velocity.lengthSquared() / particle.getMass();
        return (float) Math.min(rate, Float.MAX_VALUE);
    }

    @Override
    public String describe() {
        return "F = -" + coefficient + "·|V|²·V (slide form, not physical)";
    }
}

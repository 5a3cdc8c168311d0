package particlelab.physics;

/**
 * A built-in force that {@link ParticleIntegrator} folds into its coefficients (g, b, c, k)
 * instead of asking it through the {@link Force} interface every step. It counts the changes
 * of its coefficients, so that an integrator sees a setter at its next step with one read per
 * force.
 */
abstract class FoldedForce implements Force {

    /** How often a coefficient was set (wraps around; only inequality matters). */
    private int changeCount;

    /**
     * Count the changes of the coefficients, so that an integrator that folded them knows
     * when to fold again.
     *
     * @return how often a coefficient was set
     */
    final int changeCount() {
        return changeCount;
    }

    /** Note that a coefficient was set: call from every setter. */
    final void changed() {
        ++changeCount;
    }
}

package particlelab.physics;

/**
 * A built-in force that {@link ParticleIntegrator} folds into its coefficients (g, b, c, k)
 * instead of asking it through the {@link Force} interface every step. It counts the changes
 * of its coefficients, and all folded forces together count theirs, so that an integrator
 * sees a setter at its next step: one read while no folded force changed, one per force of
 * its own after a change. Like the integrators, forces are meant for one thread (the
 * counters are plain fields).
 */
abstract class FoldedForce implements Force {

    /**
     * How often a coefficient of any folded force was set (wraps around; only inequality
     * matters): one read tells an integrator that none of its forces changed.
     */
    private static int anyChangeCount;
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

    /**
     * Count the changes of every folded force's coefficients: unchanged since an integrator
     * last read it means that none of its forces changed either.
     *
     * @return how often a coefficient of any folded force was set
     */
    static int anyChangeCount() {
        return anyChangeCount;
    }

    /** Note that a coefficient was set: call from every setter. */
    final void changed() {
        ++changeCount;
        ++anyChangeCount;
    }
}

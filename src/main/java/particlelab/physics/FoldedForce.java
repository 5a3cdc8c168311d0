package particlelab.physics;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.List;

/**
 * A built-in force that {@link ParticleIntegrator} folds into its coefficients (g, b, c, k)
 * instead of asking it through the {@link Force} interface every step.
 *
 * <p>How a setter reaches the integrators: each integrator's {@link FoldedForces} registers
 * with the forces it folds ({@link #foldedBy}), and every setter calls {@link #changed()},
 * which marks those folds stale; an integrator reads that one flag of its own at its next
 * step and folds again if it is set. A force keeps its folds weakly, so an integrator that a
 * scene dropped is not kept alive by a force that outlives it. Like the integrators, forces
 * are meant for one thread (the flags are plain fields).
 */
abstract class FoldedForce implements Force {

    /** The folds of the integrators that hold this force (weakly; a few per force). */
    private final List<WeakReference<FoldedForces>> folds = new ArrayList<>(2);

    /**
     * Remember a fold of this force, to mark it stale when a coefficient changes. Folds that
     * are gone are forgotten here, so the list stays as long as the integrators that live.
     *
     * @param fold the fold of an integrator that holds this force (not null)
     */
    final void foldedBy(FoldedForces fold) {
        for (int i = folds.size() - 1; i >= 0; --i) {
            if (folds.get(i).get() == null) {
                folds.remove(i);
            }
        }
        folds.add(new WeakReference<>(fold));
    }

    /** Note that a coefficient was set: call from every setter. Allocates nothing. */
    final void changed() {
        for (int i = 0; i < folds.size(); ++i) {
            FoldedForces fold = folds.get(i).get();
            if (fold != null) {
                fold.markStale();
            }
        }
    }
}

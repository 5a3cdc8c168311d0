package particlelab.world;

/**
 * Hears bodies join and leave a {@link World}, so that views, trails and mappings follow
 * spawned and destroyed bodies and nothing is left behind.
 */
public interface BodyListener {

    /**
     * Called after a body joined the world (by {@link World#addBody}).
     *
     * @param world the world (not null)
     * @param body the new body (not null)
     */
    default void bodyAdded(World world, Body body) {
    }

    /**
     * Called when a destroyed body leaves the world (after the epilogue, when destroyed during
     * a step). Drop every reference to it: the world recycles it.
     *
     * @param world the world (not null)
     * @param body the body leaving (not null)
     */
    default void bodyRemoved(World world, Body body) {
    }
}

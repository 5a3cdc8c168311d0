package particlelab.world;

/** The lecture's two ways of detecting a collision, chosen per rule (per scene). */
public enum Detection {
    /**
     * The overlap test: after the step, are the two inside each other? Cheap, finds the
     * contact late (already overlapping, reported at the step's end) and misses a thin wall a
     * fast body jumps over in one step (tunnelling).
     */
    OVERLAP,
    /**
     * The intersection test over the step: sweep each body along its straight segment
     * {@code P..P + h·V} and find the time of impact inside the step. Exact for the
     * semi-implicit Euler step, never misses; several impacts in one step are handled in time
     * order.
     */
    SWEPT
}
